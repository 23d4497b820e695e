/*
 * display_kms.c — "kms" display: the board's screen without a window system
 * (kmscube's legacy path): DRM/KMS for the mode and the page flips, GBM for
 * the scan-out buffers, EGL on EGL_PLATFORM_GBM_KHR for an ES 3.0 context.
 *
 * Open: the given card, or the first /dev/dri/card* (in number order) with a
 * connected connector; on it the first connected connector, its preferred
 * mode (or the mode of the asked size), the CRTC its encoder drives (else
 * the first CRTC an encoder of it can drive).  The CRTC as it was is saved.
 * We must be DRM master: the first opener of a card is, unless another
 * display server (X, Wayland, a console login's fbcon does not count) is.
 *
 * Present: draw, eglSwapBuffers, lock GBM's front buffer, wrap it in a DRM
 * framebuffer (once per buffer: the fb id lives in the bo's user data and
 * goes with it), then drmModeSetCrtc for the first frame, and later
 * drmModePageFlip with DRM_MODE_PAGE_FLIP_EVENT, waiting for the event: the
 * flip happens at vblank, so present returns at the display's rate.  The
 * buffer shown before is released back to GBM only after the flip, so GBM
 * never renders into the buffer being scanned out.
 *
 * Close: the saved CRTC (mode, framebuffer, position) is put back before
 * our buffers are destroyed, then DRM master is dropped.
 *
 * Limits (DISPLAY.md): legacy KMS (no atomic), one connector, XRGB8888,
 * no hot-plug, no capture; never run here on real hardware (no /dev/dri on
 * the development machine).  Built only when pkg-config found libdrm and
 * gbm (HFS_HAVE_KMS); otherwise open answers "not built".
 */
#include "display_backend.h"

#include <stdlib.h>

#ifdef HFS_HAVE_KMS

#include "display_gl.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <gbm.h>
#include <poll.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include <xf86drm.h>
#include <xf86drmMode.h>

#define DRI_DIR "/dev/dri"
#define MAX_CARDS 16
#define FLIP_TIMEOUT_MS 1000

typedef struct kms_display {
    hfs_display base;
    int fd;
    int master;                 /* we hold DRM master: drop it on close */
    uint32_t connector_id, crtc_id;
    drmModeModeInfo mode;
    drmModeCrtc *saved_crtc;    /* the CRTC as we found it, restored on close */
    int crtc_set;               /* our first frame went out with SetCrtc */
    struct gbm_device *gbm;
    struct gbm_surface *surface;
    struct gbm_bo *shown;       /* the buffer on screen (locked), or NULL */
    hfs_display_gl gl;
} kms_display;

/* A DRM framebuffer wrapping a GBM buffer, freed with the buffer. */
typedef struct kms_fb {
    int fd;
    uint32_t id;
} kms_fb;

static void fb_destroy(struct gbm_bo *bo, void *data)
{
    kms_fb *fb = data;
    (void)bo;
    if (fb->id)
        drmModeRmFB(fb->fd, fb->id);
    free(fb);
}

static int bo_fb(kms_display *d, struct gbm_bo *bo, uint32_t *id, hfs_error *err)
{
    kms_fb *fb = gbm_bo_get_user_data(bo);
    if (fb) {
        *id = fb->id;
        return HFS_OK;
    }
    fb = calloc(1, sizeof *fb);
    if (!fb)
        return hfs_fail(err, HFS_E_NOMEM, "out of memory");
    fb->fd = d->fd;
    /* depth 24, 32 bits per pixel: XRGB8888, the GBM surface's format. */
    if (drmModeAddFB(d->fd, gbm_bo_get_width(bo), gbm_bo_get_height(bo), 24, 32,
                     gbm_bo_get_stride(bo), gbm_bo_get_handle(bo).u32, &fb->id)) {
        int e = errno;
        free(fb);
        return hfs_fail(err, HFS_E_CONTEXT, "drmModeAddFB failed (%s)", strerror(e));
    }
    gbm_bo_set_user_data(bo, fb, fb_destroy);
    *id = fb->id;
    return HFS_OK;
}

/* The first connected connector with a mode, or NULL. */
static drmModeConnector *connected(int fd, const drmModeRes *res)
{
    for (int i = 0; i < res->count_connectors; ++i) {
        drmModeConnector *c = drmModeGetConnector(fd, res->connectors[i]);
        if (c && c->connection == DRM_MODE_CONNECTED && c->count_modes > 0)
            return c;
        drmModeFreeConnector(c);
    }
    return NULL;
}

static uint32_t find_crtc(int fd, const drmModeRes *res, const drmModeConnector *conn)
{
    uint32_t crtc = 0;
    drmModeEncoder *enc = conn->encoder_id ? drmModeGetEncoder(fd, conn->encoder_id) : NULL;
    if (enc && enc->crtc_id)
        crtc = enc->crtc_id; /* what the console uses now: no reconfiguration */
    drmModeFreeEncoder(enc);
    for (int i = 0; !crtc && i < conn->count_encoders; ++i) {
        enc = drmModeGetEncoder(fd, conn->encoders[i]);
        for (int j = 0; enc && !crtc && j < res->count_crtcs && j < 32; ++j)
            if (enc->possible_crtcs & (1u << j))
                crtc = res->crtcs[j];
        drmModeFreeEncoder(enc);
    }
    return crtc;
}

static int pick_mode(kms_display *d, const drmModeConnector *conn, const hfs_display_opts *o,
                     hfs_error *err)
{
    int pick = -1;
    for (int i = 0; i < conn->count_modes && pick < 0; ++i) {
        const drmModeModeInfo *m = &conn->modes[i];
        if (o->width > 0 ? (m->hdisplay == o->width && m->vdisplay == o->height)
                         : (m->type & DRM_MODE_TYPE_PREFERRED) != 0)
            pick = i;
    }
    if (pick < 0 && o->width > 0)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "connector %u has no %dx%d mode (preferred: %s)",
                        conn->connector_id, o->width, o->height, conn->modes[0].name);
    d->mode = conn->modes[pick < 0 ? 0 : pick]; /* no preferred flag: the first (largest) */
    d->base.width = d->mode.hdisplay;
    d->base.height = d->mode.vdisplay;
    return HFS_OK;
}

/* Tries one card; on failure appends "PATH: reason" to why. */
static int try_card(kms_display *d, const char *path, const hfs_display_opts *o, char *why,
                    size_t why_size, hfs_error *err)
{
    size_t used = strlen(why);
    const char *sep = used ? "; " : "";
    int fd = open(path, O_RDWR | O_CLOEXEC);
    if (fd < 0) {
        snprintf(why + used, why_size - used, "%s%s: %s", sep, path, strerror(errno));
        return HFS_E_CONTEXT;
    }
    drmModeRes *res = drmModeGetResources(fd);
    drmModeConnector *conn = res ? connected(fd, res) : NULL;
    uint32_t crtc = conn ? find_crtc(fd, res, conn) : 0;
    int rc = HFS_OK;
    if (!res || !conn || !crtc) {
        snprintf(why + used, why_size - used, "%s%s: %s", sep, path,
                 !res ? "not a KMS device" : !conn ? "no connected connector"
                                                   : "no CRTC for the connector");
        rc = HFS_E_CONTEXT;
    } else {
        d->fd = fd;
        d->connector_id = conn->connector_id;
        d->crtc_id = crtc;
        rc = pick_mode(d, conn, o, err);
    }
    drmModeFreeConnector(conn);
    drmModeFreeResources(res);
    if (rc && d->fd != fd)
        close(fd);
    return rc;
}

static int card_number(const char *name)
{
    return strncmp(name, "card", 4) == 0 && name[4] >= '0' && name[4] <= '9' ? atoi(name + 4)
                                                                              : -1;
}

static int find_device(kms_display *d, const hfs_display_opts *o, hfs_error *err)
{
    char why[400] = "";
    if (o->device) {
        int rc = try_card(d, o->device, o, why, sizeof why, err);
        if (rc == HFS_E_CONTEXT)
            return hfs_fail(err, rc, "%s", why);
        return rc;
    }
    /* Cards in number order, so "the first card" means the same every boot. */
    int cards[MAX_CARDS], n = 0;
    DIR *dir = opendir(DRI_DIR);
    for (struct dirent *e; dir && (e = readdir(dir)) != NULL;) {
        int k = card_number(e->d_name);
        if (k >= 0 && n < MAX_CARDS)
            cards[n++] = k;
    }
    if (dir)
        closedir(dir);
    for (int i = 1; i < n; ++i)
        for (int j = i; j > 0 && cards[j - 1] > cards[j]; --j) {
            int t = cards[j];
            cards[j] = cards[j - 1];
            cards[j - 1] = t;
        }
    for (int i = 0; i < n; ++i) {
        char path[64];
        snprintf(path, sizeof path, DRI_DIR "/card%d", cards[i]);
        int rc = try_card(d, path, o, why, sizeof why, err);
        if (rc != HFS_E_CONTEXT)
            return rc; /* found (0), or a card that cannot do what was asked */
    }
    return hfs_fail(err, HFS_E_CONTEXT, "no DRM device with a connected connector (%s)",
                    n ? why : DRI_DIR ": none");
}

static int take_master(kms_display *d, hfs_error *err)
{
    if (drmIsMaster(d->fd) || drmSetMaster(d->fd) == 0) {
        d->master = 1;
        return HFS_OK;
    }
    return hfs_fail(err, HFS_E_CONTEXT, "not DRM master (%s); is another display server "
                    "running?", strerror(errno));
}

static void kms_close(hfs_display *base)
{
    kms_display *d = (kms_display *)base;
    if (d->saved_crtc) {
        /* Give the screen back as it was before our buffers disappear. */
        drmModeCrtc *c = d->saved_crtc;
        if (d->crtc_set)
            drmModeSetCrtc(d->fd, c->crtc_id, c->buffer_id, c->x, c->y, &d->connector_id, 1,
                           c->mode_valid ? &c->mode : NULL);
        drmModeFreeCrtc(c);
    }
    if (d->shown)
        gbm_surface_release_buffer(d->surface, d->shown);
    hfs_dgl_close(&d->gl); /* the EGL surface before the GBM surface under it */
    if (d->surface)
        gbm_surface_destroy(d->surface); /* frees the bos, their fbs with them */
    if (d->gbm)
        gbm_device_destroy(d->gbm);
    if (d->master)
        drmDropMaster(d->fd);
    if (d->fd >= 0)
        close(d->fd);
    free(d);
}

static int kms_open(const hfs_display_opts *o, hfs_display **out, hfs_error *err)
{
    static const char *const platform_exts[] = { "EGL_KHR_platform_gbm",
                                                 "EGL_MESA_platform_gbm", NULL };
    int rc;
    kms_display *d = calloc(1, sizeof *d);
    if (!d)
        return hfs_fail(err, HFS_E_NOMEM, "out of memory");
    d->fd = -1;
    d->gl.display = EGL_NO_DISPLAY;
    if ((rc = find_device(d, o, err)) || (rc = take_master(d, err)))
        goto fail;
    d->saved_crtc = drmModeGetCrtc(d->fd, d->crtc_id);
    d->gbm = gbm_create_device(d->fd);
    if (!d->gbm) {
        rc = hfs_fail(err, HFS_E_CONTEXT, "gbm_create_device failed");
        goto fail;
    }
    d->surface = gbm_surface_create(d->gbm, d->mode.hdisplay, d->mode.vdisplay,
                                    GBM_FORMAT_XRGB8888,
                                    GBM_BO_USE_SCANOUT | GBM_BO_USE_RENDERING);
    if (!d->surface) {
        rc = hfs_fail(err, HFS_E_CONTEXT, "gbm_surface_create(%ux%u XRGB8888) failed",
                      d->mode.hdisplay, d->mode.vdisplay);
        goto fail;
    }
    if ((rc = hfs_dgl_open(&d->gl, EGL_PLATFORM_GBM_KHR, d->gbm, platform_exts, err)) ||
        (rc = hfs_dgl_choose_config(&d->gl, GBM_FORMAT_XRGB8888, NULL, err)) ||
        (rc = hfs_dgl_start(&d->gl, d->surface, err)))
        goto fail;
    *out = &d->base;
    return HFS_OK;

fail:
    kms_close(&d->base);
    return rc;
}

static void on_flip(int fd, unsigned sequence, unsigned sec, unsigned usec, void *data)
{
    (void)fd, (void)sequence, (void)sec, (void)usec;
    *(int *)data = 0;
}

static int flip_and_wait(kms_display *d, uint32_t fb, hfs_error *err)
{
    int waiting = 1;
    if (drmModePageFlip(d->fd, d->crtc_id, fb, DRM_MODE_PAGE_FLIP_EVENT, &waiting))
        return hfs_fail(err, HFS_E_CONTEXT, "drmModePageFlip failed (%s)", strerror(errno));
    drmEventContext ev = { .version = 2, .page_flip_handler = on_flip };
    while (waiting) {
        struct pollfd p = { .fd = d->fd, .events = POLLIN };
        int n = poll(&p, 1, FLIP_TIMEOUT_MS);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return hfs_fail(err, HFS_E_CONTEXT, "page flip not done within %d ms",
                            FLIP_TIMEOUT_MS);
        drmHandleEvent(d->fd, &ev);
    }
    return HFS_OK;
}

static int kms_present(hfs_display *base, const uint8_t *rgba, int w, int h, hfs_error *err)
{
    kms_display *d = (kms_display *)base;
    uint32_t fb = 0;
    int rc;
    if ((rc = hfs_dgl_make_current(&d->gl, err)) ||
        (rc = hfs_dgl_draw(&d->gl, rgba, w, h, d->base.width, d->base.height, err)) ||
        (rc = hfs_dgl_swap(&d->gl, err)))
        return rc;
    struct gbm_bo *bo = gbm_surface_lock_front_buffer(d->surface);
    if (!bo)
        return hfs_fail(err, HFS_E_CONTEXT, "gbm_surface_lock_front_buffer failed");
    if ((rc = bo_fb(d, bo, &fb, err)))
        goto release;
    if (!d->crtc_set) {
        if (drmModeSetCrtc(d->fd, d->crtc_id, fb, 0, 0, &d->connector_id, 1, &d->mode)) {
            rc = hfs_fail(err, HFS_E_CONTEXT, "drmModeSetCrtc(%s) failed (%s)", d->mode.name,
                          strerror(errno));
            goto release;
        }
        d->crtc_set = 1;
    } else if ((rc = flip_and_wait(d, fb, err))) {
        goto release;
    }
    if (d->shown)
        gbm_surface_release_buffer(d->surface, d->shown);
    d->shown = bo;
    return HFS_OK;

release:
    /* Not on screen: give it back, or GBM runs out of buffers. */
    gbm_surface_release_buffer(d->surface, bo);
    return rc;
}

static int kms_fd(const hfs_display *base)
{
    (void)base;
    return -1; /* no window-system events; flips are waited for inside present */
}

static int kms_handle_events(hfs_display *base)
{
    (void)base;
    return 0;
}

static int kms_capture(hfs_display *base, uint8_t **rgba, int *w, int *h, hfs_error *err)
{
    (void)base, (void)rgba, (void)w, (void)h;
    return hfs_fail(err, HFS_E_UNSUPPORTED, "capture not supported (scan-out buffers are "
                    "not read back)");
}

/* Embedding (display.h hfs_display_present_texture): our EGL handles for
 * a renderer to share, and its texture shown as an upload would be. */
static void kms_gl_handles(const hfs_display *base, void **egl_display, void **egl_context)
{
    const kms_display *d = (const kms_display *)base;
    *egl_display = d->gl.display;
    *egl_context = d->gl.context;
}

static int kms_present_texture(hfs_display *base, unsigned texture, void *fence, int w, int h,
                                hfs_error *err)
{
    kms_display *d = (kms_display *)base;
    hfs_dgl_show_texture(&d->gl, texture, fence, w, h);
    return kms_present(base, NULL, w, h, err); /* draws what is shown */
}

#else /* !HFS_HAVE_KMS */

static int kms_open(const hfs_display_opts *o, hfs_display **out, hfs_error *err)
{
    (void)o;
    (void)out;
    return hfs_fail(err, HFS_E_UNSUPPORTED,
                    "not built (configure with libdrm-dev and libgbm-dev installed)");
}

static void kms_close(hfs_display *base) { free(base); }
static int kms_present(hfs_display *b, const uint8_t *p, int w, int h, hfs_error *err)
{
    (void)b, (void)p, (void)w, (void)h;
    return hfs_fail(err, HFS_E_UNSUPPORTED, "not built");
}
static int kms_fd(const hfs_display *b) { (void)b; return -1; }
static int kms_handle_events(hfs_display *b) { (void)b; return 0; }
static int kms_capture(hfs_display *b, uint8_t **p, int *w, int *h, hfs_error *err)
{
    (void)b, (void)p, (void)w, (void)h;
    return hfs_fail(err, HFS_E_UNSUPPORTED, "not built");
}

#endif /* HFS_HAVE_KMS */

const struct hfs_display_backend hfs_display_backend_kms = {
    .name = "kms",
    .open = kms_open,
    .close = kms_close,
    .present = kms_present,
    .fd = kms_fd,
    .handle_events = kms_handle_events,
    .capture = kms_capture,
#ifdef HFS_HAVE_KMS
    .gl_handles = kms_gl_handles,
    .present_texture = kms_present_texture,
#endif
};
