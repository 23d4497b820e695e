/*
 * cpu_far_grid.h — the far part of split horizons (split_horizon.h) in the
 * CPU reference: each far occluder at the receivers of the coarse grid, for
 * the K sub-directions of every environment direction, and their blend at
 * a texel.  The GLES path computes the same pairs in its far pass
 * (env_far_grid.c) and blends them by texture filtering.  The same grid,
 * one sub-direction a direction, holds the slice path's near occluders on
 * a sub-sampled visibility grid (env_horizons.frag HFS_PAIRS; cpu_grid.h).
 */
#ifndef HFS_CPU_FAR_GRID_H
#define HFS_CPU_FAR_GRID_H

#include "cpu_horizon.h"
#include "cpu_pyramid.h"
#include "split_horizon.h"
#include "visibility.h"

typedef struct hfs_cpu_far hfs_cpu_far;

/* What a grid of occluders holds: each receiver's occluder (height over
 * it, distance, texels; env_horizons.frag's pairs) in each of k
 * sub-directions of every direction of a full swath. */
typedef struct hfs_cpu_occ_desc {
    int step;        /* receivers every `step` texels, the last on the edge */
    int k;           /* sub-directions a direction (hfs_split_swath; 1: itself) */
    int first;       /* the finest scale searched, going coarser ... */
    int coarsest;    /* ... at most to this one (hfs_horizon_occluder) */
    int refine;      /* samples refining the max */
    double gap_from; /* then the gap search from this distance; < 0: none */
    int plane;       /* a texel counts a slope only where it rises above its
                        sub-direction's tangent plane (hfs_split_above_plane) */
    int heights;     /* occluders a receiver keeps per sub-direction: 1 (from
                        its own height) or HFS_SPLIT_HEIGHTS (split_horizon.h;
                        needs gap_from >= 0); 0 reads as 1 */
} hfs_cpu_occ_desc;

/* The grid desc of field f over pyramid pyr (level offset `offset`) for
 * the full swath env; tie the slope tie (hfs_horizon_tie_slope).  Computed
 * on `threads` workers.  Returns HFS_OK, HFS_E_NOMEM or HFS_E_INVALID. */
int hfs_cpu_occ_create(const hfs_field *f, const hfs_cpu_pyramid *pyr, int offset,
                       const hfs_cpu_occ_desc *desc, const hfs_swath *env, double tie,
                       int threads, hfs_cpu_far **out, hfs_error *err);

/* Split horizons' far grid (hfs_cpu_occ_create with split's far_step,
 * far_dirs, the far scales, far_refine, the gap search from far-from and
 * the plane rule); q gives the level offset. */
int hfs_cpu_far_create(const hfs_field *f, const hfs_cpu_pyramid *pyr, const hfs_quality *q,
                       const hfs_split *split, const hfs_swath *env, double tie, int threads,
                       hfs_cpu_far **out, hfs_error *err);
void hfs_cpu_far_destroy(hfs_cpu_far *g);

/* The finest scale index the near part searches up to: scales
 * 0..coarsest-1 are far (hfs_horizon_refined_within's `coarsest`). */
int hfs_cpu_far_coarsest_near(const hfs_cpu_far *g);

/* Where a texel lies on the far grid, the same for every direction: its
 * four receivers' pairs (offsets into the grid), their weights (bilinear,
 * or along an edge or at one receiver where the others stand across a
 * wall: hfs_split_far_snap), how far the receivers' blended height
 * stands above the texel, and the place the weights blend, less the
 * texel's (off: 0 but across a wall; each occluder is then that much
 * nearer or farther along its direction).  Texels. */
typedef struct hfs_cpu_far_place {
    size_t at[4];
    double wt[4];
    double dz;
    double off[2];
} hfs_cpu_far_place;
void hfs_cpu_far_place_of(const hfs_cpu_far *g, int i, int j, hfs_cpu_far_place *pl);

/* The slopes at a texel (its place pl, unit normal n) of environment
 * direction d's k sub-directions (slope[0..k-1]): each occluder blended
 * between the receivers and moved to the texel's height
 * (hfs_split_far_slope); -1e30 where there is none or (desc.plane) where
 * it does not rise above its sub-direction's tangent plane
 * (hfs_split_above_plane). */
void hfs_cpu_far_slopes(const hfs_cpu_far *g, const hfs_cpu_far_place *pl, int d,
                        const double n[3], double *slope);

#endif /* HFS_CPU_FAR_GRID_H */
