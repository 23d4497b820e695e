/*
 * test_gl_multi.c — two contexts alive in one process (argv[1], argv[2]:
 * backend names), used in turn: the library keeps no global state, EGL's
 * process-wide display is shared without being terminated under the other
 * context, and function tables of different backends do not cross.
 *   requires: both contexts can be made here, else SKIP (77);
 *   checks:   each renders the pattern correctly, interleaved, and each
 *             survives the other's destruction.
 */
#include "gl_context.h"
#include "gl_test.h"
#include "gl_pattern.h"

#include <stdio.h>
#include <string.h>

int main(int argc, char **argv)
{
    setvbuf(stdout, NULL, _IONBF, 0); /* keep order with stderr in logs */
    const char *names[2] = { argc > 1 ? argv[1] : "surfaceless",
                             argc > 2 ? argv[2] : "surfaceless" };
    hfs_gl_context *ctx[2] = { NULL, NULL };
    hfs_gl gl[2];
    hfs_error err = { "" };
    int failures = 0;

    for (int k = 0; k < 2; ++k) {
        int rc = hfs_gl_context_create(names[k], &ctx[k], &err);
        if (rc == 0)
            rc = hfs_gl_load(&gl[k], hfs_gl_context_loader, ctx[k], &err);
        if (rc) {
            hfs_gl_context_destroy(ctx[0]);
            hfs_gl_context_destroy(ctx[1]);
            if (rc == HFS_E_CONTEXT || rc == HFS_E_UNSUPPORTED)
                gl_test_unavailable("cannot make the context", &err);
            printf("FAIL: %s\n", err.msg);
            return 1;
        }
        printf("context %d: %s\n", k, hfs_gl_context_describe(ctx[k]));
    }

    /* Interleave: 0, 1, 0; then destroy 0 and use 1 again. */
    static const int order[] = { 0, 1, 0 };
    for (size_t s = 0; s < sizeof order / sizeof order[0]; ++s) {
        int k = order[s];
        char tag[80];
        snprintf(tag, sizeof tag, "test_gl_multi_%zu_%s", s, names[k]);
        if (hfs_gl_context_make_current(ctx[k], &err)) {
            printf("FAIL: %s\n", err.msg);
            failures++;
            continue;
        }
        if (pattern_check(&gl[k], s == 1 ? -1.0 : 1.0, tag)) {
            printf("FAIL: pattern on context %d (%s), step %zu\n", k, names[k], s);
            failures++;
        }
    }
    hfs_gl_context_destroy(ctx[0]);
    if (hfs_gl_context_make_current(ctx[1], &err)) {
        printf("FAIL: after destroying context 0: %s\n", err.msg);
        failures++;
    } else if (pattern_check(&gl[1], 1.0, "test_gl_multi_last")) {
        printf("FAIL: context 1 (%s) broken by destroying context 0\n", names[1]);
        failures++;
    }
    hfs_gl_context_destroy(ctx[1]);

    if (failures) {
        printf("FAIL: %d failure(s)\n", failures);
        return 1;
    }
    printf("PASS: %s + %s\n", names[0], names[1]);
    return 0;
}
