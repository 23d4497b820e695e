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

/* The environment contributes iff it is on and one of its SH coefficients
 * is not zero (every backend). */
int hfs_env_contributes(const hfs_lighting *l);

/* Whether indirect bounces stop at the direct light's horizon in each
 * slice (cpu_bounce.h): under an environment that contributes, on the
 * exact-slice path, where the GLES grid keeps that horizon per direction.
 * Every backend that gathers bounces follows this. */
int hfs_bounce_capped(const hfs_lighting *l, const hfs_quality *q);

/* The bounces' azimuths: the largest divisor of q->nphi_env not above
 * q->nphi_bounce (at least 1); they are every (nphi_env / n)-th of the
 * environment's directions, from its first. */
int hfs_bounce_dirs(const hfs_quality *q);

/* A local light costs something iff it is enabled, has a positive radiance
 * channel and a positive radius (a point has zero solid angle: 0, as the
 * truth).  Every backend skips exactly the same lights. */
int hfs_local_light_contributes(const hfs_local_light *l);

/* Smallest disk radius the visibility of a key light sees, in radians: 30
 * float ulps of pi/2, so that the elevation window e - alpha < e + alpha and
 * the swath's half-width stay apart at every elevation on the fp16/fp32 GLES
 * path and in the double CPU reference alike (below ~ulp(elev)/2 the window
 * collapses to a point and a 1e-8 rad sun would come out black).  A disk
 * that small is a point at any terrain scale: its visible FRACTION is taken
 * from a disk of this radius about the same centre, while its irradiance
 * (hfs_cap_irradiance) keeps the true alpha.  Every backend uses it. */
#define HFS_MIN_VIS_ALPHA 1e-6

/* max(alpha, HFS_MIN_VIS_ALPHA): the radius a key light's swath and
 * visible-fraction projection use. */
double hfs_key_vis_alpha(double alpha);

/* A local light seen from receiver point p (world units): unit direction
 * toward its centre, distance to the centre, and the cap half-angle
 * asin(r/d) (pi when p is inside or on the sphere, in which case dir is +z
 * if the centre coincides with p).  Returns 1 if p is inside the sphere.
 * A light of radius 0 is a point: alpha = 0 and never inside (even at d = 0). */
int hfs_local_light_cap(const hfs_local_light *l, const double p[3],
                        double dir[3], double *dist, double *alpha);

/* What decides whether the terrain can shadow a light at all: the highest
 * world height, a bound on the terrain's slope (rise per horizontal world
 * unit along any direction, over the bilinear surface: sqrt(sx^2 + sy^2)
 * with sx, sy the steepest differences along x and y) and the field's
 * horizontal extent, (W-1) dx by (H-1) dx. */
typedef struct hfs_field_extent {
    double z_top, slope, x_max, y_max;
} hfs_field_extent;

void hfs_field_extent_make(const hfs_field *f, hfs_field_extent *e);

/* 1 if no part of the terrain can come between any receiver and any point
 * of local light l (the light is beyond the terrain's shadow range), so its
 * visible fraction is exactly 1 everywhere and no visibility need be
 * computed: its lowest point is above the highest terrain, and a ray from
 * any receiver to any point of it rises faster than the terrain can, i.e.
 * (z_c - r - z_top) / D > slope, D the farthest horizontal distance from a
 * receiver to a point of the light.  Conservative: 0 where it cannot tell.
 * Every backend uses it, so they agree on which lights are open. */
int hfs_local_light_open(const hfs_field_extent *e, const hfs_local_light *l);

#endif /* HFS_LIGHTS_H */
