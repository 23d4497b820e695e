/*
 * env_open.h — an environment map's open-sky irradiance beyond order 4
 * (issue 17; DESIGN.md "The open sky of an environment map").
 *
 * The CPU reference and GLES light the environment through its order-4 SH
 * (env_sh): visibility, exact slices or the seeds' product, needs a
 * low-order sky.  But order 4 holds a map's irradiance only up to the
 * clamped cosine's bands it drops (4, 6, ...): on open flat ground under
 * data/courtyard.exr the SH gives 11% more red than the map.  That error
 * covers the whole image, lit or shadowed, and no horizon quality removes
 * it.  The renderers split the environment's irradiance as
 *     E(N) = E_open(N) - E_occluded(N)
 * (the exact-slice form, slice_light.h), and only the occluded part needs
 * visibility.  The open part is a function of the normal alone, so it can
 * come from the map itself:
 *     D(N) = Int_sphere L_map(w) max(0, N.w) dw  -  H(N) . L_sh
 * (H the clamped cosine's SH, L_sh the map's projection), tabulated once
 * per map and added to the environment's term: rho/pi D(N').  N' is the
 * normal turned by -env_rotate (the table lives in the map's frame, so
 * turning the sky costs nothing).  What is left is the occluded part's
 * projection error, which shrinks with the occluded share of the sky.
 * With env-lights the map is the decomposition's residual (its lights are
 * key lights), and L_sh its projection.
 *
 * The table: HFS_ENV_OPEN_N x HFS_ENV_OPEN_N RGB floats, row-major, node
 * (i, j) at (u, v) = (-1 + 2 i / (N - 1), -1 + 2 j / (N - 1)) of an
 * azimuthal equidistant map of the upper hemisphere: theta = (pi/2)
 * min(1, |(u, v)|) from +z, towards azimuth atan2(v, u), so the nodes are
 * about 5.6 degrees apart everywhere (nodes beyond the rim hold the rim's
 * direction; bilinear lookups stay continuous there).  A height field's
 * normal has n_z > 0; a lookup below the horizon takes the rim.
 *
 * The map's integral is exact per pixel for the cosine's linear part (each
 * pixel's vector moment Int_p w dw in closed form), pixels gathered into at
 * most 128 x 64 cells; only a cell crossing the normal's horizon is
 * clamped as a whole (at its centre).  libc and libm only.
 */
#ifndef HFS_ENV_OPEN_H
#define HFS_ENV_OPEN_H

#include "hfshade_envmap.h" /* HFS_ENV_OPEN_N, HFS_ENV_OPEN_FLOATS */

/* Writes D for the w x h linear RGB map (SPEC's equirect, finite texels)
 * and sh, the map's order-4 projection (hfs_sh_project_equirect), into
 * table (HFS_ENV_OPEN_FLOATS floats).  Returns HFS_OK, or HFS_E_INVALID
 * for a size below 1 or HFS_E_NOMEM (one line in err). */
int hfs_env_open_build(const float *rgb, int w, int h, const double sh[3][HFS_SH_COEFFS],
                       float *table, hfs_error *err);

/* The table's (u, v) of a unit normal n in the map's frame, turned by
 * -rotate about +z (rotate = lighting env_rotate).  GLES mirrors it
 * (shade.frag hfs_env_open_uv). */
void hfs_env_open_uv(const double n[3], double rotate, double uv[2]);

/* D at the normal n (unit; world frame) for a sky turned by rotate:
 * bilinear between the nodes around hfs_env_open_uv(n). */
void hfs_env_open_lookup(const float *table, const double n[3], double rotate, double out[3]);

/* The largest |D| of the table (the GLES path stores D / this in fp16). */
double hfs_env_open_max(const float *table);

#endif /* HFS_ENV_OPEN_H */
