/*
 * split_horizon.c — the rules of split horizons (split_horizon.h).
 */
#include "split_horizon.h"

#include "pyramid_layout.h"

#include <math.h>

void hfs_split_make(const hfs_quality *q, hfs_split *s)
{
    s->on = q->far_from > 0 && q->visibility == HFS_VIS_SLICE;
    s->from = q->far_from;
    s->k = q->far_dirs < 1 ? 1 : (q->far_dirs > HFS_SPLIT_MAX_K ? HFS_SPLIT_MAX_K : q->far_dirs);
    s->step = hfs_quality_far_step(q);
}

void hfs_split_swath(const hfs_swath *env, int k, hfs_swath *far)
{
    hfs_swath_full(env->n * k, far);
    far->phi0 = env->phi0 + env->dphi * (0.5 / k - 0.5);
}

int hfs_split_near_count(int n_levels, int k, double from)
{
    int count = 0;
    for (int i = n_levels - 1; i >= 0; --i)
        if (hfs_pyramid_spacing(n_levels, k, i) <= from * (1.0 + 1e-9))
            ++count;
    return count;
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

double hfs_split_far_slope(double h, double d, double dz, int g)
{
    if (!(d > 0.0))
        return -1e30;
    const double m = d / g < 1.0 ? d / g : 1.0;
    return (h + dz * m) / d;
}
