/*
 * test_gl_names.c — context names and errors, no driver needed:
 * a bogus name fails with HFS_E_INVALID and one line that names it and the
 * known names; NULL out is refused; destroy(NULL) is a no-op.
 */
#include "gl_context.h"

#include <stdio.h>
#include <string.h>

#include "check.h"

int main(void)
{
    setvbuf(stdout, NULL, _IONBF, 0); /* keep order with stderr in logs */
    hfs_error err = { "" };
    hfs_gl_context *ctx = (hfs_gl_context *)&err; /* must be reset to NULL */

    int rc = hfs_gl_context_create("bogus", &ctx, &err);
    printf("bogus: %d (%s): %s\n", rc, hfs_status_name(rc), err.msg);
    CHECK(rc == HFS_E_INVALID, "bogus name gave %d", rc);
    CHECK(ctx == NULL, "out not reset on failure");
    CHECK(err.msg[0] != '\0' && strchr(err.msg, '\n') == NULL, "message not one line");
    CHECK(strstr(err.msg, "bogus") != NULL, "message does not name the context");
    CHECK(strstr(err.msg, "surfaceless") && strstr(err.msg, "osmesa") && strstr(err.msg, "auto"),
          "message does not list the known names");

    /* Names are exact: no case folding, no prefixes. */
    CHECK(hfs_gl_context_create("Surfaceless", &ctx, &err) == HFS_E_INVALID, "case folded");
    CHECK(hfs_gl_context_create("", &ctx, &err) == HFS_E_INVALID, "empty name accepted");
    CHECK(hfs_gl_context_create("osmesa ", &ctx, &err) == HFS_E_INVALID, "trailing space");

    /* An absurdly long name is cut, not overflowed. */
    char long_name[2000];
    memset(long_name, 'x', sizeof long_name - 1);
    long_name[sizeof long_name - 1] = '\0';
    CHECK(hfs_gl_context_create(long_name, &ctx, &err) == HFS_E_INVALID, "long name");
    CHECK(strlen(err.msg) < sizeof err.msg, "message overflow");

    CHECK(hfs_gl_context_create("surfaceless", NULL, &err) == HFS_E_INVALID, "NULL out");
    CHECK(hfs_gl_context_create("bogus", &ctx, NULL) == HFS_E_INVALID, "NULL err");
    hfs_gl_context_destroy(NULL);

    CHECK(strcmp(hfs_gl_context_names(), "surfaceless, osmesa, auto") == 0, "names");

    if (failures) {
        printf("FAIL: %d check(s) failed\n", failures);
        return 1;
    }
    printf("PASS\n");
    return 0;
}
