/*
 * test_gles_render.c — the GLES renderer against its oracle, the CPU
 * reference, and on its own (label "gl").  One executable, one mode per
 * ctest entry (the fetch counts are test_gles_fetch.c's, sub-sampling and
 * the slice path test_gles_grid.c's, refusals and extreme relief
 * test_gles_limits.c's):
 *
 *   equal SCENE PREC PATH [SUB MEAN MAX [CONTEXT]]
 *       GLES (precision PREC = fp16|fp32, visibility PATH = legendre|tables|
 *       slice|split (split: the slice path with split horizons), subsample
 *       SUB, default 1) vs CPU at the same settings, on
 *       scene SCENE = cones (64x64), fractal (64x64, relief 1), dem (96x96
 *       crop of data/jacksboro.png, dx 83, zscale 2).  SPEC metrics with the
 *       unshadowed normalizer; fails if mean > MEAN or max > MAX (defaults:
 *       the 2e-3 / 2e-2) or any output is non-finite.  CONTEXT: a
 *       gl_context.h name (default surfaceless).
 *   determinism   fp16, every path and subsample: the same input renders bit
 *       for bit the same across frames, across the terrain cache (a cached
 *       frame equals a recomputed one) and across two renderer objects.
 *   cache         changing only the lights reuses the pyramid and env
 *       visibility; changing one height recomputes them; results equal a
 *       fresh renderer's.
 *   flat          SPEC's must-show on the GLES path: a flat plane under the
 *       uniform sky gives 1 at every texel (within 1.2e-6, fp16 and fp32),
 *       also at 600 x 450 (the host's threaded split and read-back).
 *   variants      fp32 and fp16 against the CPU (10x the measurement) away from the
 *       defaults: non-square and tiny fields, other k / offset / nphi, a key
 *       light with 9 directions (two key passes), a pole-covering key light
 *       (full swath), three key lights at once, env only, key only, albedo,
 *       env rotation, both visibility paths.
 *   memory        what a frame does not read is not allocated (issue 37):
 *       at subsample 2 a key light whose texels search their rays to the
 *       field's end adds only its factor layer (no grid horizons), and
 *       the slice path holds no V_env grid (a Legendre frame after it on
 *       the same renderer makes its 4 targets); each frame equals a fresh
 *       renderer's bit for bit.
 *
 * Lighting: a non-uniform, coloured SH environment (sky brighter towards
 * +z and +x) and one key light (azimuth 336, elevation 15, radius 2
 * degrees), so both parts of the shading are exercised.  Terrains are made
 * in-test with tools/hfgen.c's formulas.  No GLES context of any kind: exit 77 (gl_test.h).
 * The data directory comes from HFS_DATA_DIR (compile definition).
 */
#include "gles_render_util.h"

#include <stdint.h>
#include <stdlib.h>

/* ---- modes ---------------------------------------------------------------------------- */

static int mode_equal(int argc, char **argv)
{
    if (argc < 5)
        return 2;
    const char *name = argv[2], *prec = argv[3], *path = argv[4];
    const int sub = argc > 5 ? atoi(argv[5]) : 1;
    const double max_mean = argc > 6 ? atof(argv[6]) : 2e-3;
    const double max_max = argc > 7 ? atof(argv[7]) : 2e-2;
    const int n = !strcmp(name, "dem") ? 96 : 64;
    test_context = argc > 8 ? argv[8] : NULL;
    scene s;
    if (scene_make(name, n, HFS_DATA_DIR, &s))
        return 1;
    hfs_renderer *r = gles_or_skip(NULL);
    hfs_lighting l = scene_lighting(1, 1);
    hfs_quality q = quality(prec, path, sub);
    hfs_image g = {0}, c = {0};
    if (!render(r, &s, &l, &q, &g) && !cpu_render(&s, &l, &q, &c)) {
        hfs_metrics m = compare(&s, &l, &q, &g, &c);
        hfs_gles_stats st;
        memset(&st, 0, sizeof st);
        printf("%s %dx%d %s %s subsample %d: mean %.3e rmse %.3e p99 %.3e max %.3e "
               "nonfinite %ld (norm %.4g)\n", name, n, n, prec, path, sub, m.mean_abs, m.rmse,
               m.p99_abs, m.max_abs, m.nonfinite, m.norm);
        const long over = count_over(&g, &c, m.norm, max_max);
        printf("texels past the max bound %.1e: %ld (allowed %ld)\n", max_max, over,
               tie_allowance(&g));
        CHECK(m.nonfinite == 0, "%ld non-finite outputs", m.nonfinite);
        CHECK(m.mean_abs <= max_mean, "mean %.3e > %.3e", m.mean_abs, max_mean);
        CHECK(over <= tie_allowance(&g), "%ld texels past the max %.3e (largest %.3e)", over,
              max_max, m.max_abs);
    }
    hfs_image_free(&g);
    hfs_image_free(&c);
    hfs_renderer_destroy(r);
    scene_free(&s);
    return failures ? 1 : 0;
}

/* Same input -> same output, bit for bit: across frames (cached and
 * recomputed), across renderer objects, for every path and subsample. */
static int mode_determinism(void)
{
    scene s;
    if (scene_make("fractal", 48, HFS_DATA_DIR, &s))
        return 1;
    hfs_renderer *r1 = gles_or_skip(NULL), *r2 = gles_or_skip(NULL);
    hfs_lighting l = scene_lighting(1, 1);
    static const char *const paths[] = {"legendre", "tables"};
    for (int p = 0; p < 2; ++p)
        for (int sub = 1; sub <= 4; sub *= 2) {
            hfs_quality q = quality("fp16", paths[p], sub);
            hfs_image a = {0}, b = {0}, c = {0}, d = {0};
            render(r1, &s, &l, &q, &a);
            render(r1, &s, &l, &q, &b);            /* terrain and env cached */
            hfs_renderer_invalidate(r1);
            render(r1, &s, &l, &q, &c);            /* recomputed */
            render(r2, &s, &l, &q, &d);            /* another object */
            CHECK(a.rgb && bitequal(&a, &b), "%s sub %d: cached frame differs", paths[p], sub);
            CHECK(a.rgb && bitequal(&a, &c), "%s sub %d: recomputed frame differs", paths[p], sub);
            CHECK(a.rgb && bitequal(&a, &d), "%s sub %d: second renderer differs", paths[p], sub);
            hfs_image_free(&a);
            hfs_image_free(&b);
            hfs_image_free(&c);
            hfs_image_free(&d);
        }
    hfs_renderer_destroy(r1);
    hfs_renderer_destroy(r2);
    scene_free(&s);
    printf("determinism: %s\n", failures ? "FAILED" : "bit-identical");
    return failures ? 1 : 0;
}

/* The caches: what changes invalidates exactly what depends on it. */
static int mode_cache(void)
{
    scene s;
    if (scene_make("cones", 48, HFS_DATA_DIR, &s))
        return 1;
    hfs_renderer *r = gles_or_skip(NULL);
    hfs_renderer_desc dd = {.backend = HFS_BACKEND_GLES};
    hfs_lighting l = scene_lighting(1, 1);
    hfs_quality q = quality("fp16", "legendre", 2);
    hfs_image a = {0}, fresh = {0};
    hfs_gles_stats st;
    hfs_renderer_set_timing(r, 1);

    render(r, &s, &l, &q, &a);
    hfs_timings t;
    hfs_renderer_timings(r, &t);
    /* upload, decimate, reconstruct, env, key, transfer, keyfactor, shade,
     * readback (no normals stage: computed where they are read) */
    CHECK(t.n_passes == 9, "first frame: %d passes", t.n_passes);
    for (int p = 0; p < t.n_passes; ++p)
        CHECK(!t.pass[p].cached, "first frame: %s cached", t.pass[p].name);

    /* Only the light moves: terrain passes, env and the env transfer cached;
     * key, key factor and shade run. */
    l.key[0].phi += 0.5;
    render(r, &s, &l, &q, &a);
    hfs_renderer_timings(r, &t);
    for (int p = 0; p < t.n_passes; ++p) {
        const int terrain = !strcmp(t.pass[p].name, "upload") ||
                            !strcmp(t.pass[p].name, "decimate") ||
                            !strcmp(t.pass[p].name, "reconstruct") || !strcmp(t.pass[p].name, "env") ||
                            !strcmp(t.pass[p].name, "transfer");
        CHECK(t.pass[p].cached == terrain, "light change: %s cached=%d", t.pass[p].name,
              t.pass[p].cached);
    }
    hfs_renderer *r2 = gl_test_renderer(&dd);
    render(r2, &s, &l, &q, &fresh);
    CHECK(bitequal(&a, &fresh), "light change: cached frame differs from a fresh renderer");

    /* One height changes (in place, same pointer): everything recomputes. */
    s.z[5 * 48 + 7] += 0.25f;
    render(r, &s, &l, &q, &a);
    hfs_renderer_timings(r, &t);
    for (int p = 0; p < t.n_passes; ++p)
        CHECK(!t.pass[p].cached, "height change: %s cached", t.pass[p].name);
    if (r2) {
        hfs_renderer_invalidate(r2);
        render(r2, &s, &l, &q, &fresh);
        CHECK(bitequal(&a, &fresh), "height change: result differs from a fresh render");
    }

    /* zscale and subsample changes recompute what depends on them. */
    s.f.zscale = 1.5;
    render(r, &s, &l, &q, &a);
    hfs_renderer_timings(r, &t);
    CHECK(t.n_passes > 0 && !t.pass[0].cached, "zscale change: upload cached");
    q.subsample = 1;
    render(r, &s, &l, &q, &a);
    hfs_renderer_timings(r, &t);
    for (int p = 0; p < t.n_passes; ++p)
        if (!strcmp(t.pass[p].name, "env"))
            CHECK(!t.pass[p].cached, "subsample change: env cached");
        else if (!strcmp(t.pass[p].name, "reconstruct"))
            CHECK(t.pass[p].cached, "subsample change: pyramid recomputed");
    (void)st;
    hfs_image_free(&a);
    hfs_image_free(&fresh);
    hfs_renderer_destroy(r2);
    hfs_renderer_destroy(r);
    scene_free(&s);
    printf("cache: %s\n", failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}

/* SPEC must-show on the GLES path: a flat plane under the uniform sky is 1. */
static int mode_flat(void)
{
    hfs_renderer *r = gles_or_skip(NULL);
    /* 600 x 450 (one setting): past the texel count at which the heights'
     * split and the read-back's sum run on worker threads (layout.c,
     * pass_readback.c); a chunk misplaced leaves texels off 1 */
    static const int sizes[][2] = {{2, 2}, {37, 20}, {64, 64}, {600, 450}};
    for (int si = 0; si < 4; ++si)
        for (int prec = 0; prec < 2; ++prec)
            for (int p = 0; p < 2; ++p)
                for (int sub = 1; sub <= 4; sub *= 4) {
                    const int w = sizes[si][0], h = sizes[si][1];
                    if (si == 3 && (prec || p || sub != 4))
                        continue;
                    scene s;
                    memset(&s, 0, sizeof s);
                    s.z = calloc((size_t)w * h, sizeof *s.z);
                    for (size_t i = 0; s.z && i < (size_t)w * h; ++i)
                        s.z[i] = 12.5f;
                    s.f = (hfs_field){.width = w, .height = h, .z = s.z, .dx = 2.0, .zscale = 3.0};
                    hfs_lighting l;
                    hfs_lighting_defaults(&l);
                    l.has_env = 1;
                    for (int c = 0; c < 3; ++c)
                        l.env_sh[c][0] = sqrt(4.0 * PI);
                    hfs_quality q = quality(prec ? "fp32" : "fp16", p ? "tables" : "legendre", sub);
                    hfs_image img = {0};
                    if (!render(r, &s, &l, &q, &img)) {
                        double worst = 0.0;
                        for (size_t i = 0; i < (size_t)w * h * 3; ++i)
                            worst = fmax(worst, fabs(img.rgb[i] - 1.0));
                        /* measured 0 (Legendre) and 1.19e-7 (tables: one
                         * float ulp) on fp16 and fp32 alike, every size,
                         * subsample and llvmpipe variant: 10x the latter */
                        const double tol = 1.2e-6;
                        CHECK(worst <= tol, "flat %dx%d %s %s sub %d: |Lo - 1| = %.3e > %.1e", w,
                              h, prec ? "fp32" : "fp16", p ? "tables" : "legendre", sub, worst, tol);
                    }
                    hfs_image_free(&img);
                    free(s.z);
                }
    hfs_renderer_destroy(r);
    printf("flat: %s\n", failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}



/* Texture bytes of renderer r after rendering l at q (timing level 1). */
static double frame_bytes(hfs_renderer *r, const scene *s, const hfs_lighting *l,
                          const hfs_quality *q, hfs_image *img)
{
    hfs_timings t;
    hfs_renderer_set_timing(r, 1);
    if (render(r, s, l, q, img))
        return -1.0;
    hfs_renderer_timings(r, &t);
    return (double)t.texture_bytes;
}

#define HELD_64 248832 /* mode_memory: measured */
/* the grid's horizons and far grid at 64², 2x2, 16 directions: 33² receivers x 8
 * layers (2 directions a layer, each a horizon and its distance) x 8 bytes,
 * and the far grid, 9² receivers (step 8) x 16 tiles (32 sub-directions, 2 a
 * tile) x 8 bytes x 3 layers (the occluders seen from three heights,
 * split_horizon.h HFS_SPLIT_HEIGHTS; one layer before session 44) */
#define GRID_64 (33 * 33 * 8 * 8 + 9 * 9 * 16 * 8 * 3)
static int mode_memory(void)
{
    scene s;
    if (scene_make("fractal", 64, HFS_DATA_DIR, &s))
        return 1;
    const double texels = 64.0 * 64.0, cells = 33.0 * 33.0; /* the 2x2 grid's receivers */
    hfs_lighting sky = scene_lighting(1, 0), both = scene_lighting(1, 1);
    hfs_quality q = quality("fp16", "split", 2);
    hfs_renderer *a = gles_or_skip(NULL), *b = gles_or_skip(NULL), *fresh = gles_or_skip(NULL);
    hfs_image x = {0}, y = {0};
    /* the sun adds its factor layer (RG16F) and nothing on the grid */
    const double key = frame_bytes(b, &s, &both, &q, &x) - frame_bytes(a, &s, &sky, &q, &y);
    CHECK(key == 4.0 * texels, "a key light on the 2x2 grid adds %.0f bytes, want %.0f", key,
          4.0 * texels);
    /* a Legendre frame after a slice frame makes the V_env grid */
    hfs_quality ql = quality("fp16", "legendre", 2);
    const double before = frame_bytes(a, &s, &sky, &q, &x);
    const double venv = frame_bytes(a, &s, &sky, &ql, &x) - before;
    CHECK(venv >= 4.0 * 8.0 * cells, "the Legendre frame added %.0f bytes, want >= %.0f (V_env)",
          venv, 4.0 * 8.0 * cells);
    render(fresh, &s, &sky, &ql, &y);
    CHECK(x.rgb && y.rgb && bitequal(&x, &y), "Legendre after slice differs from a fresh frame");
    /* what the sky + sun frame holds, pinned as measured (80.3 bytes a
     * texel at 64²: bounds, level array (the heights its last layer), lit
     * targets, the sky occlusion, grid horizons, far grid, key factor);
     * the pyramid build's own targets are not held after the terrain pass
     * (with them: 511572, 9f0a10f), nor the transfer while the sky stays
     * still (with it, 20 bytes a texel more: 459968, 2d49db2), nor normals
     * (computed where they are read; with them, 8 bytes a texel more:
     * 378048, b217fe9), nor a second copy of the heights (4 bytes a texel
     * more: 345280, ab315dc), nor the grid's horizons and far grid once
     * the sky occlusion is made (GRID_64 more: 328896, 98e33cc) */
    const double held = frame_bytes(b, &s, &both, &q, &x);
    CHECK(held == HELD_64, "the sky + sun frame holds %.0f texture bytes, want %.0f", held,
          (double)HELD_64);
    /* the sky turned: the transfer (20 bytes a texel more than the sky
     * occlusion), and the grid's horizons made anew and kept from now on */
    hfs_lighting turned = both;
    turned.env_rotate += 0.5;
    const double held_t = frame_bytes(b, &s, &turned, &q, &x);
    CHECK(held_t == HELD_64 + 20.0 * texels + GRID_64,
          "the turned frame holds %.0f texture bytes, want %.0f", held_t,
          HELD_64 + 20.0 * texels + GRID_64);
    printf("memory: key light +%.0f bytes, V_env +%.0f bytes, sky + sun frame %.0f bytes "
           "(turned %.0f)\n", key, venv, held, held_t);
    hfs_image_free(&x);
    hfs_image_free(&y);
    hfs_renderer_destroy(a);
    hfs_renderer_destroy(b);
    hfs_renderer_destroy(fresh);
    scene_free(&s);
    return failures ? 1 : 0;
}

/* Away from the defaults (fp32: the algorithm itself must match). */
static int mode_variants(void)
{
    hfs_renderer *r = gles_or_skip(NULL);
    /* meas: measured {mean, max} per path (Legendre, tables) and precision
     * (fp16, fp32), the largest of RelWithDebInfo, Release, Debug + ASan and
     * the es30 / sse41 variants (llvmpipe, Mesa 22.3.6); the bound is 10x. */
    struct {
        const char *scene;
        int w, h, k, offset, nphi_env, nphi_key, keys, env, sub;
        double meas[2][2][2];
    } cases[] = {
        {"fractal", 37, 20, 4, 2, 32, 3, 1, 1, 1,
         {{{3.2e-5, 2.8e-4}, {1.0e-7, 2.1e-6}}, {{3.3e-5, 2.7e-4}, {9.2e-8, 8.5e-7}}}},
        {"cones", 2, 2, 4, 2, 32, 3, 1, 1, 1,
         {{{1.7e-7, 2.1e-7}, {1.9e-7, 2.1e-7}}, {{3.6e-5, 4.0e-5}, {9.5e-8, 1.4e-7}}}},
        {"cones", 3, 17, 4, 2, 32, 3, 1, 1, 1,
         {{{1.7e-7, 2.1e-7}, {1.9e-7, 2.1e-7}}, {{3.6e-5, 4.0e-5}, {9.5e-8, 1.4e-7}}}},
        {"fractal", 70, 41, 2, 1, 16, 5, 1, 1, 1,
         {{{3.3e-5, 3.1e-4}, {1.2e-7, 6.1e-6}}, {{3.4e-5, 2.7e-4}, {1.2e-7, 1.7e-6}}}},
        {"fractal", 48, 48, 8, 3, 24, 9, 1, 1, 1,
         {{{3.9e-5, 2.9e-4}, {6.6e-8, 2.7e-6}}, {{4.1e-5, 3.0e-4}, {1.0e-7, 8.8e-7}}}},
        {"fractal", 48, 48, 4, 0, 32, 3, 3, 1, 1,
         {{{1.8e-5, 1.3e-4}, {1.5e-7, 4.3e-6}}, {{2.1e-5, 1.5e-4}, {1.7e-7, 1.5e-6}}}},
        {"cones", 48, 48, 4, 2, 32, 3, 0, 1, 1,
         {{{1.1e-5, 7.9e-5}, {1.1e-7, 4.4e-7}}, {{3.2e-5, 1.1e-4}, {1.1e-7, 4.4e-7}}}},
        {"cones", 48, 48, 4, 2, 32, 3, 1, 0, 1, /* key alone: it is the norm */
         {{{1.3e-7, 1.0e-5}, {1.2e-7, 1.0e-5}}, {{1.0e-5, 1.7e-4}, {1.7e-7, 1.1e-6}}}},
        {"fractal", 48, 48, 4, 2, 32, 3, 4, 0, 1,
         {{{3.4e-7, 3.7e-6}, {3.3e-7, 3.7e-6}}, {{5.2e-6, 9.9e-5}, {2.7e-7, 3.4e-6}}}},
    };
    for (size_t ci = 0; ci < sizeof cases / sizeof cases[0]; ++ci)
        for (int p = 0; p < 2; ++p)
            for (int prec = 0; prec < 2; ++prec) {
                scene s;
                const int n = cases[ci].w > cases[ci].h ? cases[ci].w : cases[ci].h;
                if (scene_make(cases[ci].scene, n, HFS_DATA_DIR, &s))
                    return 1;
                /* crop to w x h (rows stay contiguous with width w) */
                for (int j = 0; j < cases[ci].h; ++j)
                    memmove(s.z + (size_t)j * cases[ci].w, s.z + (size_t)j * n,
                            (size_t)cases[ci].w * sizeof *s.z);
                s.f.width = cases[ci].w;
                s.f.height = cases[ci].h;
                hfs_lighting l = scene_lighting(cases[ci].env, cases[ci].keys > 0);
                l.n_key = cases[ci].keys;
                for (int k = 1; k < l.n_key; ++k) {
                    l.key[k] = l.key[0];
                    l.key[k].phi += 2.1 * k;
                    l.key[k].elev = k == 3 ? 80.0 * PI / 180.0 : 35.0 * PI / 180.0;
                    l.key[k].alpha = k == 3 ? 12.0 * PI / 180.0 : 4.0 * PI / 180.0; /* k 3: covers the zenith */
                }
                l.albedo = 0.55;
                l.env_rotate = -1.1;
                hfs_quality q = quality(prec ? "fp32" : "fp16", p ? "tables" : "legendre",
                                        cases[ci].sub);
                q.k = cases[ci].k;
                q.offset = cases[ci].offset;
                q.nphi_env = cases[ci].nphi_env;
                q.nphi_key = cases[ci].nphi_key;
                hfs_image g = {0}, c = {0};
                if (!render(r, &s, &l, &q, &g) && !cpu_render(&s, &l, &q, &c)) {
                    hfs_metrics m = compare(&s, &l, &q, &g, &c);
                    const double bmean = 10.0 * cases[ci].meas[p][prec][0];
                    const double bmax = 10.0 * cases[ci].meas[p][prec][1];
                    const long over = count_over(&g, &c, m.norm, bmax);
                    printf("%-8s %3dx%-3d k%d o%d nphi %2d/%d keys %d env %d %-8s %s: mean %.2e max %.2e"
                           " (%ld texels past %.1e)\n",
                           cases[ci].scene, cases[ci].w, cases[ci].h, q.k, q.offset, q.nphi_env,
                           q.nphi_key, l.n_key, l.has_env, p ? "tables" : "legendre",
                           prec ? "fp32" : "fp16", m.mean_abs, m.max_abs, over, bmax);
                    CHECK(m.nonfinite == 0 && m.mean_abs <= bmean && over <= tie_allowance(&g),
                          "case %zu: mean %.3e (bound %.1e) max %.3e: %ld texels past %.1e", ci,
                          m.mean_abs, bmean, m.max_abs, over, bmax);
                }
                hfs_image_free(&g);
                hfs_image_free(&c);
                scene_free(&s);
            }
    hfs_renderer_destroy(r);
    return failures ? 1 : 0;
}

int main(int argc, char **argv)
{
    setvbuf(stdout, NULL, _IONBF, 0);
    if (argc < 2) {
        fprintf(stderr, "usage: test_gles_render equal|determinism|cache|flat|memory|"
                        "variants ...\n");
        return 2;
    }
    if (!strcmp(argv[1], "equal"))
        return mode_equal(argc, argv);
    if (!strcmp(argv[1], "determinism"))
        return mode_determinism();
    if (!strcmp(argv[1], "cache"))
        return mode_cache();
    if (!strcmp(argv[1], "flat"))
        return mode_flat();
    if (!strcmp(argv[1], "memory"))
        return mode_memory();
    if (!strcmp(argv[1], "variants"))
        return mode_variants();
    fprintf(stderr, "unknown mode %s\n", argv[1]);
    return 2;
}
