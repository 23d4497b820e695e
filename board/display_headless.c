/*
 * display_headless.c — "headless" display: no screen and no GL.  Keeps the
 * last canvas in memory (hfs_display_capture returns it) and, with
 * out_pattern, writes every presented canvas as a numbered RGBA PNG through
 * hfshade_io (frame numbers count presents from 0).
 *
 * The canvas is the picture itself when no size was asked for; with a size
 * it is that size, black, with the picture fitted in by nearest neighbour
 * (GL displays use bilinear at non-integer scales, so those canvases differ
 * from a window's there; at integer scales they are the same).
 *
 * For CI and for kiosks whose frames are collected rather than shown.
 */
#include "display_backend.h"
#include "hfs_io.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct headless_display {
    hfs_display base;
    int fixed_size;      /* a size was asked for: the canvas keeps it */
    char *out_pattern;   /* owned copy, or NULL */
    int frame;           /* next frame number */
    uint8_t *canvas;     /* base.width x base.height RGBA8, or NULL */
} headless_display;

/* A pattern is used with exactly one int argument: accept one %d-like
 * conversion (flags, width, precision allowed) and %%, nothing else, so a
 * stray %s can never read a missing argument. */
static int pattern_ok(const char *p)
{
    int conversions = 0;
    for (; *p; ++p) {
        if (*p != '%')
            continue;
        ++p;
        if (*p == '%')
            continue;
        while (*p && strchr("-+ 0#", *p))
            ++p;
        while (*p >= '0' && *p <= '9')
            ++p;
        if (*p == '.')
            for (++p; *p >= '0' && *p <= '9'; ++p)
                ;
        if (*p != 'd' && *p != 'i' && *p != 'u' && *p != 'x' && *p != 'X' && *p != 'o')
            return 0;
        ++conversions;
    }
    return conversions == 1;
}

static int headless_open(const hfs_display_opts *o, hfs_display **out, hfs_error *err)
{
    headless_display *d = calloc(1, sizeof *d);
    if (!d)
        return hfs_fail(err, HFS_E_NOMEM, "out of memory");
    if (o->out_pattern) {
        if (!pattern_ok(o->out_pattern)) {
            free(d);
            return hfs_fail(err, HFS_E_INVALID, "output pattern \"%s\" must hold exactly one "
                            "integer conversion (\"frame-%%04d.png\")", o->out_pattern);
        }
        d->out_pattern = strdup(o->out_pattern);
        if (!d->out_pattern) {
            free(d);
            return hfs_fail(err, HFS_E_NOMEM, "out of memory");
        }
    }
    d->fixed_size = o->width > 0;
    d->base.width = o->width;
    d->base.height = o->height;
    *out = &d->base;
    return HFS_OK;
}

static void headless_close(hfs_display *base)
{
    headless_display *d = (headless_display *)base;
    free(d->canvas);
    free(d->out_pattern);
    free(d);
}

/* Nearest-neighbour fit of the picture on a black canvas. */
static void blit_nearest(uint8_t *dst, int dw, int dh, const uint8_t *src, int sw, int sh)
{
    hfs_display_fit f = hfs_display_fit_rect(sw, sh, dw, dh);
    memset(dst, 0, (size_t)dw * (size_t)dh * 4);
    for (size_t k = 3; k < (size_t)dw * (size_t)dh * 4; k += 4)
        dst[k] = 255;
    for (int y = 0; y < f.h; ++y) {
        int sy = (int)(((long long)y * sh) / f.h);
        uint8_t *row = dst + ((size_t)(f.y + y) * (size_t)dw + (size_t)f.x) * 4;
        for (int x = 0; x < f.w; ++x) {
            int sx = (int)(((long long)x * sw) / f.w);
            memcpy(row + 4 * (size_t)x, src + ((size_t)sy * (size_t)sw + (size_t)sx) * 4, 3);
        }
    }
}

static int headless_present(hfs_display *base, const uint8_t *rgba, int w, int h,
                            hfs_error *err)
{
    headless_display *d = (headless_display *)base;
    int cw = d->fixed_size ? d->base.width : w, ch = d->fixed_size ? d->base.height : h;

    if (!d->canvas || cw != d->base.width || ch != d->base.height) {
        uint8_t *c = realloc(d->canvas, (size_t)cw * (size_t)ch * 4);
        if (!c)
            return hfs_fail(err, HFS_E_NOMEM, "out of memory for a %dx%d canvas", cw, ch);
        d->canvas = c;
        d->base.width = cw;
        d->base.height = ch;
    }
    if (d->fixed_size) {
        blit_nearest(d->canvas, cw, ch, rgba, w, h);
    } else {
        /* The screen is opaque: alpha 255 as a window capture would give. */
        for (size_t k = 0; k < (size_t)w * (size_t)h * 4; k += 4) {
            memcpy(d->canvas + k, rgba + k, 3);
            d->canvas[k + 3] = 255;
        }
    }
    if (d->out_pattern) {
        char path[4096];
        int n = snprintf(path, sizeof path, d->out_pattern, d->frame);
        if (n < 0 || (size_t)n >= sizeof path)
            return hfs_fail(err, HFS_E_INVALID, "output pattern \"%s\" makes a path too long",
                            d->out_pattern);
        int rc = hfs_png_write_rgba8(path, cw, ch, d->canvas, err);
        if (rc)
            return rc;
    }
    d->frame++;
    return HFS_OK;
}

static int headless_fd(const hfs_display *base)
{
    (void)base;
    return -1;
}

static int headless_handle_events(hfs_display *base)
{
    (void)base;
    return 0;
}

static int headless_capture(hfs_display *base, uint8_t **rgba, int *w, int *h, hfs_error *err)
{
    headless_display *d = (headless_display *)base;
    size_t n = (size_t)d->base.width * (size_t)d->base.height * 4;
    if (!d->canvas)
        return hfs_fail(err, HFS_E_INVALID, "nothing presented yet");
    *rgba = malloc(n);
    if (!*rgba)
        return hfs_fail(err, HFS_E_NOMEM, "out of memory");
    memcpy(*rgba, d->canvas, n);
    *w = d->base.width;
    *h = d->base.height;
    return HFS_OK;
}

const struct hfs_display_backend hfs_display_backend_headless = {
    .name = "headless",
    .open = headless_open,
    .close = headless_close,
    .present = headless_present,
    .fd = headless_fd,
    .handle_events = headless_handle_events,
    .capture = headless_capture,
};
