/*
 * gl_require.c — see gl_require.h.
 */
#include "gl_require.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl_context.h"

int hfs_gl_required(void)
{
    const char *v = getenv("HFS_REQUIRE_GL");
    return v && strcmp(v, "1") == 0;
}

int hfs_gl_missing_device(hfs_error *why)
{
    hfs_gl_context *ctx = NULL;
    hfs_error probe = {""};
    const int rc = hfs_gl_context_create("auto", &ctx, &probe);
    if (rc == HFS_OK) {
        snprintf(why->msg, sizeof why->msg, "a GLES context can be made here (%.200s)",
                 hfs_gl_context_describe(ctx));
        hfs_gl_context_destroy(ctx);
        return 0;
    }
    if (hfs_gl_required()) {
        snprintf(why->msg, sizeof why->msg, "HFS_REQUIRE_GL=1 and no GLES context can be made: %.400s",
                 probe.msg);
        return 0;
    }
    snprintf(why->msg, sizeof why->msg, "no GLES context of any kind here: %.400s", probe.msg);
    return 1;
}
