/*
 * cpu_render_setup.c — the CPU reference's per-frame state, built before the
 * rows are shaded (cpu_render_ctx.h): swath jobs, horizon plans,
 * visibility objects, scratch.
 */
#include "cpu_render_ctx.h"

#include "key_setup.h"
#include "lights.h"
#include "parallel.h"

#include <stdlib.h>
#include <string.h>

typedef struct vis_build {
    swath_job *jobs;
    hfs_visibility_path path;
    int *rc;
    hfs_error *err;
} vis_build;

static void build_visibility(void *ctx, int row, int worker)
{
    vis_build *b = ctx;
    (void)worker;
    if (b->jobs[row].vis_of >= 0)
        return; /* shares an identical swath's object */
    b->rc[row] = hfs_visibility_create(&b->jobs[row].swath, b->path, &b->jobs[row].vis,
                                       &b->err[row]);
}

static int same_swath(const hfs_swath *a, const hfs_swath *b)
{
    return a->n == b->n && a->full == b->full && a->phi0 == b->phi0 && a->dphi == b->dphi &&
           a->elev_lo == b->elev_lo && a->elev_hi == b->elev_hi;
}

void hfs_cpu_ctx_free_scratch(worker_scratch *s)
{
    free(s->normals);
    free(s->floor_row);
    free(s->maxd);
    free(s->levels);
    free(s->omega);
    free(s->floors);
    free(s->om);
    free(s->fl);
    free(s->local_lo);
    free(s->local_sp);
    free(s->grid_pl);
    free(s->key_near);
}

/* The swath jobs: the environment's (jobs[0]) and each contributing key
 * light's (key_setup.h, as on GLES). */
void hfs_cpu_ctx_add_jobs(render_ctx *c, const hfs_lighting *l, const hfs_quality *q)
{
    if (c->has_env) {
        swath_job *job = &c->jobs[c->n_jobs++];
        job->vis_of = -1;
        job->is_env = 1;
        hfs_swath_full(q->nphi_env, &job->swath);
        hfs_env_rotated(l, c->l_env);
        c->env_open = l->env_open;
        c->env_rotate = l->env_rotate;
        for (int ch = 0; ch < 3; ++ch)
            c->env_neg[ch] = l->albedo * hfs_sh_negative_bound(c->l_env[ch]);
    }
    for (int i = 0; i < l->n_key && i < HFS_MAX_KEY_LIGHTS; ++i) {
        const hfs_key_light *k = &l->key[i];
        if (!hfs_key_light_contributes(k, l->albedo + l->specular))
            continue;
        swath_job *job = &c->jobs[c->n_jobs++];
        job->vis_of = -1;
        /* The swath and the visible fraction see at least HFS_MIN_VIS_ALPHA
         * (key_setup.h), as on GLES; E_cap keeps alpha. */
        hfs_key_setup ks;
        hfs_key_setup_make(k, q, &ks);
        job->swath = ks.swath;
        memcpy(job->dir, ks.dir, sizeof job->dir);
        job->alpha = ks.alpha;
        memcpy(job->le, ks.le, sizeof job->le);
        memcpy(job->l_sh, ks.l_sh, sizeof job->l_sh);
        job->l_norm = ks.l_norm;
        /* A full swath identical to the environment's reuses its reads. */
        job->shares_env = c->has_env && job->swath.full && job->swath.n == c->jobs[0].swath.n &&
                          job->swath.phi0 == c->jobs[0].swath.phi0;
        c->env_shared |= job->shares_env;
    }
}

/* Each job's horizon plan (shared with the environment where the swath
 * is its own) and the worker offsets; *max_n = the most samples a job has. */
int hfs_cpu_ctx_make_plans(render_ctx *c, const hfs_cpu_pyramid *pyr, const hfs_quality *q,
                      int *max_n, hfs_error *err)
{
    const int w = c->w;
    *max_n = 1;
    for (int j = 0; j < c->n_jobs; ++j) {
        swath_job *job = &c->jobs[j];
        const int nd = job->swath.n;
        *max_n = nd > *max_n ? nd : *max_n;
        c->omega_at[j + 1] = c->omega_at[j] + (size_t)nd * (size_t)w;
        if (!job->shares_env) {
            double *phi = malloc((size_t)nd * sizeof *phi);
            if (!phi)
                return hfs_fail(err, HFS_E_NOMEM, "backend cpu: out of memory");
            for (int d = 0; d < nd; ++d)
                phi[d] = hfs_swath_phi(&job->swath, d);
            const int rc = hfs_horizon_plan_create(pyr, c->f->dx, c->f->zscale, q->offset, phi, nd,
                                                   &job->plan, err);
            free(phi);
            if (rc)
                return rc;
        }
    }
    return HFS_OK;
}

/* Visibility objects, one per distinct swath (the wedge tables take ~0.1 s
 * each): one job per parallel "row". */
int hfs_cpu_ctx_build_all_visibility(render_ctx *c, hfs_visibility_path path, int threads,
                                hfs_error *err)
{
    int rc = HFS_OK;
    vis_build vb = {.jobs = c->jobs, .path = path};
    const size_t n_jobs = (size_t)c->n_jobs;
    vb.rc = calloc(n_jobs + 1, sizeof *vb.rc);
    vb.err = calloc(n_jobs + 1, sizeof *vb.err);
    if (!vb.rc || !vb.err) {
        free(vb.rc);
        free(vb.err);
        return hfs_fail(err, HFS_E_NOMEM, "backend cpu: out of memory");
    }
    for (int j = 0; j < c->n_jobs; ++j) {
        for (int r = 0; r < j && c->jobs[j].vis_of < 0; ++r)
            if (c->jobs[r].vis_of < 0 && same_swath(&c->jobs[r].swath, &c->jobs[j].swath))
                c->jobs[j].vis_of = r;
    }
    hfs_parallel_rows(c->n_jobs, threads, build_visibility, &vb, NULL, NULL);
    for (int j = 0; j < c->n_jobs && !rc; ++j)
        if (vb.rc[j]) {
            rc = vb.rc[j];
            if (err)
                *err = vb.err[j];
        }
    for (int j = 0; j < c->n_jobs; ++j)
        if (c->jobs[j].vis_of >= 0)
            c->jobs[j].vis = c->jobs[c->jobs[j].vis_of].vis;
    free(vb.rc);
    free(vb.err);
    return rc;
}

/* Per-worker scratch (freed with the context, also on failure). */
int hfs_cpu_ctx_alloc_scratch(render_ctx *c, int threads, int max_n, hfs_error *err)
{
    const int w = c->w;
    const hfs_cpu_local *local = c->local;
    c->scratch = calloc((size_t)threads, sizeof *c->scratch);
    if (!c->scratch)
        return hfs_fail(err, HFS_E_NOMEM, "backend cpu: out of memory");
    const size_t total = c->omega_at[c->n_jobs];
    for (int t = 0; t < threads; ++t) {
        worker_scratch *s = &c->scratch[t];
        s->normals = malloc((size_t)w * 3 * sizeof(double));
        s->floor_row = malloc((size_t)w * sizeof(double));
        s->maxd = malloc((size_t)w * sizeof(double));
        s->levels = malloc((size_t)c->n_levels * (size_t)w * sizeof(double));
        s->omega = malloc((total + 1) * sizeof(double));
        s->floors = malloc((total + 1) * sizeof(double));
        s->om = malloc((size_t)max_n * sizeof(double));
        s->fl = malloc((size_t)max_n * sizeof(double));
        if (local) /* local lights (issue 4) */
            s->local_lo = malloc((size_t)w * 3 * sizeof(double));
        if (local && c->gloss.on)
            s->local_sp = malloc((size_t)w * 3 * sizeof(double));
        const int grid = c->sub > 1, near = grid && c->slices.p; /* cpu_grid.h */
        if (near)
            s->grid_pl = malloc((size_t)w * sizeof *s->grid_pl);
        if (grid)
            s->key_near = malloc((size_t)w * sizeof *s->key_near);
        if ((near && !s->grid_pl) || (grid && !s->key_near) || !s->normals || !s->floor_row || !s->maxd || !s->levels || !s->omega ||
            !s->floors || !s->om || !s->fl || (local && !s->local_lo) ||
            (local && c->gloss.on && !s->local_sp))
            return hfs_fail(err, HFS_E_NOMEM, "backend cpu: out of memory for %d workers",
                            threads);
    }
    return HFS_OK;
}

int hfs_cpu_ctx_make_slices(render_ctx *c, const hfs_lighting *l, const hfs_quality *q,
                            const hfs_cpu_pyramid *pyr, int threads, hfs_error *err)
{
    if (q->visibility != HFS_VIS_SLICE || !c->has_env)
        return HFS_OK;
    const hfs_swath *env = &c->jobs[0].swath;
    int rc = hfs_slice_table_init(&c->slices, env, err);
    hfs_split_make(q, &c->split);
    if (!rc && c->split.on)
        rc = hfs_cpu_far_create(c->f, pyr, q, &c->split, env, c->tie, threads, &c->far, err);
    if (!rc && l->env_shade_map && l->env_open)
        rc = hfs_map_slices_build(&c->map_slices, l->env_shade_map, l->env_map_width,
                                  l->env_map_height, l->env_rotate, c->slices.dir, c->slices.n,
                                  c->slices.dphi, err);
    return rc;
}
