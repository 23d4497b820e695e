/*
 * cpu_local_priv.h — the CPU reference's local lights (cpu_local.h) inside:
 * the object, its per-worker scratch, and what cpu_local.c lends
 * cpu_local_grid.c (a sub-sampled visibility grid, issue 36 item 5),
 * which sits above it (cpu_local.c reads the grid, never calls it).
 * Private to those two files.
 */
#ifndef HFS_CPU_LOCAL_PRIV_H
#define HFS_CPU_LOCAL_PRIV_H

#include "cpu_horizon.h"
#include "ray_bound.h"
#include "cpu_local.h"
#include "gloss.h"
#include "local_geometry.h"
#include "visibility.h"

typedef struct local_src {
    hfs_local_light light;
    double le[3];
    int open;                  /* beyond the terrain's shadow range: ratio 1 */
} local_src;

typedef struct local_scratch {
    /* full mode: per direction d, scale s, receiver x at [(d*N + s)*W + x] */
    double *om, *co, *si;
    double *floors;            /* full mode: nphi x W */
    /* per sample */
    double *slope;             /* N */
    unsigned char *in_grid;    /* N */
    double *lv_omega;          /* N */
    double *om_k, *fl_k;       /* nphi: per-sample horizons / floors (tables) */
} local_scratch;

struct hfs_cpu_local {
    const hfs_field *f;
    int w, h, n_levels, nphi, threads;
    hfs_local_swath_mode mode;
    hfs_visibility_path path;
    int row_pass;              /* full mode: horizons of the fixed directions per row */
    double rho;                /* albedo */
    hfs_gloss gloss;           /* glossy surfaces (gloss.h) */
    double h_zonal[HFS_ZH_N];
    double E[HFS_SH_N * HFS_NLP_N];
    int n_src;
    local_src src[HFS_MAX_LOCAL_LIGHTS];
    hfs_horizon_scales *scales;
    double *dist_world;        /* N: d_s dx */
    hfs_local_swath full;      /* the full swath */
    double *full_cs;           /* nphi x (c, s), snapped */
    double *full_A;            /* nphi x 16 */
    hfs_horizon_plan *plan;    /* row pass */
    /* each sample's own ray (ray_bound.h, issue 36 item 1): the max
     * pyramid's bounds and the heights they bound, borrowed from the
     * pyramid */
    const hfs_ray_bound_layout *rb;
    const double *rb_atlas, *rb_z;
    size_t rb_stride;
    hfs_visibility *tables;    /* wedge-table path */
    local_scratch *scratch;
    /* a sub-sampled visibility grid (subsample 2, 4; issue 36 item 5):
     * each light's visible fraction at the receivers, gh x gw per light,
     * as local_visibility.frag writes it (NULL at subsample 1) */
    int sub, gw, gh;
    double *grid;
};

/* cpu_local.c: the visible fraction of the cap of view lv from receiver
 * (i, j) (normal n, H(N) hn), in the ratio form; rows: row j's full-swath
 * pass ran (its horizons may be read from the scratch). */
double hfs_cpu_local_cap_ratio(const hfs_cpu_local *lc, local_scratch *s,
                               const hfs_local_view *lv, int i, int j, const double n[3],
                               const double hn[HFS_SH_N], int rows);


#endif /* HFS_CPU_LOCAL_PRIV_H */
