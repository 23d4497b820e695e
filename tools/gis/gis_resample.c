/*
 * gis_resample.c — see gis_resample.h.
 */
#include "gis_resample.h"

#include <math.h>
#include <stddef.h>

/* v at the square grid's point (gx, gy), bilinear, clamped to the grid. */
static double bilinear(const float *v, int sw, int sh, double gx, double gy)
{
    gx = fmin(gx, sw - 1.0), gy = fmin(gy, sh - 1.0);
    const int i0 = gx >= sw - 1 ? sw - 2 : (int)gx, j0 = gy >= sh - 1 ? sh - 2 : (int)gy;
    const double fx = gx - i0, fy = gy - j0;
    const float *r0 = v + (size_t)j0 * (size_t)sw + (size_t)i0, *r1 = r0 + sw;
    const double a = (1.0 - fx) * r0[0] + fx * r0[1], b = (1.0 - fx) * r1[0] + fx * r1[1];
    return (1.0 - fy) * a + fy * b;
}

void gis_sample_back(const float *v, int sw, int sh, double sx, double sy, int w, int h,
                     const unsigned char *hole, float nodata, float *out)
{
    const int same = sx == 1.0 && sy == 1.0 && sw == w && sh == h;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const size_t p = (size_t)j * (size_t)w + (size_t)i;
            const float x = same ? v[p] : (float)bilinear(v, sw, sh, i * sx, j * sy);
            out[p] = (hole && hole[p]) || !isfinite(x) ? nodata : x;
        }
}
