/*
 * pyramid_layout.c — see pyramid_layout.h.
 */
#include "pyramid_layout.h"

#include <math.h>

int hfs_pyramid_level_count(int w, int h, int k)
{
    const int n = w > h ? w : h;
    if (n <= 1 || k < 1)
        return 1;
    /* k*log2(n) is an exact integer for n a power of two and otherwise not
     * within 1e-9 of one for any realistic size; the epsilon only absorbs a
     * libm that would round log2(2^m) up. */
    return (int)ceil((double)k * log2((double)n) - 1e-9) + 1;
}

double hfs_pyramid_spacing(int n_levels, int k, int level)
{
    return exp2((double)(n_levels - 1 - level) / (double)k);
}

void hfs_pyramid_level_size(int w, int h, int k, int level, int *lw, int *lh)
{
    const int n_levels = hfs_pyramid_level_count(w, h, k);
    const double s = hfs_pyramid_spacing(n_levels, k, level);
    /* s is an exact power of two whenever w/s can be an integer, so ceil is
     * exact where it matters. */
    double a = ceil((double)w / s), b = ceil((double)h / s);
    *lw = a < 1.0 ? 1 : (a > (double)w ? w : (int)a);
    *lh = b < 1.0 ? 1 : (b > (double)h ? h : (int)b);
}

int hfs_pyramid_read_level(int n_levels, int k, int offset, int level)
{
    long r = (long)level + (long)k * (long)offset;
    if (r > n_levels - 1)
        r = n_levels - 1;
    if (r < 0)
        r = 0;
    return (int)r;
}


double hfs_horizon_tie_slope(double half_range, double zscale, double dx)
{
    return 1e-6 * (half_range > 0.0 ? half_range : 1.0) * zscale / dx;
}

int hfs_grid_count(int n, int g)
{
    if (g < 1)
        g = 1;
    return (n - 1 + g - 1) / g + 1;
}

void hfs_grid_axis(int p, int g, int n, int *a0, double *t)
{
    const int a = p / g, x0 = a * g, x1 = x0 + g < n - 1 ? x0 + g : n - 1;
    *a0 = a;
    *t = x1 > x0 ? (double)(p - x0) / (double)(x1 - x0) : 0.0;
}
