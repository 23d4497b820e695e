/*
 * test_ray_bound.c — the gap search's max pyramid and search
 * (runtime/core/ray_bound.h) against brute force:
 *   1. every box of grid points: the one read hfs_ray_bound_level picks is
 *      at least the box's largest height (the bound is conservative) and,
 *      for boxes within one 2x2 block of level 1, at most its block's;
 *   2. random fields (narrow posts, walls one texel wide, noise), random
 *      receivers and directions (axis-aligned, diagonal, any): the search
 *      returns max(start, every crossing's slope) computed crossing by
 *      crossing, whatever the start, and its distance; t_first skips the
 *      crossings before it;
 *   3. a post one texel wide 200 texels away is found, with few reads;
 *   4. hfs_ray_bound_search_cells on the same fields: the supremum of
 *      the bilinear surface's slopes along the ray, against a numerical
 *      one (the ray cut at every grid line of both axes, a ternary
 *      search on each piece; within 1e-12 relative: rounding, measured
 *      4e-14); the crossings alone fall short of it on about a fifth of
 *      the rays (the twisted cells this search solves), and a cell
 *      passed diagonally past its one raised corner is found at its
 *      inner peak where every crossing sees 0.  From t_first itself
 *      (past crossing 1): a search continued from where another stopped
 *      gives what one search over both gives, with no gap before the
 *      second one's first crossing.
 */
#include "ray_bound.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static int failures;
#define CHECK(c, ...)                                                                        \
    do {                                                                                     \
        if (!(c)) {                                                                          \
            fprintf(stderr, "FAIL %s:%d: ", __FILE__, __LINE__);                             \
            fprintf(stderr, __VA_ARGS__);                                                    \
            fputc('\n', stderr);                                                             \
            ++failures;                                                                      \
        }                                                                                    \
    } while (0)

static unsigned rng = 12345u;
static double urand(void)
{
    rng = rng * 1664525u + 1013904223u;
    return (rng >> 8) / 16777216.0;
}

/* A field of noise, posts and one-texel walls on a plane tilted by
 * (tx, ty) per texel, plus (wave) waves whose valleys a receiver looks
 * across: slopes that are all negative and grow
 * with distance, so that a run below the receiver holds its largest slope
 * at its far end. */
static void make_field(float *z, int w, int h, double tx, double ty, int wave)
{
    for (int t = 0; t < w * h; ++t) {
        const int i = t % w, j = t / w;
        z[t] = (float)(0.3 * urand() + tx * i + ty * j);
        if (wave)
            z[t] += (float)(5.0 * (sin(i * 0.21) * cos(j * 0.17) + 0.5 * sin(i * 0.53 + j * 0.71)));
    }
    for (int p = 0; p < 6; ++p) {
        const int x = (int)(urand() * w), y = (int)(urand() * h);
        z[y * w + x] = (float)(5.0 + 20.0 * urand());
    }
    const int wx = (int)(urand() * w);
    for (int y = 0; y < h; ++y)
        z[y * w + wx] += 3.0f;
}

static double bound_read(const hfs_ray_bound_layout *L, const double *atlas, int x0, int x1,
                         int y0, int y1)
{
    const int l = hfs_ray_bound_level(x0, x1, y0, y1);
    if (l < 1 || l >= L->n_levels)
        return -HUGE_VAL;
    return atlas[(size_t)(L->y0[l] + (y0 >> l)) * L->aw + (size_t)(L->x0[l] + (x0 >> l))];
}

static void check_boxes(const float *z, int w, int h, const hfs_ray_bound_layout *L,
                        const double *atlas)
{
    long boxes = 0;
    for (int x0 = 0; x0 < w; x0 += 3)
        for (int x1 = x0; x1 < w; x1 += 2)
            for (int y0 = 0; y0 < h; y0 += 5)
                for (int y1 = y0; y1 < h; y1 += 3) {
                    double m = -HUGE_VAL;
                    for (int y = y0; y <= y1; ++y)
                        for (int x = x0; x <= x1; ++x)
                            m = fmax(m, z[y * w + x]);
                    const double b = bound_read(L, atlas, x0, x1, y0, y1);
                    CHECK(b >= m, "box [%d,%d]x[%d,%d]: bound %g below max %g", x0, x1, y0, y1,
                          b, m);
                    ++boxes;
                }
    CHECK(boxes >= (long)((w + 2) / 3) * ((h + 4) / 5), "only %ld boxes", boxes);
    /* level 1 is tight: a 4x4 block of points at even corners is one read */
    for (int y0 = 0; y0 + 3 < h; y0 += 2)
        for (int x0 = 0; x0 + 3 < w; x0 += 2) {
            double m = -HUGE_VAL;
            for (int y = y0; y < y0 + 4; ++y)
                for (int x = x0; x < x0 + 4; ++x)
                    m = fmax(m, z[y * w + x]);
            CHECK(bound_read(L, atlas, x0, x0 + 3, y0, y0 + 3) == m, "level 1 at %d,%d not tight",
                  x0, y0);
        }
}

/* Brute force: the slope of every crossing from (i, j) in (c, s) at
 * distance >= t_first and <= t_last, as ray_bound.h defines them, nearest first; returns
 * the max of best and those, *dist the distance of the crossing that leads
 * (taking the lead past the relative tie). */
static double brute(const double *zd, int w, int h, int i, int j, double c, double s,
                    double t_first, double t_last, double zs, double best, double *dist)
{
    const int xm = fabs(c) >= fabs(s);
    const double ma = xm ? c : s, mi = xm ? s : c, inv = 1.0 / fabs(ma), r = mi / fabs(ma);
    const int step = ma >= 0 ? 1 : -1, p = xm ? i : j, q = xm ? j : i, np = xm ? w : h,
              nq = xm ? h : w;
    double lead = best;
    for (int m = 1;; ++m) {
        const int x = p + step * m;
        double y = q + m * r;
        if (x < 0 || x > np - 1 || y < -1e-3 || y > nq - 1 + 1e-3 || m > t_last / inv + 1e-4)
            break;
        if (m < t_first / inv - 1e-4)
            continue;
        y = fmin(fmax(y, 0.0), nq - 1);
        int y0 = (int)floor(y);
        if (y0 > nq - 2)
            y0 = nq >= 2 ? nq - 2 : 0;
        const double f = y - y0;
        const double a = xm ? zd[y0 * w + x] : zd[x * w + y0];
        const double b = nq >= 2 ? (xm ? zd[(y0 + 1) * w + x] : zd[x * w + y0 + 1]) : a;
        const double sl = (a + f * (b - a) - zd[j * w + i]) * zs / (m * inv);
        if (sl > lead + 1e-5 * fabs(lead)) { /* the horizons' tie (HFS_HORIZON_TIE) */
            lead = sl;
            *dist = m * inv;
        }
        best = sl > best ? sl : best;
    }
    return best;
}

/* A field of make_field's, in float and double, with its bounds. */
typedef struct fixture {
    float *z;
    double *zd, *atlas, *scr;
    hfs_ray_bound_layout L;
} fixture;

static void fixture_make(fixture *F, int w, int h, double tx, double ty, int wave)
{
    F->z = malloc((size_t)w * h * sizeof *F->z);
    F->zd = malloc((size_t)w * h * sizeof *F->zd);
    make_field(F->z, w, h, tx, ty, wave);
    for (int t = 0; t < w * h; ++t)
        F->zd[t] = F->z[t];
    hfs_ray_bound_layout_make(w, h, &F->L);
    F->atlas = malloc((size_t)F->L.aw * F->L.ah * sizeof *F->atlas);
    F->scr = malloc(2 * (size_t)F->L.lw[1] * F->L.lh[1] * sizeof *F->scr);
    hfs_ray_bound_build(&F->L, F->z, 0.0, 1.0, -HUGE_VAL, F->atlas, F->scr);
}

static void fixture_free(fixture *F)
{
    free(F->z), free(F->zd), free(F->atlas), free(F->scr);
}

static void check_search(int w, int h, int trials, double tx, double ty, int wave)
{
    fixture F;
    fixture_make(&F, w, h, tx, ty, wave);
    const hfs_ray_bound_layout L = F.L;
    const double *zd = F.zd, *atlas = F.atlas;
    check_boxes(F.z, w, h, &L, atlas);
    static const double fixed[] = {0.0, 90.0, 180.0, 270.0, 45.0, 135.0, 225.0, 315.0, 30.0};
    long reads = 0;
    for (int k = 0; k < trials; ++k) {
        const int i = (int)(urand() * w), j = (int)(urand() * h);
        const double deg = k < 9 ? fixed[k] : 360.0 * urand();
        const double rad = deg * 3.14159265358979323846 / 180.0;
        double c = cos(rad), s = sin(rad);
        c = fabs(c) < 1e-12 ? 0.0 : c;
        s = fabs(s) < 1e-12 ? 0.0 : s;
        const double zs = 0.5 + urand(), t_first = k % 3 == 0 ? 10.0 * urand() : 0.0;
        /* every fifth search ends short of the grid's edge (a key light's
         * per-texel search stops where the grid's starts) */
        const double t_last = k % 5 == 1 ? t_first + 1.0 + 30.0 * urand() : HUGE_VAL;
        const double start = k % 2 ? -1e30 : 0.2 * urand() - 0.1;
        double d_b = -1.0, d_s = -1.0;
        const double want = brute(zd, w, h, i, j, c, s, t_first, t_last, zs, start, &d_b);
        const double got = hfs_ray_bound_search(&L, atlas, zd, (size_t)w, i, j, c, s, t_first,
                                                t_last, zs, 0.0, start, &d_s, &reads);
        CHECK(got == want && d_s == d_b, "%dx%d (%d,%d) at %g deg from %g to %g: %.17g (d %g), "
              "brute force %.17g (d %g)", w, h, i, j, deg, t_first, t_last, got, d_s, want, d_b);
    }
    fixture_free(&F);
}

/* One post one texel wide, 200 texels down a flat row: found, at its
 * distance, in a few dozen reads rather than 200. */
static void check_post(void)
{
    const int w = 300, h = 9;
    float *z = calloc((size_t)w * h, sizeof *z);
    double *zd = calloc((size_t)w * h, sizeof *zd);
    z[4 * w + 250] = 10.0f;
    zd[4 * w + 250] = 10.0;
    hfs_ray_bound_layout L;
    hfs_ray_bound_layout_make(w, h, &L);
    double *atlas = malloc((size_t)L.aw * L.ah * sizeof *atlas);
    double *scr = malloc(2 * (size_t)L.lw[1] * L.lh[1] * sizeof *scr);
    hfs_ray_bound_build(&L, z, 0.0, 1.0, -HUGE_VAL, atlas, scr);
    double d = 0.0;
    long reads = 0;
    const double sl = hfs_ray_bound_search(&L, atlas, zd, (size_t)w, 50, 4, 1.0, 0.0, 0.0,
                                           HUGE_VAL, 1.0, 0.0, 0.0, &d, &reads);
    CHECK(sl == 10.0 / 200.0 && d == 200.0, "post: slope %g at %g", sl, d);
    CHECK(reads < 60, "post: %ld reads", reads);
    /* missed off its row: the post lies one row beside the ray */
    d = 0.0;
    const double off = hfs_ray_bound_search(&L, atlas, zd, (size_t)w, 50, 3, 1.0, 0.0, 0.0,
                                            HUGE_VAL, 1.0, 0.0, 0.0, &d, NULL);
    CHECK(off == 0.0 && d == 0.0, "post beside the ray: slope %g", off);
    printf("post 200 texels away: %ld reads\n", reads);
    free(z), free(zd), free(atlas), free(scr);
}

/* The bilinear surface at (x, y) inside the grid (SPEC's surface). */
static double surface(const double *zd, int w, int h, double x, double y)
{
    x = fmin(fmax(x, 0.0), w - 1.0), y = fmin(fmax(y, 0.0), h - 1.0);
    int i = (int)floor(x), j = (int)floor(y);
    i = i > w - 2 ? (w >= 2 ? w - 2 : 0) : i;
    j = j > h - 2 ? (h >= 2 ? h - 2 : 0) : j;
    const double fx = x - i, fy = y - j;
    const int i1 = w >= 2 ? i + 1 : i, j1 = h >= 2 ? j + 1 : j;
    const double a = zd[j * w + i] + fx * (zd[j * w + i1] - zd[j * w + i]);
    const double b = zd[j1 * w + i] + fx * (zd[j1 * w + i1] - zd[j1 * w + i]);
    return a + fy * (b - a);
}

/* The slope of the surface point u crossings along the ray. */
typedef struct ray_pts {
    const double *zd;
    int w, h, xm, step, p, q;
    double r, inv, zs, z0;
} ray_pts;

static double ray_slope(const ray_pts *R, double u)
{
    const double mj = R->p + R->step * u, mn = R->q + u * R->r;
    const double v = R->xm ? surface(R->zd, R->w, R->h, mj, mn)
                           : surface(R->zd, R->w, R->h, mn, mj);
    return (v - R->z0) * R->zs / (u * R->inv);
}

/* The supremum along the ray from the first crossing at t >= t_first to
 * t_last or the grid's edge, found numerically: the ray cut at every grid
 * line it crosses (both axes), on each piece one bilinear cell's quadratic
 * over the distance, whose slope z / t has g' = gamma - alpha / t^2, so at
 * most one stationary point: the piece's ends and a ternary search (exact
 * for a peak, and only ever a surface point otherwise); with brute()'s
 * crossings (their edge tolerance). */
static double sampled(const double *zd, int w, int h, int i, int j, double c, double s,
                      double t_first, double t_last, double zs, double best)
{
    double d = 0.0;
    best = brute(zd, w, h, i, j, c, s, t_first, t_last, zs, best, &d);
    const int xm = fabs(c) >= fabs(s);
    const double ma = xm ? c : s, mi = xm ? s : c, inv = 1.0 / fabs(ma), r = mi / fabs(ma);
    const int step = ma >= 0 ? 1 : -1, p = xm ? i : j, q = xm ? j : i, np = xm ? w : h,
              nq = xm ? h : w;
    const ray_pts R = {zd, w, h, xm, step, p, q, r, inv, zs, zd[j * w + i]};
    /* from t_first itself past crossing 1 (the receiver's own cell peaks at
     * an end: the first crossing, or the caller's near end) */
    const double uf = t_first / inv, m_first = fmax(1.0, ceil(uf - 1e-4));
    const double u0 = m_first >= 2.0 && m_first - uf > 1e-4 ? uf : m_first;
    double u1 = fmin(t_last / inv, step > 0 ? np - 1 - p : p);
    if (r != 0.0)
        u1 = fmin(u1, r > 0.0 ? (nq - 1 - q) / r : q / -r);
    for (double lo = u0; lo < u1;) {
        /* the next grid line: a crossing, or a minor line */
        double hi = fmin(u1, floor(lo) + 1.0);
        if (r != 0.0) {
            const double y = q + lo * r, next = r > 0.0 ? floor(y) + 1.0 : ceil(y) - 1.0;
            hi = fmin(hi, (next - q) / r);
        }
        if (!(hi > lo)) /* at a line, rounding: step past it */
            hi = fmin(u1, lo + 1e-9);
        double a = lo, b = hi;
        for (int it = 0; it < 200; ++it) {
            const double m1 = a + (b - a) / 3.0, m2 = b - (b - a) / 3.0;
            if (ray_slope(&R, m1) < ray_slope(&R, m2))
                a = m1;
            else
                b = m2;
        }
        const double ends = fmax(ray_slope(&R, lo), ray_slope(&R, hi));
        best = fmax(best, fmax(ends, ray_slope(&R, 0.5 * (a + b))));
        lo = hi;
    }
    return best;
}

static void check_cells(int w, int h, int trials, double tx, double ty, int wave)
{
    fixture F;
    fixture_make(&F, w, h, tx, ty, wave);
    const hfs_ray_bound_layout L = F.L;
    const double *zd = F.zd, *atlas = F.atlas;
    long reads[2] = {0, 0}, short_of = 0;
    double worst_below = 0.0, worst_above = 0.0;
    for (int k = 0; k < trials; ++k) {
        const int i = (int)(urand() * w), j = (int)(urand() * h);
        const double deg = 360.0 * urand();
        const double rad = deg * 3.14159265358979323846 / 180.0;
        double c = cos(rad), s = sin(rad);
        const double zs = 0.5 + urand(), t_first = k % 3 == 0 ? 10.0 * urand() : 0.0;
        const double t_last = k % 5 == 1 ? t_first + 1.0 + 30.0 * urand() : HUGE_VAL;
        const double start = k % 2 ? -1e30 : 0.2 * urand() - 0.1;
        double d = 0.0;
        const double got = hfs_ray_bound_search_cells(&L, atlas, zd, (size_t)w, i, j, c, s,
                                                      t_first, t_last, zs, 0.0, start, &d,
                                                      &reads[0]);
        const double old = hfs_ray_bound_search(&L, atlas, zd, (size_t)w, i, j, c, s, t_first,
                                                t_last, zs, 0.0, start, &d, &reads[1]);
        const double want = sampled(zd, w, h, i, j, c, s, t_first, t_last, zs, start);
        const double tol = 1e-12 * (1.0 + fabs(want));
        worst_below = fmax(worst_below, want - got);
        worst_above = fmax(worst_above, got - want);
        short_of += old < want - tol;
        CHECK(fabs(got - want) <= tol,
              "cells %dx%d (%d,%d) at %g deg from %g to %g: %.17g, sampled %.17g", w, h, i, j,
              deg, t_first, t_last, got, want);
        /* a search continued from where another stopped (the key lights'
         * near and edge searches) leaves no gap: the two give the whole */
        const double t_mid = t_first + 1.0 + 20.0 * urand();
        double d2 = 0.0;
        const double part = hfs_ray_bound_search_cells(&L, atlas, zd, (size_t)w, i, j, c, s,
                                                       t_first, fmin(t_mid, t_last), zs, 0.0,
                                                       start, &d2, NULL);
        const double both = t_mid >= t_last ? part
                                            : hfs_ray_bound_search_cells(
                                                  &L, atlas, zd, (size_t)w, i, j, c, s, t_mid,
                                                  t_last, zs, 0.0, part, &d2, NULL);
        CHECK(fabs(both - got) <= tol,
              "cells %dx%d (%d,%d) at %g deg from %g to %g, split at %g: %.17g, whole %.17g", w,
              h, i, j, deg, t_first, t_last, t_mid, both, got);
    }
    printf("cells %dx%d: %d rays, the crossings short on %ld; above the samples by %.3g at "
           "most, below by %.3g; reads %.1f against %.1f\n", w, h, trials, short_of,
           worst_above, worst_below, (double)reads[0] / trials, (double)reads[1] / trials);
    CHECK(wave == 0 || short_of > 0, "no ray where the crossings fall short: nothing tested");
    fixture_free(&F);
}

/* One raised corner passed diagonally: heights 0 but (4, 2) = 1 on a 9x5
 * grid, the ray from (0, 1) along (1, 0.6).  Its crossings, x = 3 at
 * y = 2.8 and x = 4 at y = 3.4, lie on rows that the corner does not
 * touch: all 0.  Between them the ray passes through the cell
 * [3, 4] x [2, 3] (to y = 3 at x = 3 1/3), where the corner's weight
 * a (1 - b) = a (0.2 - 0.6 a) peaks at a = 1/6: the search finds that
 * peak's slope (about 0.0045), the crossings see nothing. */
static void check_corner(void)
{
    const int w = 9, h = 5;
    double zd[9 * 5] = {0};
    float z[9 * 5] = {0};
    zd[2 * w + 4] = 1.0, z[2 * w + 4] = 1.0f;
    hfs_ray_bound_layout L;
    hfs_ray_bound_layout_make(w, h, &L);
    double atlas[64], scr[64];
    hfs_ray_bound_build(&L, z, 0.0, 1.0, -HUGE_VAL, atlas, scr);
    /* from (0, 1) towards (+1, +0.6): crossing x = 3 at y = 2.8, x = 4 at 3.4 */
    const double n = sqrt(1.0 + 0.36), c = 1.0 / n, s = 0.6 / n;
    double d = 0.0;
    const double got = hfs_ray_bound_search_cells(&L, atlas, zd, (size_t)w, 0, 1, c, s, 0.0,
                                                  HUGE_VAL, 1.0, 0.0, -1e30, &d, NULL);
    const double old = hfs_ray_bound_search(&L, atlas, zd, (size_t)w, 0, 1, c, s, 0.0, HUGE_VAL,
                                            1.0, 0.0, -1e30, &d, NULL);
    const double want = sampled(zd, w, h, 0, 1, c, s, 0.0, HUGE_VAL, 1.0, -1e30);
    CHECK(fabs(got - want) <= 1e-12 && old == 0.0 && got > 0.004,
          "corner: cells %.17g, crossings %.17g, sampled %.17g", got, old, want);
    printf("corner: cells %.6f, crossings %.6f, sampled %.6f\n", got, old, want);
}

int main(void)
{
    check_search(64, 48, 600, 0.0, 0.0, 0);
    check_search(37, 90, 400, 0.0, 0.0, 0);
    check_search(48, 40, 600, 0.4, -0.25, 0);
    check_search(40, 40, 40000, 0.0, 0.0, 1);
    check_search(70, 33, 20000, -0.1, 0.05, 1);
    check_search(5, 3, 100, 0.0, 0.0, 0);
    check_search(1, 40, 30, 0.0, 0.2, 0);
    check_post();
    check_cells(64, 48, 3000, 0.0, 0.0, 1);
    check_cells(37, 90, 2000, 0.4, -0.25, 0);
    check_cells(70, 33, 2000, -0.1, 0.05, 1);
    check_cells(5, 3, 200, 0.0, 0.0, 0);
    check_cells(1, 40, 30, 0.0, 0.2, 0);
    check_corner();
    if (failures) {
        fprintf(stderr, "%d failures\n", failures);
        return 1;
    }
    printf("ok\n");
    return 0;
}
