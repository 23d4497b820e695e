/*
 * test_horizons.c — hfs_renderer_horizons (issue 39) on its three
 * backends, against the truth's exact horizons and against geometry:
 *   - the CPU reference's search is the exact supremum over the bilinear
 *     surface (every cell between crossings solved, ray_bound.h "cells"),
 *     so it equals the truth's within a float's rounding and never
 *     exceeds it; GLES stays within a bound of the CPU (fp16 hi + lo
 *     heights, fp16 hi + lo angles) and so of the truth;
 *   - a tilted plane: every backend gives atan(slope) exactly towards it
 *     and atan(-slope) away; border texels looking out get
 *     HFS_HORIZON_NONE;
 *   - the radius: a spike farther than the radius is not seen, nearer it is;
 *   - invariances: dx and zscale scaled together leave the angles as they
 *     are; the field mirrored in x with the azimuths mirrored gives the
 *     mirrored angles; a non-square field;
 *   - GLES tiles (a field over the ES 3.0 minimum under strict limits):
 *     equal to the single search within the fp16 path, no seam.
 * Usage: test_horizons [W H] (default 61 47).  GLES parts skip (77) only
 * when no GL context can be made at all (gl_test.h).
 */
#include "check.h"
#include "gl_test.h"
#include "terrain_gen.h"

#include <math.h>
#include <stdlib.h>

#define PI 3.14159265358979323846
#define N_AZ 7

/* Bounds, about 1.2x what was measured at 61 x 47 (printed by this test;
 * radians): CPU - truth 0 at every texel (both the exact supremum over
 * the bilinear surface, in double, rounded to float: the bound allows a
 * float's rounding of an angle, not a cell's twist, which the crossings
 * alone missed by up to 0.20 rad on this very rough field: relief 0.35 x
 * zscale 9 over dx 1.5); GLES -
 * CPU fp16 mean 9.6e-7, max 1.11e-5, fp32 9.4e-7, 1.2e-5; mirrored GLES
 * 4.65e-6 (the CPU and the truth: 0).  Tiles (2600 x 24, zscale 40): the
 * tiled search against the single one 1.42e-3 at worst, 4.9e-4 at the
 * seam: the GPU's heights (fp16 hi + lo, or fp32) hold about 2^-23 of the
 * field's range, and this fractal's range grows with its width while its
 * texel-to-texel steps do not (the single search against the CPU: 1.2e-3
 * at 2600 wide, 8.0e-4 at 2000 in fp16 and 8.0e-4 in fp32, 7.2e-5 at
 * 200). */
#define BOUND_CPU_MEAN 1e-7
#define BOUND_CPU_MAX 2.4e-7
#define BOUND_GLES_MEAN 1.2e-6
#define BOUND_GLES_MAX 1.35e-5
#define BOUND_GLES32_MEAN 1.15e-6
#define BOUND_GLES32_MAX 1.45e-5
#define BOUND_MIRROR 5.6e-6
#define BOUND_TILES 1.7e-3

static const double azimuths[N_AZ] = {0.0, 0.5 * PI, PI, 1.25 * PI, 0.3, 2.0, -1.1};

typedef struct err_stats {
    double mean, max;
} err_stats;

static err_stats compare(const float *a, const float *b, size_t n)
{
    err_stats e = {0.0, 0.0};
    size_t worst = 0;
    for (size_t k = 0; k < n; ++k) {
        const double d = fabs((double)a[k] - b[k]);
        e.mean += d / (double)n;
        if (d > e.max)
            e.max = d, worst = k;
    }
    if (getenv("HFS_HORIZONS_VERBOSE"))
        printf("  worst at %zu: %.9g vs %.9g\n", worst, a[worst], b[worst]);
    return e;
}

static hfs_renderer *make(hfs_backend b)
{
    const hfs_renderer_desc d = {.backend = b};
    if (b == HFS_BACKEND_GLES)
        return gl_test_renderer(&d);
    hfs_renderer *r = NULL;
    hfs_error err = {""};
    if (hfs_renderer_create(&d, &r, &err)) {
        fprintf(stderr, "FAIL: %s\n", err.msg);
        exit(1);
    }
    return r;
}

static float *horizons(hfs_renderer *r, const hfs_field *f, const double *az, int n,
                       double radius, hfs_precision precision)
{
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.precision = precision;
    const hfs_horizon_desc d = {.n_azimuths = n, .azimuth = az, .radius = radius};
    float *out = malloc((size_t)n * (size_t)f->width * (size_t)f->height * sizeof *out);
    hfs_error err = {""};
    const int rc = out ? hfs_renderer_horizons(r, f, &q, &d, out, &err) : HFS_E_NOMEM;
    CHECK(rc == HFS_OK, "%s horizons: %s", hfs_renderer_backend_name(r), err.msg);
    if (rc) {
        free(out);
        exit(1);
    }
    return out;
}

/* The fractal: CPU <= truth everywhere, CPU near the truth, GLES near the CPU. */
static void fractal_checks(hfs_renderer *const r[3], int w, int h)
{
    float *z = malloc((size_t)w * h * sizeof *z);
    hfs_terrain_fractal(z, w, h, 7u, 0.35);
    const hfs_field f = {w, h, z, 1.5, 9.0};
    const size_t n = (size_t)N_AZ * w * h;
    float *t = horizons(r[2], &f, azimuths, N_AZ, 0.0, HFS_PRECISION_FP16);
    float *c = horizons(r[1], &f, azimuths, N_AZ, 0.0, HFS_PRECISION_FP16);
    long above = 0, none = 0;
    for (size_t k = 0; k < n; ++k) {
        above += c[k] > t[k] + 1e-6f;
        none += (c[k] == HFS_HORIZON_NONE) != (t[k] == HFS_HORIZON_NONE);
    }
    CHECK(above == 0, "the CPU's search rose above the truth's supremum at %ld texels", above);
    CHECK(none == 0, "CPU and truth disagree on %ld rays meeting no terrain", none);
    const err_stats ct = compare(c, t, n);
    printf("fractal %dx%d: cpu - truth mean %.3g max %.3g rad\n", w, h, ct.mean, ct.max);
    CHECK(ct.mean <= BOUND_CPU_MEAN && ct.max <= BOUND_CPU_MAX, "cpu vs truth: mean %g max %g",
          ct.mean, ct.max);
    if (r[0]) {
        for (int p = 0; p < 2; ++p) {
            float *g = horizons(r[0], &f, azimuths, N_AZ, 0.0,
                                p ? HFS_PRECISION_FP32 : HFS_PRECISION_FP16);
            const err_stats gc = compare(g, c, n), gt = compare(g, t, n);
            printf("  gles %s - cpu mean %.3g max %.3g; - truth mean %.3g max %.3g rad\n",
                   p ? "fp32" : "fp16", gc.mean, gc.max, gt.mean, gt.max);
            CHECK(gc.mean <= (p ? BOUND_GLES32_MEAN : BOUND_GLES_MEAN) &&
                      gc.max <= (p ? BOUND_GLES32_MAX : BOUND_GLES_MAX),
                  "gles %s vs cpu: mean %g max %g", p ? "fp32" : "fp16", gc.mean, gc.max);
            CHECK(gt.mean <= (p ? BOUND_GLES32_MEAN : BOUND_GLES_MEAN) &&
                      gt.max <= (p ? BOUND_GLES32_MAX : BOUND_GLES_MAX),
                  "gles %s vs truth: mean %g max %g", p ? "fp32" : "fp16", gt.mean, gt.max);
            free(g);
        }
    }
    free(t);
    free(c);
    free(z);
}

/* z = a x (x = i dx): towards +x the horizon is the plane itself, atan(a
 * zscale / dx... per world unit); away from it, the nearest crossing's
 * fall; the last column looking +x meets nothing. */
static void plane_checks(hfs_renderer *r, int w, int h)
{
    float *z = malloc((size_t)w * h * sizeof *z);
    const double dx = 2.0, zscale = 0.5, a = 3.0; /* world slope a zscale / dx = 0.75 */
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            z[(size_t)j * w + i] = (float)(a * i);
    const hfs_field f = {w, h, z, dx, zscale};
    const double az[2] = {0.0, PI};
    float *o = horizons(r, &f, az, 2, 0.0, HFS_PRECISION_FP16);
    const double up = atan(a * zscale / dx);
    const double tol = strcmp(hfs_renderer_backend_name(r), "gles") ? 1e-6 : 2e-4;
    long bad = 0;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const float e = o[(size_t)j * w + i], wst = o[(size_t)(h + j) * w + i];
            bad += i < w - 1 ? fabs(e - up) > tol : e != HFS_HORIZON_NONE;
            bad += i > 0 ? fabs(wst + up) > tol : wst != HFS_HORIZON_NONE;
        }
    CHECK(bad == 0, "%s: the tilted plane's horizons wrong at %ld texel rays",
          hfs_renderer_backend_name(r), bad);
    free(o);
    free(z);
}

/* A spike 12 texels east of the centre on a flat field: not seen within a
 * radius of 11 texels, seen within 13; within 11.5 every backend sees its
 * flank (height 12 at 11.5 texels: the bilinear surface cut at the
 * radius, which the crossings' searches take as one more end). */
static void radius_checks(hfs_renderer *r, int w, int h)
{
    float *z = calloc((size_t)w * h, sizeof *z);
    const int ci = w / 2 - 6, cj = h / 2;
    z[(size_t)cj * w + ci + 12] = 24.0f;
    const hfs_field f = {w, h, z, 0.5, 1.0};
    const double az = 0.0, texels[3] = {11.0, 11.5, 13.0};
    const double want[3] = {0.0, atan(12.0 / (11.5 * f.dx)), atan(24.0 / (12.0 * f.dx))};
    for (int k = 0; k < 3; ++k) {
        float *o = horizons(r, &f, &az, 1, texels[k] * f.dx, HFS_PRECISION_FP16);
        const float seen = o[(size_t)cj * w + ci];
        CHECK(fabs(seen - want[k]) < 2e-4, "%s radius %g texels: %g, want %g",
              hfs_renderer_backend_name(r), texels[k], seen, want[k]);
        free(o);
    }
    free(z);
}

/* dx and zscale doubled together: the same angles; the field mirrored in x
 * and the azimuths mirrored (phi -> pi - phi): the mirrored angles. */
static void invariance_checks(hfs_renderer *r, int w, int h)
{
    float *z = malloc((size_t)w * h * sizeof *z), *m = malloc((size_t)w * h * sizeof *m);
    hfs_terrain_fractal(z, w, h, 11u, 0.3);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            m[(size_t)j * w + i] = z[(size_t)j * w + (w - 1 - i)];
    const hfs_field f = {w, h, z, 1.25, 7.0}, f2 = {w, h, z, 2.5, 14.0}, fm = {w, h, m, 1.25, 7.0};
    double mirrored[N_AZ];
    for (int a = 0; a < N_AZ; ++a)
        mirrored[a] = PI - azimuths[a];
    float *o = horizons(r, &f, azimuths, N_AZ, 0.0, HFS_PRECISION_FP16);
    float *o2 = horizons(r, &f2, azimuths, N_AZ, 0.0, HFS_PRECISION_FP16);
    float *om = horizons(r, &fm, mirrored, N_AZ, 0.0, HFS_PRECISION_FP16);
    const size_t n = (size_t)N_AZ * w * h;
    const err_stats s = compare(o, o2, n);
    double mir = 0.0;
    for (int a = 0; a < N_AZ; ++a)
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) {
                const size_t p = ((size_t)a * h + j) * w;
                mir = fmax(mir, fabs((double)o[p + i] - om[p + (w - 1 - i)]));
            }
    printf("%s: scaled max %.3g, mirrored max %.3g rad\n", hfs_renderer_backend_name(r), s.max,
           mir);
    CHECK(s.max <= 1e-6, "%s: dx and zscale doubled moved an angle by %g",
          hfs_renderer_backend_name(r), s.max);
    CHECK(mir <= BOUND_MIRROR, "%s: the mirrored field's angles differ by %g",
          hfs_renderer_backend_name(r), mir);
    free(o), free(o2), free(om), free(z), free(m);
}

/* A 2600 x 24 field under the ES 3.0 minimum (2048 texels: two tiles,
 * the seam at column 1984 = 2048 - 2 halos) against the same search in one
 * piece at the driver's limit: within the tiles' own fp16 normalization,
 * and no texel next to the seam further from the single search than the
 * worst texel elsewhere.  Without a radius: one line naming the way out. */
static void tile_checks(hfs_renderer *single, int w, int h)
{
    const hfs_renderer_desc sd = {.backend = HFS_BACKEND_GLES, .gl_strict_limits = 1};
    hfs_renderer *strict = gl_test_renderer(&sd);
    float *z = malloc((size_t)w * h * sizeof *z);
    hfs_terrain_fractal(z, w, h, 5u, 0.3);
    const hfs_field f = {w, h, z, 2.0, 40.0};
    const double radius = 30.0 * f.dx; /* halo 32: inner parts of 1984 */
    float *a = horizons(strict, &f, azimuths, N_AZ, radius, HFS_PRECISION_FP16);
    float *b = horizons(single, &f, azimuths, N_AZ, radius, HFS_PRECISION_FP16);
    double seam = 0.0, rest = 0.0;
    for (int k = 0; k < N_AZ; ++k)
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) {
                const size_t p = ((size_t)k * h + j) * w + i;
                const double d = fabs((double)a[p] - b[p]);
                if (abs(i - 1984) <= 2)
                    seam = fmax(seam, d);
                else
                    rest = fmax(rest, d);
            }
    printf("tiles %dx%d: seam max %.3g, elsewhere max %.3g rad\n", w, h, seam, rest);
    CHECK(seam <= rest && rest <= BOUND_TILES, "tiles: seam %g, elsewhere %g", seam, rest);
    hfs_error err = {""};
    const hfs_horizon_desc whole = {.n_azimuths = N_AZ, .azimuth = azimuths};
    CHECK(hfs_renderer_horizons(strict, &f, NULL, &whole, a, &err) == HFS_E_UNSUPPORTED &&
              strstr(err.msg, "give a radius"),
          "tiles without a radius: %s", err.msg);
    free(a), free(b), free(z);
    hfs_renderer_destroy(strict);
}

static int by_value(const void *a, const void *b)
{
    const float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* window [lo, hi] against the whole search `all` (scratch: win). */
static void window_check(hfs_renderer *r, const hfs_field *f, hfs_horizon_desc *d, double lo,
                         double hi, const float *all, float *win)
{
    const size_t n = (size_t)N_AZ * f->width * f->height;
    d->lo = lo, d->hi = hi;
    hfs_error err = {""};
    CHECK(hfs_renderer_horizons(r, f, NULL, d, win, &err) == HFS_OK, "window: %s", err.msg);
    long off = 0, inside = 0;
    for (size_t k = 0; k < n; ++k) {
        const float want = all[k] == HFS_HORIZON_NONE ? (float)lo
                                                      : fminf(fmaxf(all[k], (float)lo), (float)hi);
        off += win[k] != want;
        inside += all[k] > (float)lo && all[k] < (float)hi;
    }
    printf("%s window [%.2f, %.2f]: %ld of %zu differ from the clamped search (%ld inside)\n",
           hfs_renderer_backend_name(r), lo, hi, off, n, inside);
    CHECK(off == 0 && inside > (long)n / 4, "%s window: %ld differ, %ld inside",
          hfs_renderer_backend_name(r), off, inside);
}

/* A window [lo, hi] returns clamp(gamma, lo, hi) of the whole search, lo
 * for a ray that meets no terrain, on every backend, bit for bit: the
 * search only skips (from lo) or stops (at hi) where the clamp would hide
 * the difference.  A window that is not one is refused. */
static void window_checks(hfs_renderer *r, int w, int h)
{
    float *z = malloc((size_t)w * h * sizeof *z);
    hfs_terrain_fractal(z, w, h, 11u, 0.5);
    const hfs_field f = {w, h, z, 1.0, 0.6};
    const size_t n = (size_t)N_AZ * w * h;
    float *all = horizons(r, &f, azimuths, N_AZ, 0.0, HFS_PRECISION_FP16);
    float *win = malloc(n * sizeof *win);
    /* the windows: the 30th to 70th percentiles of this field's horizons,
     * and one from a negative elevation (the searches start at a negative
     * slope; a ray with no terrain, or none above lo, comes back as lo
     * exactly, not as the float atan(tan(lo))) to the median */
    memcpy(win, all, n * sizeof *win);
    qsort(win, n, sizeof *win, by_value);
    const double los[2] = {win[n * 3 / 10], -0.1}, his[2] = {win[n * 7 / 10], win[n / 2]};
    hfs_horizon_desc d = {.n_azimuths = N_AZ, .azimuth = azimuths, .window = 1};
    hfs_error err = {""};
    for (int k = 0; k < 2; ++k)
        window_check(r, &f, &d, los[k], his[k], all, win);
    d.lo = 0.4, d.hi = 0.3;
    CHECK(hfs_renderer_horizons(r, &f, NULL, &d, win, &err) == HFS_E_INVALID &&
              strstr(err.msg, "window [0.4, 0.3]"),
          "a window with lo > hi: %s", err.msg);
    free(win);
    free(all);
    free(z);
}

int main(int argc, char **argv)
{
    const int w = argc > 2 ? atoi(argv[1]) : 61, h = argc > 2 ? atoi(argv[2]) : 47;
    hfs_renderer *r[3] = {make(HFS_BACKEND_GLES), make(HFS_BACKEND_CPU),
                          make(HFS_BACKEND_TRUTH)};
    fractal_checks(r, w, h);
    tile_checks(r[0], 2600, 24);
    for (int b = 0; b < 3; ++b) {
        plane_checks(r[b], w, h);
        radius_checks(r[b], w, h);
        invariance_checks(r[b], w, h);
        window_checks(r[b], w, h);
    }
    /* a bad request: one line, nothing computed */
    hfs_error err = {""};
    float one;
    const hfs_horizon_desc bad = {.n_azimuths = 0, .azimuth = azimuths};
    float zz[4] = {0};
    const hfs_field tiny = {2, 2, zz, 1.0, 1.0};
    CHECK(hfs_renderer_horizons(r[1], &tiny, NULL, &bad, &one, &err) == HFS_E_INVALID &&
              strstr(err.msg, "0 azimuths"),
          "no azimuths: %s", err.msg);
    for (int b = 0; b < 3; ++b)
        hfs_renderer_destroy(r[b]);
    printf("%s: %ld checks, %d failures\n", failures ? "FAIL" : "PASS", checks, failures);
    return failures ? 1 : 0;
}
