/*
 * post_geometry.h — what the shadow tests of a post on a flat field share
 * (test_long_shadow.c: a sun; test_local_shadow.c: a local light): their
 * check macro and the 2-D ray's entry into a square, by which they tell
 * the umbra and the lit ground from geometry alone.
 */
#ifndef HFS_TEST_POST_GEOMETRY_H
#define HFS_TEST_POST_GEOMETRY_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "hfshade.h"

/* A failed check, counted in the tests' `failures` (check.h), its message
 * on stderr. */
#define LS_CHECK(c, ...)                                                                     \
    do {                                                                                     \
        if (!(c)) {                                                                          \
            fprintf(stderr, "FAIL: " __VA_ARGS__);                                           \
            fputc('\n', stderr);                                                             \
            ++failures;                                                                      \
        }                                                                                    \
    } while (0)

/* Entry distance (along the unit (c, s)) of the 2-D ray from (px, py) into
 * the square [a0, a1] x [b0, b1], or -1 when it misses (slab method). */
static inline double ray_enter(double px, double py, double c, double s, double a0, double a1,
                               double b0, double b1)
{
    double t0 = 0.0, t1 = 1e30;
    const double o[2] = {px, py}, d[2] = {c, s}, lo[2] = {a0, b0}, hi[2] = {a1, b1};
    for (int k = 0; k < 2; ++k) {
        if (fabs(d[k]) < 1e-12) {
            if (o[k] < lo[k] || o[k] > hi[k])
                return -1.0;
            continue;
        }
        double ta = (lo[k] - o[k]) / d[k], tb = (hi[k] - o[k]) / d[k];
        if (ta > tb) {
            const double t = ta;
            ta = tb;
            tb = t;
        }
        t0 = fmax(t0, ta);
        t1 = fmin(t1, tb);
    }
    return t0 <= t1 ? t0 : -1.0;
}

/* A flat w x h field (dx 1, zscale 1) with a post of `height` on the grid
 * points [x0, x0 + side - 1] x [y0, y0 + side - 1]; *z: its heights, the
 * caller's to free (NULL when out of memory: the field is then empty). */
static inline hfs_field post_field(int w, int h, int x0, int y0, int side, double height,
                                   float **z)
{
    *z = calloc((size_t)w * h, sizeof **z);
    for (int j = y0; *z && j < y0 + side; ++j)
        for (int i = x0; i < x0 + side; ++i)
            (*z)[(size_t)j * w + i] = (float)height;
    return (hfs_field){.width = *z ? w : 0, .height = *z ? h : 0, .z = *z, .dx = 1.0,
                       .zscale = 1.0};
}

/* The checks of a case: enough umbra texels to mean anything, none of them
 * lit, none of the lit ground shadowed. */
static inline void post_checks(const char *name, long min_umbra, long n_umbra, long bad_umbra,
                               long n_lit, long bad_lit)
{
    LS_CHECK(n_umbra > min_umbra, "%s: only %ld umbra texels (the case is wrong)", name,
             n_umbra);
    LS_CHECK(bad_umbra == 0, "%s: %ld of %ld umbra texels lit", name, bad_umbra, n_umbra);
    LS_CHECK(bad_lit == 0, "%s: %ld of %ld lit texels shadowed", name, bad_lit, n_lit);
}

#endif /* HFS_TEST_POST_GEOMETRY_H */
