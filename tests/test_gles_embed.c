/*
 * test_gles_embed.c — embedding without a read-back (issue 20,
 * hfs_renderer_render_texture): the test makes its own EGL surfaceless
 * context, as an application would, and a renderer sharing with it; the
 * lit texture is read back IN THE TEST'S CONTEXT (attached to the test's
 * own framebuffer, after glWaitSync on the renderer's fence) and compared
 * with hfs_renderer_render's image:
 *   radiance  RGBA16F: each value the image's converted to fp16, so
 *             |t - v| <= 2^-10 |v| + 2^-24 (one ulp, normal or subnormal:
 *             GL leaves the float -> half rounding to the driver, and
 *             llvmpipe truncates: measured 1.997 half-ulps, 0.9985 of
 *             this bound) plus the image's own float rounding (2^-24 |v|);
 *   srgb8     RGBA8: hfs_srgb8_encode's byte, +-1 where the GPU's float
 *             OETF lands on the other side of a rounding edge (measured:
 *             printed count).
 * And the planner: a second frame with nothing changed runs no pass and
 * hands out the same texture; a re-tinted key light runs the shading and
 * the lit texture, not the read-back; a black frame and back; the
 * application's context is current again after every call (renders,
 * point queries, destroy); refusals.
 */
#include "gl_app.h"
#include "hfs_io.h"
#include "test_gles_scenes.h"

#include <math.h>
#include <string.h>

static int failures;
#define CHECK(c, ...)                                                                        \
    do {                                                                                     \
        if (!(c)) {                                                                          \
            printf("%s:%d: FAIL: ", __FILE__, __LINE__);                                     \
            printf(__VA_ARGS__);                                                             \
            printf("\n");                                                                    \
            ++failures;                                                                      \
        }                                                                                    \
    } while (0)

typedef gl_app app;

/* The lit texture as the application sees it (gl_app.h). */
static int app_read(app *a, const hfs_lit_texture *t, float *rgba)
{
    hfs_error err = {""};
    const int rc = gl_app_read(a, t, rgba, &err);
    CHECK(!rc, "read in the application's context: %s", err.msg);
    return rc;
}

/* The texture in the application's context against the image: radiance
 * within fp16's rounding, or the sRGB bytes within one code. */
static void compare(app *a, const hfs_lit_texture *t, const hfs_image *img,
                    const hfs_lit_texture_desc *how, const char *what)
{
    const size_t npx = (size_t)img->width * img->height;
    float *rgba = malloc(npx * 4 * sizeof *rgba);
    if (!rgba || app_read(a, t, rgba)) {
        free(rgba);
        CHECK(0, "%s: no pixels", what);
        return;
    }
    double worst = 0.0; /* |t - v| over its bound */
    long off_by_one = 0, worse = 0;
    for (size_t i = 0; i < npx; ++i)
        for (int c = 0; c < 3; ++c) {
            const double v = img->rgb[3 * i + (size_t)c], tv = rgba[4 * i + (size_t)c];
            if (how->encoding == HFS_LIT_RADIANCE) {
                const double bound = (0x1p-10 + 0x1p-24) * fabs(v) + 0x1p-24;
                worst = fmax(worst, fabs(tv - v) / bound);
                continue;
            }
            unsigned char want[3];
            hfs_srgb8_encode_rgb(img->rgb + 3 * i, how->exposure ? how->exposure : 1.0,
                                 (hfs_tonemap)how->tonemap, want);
            const double d = fabs(floor(tv * 255.0 + 0.5) - want[c]);
            off_by_one += d == 1.0;
            worse += d > 1.0;
        }
    if (how->encoding == HFS_LIT_RADIANCE) {
        printf("%-28s radiance: worst |t - v| / fp16 bound %.3f\n", what, worst);
        CHECK(worst <= 1.0, "%s: radiance beyond fp16's rounding (%.3f of the bound)", what,
              worst);
    } else {
        printf("%-28s srgb8: %ld of %zu values one code off, %ld more\n", what, off_by_one,
               npx * 3, worse);
        CHECK(worse == 0 && off_by_one <= (long)(npx * 3 / 100),
              "%s: sRGB bytes differ (%ld by one, %ld by more)", what, off_by_one, worse);
    }
    free(rgba);
}

static void check_current(const app *a, const char *after)
{
    CHECK(eglGetCurrentContext() == a->ctx, "after %s the application's context is not "
          "current", after);
}

static int n_ran(const hfs_renderer *r)
{
    hfs_frame_report rep;
    hfs_renderer_frame_report(r, &rep);
    return rep.n_ran;
}

/* What only the texture path refuses, one line each; the application's
 * context made current again after the renderer that has its own. */
static void refusals(app *a, const hfs_field *f, const hfs_lighting *l, const hfs_quality *q)
{
    hfs_error err = {""};
    hfs_lit_texture t;
    hfs_renderer *own = gl_test_gles(); /* its own context: no texture of ours */
    CHECK(hfs_renderer_render_texture(own, f, l, q, NULL, &t, &err) == HFS_E_UNSUPPORTED &&
              t.texture == 0, "a renderer without egl_share_context: %s", err.msg);
    printf("refused: %s\n", err.msg);
    hfs_renderer_destroy(own);
    eglMakeCurrent(a->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, a->ctx);
    const hfs_renderer_desc cpu_desc = {.backend = HFS_BACKEND_CPU};
    hfs_renderer *cpu = NULL;
    CHECK(!hfs_renderer_create(&cpu_desc, &cpu, &err), "cpu renderer: %s", err.msg);
    CHECK(hfs_renderer_render_texture(cpu, f, l, q, NULL, &t, &err) == HFS_E_UNSUPPORTED,
          "the cpu backend: %s", err.msg);
    printf("refused: %s\n", err.msg);
    hfs_renderer_destroy(cpu);
    const hfs_renderer_desc half = {.backend = HFS_BACKEND_GLES, .egl_display = a->dpy};
    hfs_renderer *r = NULL;
    CHECK(hfs_renderer_create(&half, &r, &err) == HFS_E_INVALID && !r,
          "a display without a context: %s", err.msg);
    printf("refused: %s\n", err.msg);
    check_current(a, "the refusals");
}

/* The planner on the texture path: nothing changed, a re-tinted key, the
 * image again, a black frame and back. */
static void planned(app *a, hfs_renderer *r, const hfs_field *f, hfs_lighting l,
                    const hfs_quality *q, const hfs_lit_texture *first)
{
    hfs_error err = {""};
    hfs_lit_texture t;
    char ran[256];
    CHECK(!hfs_renderer_render_texture(r, f, &l, q, NULL, &t, &err), "%s", err.msg);
    CHECK(n_ran(r) == 0 && t.texture == first->texture,
          "nothing changed: ran \"%s\", texture %u (was %u)", gl_test_ran(r, ran, sizeof ran),
          t.texture, first->texture);
    l.key[0].radiance[0] *= 0.5f;
    CHECK(!hfs_renderer_render_texture(r, f, &l, q, NULL, &t, &err), "%s", err.msg);
    gl_test_ran(r, ran, sizeof ran);
    printf("re-tinted key ran: %s\n", ran);
    CHECK(!strcmp(ran, "shade lit texture "), "re-tinted key ran \"%s\"", ran);
    hfs_image img = {0};
    CHECK(!hfs_image_alloc(&img, f->width, f->height, &err), "%s", err.msg);
    CHECK(!hfs_renderer_render(r, f, &l, q, &img, NULL, NULL, &err), "%s", err.msg);
    gl_test_ran(r, ran, sizeof ran);
    printf("then the image ran: %s\n", ran);
    CHECK(strstr(ran, "readback") != NULL, "the image after a texture frame ran \"%s\"", ran);
    compare(a, &t, &img, &(hfs_lit_texture_desc){0}, "re-tinted key");
    /* The texture again after an image frame: nothing changed for it (an
     * image frame leaves the texture's encoding as it was; measured: no
     * pass), at most the lit pass, never for its encoding. */
    CHECK(!hfs_renderer_render_texture(r, f, &l, q, NULL, &t, &err), "%s", err.msg);
    gl_test_ran(r, ran, sizeof ran);
    hfs_frame_report rep;
    hfs_renderer_frame_report(r, &rep);
    for (int i = 0; i < rep.n_steps; ++i)
        CHECK(!strstr(rep.step[i].reason, "encoding"), "after an image frame: %s ran for \"%s\"",
              rep.step[i].pass, rep.step[i].reason);
    printf("texture after that image ran: %s\n", ran);
    CHECK(!strcmp(ran, "lit texture ") || !ran[0], "texture after the image ran \"%s\"", ran);

    hfs_lighting dark;
    hfs_lighting_defaults(&dark);
    CHECK(!hfs_renderer_render_texture(r, f, &dark, q, NULL, &t, &err), "%s", err.msg);
    hfs_image black = {0};
    CHECK(!hfs_image_alloc(&black, f->width, f->height, &err), "%s", err.msg);
    memset(black.rgb, 0, (size_t)f->width * f->height * 3 * sizeof *black.rgb);
    compare(a, &t, &black, &(hfs_lit_texture_desc){0}, "no light: black");
    CHECK(!hfs_renderer_render_texture(r, f, &l, q, NULL, &t, &err), "%s", err.msg);
    gl_test_ran(r, ran, sizeof ran);
    CHECK(strstr(ran, "lit texture") != NULL, "lit again after black ran \"%s\"", ran);
    compare(a, &t, &img, &(hfs_lit_texture_desc){0}, "lit again after black");
    check_current(a, "the planned frames");
    hfs_image_free(&black);
    hfs_image_free(&img);
}

int main(void)
{
    app a;
    gl_app_make(&a);
    scene s;
    if (scene_make("fractal", 96, NULL, &s))
        return 1;
    const hfs_lighting l = scene_lighting(1, 1);
    hfs_quality q;
    hfs_quality_defaults(&q);
    hfs_error err = {""};

    const hfs_renderer_desc desc = {.backend = HFS_BACKEND_GLES, .egl_display = a.dpy,
                                    .egl_share_context = a.ctx};
    hfs_renderer *r = gl_test_renderer(&desc);
    check_current(&a, "create");
    printf("renderer: %s\n", hfs_renderer_backend_name(r));
    hfs_image img = {0};
    CHECK(!hfs_image_alloc(&img, s.f.width, s.f.height, &err), "%s", err.msg);
    CHECK(!hfs_renderer_render(r, &s.f, &l, &q, &img, NULL, NULL, &err), "%s", err.msg);
    check_current(&a, "render");

    hfs_lit_texture t;
    CHECK(!hfs_renderer_render_texture(r, &s.f, &l, &q, NULL, &t, &err), "%s", err.msg);
    check_current(&a, "render_texture");
    char ran[256];
    gl_test_ran(r, ran, sizeof ran);
    printf("texture after the image ran: %s\n", ran);
    CHECK(!strcmp(ran, "lit texture "), "texture after the image ran \"%s\"", ran);
    CHECK(t.internal_format == GL_RGBA16F && t.width == s.f.width && t.height == s.f.height &&
              t.fence, "texture %u: format 0x%x, %dx%d", t.texture, t.internal_format,
          t.width, t.height);
    compare(&a, &t, &img, &(hfs_lit_texture_desc){0}, "radiance");

    double vmax = hfs_image_max(&img);
    /* The GLSL curves against the C ones (hfs_io.h "Display mapping"); the
     * hue-keeping one also exposed so the brightest texels pass its white
     * point (32 x the largest: beyond 16) and the shoulder and the clip to
     * white are both compared. */
    static const char *const names[] = {"srgb8, clamp", "srgb8, reinhard", "srgb8, hue",
                                        "srgb8, hue, 32x"};
    for (int k = 0; k < 4; ++k) {
        const int tm = k < 3 ? k : HFS_TONEMAP_HUE;
        const hfs_lit_texture_desc srgb = {HFS_LIT_SRGB8, (k < 3 ? 1.0 : 32.0) / vmax, tm};
        hfs_lit_texture ts;
        CHECK(!hfs_renderer_render_texture(r, &s.f, &l, &q, &srgb, &ts, &err), "%s", err.msg);
        CHECK(ts.internal_format == GL_RGBA8, "srgb8: format 0x%x", ts.internal_format);
        compare(&a, &ts, &img, &srgb, names[k]);
    }
    const hfs_lit_texture_desc bad = {HFS_LIT_SRGB8, -1.0, 0};
    CHECK(hfs_renderer_render_texture(r, &s.f, &l, &q, &bad, &t, &err) == HFS_E_INVALID,
          "exposure -1 accepted");
    printf("refused: %s\n", err.msg);
    CHECK(!hfs_renderer_render_texture(r, &s.f, &l, &q, NULL, &t, &err), "%s", err.msg);
    const double xyz[3] = {10.0 * s.f.dx, 20.0 * s.f.dx, 50.0};
    float vis[HFS_MAX_KEY_LIGHTS];
    CHECK(!hfs_renderer_query_points(r, &s.f, &l, &q, xyz, 1, vis, &err), "%s", err.msg);
    check_current(&a, "query_points");
    planned(&a, r, &s.f, l, &q, &t);
    refusals(&a, &s.f, &l, &q);

    hfs_renderer_destroy(r);
    check_current(&a, "destroy");
    hfs_image_free(&img);
    scene_free(&s);
    gl_app_free(&a);
    printf("embed: %s\n", failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
