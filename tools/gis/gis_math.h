/*
 * gis_math.h — the arithmetic of the GIS commands (issue 39; SPEC.md
 * "Terrain rasters (GIS products)" and "Azimuths for map users"), with no
 * GDAL and no renderer, so a unit test pins every number
 * (tests/test_gis_math.c):
 *   - azimuths: the command line's conventions to SPEC's phi, and a map's
 *     phi to the grid's (a grid whose rows run north or columns west);
 *   - the products from horizon elevation angles gamma (radians, as
 *     hfs_renderer_horizons returns them): sky-view factor (Zaksek or
 *     Lambertian), openness, the horizon raster's degrees;
 *   - the isotropic sky's share on a tilted surface (insolation's diffuse);
 *   - the horizon command's file names, as GRASS r.horizon names its maps.
 * Angles on the command line are degrees; everything here that takes or
 * returns phi speaks radians.
 */
#ifndef HFS_GIS_MATH_H
#define HFS_GIS_MATH_H

#include <stddef.h>

/* How the command line gives an azimuth, in degrees. */
typedef enum gis_convention {
    GIS_CCW_EAST = 0, /* GRASS r.horizon's: counter-clockwise from east   */
    GIS_COMPASS       /* clockwise from north (gdaldem hillshade -az)     */
} gis_convention;

/* "ccw-east" / "compass" (the flag's values); NULL for another value. */
const char *gis_convention_name(gis_convention c);

/* SPEC's phi (radians, from +x towards +y: clockwise from east on a
 * north-up map) of an azimuth of deg degrees in convention c:
 * ccw-east A -> -A, compass C -> C - 90. */
double gis_phi_of(double deg, gis_convention c);

/* The grid's phi of a map's phi, for a grid whose +x runs east (ex = 1)
 * or west (-1) and whose +y runs south (ey = 1, north-up) or north (-1,
 * south-up): the same ground direction in the grid's own axes. */
double gis_grid_phi(double map_phi, int ex, int ey);

/* 1 where hfs_renderer_horizons found no terrain along the ray
 * (HFS_HORIZON_NONE, -pi/2, within the precision of the GLES path's
 * fp16 hi + lo angles; a real horizon is never that steep a drop). */
int gis_horizon_none(float gamma);

/* Sky-view factor kinds (SPEC): Zaksek et al. 2011, 1 - mean sin(gamma+);
 * Lambertian (Haentzschel et al. 2005, SAGA), mean cos^2(gamma+); gamma+ =
 * max(gamma, 0), so a ray that meets no terrain counts as open sky. */
typedef enum gis_svf_kind { GIS_SVF_ZAKSEK = 0, GIS_SVF_LAMBERTIAN } gis_svf_kind;

/* acc[p] += the kind's term of gamma[p] (n texels): sin(gamma+) or
 * cos^2(gamma+). */
void gis_svf_add(double *acc, const float *gamma, size_t n, gis_svf_kind kind);

/* out[p] = the sky-view factor of n_dirs directions' summed terms acc[p]. */
void gis_svf_finish(float *out, const double *acc, size_t n, int n_dirs, gis_svf_kind kind);

/* Openness (Yokoyama et al. 2002; SPEC): sum[p] += 90 - gamma[p] in
 * degrees (gamma signed, from the texel), count[p] += 1, for the rays that
 * meet terrain; a ray that meets none is left out of its texel's mean. */
void gis_openness_add(double *sum, int *count, const float *gamma, size_t n);

/* out[p] = sum[p] / count[p] degrees; NaN where count[p] = 0 (every
 * direction left the field at once: nodata in the raster). */
void gis_openness_finish(float *out, const double *sum, const int *count, size_t n);

/* out[p] = gamma[p] in degrees, clamped to >= 0 (SPEC: 0 where nothing
 * rises above the horizontal; r.horizon -d's map). */
void gis_horizon_degrees(float *out, const float *gamma, size_t n);

/* The nodata value of a product whose values lie in [lo, hi]: the input's
 * declared one (has_nodata, nodata) when a Float32 holds it and it cannot
 * be a value of the product (NaN, or finite outside [lo, hi]: SRTM's
 * -32768, -9999, ...); else GIS_NODATA (an input without one, or with 0,
 * which a sky-view factor of 0 or a horizon of 0 degrees would collide
 * with). */
#define GIS_NODATA (-9999.0f)
float gis_nodata_for(int has_nodata, double nodata, double lo, double hi);

/* The visible fraction V of the sun's disk (angular radius alpha, centre
 * at SPEC azimuth phi and elevation elev, radians) on a surface of unit
 * normal n under a horizon at elevation gamma at the centre's azimuth: of
 * the disk's irradiance on that surface (its part above the tangent
 * plane, cosine-weighted), the share from its part above the horizon, as
 * the truth's shadowed over unshadowed render defines it.  1 for a ray
 * that meets no terrain (gis_horizon_none) or gamma <= elev - alpha, 0 for
 * gamma >= elev + alpha; between them the disk is taken as flat and the
 * horizon as straight across it (it spans 0.53 degrees of azimuth).  With
 * the whole disk above the tangent plane both integrals are exact (closed
 * form: a chord's segment of a disk under a linear weight); with the plane
 * across the disk (a sun grazing the surface) they are summed over a
 * GIS_DISK_GRID^2 midpoint grid of it; 0 when no part of it lies above
 * the tangent plane. */
#define GIS_DISK_GRID 32
/* 1 when the horizon gamma crosses the disk: strictly between its lowest
 * and highest elevations as floats (a horizon window's ends, clamped to
 * them as floats, count as outside). */
int gis_disk_cut(double elev, double alpha, float gamma);
double gis_disk_visible(const double n[3], double phi, double elev, double alpha, float gamma);

/* The isotropic sky's share on a tilted surface under its horizons:
 * (1/pi) times the integral of max(0, n.w) over the sky's directions
 * that the terrain leaves open, the sky being the upper hemisphere (as a
 * clear-sky model's diffuse horizontal irradiance is: below the
 * horizontal lies ground, whose reflection is not counted; the svf's
 * gamma+ = max(gamma, 0) likewise); 1 on open flat ground, (1 + n_z) / 2
 * on an open tilted plane.  Azimuth by azimuth, above g = max(gamma, t,
 * 0), t = atan(-n_h / n_z) where the tangent plane cuts the azimuth's
 * vertical half-plane (n_h = n_x cos phi + n_y sin phi), the integral of
 * (n_z sin e + n_h cos e) cos e de is, in closed form,
 *   n_z cos^2(g) / 2 + n_h ((pi/2 - g) / 2 - sin(2g) / 4),
 * and twice the azimuths' mean of it is the share (a uniform rule over
 * the circle).  A ray that met no terrain (gis_horizon_none) has gamma
 * below every g.  acc[p] += the term of azimuth phi (the grid's, radians)
 * at texel p of unit normal n[3p..3p+2] (n_z > 0, a height field's). */
void gis_sky_add(double *acc, const float *gamma, const float *n, size_t count, double phi);

/* out[p] = the share from the n_dirs azimuths' summed terms acc[p],
 * clamped to [0, 1] (2 acc / n_dirs). */
void gis_sky_finish(float *out, const double *acc, size_t count, int n_dirs);

/* How far (world units of horizontal distance) terrain of relief `relief`
 * (world units: zscale times the field's highest minus lowest height) can
 * cast a shadow onto a disk whose lowest point stands at elevation low
 * (radians): relief / tan(low), the distance at which a ray that rises at
 * `low` clears the highest terrain from the lowest; HUGE_VAL (no bound:
 * the whole field) when low <= 0 or that distance is not finite. */
double gis_shadow_reach(double relief, double low);

/* deg brought into [0, 360). */
double gis_wrap_degrees(double deg);

/* The file name of azimuth deg (its convention's degrees) for PREFIX, as
 * r.horizon names its maps (G_generate_basename): PREFIX_AAA.tif with the
 * azimuth in [0, 360) zero-padded to three integer digits and `decimals`
 * decimals, the dot made '_' (PREFIX_045.tif; decimals 1: PREFIX_022_5.tif,
 * PREFIX_045_0.tif).  0, or -1 when it does not fit buf[n]. */
int gis_horizon_name(char *buf, size_t n, const char *prefix, double deg, int decimals);

/* The decimals a number is written with ("22.5" -> 1, "45" -> 0, "1e1" ->
 * 0): the digits after its '.' up to an exponent. */
int gis_decimals_of(const char *number);

#endif /* HFS_GIS_MATH_H */
