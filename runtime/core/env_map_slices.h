/*
 * env_map_slices.h — an environment map integrated along the azimuth
 * slices (issue 17; DESIGN.md "The open sky of an environment map").
 *
 * The exact-slice path (slice_light.h) integrates each slice's occluded
 * elevations against the order-4 SH sky.  Near the horizon, where the
 * terrain occludes, a real map (walls, a treeline, a bright opening) is
 * what order 4 blurs most, so even with exact horizons the occluded part
 * is wrong by the projection.  With the map at hand, each slice's part
 * can be integrated against the map itself:
 *     S_j(x) = Int_x^{pi/2} L_j(e) (a cos e + b sin e) cos e de
 *            = a F_j(x) + b G_j(x),
 * L_j(e) the map's mean over slice j's wedge of azimuths [phi_j - dphi/2,
 * phi_j + dphi/2] (after the sky's rotation), a = N.d(phi_j), b = N_z.
 * The map is piecewise constant per pixel row, so F_j and G_j are exact at
 * the rows' boundaries and in closed form inside a row; the table holds
 * them at HFS_MAP_SLICE_E elevations evenly spaced over [-pi/2, pi/2]
 * (0.7 degree apart), read linearly between, so the CPU reference and GLES
 * (an fp16 texture, hi + lo) read the same function.  The renderer adds
 * dphi (S_j(x) - S_j(floor)) per slice (<= 0: the occluded part) to the
 * map's open-sky irradiance (env_open.h): no SH anywhere in the
 * environment's diffuse term.  The approximations left besides the
 * horizons: a slice's horizon stands for its whole wedge, the wedge's mean
 * radiance for each azimuth in it, and F, G are linear between samples.
 * Built per lighting change: O(map texels) (every texel falls into one
 * wedge), a few ms for a 1024 x 512 map.  libc and libm only.
 */
#ifndef HFS_ENV_MAP_SLICES_H
#define HFS_ENV_MAP_SLICES_H

#include "hfshade.h"

#define HFS_MAP_SLICE_E 257

typedef struct hfs_map_slices {
    int n;               /* slices                                          */
    double dphi;
    double *dir;         /* n x 2: (cos phi_j, sin phi_j)                   */
    double *fg;          /* n x HFS_MAP_SLICE_E x 6: F (RGB), G (RGB) at
                            e_i = -pi/2 + pi i / (HFS_MAP_SLICE_E - 1)      */
} hfs_map_slices;

/* For n slices at the given directions (n x 2, (cos, sin) of phi_j, as the
 * horizons snap them), each a wedge of dphi, over the w x h map turned by
 * rotate about +z (lighting env_rotate).  Returns HFS_OK or HFS_E_NOMEM
 * (one line in err). */
int hfs_map_slices_build(hfs_map_slices *ms, const float *rgb, int w, int h, double rotate,
                         const double *dir, int n, double dphi, hfs_error *err);
void hfs_map_slices_free(hfs_map_slices *ms);

/* Adds slice j's occluded part, dphi (S_j(x) - S_j(floor)) per channel,
 * floor the tangent plane's elevation (<= 0 added for x <= floor: open),
 * to e (irradiance, before rho/pi). */
void hfs_map_slices_occluded(const hfs_map_slices *ms, int j, const double n[3], double x,
                             double e[3]);
/* The mean of slice j's occluded part over the nx horizons of its
 * sub-directions (split horizons, split_horizon.h). */
void hfs_map_slices_occluded_mean(const hfs_map_slices *ms, int j, const double n[3],
                                  const double *x, int nx, double e[3]);

#endif /* HFS_ENV_MAP_SLICES_H */
