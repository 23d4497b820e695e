/*
 * status.c — error strings and small value helpers of the public API.
 */
#include "hfshade.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int hfs_fail(hfs_error *err, int code, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err->msg, sizeof err->msg, fmt, ap);
        va_end(ap);
        /* Messages are one line: fold any newline a caller let through. */
        for (char *p = err->msg; *p; ++p)
            if (*p == '\n' || *p == '\r')
                *p = ' ';
    }
    return code;
}

const char *hfs_status_name(int code)
{
    switch (code) {
    case HFS_OK: return "ok";
    case HFS_E_INVALID: return "invalid";
    case HFS_E_NOMEM: return "out of memory";
    case HFS_E_IO: return "i/o";
    case HFS_E_FORMAT: return "format";
    case HFS_E_UNSUPPORTED: return "unsupported";
    case HFS_E_CONTEXT: return "context";
    case HFS_E_GL: return "gl";
    default: return "unknown";
    }
}

void hfs_lighting_defaults(hfs_lighting *l)
{
    memset(l, 0, sizeof *l);
    l->albedo = 1.0;
    l->gloss = 32.0;      /* glossy surfaces: specular 0 = off */
    l->view_dir[2] = 1.0; /* seen from +z (SPEC "Glossy") */
}

int hfs_image_alloc(hfs_image *img, int width, int height, hfs_error *err)
{
    img->width = img->height = 0;
    img->rgb = NULL;
    if (width < 1 || height < 1 || (size_t)width > SIZE_MAX / 3 / sizeof(float) / (size_t)height)
        return hfs_fail(err, HFS_E_INVALID, "image size %dx%d is out of range", width, height);
    img->rgb = calloc((size_t)width * (size_t)height * 3, sizeof(float));
    if (!img->rgb)
        return hfs_fail(err, HFS_E_NOMEM, "out of memory for a %dx%d image", width, height);
    img->width = width;
    img->height = height;
    return HFS_OK;
}

void hfs_image_free(hfs_image *img)
{
    if (!img)
        return;
    free(img->rgb);
    img->rgb = NULL;
    img->width = img->height = 0;
}
