/*
 * cpu_far_grid.c — see cpu_far_grid.h.
 */
#include "cpu_far_grid.h"

#include "field_geom.h"
#include "parallel.h"
#include "pyramid_layout.h"

#include <math.h>
#include <stdlib.h>

struct hfs_cpu_far {
    const hfs_field *f;
    hfs_cpu_occ_desc d;
    int n_env, n_sub;           /* directions, sub-directions (k n_env)      */
    int gw, gh;                 /* grid receivers                            */
    double tie;
    double hunit;               /* the pairs' height unit (hfs_split_h_unit) */
    hfs_horizon_plan *plan;     /* the sub-directions                        */
    double *omega;              /* per worker: n_levels angles               */
    int n_levels;
    int heights;                /* occluders a sub-direction (desc.heights)  */
    size_t layer;               /* floats a height's layer holds             */
    float *pairs;               /* heights x gh x gw x n_sub x 2: height over
                                   the receiver (in hunit texels) and
                                   distance (texels), as the GLES pass stores
                                   them (a layer per height)                 */
};

/* Heights in texels of the horizontal: world z / dx. */
static double height_texels(const hfs_field *f, int i, int j)
{
    return f->zscale * (double)f->z[(size_t)j * (size_t)f->width + (size_t)i] / f->dx;
}

/* Grid index a's texel along an axis of n texels: a s, the last at n - 1. */
static int receiver_at(int a, int s, int n)
{
    return a * s < n - 1 ? a * s : n - 1;
}

/* The stored pair of an occluder of height h over its receiver (texels)
 * at distance dist (0: none). */
static void store_pair(const hfs_cpu_far *g, double h, double dist, float *out)
{
    if (dist > 0.0) {
        h /= g->hunit;
        h = h > HFS_SPLIT_MAX_H ? HFS_SPLIT_MAX_H : (h < -HFS_SPLIT_MAX_H ? -HFS_SPLIT_MAX_H : h);
        out[0] = (float)h;
        out[1] = (float)dist;
    } else {
        out[0] = (float)HFS_SPLIT_NONE_H;
        out[1] = 0.0f;
    }
}

/* The lowest and highest of the 3 x 3 far receivers around grid point
 * (a, b) (itself included), as grid points (lo[0], lo[1]), (hi[0], hi[1]);
 * the first met of equal heights, rows then columns (env_horizons.frag
 * far_around). */
static void receivers_around(const hfs_cpu_far *g, int a, int b, int lo[2], int hi[2])
{
    const int st = g->d.step;
    double zlo = HUGE_VAL, zhi = -HUGE_VAL;
    for (int v = -1; v <= 1; ++v) {
        const int bb = b + v < 0 ? 0 : (b + v >= g->gh ? g->gh - 1 : b + v);
        for (int u = -1; u <= 1; ++u) {
            const int aa = a + u < 0 ? 0 : (a + u >= g->gw ? g->gw - 1 : a + u);
            const int x = receiver_at(aa, st, g->f->width), y = receiver_at(bb, st, g->f->height);
            const double z = g->f->z[(size_t)y * (size_t)g->f->width + (size_t)x];
            if (z < zlo) {
                zlo = z;
                lo[0] = x, lo[1] = y;
            }
            if (z > zhi) {
                zhi = z;
                hi[0] = x, hi[1] = y;
            }
        }
    }
}

/* Receiver (x, y)'s occluder in sub-direction e seen from the height of
 * grid point at (split_horizon.h HFS_SPLIT_HEIGHTS), stored over the
 * receiver into out, from its own occluder (slope, dist) on; at its own
 * height, that occluder (env_horizons.frag's far pass alike).  The lead
 * moves past the horizons' tie, as in every search: on flat roofs, where
 * crossings tie exactly, float and double then name the same one (with
 * the relative tie alone they did not, a trial). */
static void far_from_height(const hfs_cpu_far *g, int e, int x, int y, const int at[2],
                            double slope, double dist, float *out)
{
    const float *z = g->f->z;
    const size_t w = (size_t)g->f->width;
    if (z[(size_t)at[1] * w + (size_t)at[0]] == z[(size_t)y * w + (size_t)x]) {
        store_pair(g, slope * dist, dist, out);
        return;
    }
    double d = dist, rise;
    const double t = hfs_horizon_gap_from(g->plan, e, x, y, at[0], at[1], g->d.gap_from, g->tie,
                                          slope, &d, &rise);
    store_pair(g, t * d + rise, d, out);
}

/* Grid row b: every receiver's occluder in every sub-direction. */
static void far_row(void *ctx, int b, int worker)
{
    const hfs_cpu_far *g = ctx;
    const int st = g->d.step;
    const int y = receiver_at(b, st, g->f->height);
    double *omega = g->omega + (size_t)worker * (size_t)g->n_levels;
    for (int a = 0; a < g->gw; ++a) {
        const int x = receiver_at(a, st, g->f->width);
        float *out = g->pairs + ((size_t)b * (size_t)g->gw + (size_t)a) * (size_t)g->n_sub * 2;
        int around[2][2] = {{x, y}, {x, y}};
        if (g->heights > 1)
            receivers_around(g, a, b, around[0], around[1]);
        for (int e = 0; e < g->n_sub; ++e) {
            double slope, dist;
            hfs_horizon_point(g->plan, e, x, y, HFS_HORIZON_OFF, NULL, NULL, omega);
            const int has = hfs_horizon_occluder(g->plan, e, x, y, omega, 1, g->d.first,
                                                 g->d.coarsest, g->d.refine, g->tie, &slope,
                                                 &dist);
            /* and every gap from far-from on (issue 36; env_horizons.frag) */
            if (g->d.gap_from >= 0.0)
                slope = hfs_horizon_gap(g->plan, e, x, y, g->d.gap_from, g->tie,
                                        has ? slope : -1e30, 0, &dist, NULL);
            store_pair(g, slope * dist, dist, out + 2 * e);
            for (int c = 1; c < g->heights; ++c)
                far_from_height(g, e, x, y, around[c - 1], slope, dist,
                                out + (size_t)c * g->layer + 2 * e);
        }
    }
}

int hfs_cpu_occ_create(const hfs_field *f, const hfs_cpu_pyramid *pyr, int offset,
                       const hfs_cpu_occ_desc *desc, const hfs_swath *env, double tie,
                       int threads, hfs_cpu_far **out, hfs_error *err)
{
    *out = NULL;
    hfs_cpu_far *g = calloc(1, sizeof *g);
    if (!g)
        return hfs_fail(err, HFS_E_NOMEM, "backend cpu: out of memory for an occluder grid");
    g->f = f;
    g->d = *desc;
    g->n_env = env->n;
    g->n_sub = env->n * desc->k;
    g->gw = hfs_grid_count(f->width, desc->step);
    g->gh = hfs_grid_count(f->height, desc->step);
    g->n_levels = hfs_cpu_pyramid_count(pyr);
    g->tie = tie;
    double lo, hi;
    hfs_field_range(f, &lo, &hi);
    g->hunit = hfs_split_h_unit(lo, hi, f->zscale, f->dx);
    double *phi = malloc((size_t)g->n_sub * sizeof *phi);
    const int workers = threads < 1 ? 1 : threads;
    g->omega = malloc((size_t)workers * (size_t)g->n_levels * sizeof *g->omega);
    g->heights = desc->heights > 1 && desc->gap_from >= 0.0 ? desc->heights : 1;
    g->layer = (size_t)g->gw * (size_t)g->gh * (size_t)g->n_sub * 2;
    g->pairs = malloc(g->layer * (size_t)g->heights * sizeof *g->pairs);
    int rc = !phi || !g->omega || !g->pairs
                 ? hfs_fail(err, HFS_E_NOMEM, "backend cpu: out of memory for an occluder grid")
                 : HFS_OK;
    hfs_swath sub;
    hfs_split_swath(env, desc->k, &sub);
    for (int e = 0; !rc && e < g->n_sub; ++e)
        phi[e] = hfs_swath_phi(&sub, e);
    if (!rc)
        rc = hfs_horizon_plan_create(pyr, f->dx, f->zscale, offset, phi, g->n_sub, &g->plan,
                                     err);
    free(phi);
    if (!rc)
        hfs_parallel_rows(g->gh, workers, far_row, g, NULL, NULL);
    if (rc) {
        hfs_cpu_far_destroy(g);
        return rc;
    }
    *out = g;
    return HFS_OK;
}

int hfs_cpu_far_create(const hfs_field *f, const hfs_cpu_pyramid *pyr, const hfs_quality *q,
                       const hfs_split *split, const hfs_swath *env, double tie, int threads,
                       hfs_cpu_far **out, hfs_error *err)
{
    const int n_levels = hfs_cpu_pyramid_count(pyr);
    const hfs_cpu_occ_desc d = {
        .step = split->step, .k = split->k,
        .first = hfs_split_first_far(n_levels, hfs_cpu_pyramid_k(pyr), split->from),
        .coarsest = 0, .refine = split->far_refine, .gap_from = split->from, .plane = 1,
        .heights = split->heights};
    return hfs_cpu_occ_create(f, pyr, q->offset, &d, env, tie, threads, out, err);
}

void hfs_cpu_far_destroy(hfs_cpu_far *g)
{
    if (!g)
        return;
    hfs_horizon_plan_destroy(g->plan);
    free(g->omega);
    free(g->pairs);
    free(g);
}

int hfs_cpu_far_coarsest_near(const hfs_cpu_far *g)
{
    return g->d.first + 1;
}

void hfs_cpu_far_place_of(const hfs_cpu_far *g, int i, int j, hfs_cpu_far_place *pl)
{
    const int s = g->d.step;
    int a0, b0;
    double tx, ty;
    hfs_grid_axis(i, s, g->f->width, &a0, &tx);
    hfs_grid_axis(j, s, g->f->height, &b0, &ty);
    const int a1 = a0 + 1 < g->gw ? a0 + 1 : a0, b1 = b0 + 1 < g->gh ? b0 + 1 : b0;
    const int ra[4] = {a0, a1, a0, a1}, rb[4] = {b0, b0, b1, b1};
    const double zp = height_texels(g->f, i, j);
    double zr[4], rise[4];
    for (int r = 0; r < 4; ++r) {
        const int x = receiver_at(ra[r], s, g->f->width), y = receiver_at(rb[r], s, g->f->height);
        zr[r] = height_texels(g->f, x, y);
        const double dist = hypot(x - i, y - j);
        rise[r] = dist > 0.0 ? fmax(zr[r] - zp, 0.0) / dist : 0.0;
    }
    hfs_split_far_snap(tx, ty, rise, HFS_SPLIT_STEEP, &tx, &ty);
    /* where the texel reads the grid, less its own place (0 but off a wall) */
    const int xa = receiver_at(a0, s, g->f->width), xb = receiver_at(a1, s, g->f->width);
    const int ya = receiver_at(b0, s, g->f->height), yb = receiver_at(b1, s, g->f->height);
    pl->off[0] = xa + tx * (xb - xa) - i;
    pl->off[1] = ya + ty * (yb - ya) - j;
    const double wt[4] = {(1 - tx) * (1 - ty), tx * (1 - ty), (1 - tx) * ty, tx * ty};
    pl->dz = 0.0;
    for (int r = 0; r < 4; ++r) {
        pl->dz += wt[r] * (zr[r] - zp);
        pl->at[r] = ((size_t)rb[r] * (size_t)g->gw + (size_t)ra[r]) * (size_t)g->n_sub * 2;
        pl->wt[r] = wt[r];
    }
}

void hfs_cpu_far_slopes(const hfs_cpu_far *g, const hfs_cpu_far_place *pl, int d,
                        const double n[3], double *slope)
{
    for (int h = 0; h < g->d.k; ++h) {
        const int e = d * g->d.k + h;
        double cs, sn;
        hfs_horizon_plan_dir(g->plan, e, &cs, &sn);
        /* read off the texel's place: the occluder that much nearer or farther */
        const double shift = pl->off[0] * cs + pl->off[1] * sn;
        slope[h] = -1e30;
        for (int c = 0; c < g->heights; ++c) { /* the largest of the heights' */
            double hb = 0.0, db = 0.0;
            for (int r = 0; r < 4; ++r) {
                const float *p = g->pairs + (size_t)c * g->layer + pl->at[r] + 2 * (size_t)e;
                hb += pl->wt[r] * p[0] * g->hunit;
                db += pl->wt[r] * p[1];
            }
            const double t =
                hfs_split_far_slope(hb, hfs_split_far_d(db, shift), pl->dz, g->d.step);
            slope[h] = t > slope[h] ? t : slope[h];
        }
        if (!g->d.plane)
            continue;
        if (!hfs_split_above_plane(slope[h], n[0] * cs + n[1] * sn, n))
            slope[h] = -1e30;
    }
}
