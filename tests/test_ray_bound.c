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
 *   3. a post one texel wide 200 texels away is found, with few reads.
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

static void check_search(int w, int h, int trials, double tx, double ty, int wave)
{
    float *z = malloc((size_t)w * h * sizeof *z);
    double *zd = malloc((size_t)w * h * sizeof *zd);
    make_field(z, w, h, tx, ty, wave);
    for (int t = 0; t < w * h; ++t)
        zd[t] = z[t];
    hfs_ray_bound_layout L;
    hfs_ray_bound_layout_make(w, h, &L);
    double *atlas = malloc((size_t)L.aw * L.ah * sizeof *atlas);
    double *scr = malloc(2 * (size_t)L.lw[1] * L.lh[1] * sizeof *scr);
    hfs_ray_bound_build(&L, z, 0.0, 1.0, -HUGE_VAL, atlas, scr);
    check_boxes(z, w, h, &L, atlas);
    static const double fixed[] = {0.0, 90.0, 180.0, 270.0, 45.0, 135.0, 225.0, 315.0, 30.0};
    long reads = 0;
    for (int k = 0; k < trials; ++k) {
        const int i = (int)(urand() * w), j = (int)(urand() * h);
        const double deg = k < 9 ? fixed[k] : 360.0 * urand();
        double c = cos(deg * 3.14159265358979323846 / 180.0), s = sin(deg * 3.14159265358979323846 / 180.0);
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
    free(z), free(zd), free(atlas), free(scr);
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
    if (failures) {
        fprintf(stderr, "%d failures\n", failures);
        return 1;
    }
    printf("ok\n");
    return 0;
}
