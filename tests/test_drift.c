/*
 * test_drift.c — accuracy drift (issue 35, deliverable 2): bugs that move
 * the result of both backends alike, or by less than a loose bound, must
 * move a measured number past its bound.  At the default quality and at
 * each quality preset (hfs_quality_preset: kiosk = the defaults, panel,
 * headless), on three non-square fields with dx != 1, under a sky that is
 * symmetric in no axis:
 *
 *   truth SCENE  the CPU reference against the ground truth (one truth
 *                image per scene, reused for the three presets): mean and
 *                p99 of |cpu - truth| / the largest unshadowed value;
 *   gles SCENE   GLES at each preset (so at each subsample the presets
 *                use: 2, 1, 4) against the CPU reference at the same
 *                quality: mean and p99 over every texel, and on the 2x2
 *                and 4x4 grids over the grid's own texels too (77 without
 *                a GLES context).  The CPU computes the same visibility
 *                grid (cpu_grid.h), so over every texel as at the grid's
 *                own GLES stays within ~1e-4 of it (fp16; the narrow
 *                blocks 1.5e-3 mean), and a far pass refined with the
 *                near part's count shows (10x the mean).  (Before the
 *                CPU had a grid, its interpolation, 1e-3 to 1e-1, hid
 *                any GLES drift smaller than that over every texel.)
 *
 * SCENE: fractal (terrain), rough (texel-scale noise on a low fractal),
 * blocks (narrow blocks, 1-2 texels wide, on a flat ground).  The
 * kiosk preset is the defaults (checked here too).  Every bound
 * is 1.2x the value measured at this commit (table below; both backends
 * are deterministic, and the GLES numbers are the same in every build and
 * with MESA_GLES_VERSION_OVERRIDE=3.0 or HFS_GL_STRICT_LIMITS=1), so a
 * change of 20% in either metric fails.  The truth part catches a drift of
 * the shared algorithm by that much (split horizons' sub-directions off
 * their wedges' centres by half a step: fractal panel mean 1.25x); the
 * smaller ones are test_drift_rules' (the near/far boundary one scale
 * early: 1.17x at most here; the far part refined twice, not four times:
 * 1.02x).  The GLES part catches a drift of the GLES passes alone,
 * including one that only a few texels see (the p99).
 *
 *   test_drift truth|gles fractal|rough|blocks
 */
#include "gl_test.h"
#include "terrain_gen.h"
#include "test_rng.h"
#include "test_sky.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

#define W 48
#define H 40

/* ---- scenes --------------------------------------------------------------------- */

/* fractal: relief 0.4 (heights 0..16 texels), dx 0.7, zscale 0.8;
 * rough: relief 0.1 plus up to 3 texels of noise per texel, dx 1.3;
 * blocks: on a flat ground, in cells of 6 x 5 texels, one block of 1-2 x
 * 1-2 texels at a random place per cell, 3-12 texels high, dx 0.9
 * (test_rng.h: the same numbers on every machine). */
static int make_scene(const char *name, float *z, hfs_field *f)
{
    *f = (hfs_field){.width = W, .height = H, .z = z, .dx = 1.0, .zscale = 1.0};
    if (!strcmp(name, "fractal")) {
        f->dx = 0.7, f->zscale = 0.8;
        return hfs_terrain_fractal(z, W, H, 5u, 0.4);
    }
    if (!strcmp(name, "rough")) {
        f->dx = 1.3;
        if (hfs_terrain_fractal(z, W, H, 9u, 0.1))
            return -1;
        for (int k = 0; k < W * H; ++k)
            z[k] += (float)(3.0 * urand());
        return 0;
    }
    if (!strcmp(name, "blocks")) {
        f->dx = 0.9;
        memset(z, 0, sizeof(float) * W * H);
        for (int cj = 0; cj < H / 5; ++cj)
            for (int ci = 0; ci < W / 6; ++ci) {
                const int bw = 1 + (urand() > 0.5), bh = 1 + (urand() > 0.5);
                const int x0 = ci * 6 + (int)(urand() * (6 - bw));
                const int y0 = cj * 5 + (int)(urand() * (5 - bh));
                const float top = (float)(3.0 + 9.0 * urand());
                for (int j = y0; j < y0 + bh; ++j)
                    for (int i = x0; i < x0 + bw; ++i)
                        z[j * W + i] = top;
            }
        return 0;
    }
    fprintf(stderr, "unknown scene '%s' (fractal|rough|blocks)\n", name);
    return -1;
}

/* test_sky.h's sky (test_cpu_truth.c's): symmetric under no mirror and no
 * turn, so that a sub-direction turned the wrong way sees another sky. */
static hfs_lighting lighting(void)
{
    hfs_lighting l;
    hfs_lighting_defaults(&l);
    l.albedo = 0.8;
    l.has_env = 1;
    for (int c = 0; c < 3; ++c)
        memcpy(l.env_sh[c], test_sky_sh, sizeof test_sky_sh);
    return l;
}

/* ---- bounds --------------------------------------------------------------------- */

static const char *const presets[] = {"kiosk", "panel", "headless"};
#define N_PRESETS 3

/* Measured mean and p99 per mode, scene and preset at 2156b87
 * (RelWithDebInfo, llvmpipe, Mesa 22.3.6) by `build/tests/test_drift MODE
 * SCENE`, which prints them, and re-measured with issue 36's gap search
 * (the far grid's occluders between the scales: the narrow blocks against
 * the truth 4.630e-2 -> 4.080e-2 mean at the defaults, 1.437e-1 ->
 * 1.340e-1 p99; the others within 3%), and again with issue 36's
 * item 5 (the CPU computes the presets' subsample 2 and 4 as GLES does,
 * cpu_grid.h: the truth rows of kiosk and headless now measure the
 * grid's own error, e.g. fractal headless 3.832e-3 -> 7.605e-3 mean, and
 * the gles rows only what GLES alone adds, fractal kiosk 2.091e-3 ->
 * 1.362e-5), and again in session 16 against the exact truth (d8aa6e8)
 * with the key light's own cell and its whole search on the grid (9a6584e,
 * a37b16b): panel fractal 3.027e-3 -> 1.836e-3, panel rough 1.348e-2 ->
 * 5.597e-3, the gles blocks rows 1.537e-3 -> 5.135e-5 (kiosk) and 2.297e-3
 * -> 5.249e-5 (headless: GLES and the CPU no longer part on the grid's key
 * blend), the rest within 10%; the bound is 1.2x each. */
typedef struct measured {
    const char *mode, *scene;
    /* per preset (kiosk, panel, headless): {mean, p99} over every texel,
     * then (gles, on a sub-sampled grid) over the grid's texels */
    double m[N_PRESETS][4];
} measured;

static const measured table[] = {
    {"truth", "fractal", {{4.006e-3, 2.321e-2}, {1.836e-3, 1.528e-2}, {7.691e-3, 5.917e-2}}},
    {"truth", "rough", {{1.347e-2, 7.290e-2}, {5.597e-3, 2.666e-2}, {2.469e-2, 1.599e-1}}},
    {"truth", "blocks", {{4.251e-2, 1.385e-1}, {1.845e-2, 6.220e-2}, {5.837e-2, 2.021e-1}}},
    {"gles", "fractal", {{1.362e-5, 7.348e-5, 1.458e-5, 6.783e-5}, {2.094e-5, 3.464e-4},
                         {1.284e-5, 7.237e-5, 1.519e-5, 8.004e-5}}},
    {"gles", "rough", {{3.350e-5, 1.858e-4, 3.555e-5, 1.919e-4}, {3.716e-5, 1.967e-4},
                       {3.447e-5, 1.794e-4, 3.197e-5, 1.529e-4}}},
    {"gles", "blocks", {{5.135e-5, 1.972e-4, 4.744e-5, 1.982e-4}, {5.804e-5, 4.420e-4},
                        {5.249e-5, 1.964e-4, 4.609e-5, 2.096e-4}}},
};

/* ---- rendering --------------------------------------------------------------------- */

static int render(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l,
                  const hfs_quality *q, hfs_image *out)
{
    hfs_error err = {""};
    int rc = hfs_image_alloc(out, f->width, f->height, &err);
    if (!rc)
        rc = hfs_renderer_render(r, f, l, q, out, NULL, NULL, &err);
    CHECK(rc == HFS_OK, "render: %s", err.msg);
    return rc;
}

static hfs_renderer *make_renderer(hfs_backend b)
{
    const hfs_renderer_desc d = {.backend = b};
    if (b == HFS_BACKEND_GLES)
        return gl_test_renderer(&d);
    hfs_renderer *r = NULL;
    hfs_error err = {""};
    CHECK(hfs_renderer_create(&d, &r, &err) == HFS_OK, "create: %s", err.msg);
    return r;
}

/* Compares a against ref over the unshadowed maximum norm, against the
 * measured {mean, p99} m; what: "" (every texel) or " grid". */
static void judge(const char *mode, const char *scene, const char *preset, const char *what,
                  const hfs_image *a, const hfs_image *ref, double norm, const double m[2])
{
    hfs_metrics e = {0};
    hfs_error err = {""};
    CHECK(hfs_compare_images(a, ref, norm, &e, &err) == HFS_OK, "compare: %s", err.msg);
    const double bmean = 1.2 * m[0], bp99 = 1.2 * m[1];
    printf("%s %s %-8s%-5s: mean %.3e (bound %.3e) p99 %.3e (bound %.3e) max %.3e\n", mode,
           scene, preset, what, e.mean_abs, bmean, e.p99_abs, bp99, e.max_abs);
    CHECK(e.nonfinite == 0, "%s %s %s%s: %ld non-finite values", mode, scene, preset, what,
          e.nonfinite);
    CHECK(e.mean_abs <= bmean, "%s %s %s%s: mean %.3e > bound %.3e (measured %.3e)", mode, scene,
          preset, what, e.mean_abs, bmean, m[0]);
    CHECK(e.p99_abs <= bp99, "%s %s %s%s: p99 %.3e > bound %.3e (measured %.3e)", mode, scene,
          preset, what, e.p99_abs, bp99, m[1]);
}

/* The texels of the visibility grid of step sub (i, j multiples of sub):
 * there GLES reads its own receivers' horizons, with no interpolation
 * between them, so what is left against the CPU is fp16 and float
 * rounding, and a drift of the GLES passes themselves shows above it. */
static int grid_texels(const hfs_image *a, int sub, hfs_image *out)
{
    hfs_error err = {""};
    const int gw = (a->width + sub - 1) / sub, gh = (a->height + sub - 1) / sub;
    if (hfs_image_alloc(out, gw, gh, &err))
        return -1;
    for (int j = 0; j < gh; ++j)
        for (int i = 0; i < gw; ++i)
            memcpy(out->rgb + 3 * ((size_t)j * gw + i),
                   a->rgb + 3 * ((size_t)j * sub * a->width + (size_t)i * sub), 3 * sizeof(float));
    return 0;
}

/* GLES g against the CPU c at quality q: every texel, and on a
 * sub-sampled grid its texels apart. */
static void judge_gles(const char *scene, const char *preset, const hfs_quality *q,
                       const hfs_image *g, const hfs_image *c, double norm, const double m[4])
{
    judge("gles", scene, preset, "", g, c, norm, m);
    if (q->subsample < 2)
        return;
    hfs_image gg = {0}, cg = {0};
    if (!grid_texels(g, q->subsample, &gg) && !grid_texels(c, q->subsample, &cg))
        judge("gles", scene, preset, " grid", &gg, &cg, norm, m + 2);
    else
        CHECK(0, "out of memory");
    hfs_image_free(&gg);
    hfs_image_free(&cg);
}

int main(int argc, char **argv)
{
    setvbuf(stdout, NULL, _IONBF, 0);
    if (argc != 3 || (strcmp(argv[1], "truth") && strcmp(argv[1], "gles"))) {
        fprintf(stderr, "usage: test_drift truth|gles fractal|rough|blocks\n");
        return 2;
    }
    const int gles = !strcmp(argv[1], "gles");
    const measured *meas = NULL;
    for (size_t i = 0; i < sizeof table / sizeof table[0]; ++i)
        if (!strcmp(table[i].mode, argv[1]) && !strcmp(table[i].scene, argv[2]))
            meas = &table[i];
    static float z[W * H];
    hfs_field f;
    if (!meas || make_scene(argv[2], z, &f))
        return 2;
    const hfs_lighting l = lighting();
    hfs_quality q, kiosk;
    hfs_quality_defaults(&q);
    CHECK(hfs_quality_preset(&kiosk, "kiosk") == HFS_OK && !memcmp(&q, &kiosk, sizeof q),
          "the defaults are not the kiosk preset");
    hfs_image ref = {0}, unsh = {0};
    hfs_error err = {""};
    hfs_renderer *cpu = make_renderer(HFS_BACKEND_CPU);
    hfs_renderer *other = make_renderer(gles ? HFS_BACKEND_GLES : HFS_BACKEND_TRUTH);
    int rc = !cpu || !other || hfs_image_alloc(&unsh, W, H, &err) ||
             hfs_render_unshadowed(&f, &l, &q, &unsh, &err);
    /* The truth does not depend on the preset: one image for all three. */
    if (!rc && !gles)
        rc = render(other, &f, &l, &q, &ref);
    const double norm = hfs_image_max(&unsh);
    CHECK(!rc && norm > 0.0, "setup: %s", err.msg);
    for (int p = 0; !rc && p < N_PRESETS; ++p) {
        hfs_image c = {0}, g = {0};
        CHECK(hfs_quality_preset(&q, presets[p]) == HFS_OK, "preset %s", presets[p]);
        if (render(cpu, &f, &l, &q, &c) || (gles && render(other, &f, &l, &q, &g)))
            rc = -1;
        else if (gles)
            judge_gles(argv[2], presets[p], &q, &g, &c, norm, meas->m[p]);
        else
            judge("truth", argv[2], presets[p], "", &c, &ref, norm, meas->m[p]);
        hfs_image_free(&c);
        hfs_image_free(&g);
    }
    hfs_image_free(&ref);
    hfs_image_free(&unsh);
    hfs_renderer_destroy(cpu);
    hfs_renderer_destroy(other);
    printf("test_drift %s %s: %s\n", argv[1], argv[2], failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
