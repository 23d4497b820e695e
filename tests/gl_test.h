/*
 * gl_test.h — how a GL test gets its renderer or context, and the one rule
 * for skipping (runtime/gl/gl_require.h): exit 77 only when no GLES context of
 * any kind can be made here; every other failure fails the test (exit 1),
 * and with HFS_REQUIRE_GL=1 (CI) even that does.
 *
 * Header-only (static inline); link hfs_gl.
 */
#ifndef HFS_TEST_GL_TEST_H
#define HFS_TEST_GL_TEST_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl_require.h"
#include "hfshade.h"

#define GL_TEST_SKIP 77

/* Something GL failed with err: exits 77 ("SKIP: ...") when that is because
 * this machine has no GLES context at all, else 1 ("FAIL: ..."). */
static inline _Noreturn void gl_test_unavailable(const char *what, const hfs_error *err)
{
    hfs_error why = {""};
    if (hfs_gl_missing_device(&why)) {
        printf("SKIP: %s: %s (%s)\n", what, err->msg, why.msg);
        fflush(stdout);
        exit(GL_TEST_SKIP);
    }
    printf("FAIL: %s: %s (%s)\n", what, err->msg, why.msg);
    fprintf(stderr, "FAIL: %s: %s (%s)\n", what, err->msg, why.msg);
    fflush(stdout);
    exit(1);
}

/* A renderer for desc, or exits by the rule above. */
static inline hfs_renderer *gl_test_renderer(const hfs_renderer_desc *desc)
{
    hfs_renderer *r = NULL;
    hfs_error err = {""};
    if (hfs_renderer_create(desc, &r, &err))
        gl_test_unavailable("cannot create the GLES renderer", &err);
    return r;
}

/* The passes r's last frame ran, each followed by a space ("shade
 * readback "), into buf (n bytes). */
static inline const char *gl_test_ran(const hfs_renderer *r, char *buf, size_t n)
{
    hfs_frame_report rep;
    hfs_renderer_frame_report(r, &rep);
    size_t used = 0;
    buf[0] = 0;
    for (int i = 0; i < rep.n_steps; ++i)
        if (rep.step[i].ran && used < n) {
            const int w = snprintf(buf + used, n - used, "%s ", rep.step[i].pass);
            used += w > 0 ? (size_t)w : 0;
        }
    return buf;
}

/* Whether r's last frame recomputed only what an edit of the heights
 * reaches (issue 38: its terrain step says "heights edited"). */
static inline int gl_test_edited(const hfs_renderer *r)
{
    hfs_frame_report rep;
    if (hfs_renderer_frame_report(r, &rep))
        return 0;
    for (int i = 0; i < rep.n_steps; ++i)
        if (rep.step[i].ran && !strncmp(rep.step[i].reason, "heights edited", 14))
            return 1;
    return 0;
}

/* The product's renderer (GLES, default context and profile). */
static inline hfs_renderer *gl_test_gles(void)
{
    const hfs_renderer_desc d = {.backend = HFS_BACKEND_GLES};
    return gl_test_renderer(&d);
}

/* A test's renderer from its arguments: `TEST gles ...` the product's
 * (gl_test_gles: 77 without a context), anything else the CPU reference
 * (an error exits 1); *gles says which. */
static inline hfs_renderer *gl_test_from_args(int argc, char **argv, int *gles)
{
    *gles = argc > 1 && !strcmp(argv[1], "gles");
    if (*gles)
        return gl_test_gles();
    hfs_renderer *r = NULL;
    hfs_error err = {""};
    const hfs_renderer_desc d = {.backend = HFS_BACKEND_CPU};
    if (hfs_renderer_create(&d, &r, &err)) {
        fprintf(stderr, "cpu: %s\n", err.msg);
        exit(1);
    }
    return r;
}

#endif /* HFS_TEST_GL_TEST_H */
