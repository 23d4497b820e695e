/*
 * test_display_x11.c — the "x11" display in a real X server (label "gl"):
 * starts its own Xvfb (-displayfd picks a free display number; -noreset,
 * or the server resets when our last connection closes and refuses the next
 * one for a moment), renders a 64x48 scene with the GLES renderer (cones, a
 * low key light: hard shadows, a dim uniform sky), makes the picture with
 * frame_image, presents it in a window and reads the window back with
 * XGetImage (hfs_display_capture):
 *
 *   1:1   64x48 window, renderer and window alive together (the kiosk's
 *         loop: a second frame rendered between presents, with the
 *         frame-time overlay drawn on it): the capture must equal that
 *         picture byte for byte
 *         (RGBA8 texture, NEAREST, 24-bit TrueColor visual: no dithering,
 *         no conversion; the maximum difference is printed);
 *   2x    128x96 window: exactly the picture scaled 2x by nearest;
 *   fit   100x100 window: 12 black rows above, 13 below, picture between
 *         (bilinear there, so only the bars are checked exactly);
 *   texture a renderer sharing the window's context shows its sRGB
 *         texture (hfs_display_present_texture, issue 20): the same bytes;
 *   close a WM_DELETE_WINDOW message sent from another X client makes
 *         hfs_display_handle_events return 1 (what a close button does).
 *
 * Writes display_x11_expected.png and display_x11_capture.png (and, for 2x,
 * display_x11_capture_2x.png) in the working directory, so a failure can be
 * looked at.  Exits 77 with the reason when Xvfb is not installed, does not
 * start, or no GLES renderer can be made.
 */
#include "display.h"
#include "frame_image.h"
#include "overlay.h"
#include "terrain_gen.h"

#include <X11/Xlib.h>
#include <errno.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "check.h"
#include "test_display_util.h"
#include "gl_test.h"

#define SKIP 77
#define PI 3.14159265358979323846
enum { W = 64, H = 48 };

static pid_t xvfb_pid = -1;

static int on_path(const char *prog)
{
    const char *path = getenv("PATH");
    char buf[4096];
    for (const char *p = path ? path : "/usr/bin:/bin"; *p;) {
        size_t n = strcspn(p, ":");
        snprintf(buf, sizeof buf, "%.*s/%s", (int)n, p, prog);
        if (access(buf, X_OK) == 0)
            return 1;
        p += n + (p[n] == ':');
    }
    return 0;
}

static void stop_xvfb(void)
{
    if (xvfb_pid > 0) {
        kill(xvfb_pid, SIGTERM);
        waitpid(xvfb_pid, NULL, 0);
        xvfb_pid = -1;
    }
}

/* Starts Xvfb on a free display; returns its number, or -1 with why. */
static int start_xvfb(char *why, size_t why_size)
{
    int fds[2];
    if (pipe(fds)) {
        snprintf(why, why_size, "pipe: %s", strerror(errno));
        return -1;
    }
    xvfb_pid = fork();
    if (xvfb_pid < 0) {
        snprintf(why, why_size, "fork: %s", strerror(errno));
        return -1;
    }
    if (xvfb_pid == 0) {
        char fd[16];
        close(fds[0]);
        /* Linux: Xvfb dies with us even if this test crashes. */
        prctl(PR_SET_PDEATHSIG, SIGTERM);
        snprintf(fd, sizeof fd, "%d", fds[1]);
        /* Xvfb's chatter (keymap warnings) goes to a log, not the test's. */
        FILE *log = freopen("display_x11_xvfb.log", "w", stderr);
        (void)log;
        execlp("Xvfb", "Xvfb", "-displayfd", fd, "-screen", "0", "320x240x24", "-noreset", "-nolisten",
               "tcp", (char *)NULL);
        _exit(127);
    }
    close(fds[1]);
    /* Xvfb writes the display number when it accepts connections. */
    char num[32] = "";
    size_t got = 0;
    while (got < sizeof num - 1 && !strchr(num, '\n')) {
        struct pollfd p = {.fd = fds[0], .events = POLLIN};
        if (poll(&p, 1, 20000) <= 0)
            break;
        ssize_t n = read(fds[0], num + got, sizeof num - 1 - got);
        if (n <= 0)
            break;
        got += (size_t)n;
        num[got] = '\0';
    }
    close(fds[0]);
    if (!strchr(num, '\n')) {
        snprintf(why, why_size, "Xvfb did not start (see display_x11_xvfb.log)");
        stop_xvfb();
        return -1;
    }
    return atoi(num);
}

/* The scene: cones, a dim uniform sky and one low key light. */
typedef struct scene {
    hfs_renderer *r;
    float *z;
    hfs_field f;
    hfs_lighting l;
    hfs_quality q;
} scene;

/* Makes the GLES renderer and the scene, or exits 77 when no GLES here. */
static void scene_make(scene *s)
{
    hfs_renderer_desc desc = {.backend = HFS_BACKEND_GLES};
    hfs_error err = {""};
    memset(s, 0, sizeof *s);
    if (hfs_renderer_create(&desc, &s->r, &err)) {
        stop_xvfb();
        gl_test_unavailable("cannot create the GLES renderer", &err);
    }
    s->z = calloc((size_t)W * H, sizeof *s->z);
    hfs_terrain_cones(s->z, W, H);
    s->f = (hfs_field){.width = W, .height = H, .z = s->z, .dx = 1.0, .zscale = 1.0};
    hfs_lighting_defaults(&s->l);
    s->l.has_env = 1;
    for (int c = 0; c < 3; ++c)
        s->l.env_sh[c][0] = 0.08 * sqrt(4.0 * PI); /* uniform sky, radiance 0.08 */
    s->l.n_key = 1;
    s->l.key[0] = (hfs_key_light){.phi = 30 * PI / 180, .elev = 12 * PI / 180,
                                  .alpha = 3 * PI / 180, .radiance = {220, 205, 180}};
    hfs_quality_defaults(&s->q);
}

static void scene_free(scene *s)
{
    hfs_renderer_destroy(s->r);
    free(s->z);
}

/* Renders with the key light at azimuth phi_deg and makes the picture. */
static void render_picture(scene *s, double phi_deg, uint8_t *pic)
{
    hfs_error err = {""};
    hfs_image img = {0}, un = {0};
    s->l.key[0].phi = phi_deg * PI / 180;
    CHECK(hfs_image_alloc(&img, W, H, &err) == 0, "%s", err.msg);
    CHECK(hfs_renderer_render(s->r, &s->f, &s->l, &s->q, &img, NULL, NULL, &err) == 0,
          "render: %s", err.msg);
    /* The scene must show shadows: some texels well below unshadowed. */
    CHECK(hfs_image_alloc(&un, W, H, &err) == 0 &&
          hfs_render_unshadowed(&s->f, &s->l, &s->q, &un, &err) == 0, "%s", err.msg);
    int shadowed = 0;
    for (int k = 0; k < W * H * 3; ++k)
        shadowed += img.rgb[k] < 0.7f * un.rgb[k];
    printf("scene (key at %.0f deg): %d of %d channel values in shadow\n", phi_deg, shadowed,
           W * H * 3);
    CHECK(shadowed > 100, "no visible shadows (%d)", shadowed);
    CHECK(hfs_frame_to_rgba8(&img, NULL, pic, &err) == 0, "%s", err.msg);
    hfs_image_free(&img);
    hfs_image_free(&un);
}

static uint8_t *present_and_capture(const uint8_t *pic, int ww, int wh, int *cw, int *ch)
{
    hfs_display_opts o = {.width = ww, .height = wh, .title = "test_display_x11"};
    hfs_display *d = NULL;
    hfs_error err = {""};
    uint8_t *cap = NULL;
    if (hfs_display_open("x11", &o, &d, &err)) {
        CHECK(0, "open %dx%d: %s", ww, wh, err.msg);
        return NULL;
    }
    CHECK(hfs_display_fd(d) >= 0, "no event fd");
    /* Twice: the second present reuses the texture (TexSubImage2D path). */
    for (int i = 0; i < 2; ++i)
        CHECK(hfs_display_present(d, pic, W, H, &err) == 0, "present: %s", err.msg);
    CHECK(hfs_display_handle_events(d) == 0, "close requested out of the blue");
    CHECK(hfs_display_capture(d, &cap, cw, ch, &err) == 0, "capture: %s", err.msg);
    hfs_display_close(d);
    return cap;
}

/* The kiosk's loop: renderer and window alive together, their contexts
 * made current in turn; the second frame (with the overlay) must be what
 * the window shows, byte for byte. */
static void check_1to1(scene *s, const uint8_t *first)
{
    int cw = 0, ch = 0;
    hfs_error err = {""};
    uint8_t *cap = NULL;
    static uint8_t pic[W * H * 4];
    const uint8_t white[4] = {255, 255, 255, 255}, shade[4] = {0, 0, 0, 160};
    hfs_display_opts o = {.width = W, .height = H, .title = "test_display_x11"};
    hfs_display *d = NULL;
    if (hfs_display_open("x11", &o, &d, &err)) {
        CHECK(0, "open: %s", err.msg);
        return;
    }
    CHECK(hfs_display_present(d, first, W, H, &err) == 0, "present: %s", err.msg);
    render_picture(s, 210.0, pic); /* the renderer's context again */
    hfs_overlay_text(pic, W, H, 1, 1, 1, "12.3 ms", white, shade);
    CHECK(memcmp(pic, first, sizeof pic) != 0, "second frame equals the first");
    CHECK(hfs_display_present(d, pic, W, H, &err) == 0, "present: %s", err.msg);
    CHECK(hfs_display_capture(d, &cap, &cw, &ch, &err) == 0, "capture: %s", err.msg);
    hfs_display_close(d);
    if (!cap)
        return;
    CHECK(cw == W && ch == H, "capture is %dx%d", cw, ch);
    CHECK(hfs_png_write_rgba8("display_x11_expected.png", W, H, pic, &err) == 0, "%s", err.msg);
    CHECK(hfs_png_write_rgba8("display_x11_capture.png", cw, ch, cap, &err) == 0, "%s",
          err.msg);
    /* The PNG on disk is the capture: decode it and compare that. */
    int pw = 0, ph = 0;
    uint8_t *png = read_png_rgba("display_x11_capture.png", &pw, &ph);
    CHECK(png && pw == W && ph == H, "capture PNG unreadable");
    long n = 0;
    int worst = png && pw == W && ph == H ? max_rgb_diff(png, pic, W, H, &n) : 255;
    printf("1:1: capture vs picture: max difference %d/255 over %ld of %d pixels\n", worst, n,
           W * H);
    CHECK(worst == 0, "1:1 capture differs (max %d, %ld pixels)", worst, n);
    free(png);
    free(cap);
}

/* Embedding (issue 20): a renderer sharing the window's context hands the
 * sRGB picture over as a texture (hfs_renderer_render_texture,
 * HFS_LIT_SRGB8), shown with hfs_display_present_texture: no read-back,
 * no upload, and the same bytes on screen as the read-back picture. */
static void check_texture(scene *s, const uint8_t *pic)
{
    int cw = 0, ch = 0;
    hfs_error err = {""};
    uint8_t *cap = NULL;
    hfs_display_opts o = {.width = W, .height = H, .title = "test_display_x11"};
    hfs_display *d = NULL;
    if (hfs_display_open("x11", &o, &d, &err)) {
        CHECK(0, "open: %s", err.msg);
        return;
    }
    hfs_renderer_desc desc = {.backend = HFS_BACKEND_GLES};
    CHECK(hfs_display_gl_handles(d, &desc.egl_display, &desc.egl_share_context) == 1,
          "x11 gives no EGL handles");
    hfs_renderer *r = NULL;
    CHECK(hfs_renderer_create(&desc, &r, &err) == 0, "shared renderer: %s", err.msg);
    const hfs_lit_texture_desc how = {HFS_LIT_SRGB8, 1.0, 0};
    hfs_lit_texture t = {0};
    s->l.key[0].phi = 30.0 * PI / 180; /* pic's light */
    for (int i = 0; r && i < 2; ++i) { /* the second: no pass, the same texture */
        CHECK(hfs_renderer_render_texture(r, &s->f, &s->l, &s->q, &how, &t, &err) == 0,
              "render texture: %s", err.msg);
        CHECK(hfs_display_present_texture(d, t.texture, t.fence, t.width, t.height, &err) == 0,
              "present texture: %s", err.msg);
    }
    CHECK(hfs_display_capture(d, &cap, &cw, &ch, &err) == 0, "capture: %s", err.msg);
    hfs_renderer_destroy(r);
    hfs_display_close(d);
    if (!cap)
        return;
    long n = 0;
    const int worst = cw == W && ch == H ? max_rgb_diff(cap, pic, W, H, &n) : 255;
    printf("texture: capture vs read-back picture: max difference %d/255 over %ld of %d "
           "pixels\n", worst, n, W * H);
    CHECK(worst == 0, "texture capture differs (max %d, %ld pixels)", worst, n);
    free(cap);
}

static void check_2x(const uint8_t *pic)
{
    int cw = 0, ch = 0;
    hfs_error err = {""};
    uint8_t *cap = present_and_capture(pic, 2 * W, 2 * H, &cw, &ch);
    if (!cap)
        return;
    CHECK(cw == 2 * W && ch == 2 * H, "capture is %dx%d", cw, ch);
    hfs_png_write_rgba8("display_x11_capture_2x.png", cw, ch, cap, &err);
    uint8_t *want = malloc((size_t)4 * W * H * 4);
    scale_nearest(pic, W, H, 2, want);
    long n = 0;
    int worst = cw == 2 * W && ch == 2 * H ? max_rgb_diff(cap, want, cw, ch, &n) : 255;
    printf("2x: capture vs nearest 2x: max difference %d/255 over %ld pixels\n", worst, n);
    CHECK(worst == 0, "2x capture differs");
    free(want);
    free(cap);
}

static void check_fit(const uint8_t *pic)
{
    int cw = 0, ch = 0;
    uint8_t *cap = present_and_capture(pic, 100, 100, &cw, &ch);
    if (!cap)
        return;
    /* 64x48 fits as 100x75 at y = 12. */
    int bars_ok = 1, inside_lit = 0;
    for (int y = 0; y < ch; ++y)
        for (int x = 0; x < cw; ++x) {
            const uint8_t *p = cap + ((size_t)y * (size_t)cw + (size_t)x) * 4;
            if (y < 12 || y >= 87)
                bars_ok &= !p[0] && !p[1] && !p[2];
            else
                inside_lit += p[0] > 0;
        }
    CHECK(bars_ok, "letterbox bars not black");
    CHECK(inside_lit > 100 * 75 / 2, "picture missing inside the fit (%d lit)", inside_lit);
    free(cap);
}

/* A close button: WM_DELETE_WINDOW sent by another client to our window. */
static void check_close_request(const uint8_t *pic)
{
    hfs_display *d = NULL;
    hfs_error err = {""};
    hfs_display_opts o = {.width = W, .height = H};
    if (hfs_display_open("x11", &o, &d, &err)) {
        CHECK(0, "open: %s", err.msg);
        return;
    }
    CHECK(hfs_display_present(d, pic, W, H, &err) == 0, "%s", err.msg);
    Display *other = XOpenDisplay(NULL);
    CHECK(other != NULL, "second connection");
    if (other) {
        Window root = DefaultRootWindow(other), parent, *kids = NULL;
        unsigned n = 0;
        XQueryTree(other, root, &root, &parent, &kids, &n);
        Atom protocols = XInternAtom(other, "WM_PROTOCOLS", False);
        Atom del = XInternAtom(other, "WM_DELETE_WINDOW", False);
        for (unsigned i = 0; i < n; ++i) { /* no window manager: ours is the only one */
            XEvent ev;
            memset(&ev, 0, sizeof ev);
            ev.xclient.type = ClientMessage;
            ev.xclient.window = kids[i];
            ev.xclient.message_type = protocols;
            ev.xclient.format = 32;
            ev.xclient.data.l[0] = (long)del;
            XSendEvent(other, kids[i], False, NoEventMask, &ev);
        }
        XFlush(other);
        if (kids)
            XFree(kids);
        CHECK(n >= 1, "no top-level window found");
        int closed = 0;
        for (int t = 0; t < 50 && !closed; ++t) {
            struct pollfd p = {.fd = hfs_display_fd(d), .events = POLLIN};
            poll(&p, 1, 100);
            closed = hfs_display_handle_events(d);
        }
        CHECK(closed == 1, "WM_DELETE_WINDOW did not become a close request");
        CHECK(hfs_display_handle_events(d) == 1, "close request not sticky");
        XCloseDisplay(other);
    }
    hfs_display_close(d);
}

int main(void)
{
    setvbuf(stdout, NULL, _IONBF, 0);
    if (!on_path("Xvfb")) {
        printf("SKIP: Xvfb is not installed (Debian: apt install xvfb)\n");
        return SKIP;
    }
    char why[256] = "";
    int num = start_xvfb(why, sizeof why);
    if (num < 0) {
        printf("SKIP: %s\n", why);
        return SKIP;
    }
    char name[32];
    snprintf(name, sizeof name, ":%d", num);
    setenv("DISPLAY", name, 1);
    printf("Xvfb on %s\n", name);

    static uint8_t pic[W * H * 4];
    scene s;
    scene_make(&s);
    render_picture(&s, 30.0, pic);
    check_1to1(&s, pic);
    check_texture(&s, pic);
    scene_free(&s);
    check_2x(pic);
    check_fit(pic);
    check_close_request(pic);
    stop_xvfb();
    if (failures)
        fprintf(stderr, "%d check(s) failed\n", failures);
    return failures ? 1 : 0;
}
