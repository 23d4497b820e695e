/*
 * layout.h — the numbers a GLES frame is laid out by, without GL (pure
 * functions, unit-tested without a driver):
 *   layout        level count/sizes/spacings exactly as the CPU reference
 *                 (pyramid_layout.h), the reconstructed range, the
 *                 sub-sampled visibility grid, the height normalization;
 *   heights       the field as fp16 hi+lo pairs (or fp32) of normalized
 *                 heights v = (z - base) / hscale in [-1, 1];
 *   output scale  the power of two every radiance is multiplied by so the
 *                 frame stays inside fp16's range.
 */
#ifndef HFS_GLES_LAYOUT_H
#define HFS_GLES_LAYOUT_H

#include <stddef.h>
#include <stdint.h>

#include "hfshade.h"
#include "ray_bound.h"

#define HFS_GLES_MAX_LEVELS 256

typedef struct hfs_gles_layout {
    int w, h;                 /* field size                                   */
    int k, offset;            /* quality                                      */
    int n_levels;             /* N = hfs_pyramid_level_count                  */
    int lmin;                 /* lowest level read: min(k*o, N-1)             */
    int n_layers;             /* reconstructed layers N - lmin (input incl.)  */
    int sub, vw, vh;          /* visibility grid: step, size                  */
    int lw[HFS_GLES_MAX_LEVELS], lh[HFS_GLES_MAX_LEVELS];
    double spacing[HFS_GLES_MAX_LEVELS];   /* s_i = d_i                       */
    int read_layer[HFS_GLES_MAX_LEVELS];   /* read level of scale i, - lmin   */
    double base, hscale;      /* v = (z - base) / hscale, v in [-1, 1]        */
    double hunit;             /* the grids' occluder heights' unit, texels
                                 (split_horizon.h hfs_split_h_unit)           */
    double vmax;              /* max v (1, or 0 for a flat field)            */
    double dx, zscale;
    hfs_ray_bound_layout rb;  /* the gap search's bounds (bounds_texture.h)   */
} hfs_gles_layout;

/* Fills L for field f and quality q (validated inputs).  HFS_E_UNSUPPORTED
 * when the level count exceeds HFS_GLES_MAX_LEVELS. */
int hfs_gles_layout_init(hfs_gles_layout *L, const hfs_field *f, const hfs_quality *q,
                         hfs_error *err);


/* Normalized heights, row-major W x H, two components per texel:
 *   fp32 = 0: uint16_t pairs (hi, lo): hi = half(v), lo = half(v - hi);
 *   fp32 = 1: float pairs (v, 0).
 * dst holds W*H*2 elements of the chosen type.  Returns the max absolute
 * representation error |hi + lo - v| in normalized units when `measure`
 * (tests), else 0 (0 for fp32). */
double hfs_gles_split_heights(const hfs_gles_layout *L, const hfs_field *f, int fp32,
                              void *dst, int measure);

/* The largest irradiance E (exit radiance rho/pi Le E) local light l can
 * give any receiver of the field: pi when the sphere reaches the field's
 * bounding box (receivers lifted by 1e-4 dx), else pi (r / d_min)^2 with
 * d_min the distance from the centre to the box (a cap of half-angle alpha
 * gives at most pi sin^2 alpha).  Bounds the output scale below. */
double hfs_gles_local_max_irradiance(const hfs_gles_layout *L, const hfs_local_light *l);

/* fp16 <-> float are in gl_util.h.  Power-of-two output scale that keeps
 * the frame's largest possible exit radiance (bound) in fp16's range:
 * 2^e with bound * 2^e <= 16384, e in [-1000, 1000]; the renderer multiplies
 * every radiance by it before the shaders see one. */
double hfs_gles_output_scale(double bound);

#endif /* HFS_GLES_LAYOUT_H */
