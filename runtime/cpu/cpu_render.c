/*
 * cpu_render.c — hfs_cpu_render (backends.h): the CPU reference of
 * DESIGN.md, in double precision, rows in parallel, bit-identical for any
 * thread count (each row is computed by one worker from immutable shared
 * state plus that worker's scratch).
 *
 * Per frame:
 *   1. the height pyramid, reconstructing only the levels the horizon pass
 *      reads (min(k*o, N-1)..N-1);
 *   2. per swath (the environment's full swath, one per key light): a horizon
 *      plan (receiver-independent sample offsets) and a visibility object
 *      (folded Legendre matrices or wedge tables);
 *   3. per row, per direction: horizons of the whole row (environment: fast
 *      level max; key lights: B-spline max over scale), floors from the
 *      row's normals; on a sub-sampled visibility grid (subsample 2, 4)
 *      the horizons from the grid's receivers as the GLES path forms them
 *      (cpu_grid.h, built once per frame: trace_row_grid, env_texel);
 *   4. per texel: H(N), then
 *        environment  Lo += rho/pi * (H * V_env) . L_env          (per channel)
 *        key light    Lo += rho/pi * Le * E_cap(N.d, alpha) * clamp(num/den, 0, 1)
 *                     num = (H * V_key) . L_key, den = (H * V_open) . L_key,
 *      where L_key is the SH of the light's disk with unit radiance (the
 *      ratio does not depend on the radiance) and V_open is the same swath
 *      with every horizon at the floor.  Both products use
 *      (H * V) . L = V . (H * L) (the triple-product tensor is symmetric), so
 *      one product H * L_key per texel serves num and den.
 *   A key light whose swath is the environment's (a pole-covering disk with
 *   nphi_key <= nphi_env) shares the environment's pyramid reads, and jobs
 *   with identical swaths share one visibility object (tables are built in
 *   parallel, ~0.1 s each).
 *
 * Memory: (N - min(k*o, N-1)) reconstructed levels of (W+1)(H+1) doubles
 * plus, per worker, rows of horizons; a glossy frame its W x H x 3 term.
 * Glossy surfaces (gloss.h): each texel's lobe term goes to c->spec, added
 * after the albedo map (the lobe is not the albedo's).
 *
 * Deliberate choices (also in DESIGN.md "Shading"): den counts as zero when
 * den <= 1e-12 |L_key| |V_open| (scales with the swath, so a tiny alpha keeps
 * its light); a disk wholly below the tangent plane (E_cap = 0) skips the
 * visibility work.  subsample is honoured (subsample 1: every texel its
 * own receiver; 2 and 4: cpu_grid.h, DESIGN.md "One reference at every
 * subsample", which also says where the CPU still differs from GLES
 * there: fp16 storage, float grid coordinates, ties of the occluders'
 * distances; local lights on the grid too, cpu_local_grid.c; the bounces
 * stay per texel);
 * precision is the GLES path's only (the CPU is double throughout).
 *
 * Local lights (issue 4) live in cpu_local.c (DESIGN.md "Local lights"); this
 * file only hooks them in, marked "local lights (issue 4)": the module is
 * created after the pyramid, fills a per-worker row of their exit radiance
 * right after the row's normals (hfs_cpu_local_row), and each texel adds it
 * last.  hfs_cpu_render_with (cpu_local.h) takes the local-light options;
 * hfs_cpu_render uses the defaults.
 */
#include "albedo.h"
#include "cpu_render_ctx.h"
#include "env_map_slices.h"
#include "env_open.h"
#include "backends.h"
#include "cpu_grid.h"
#include "cpu_horizon.h"
#include "cpu_local.h"
#include "cpu_pyramid.h"
#include "key_setup.h"
#include "slice_light.h"
#include "visibility.h"
#include "cpu_bounce.h"
#include "field_geom.h"
#include "env_gloss.h"
#include "gloss.h"
#include "lights.h"
#include "parallel.h"
#include "pyramid_layout.h"
#include "sh.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

/* The environment's exit radiance lies in [-neg, open + neg]: open = rho/pi
 * H.L is the unshadowed value and neg = rho * (negative part of L), 0 for a
 * non-negative sky; visibility in [0, 1] can only remove light (or negative
 * light).  Order-4 truncation of the product, and on the GLES path
 * sub-sampling and fp16 storage, can step outside (a uniform sky of 1 gave
 * 1.02 on 1e4 slopes at subsample 2); clamping into an interval that holds
 * the exact value never moves a result away from it. */
static double env_clamp(double v, double open, double neg)
{
    const double lo = -neg, hi = open + neg;
    return v < lo ? lo : (v > hi ? hi : v);
}

/* Converts a radiance to the output type; finite for any finite input. */
static float to_output(double v)
{
    if (!(v == v))
        return 0.0f; /* unreachable for validated inputs; keeps the contract */
    if (v > FLT_MAX)
        return FLT_MAX;
    if (v < -FLT_MAX)
        return -FLT_MAX;
    return (float)v;
}

static double norm16(const double v[HFS_SH_N])
{
    return sqrt(hfs_sh_dot(v, v));
}

/* hfs_horizon_tie_slope of field f. */
static double tie_slope(const hfs_field *f)
{
    double lo, hi;
    hfs_field_range(f, &lo, &hi);
    return hfs_horizon_tie_slope(0.5 * hi - 0.5 * lo, f->zscale, f->dx);
}

/* A key light's horizon at receiver (i, j) in direction d of plan from the
 * row's per-scale angles: SN08's B-spline max (refine 0) or the max
 * refined between scales and searched in every gap between them
 * (cpu_horizon.h). */
static double key_horizon(const render_ctx *c, const hfs_horizon_plan *plan, int d, int i,
                          int j, const double *levels, double floor)
{
    /* The receiver's own cell: its near end's slope is no scale's sample
     * (issue 36: on texel-scale relief the sun was seen through it). */
    double cs, sn;
    hfs_horizon_plan_dir(plan, d, &cs, &sn);
    const double own = atan(hfs_field_first_cell_slope(c->f, i, j, cs, sn));
    if (c->refine <= 0)
        return fmax(own, hfs_horizon_bspline_max(levels + i, c->n_levels, (size_t)c->w, floor));
    const double o = hfs_horizon_refined(plan, d, i, j, levels + i, (size_t)c->w, floor,
                                         c->refine, c->tie, NULL, 0);
    /* and every band between the scales (issue 36: no narrow occluder's
     * long shadow is lost) */
    double dist = 0.0;
    const double t = tan(o), g = hfs_horizon_gap(plan, d, i, j, 0.0, c->tie, t, 1, &dist, NULL);
    return fmax(own, g > t ? atan(g) : o);
}

/* Split horizons (split_horizon.h): direction d's sub-horizons at a texel
 * (its far place pl), max(near om, each far slope's elevation), into
 * x[0..k-1]. */
static int sub_horizons(const render_ctx *c, const hfs_cpu_far_place *pl, int d,
                        const double n[3], double om, double *x)
{
    double fs[HFS_SPLIT_MAX_K];
    hfs_cpu_far_slopes(c->far, pl, d, n, fs);
    for (int h = 0; h < c->split.k; ++h) {
        const double a = atan(fs[h]);
        x[h] = a > om ? a : om;
    }
    return c->split.k;
}

/* The environment's exit radiance at texel (i, j) (normal n, H(N) hn),
 * added to lo; its glossy term to sp when the surface is (nr > 0). */
static void env_texel(const render_ctx *c, worker_scratch *s, const swath_job *job,
                      const double *omega, int i, int j, const double n[3],
                      const double hn[HFS_SH_N], double nr, const double r[3], double lo[3],
                      double sp[3])
{
    const int nd = job->swath.n, w = c->w;
    /* With the map's own slices the SH's occluded part is needed only by
     * the glossy lobe (hfs_gloss_env). */
    const int map = c->map_slices.fg != NULL, need_t = !map || nr > 0.0;
    double v[HFS_SH_N], t[HFS_SH_N], x[HFS_SPLIT_MAX_K];
    /* env-shade = map: the open sky beyond order 4, and with the map's
     * slices the occluded part from the map instead of the SH. */
    double e[3] = {0.0, 0.0, 0.0};
    if (c->env_open)
        hfs_env_open_lookup(c->env_open, n, c->env_rotate, e);
    if (c->slices.p) { /* exact slice lighting (slice_light.h) */
        memcpy(t, hn, sizeof t); /* the open hemisphere, exactly */
        hfs_cpu_far_place pl; /* split horizons: once per texel */
        if (c->far)
            hfs_cpu_far_place_of(c->far, i, j, &pl);
        for (int d = 0; d < nd; ++d) {
            const double om = omega[(size_t)d * w + i];
            const int nx = c->far ? sub_horizons(c, &pl, d, n, om, x) : (x[0] = om, 1);
            if (need_t)
                hfs_slice_add_occluded_mean(&c->slices, d, n, x, nx, t);
            if (map)
                hfs_map_slices_occluded_mean(&c->map_slices, d, n, x, nx, e);
        }
    } else {
        if (c->vgrid) { /* a sub-sampled grid (cpu_grid.h) */
            hfs_cpu_grid_env_v(c, i, j, n, v);
        } else {
            for (int d = 0; d < nd; ++d)
                s->om[d] = omega[(size_t)d * w + i];
            hfs_visibility_eval(job->vis, s->om, v);
        }
        hfs_sh_product(hn, v, t);
    }
    for (int ch = 0; ch < 3; ++ch)
        lo[ch] += env_clamp(c->rho_pi * (hfs_sh_dot(map ? hn : t, c->l_env[ch]) + e[ch]),
                            c->rho_pi * (hfs_sh_dot(hn, c->l_env[ch]) + e[ch]), c->env_neg[ch]);
    if (nr > 0.0) {
        double dg[3]; /* the map's lobe beyond order 4 (env_gloss.h) */
        if (c->env_gloss)
            hfs_env_gloss_lookup(c->env_gloss, r, c->env_rotate, dg);
        hfs_gloss_env(&c->gloss, nr, r, t, hn, c->l_env, c->env_gloss ? dg : NULL, sp);
    }
}

/* trace_row on a sub-sampled grid (cpu_grid.h): the slice path's
 * horizons from the grid's near occluders, each key light's from its
 * grid and its near search; Legendre and tables read V from the grid in
 * env_texel. */
static void trace_row_grid(const render_ctx *c, worker_scratch *s, int j)
{
    const int w = c->w;
    if (c->near)
        hfs_cpu_grid_env_places(c, s, j);
    for (int q = 0; q < c->n_jobs; ++q) {
        const swath_job *job = &c->jobs[q];
        if (job->is_env && !c->near)
            continue;
        const hfs_horizon_plan *plan = job->plan ? job->plan : c->jobs[0].plan;
        for (int i = 0; !job->is_env && i < w; ++i)
            s->key_near[i] = hfs_cpu_grid_key_near(c, job, i, j);
        for (int d = 0; d < job->swath.n; ++d) {
            double cs, sn;
            hfs_horizon_plan_dir(plan, d, &cs, &sn);
            double *fl = job->is_env ? s->floor_row : s->floors + c->omega_at[q] + (size_t)d * w;
            double *om = s->omega + c->omega_at[q] + (size_t)d * w;
            for (int i = 0; i < w; ++i)
                fl[i] = hfs_horizon_floor(s->normals + 3 * i, cs, sn);
            if (job->is_env)
                hfs_cpu_grid_env_row(c, s, d, j, fl, om);
            for (int i = 0; !job->is_env && i < w; ++i)
                om[i] = hfs_cpu_grid_key_horizon(c, job, d, i, j, s->normals + 3 * i, fl[i],
                                                 s->key_near[i]);
        }
    }
}

/* Horizons of row j for every job: omega (and, for key lights, the floors
 * that make V_open).  Directions are traced one at a time over the whole row
 * so that each (direction, scale) streams through contiguous memory. */
static void trace_row(const render_ctx *c, worker_scratch *s, int j)
{
    const int w = c->w;
    if (c->sub > 1) {
        trace_row_grid(c, s, j);
        return;
    }
    for (int q = 0; q < c->n_jobs; ++q) {
        const swath_job *job = &c->jobs[q];
        if (job->shares_env)
            continue; /* filled during the environment's pass */
        const int want_levels = !job->is_env || c->env_shared;
        double *omega = s->omega + c->omega_at[q];
        double *floors = s->floors + c->omega_at[q];
        for (int d = 0; d < job->swath.n; ++d) {
            double cs, sn;
            hfs_horizon_plan_dir(job->plan, d, &cs, &sn);
            double *fl = job->is_env ? s->floor_row : floors + (size_t)d * w;
            for (int i = 0; i < w; ++i)
                fl[i] = hfs_horizon_floor(s->normals + 3 * i, cs, sn);
            /* Split horizons need the per-scale angles (the near part's
             * range), refined or not. */
            const int env_refined = job->is_env && (c->refine > 0 || c->far);
            hfs_horizon_row(job->plan, d, j, fl, job->is_env && !env_refined ? s->maxd : NULL,
                            want_levels || env_refined ? s->levels : NULL);
            double *om = omega + (size_t)d * w;
            if (!job->is_env) {
                for (int i = 0; i < w; ++i)
                    om[i] = key_horizon(c, job->plan, d, i, j, s->levels, fl[i]);
                continue;
            }
            /* Exact slices search the receiver's own cell exactly instead
             * of the finest scale, which lies in it (as the GLES path). */
            const int own_cell = c->slices.p != NULL;
            const int coarsest = c->far ? hfs_cpu_far_coarsest_near(c->far) : 0;
            const int refine = c->far ? c->split.near_refine : c->refine;
            for (int i = 0; i < w; ++i) {
                const double fls = hfs_horizon_floor_slope(s->normals + 3 * i, cs, sn);
                om[i] = env_refined
                            ? hfs_horizon_refined_within(job->plan, d, i, j, s->levels + i,
                                                         (size_t)w, fl[i], refine, c->tie, &fls,
                                                         own_cell, coarsest)
                            : hfs_horizon_env_from_maxd(s->maxd[i], fl[i]);
            }
            if (own_cell)
                for (int i = 0; i < w; ++i)
                    om[i] = fmax(om[i], atan(hfs_field_first_cell_slope(c->f, i, j, cs, sn)));
            /* Key lights on the environment's swath: same reads, B-spline max. */
            for (int r = 0; r < c->n_jobs; ++r) {
                if (!c->jobs[r].shares_env)
                    continue;
                double *kom = s->omega + c->omega_at[r] + (size_t)d * w;
                double *kfl = s->floors + c->omega_at[r] + (size_t)d * w;
                for (int i = 0; i < w; ++i) {
                    kfl[i] = fl[i];
                    kom[i] = key_horizon(c, job->plan, d, i, j, s->levels, fl[i]);
                }
            }
        }
    }
}

static void render_row(void *ctx, int j, int worker)
{
    const render_ctx *c = ctx;
    worker_scratch *s = &c->scratch[worker];
    const int w = c->w;

    for (int i = 0; i < w; ++i)
        hfs_field_normal(c->f, i, j, s->normals + 3 * i);
    trace_row(c, s, j);
    if (c->local) /* local lights (issue 4) */
        hfs_cpu_local_row(c->local, worker, j, s->normals, s->local_lo, s->local_sp);

    float *dst = c->out->rgb + (size_t)j * (size_t)w * 3;
    for (int i = 0; i < w; ++i) {
        const double *n = s->normals + 3 * i;
        double hn[HFS_SH_N];
        hfs_sh_rotate_zonal(c->h_zonal, n[0], n[1], n[2], hn);
        double lo[3] = {0.0, 0.0, 0.0};
        double r[3] = {0.0, 0.0, 1.0}, sp[3] = {0.0, 0.0, 0.0}; /* glossy: R and the term */
        const double pw[3] = {i * c->f->dx, j * c->f->dx, hfs_field_z(c->f, i, j)};
        const double nr = c->gloss.on ? hfs_gloss_reflect(&c->gloss, pw, n, r) : 0.0;
        for (int q = 0; q < c->n_jobs; ++q) {
            const swath_job *job = &c->jobs[q];
            const int nd = job->swath.n;
            const double *omega = s->omega + c->omega_at[q];
            if (job->is_env) {
                env_texel(c, s, job, omega, i, j, n, hn, nr, r, lo, sp);
                continue;
            }
            const double cos_beta = n[0] * job->dir[0] + n[1] * job->dir[1] + n[2] * job->dir[2];
            const double e_cap = hfs_cap_irradiance(cos_beta, job->alpha);
            if (!(e_cap > 0.0))
                continue;
            const double *floors = s->floors + c->omega_at[q];
            for (int d = 0; d < nd; ++d) {
                s->om[d] = omega[(size_t)d * w + i];
                s->fl[d] = floors[(size_t)d * w + i];
            }
            double vk[HFS_SH_N], vo[HFS_SH_N], m[HFS_SH_N];
            hfs_visibility_eval(job->vis, s->om, vk);
            hfs_visibility_eval(job->vis, s->fl, vo);
            hfs_sh_product(hn, job->l_sh, m);
            const double num = hfs_sh_dot(vk, m), den = hfs_sh_dot(vo, m);
            double ratio = 0.0;
            if (den > 1e-12 * job->l_norm * norm16(vo)) {
                ratio = num / den;
                ratio = ratio < 0.0 ? 0.0 : (ratio > 1.0 ? 1.0 : ratio);
            }
            for (int ch = 0; ch < 3; ++ch)
                lo[ch] += c->rho_pi * job->le[ch] * e_cap * ratio;
            /* Glossy: the lobe at the disk's centre times its visible
             * cosine-weighted solid angle (DESIGN.md "Glossy surfaces"). */
            const double gk = nr > 0.0 ? c->gloss.ks * e_cap * ratio *
                                         hfs_gloss_lobe(&c->gloss, r, job->dir) : 0.0;
            for (int ch = 0; ch < 3; ++ch)
                sp[ch] += gk * job->le[ch];
        }
        if (c->local) /* local lights (issue 4) */
            for (int ch = 0; ch < 3; ++ch)
                lo[ch] += s->local_lo[3 * i + ch];
        for (int ch = 0; ch < 3; ++ch)
            dst[3 * i + ch] = to_output(lo[ch]);
        for (int ch = 0; ch < 3 && c->spec; ++ch)
            c->spec[3 * ((size_t)j * w + i) + ch] =
                to_output(sp[ch] + (s->local_sp ? s->local_sp[3 * i + ch] : 0.0));
    }
}

int hfs_cpu_render(const hfs_field *f, const hfs_lighting *l,
                   const hfs_quality *q, hfs_image *out,
                   hfs_progress_fn progress, void *user, hfs_error *err)
{
    hfs_cpu_local_options lo;
    hfs_cpu_local_options_default(&lo);
    lo.swath = q->local_full_swath ? HFS_LOCAL_SWATH_FULL : HFS_LOCAL_SWATH_PARTIAL;
    int rc = hfs_cpu_render_with(f, l, q, &lo, out, l->bounces > 0 ? NULL : progress, user, err);
    if (!rc && l->bounces > 0) /* indirect light (cpu_bounce.h) */
        rc = hfs_cpu_bounces(f, l, q, l->bounces, out->rgb, progress, user, err);
    return rc;
}

/* Workers: the quality's count (else the machine's), at most 64
 * (hfs_parallel_rows' own cap) and at most one per row. */
static int worker_count(const hfs_quality *q, int rows)
{
    int threads = q->threads > 0 ? q->threads : hfs_parallel_default_threads();
    if (threads > 64)
        threads = 64;
    if (threads > rows)
        threads = rows;
    return threads;
}

/* What every row reads, built once per frame: the swath jobs, the pyramid
 * (*pyr), the plans and visibility objects, the slices, the local lights,
 * each worker's scratch and the glossy term.  On failure the caller frees
 * what was built (free_frame). */
static int build_frame(render_ctx *c, const hfs_lighting *l, const hfs_quality *q,
                       const hfs_cpu_local_options *local_opt, int n_key, int n_local,
                       int threads, hfs_cpu_pyramid **pyr, hfs_error *err)
{
    const hfs_field *f = c->f;
    /* + 1: a frame may have local lights only (no swath job). */
    c->jobs = calloc((size_t)(c->has_env + n_key) + 1, sizeof *c->jobs);
    c->omega_at = calloc((size_t)(c->has_env + n_key) + 1, sizeof *c->omega_at);
    if (!c->jobs || !c->omega_at)
        return hfs_fail(err, HFS_E_NOMEM, "backend cpu: out of memory");
    hfs_cpu_ctx_add_jobs(c, l, q);

    /* Pyramid, plans, visibility. */
    const int n_levels = hfs_pyramid_level_count(c->w, c->h, q->k);
    c->n_levels = n_levels;
    c->k = q->k;
    c->sub = q->subsample > 1 ? q->subsample : 1;
    c->key_tables = q->visibility == HFS_VIS_WEDGE_TABLE;
    c->refine = q->refine;
    c->tie = tie_slope(f);
    int rc = hfs_cpu_pyramid_create(f, q->k, hfs_pyramid_read_level(n_levels, q->k, q->offset, 0),
                                    threads, pyr, err);
    if (rc)
        return rc;
    int max_n = 1;
    if ((rc = hfs_cpu_ctx_make_plans(c, *pyr, q, &max_n, err)))
        return rc;
    /* Slice lighting: the environment's slices; key lights keep Legendre. */
    const int slice = q->visibility == HFS_VIS_SLICE;
    if ((rc = hfs_cpu_ctx_build_all_visibility(c, slice ? HFS_VIS_LEGENDRE : q->visibility, threads, err)) ||
        (rc = hfs_cpu_ctx_make_slices(c, l, q, *pyr, threads, err)))
        return rc;

    /* Local lights (issue 4): NULL when none contributes. */
    if (n_local > 0) {
        hfs_cpu_local *local = NULL;
        rc = hfs_cpu_local_create(f, l, q, local_opt, *pyr, threads, &local, err);
        c->local = local;
        if (!rc && local && c->sub > 1) /* a sub-sampled grid */
            rc = hfs_cpu_local_grid_build(local, c->sub, threads, err);
        if (rc)
            return rc;
    }
    if ((rc = hfs_cpu_ctx_alloc_scratch(c, threads, max_n, err)) ||
        (rc = hfs_cpu_grid_build(c, q, *pyr, threads, err))) /* a sub-sampled grid */
        return rc;
    if (c->gloss.on && !(c->spec = malloc((size_t)c->w * (size_t)c->h * 3 * sizeof *c->spec)))
        return hfs_fail(err, HFS_E_NOMEM, "backend cpu: out of memory for the glossy term");
    /* env-shade = map: the lobe from the map itself (env_gloss.h), of the
     * map whose projection l_env is. */
    if (c->gloss.on && c->has_env && l->env_shade_map && l->env_open) {
        if (!(c->env_gloss = malloc(HFS_ENV_GLOSS_FLOATS * sizeof *c->env_gloss)))
            return hfs_fail(err, HFS_E_NOMEM, "backend cpu: out of memory for the glossy table");
        rc = hfs_env_gloss_build(l->env_shade_map, l->env_map_width, l->env_map_height,
                                 (const double(*)[HFS_SH_COEFFS])l->env_sh, c->gloss.s,
                                 c->env_gloss, err);
    }
    return rc;
}

/* Frees what build_frame built (any part of it). */
static void free_frame(render_ctx *c, int threads, hfs_cpu_pyramid *pyr)
{
    hfs_cpu_local_destroy((hfs_cpu_local *)c->local); /* local lights (issue 4) */
    if (c->scratch)
        for (int t = 0; t < threads; ++t)
            hfs_cpu_ctx_free_scratch(&c->scratch[t]);
    free(c->scratch);
    for (int j = 0; j < c->n_jobs; ++j) {
        hfs_horizon_plan_destroy(c->jobs[j].plan);
        if (c->jobs[j].vis_of < 0)
            hfs_visibility_destroy(c->jobs[j].vis);
    }
    hfs_cpu_far_destroy(c->far);
    hfs_cpu_grid_free(c);
    hfs_slice_table_free(&c->slices);
    hfs_map_slices_free(&c->map_slices);
    free(c->env_gloss);
    free(c->spec);
    free(c->jobs);
    free(c->omega_at);
    hfs_cpu_pyramid_destroy(pyr);
}

int hfs_cpu_render_with(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                        const hfs_cpu_local_options *local_opt, hfs_image *out,
                        hfs_progress_fn progress, void *user, hfs_error *err)
{
    if (!f || !l || !q || !out || !out->rgb || !f->z || f->width < 2 || f->height < 2 ||
        out->width != f->width || out->height != f->height)
        return hfs_fail(err, HFS_E_INVALID, "backend cpu: invalid field, lighting or output");
    if (q->k < 1 || q->offset < 0 || q->nphi_env < 1 || q->nphi_key < 1)
        return hfs_fail(err, HFS_E_INVALID, "backend cpu: quality k=%d offset=%d nphi_env=%d "
                        "nphi_key=%d out of range", q->k, q->offset, q->nphi_env, q->nphi_key);

    const int w = f->width, h = f->height;
    render_ctx c;
    memset(&c, 0, sizeof c);
    c.f = f;
    c.out = out;
    c.w = w;
    c.h = h;
    c.rho_pi = l->albedo / PI;
    hfs_zh_clamped_cosine(c.h_zonal);
    const int threads = worker_count(q, h);

    /* Which lights contribute. */
    const int has_env = hfs_env_contributes(l);
    int n_key = 0;
    for (int i = 0; i < l->n_key && i < HFS_MAX_KEY_LIGHTS; ++i)
        n_key += hfs_key_light_contributes(&l->key[i], l->albedo + l->specular);
    int n_local = 0; /* local lights (issue 4) */
    for (int i = 0; i < l->n_local && i < HFS_MAX_LOCAL_LIGHTS; ++i)
        n_local += hfs_local_light_contributes(&l->local[i]);
    hfs_gloss_make(l, &c.gloss);
    if ((!has_env && n_key == 0 && n_local == 0) || !(l->albedo > 0.0 || c.gloss.on)) {
        memset(out->rgb, 0, (size_t)w * (size_t)h * 3 * sizeof *out->rgb);
        if (progress)
            progress(user, 1.0);
        return HFS_OK;
    }

    c.has_env = has_env;
    hfs_cpu_pyramid *pyr = NULL;
    const int rc = build_frame(&c, l, q, local_opt, n_key, n_local, threads, &pyr, err);
    if (!rc) {
        hfs_parallel_rows(h, threads, render_row, &c, progress, user);
        hfs_albedo_map_apply(l->albedo_map, out);
        for (size_t p = 0; c.spec && p < (size_t)w * (size_t)h * 3; ++p)
            out->rgb[p] += c.spec[p]; /* the lobe is not the albedo's */
    }
    free_frame(&c, threads, pyr);
    return rc;
}
