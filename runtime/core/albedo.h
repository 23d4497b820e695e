/*
 * albedo.h — the per-texel albedo map (SPEC "Albedo"; hfs_lighting
 * albedo_map): rho(x) = albedo * map(x) per RGB channel, map values in
 * [0, 1] on the height field's grid.  Direct light is linear in rho, so
 * every backend renders with the uniform albedo and multiplies its exit
 * radiance by the map at the end (the CPU reference, the truth and the
 * unshadowed normalizer here; the GLES shading pass in its shader).  Shared
 * by the backends, so neither a cpu_ nor a gles_ module.
 */
#ifndef HFS_ALBEDO_H
#define HFS_ALBEDO_H

#include "hfshade.h"

/* out->rgb[i] *= map[i] over the whole image (W*H*3); map NULL: nothing. */
void hfs_albedo_map_apply(const float *map, hfs_image *out);

/* HFS_OK, or HFS_E_INVALID with "albedo map: texel (i, j) channel c is V,
 * outside [0, 1]" (NaN and Inf included) for the first texel that is not
 * a valid albedo.  map NULL is valid. */
int hfs_albedo_map_check(const float *map, int width, int height, hfs_error *err);

#endif /* HFS_ALBEDO_H */
