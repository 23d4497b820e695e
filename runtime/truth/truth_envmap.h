/*
 * truth_envmap.h — the ground truth of an environment map (hfs_lighting's
 * env_map): the map itself integrated per receiver, no SH projection
 * (DESIGN.md "Ground truth of an environment map").
 *
 * The map's pixel (c, r) is a piece of the sphere, azimuth [2 pi c / W,
 * 2 pi (c+1) / W] + env_rotate, elevation [pi/2 - pi (r+1) / H,
 * pi/2 - pi r / H], of constant radiance.  Over such a piece the
 * receiver's cosine N.s = (nx cos phi + ny sin phi) cos e + nz sin e
 * integrates in closed form:
 *     Int L max(0, N.s) dw = L [(nx C + ny S) Icc + nz D Isc],
 * C = Int cos phi dphi, S = Int sin phi dphi, D = Int dphi over the
 * azimuths, Icc = Int cos^2 e de, Isc = Int sin e cos e de over the
 * visible elevations (above the horizon and the tangent plane).
 *
 *   - bright pixels (radiance above HFS_ENVMAP_BRIGHT_K times the map's
 *     mean, the HFS_ENVMAP_BRIGHT_MAX brightest): each at its own column
 *     azimuth, with that azimuth's exact horizon (one walk per column)
 *     and its own fractional elevation coverage;
 *   - every other pixel: summed into A azimuth wedges (A = truth_azimuths)
 *     as per-row sums of L D, L C, L S (a column split exactly where it
 *     straddles two wedges) and their prefix sums from the zenith down, so
 *     a receiver costs, per wedge, one exact horizon (at the wedge's middle
 *     azimuth, as the SH truth) and O(1) for the rows above it, the row it
 *     cuts taken in part.
 * The only approximation: a wedge (a bright column) sees one horizon and
 * one tangent-plane elevation, those of its middle azimuth.
 *
 * Immutable once made; shared by the truth's threads.
 */
#ifndef HFS_TRUTH_ENVMAP_H
#define HFS_TRUTH_ENVMAP_H

#include "hfshade.h"
#include "truth_raycast.h"

#define HFS_ENVMAP_BRIGHT_K 32.0   /* bright: above K x the mean radiance */
#define HFS_ENVMAP_BRIGHT_MAX 1024 /* at most this many bright pixels      */

typedef struct hfs_truth_envmap hfs_truth_envmap;

/* Prepares the map of l (env_map non-NULL, validated) for n_az wedges,
 * bright pixels above k x the mean, at most max_bright of them (the
 * brightest; ties by index).  *out = NULL for an all-black map (it adds
 * nothing).  Returns HFS_OK or HFS_E_NOMEM. */
int hfs_truth_envmap_make(const hfs_lighting *l, int n_az, double k, int max_bright,
                          hfs_truth_envmap **out);
void hfs_truth_envmap_free(hfs_truth_envmap *m);

/* Number of bright pixels and of their distinct columns (for tests). */
void hfs_truth_envmap_counts(const hfs_truth_envmap *m, int *n_bright, int *n_columns);

/* lo[c] += rho / pi * Int L_c(s) V(s) max(0, N.s) ds for the receiver at grid
 * point (i, j), lifted world height z0, normal n. */
void hfs_truth_envmap_receiver(const hfs_truth_envmap *m, const hfs_truth_grid *g, int i,
                               int j, double z0, const double n[3], double rho,
                               double lo[3]);

/* The map's radiance in world direction s (unit): the pixel holding it
 * (the map is piecewise constant), env_rotate applied. */
void hfs_truth_envmap_radiance(const hfs_truth_envmap *m, const double s[3], double out[3]);

/* The lowest elevation that counts along the horizontal direction (c, s)
 * (unit) for the receiver (i, j, z0) with normal n: the larger of the
 * exact horizon (hfs_truth_horizon; -pi/2 when nothing occludes) and the
 * tangent plane's elevation there.  hint as hfs_truth_horizon's. */
double hfs_truth_env_lo(const hfs_truth_grid *g, int i, int j, double z0, const double n[3],
                        double c, double s, double *hint);

#endif /* HFS_TRUTH_ENVMAP_H */
