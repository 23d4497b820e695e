/*
 * bounce_scenes.h — the scenes and closed forms the indirect-light tests
 * share (test_truth_bounce.c, test_cpu_bounce.c):
 *   bounce_uniform_sky()        an environment of radiance 1 everywhere
 *   bounce_wall(...)            a floor (height 0) and a wall (height hw) for
 *                               x >= X over the whole y range, with an exit
 *                               radiance lw on the wall and on the last floor
 *                               texel (the bilinear ramp's foot), 0 elsewhere
 *   bounce_wall_view_factor()   the view factor from floor texel (i, jc) to
 *                               that wall: the ramp subtends a vertical wall
 *                               at its top edge (x = X), of the grid's
 *                               length, by Lambert's polygon formula
 *   bounce_groove(...)          a V-groove along y, slope 1.5
 *   bounce_furnace(...)         over images with 0..3 bounces: the most
 *                               negative bounce and the largest total
 */
#ifndef HFS_TEST_BOUNCE_SCENES_H
#define HFS_TEST_BOUNCE_SCENES_H

#include "hfshade.h"

#include <math.h>
#include <stdlib.h>

#define BOUNCE_PI 3.14159265358979323846

static inline hfs_lighting bounce_uniform_sky(void)
{
    hfs_lighting l;
    hfs_lighting_defaults(&l);
    l.has_env = 1;
    for (int c = 0; c < 3; ++c)
        l.env_sh[c][0] = sqrt(4.0 * BOUNCE_PI); /* radiance 1 */
    return l;
}

/* Heights and the exit radiance (w*h and w*h*3, malloc'ed) of the wall. */
static inline void bounce_wall(int w, int h, int X, double hw, double lw, float **z, float **lo)
{
    *z = calloc((size_t)w * h, sizeof **z);
    *lo = calloc((size_t)w * h * 3, sizeof **lo);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            (*z)[j * w + i] = i >= X ? (float)hw : 0.0f;
            for (int c = 0; c < 3 && i >= X - 1; ++c)
                (*lo)[3 * (j * w + i) + c] = (float)lw;
        }
}

/* Lambert: F from a point with normal +z to the polygon v (relative to
 * the point), the sign dropped. */
static inline double bounce_polygon_view_factor(const double v[][3], int nv)
{
    double sum = 0.0;
    for (int k = 0; k < nv; ++k) {
        const double *a = v[k], *b = v[(k + 1) % nv];
        const double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                             a[0] * b[1] - a[1] * b[0]};
        const double lc = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        if (lc > 0.0)
            sum += atan2(lc, a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) * c[2] / lc;
    }
    return fabs(sum) / (2.0 * BOUNCE_PI);
}

/* From floor texel (i, jc), lifted by 1e-4 (dx = 1), to the wall of
 * bounce_wall(w, h, X, hw, ...). */
static inline double bounce_wall_view_factor(int i, int jc, int h, int X, double hw)
{
    const double D = X - i, lift = 1e-4;
    const double v[4][3] = {{D, -jc, -lift}, {D, h - 1 - jc, -lift}, {D, h - 1 - jc, hw - lift},
                            {D, -jc, hw - lift}};
    return bounce_polygon_view_factor(v, 4);
}

/* A V-groove along y: z = 1.5 |x - (w - 1) / 2| (w*h, malloc'ed). */
static inline float *bounce_groove(int w, int h)
{
    float *z = malloc((size_t)w * h * sizeof *z);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            z[j * w + i] = (float)(1.5 * fabs(i - 0.5 * (w - 1)));
    return z;
}

/* lo[b] (n floats each) rendered with b = 0..3 bounces: the smallest
 * lo[b] - lo[b-1] (a bounce's own light, >= 0 when right) into *neg and
 * the largest lo[3] into *total. */
static inline void bounce_furnace(float *const lo[4], size_t n, double *neg, double *total)
{
    *neg = 0.0, *total = 0.0;
    for (size_t p = 0; p < n; ++p) {
        for (int b = 1; b < 4; ++b)
            *neg = fmin(*neg, (double)lo[b][p] - lo[b - 1][p]);
        *total = fmax(*total, lo[3][p]);
    }
}

#endif /* HFS_TEST_BOUNCE_SCENES_H */
