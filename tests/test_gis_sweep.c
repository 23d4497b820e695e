/*
 * test_gis_sweep.c — the GIS horizons' sweep (tools/gis/gis_sweep.h;
 * `--method sweep`), no GDAL, no GL:
 *   axes      an azimuth along the grid's axes follows rows or columns:
 *             there the lines are the rays, and every angle equals the
 *             CPU backend's exact one (hfs_renderer_horizons, the bilinear
 *             surface's supremum) to rounding;
 *   oblique   oblique azimuths on a non-square field with dx != 1 and a
 *             zscale, terrain-like ridges and texel-scale relief: against
 *             the exact horizons, mean and worst error in degrees within
 *             bounds 1.2x what was measured on these fields (the sweep
 *             reads up to half a texel aside beyond GIS_SWEEP_NEAR
 *             columns);
 *   between   tops between the columns' crossings: saddles along the
 *             diagonals, ridges along rows, each within bounds; closed
 *             forms of one twisted cell (near and far) and one ridge;
 *   dome      a profile concave along every line: more hull points than
 *             the line has columns (the hull's storage, under ASan);
 *   turn      the field turned a quarter (and mirrored), the azimuth with
 *             it: the same angles, bit for bit (the lines turn with it);
 *   threads   1 and 3 workers: the same angles, bit for bit; and each
 *             azimuth alone, its lines in parts among 3 or 7 workers;
 *   window    angles wanted in [lo, hi] only (a sun's disk): the clamp of
 *             the whole sweep's, bit for bit, though a high sun's lines
 *             skip what their bounds say cannot reach the window; a
 *             plane rising across the lines, where a line's offset from
 *             the texel's ray decides;
 *   refused   a non-finite azimuth, a field without heights.
 */
#include "check.h"
#include "gis_sweep.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define DEG (180.0 / PI)

/* 1.2x the errors measured on these fields (degrees; docs/GIS.md) */
#define BOUND_RIDGES_MEAN 0.311   /* measured 0.2593 */
#define BOUND_RIDGES_WORST 13.2   /* 11.02 */
#define BOUND_ROUGH_MEAN 0.383    /* 0.3188 */
#define BOUND_ROUGH_WORST 27.6    /* 23.04 */
#define BOUND_SADDLES_MEAN 0.0006 /* 0.0005 */
#define BOUND_SADDLES_WORST 0.052 /* 0.043 */
#define BOUND_ROWS_MEAN 0.716     /* 0.5965 */
#define BOUND_ROWS_WORST 16.1     /* 13.41 */
#define BOUND_DOME_MEAN 0.171     /* 0.1427 */
#define BOUND_DOME_WORST 6.81     /* 5.679 */

/* Two ridges and texel-scale noise of amplitude `noise`, W x H. */
static float *field_of(int w, int h, unsigned seed, double noise)
{
    float *z = malloc((size_t)w * (size_t)h * sizeof *z);
    srand(seed);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            z[(size_t)j * w + i] = (float)(30.0 * exp(-pow((i - 0.3 * w) / 6.0, 2.0)) +
                                           20.0 * exp(-pow((j - 0.6 * h) / 4.0, 2.0)) +
                                           noise * rand() / (double)RAND_MAX);
    return z;
}

/* The CPU backend's exact horizons (hfs_renderer_horizons) of field f
 * for n azimuths, into exact (n x W x H). */
static void exact_horizons(const hfs_field *f, const double *phi, int n, float *exact)
{
    hfs_renderer *r = NULL;
    hfs_error err;
    const hfs_renderer_desc desc = {.backend = HFS_BACKEND_CPU};
    const hfs_horizon_desc hd = {.n_azimuths = n, .azimuth = phi};
    CHECK(hfs_renderer_create(&desc, &r, &err) == HFS_OK &&
              hfs_renderer_horizons(r, f, NULL, &hd, exact, &err) == HFS_OK,
          "exact: %s", err.msg);
    hfs_renderer_destroy(r);
}

/* Mean and worst |a - b| over n values, degrees (NONE against NONE: 0). */
static void error_deg(const float *a, const float *b, size_t n, double *mean, double *worst)
{
    double sum = 0.0;
    *worst = 0.0;
    for (size_t p = 0; p < n; ++p) {
        const double e = a[p] == b[p] ? 0.0 : fabs((double)a[p] - b[p]) * DEG;
        sum += e;
        *worst = fmax(*worst, e);
    }
    *mean = sum / (double)n;
}

/* The sweep against the exact horizons on field f: bounds on the mean
 * and worst error (degrees), and whether the axes must match to rounding. */
static void check_against_exact(const char *name, const hfs_field *f, const double *phi, int n,
                                double max_mean, double max_worst)
{
    const size_t texels = (size_t)f->width * f->height;
    float *sweep = malloc((size_t)n * texels * sizeof *sweep);
    float *exact = malloc((size_t)n * texels * sizeof *exact);
    hfs_error err;
    CHECK(gis_sweep_horizons(f, phi, n, 0, sweep, &err) == HFS_OK, "%s: %s", name, err.msg);
    exact_horizons(f, phi, n, exact);
    double mean, worst;
    error_deg(sweep, exact, (size_t)n * texels, &mean, &worst);
    printf("%s: against the exact horizons, mean %.4f deg, worst %.3f deg\n", name, mean, worst);
    CHECK(mean <= max_mean && worst <= max_worst, "%s: mean %.4f deg (at most %.4f), worst %.3f "
          "deg (at most %.3f)", name, mean, max_mean, worst, max_worst);
    free(sweep);
    free(exact);
}

/* Along the axes the lines are the rays and the sweep is exact: the near
 * columns in closed form, the rest on the ray's own line. */
static void check_axes(void)
{
    const int w = 37, h = 23;
    float *z = field_of(w, h, 1, 8.0);
    const hfs_field f = {.width = w, .height = h, .z = z, .dx = 7.0, .zscale = 1.5};
    const double phi[4] = {0.0, PI / 2, PI, -PI / 2};
    check_against_exact("axes", &f, phi, 4, 1e-4, 1e-3);
    free(z);
}

/* Oblique azimuths, a non-square field, dx != 1, a zscale: terrain-like
 * (ridges, little noise) and texel-scale relief. */
static void check_oblique(void)
{
    const int w = 61, h = 45, n = 8;
    double phi[8];
    for (int k = 0; k < n; ++k)
        phi[k] = 0.37 + k * 2.0 * PI / n; /* none along an axis */
    float *z = field_of(w, h, 2, 0.4);
    const hfs_field smooth = {.width = w, .height = h, .z = z, .dx = 2.5, .zscale = 0.8};
    check_against_exact("ridges", &smooth, phi, n, BOUND_RIDGES_MEAN, BOUND_RIDGES_WORST);
    free(z);
    z = field_of(w, h, 2, 8.0);
    const hfs_field rough = {.width = w, .height = h, .z = z, .dx = 2.5, .zscale = 0.8};
    check_against_exact("rough", &rough, phi, n, BOUND_ROUGH_MEAN, BOUND_ROUGH_WORST);
    free(z);
}

/* Fields whose tops lie between the crossings with the columns: saddles
 * (a checkerboard over the field's right half, flat ground left of it:
 * along a diagonal each cell bulges to half its height between corners
 * of height 0) seen along the diagonals, and ridges one
 * row wide every 7 rows crossed at a slope of 1/2 (their tops where the
 * line crosses the row, between two columns). */
static void check_between(void)
{
    const int w = 48, h = 40;
    float *z = malloc((size_t)w * h * sizeof *z);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            z[(size_t)j * w + i] = (float)(i >= w / 2 && (i + j) % 2 ? 3.0 + 0.01 * i : 0.0);
    const hfs_field saddles = {.width = w, .height = h, .z = z, .dx = 1.0, .zscale = 1.0};
    const double diag[2] = {PI / 4, -3 * PI / 4};
    check_against_exact("saddles", &saddles, diag, 2, BOUND_SADDLES_MEAN, BOUND_SADDLES_WORST);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            z[(size_t)j * w + i] = (float)(j % 7 == 3 ? 5.0 + 0.05 * i : 0.02 * i);
    const hfs_field ridges = {.width = w, .height = h, .z = z, .dx = 2.0, .zscale = 1.0};
    const double half[2] = {atan(0.5), PI + atan(0.5)};
    check_against_exact("row ridges", &ridges, half, 2, BOUND_ROWS_MEAN, BOUND_ROWS_WORST);
    free(z);
}

/* One texel's angle against its closed form: a saddle cell (corners 0,
 * H, H, 0) crossed corner to corner along the diagonal, within the near
 * columns (at column 3) and beyond them on the texel's own line (at
 * column 10): the surface bulges to H/2 at the cell's middle (between
 * crossings; the tangent meets it there to 1e-3); a ridge one row wide
 * crossed between two columns at a slope of 0.4 (its top on the row, where
 * the columns' crossings stand at 0.8 H). */
static void check_closed_forms(void)
{
    enum { W = 16, H = 12 };
    static float z[W * H];
    const double top = 4.0, dx = 2.0;
    const hfs_field f = {.width = W, .height = H, .z = z, .dx = dx, .zscale = 1.0};
    float out[W * H];
    hfs_error err;
    const int at[2] = {3, 10};
    for (int c = 0; c < 2; ++c) {
        memset(z, 0, sizeof z);
        const int x = at[c];
        z[x * W + x + 1] = z[(x + 1) * W + x] = (float)top; /* (x+1, x), (x, x+1) */
        const double phi = PI / 4;
        CHECK(gis_sweep_horizons(&f, &phi, 1, 1, out, &err) == HFS_OK, "saddle: %s", err.msg);
        /* from (1, 1): the bulge's top at (x + 1/2, x + 1/2), the best
         * point at a* = sqrt(m^2 + m) - m of the cell, m = x - 1 */
        const double m = x - 1, a = sqrt(m * m + m) - m;
        const double want = atan(2.0 * top * a * (1.0 - a) / ((m + a) * dx * sqrt(2.0)));
        const double got = out[1 * W + 1];
        CHECK(fabs(got - want) <= (c == 0 ? 1e-6 : 1e-3 * want), "saddle at column %d: %.7f "
              "rad, the closed form %.7f", x, got, want);
    }
    memset(z, 0, sizeof z);
    for (int i = 0; i < W; ++i)
        z[5 * W + i] = (float)top; /* row 5 */
    const double phi = atan(0.4);
    CHECK(gis_sweep_horizons(&f, &phi, 1, 1, out, &err) == HFS_OK, "ridge: %s", err.msg);
    /* from (0, 2): row 5 crossed at column 7.5 */
    const double want = atan(top / (7.5 * dx * sqrt(1.0 + 0.16)));
    CHECK(fabs(out[2 * W] - want) <= 1e-6, "ridge: %.7f rad, the closed form %.7f",
          (double)out[2 * W], want);
    /* the same ridge within the near columns, its top where the ray
     * crosses the row: from (0, 3) at 0.8 rows a column, row 4 at column
     * 1.25 and row 5 at column 2.5, the chord's slope rising to the
     * crossing (top / 2.5 a column) and falling after it */
    const double steep = atan(0.8);
    CHECK(gis_sweep_horizons(&f, &steep, 1, 1, out, &err) == HFS_OK, "near ridge: %s", err.msg);
    const double near_want = atan(top / (2.5 * dx * sqrt(1.0 + 0.64)));
    CHECK(fabs(out[3 * W] - near_want) <= 1e-6, "near ridge: %.7f rad, the closed form %.7f",
          (double)out[3 * W], near_want);
}

/* A dome (z = -(i - W/2)^2 / 100 - j^2 / 20), concave along every line:
 * each crossing with a column and a row stays on the upper hull, more
 * points than the line has columns (the hull's storage, under the
 * sanitizers), and the angles within the bounds measured. */
static void check_dome(void)
{
    const int w = 300, h = 12;
    float *z = malloc((size_t)w * h * sizeof *z);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            z[(size_t)j * w + i] = (float)(-0.01 * (i - w / 2) * (i - w / 2) - 0.05 * j * j);
    const hfs_field f = {.width = w, .height = h, .z = z, .dx = 1.0, .zscale = 1.0};
    const double phi[2] = {atan(0.035), PI + atan(0.035)}; /* 10 rows over 300 columns */
    check_against_exact("dome", &f, phi, 2, BOUND_DOME_MEAN, BOUND_DOME_WORST);
    free(z);
}

/* A quarter turn of field f: (i, j) -> (H - 1 - j, i), W and H swapped. */
static float *turned(const hfs_field *f)
{
    float *t = malloc((size_t)f->width * f->height * sizeof *t);
    for (int j = 0; j < f->height; ++j)
        for (int i = 0; i < f->width; ++i)
            t[(size_t)i * f->height + (f->height - 1 - j)] = f->z[(size_t)j * f->width + i];
    return t;
}

/* Turned a quarter, and mirrored across x, with the azimuths: the same
 * angles, bit for bit; 1 and 3 threads alike. */
static void check_turns_threads(void)
{
    const int w = 29, h = 19, n = 5;
    float *z = field_of(w, h, 3, 8.0);
    const hfs_field f = {.width = w, .height = h, .z = z, .dx = 3.0, .zscale = 1.0};
    double phi[5], phi_t[5], phi_m[5];
    for (int k = 0; k < n; ++k) {
        phi[k] = 0.2 + 1.3 * k;
        phi_t[k] = phi[k] + PI / 2; /* (x, y) -> (-y, x) turns phi by a quarter */
        phi_m[k] = PI - phi[k];     /* x -> W - 1 - x */
    }
    const size_t texels = (size_t)w * h;
    float *a = malloc(n * texels * sizeof *a), *b = malloc(n * texels * sizeof *b);
    float *c = malloc(n * texels * sizeof *c);
    hfs_error err;
    float *zt = turned(&f);
    const hfs_field ft = {.width = h, .height = w, .z = zt, .dx = 3.0, .zscale = 1.0};
    float *zm = malloc(texels * sizeof *zm);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            zm[(size_t)j * w + (w - 1 - i)] = z[(size_t)j * w + i];
    const hfs_field fm = {.width = w, .height = h, .z = zm, .dx = 3.0, .zscale = 1.0};
    CHECK(gis_sweep_horizons(&f, phi, n, 1, a, &err) == HFS_OK &&
              gis_sweep_horizons(&f, phi, n, 3, b, &err) == HFS_OK,
          "threads: %s", err.msg);
    CHECK(!memcmp(a, b, n * texels * sizeof *a), "threads: 1 and 3 workers differ");
    /* one azimuth at a time: its lines in parts among the workers (7
     * workers: more parts than this field has lines) */
    long alone_diff = 0;
    for (int k = 0; k < n; ++k)
        for (int t = 3; t <= 7; t += 4) {
            CHECK(gis_sweep_horizons(&f, &phi[k], 1, t, c, &err) == HFS_OK, "alone: %s", err.msg);
            alone_diff += memcmp(a + (size_t)k * texels, c, texels * sizeof *c) != 0;
        }
    CHECK(alone_diff == 0, "threads: %ld azimuths alone differ from all at once", alone_diff);
    CHECK(gis_sweep_horizons(&ft, phi_t, n, 2, c, &err) == HFS_OK, "turn: %s", err.msg);
    long turn_diff = 0, mirror_diff = 0;
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i)
                turn_diff += a[((size_t)k * h + j) * w + i] !=
                             c[((size_t)k * w + i) * h + (h - 1 - j)];
    CHECK(gis_sweep_horizons(&fm, phi_m, n, 2, c, &err) == HFS_OK, "mirror: %s", err.msg);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i)
                mirror_diff += a[((size_t)k * h + j) * w + i] !=
                               c[((size_t)k * h + j) * w + (w - 1 - i)];
    CHECK(turn_diff == 0 && mirror_diff == 0, "turn: %ld angles differ; mirror: %ld", turn_diff,
          mirror_diff);
    free(a), free(b), free(c), free(z), free(zt), free(zm);
}

/* A window [lo, hi] (a sun's disk, a wider one, one at the field's
 * top): each angle the clamp of the whole sweep's, bit for bit, lo where
 * the ray meets nothing, though the hull's texels above hi skip their own
 * columns and the others their arctangent. */
static void check_window(void)
{
    const int w = 61, h = 47, n = 5;
    float *z = field_of(w, h, 7u, 2.0);
    const hfs_field f = {.width = w, .height = h, .z = z, .dx = 2.5, .zscale = 1.3};
    const double phi[5] = {0.3, 1.2, 2.9, 4.0, 5.5};
    /* suns at 17 to 69 degrees (lines that skip their hull, their own
     * columns or both: line_bounds), a wide window, one at the top */
    const double win[5][2] = {{0.30, 0.31}, {0.7, 0.71}, {1.0, 1.01}, {-0.2, 0.6}, {1.2, PI / 2}};
    const size_t all = (size_t)n * w * h;
    float *a = malloc(all * sizeof *a), *b = malloc(all * sizeof *b);
    hfs_error err;
    CHECK(gis_sweep_horizons(&f, phi, n, 2, a, &err) == HFS_OK, "window: %s", err.msg);
    for (int k = 0; k < 5; ++k) {
        const double lo = win[k][0], hi = win[k][1];
        CHECK(gis_sweep_horizons_in(&f, phi, n, 2, lo, hi, b, &err) == HFS_OK, "window: %s",
              err.msg);
        long differ = 0, inside = 0;
        for (size_t p = 0; p < all; ++p) {
            const float want = a[p] < lo ? (float)lo : a[p] > hi ? (float)hi : a[p];
            differ += b[p] != want;
            inside += a[p] > lo && a[p] < hi;
        }
        CHECK(differ == 0 && inside > 0, "window [%g, %g]: %ld of %zu angles differ (%ld inside)",
              lo, hi, differ, all, inside);
    }
    CHECK(gis_sweep_horizons_in(&f, phi, n, 1, 0.5, 0.4, b, &err) == HFS_E_INVALID,
          "window: lo above hi refused");
    free(a), free(b), free(z);
    /* one row, one column, one cell: the bounds' bands clamp to the field */
    const int thin[4][2] = {{1, 9}, {9, 1}, {2, 2}, {3, 17}};
    for (int t = 0; t < 4; ++t) {
        const int tw = thin[t][0], th = thin[t][1];
        float *tz = field_of(tw, th, 11u + (unsigned)t, 3.0);
        const hfs_field ft = {.width = tw, .height = th, .z = tz, .dx = 1.0, .zscale = 1.0};
        const size_t tn = (size_t)n * tw * th;
        float *ta = malloc(tn * sizeof *ta), *tb = malloc(tn * sizeof *tb);
        long differ = 0;
        for (int k = 0; k < 5; ++k) {
            const double lo = win[k][0], hi = win[k][1];
            CHECK(gis_sweep_horizons(&ft, phi, n, 2, ta, &err) == HFS_OK &&
                      gis_sweep_horizons_in(&ft, phi, n, 2, lo, hi, tb, &err) == HFS_OK,
                  "window %dx%d: %s", tw, th, err.msg);
            for (size_t p = 0; p < tn; ++p)
                differ += tb[p] != (ta[p] < lo ? (float)lo : ta[p] > hi ? (float)hi : ta[p]);
        }
        CHECK(differ == 0, "window %dx%d: %ld angles differ from the clamp", tw, th, differ);
        free(ta), free(tb), free(tz);
    }
}

/* A plane rising across the lines (z = y) seen along an azimuth 1 in 20
 * off the x axis: the texels' own rays rise 0.05 a column, under a sun
 * with tan(lo) = 0.1 (their own columns skipped), but a line half a row
 * uphill of a texel's ray shows it a hull up to 0.05 + 0.5 / 4 a column:
 * the hull's offset from the ray is what decides these texels, and the
 * window's values must still be the whole sweep's clamped. */
static void check_cross_slope(void)
{
    const int w = 80, h = 40, n = 4;
    float *z = malloc((size_t)w * h * sizeof *z);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            z[(size_t)j * w + i] = (float)j;
    const hfs_field f = {.width = w, .height = h, .z = z, .dx = 1.0, .zscale = 1.0};
    const double a = atan(0.05), phi[4] = {a, -a, PI - a, PI + a};
    const double lo = atan(0.1), hi = lo + 0.05;
    const size_t all = (size_t)n * w * h;
    float *full = malloc(all * sizeof *full), *win = malloc(all * sizeof *win);
    hfs_error err;
    CHECK(gis_sweep_horizons(&f, phi, n, 2, full, &err) == HFS_OK &&
              gis_sweep_horizons_in(&f, phi, n, 2, lo, hi, win, &err) == HFS_OK,
          "cross slope: %s", err.msg);
    long differ = 0, inside = 0;
    for (size_t p = 0; p < all; ++p) {
        const float want = full[p] < lo ? (float)lo : full[p] > hi ? (float)hi : full[p];
        differ += win[p] != want;
        inside += full[p] > lo && full[p] < hi;
    }
    CHECK(differ == 0 && inside > 0, "cross slope: %ld of %zu angles differ (%ld inside)", differ,
          all, inside);
    free(z), free(full), free(win);
}

static void check_refused(void)
{
    float z[4] = {0};
    const hfs_field f = {.width = 2, .height = 2, .z = z, .dx = 1.0, .zscale = 1.0};
    const hfs_field none = {.width = 2, .height = 2, .z = NULL, .dx = 1.0, .zscale = 1.0};
    const double bad = NAN, good = 0.5;
    float out[4];
    hfs_error err;
    CHECK(gis_sweep_horizons(&f, &bad, 1, 1, out, &err) == HFS_E_INVALID &&
              strstr(err.msg, "azimuth 0"),
          "refused: a NaN azimuth (%s)", err.msg);
    CHECK(gis_sweep_horizons(&none, &good, 1, 1, out, &err) == HFS_E_INVALID,
          "refused: no heights");
}

int main(void)
{
    check_axes();
    check_oblique();
    check_between();
    check_closed_forms();
    check_dome();
    check_turns_threads();
    check_window();
    check_cross_slope();
    check_refused();
    printf("test_gis_sweep: %ld checks, %d failures\n", checks, failures);
    return failures != 0;
}
