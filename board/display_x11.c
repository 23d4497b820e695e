/*
 * display_x11.c — "x11" display: an Xlib window on $DISPLAY with an ES 3.0
 * context on EGL's X11 platform (EGL_KHR_platform_x11 / EXT), swap interval
 * 1.  For desktops and for testing the GL display path under Xvfb.
 *
 * Events: the window asks for WM_DELETE_WINDOW (the close button becomes a
 * close request, not a killed connection), Expose (redraws the last picture)
 * and StructureNotify (follows resizes, waits for the first map).  Events are
 * read in present and handle_events alike, so none is lost whichever the
 * caller polls.
 *
 * Capture reads the window back with XGetImage (the server's copy: what is
 * on screen).  It needs the window mapped and entirely on its screen:
 * otherwise the server answers BadMatch, which Xlib's default handler turns
 * into exit(), and installing our own handler would be process-wide state.
 * So we check first and refuse (HFS_E_UNSUPPORTED) instead.
 *
 * Limits: one screen (the default one); the window is a normal managed
 * window (no full-screen request); nothing here handles a lost X connection
 * (Xlib exits the process, as for every Xlib program).  Built only when
 * pkg-config found x11 (HFS_HAVE_X11); otherwise open answers "not built".
 */
#include "display_backend.h"

#include <stdlib.h>

#ifdef HFS_HAVE_X11

#include "display_gl.h"

#include <X11/Xatom.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <poll.h>
#include <string.h>
#include <time.h>

#define DEFAULT_W 640
#define DEFAULT_H 480
#define MAP_TIMEOUT_MS 5000

typedef struct x11_display {
    hfs_display base;
    Display *dpy;
    Window window;
    Colormap colormap;
    XVisualInfo visual;
    Atom wm_delete;
    int mapped, close_requested, exposed;
    hfs_display_gl gl;
} x11_display;

/* Handles every queued event; never blocks. */
static void pump(x11_display *d)
{
    while (XPending(d->dpy)) {
        XEvent ev;
        XNextEvent(d->dpy, &ev);
        switch (ev.type) {
        case MapNotify:
            d->mapped = 1;
            break;
        case UnmapNotify:
            d->mapped = 0;
            break;
        case ConfigureNotify:
            d->base.width = ev.xconfigure.width;
            d->base.height = ev.xconfigure.height;
            break;
        case Expose:
            if (ev.xexpose.count == 0)
                d->exposed = 1;
            break;
        case ClientMessage:
            if ((Atom)ev.xclient.data.l[0] == d->wm_delete)
                d->close_requested = 1;
            break;
        default:
            break;
        }
    }
}

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

/* Drawing before the window is mapped draws into nothing. */
static int wait_mapped(x11_display *d, hfs_error *err)
{
    const double end = now_ms() + MAP_TIMEOUT_MS;
    for (pump(d); !d->mapped; pump(d)) {
        double left = end - now_ms();
        if (left <= 0)
            return hfs_fail(err, HFS_E_CONTEXT, "window not mapped within %d ms",
                            MAP_TIMEOUT_MS);
        struct pollfd p = { .fd = ConnectionNumber(d->dpy), .events = POLLIN };
        poll(&p, 1, (int)left + 1);
    }
    return HFS_OK;
}

static void x11_close(hfs_display *base)
{
    x11_display *d = (x11_display *)base;
    hfs_dgl_close(&d->gl); /* before the window and connection it lives on */
    if (d->window)
        XDestroyWindow(d->dpy, d->window);
    if (d->colormap)
        XFreeColormap(d->dpy, d->colormap);
    if (d->dpy)
        XCloseDisplay(d->dpy);
    free(d);
}

static int make_window(x11_display *d, EGLint visual_id, const hfs_display_opts *o,
                       hfs_error *err)
{
    int screen = DefaultScreen(d->dpy);
    XVisualInfo tmpl = { .visualid = (VisualID)visual_id, .screen = screen };
    int n = 0;
    XVisualInfo *vi = visual_id ? XGetVisualInfo(d->dpy, VisualIDMask | VisualScreenMask,
                                                 &tmpl, &n)
                                : NULL;
    if (vi && n > 0) {
        d->visual = vi[0];
    } else {
        /* EGL gave no visual (allowed): the screen's default one. */
        tmpl.visualid = XVisualIDFromVisual(DefaultVisual(d->dpy, screen));
        if (vi)
            XFree(vi);
        vi = XGetVisualInfo(d->dpy, VisualIDMask | VisualScreenMask, &tmpl, &n);
        if (!vi || n < 1)
            return hfs_fail(err, HFS_E_CONTEXT, "no X visual for EGL visual 0x%x",
                            (unsigned)visual_id);
        d->visual = vi[0];
    }
    XFree(vi);

    Window root = RootWindow(d->dpy, screen);
    d->colormap = XCreateColormap(d->dpy, root, d->visual.visual, AllocNone);
    XSetWindowAttributes a;
    memset(&a, 0, sizeof a);
    a.colormap = d->colormap;
    a.background_pixel = 0; /* black until the first picture */
    a.border_pixel = 0;     /* needed when the visual is not the root's */
    a.event_mask = StructureNotifyMask | ExposureMask;
    d->window = XCreateWindow(d->dpy, root, 0, 0, (unsigned)d->base.width,
                              (unsigned)d->base.height, 0, d->visual.depth, InputOutput,
                              d->visual.visual,
                              CWColormap | CWBackPixel | CWBorderPixel | CWEventMask, &a);
    if (!d->window)
        return hfs_fail(err, HFS_E_CONTEXT, "XCreateWindow failed");
    XStoreName(d->dpy, d->window, o->title ? o->title : "hfshade");
    d->wm_delete = XInternAtom(d->dpy, "WM_DELETE_WINDOW", False);
    XSetWMProtocols(d->dpy, d->window, &d->wm_delete, 1);
    XMapWindow(d->dpy, d->window);
    return wait_mapped(d, err);
}

static int x11_open(const hfs_display_opts *o, hfs_display **out, hfs_error *err)
{
    static const char *const platform_exts[] = { "EGL_KHR_platform_x11",
                                                 "EGL_EXT_platform_x11", NULL };
    int rc;
    x11_display *d = calloc(1, sizeof *d);
    if (!d)
        return hfs_fail(err, HFS_E_NOMEM, "out of memory");
    d->gl.display = EGL_NO_DISPLAY;
    d->base.width = o->width > 0 ? o->width : DEFAULT_W;
    d->base.height = o->height > 0 ? o->height : DEFAULT_H;

    d->dpy = XOpenDisplay(NULL);
    if (!d->dpy) {
        const char *name = getenv("DISPLAY");
        if (!name || !*name)
            rc = hfs_fail(err, HFS_E_CONTEXT, "cannot open X display (DISPLAY unset)");
        else
            rc = hfs_fail(err, HFS_E_CONTEXT, "cannot open X display '%s' (no X server "
                          "there, or no access)", name);
        goto fail;
    }
    EGLint visual = 0;
    if ((rc = hfs_dgl_open(&d->gl, EGL_PLATFORM_X11_KHR, d->dpy, platform_exts, err)) ||
        (rc = hfs_dgl_choose_config(&d->gl, -1, &visual, err)) ||
        (rc = make_window(d, visual, o, err)) ||
        (rc = hfs_dgl_start(&d->gl, &d->window, err)))
        goto fail;
    *out = &d->base;
    return HFS_OK;

fail:
    x11_close(&d->base);
    return rc;
}

static int x11_present(hfs_display *base, const uint8_t *rgba, int w, int h, hfs_error *err)
{
    x11_display *d = (x11_display *)base;
    int rc;
    pump(d);
    if ((rc = hfs_dgl_make_current(&d->gl, err)) ||
        (rc = hfs_dgl_draw(&d->gl, rgba, w, h, d->base.width, d->base.height, err)) ||
        (rc = hfs_dgl_swap(&d->gl, err)))
        return rc;
    d->exposed = 0;
    return HFS_OK;
}

static int x11_fd(const hfs_display *base)
{
    const x11_display *d = (const x11_display *)base;
    return ConnectionNumber(d->dpy);
}

static int x11_handle_events(hfs_display *base)
{
    x11_display *d = (x11_display *)base;
    pump(d);
    if (d->exposed && d->gl.tex_w > 0) {
        /* The server dropped the window's contents: show the last picture
         * again (a failure here shows at the next present). */
        if (!hfs_dgl_make_current(&d->gl, NULL) &&
            !hfs_dgl_draw(&d->gl, NULL, 0, 0, d->base.width, d->base.height, NULL))
            hfs_dgl_swap(&d->gl, NULL);
        d->exposed = 0;
    }
    return d->close_requested;
}

/* Bits of a visual mask: its shift and width. */
static void mask_shift(unsigned long mask, int *shift, int *bits)
{
    *shift = 0;
    *bits = 0;
    if (!mask)
        return;
    while (!(mask & 1)) {
        mask >>= 1;
        ++*shift;
    }
    while (mask & 1) {
        mask >>= 1;
        ++*bits;
    }
}

static uint8_t channel(unsigned long pixel, int shift, int bits)
{
    unsigned long v = (pixel >> shift) & ((1ul << bits) - 1);
    unsigned long max = (1ul << bits) - 1;
    return (uint8_t)(bits == 8 ? v : (v * 255 + max / 2) / max);
}

static int x11_capture(hfs_display *base, uint8_t **rgba, int *w, int *h, hfs_error *err)
{
    x11_display *d = (x11_display *)base;
    XWindowAttributes wa;
    Window child;
    int rx = 0, ry = 0;

    pump(d);
    if (d->gl.tex_w < 1)
        return hfs_fail(err, HFS_E_INVALID, "nothing presented yet");
    /* Make sure the server has executed everything (the swap's image too). */
    XSync(d->dpy, False);
    if (!XGetWindowAttributes(d->dpy, d->window, &wa) || wa.map_state != IsViewable)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "cannot capture: window not viewable");
    XTranslateCoordinates(d->dpy, d->window, wa.root, 0, 0, &rx, &ry, &child);
    if (rx < 0 || ry < 0 || rx + wa.width > WidthOfScreen(wa.screen) ||
        ry + wa.height > HeightOfScreen(wa.screen))
        return hfs_fail(err, HFS_E_UNSUPPORTED, "cannot capture: window not entirely on "
                        "screen (%dx%d at %d,%d)", wa.width, wa.height, rx, ry);
    XImage *img = XGetImage(d->dpy, d->window, 0, 0, (unsigned)wa.width, (unsigned)wa.height,
                            AllPlanes, ZPixmap);
    if (!img)
        return hfs_fail(err, HFS_E_CONTEXT, "XGetImage failed");
    int rs, rb, gs, gb, bs, bb;
    mask_shift(d->visual.red_mask, &rs, &rb);
    mask_shift(d->visual.green_mask, &gs, &gb);
    mask_shift(d->visual.blue_mask, &bs, &bb);
    if (d->visual.class != TrueColor || !rb || !gb || !bb) {
        XDestroyImage(img);
        return hfs_fail(err, HFS_E_UNSUPPORTED, "cannot capture: not a TrueColor visual");
    }
    uint8_t *p = malloc((size_t)wa.width * (size_t)wa.height * 4);
    if (!p) {
        XDestroyImage(img);
        return hfs_fail(err, HFS_E_NOMEM, "out of memory");
    }
    for (int y = 0; y < wa.height; ++y)
        for (int x = 0; x < wa.width; ++x) {
            unsigned long px = XGetPixel(img, x, y);
            uint8_t *o = p + ((size_t)y * (size_t)wa.width + (size_t)x) * 4;
            o[0] = channel(px, rs, rb);
            o[1] = channel(px, gs, gb);
            o[2] = channel(px, bs, bb);
            o[3] = 255;
        }
    XDestroyImage(img);
    *rgba = p;
    *w = wa.width;
    *h = wa.height;
    return HFS_OK;
}

/* Embedding (display.h hfs_display_present_texture): our EGL handles for
 * a renderer to share, and its texture shown as an upload would be. */
static void x11_gl_handles(const hfs_display *base, void **egl_display, void **egl_context)
{
    const x11_display *d = (const x11_display *)base;
    *egl_display = d->gl.display;
    *egl_context = d->gl.context;
}

static int x11_present_texture(hfs_display *base, unsigned texture, void *fence, int w, int h,
                                hfs_error *err)
{
    x11_display *d = (x11_display *)base;
    hfs_dgl_show_texture(&d->gl, texture, fence, w, h);
    return x11_present(base, NULL, w, h, err); /* draws what is shown */
}

#else /* !HFS_HAVE_X11 */

static int x11_open(const hfs_display_opts *o, hfs_display **out, hfs_error *err)
{
    (void)o;
    (void)out;
    return hfs_fail(err, HFS_E_UNSUPPORTED, "not built (configure with libx11-dev installed)");
}

static void x11_close(hfs_display *base) { free(base); }
static int x11_present(hfs_display *b, const uint8_t *p, int w, int h, hfs_error *err)
{
    (void)b, (void)p, (void)w, (void)h;
    return hfs_fail(err, HFS_E_UNSUPPORTED, "not built");
}
static int x11_fd(const hfs_display *b) { (void)b; return -1; }
static int x11_handle_events(hfs_display *b) { (void)b; return 0; }
static int x11_capture(hfs_display *b, uint8_t **p, int *w, int *h, hfs_error *err)
{
    (void)b, (void)p, (void)w, (void)h;
    return hfs_fail(err, HFS_E_UNSUPPORTED, "not built");
}

#endif /* HFS_HAVE_X11 */

const struct hfs_display_backend hfs_display_backend_x11 = {
    .name = "x11",
    .open = x11_open,
    .close = x11_close,
    .present = x11_present,
    .fd = x11_fd,
    .handle_events = x11_handle_events,
    .capture = x11_capture,
#ifdef HFS_HAVE_X11
    .gl_handles = x11_gl_handles,
    .present_texture = x11_present_texture,
#endif
};
