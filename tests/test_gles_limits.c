/*
 * test_gles_limits.c — the GLES renderer at the edges of what it takes
 * (label "gl"; split from test_gles_render.c, whose modes are the
 * renderer against its oracle in the usual ranges).  One executable, one
 * mode per ctest entry:
 *
 *   errors        refusals: local lights on the wedge-table path, an unknown
 *       profile, fp32 under es30-half, a field beyond the es30 texture size;
 *       nphi-env beyond the es30 uniform-block size is carried by a texture
 *       and renders as the uniform-block path does, bit for bit.
 *   steep         walls of slope ~1e21 (zscale 1e12, dx 1e-9): a key
 *       light's frame is the CPU's within 1.2x of the measurement (at the
 *       default subsample and at subsample 1), every
 *       frame is finite, and the sky at subsample 1, 2 and 4, the CPU
 *       reference's and GLES's, does not depend on the relief's scale.
 *   relief        relief beyond fp16's range (zscale 1e5 and 1e6 at dx 1:
 *       about 1e5 and 1e6 texels): the grids store their occluders'
 *       heights in a unit that keeps them within fp16
 *       (split_horizon.h hfs_split_h_unit), so the sky at subsample 1, 2
 *       and 4 changes between the two by what its steeper slopes change,
 *       on the CPU reference and GLES (before: up to the whole maximum).
 *
 * No GLES context of any kind: exit 77 (gl_test.h).  The data directory
 * comes from HFS_DATA_DIR (compile definition).
 */
#include "gles_render_util.h"

#include <stdlib.h>

/* Refusals: one line, the right code, nothing rendered. */
static int mode_errors(void)
{
    scene s;
    if (scene_make("cones", 32, HFS_DATA_DIR, &s))
        return 1;
    /* Strict limits: the ES 3.0 minimums, which every device has. */
    const hfs_renderer_desc strict = {.backend = HFS_BACKEND_GLES, .context = test_context,
                                      .gl_strict_limits = 1};
    hfs_renderer *r = gl_test_renderer(&strict);
    hfs_lighting l = scene_lighting(1, 0);
    hfs_quality q = quality("fp16", "legendre", 1);
    hfs_image img = {0};
    hfs_error err;
    if (hfs_image_alloc(&img, 32, 32, &err))
        return 1;

    /* A swath too long for ES 3.0's 16 KiB uniform blocks (nphi-env 128:
     * 2 + 17*128 + 258 vec4 = 39 KB) is carried by a texture instead of
     * refused (issue 13); below it is compared with the uniform-block path. */
    q.nphi_env = 128;
    int rc = hfs_renderer_render(r, &s.f, &l, &q, &img, NULL, NULL, &err);
    printf("nphi-env 128, strict limits: %s\n", rc ? err.msg : "ok (swath in a texture)");
    CHECK(rc == 0, "nphi-env 128 under es30-half, strict limits: %d %s", rc, err.msg);
    /* A field wider than ES 3.0's 2048 texels renders in tiles (issue 39,
     * test_tiled_render.c pins the result); one whose lights see terrain
     * at any distance (a local light) cannot, and is refused in one line
     * naming the limit, the size and the way out. */
    float *wide_z = calloc((size_t)2049 * 4, sizeof *wide_z);
    const hfs_field wide = {.width = 2049, .height = 4, .z = wide_z, .dx = 1.0, .zscale = 1.0};
    hfs_image wide_img = {0};
    if (!wide_z || hfs_image_alloc(&wide_img, 2049, 4, &err))
        return 1;
    q.nphi_env = 32;
    rc = hfs_renderer_render(r, &wide, &l, &q, &wide_img, NULL, NULL, &err);
    CHECK(rc == 0, "field 2049x4 under es30-half, in tiles: %d %s", rc, err.msg);
    hfs_lighting lit_locally = l;
    lit_locally.n_local = 1;
    lit_locally.local[0] = (hfs_local_light){.pos = {10, 1, 5}, .radius = 0.5,
                                             .radiance = {100, 100, 100}};
    rc = hfs_renderer_render(r, &wide, &lit_locally, &q, &wide_img, NULL, NULL, &err);
    printf("field 2049x4 with a local light, strict limits: %s\n", err.msg);
    CHECK(rc == HFS_E_UNSUPPORTED && strstr(err.msg, "2048") && strstr(err.msg, "2049") &&
              strstr(err.msg, "the cpu backend"),
          "field 2049x4 with a local light under es30-half: %d %s", rc, err.msg);
    CHECK(strchr(err.msg, '\n') == NULL, "message not one line");
    hfs_image_free(&wide_img);
    free(wide_z);
    CHECK(hfs_renderer_render(r, &s.f, &l, &q, &img, NULL, NULL, &err) == 0,
          "renderer unusable after a refusal: %s", err.msg);

    hfs_renderer_desc d = {.backend = HFS_BACKEND_GLES, .gl_profile = "es29"};
    hfs_renderer *bad = NULL;
    rc = hfs_renderer_create(&d, &bad, &err);
    printf("profile es29: %s\n", err.msg);
    CHECK(rc == HFS_E_INVALID && bad == NULL && strstr(err.msg, "es30-half"), "profile es29: %d %s",
          rc, err.msg);

    d.gl_profile = "es30-half";
    bad = gl_test_renderer(&d);
    /* Without strict limits the driver's own: nphi-env 128 fits llvmpipe's
     * 64 KiB blocks under es30-half (issue 13), and the frame is the strict
     * renderer's (swath in a texture) bit for bit. */
    q.nphi_env = 128;
    hfs_image ubo_img = {0};
    if (hfs_image_alloc(&ubo_img, 32, 32, &err) ||
        hfs_renderer_render(r, &s.f, &l, &q, &img, NULL, NULL, &err))
        return 1;
    rc = hfs_renderer_render(bad, &s.f, &l, &q, &ubo_img, NULL, NULL, &err);
    printf("nphi-env 128 under es30-half, driver limits: %s\n", rc ? err.msg : "ok");
    CHECK(rc == 0, "nphi-env 128, driver limits: %s", err.msg);
    CHECK(rc || !memcmp(img.rgb, ubo_img.rgb, (size_t)32 * 32 * 3 * sizeof *img.rgb),
          "nphi-env 128: the swath in a texture and in a uniform block differ");
    hfs_image_free(&ubo_img);
    q.nphi_env = 32;
    q.precision = HFS_PRECISION_FP32;
    rc = hfs_renderer_render(bad, &s.f, &l, &q, &img, NULL, NULL, &err);
    printf("fp32 under es30-half: %s\n", err.msg);
    CHECK(rc == HFS_E_UNSUPPORTED && strstr(err.msg, "es30-half"), "fp32 under es30-half: %d %s",
          rc, err.msg);
    hfs_renderer_destroy(bad);
    /* es32 relaxes the limits: nphi-env 128 fits the driver's uniform blocks.
     * A driver below ES 3.2 (MESA_GLES_VERSION_OVERRIDE=3.0) refuses the
     * profile, and only with the capability layer's one line. */
    d.gl_profile = "es32";
    rc = hfs_renderer_create(&d, &bad, &err);
    if (rc == 0) {
        q.precision = HFS_PRECISION_FP16;
        q.nphi_env = 128;
        rc = hfs_renderer_render(bad, &s.f, &l, &q, &img, NULL, NULL, &err);
        printf("nphi-env 128 under es32: %s\n", rc ? err.msg : "ok");
        CHECK(rc == 0, "nphi-env 128 under es32: %s", err.msg);
        hfs_renderer_destroy(bad);
    } else {
        printf("es32 not available here: %s\n", err.msg);
        CHECK(rc == HFS_E_UNSUPPORTED && strstr(err.msg, "profile es32: this driver offers"),
              "es32 refused for another reason: %d %s", rc, err.msg);
    }
    hfs_image_free(&img);
    hfs_renderer_destroy(r);
    scene_free(&s);
    return failures ? 1 : 0;
}

/* Walls of slope ~1e21 (zscale 1e12, dx 1e-9: the validated ranges'
 * corner): the normals computed where they are read (hfs_normal_at) must
 * not overflow (|g| ~ 1e21 squared is beyond float), so a key light's frame
 * stays the CPU's (measured max 1.43e-5, mean 3.58e-7 of the unshadowed
 * maximum; bounds 1.2x) and every frame stays finite; the sky, on each
 * backend, is the sky of zscale 1e6 (slopes ~1e15). */
#define KEY1_MAX 3.05e-7  /* measured 2.53e-7 / 3.06e-9: bounds 1.2x */
#define KEY1_MEAN 3.7e-9
static int mode_steep(void)
{
    scene s;
    if (scene_make("fractal", 32, HFS_DATA_DIR, &s))
        return 1;
    s.f.dx = 1e-9;
    s.f.zscale = 1e12;
    hfs_lighting l;
    hfs_lighting_defaults(&l);
    l.albedo = 0.8;
    l.n_key = 1;
    l.key[0] = (hfs_key_light){.phi = 336.0 * PI / 180.0, .elev = 15.0 * PI / 180.0,
                               .alpha = PI / 180.0, .radiance = {1500, 1500, 1500}};
    hfs_quality q;
    hfs_quality_defaults(&q);
    hfs_renderer *r = gles_or_skip(NULL);
    hfs_image a = {0}, b = {0};
    if (!render(r, &s, &l, &q, &a) && !cpu_render(&s, &l, &q, &b)) {
        const hfs_metrics m = compare(&s, &l, &q, &a, &b);
        printf("steep, key light: max %.3e mean %.3e of the maximum, non-finite %ld\n", m.max_abs,
               m.mean_abs, m.nonfinite);
        CHECK(m.nonfinite == 0 && m.max_abs <= 1.75e-5 && m.mean_abs <= 4.3e-7,
              "steep key light: max %.3e (bound 1.75e-5), mean %.3e (bound 4.3e-7)", m.max_abs,
              m.mean_abs);
    }
    /* At subsample 1 too, where the key horizons start from the tangent
     * plane's slope (key_horizons.frag refined_horizon: tan of the plane's
     * float angle, rounded past +-pi/2, had the other sign, and texels on
     * planes falling away from the light were dark: 2.2e-2 mean, max the
     * whole maximum, before session 38). */
    hfs_quality qk = q;
    qk.subsample = 1;
    if (!render(r, &s, &l, &qk, &a) && !cpu_render(&s, &l, &qk, &b)) {
        const hfs_metrics m = compare(&s, &l, &qk, &a, &b);
        printf("steep, key light, subsample 1: max %.3e mean %.3e of the maximum\n", m.max_abs,
               m.mean_abs);
        CHECK(m.nonfinite == 0 && m.max_abs <= KEY1_MAX && m.mean_abs <= KEY1_MEAN,
              "steep key light, subsample 1: max %.3e (bound %.3g), mean %.3e (bound %.3g)",
              m.max_abs, KEY1_MAX, m.mean_abs, KEY1_MEAN);
    }
    l.has_env = 1; /* and with a sky: finite */
    for (int c = 0; c < 3; ++c)
        l.env_sh[c][0] = 3.5449077;
    if (!render(r, &s, &l, &q, &a)) {
        size_t bad = 0;
        for (size_t i = 0; i < (size_t)a.width * a.height * 3; ++i)
            bad += !isfinite(a.rgb[i]);
        CHECK(bad == 0, "steep sky + sun: %zu non-finite values", bad);
    }
    /* The CPU reference's sky does not depend on the relief's scale:
     * zscale 1e6 and 1e12 (slopes ~1e15 and ~1e21), as GLES's (issue 36:
     * the refinement chose its scale by the tan of angles that saturate
     * near +-pi/2, cpu_horizon.c scale_slope; the occluder grids took a
     * scale whose angle rounded to -pi/2 for one off the field,
     * hfs_horizon_occluder, and stored heights cut to fp16's range,
     * hfs_split_h_unit).  At subsample 1, with one horizon a direction or
     * split horizons, and at subsample 4: the same bits.  At subsample 2
     * one texel of the 1024 differs (the 2x2 path's horizons are angles
     * there, which a double resolves to 1e-16 near +-pi/2: at slopes of
     * 1e15 a tenth of their distance from it): mean 1.27e-4, bound 1.2x.
     * Before (session 38): split horizons at subsample 1 1.9e-4 (bound
     * 2.3e-4); subsamples 2 and 4 were not compared. */
    l.n_key = 0;
    static const struct {
        int split, sub;
        double mean; /* 0: the same bits */
    } steep[] = {{0, 1, 0.0}, {1, 1, 0.0}, {1, 2, 1.52e-4}, {1, 4, 0.0}};
    for (size_t i = 0; i < sizeof steep / sizeof steep[0]; ++i) {
        hfs_quality q1 = q;
        q1.subsample = steep[i].sub;
        q1.split = steep[i].split;
        s.f.zscale = 1e6;
        const int rc = cpu_render(&s, &l, &q1, &a);
        s.f.zscale = 1e12;
        if (!rc && !cpu_render(&s, &l, &q1, &b)) {
            const hfs_metrics m = compare(&s, &l, &q1, &b, &a);
            printf("steep sky, CPU, split %d, subsample %d: zscale 1e12 against 1e6 max %.3e "
                   "mean %.3e\n",
                   steep[i].split, steep[i].sub, m.max_abs, m.mean_abs);
            CHECK(steep[i].mean > 0.0 ? m.mean_abs <= steep[i].mean : bitequal(&a, &b),
                  "steep sky, CPU, split %d, subsample %d: zscale 1e12 against 1e6 max %.3e "
                  "mean %.3e",
                  steep[i].split, steep[i].sub, m.max_abs, m.mean_abs);
        }
    }
    /* GLES's sky does not depend on the relief's scale either, at the
     * default split horizons (issue 36, session 40), for two reasons:
     *   - the grids store each occluder as its height over its receiver,
     *     and env_horizons.frag made that height from the slope clamped to
     *     1e18, so a wall steeper than that lost most of its height;
     *   - env_slices.frag averages a slice's two sub-horizons through the
     *     sum of their unit vectors, whose direction is rounding where the
     *     two lie near +-pi/2 at once (slopes past ~1e7): the difference's
     *     direction is taken there.
     * Before, at zscale 1e12 against 1e6, mean / max of the maximum:
     * 5.0e-2 / 0.71 at subsample 1, 0.22 / 1.0 at 2, 0.26 / 1.0 at 4.  Now
     * subsamples 1 and 4 give the same bits and 2 differs at the CPU's own
     * texel above (1.27e-4 / 0.130; bounds 1.2x).  And GLES at fp32 is the
     * CPU's at subsample 2 (the same grids, in float) at zscale 1e6,
     * slopes of 1e15, where only the second fault reaches: measured
     * 7.9e-8 / 5.2e-7 (before: 2.7e-3 / 0.13), bounds 1.2x.  One bounce
     * reads the same grids (bounce_gather.frag's far sub-horizons):
     * before, 0.19 / 1.0 at the default subsample; now 8.6e-5 / 0.084 (one
     * texel, the sky's at subsample 2), bounds 1.2x. */
    static const struct {
        int sub, bounces;
        double mean, max; /* 0: the same bits */
    } gsteep[] = {{1, 0, 0.0, 0.0}, {2, 0, 1.52e-4, 0.156}, {4, 0, 0.0, 0.0},
                  {2, 1, 1.04e-4, 0.101}};
    for (size_t i = 0; i < sizeof gsteep / sizeof gsteep[0]; ++i) {
        hfs_quality q1 = q;
        q1.subsample = gsteep[i].sub;
        hfs_lighting l1 = l;
        l1.bounces = gsteep[i].bounces;
        s.f.zscale = 1e6;
        const int rc = render(r, &s, &l1, &q1, &a);
        s.f.zscale = 1e12;
        if (!rc && !render(r, &s, &l1, &q1, &b)) {
            const hfs_metrics m = compare(&s, &l1, &q1, &b, &a);
            printf("steep sky, GLES, subsample %d, %d bounce(s): zscale 1e12 against 1e6 max "
                   "%.3e mean %.3e\n",
                   gsteep[i].sub, gsteep[i].bounces, m.max_abs, m.mean_abs);
            CHECK(m.nonfinite == 0 &&
                      (gsteep[i].mean > 0.0
                           ? m.mean_abs <= gsteep[i].mean && m.max_abs <= gsteep[i].max
                           : bitequal(&a, &b)),
                  "steep sky, GLES, subsample %d, %d bounce(s): zscale 1e12 against 1e6 max "
                  "%.3e mean %.3e",
                  gsteep[i].sub, gsteep[i].bounces, m.max_abs, m.mean_abs);
        }
    }
    hfs_quality q32 = q;
    q32.precision = HFS_PRECISION_FP32;
    q32.subsample = 2;
    s.f.zscale = 1e6; /* slopes ~1e15: under the slopes' clamp, past ~1e7 */
    if (!render(r, &s, &l, &q32, &a) && !cpu_render(&s, &l, &q32, &b)) {
        const hfs_metrics m = compare(&s, &l, &q32, &a, &b);
        printf("steep sky, GLES fp32 against the CPU, subsample 2: max %.3e mean %.3e\n",
               m.max_abs, m.mean_abs);
        CHECK(m.nonfinite == 0 && m.max_abs <= 6.3e-7 && m.mean_abs <= 9.5e-8,
              "steep sky, GLES fp32 against the CPU, subsample 2: max %.3e (bound 6.3e-7), "
              "mean %.3e (bound 9.5e-8)",
              m.max_abs, m.mean_abs);
    }
    hfs_image_free(&a);
    hfs_image_free(&b);
    hfs_renderer_destroy(r);
    scene_free(&s);
    return failures ? 1 : 0;
}

/* Relief of 1e5 and 1e6 texels: every horizon within a few 1e-5 radians
 * of the vertical in both, so the two skies agree as closely as these
 * measured means (bounds 1.2x; with the unit held at 1, the heights cut
 * to fp16's 3e4 as before it: 4.9e-3, 2.7e-2 and 2.9e-2 at subsample 1, 2
 * and 4, GLES 2.7e-2), and the renders stay finite.  Not exact: a zscale
 * is no similarity, and the grids' wall rule (a receiver rising steeper
 * than HFS_SPLIT_STEEP) reads some texels' far occluders at another place
 * at 1e5 than at 1e6.  At subsample 4 that moved nothing visible (bound
 * 1.05e-9) until the far occluders came from three heights (session 44),
 * which differ more between receivers: 3.19e-5, still below subsample
 * 2's. */
static int mode_relief(void)
{
    scene s;
    if (scene_make("fractal", 32, HFS_DATA_DIR, &s))
        return 1;
    hfs_lighting l;
    hfs_lighting_defaults(&l);
    l.albedo = 0.8;
    l.has_env = 1;
    for (int c = 0; c < 3; ++c)
        l.env_sh[c][0] = 3.5449077;
    hfs_quality q;
    hfs_quality_defaults(&q);
    hfs_renderer *r = gles_or_skip(NULL);
    /* backend (0 CPU, 1 GLES), subsample, bound on the mean */
    static const struct {
        int gles, sub;
        double mean;
    } runs[] = {{0, 1, 5.1e-8}, {0, 2, 3.05e-4}, {0, 4, 3.83e-5}, {1, 2, 3.05e-4}};
    hfs_image a = {0}, b = {0};
    for (size_t i = 0; i < sizeof runs / sizeof runs[0]; ++i) {
        q.subsample = runs[i].sub;
        s.f.zscale = 1e5;
        const int rc = runs[i].gles ? render(r, &s, &l, &q, &a) : cpu_render(&s, &l, &q, &a);
        s.f.zscale = 1e6;
        if (rc || (runs[i].gles ? render(r, &s, &l, &q, &b) : cpu_render(&s, &l, &q, &b))) {
            CHECK(0, "relief: %s subsample %d did not render", runs[i].gles ? "gles" : "cpu",
                  runs[i].sub);
            continue;
        }
        const hfs_metrics m = compare(&s, &l, &q, &a, &b);
        printf("relief, %s subsample %d: zscale 1e5 against 1e6 mean %.3e max %.3e\n",
               runs[i].gles ? "gles" : "cpu", runs[i].sub, m.mean_abs, m.max_abs);
        CHECK(m.nonfinite == 0 && m.mean_abs <= runs[i].mean,
              "relief, %s subsample %d: mean %.3e (bound %.2g), non-finite %ld",
              runs[i].gles ? "gles" : "cpu", runs[i].sub, m.mean_abs, runs[i].mean, m.nonfinite);
    }
    hfs_image_free(&a);
    hfs_image_free(&b);
    hfs_renderer_destroy(r);
    scene_free(&s);
    return failures ? 1 : 0;
}

int main(int argc, char **argv)
{
    setvbuf(stdout, NULL, _IONBF, 0);
    if (argc < 2) {
        fprintf(stderr, "usage: test_gles_limits errors|steep|relief\n");
        return 2;
    }
    if (!strcmp(argv[1], "errors"))
        return mode_errors();
    if (!strcmp(argv[1], "steep"))
        return mode_steep();
    if (!strcmp(argv[1], "relief"))
        return mode_relief();
    fprintf(stderr, "unknown mode %s\n", argv[1]);
    return 2;
}
