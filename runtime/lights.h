/*
 * lights.h — light geometry shared by every backend: where a light is as
 * seen from a receiver, and its exact unshadowed irradiance.
 */
#ifndef HFS_LIGHTS_H
#define HFS_LIGHTS_H

#include "hfshade.h"

/* Irradiance integral over a uniform cap of half-angle alpha whose axis makes
 * angle beta with the normal: E = integral_cap max(0, N.s) ds, exact (closed
 * form of Snyder 1996 for the straddling case).  cos_beta in [-1, 1],
 * alpha in [0, pi]; alpha >= pi/2 is handled (alpha = pi: the whole sphere, E = pi).
 * Multiply by radiance and rho/pi for exit radiance. */
double hfs_cap_irradiance(double cos_beta, double alpha);

/* A key light contributes iff it is enabled and its brightest possible exit
 * radiance (normal incidence, no shadow) is not zero in double; every
 * backend skips exactly the same lights.  The second condition only drops
 * disks so small (alpha < ~1e-154) that their swath width would underflow;
 * their output is 0 in any case. */
int hfs_key_light_contributes(const hfs_key_light *k, double albedo);

/* A local light seen from receiver point p (world units): unit direction
 * toward its centre, distance to the centre, and the cap half-angle
 * asin(r/d) (pi when p is inside or on the sphere, in which case dir is +z
 * if the centre coincides with p).  Returns 1 if p is inside the sphere.
 * A light of radius 0 is a point: alpha = 0 and never inside (even at d = 0). */
int hfs_local_light_cap(const hfs_local_light *l, const double p[3],
                        double dir[3], double *dist, double *alpha);

#endif /* HFS_LIGHTS_H */
