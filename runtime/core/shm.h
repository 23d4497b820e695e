/*
 * shm.h — shadow height maps (Lee & Kim, "Real-time Soft Shadowing of
 * Dynamic Height Map Using a Shadow Height Map"; issue 19), neutral: the
 * CPU reference builds them here, the GLES path runs the same doubling
 * passes (one pass per step), and both answer point queries the same way.
 *
 * For a distant light at azimuth phi (SPEC: from +x toward +y) and
 * elevation e, the shadow height of grid point x is
 *     S(x) = max_{t >= 0} [ H(x + t u) - t dx tan e ],  u = (cos phi, sin phi),
 * t in texels along the light's azimuth, H the bilinear surface in world
 * z: a point (x, z) above the field sees the light's centre iff z >= S(x).
 * The paper's recurrence S(x) = max(H(x), S(x + u) - dx tan e) unrolls to
 * that max over t = 0, 1, 2, ...; here it is computed by doubling, the
 * max-plus scan a GPU runs in log2 passes:
 *     S_0 = H,   S_{j+1}(x) = max(S_j(x), S_j(x + 2^j u) - 2^j dx tan e),
 * S_j read bilinearly between grid points (positions off the grid add
 * nothing: the field ends there).  After J passes S_J covers t = 0 ..
 * 2^J - 1, J = hfs_shm_passes (every t the grid can hold).  Bilinear reads
 * of an intermediate max are the paper's own approximation (its type-2
 * SHM interpolates the propagated value too); along an axis (phi a
 * multiple of 90 degrees) every read is at a grid point and S is exact on
 * the polyline through the grid points.
 *
 * A disk light of angular radius alpha: SHMs at HFS_SHM_LAYERS elevations
 * across the disk, e - alpha .. e + alpha (higher elevations cast lower
 * shadow heights).  A point at height z sees the disk above the elevation
 * theta* where the layers' S crosses z (linear in S between layers), and
 * its visible fraction is the disk's area above the horizontal chord at
 * theta*: f(h) = (acos h - h sqrt(1 - h^2)) / pi, h = (theta* - e) / alpha
 * (the azimuthal spread of the disk is ignored: the layers share the
 * centre's azimuth).  Exact rays in the truth measure the difference.
 */
#ifndef HFS_SHM_H
#define HFS_SHM_H

#include "hfshade.h"

/* HFS_SHM_LAYERS (hfshade.h): the elevations across a disk light. */

/* Doubling passes that cover every distance a w x h grid holds. */
int hfs_shm_passes(int w, int h);

/* The layer's elevation: e + alpha (2 k / (HFS_SHM_LAYERS - 1) - 1), k = 0
 * the disk's lowest edge (the highest shadow heights). */
double hfs_shm_layer_elevation(double elev, double alpha, int k);

/* S of the light (phi, elev) over field f into s (W*H, row-major, world
 * z); scratch holds W*H floats.  Rows in parallel (threads as
 * hfs_parallel_rows; 0 = default), the same output for any count. */
void hfs_shm_build(const hfs_field *f, double phi, double elev, float *s, float *scratch,
                   int threads);

/* S bilinearly at grid position (gx, gy), clamped to the grid. */
double hfs_shm_sample(const float *s, int w, int h, double gx, double gy);

/* The visible fraction of a disk light (elev, alpha) for a point at height
 * z, from its layers' shadow heights s[0 .. HFS_SHM_LAYERS - 1] there (in
 * layer order: s non-increasing in k up to rounding). */
double hfs_shm_disk_fraction(const double s[HFS_SHM_LAYERS], double z);

#endif /* HFS_SHM_H */
