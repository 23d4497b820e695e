/*
 * test_gles_render.c — the GLES renderer against its oracle, the CPU
 * reference (label "gl").  One executable, one mode per ctest entry:
 *
 *   equal SCENE PREC PATH [SUB MEAN MAX [CONTEXT]]
 *       GLES (precision PREC = fp16|fp32, visibility PATH = legendre|tables,
 *       subsample SUB, default 1) vs CPU at default settings otherwise, on
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
 *       uniform sky gives 1 at every texel (fp16: 1e-3, fp32: 1e-5).
 *   timing        timing levels 1 and 2 report every pass, fetch counts and
 *       texture memory.
 *   variants      fp32 (tight) and fp16 against the CPU away from the
 *       defaults: non-square and tiny fields, other k / offset / nphi, a key
 *       light with 9 directions (two key passes), a pole-covering key light
 *       (full swath), three key lights at once, env only, key only, albedo,
 *       env rotation, both visibility paths.
 *   errors        refusals: local lights on the wedge-table path, an unknown
 *       profile, fp32 under es30-half, nphi-env beyond the es30 uniform-block
 *       limit.
 *
 * Lighting: a non-uniform, coloured SH environment (sky brighter towards
 * +z and +x) and one key light (azimuth 336, elevation 15, radius 2
 * degrees), so both parts of the shading are exercised.  Terrains are made
 * in-test with tools/hfgen.c's formulas.  No GLES context here: exit 77.
 * The data directory comes from HFS_DATA_DIR (compile definition).
 */
#include "backends.h"
#include "test_gles_scenes.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define SKIP 77

#ifndef HFS_DATA_DIR
#define HFS_DATA_DIR "data"
#endif

#include "check.h"

static hfs_quality quality(const char *prec, const char *path, int sub)
{
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.precision = prec && !strcmp(prec, "fp32") ? HFS_PRECISION_FP32 : HFS_PRECISION_FP16;
    q.visibility = path && !strcmp(path, "tables") ? HFS_VIS_WEDGE_TABLE : HFS_VIS_LEGENDRE;
    q.subsample = sub;
    return q;
}

/* Makes a GLES renderer, or exits 77 with the reason. */
static const char *test_context; /* NULL: surfaceless */

static hfs_renderer *gles_or_skip(const char *profile)
{
    hfs_renderer_desc d = {.backend = HFS_BACKEND_GLES, .context = test_context,
                           .gl_profile = profile};
    hfs_renderer *r = NULL;
    hfs_error err;
    int rc = hfs_renderer_create(&d, &r, &err);
    if (rc == HFS_E_CONTEXT || (rc && !profile)) {
        printf("SKIP: no GLES renderer here: %s\n", err.msg);
        exit(SKIP);
    }
    return r;
}

static int render(hfs_renderer *r, const scene *s, const hfs_lighting *l, const hfs_quality *q,
                  hfs_image *img)
{
    hfs_error err;
    if (!img->rgb && hfs_image_alloc(img, s->f.width, s->f.height, &err)) {
        CHECK(0, "alloc: %s", err.msg);
        return -1;
    }
    int rc = hfs_renderer_render(r, &s->f, l, q, img, NULL, NULL, &err);
    CHECK(rc == 0, "render: %s", err.msg);
    return rc;
}

static int cpu_render(const scene *s, const hfs_lighting *l, const hfs_quality *q,
                      hfs_image *img)
{
    hfs_renderer_desc d = {.backend = HFS_BACKEND_CPU};
    hfs_renderer *r = NULL;
    hfs_error err;
    if (hfs_renderer_create(&d, &r, &err))
        return -1;
    int rc = render(r, s, l, q, img);
    hfs_renderer_destroy(r);
    return rc;
}

static hfs_metrics compare(const scene *s, const hfs_lighting *l, const hfs_quality *q,
                           const hfs_image *a, const hfs_image *b)
{
    hfs_metrics m;
    memset(&m, 0, sizeof m);
    hfs_image un = {0};
    hfs_error err;
    if (hfs_image_alloc(&un, s->f.width, s->f.height, &err) ||
        hfs_render_unshadowed(&s->f, l, q, &un, &err) ||
        hfs_compare_images(a, b, hfs_image_max(&un), &m, &err))
        CHECK(0, "compare: %s", err.msg);
    hfs_image_free(&un);
    return m;
}

static inline int bitequal(const hfs_image *a, const hfs_image *b)
{
    return a->width == b->width && a->height == b->height &&
           !memcmp(a->rgb, b->rgb, (size_t)a->width * a->height * 3 * sizeof(float));
}

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
        CHECK(m.nonfinite == 0, "%ld non-finite outputs", m.nonfinite);
        CHECK(m.mean_abs <= max_mean, "mean %.3e > %.3e", m.mean_abs, max_mean);
        CHECK(m.max_abs <= max_max, "max %.3e > %.3e", m.max_abs, max_max);
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
    hfs_error err;
    hfs_renderer_set_timing(r, 1);

    render(r, &s, &l, &q, &a);
    hfs_timings t;
    hfs_renderer_timings(r, &t);
    CHECK(t.n_passes == 10, "first frame: %d passes", t.n_passes);
    for (int p = 0; p < t.n_passes; ++p)
        CHECK(!t.pass[p].cached, "first frame: %s cached", t.pass[p].name);

    /* Only the light moves: terrain passes, env and the env transfer cached;
     * key, key factor and shade run. */
    l.key[0].phi += 0.5;
    render(r, &s, &l, &q, &a);
    hfs_renderer_timings(r, &t);
    for (int p = 0; p < t.n_passes; ++p) {
        const int terrain = !strcmp(t.pass[p].name, "upload") || !strcmp(t.pass[p].name, "normals") ||
                            !strcmp(t.pass[p].name, "decimate") ||
                            !strcmp(t.pass[p].name, "reconstruct") || !strcmp(t.pass[p].name, "env") ||
                            !strcmp(t.pass[p].name, "transfer");
        CHECK(t.pass[p].cached == terrain, "light change: %s cached=%d", t.pass[p].name,
              t.pass[p].cached);
    }
    hfs_renderer *r2 = NULL;
    if (!hfs_renderer_create(&dd, &r2, &err)) {
        render(r2, &s, &l, &q, &fresh);
        CHECK(bitequal(&a, &fresh), "light change: cached frame differs from a fresh renderer");
    }

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
    static const int sizes[][2] = {{2, 2}, {37, 20}, {64, 64}};
    for (int si = 0; si < 3; ++si)
        for (int prec = 0; prec < 2; ++prec)
            for (int p = 0; p < 2; ++p)
                for (int sub = 1; sub <= 4; sub *= 4) {
                    const int w = sizes[si][0], h = sizes[si][1];
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
                        const double tol = prec ? 1e-5 : 1e-3;
                        CHECK(worst <= tol, "flat %dx%d %s %s sub %d: |Lo - 1| = %.3e > %.0e", w,
                              h, prec ? "fp32" : "fp16", p ? "tables" : "legendre", sub, worst, tol);
                    }
                    hfs_image_free(&img);
                    free(s.z);
                }
    hfs_renderer_destroy(r);
    printf("flat: %s\n", failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}

/* Timing levels: every pass named, times and memory reported, fetches
 * counted at level 2 and equal to an independent count for a flat field
 * (every sample in-grid is skipped by the height bound there). */
static int mode_timing(void)
{
    scene s;
    if (scene_make("dem", 64, HFS_DATA_DIR, &s))
        return 1;
    hfs_renderer *r = gles_or_skip(NULL);
    hfs_lighting l = scene_lighting(1, 1);
    hfs_quality q = quality("fp16", "legendre", 2);
    hfs_image img = {0};
    hfs_timings t;
    render(r, &s, &l, &q, &img);
    hfs_renderer_timings(r, &t);
    CHECK(t.n_passes == 0, "timing off: %d passes reported", t.n_passes);
    static const char *const names[] = {"upload", "normals", "decimate", "reconstruct", "env",
                                        "key", "transfer", "keyfactor", "shade", "readback"};
    const int n_names = (int)(sizeof names / sizeof names[0]);
    for (int level = 1; level <= 2; ++level) {
        hfs_renderer_set_timing(r, level);
        hfs_renderer_invalidate(r);
        render(r, &s, &l, &q, &img);
        hfs_renderer_timings(r, &t);
        printf("timing level %d (%s, %s): frame %.2f ms, passes %.2f ms, %zu texture bytes\n",
               level, t.method, t.device, t.frame_ms, t.gpu_ms, t.texture_bytes);
        CHECK(t.n_passes == n_names, "level %d: %d passes", level, t.n_passes);
        for (int p = 0; p < t.n_passes && p < n_names; ++p) {
            printf("  %-12s %8.3f ms %12.0f fetches\n", t.pass[p].name, t.pass[p].ms,
                   t.pass[p].fetches);
            CHECK(!strcmp(t.pass[p].name, names[p]), "pass %d is %s, want %s", p, t.pass[p].name,
                  names[p]);
            CHECK(t.pass[p].ms >= 0.0 && t.pass[p].ms < 60000.0, "%s: %g ms", t.pass[p].name,
                  t.pass[p].ms);
            if (level == 2 || (strcmp(names[p], "env") && strcmp(names[p], "key")))
                CHECK(t.pass[p].fetches >= 0.0, "%s: fetches %g", names[p], t.pass[p].fetches);
        }
        CHECK(t.texture_bytes > (size_t)64 * 64 * 4 * 10, "texture bytes %zu", t.texture_bytes);
        CHECK(t.frame_ms > 0.0 && t.gpu_ms > 0.0, "frame %g ms, passes %g ms", t.frame_ms,
              t.gpu_ms);
    }
    /* Level 2 destroyed the cached visibility; the next frame is still right. */
    hfs_image again = {0};
    hfs_renderer_set_timing(r, 0);
    render(r, &s, &l, &q, &again);
    hfs_renderer_invalidate(r);
    render(r, &s, &l, &q, &img);
    CHECK(bitequal(&img, &again), "frame after a counting frame differs");
    CHECK(hfs_renderer_set_timing(r, 3) == HFS_E_INVALID, "timing level 3 accepted");
    hfs_image_free(&img);
    hfs_image_free(&again);
    hfs_renderer_destroy(r);
    scene_free(&s);
    return failures ? 1 : 0;
}

/* Away from the defaults (fp32: the algorithm itself must match). */
static int mode_variants(void)
{
    hfs_renderer *r = gles_or_skip(NULL);
    struct {
        const char *scene;
        int w, h, k, offset, nphi_env, nphi_key, keys, env, sub;
        double mean32, max32;
    } cases[] = {
        {"fractal", 37, 20, 4, 2, 32, 3, 1, 1, 1, 5e-6, 2e-4},
        {"cones", 2, 2, 4, 2, 32, 3, 1, 1, 1, 5e-6, 2e-4},
        {"cones", 3, 17, 4, 2, 32, 3, 1, 1, 1, 5e-6, 2e-4},
        {"fractal", 70, 41, 2, 1, 16, 5, 1, 1, 1, 5e-6, 2e-4},
        {"fractal", 48, 48, 8, 3, 24, 9, 1, 1, 1, 5e-6, 2e-4},
        {"fractal", 48, 48, 4, 0, 32, 3, 3, 1, 1, 5e-6, 2e-4},
        {"cones", 48, 48, 4, 2, 32, 3, 0, 1, 1, 5e-6, 2e-4},
        {"cones", 48, 48, 4, 2, 32, 3, 1, 0, 1, 5e-6, 5e-4}, /* key alone: it is the norm */
        {"fractal", 48, 48, 4, 2, 32, 3, 4, 0, 1, 5e-6, 2e-4},
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
                    const double bmean = prec ? cases[ci].mean32 : 1e-4;
                    const double bmax = prec ? cases[ci].max32 : 5e-4;
                    printf("%-8s %3dx%-3d k%d o%d nphi %2d/%d keys %d env %d %-8s %s: mean %.2e max %.2e\n",
                           cases[ci].scene, cases[ci].w, cases[ci].h, q.k, q.offset, q.nphi_env,
                           q.nphi_key, l.n_key, l.has_env, p ? "tables" : "legendre",
                           prec ? "fp32" : "fp16", m.mean_abs, m.max_abs);
                    CHECK(m.nonfinite == 0 && m.mean_abs <= bmean && m.max_abs <= bmax,
                          "case %zu: mean %.3e (bound %.0e) max %.3e (bound %.0e)", ci, m.mean_abs,
                          bmean, m.max_abs, bmax);
                }
                hfs_image_free(&g);
                hfs_image_free(&c);
                scene_free(&s);
            }
    hfs_renderer_destroy(r);
    return failures ? 1 : 0;
}

/* Refusals: one line, the right code, nothing rendered. */
static int mode_errors(void)
{
    scene s;
    if (scene_make("cones", 32, HFS_DATA_DIR, &s))
        return 1;
    hfs_renderer *r = gles_or_skip(NULL);
    hfs_lighting l = scene_lighting(1, 0);
    hfs_quality q = quality("fp16", "legendre", 1);
    hfs_image img = {0};
    hfs_error err;
    if (hfs_image_alloc(&img, 32, 32, &err))
        return 1;

    q.nphi_env = 128; /* 2 + 17*128 + 258 vec4 = 39 KB > 16 KB (es30) */
    int rc = hfs_renderer_render(r, &s.f, &l, &q, &img, NULL, NULL, &err);
    printf("nphi-env 128: %s\n", err.msg);
    CHECK(rc == HFS_E_UNSUPPORTED && strstr(err.msg, "GL_MAX_UNIFORM_BLOCK_SIZE"),
          "nphi-env 128 under es30-half: %d %s", rc, err.msg);
    CHECK(strchr(err.msg, '\n') == NULL, "message not one line");
    q.nphi_env = 32;
    CHECK(hfs_renderer_render(r, &s.f, &l, &q, &img, NULL, NULL, &err) == 0,
          "renderer unusable after a refusal: %s", err.msg);

    hfs_renderer_desc d = {.backend = HFS_BACKEND_GLES, .gl_profile = "es29"};
    hfs_renderer *bad = NULL;
    rc = hfs_renderer_create(&d, &bad, &err);
    printf("profile es29: %s\n", err.msg);
    CHECK(rc == HFS_E_INVALID && bad == NULL && strstr(err.msg, "es30-half"), "profile es29: %d %s",
          rc, err.msg);

    d.gl_profile = "es30-half";
    if (!hfs_renderer_create(&d, &bad, &err)) {
        q.precision = HFS_PRECISION_FP32;
        rc = hfs_renderer_render(bad, &s.f, &l, &q, &img, NULL, NULL, &err);
        printf("fp32 under es30-half: %s\n", err.msg);
        CHECK(rc == HFS_E_UNSUPPORTED && strstr(err.msg, "es30-half"), "fp32 under es30-half: %d %s",
              rc, err.msg);
        hfs_renderer_destroy(bad);
    }
    /* es32 relaxes the limits: nphi-env 128 fits the driver's uniform blocks. */
    d.gl_profile = "es32";
    if (!hfs_renderer_create(&d, &bad, &err)) {
        q.precision = HFS_PRECISION_FP16;
        q.nphi_env = 128;
        rc = hfs_renderer_render(bad, &s.f, &l, &q, &img, NULL, NULL, &err);
        printf("nphi-env 128 under es32: %s\n", rc ? err.msg : "ok");
        hfs_renderer_destroy(bad);
    } else {
        printf("es32 not available here: %s\n", err.msg);
    }
    hfs_image_free(&img);
    hfs_renderer_destroy(r);
    scene_free(&s);
    return failures ? 1 : 0;
}

int main(int argc, char **argv)
{
    setvbuf(stdout, NULL, _IONBF, 0);
    if (argc < 2) {
        fprintf(stderr, "usage: test_gles_render equal|determinism|cache|flat|timing|errors ...\n");
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
    if (!strcmp(argv[1], "timing"))
        return mode_timing();
    if (!strcmp(argv[1], "errors"))
        return mode_errors();
    if (!strcmp(argv[1], "variants"))
        return mode_variants();
    fprintf(stderr, "unknown mode %s\n", argv[1]);
    return 2;
}
