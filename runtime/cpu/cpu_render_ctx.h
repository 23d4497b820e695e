/*
 * cpu_render_ctx.h — the CPU reference's per-frame state (cpu_render.c
 * shades with it, cpu_render_setup.c builds it): the swath jobs (the
 * environment's and each key light's), the workers' scratch rows, and the
 * frame's lighting in the form the texels read it; on a sub-sampled grid
 * what cpu_grid.c builds.  Private to those three files.
 */
#ifndef HFS_CPU_RENDER_CTX_H
#define HFS_CPU_RENDER_CTX_H

#include "cpu_far_grid.h"
#include "cpu_horizon.h"
#include "cpu_local.h"
#include "cpu_pyramid.h"
#include "env_map_slices.h"
#include "gloss.h"
#include "hfshade.h"
#include "key_setup.h"
#include "sh.h"
#include "slice_light.h"
#include "visibility.h"

/* One swath to trace: the environment or a key light. */
typedef struct swath_job {
    int is_env;
    hfs_swath swath;
    hfs_horizon_plan *plan;    /* NULL when shared with the environment */
    hfs_visibility *vis;       /* owned unless vis_of >= 0 */
    int vis_of;                /* job whose identical swath's object this uses */
    /* key lights */
    int shares_env;            /* horizons from the environment's row pass */
    double dir[3];             /* unit direction to the disk centre */
    double alpha;
    double le[3];              /* radiance per channel */
    double l_sh[HFS_SH_N];     /* SH of the disk, unit radiance */
    double l_norm;             /* |l_sh| */
    /* on a sub-sampled grid (cpu_grid.h) */
    hfs_key_near near;         /* the texels' near search */
    double *grid;              /* per receiver and direction: tan of the
                                  horizon, its distance (0: none) */
} swath_job;

typedef struct worker_scratch {
    double *normals;           /* W x 3 */
    double *floor_row;         /* W */
    double *maxd;              /* W */
    double *levels;            /* N x W */
    double *omega;             /* per job: n_j x W, consecutive */
    double *floors;            /* per key job: n_j x W (V_open) */
    double *om, *fl;           /* gathered per texel: max n */
    double *local_lo;          /* local lights (issue 4): W x 3, or NULL */
    double *local_sp;          /* their glossy term: W x 3 when glossy, or NULL */
    hfs_cpu_far_place *grid_pl; /* sub-sampled slice path: W places (cpu_grid.h) */
    double *key_near;          /* sub-sampled grid: W, a key light's near search */
} worker_scratch;

typedef struct render_ctx {
    const hfs_field *f;
    hfs_image *out;
    int w, h, n_levels;
    int k;                     /* the pyramid's levels per octave */
    int refine;                /* hfs_quality.refine */
    /* the visibility grid (hfs_quality.subsample; cpu_grid.h): receivers
     * every sub texels, gw x gh of them; sub 1 computes every texel as
     * its own receiver, without these */
    int sub, gw, gh;
    int key_tables;            /* key lights on the wedge-table path */
    hfs_cpu_far *near;         /* slice path: the grid's near occluders */
    double *vgrid;             /* Legendre, tables: V_env - hemisphere, 16 a receiver */
    double h_hemi[HFS_ZH_N];   /* the hemisphere's ZH (hfs_zh_cap(pi/2)) */
    double tie;                /* its absolute slope tie, hfs_horizon_tie_slope */
    double rho_pi;             /* albedo / pi */
    double h_zonal[HFS_ZH_N];  /* clamped cosine */
    double l_env[3][HFS_SH_N]; /* rotated environment */
    double env_neg[3];         /* rho * hfs_sh_negative_bound(l_env[c]) */
    const float *env_open;     /* lighting env_open (env_open.h), or NULL */
    double env_rotate;
    int n_jobs;
    swath_job *jobs;           /* jobs[0] is the environment when has_env */
    int has_env;
    int env_shared;            /* some key light shares the environment pass */
    size_t *omega_at;          /* offset of job j in worker omega/floors */
    worker_scratch *scratch;
    const hfs_cpu_local *local; /* local lights (issue 4), NULL if none */
    hfs_slice_table slices;    /* HFS_VIS_SLICE: the environment's slices (p NULL otherwise) */
    hfs_map_slices map_slices; /* the map along them (fg NULL otherwise) */
    hfs_split split;           /* split horizons (split_horizon.h) */
    hfs_cpu_far *far;          /* their far grid, NULL when not split */
    hfs_gloss gloss;           /* glossy surfaces (gloss.h) */
    float *spec;               /* W x H x 3 glossy term when gloss.on, added after the map */
    float *env_gloss;          /* env-shade = map, glossy: the map's lobe beyond order 4
                                  (env_gloss.h), NULL otherwise */
} render_ctx;

/* cpu_render_setup.c.  The jobs of the frame's environment (jobs[0], its
 * rotated SH and negative bound) and contributing key lights (key_setup.h,
 * as on GLES); c->jobs allocated by the caller. */
void hfs_cpu_ctx_add_jobs(render_ctx *c, const hfs_lighting *l, const hfs_quality *q);
/* Each job's horizon plan over the pyramid; *max_n the most directions. */
int hfs_cpu_ctx_make_plans(render_ctx *c, const hfs_cpu_pyramid *pyr, const hfs_quality *q,
                           int *max_n, hfs_error *err);
/* Each job's visibility object on `path` (identical swaths share one). */
int hfs_cpu_ctx_build_all_visibility(render_ctx *c, hfs_visibility_path path, int threads,
                                     hfs_error *err);
/* The slice path's environment: its slice table, split horizons' far grid
 * (split_horizon.h) and, with env-shade = map, the map along the slices;
 * nothing off the slice path or without an environment. */
int hfs_cpu_ctx_make_slices(render_ctx *c, const hfs_lighting *l, const hfs_quality *q,
                            const hfs_cpu_pyramid *pyr, int threads, hfs_error *err);
/* The workers' scratch rows and the jobs' offsets into them. */
int hfs_cpu_ctx_alloc_scratch(render_ctx *c, int threads, int max_n, hfs_error *err);
void hfs_cpu_ctx_free_scratch(worker_scratch *s);

#endif /* HFS_CPU_RENDER_CTX_H */
