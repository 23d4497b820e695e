/*
 * cpu_grid.c — see cpu_grid.h.
 */
#include "cpu_grid.h"

#include "field_geom.h"
#include "parallel.h"
#include "pyramid_layout.h"
#include "split_horizon.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define HALF_PI 1.57079632679489661923
/* key_horizons.frag HFS_KEY_TAN_ANGLE: horizons stored as tangents are
 * clamped to this elevation (tan < 1e4) */
#define KEY_TAN_ANGLE 1.5706963
#define MAX_LEVELS 512 /* k 16 on a side of 2^31 needs 497 */

/* The nearest fp16 value of a distance v >= 0 (ties to even): the GLES key
 * pass rounds D to fp16 in every precision (key_horizons.frag), so that
 * fp16 and fp32 frames correct alike; so does the reference. */
static double round_half(double v)
{
    if (!(v > 0.0))
        return 0.0;
    int e;
    const double m = frexp(v, &e); /* v = m 2^e, m in [0.5, 1) */
    return e < -13 ? ldexp(nearbyint(ldexp(v, 24)), -24) /* subnormal halves */
                   : ldexp(nearbyint(ldexp(m, 11)), e - 11);
}

/* Grid receiver a's grid point on an axis of n points. */
static int receiver(int a, int sub, int n)
{
    return a * sub < n - 1 ? a * sub : n - 1;
}

/* SN08's B-spline max over the scales from N-1-skip to coarser ones as
 * key_horizons.frag bspline_horizon runs it (refine 0): per-scale angles
 * (floor off the grid; omega from the point form with HFS_HORIZON_OFF),
 * the window clamped at the finest scale searched, three floor values
 * after the grid's exit; *dist the winning knot's scale (or the geometric
 * mean of a midpoint's two). */
static double bspline_grid(const double *omega, int n_levels, int lk, int skip, double fl,
                           double *dist, int *seen)
{
    double best = -HALF_PI, bd = 0.0, w[4] = {fl, fl, fl, fl};
    int tail = 3, i;
    const int top = n_levels - 1 - skip;
    *seen = 0;
    for (i = top; i >= 0; --i) {
        double a = fl;
        if (tail == 3) {
            if (omega[i] > HFS_HORIZON_OFF) {
                a = omega[i];
                *seen = 1;
            } else {
                --tail;
            }
        } else if (--tail < 0) {
            break;
        }
        if (i == top) {
            w[0] = w[1] = w[2] = w[3] = a;
            continue;
        }
        w[3] = w[2], w[2] = w[1], w[1] = w[0], w[0] = a;
        const double c = 2.0 * (n_levels - 2 - i);
        const double knot = w[1] + ((w[0] - w[1]) + (w[2] - w[1])) / 6.0;
        if (knot > best)
            best = knot, bd = c + 1.0;
        const double mid = w[1] + ((w[0] - w[1]) + 23.0 * (w[2] - w[1]) + (w[3] - w[1])) / 48.0;
        if (i + 2 < n_levels && mid > best)
            best = mid, bd = c;
    }
    if (i < 0 && top >= 0) { /* knot 0 and midpoint 0, om[-1] clamped to om[0] */
        const double c = 2.0 * (n_levels - 1);
        const double knot = w[0] + (w[1] - w[0]) / 6.0;
        if (knot > best)
            best = knot, bd = c + 1.0;
        const double mid = w[0] + (23.0 * (w[1] - w[0]) + (w[2] - w[0])) / 48.0;
        if (n_levels > 1 && mid > best)
            best = mid, bd = c;
    }
    *dist = exp2((bd - 1.0) / (2.0 * lk));
    return best;
}

/* Key job q's occluder at receiver (x, y) of normal n in each direction
 * (key_horizons.frag): (tan of the horizon, its distance rounded to fp16,
 * 0 where no scale's sample lies on the grid) into out. */
static void key_receiver(const render_ctx *c, const swath_job *job, int x, int y,
                         const double n[3], double *omega, double *out)
{
    const hfs_horizon_plan *plan = job->plan ? job->plan : c->jobs[0].plan;
    const int skip = job->near.n_grid; /* the texels search those themselves */
    for (int d = 0; d < job->swath.n; ++d) {
        double cs, sn, dist;
        int seen;
        hfs_horizon_plan_dir(plan, d, &cs, &sn);
        const double fl = hfs_horizon_floor(n, cs, sn);
        hfs_horizon_point(plan, d, x, y, HFS_HORIZON_OFF, NULL, NULL, omega);
        double om = c->refine > 0
                        ? atan(hfs_horizon_key_grid(plan, d, x, y, omega, fl, c->refine, c->tie,
                                                    skip, job->near.edge, &dist, &seen))
                        : bspline_grid(omega, c->n_levels, c->k, skip, fl, &dist, &seen);
        om = om > HALF_PI ? HALF_PI : (om < -HALF_PI ? -HALF_PI : om);
        out[2 * d] = tan(om > KEY_TAN_ANGLE ? KEY_TAN_ANGLE : (om < -KEY_TAN_ANGLE ? -KEY_TAN_ANGLE : om));
        out[2 * d + 1] = seen ? round_half(dist) : 0.0;
    }
}

/* The environment's V - hemisphere(n) at receiver (x, y) of normal n
 * (env_horizons.frag, Legendre or tables): horizons seeded with the
 * receiver's floor, every scale. */
static void env_receiver(const render_ctx *c, int x, int y, const double n[3], double *omega,
                         double *om, double *out)
{
    const swath_job *job = &c->jobs[0];
    for (int d = 0; d < job->swath.n; ++d) {
        double cs, sn, env;
        hfs_horizon_plan_dir(job->plan, d, &cs, &sn);
        const double fl = hfs_horizon_floor(n, cs, sn), fls = hfs_horizon_floor_slope(n, cs, sn);
        hfs_horizon_point(job->plan, d, x, y, fl, &env, NULL, omega);
        om[d] = c->refine > 0 ? hfs_horizon_refined_within(job->plan, d, x, y, omega, 1, fl,
                                                           c->refine, c->tie, &fls, 0, 0)
                              : env;
    }
    double hemi[HFS_SH_N];
    hfs_visibility_eval(job->vis, om, out);
    hfs_sh_rotate_zonal(c->h_hemi, n[0], n[1], n[2], hemi);
    for (int k = 0; k < HFS_SH_N; ++k)
        out[k] -= hemi[k];
}

/* Grid row b of the environment's V (Legendre, tables) and every key
 * light's occluders. */
static void grid_row(void *ctx, int b, int worker)
{
    const render_ctx *c = ctx;
    double omega[MAX_LEVELS];
    double *om = c->scratch[worker].om; /* the most directions a job has */
    const int y = receiver(b, c->sub, c->h);
    for (int a = 0; a < c->gw; ++a) {
        const int x = receiver(a, c->sub, c->w);
        const size_t at = (size_t)b * (size_t)c->gw + (size_t)a;
        double n[3];
        hfs_field_normal(c->f, x, y, n);
        if (c->vgrid)
            env_receiver(c, x, y, n, omega, om, c->vgrid + at * HFS_SH_N);
        for (int q = 0; q < c->n_jobs; ++q) {
            const swath_job *job = &c->jobs[q];
            if (!job->is_env && job->grid) /* none where the texels search it all */
                key_receiver(c, job, x, y, n, omega, job->grid + at * 2 * (size_t)job->swath.n);
        }
    }
}

/* The slice path's near occluders (env_horizons.frag HFS_PAIRS): from
 * the scale after the finest (the texel's own cell is searched per
 * texel) to far-from with split horizons, refined as their near part. */
static int env_near_grid(render_ctx *c, const hfs_quality *q, const hfs_cpu_pyramid *pyr,
                         int threads, hfs_error *err)
{
    const hfs_cpu_occ_desc d = {
        .step = c->sub, .k = 1, .first = c->n_levels - 2,
        .coarsest = c->far ? hfs_cpu_far_coarsest_near(c->far) : 0,
        .refine = c->far ? c->split.near_refine : c->refine, .gap_from = -1.0, .plane = 0};
    return hfs_cpu_occ_create(c->f, pyr, q->offset, &d, &c->jobs[0].swath, c->tie, threads,
                              &c->near, err);
}

int hfs_cpu_grid_build(render_ctx *c, const hfs_quality *q, const hfs_cpu_pyramid *pyr,
                       int threads, hfs_error *err)
{
    if (c->sub <= 1)
        return HFS_OK;
    if (c->n_levels > MAX_LEVELS)
        return hfs_fail(err, HFS_E_INVALID, "backend cpu: %d pyramid levels (at most %d)",
                        c->n_levels, MAX_LEVELS);
    c->gw = hfs_grid_count(c->w, c->sub);
    c->gh = hfs_grid_count(c->h, c->sub);
    const size_t cells = (size_t)c->gw * (size_t)c->gh;
    int rc = HFS_OK;
    if (c->has_env && c->slices.p)
        rc = env_near_grid(c, q, pyr, threads, err);
    else if (c->has_env && !(c->vgrid = malloc(cells * HFS_SH_N * sizeof *c->vgrid)))
        rc = hfs_fail(err, HFS_E_NOMEM, "backend cpu: out of memory for the visibility grid");
    hfs_zh_cap(HALF_PI, c->h_hemi);
    for (int q2 = 0; !rc && q2 < c->n_jobs; ++q2) {
        swath_job *job = &c->jobs[q2];
        if (job->is_env)
            continue;
        job->near = hfs_key_near_make(c->sub, c->n_levels, c->k, &job->swath);
        if (job->near.whole)
            continue; /* each texel searches its rays to the field's end */
        if (!(job->grid = malloc(cells * 2 * (size_t)job->swath.n * sizeof *job->grid)))
            rc = hfs_fail(err, HFS_E_NOMEM, "backend cpu: out of memory for the key grid");
    }
    if (!rc)
        hfs_parallel_rows(c->gh, threads, grid_row, c, NULL, NULL);
    return rc;
}

void hfs_cpu_grid_free(render_ctx *c)
{
    hfs_cpu_far_destroy(c->near);
    free(c->vgrid);
    for (int q = 0; c->jobs && q < c->n_jobs; ++q)
        free(c->jobs[q].grid);
}

void hfs_cpu_grid_env_places(const render_ctx *c, worker_scratch *s, int j)
{
    for (int i = 0; i < c->w; ++i)
        hfs_cpu_far_place_of(c->near, i, j, &s->grid_pl[i]);
}

void hfs_cpu_grid_env_row(const render_ctx *c, const worker_scratch *s, int d, int j,
                          const double *fl, double *om)
{
    double cs, sn;
    hfs_horizon_plan_dir(c->jobs[0].plan, d, &cs, &sn);
    for (int i = 0; i < c->w; ++i) {
        double t; /* the blend, moved to the texel (one sub-direction) */
        hfs_cpu_far_slopes(c->near, &s->grid_pl[i], d, s->normals + 3 * i, &t);
        t = fmax(t, hfs_field_first_cell_slope(c->f, i, j, cs, sn));
        om[i] = fmax(fl[i], atan(t));
    }
}

void hfs_cpu_grid_env_v(const render_ctx *c, int i, int j, const double n[3],
                        double v[HFS_SH_N])
{
    int a0, b0;
    double tx, ty;
    hfs_grid_axis(i, c->sub, c->w, &a0, &tx);
    hfs_grid_axis(j, c->sub, c->h, &b0, &ty);
    const int a1 = a0 + 1 < c->gw ? a0 + 1 : a0, b1 = b0 + 1 < c->gh ? b0 + 1 : b0;
    const double *g00 = c->vgrid + ((size_t)b0 * c->gw + a0) * HFS_SH_N;
    const double *g10 = c->vgrid + ((size_t)b0 * c->gw + a1) * HFS_SH_N;
    const double *g01 = c->vgrid + ((size_t)b1 * c->gw + a0) * HFS_SH_N;
    const double *g11 = c->vgrid + ((size_t)b1 * c->gw + a1) * HFS_SH_N;
    hfs_sh_rotate_zonal(c->h_hemi, n[0], n[1], n[2], v); /* the texel's own hemisphere */
    for (int k = 0; k < HFS_SH_N; ++k)
        v[k] += (g00[k] * (1.0 - tx) + g10[k] * tx) * (1.0 - ty) +
                (g01[k] * (1.0 - tx) + g11[k] * tx) * ty;
}

/* The slope from texel (i, j) (height zp, texels) to the field at
 * distance d (texels) in direction (cs, sn), its offset snapped as the
 * horizons' (cpu_horizon.h); -1e30 off the grid (key_visibility.frag
 * near_slope). */
static double near_slope(const render_ctx *c, int i, int j, double cs, double sn, double d,
                         double zp)
{
    double o[2] = {d * cs, d * sn}, z;
    for (int a = 0; a < 2; ++a) {
        const double r = nearbyint(o[a]);
        if (fabs(o[a] - r) < 1e-9)
            o[a] = r;
    }
    if (!hfs_field_bilinear(c->f, i + o[0], j + o[1], &z))
        return -1e30;
    return (z / c->f->dx - zp) / d;
}

/* The slopes (tan) at which key light job's elevation window starts and
 * closes (key_visibility.frag win_t): on the Legendre path a horizon below
 * the window shows the light as the window's start does, and one at its
 * end hides it (hfs_visible); the wedge tables count every elevation. */
static void key_window(const render_ctx *c, const swath_job *job, double win_t[2])
{
    win_t[0] = c->key_tables ? -1e30 : tan(fmax(job->swath.elev_lo, -1.5));
    win_t[1] = c->key_tables || !(job->swath.elev_hi < 1.57) ? 1e30 : tan(job->swath.elev_hi);
}

double hfs_cpu_grid_key_near(const render_ctx *c, const swath_job *job, int i, int j)
{
    const hfs_key_near *nr = &job->near;
    const double zp = hfs_field_z(c->f, i, j) / c->f->dx;
    double win_t[2], cs, sn;
    key_window(c, job, win_t);
    double best = win_t[0];
    int bm = -1;
    for (int m = 0; !nr->per_dir && m < nr->n && best < win_t[1]; ++m) {
        const double sl = near_slope(c, i, j, nr->cs[0], nr->cs[1], exp2((double)m / c->k), zp);
        if (sl > best)
            best = sl, bm = m;
    }
    const double d = exp2((double)bm / c->k);
    for (int q = 0; bm >= 0 && q < c->refine && best < win_t[1]; ++q)
        best = fmax(best, near_slope(c, i, j, nr->cs[0], nr->cs[1],
                                     d * hfs_horizon_refine_factor(q, c->refine, c->k), zp));
    if (nr->per_dir || nr->n <= 0)
        return best;
    /* and every crossing of the texel's own ray up to `to` (issue 36 item
     * 2); GLES stops once the window closes (the same visibility) */
    double dist = 0.0;
    hfs_horizon_snap_dir(nr->centre, &cs, &sn);
    return hfs_horizon_gap_along(job->plan ? job->plan : c->jobs[0].plan, cs, sn, i, j, 1.0,
                                 nr->to, 0.0, best, 1, &dist, NULL);
}

/* The blend of the four grid receivers' occluders around texel (i, j) of
 * height zp in direction d (cs, sn), moved to the texel, as a slope, at
 * least the texel's floor slope tfl (key_visibility.frag key_horizon). */
static double grid_blend(const render_ctx *c, const swath_job *job, int d, int i, int j,
                         double cs, double sn, double zp, double tfl)
{
    double t[2];
    /* per axis: the receivers a[0], a[1] around the texel (key_visibility.frag
     * grid_cell), their grid points x and the texel's weight t */
    int a[2][2], x[2][2];
    hfs_grid_axis(i, c->sub, c->w, &a[0][0], &t[0]);
    hfs_grid_axis(j, c->sub, c->h, &a[1][0], &t[1]);
    const int count[2] = {c->gw, c->gh}, len[2] = {c->w, c->h};
    for (int k = 0; k < 2; ++k) {
        a[k][1] = a[k][0] + 1 < count[k] ? a[k][0] + 1 : a[k][0];
        x[k][0] = receiver(a[k][0], c->sub, len[k]);
        x[k][1] = receiver(a[k][1], c->sub, len[k]);
    }
    double sl[4];
    for (int k = 0; k < 4; ++k) {
        const int gx = x[0][k % 2], gy = x[1][k / 2];
        const size_t at = (size_t)a[1][k / 2] * (size_t)c->gw + (size_t)a[0][k % 2];
        const double *g = job->grid + (at * (size_t)job->swath.n + (size_t)d) * 2;
        const double ahead = g[1] + (gx - i) * cs + (gy - j) * sn;
        /* the height term only for occluders 2 sub texels away (u_far) */
        const double rz = g[1] >= 2 * c->sub ? hfs_field_z(c->f, gx, gy) / c->f->dx - zp : 0.0;
        sl[k] = g[1] > 0.0 && ahead >= job->near.reach ? fmax(tfl, (g[0] * g[1] + rz) / ahead)
                                                       : tfl;
    }
    return (sl[0] * (1.0 - t[0]) + sl[1] * t[0]) * (1.0 - t[1]) +
           (sl[2] * (1.0 - t[0]) + sl[3] * t[0]) * t[1];
}

double hfs_cpu_grid_key_horizon(const render_ctx *c, const swath_job *job, int d, int i, int j,
                                const double n[3], double fl, double near)
{
    const hfs_horizon_plan *plan = job->plan ? job->plan : c->jobs[0].plan;
    double cs, sn;
    hfs_horizon_plan_dir(plan, d, &cs, &sn);
    const double zp = hfs_field_z(c->f, i, j) / c->f->dx;
    /* the floor's slope, as the stored tangents are clamped */
    double tfl = -(n[0] * cs + n[1] * sn) / n[2];
    tfl = tfl > 1e4 ? 1e4 : (tfl < -1e4 ? -1e4 : tfl);
    /* no grid where each texel searches its rays to the field's end */
    const double s = job->near.whole ? tfl : grid_blend(c, job, d, i, j, cs, sn, zp, tfl);
    /* the texel's own cell (its near end is no scale's sample) */
    near = fmax(near, hfs_field_first_cell_slope(c->f, i, j, cs, sn));
    for (int m = 0; job->near.per_dir && m < job->near.n; ++m)
        near = fmax(near, near_slope(c, i, j, cs, sn, exp2((double)m / c->k), zp));
    if (!job->near.per_dir && job->near.edge > job->near.to) {
        /* the direction's own ray from `to` to `edge` (issue 36 item 2) */
        double dist = 0.0;
        near = hfs_horizon_gap_along(plan, cs, sn, i, j, job->near.to, job->near.edge, 0.0, near,
                                     1, &dist, NULL);
    }
    const double om = fmax(fl, atan(fmax(s, near)));
    return om < HALF_PI ? om : HALF_PI;
}
