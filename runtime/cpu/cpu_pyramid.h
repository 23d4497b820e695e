/*
 * cpu_pyramid.h — the height pyramid of DESIGN.md ("Height pyramid"), CPU
 * reference in double precision.
 *
 * Layout: pyramid_layout.h (shared by every backend).
 *
 * Object (hfs_cpu_pyramid): the decimated levels (level i samples level i+1
 * bilinearly at its own texel centres) and their reconstructions R_i on the
 * full W x H grid (uniform bicubic B-spline of the level's samples, 16 taps;
 * R_{N-1} is the input).  Only levels first_full..N-1 are reconstructed: the
 * horizon pass reads level min(i + k*o, N-1) >= min(k*o, N-1), so the
 * renderer never pays for the others.
 *
 * Heights are the raw field values (zscale is NOT applied here; the horizon
 * pass folds it into its per-level factors).
 *
 * Reconstructed layers are stored contiguously, one block of
 * (W+1) x (H+1) doubles per level, row stride W+1: the extra column and row
 * replicate the last ones (clamp to edge) so that a bilinear read at exactly
 * x = W-1 or y = H-1 can always touch its (zero-weighted) right/lower
 * neighbour without a branch.
 *
 * Invariants worth testing (tests/test_cpu_pyramid.c): a constant field is
 * bit-for-bit constant at every level (both filters are written in a
 * difference form that is exact for constants); a linear ramp stays a ramp
 * away from the borders (bilinear and the cubic B-spline reproduce linear
 * functions).
 *
 * Ownership: create returns an object the caller frees with destroy;
 * destroy(NULL) is a no-op.  The input field is only read during create.
 * A built pyramid is immutable, so several threads may read it at once.
 */
#ifndef HFS_CPU_PYRAMID_H
#define HFS_CPU_PYRAMID_H

#include "hfshade.h"

#include "pyramid_layout.h" /* the layout, shared with the GLES path */

/* ---- object ------------------------------------------------------------------ */

typedef struct hfs_cpu_pyramid hfs_cpu_pyramid;
typedef struct hfs_ray_bound_layout hfs_ray_bound_layout;

/* Builds the pyramid of f's heights with level step k (>= 1) and reconstructs
 * levels max(first_full, 0)..N-1 to full resolution.  threads: workers for the
 * reconstruction (0 = all cores); the result does not depend on it.
 * Returns HFS_OK, HFS_E_INVALID or HFS_E_NOMEM (with a message in err). */
int hfs_cpu_pyramid_create(const hfs_field *f, int k, int first_full,
                           int threads, hfs_cpu_pyramid **out, hfs_error *err);
void hfs_cpu_pyramid_destroy(hfs_cpu_pyramid *p);

int hfs_cpu_pyramid_width(const hfs_cpu_pyramid *p);      /* W */
int hfs_cpu_pyramid_height(const hfs_cpu_pyramid *p);     /* H */
int hfs_cpu_pyramid_k(const hfs_cpu_pyramid *p);
int hfs_cpu_pyramid_count(const hfs_cpu_pyramid *p);      /* N */
int hfs_cpu_pyramid_first_full(const hfs_cpu_pyramid *p); /* lowest reconstructed */
double hfs_cpu_pyramid_spacing(const hfs_cpu_pyramid *p, int level);
void hfs_cpu_pyramid_size(const hfs_cpu_pyramid *p, int level, int *lw, int *lh);

/* Decimated samples of a level, lw*lh doubles, row-major (level N-1 = input). */
const double *hfs_cpu_pyramid_samples(const hfs_cpu_pyramid *p, int level);

/* Reconstructed layer R_level on the full grid: (W+1)*(H+1) doubles with row
 * stride hfs_cpu_pyramid_stride(p) (= W+1), value at grid point (i, j) at
 * [j*stride + i]; NULL for a level below first_full. */
const double *hfs_cpu_pyramid_full(const hfs_cpu_pyramid *p, int level);
int hfs_cpu_pyramid_stride(const hfs_cpu_pyramid *p);

/* Bilinear read of R_level at grid coordinates (gx, gy), clamped to the grid
 * (the read the horizon pass makes, spelled out for tests and tools).  The
 * level must be reconstructed. */
double hfs_cpu_pyramid_sample(const hfs_cpu_pyramid *p, int level, double gx,
                              double gy);

/* The gap search's bounds of the input heights (ray_bound.h: the max
 * pyramid's atlas, built with base 0 and scale 1) and their layout. */
const double *hfs_cpu_pyramid_bounds(const hfs_cpu_pyramid *p, const hfs_ray_bound_layout **L);

#endif /* HFS_CPU_PYRAMID_H */
