/*
 * split_horizon.c — the rules of split horizons (split_horizon.h).
 */
#include "split_horizon.h"

#include "pyramid_layout.h"

#include <math.h>

/* The settings by grid step (hfshade.h hfs_quality: far_from, far_dirs,
 * far_step at 0), from the measurements of BENCHMARKS.md "Split horizons":
 * subsample 1 is the accurate setting (the far grid at every other texel,
 * three sub-directions); the 2x2 and 4x4 grids spend no more than the
 * single horizon did. */
static const struct { int from, k, step; } by_subsample[3] = {{8, 3, 2}, {16, 2, 8}, {16, 2, 16}};

void hfs_split_make(const hfs_quality *q, hfs_split *s)
{
    const int i = q->subsample <= 1 ? 0 : (q->subsample == 2 ? 1 : 2);
    s->on = q->split != 0 && q->visibility == HFS_VIS_SLICE;
    s->from = q->far_from > 0 ? q->far_from : by_subsample[i].from;
    s->k = q->far_dirs > 0 ? q->far_dirs : by_subsample[i].k;
    s->k = s->k > HFS_SPLIT_MAX_K ? HFS_SPLIT_MAX_K : s->k;
    s->step = q->far_step > 0 ? q->far_step : by_subsample[i].step;
    s->near_refine = i == 0 || q->refine < 2 ? q->refine : 2;
    s->far_refine = q->refine;
    s->heights = s->step > 2 ? HFS_SPLIT_HEIGHTS : 1;
}

void hfs_split_swath(const hfs_swath *env, int k, hfs_swath *far)
{
    hfs_swath_full(env->n * k, far);
    far->phi0 = env->phi0 + hfs_split_turn(0, k, env->dphi);
}

double hfs_split_turn(int h, int k, double dphi)
{
    return ((h + 0.5) / k - 0.5) * dphi;
}

int hfs_split_near_count(int n_levels, int k, double from)
{
    int count = 0;
    for (int i = n_levels - 1; i >= 0; --i)
        if (hfs_pyramid_spacing(n_levels, k, i) <= from * (1.0 + 1e-9))
            ++count;
    return count;
}

int hfs_split_first_far(int n_levels, int k, double from)
{
    return n_levels - 1 - hfs_split_near_count(n_levels, k, from);
}

void hfs_split_far_snap(double tx, double ty, const double rise[4], double steep, double *sx,
                        double *sy)
{
    const double w[4] = {(1 - tx) * (1 - ty), tx * (1 - ty), (1 - tx) * ty, tx * ty};
    int ok[4], all = 1;
    for (int r = 0; r < 4; ++r) {
        ok[r] = !(w[r] > 0.0) || !(rise[r] > steep);
        all &= ok[r];
    }
    *sx = tx, *sy = ty;
    if (all)
        return;
    /* the heaviest (nearest) edge of the cell whose two receivers pass:
     * the blend along it; two edges as heavy (adjacent: opposite ones
     * passing would pass all four) meet at a receiver, which alone keeps
     * the choice the same under the field's turns and mirrors */
    static const int edge[4][2] = {{0, 1}, {2, 3}, {0, 2}, {1, 3}};
    int best = -1, tie = -1;
    double bw = 0.0;
    for (int k = 0; k < 4; ++k) {
        const int a = edge[k][0], b = edge[k][1];
        const double ew = w[a] + w[b];
        if (!ok[a] || !ok[b] || !(ew > 0.0))
            continue;
        if (ew > bw)
            best = k, tie = -1, bw = ew;
        else if (ew == bw)
            tie = k;
    }
    if (best >= 0 && tie < 0) {
        if (best < 2)
            *sy = best;
        else
            *sx = best - 2;
        return;
    }
    if (best >= 0) { /* y0 or y1 (best) with x0 or x1 (tie) */
        *sx = tie - 2, *sy = best;
        return;
    }
    /* else one receiver: the heaviest that passes, or the least steep; a
     * tie keeps the texel's own place (again the same under turns) */
    int one = -1, tied = 0;
    for (int r = 0; r < 4; ++r) {
        if (!(w[r] > 0.0))
            continue;
        const int same = one >= 0 && ok[r] == ok[one];
        if (one < 0 || (ok[r] && !ok[one]) ||
            (same && (ok[r] ? w[r] > w[one] : rise[r] < rise[one])))
            one = r, tied = 0;
        else if (same && (ok[r] ? w[r] == w[one] : rise[r] == rise[one]))
            tied = 1;
    }
    if (!tied)
        *sx = one & 1, *sy = one >> 1;
}

double hfs_split_far_d(double d, double shift)
{
    return d > 0.0 ? d + shift : d;
}

double hfs_split_h_unit(double lo, double hi, double zscale, double dx)
{
    const double relief = (hi - lo) * zscale / dx;
    if (!(relief > HFS_SPLIT_H_PLAIN)) /* and NaN: nothing to scale */
        return 1.0;
    if (!(relief < HUGE_VAL))
        return ldexp(1.0, 64);
    int e;
    const double m = frexp(relief / HFS_SPLIT_H_PLAIN, &e); /* in [0.5, 1) x 2^e */
    e = m == 0.5 ? e - 1 : e; /* an exact power of two is its own unit */
    return ldexp(1.0, e < 64 ? e : 64);
}

double hfs_split_far_slope(double h, double d, double dz, int g)
{
    if (!(d > 0.0))
        return -1e30;
    const double m = d / g < 1.0 ? d / g : 1.0;
    return (h + dz * m) / d;
}

int hfs_split_above_plane(double t, double a_h, const double n[3])
{
    const double plane = -a_h / n[2];
    return t > plane + HFS_SPLIT_PLANE_TIE * (1.0 + fabs(plane));
}

double hfs_split_band(const double *s_cap, int k, double s_top, double s_e)
{
    if (k <= 0)
        return s_top - s_e;
    double sum = 0.0;
    for (int h = 0; h < k; ++h)
        sum += fmax(s_top, s_cap[h]) - fmax(s_e, s_cap[h]);
    return sum / k;
}
