/*
 * pyramid_layout.h — the layout of the height pyramid of DESIGN.md ("Height
 * pyramid"), shared by the CPU reference (cpu_pyramid.h), the GLES path
 * (runtime/gles/layout.c) and the benchmarks, so that every backend uses and reports
 * the same numbers.  Pure functions, no allocation.
 *
 *   n = max(W, H), b = 2^(1/k), N = ceil(k log2 n) + 1 levels, index 0..N-1,
 *   level N-1 finest (the input itself).  Level i has texel spacing
 *   s_i = b^(N-1-i) input texels and size Wl = max(1, ceil(W/s_i)),
 *   Hl = max(1, ceil(H/s_i)).  Every level covers the same domain with
 *   texture-style addressing: texel t of a level of width Wl is centred at
 *   u = (t + 0.5)/Wl, full-resolution grid point i at u = (i + 0.5)/W; reads
 *   clamp to the edge.
 */
#ifndef HFS_PYRAMID_LAYOUT_H
#define HFS_PYRAMID_LAYOUT_H

/* N = ceil(k log2 max(w, h)) + 1 (k >= 1, w, h >= 1). */
int hfs_pyramid_level_count(int w, int h, int k);

/* s_i = 2^((N-1-i)/k): texel spacing of level i in input texels (and the
 * horizon distance d_i of DESIGN.md). */
double hfs_pyramid_spacing(int n_levels, int k, int level);

/* Size of level i: max(1, ceil(w/s_i)) x max(1, ceil(h/s_i)). */
void hfs_pyramid_level_size(int w, int h, int k, int level, int *lw, int *lh);

/* Level read for horizon scale i with level offset o: min(i + k*o, N-1),
 * and never below 0. */
int hfs_pyramid_read_level(int n_levels, int k, int offset, int level);

/* Key-light horizons refined between scales (DESIGN.md "Horizons"): the
 * scale to refine about is the finest whose slope is within
 *   HFS_HORIZON_TIE |slope| + hfs_horizon_tie_slope(...)
 * of the largest, so that a straight flank (equal slopes at every scale in
 * exact arithmetic) or a flat plain (slopes of rounding noise) gives the
 * same scale in float and double. */
#define HFS_HORIZON_TIE 1e-5

/* The absolute part: 1e-6 of the field's slope scale half_range * zscale /
 * dx (half_range: half the height range, 1 for a flat field, as the GLES
 * path normalizes heights). */
double hfs_horizon_tie_slope(double half_range, double zscale, double dx);

/* Receiver grids (the visibility grid, the bounces', split horizons' far
 * grid): of step g along an axis of n texels, receiver a at min(a g,
 * n - 1).  Their count, ceil((n - 1) / g) + 1, and for texel p the
 * receiver a0 before it and the weight t of the next one (0 when p is a
 * receiver), as the GLES path's hfs_grid_uv places its bilinear read. */
int hfs_grid_count(int n, int g);
void hfs_grid_axis(int p, int g, int n, int *a0, double *t);

#endif /* HFS_PYRAMID_LAYOUT_H */
