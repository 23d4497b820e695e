/*
 * display.c — picks a display backend by name and does what every backend
 * shares: argument checks, the "display NAME:" message prefix, the fit of a
 * picture on the screen.
 *
 * Invariants: a backend is only called with valid arguments; every error
 * leaving this file names the backend.  No global state.
 */
#include "display_backend.h"

#include <stdlib.h>
#include <string.h>

/* The largest picture side a display accepts: the GL texture size every
 * ES 3.0 device must support, and far beyond any screen. */
#define MAX_SIDE HFS_DISPLAY_MAX_SIDE

static const struct hfs_display_backend *const backends[] = {
    &hfs_display_backend_kms,
    &hfs_display_backend_x11,
    &hfs_display_backend_headless,
};

const char *hfs_display_names(void)
{
    return "kms, x11, headless";
}

/* Prefixes err's message with "display NAME: " in place. */
static int prefixed(hfs_error *err, const char *name, int rc)
{
    if (err) {
        hfs_error tmp = *err;
        hfs_fail(err, rc, "display %s: %s", name, tmp.msg);
    }
    return rc;
}

int hfs_display_open(const char *name, const hfs_display_opts *o, hfs_display **out,
                     hfs_error *err)
{
    const hfs_display_opts defaults = {0};
    if (!out)
        return hfs_fail(err, HFS_E_INVALID, "display: no output pointer");
    *out = NULL;
    if (!name)
        return hfs_fail(err, HFS_E_INVALID, "display: no name (known: %s)", hfs_display_names());
    if (!o)
        o = &defaults;
    if (o->width < 0 || o->height < 0 || o->width > MAX_SIDE || o->height > MAX_SIDE)
        return hfs_fail(err, HFS_E_INVALID, "display %s: size %dx%d out of range (0..%d)", name,
                        o->width, o->height, MAX_SIDE);
    if ((o->width == 0) != (o->height == 0))
        return hfs_fail(err, HFS_E_INVALID, "display %s: give both width and height, or neither",
                        name);
    for (size_t i = 0; i < sizeof backends / sizeof backends[0]; ++i) {
        const struct hfs_display_backend *b = backends[i];
        if (strcmp(name, b->name))
            continue;
        hfs_error local;
        hfs_error *e = err ? err : &local;
        int rc = b->open(o, out, e);
        if (rc) {
            *out = NULL;
            return prefixed(err, name, rc);
        }
        (*out)->backend = b;
        return HFS_OK;
    }
    return hfs_fail(err, HFS_E_INVALID, "display \"%s\": unknown (known: %s)", name,
                    hfs_display_names());
}

void hfs_display_size(const hfs_display *d, int *w, int *h)
{
    if (w)
        *w = d ? d->width : 0;
    if (h)
        *h = d ? d->height : 0;
}

const char *hfs_display_name(const hfs_display *d)
{
    return d ? d->backend->name : "";
}

int hfs_display_present(hfs_display *d, const uint8_t *rgba, int w, int h, hfs_error *err)
{
    if (!d)
        return hfs_fail(err, HFS_E_INVALID, "display: none");
    if (!rgba || w < 1 || h < 1 || w > MAX_SIDE || h > MAX_SIDE)
        return hfs_fail(err, HFS_E_INVALID, "display %s: picture %dx%d%s (1..%d per side)",
                        d->backend->name, w, h, rgba ? "" : " without pixels", MAX_SIDE);
    int rc = d->backend->present(d, rgba, w, h, err);
    return rc ? prefixed(err, d->backend->name, rc) : HFS_OK;
}

int hfs_display_gl_handles(const hfs_display *d, void **egl_display, void **egl_context)
{
    *egl_display = *egl_context = NULL;
    if (!d || !d->backend->gl_handles)
        return 0;
    d->backend->gl_handles(d, egl_display, egl_context);
    return *egl_display && *egl_context;
}

int hfs_display_present_texture(hfs_display *d, unsigned texture, void *fence, int w, int h,
                                hfs_error *err)
{
    if (!d)
        return hfs_fail(err, HFS_E_INVALID, "display: none");
    if (!d->backend->present_texture)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "display %s: no GL, no texture to show",
                        d->backend->name);
    if (!texture || w < 1 || h < 1 || w > MAX_SIDE || h > MAX_SIDE)
        return hfs_fail(err, HFS_E_INVALID, "display %s: texture %u of %dx%d (1..%d per side)",
                        d->backend->name, texture, w, h, MAX_SIDE);
    int rc = d->backend->present_texture(d, texture, fence, w, h, err);
    return rc ? prefixed(err, d->backend->name, rc) : HFS_OK;
}

int hfs_display_fd(const hfs_display *d)
{
    return d ? d->backend->fd(d) : -1;
}

int hfs_display_handle_events(hfs_display *d)
{
    return d ? d->backend->handle_events(d) : 0;
}

int hfs_display_capture(hfs_display *d, uint8_t **rgba, int *w, int *h, hfs_error *err)
{
    if (!d || !rgba || !w || !h)
        return hfs_fail(err, HFS_E_INVALID, "display: capture without display or outputs");
    *rgba = NULL;
    *w = *h = 0;
    int rc = d->backend->capture(d, rgba, w, h, err);
    return rc ? prefixed(err, d->backend->name, rc) : HFS_OK;
}

void hfs_display_close(hfs_display *d)
{
    if (d)
        d->backend->close(d);
}

hfs_display_fit hfs_display_fit_rect(int src_w, int src_h, int dst_w, int dst_h)
{
    hfs_display_fit f;
    /* Compare aspects in integers: which side limits the scale. */
    if ((long long)dst_w * src_h <= (long long)dst_h * src_w) {
        f.w = dst_w;
        f.h = (int)(((long long)src_h * dst_w * 2 + src_w) / (2LL * src_w)); /* rounded */
    } else {
        f.h = dst_h;
        f.w = (int)(((long long)src_w * dst_h * 2 + src_h) / (2LL * src_h));
    }
    if (f.w < 1)
        f.w = 1;
    if (f.h < 1)
        f.h = 1;
    if (f.w > dst_w)
        f.w = dst_w;
    if (f.h > dst_h)
        f.h = dst_h;
    f.x = (dst_w - f.w) / 2;
    f.y = (dst_h - f.h) / 2;
    f.nearest = f.w % src_w == 0 && f.h % src_h == 0 && f.w / src_w == f.h / src_h;
    return f;
}
