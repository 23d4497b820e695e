/*
 * hfshade_gis.h — public interface of libhfshade_gis (issue 40): the GIS
 * products of `hfshade svf | horizon | openness | sun | insolation`
 * (docs/GIS.md, SPEC.md "Terrain rasters") on a DEM held in memory, for
 * bindings (the Python module) and programs that have their heights
 * already.  The same code as the commands (tools/gis: gis_products,
 * gis_math, gis_horizons, gis_resample, gis_sun, solar_position,
 * clear_sky), over libhfshade's hfs_renderer_horizons: on the same
 * heights, cell size, options, site, instants and backend, every value
 * equals the command's GeoTIFF, bit for bit.  No GDAL: the caller reads
 * the DEM (and, for the sun, finds its site's longitude and latitude).
 *
 * The DEM: width x height heights, row-major, row 0 = NORTH, column 0 =
 * west (a north-up raster as GDAL reads it), square cells of `cell`
 * metres.  Holes: a texel whose `hole` byte is set, a NaN or infinite
 * height, or (has_nodata) one equal to nodata as a float.  As the
 * commands do, holes are filled by push-pull (hfs_io.h
 * hfs_height_fill_holes) only to compute their neighbours, and every hole
 * is nodata in every product.
 *
 * Outputs are width x height floats, the caller's, on the DEM's grid;
 * where the DEM has a hole (or a product has no value: openness where
 * every direction leaves the DEM at once) they hold the product's nodata
 * value, hfs_gis_nodata's.  Angles are DEGREES here, as on the command
 * line.  Errors: 0 or a negative hfs_status with a one-line message in err
 * (the argument named as the Python module names it: cell_size, radius,
 * directions, when, start, end, step, lat, lon, elevation, linke); nothing
 * is written to out on failure.
 *
 * Threads: as libhfshade (one renderer per thread).
 */
#ifndef HFSHADE_GIS_H
#define HFSHADE_GIS_H

#include "hfshade.h"

#ifdef __cplusplus
extern "C" {
#endif

#if defined(HFS_GIS_BUILDING_LIBRARY) && defined(__GNUC__)
#define HFS_GIS_API __attribute__((visibility("default")))
#else
#define HFS_GIS_API
#endif

/* A DEM in memory (the caller's; read during a call only). */
typedef struct hfs_gis_dem {
    int width, height;          /* >= 2 each                                  */
    const float *z;             /* width*height heights, row 0 = north        */
    const unsigned char *hole;  /* NULL, or width*height: non-zero = no data  */
    int has_nodata;             /* non-zero: heights equal to nodata are holes */
    double nodata;              /* compared as a float, like a band's         */
    double cell;                /* metres per cell, square, finite, > 0       */
    double zscale;              /* heights times zscale are metres, [1e-9, 1e6] */
} hfs_gis_dem;

/* The products (hfs_gis_nodata). */
typedef enum hfs_gis_product {
    HFS_GIS_SVF = 0,            /* 0..1                                       */
    HFS_GIS_HORIZON,            /* 0..90 degrees                              */
    HFS_GIS_OPENNESS,           /* 0..180 degrees                             */
    HFS_GIS_SUN,                /* W/m^2 and a fraction, >= 0                 */
    HFS_GIS_INSOLATION          /* Wh/m^2, >= 0                               */
} hfs_gis_product;

/* r: the renderer the horizons are computed on (its backend: exact), or
 * NULL: by the sweep on the host (`--method sweep`, docs/GIS.md "The
 * sweep"), the whole DEM only (radius 0; openness then needs 0 given).
 *
 * radius: the search distance in metres, [0, 1e9], 0 = the whole DEM; or
 * HFS_GIS_RADIUS_DEFAULT, the command's default: the whole DEM for svf and
 * horizon, 10 cells for openness (the Relief Visualization Toolbox's), 0
 * for sun and insolation (below). */
#define HFS_GIS_RADIUS_DEFAULT (-1.0)

/* The value written where a product has none: the DEM's nodata when a
 * Float32 holds it and it lies outside the product's values (SRTM's
 * -32768, NaN is refused: outputs are finite), else -9999; what the
 * commands write as the GeoTIFF's nodata. */
HFS_GIS_API float hfs_gis_nodata(const hfs_gis_dem *dem, hfs_gis_product product);

/* Sky-view factor over `directions` azimuths (1..1024; the command's
 * default 16), equally spaced from east counter-clockwise: Zaksek et al.
 * (lambertian 0; 1 - mean sin(max(gamma, 0))) or Haentzschel's
 * Lambertian-weighted mean cos^2(max(gamma, 0)) (lambertian 1, SAGA's). */
HFS_GIS_API int hfs_gis_svf(hfs_renderer *r, const hfs_gis_dem *dem, int directions,
                            int lambertian, double radius, float *out, hfs_error *err);

/* The horizon elevation angle at one azimuth, degrees >= 0 (r.horizon -d:
 * 0 where nothing rises above the horizontal).  azimuth in degrees,
 * [-1e6, 1e6]: compass 0 counter-clockwise from east (GRASS r.horizon's
 * convention, the command's default), compass 1 clockwise from north. */
HFS_GIS_API int hfs_gis_horizon(hfs_renderer *r, const hfs_gis_dem *dem, double azimuth,
                                int compass, double radius, float *out, hfs_error *err);

/* Positive and negative openness (Yokoyama et al. 2002), degrees, over
 * `directions` azimuths (1..1024; the command's default 8). */
HFS_GIS_API int hfs_gis_openness(hfs_renderer *r, const hfs_gis_dem *dem, int directions,
                                 double radius, float *positive, float *negative,
                                 hfs_error *err);

/* Where the sun is seen from (hfs_gis_sun, hfs_gis_insolation): one site
 * for the whole DEM, as the commands take the DEM's centre (docs/GIS.md
 * "The sun"). */
typedef struct hfs_gis_site {
    double lat, lon;            /* WGS84 degrees, [-90, 90] north and
                                 * [-360, 360] east; the commands': the
                                 * centre of the DEM's extent (gis_dem_lonlat) */
    double elevation_m;         /* metres, [-1000, 9000]; NaN: the DEM's centre
                                 * texel (width/2, height/2; filled where a
                                 * hole) times zscale, the commands' site      */
    double linke;               /* Linke turbidity [1, 10]; 0: 3.0 (r.sun's
                                 * default, the commands')                   */
    double convergence_deg;     /* [-180, 180]: the grid convergence there,
                                 * the angle from true north to the grid's
                                 * north (up its columns), positive where grid
                                 * north lies east of true north (a UTM grid
                                 * east of its central meridian, in the north);
                                 * a true compass azimuth A is the grid's A -
                                 * convergence_deg.  The commands': computed
                                 * at the site through the DEM's CRS
                                 * (HFS_GRID_CONVERGENCE_DEG); 0: the grid's
                                 * up is true north (a longitude-latitude
                                 * grid, or on the central meridian)        */
} hfs_gis_site;

/* Instants are seconds since 1970-01-01T00:00:00Z (POSIX time: no leap
 * seconds), in the years 1900..2100.  The sun's formulas take a UTC Julian
 * day: the one of the instant's UTC calendar date and time, computed as
 * the commands compute it from a parsed date-time (hfs_solar_julian_day),
 * so a whole-second instant gives the command's double exactly (a
 * fraction of a second may differ by an ulp: the command adds the
 * seconds' decimals digit by digit).  hfs_gis_julian_day gives that day
 * into *jd: 0, or HFS_E_INVALID for an instant out of range. */
HFS_GIS_API int hfs_gis_julian_day(double unix_utc, double *jd, hfs_error *err);

/* `hfshade sun --datetime T`: the direct-beam irradiance of a clear sky
 * (ESRA, as GRASS r.sun; Linke turbidity site->linke) on each texel's
 * tilted, terrain-shadowed surface at instant unix_utc, W/m^2, into beam,
 * and the visible fraction of the sun's disk, 0..1, into visible (the
 * command's bands 1 and 2; 0 on a slope facing away).  A sun at or below
 * the horizon gives zeros without rendering.  radius: metres, [0, 1e9]; 0
 * (or HFS_GIS_RADIUS_DEFAULT): shadows cast from as far as the DEM's
 * relief can reach, else none from farther than radius (`--radius`;
 * refused on the truth renderer, which renders the sun's exact shadows
 * from the whole DEM, as the command refuses it).  Nodata:
 * hfs_gis_nodata(dem, HFS_GIS_SUN). */
HFS_GIS_API int hfs_gis_sun(hfs_renderer *r, const hfs_gis_dem *dem, const hfs_gis_site *site,
                            double unix_utc, double radius, float *beam, float *visible,
                            hfs_error *err);

/* `hfshade insolation --from A --to B --step MIN --directions N`: the
 * clear sky's irradiation over [from, to), Wh/m^2, in steps of step_min
 * minutes (> 0; the last step shortened to end at `to`; at most 100000
 * steps), each step's sun at its middle: beam the direct beam on the
 * tilted, shadowed surface summed over the steps whose sun is up;
 * diffuse the isotropic sky's share under the terrain's horizons in
 * `directions` azimuths (1..1024; the command's default 16) times the
 * diffuse horizontal irradiation; global their sum (the command's bands
 * 1, 2, 3).  radius as hfs_gis_sun's, and the sky's horizons are searched
 * within it (0: to the DEM's edge).  diffuse and global both NULL: the
 * beam alone (`--beam-only`), no sky's horizons searched, the same beam
 * bit for bit.  Nodata: hfs_gis_nodata(dem, HFS_GIS_INSOLATION). */
HFS_GIS_API int hfs_gis_insolation(hfs_renderer *r, const hfs_gis_dem *dem,
                                   const hfs_gis_site *site, double from_unix_utc,
                                   double to_unix_utc, double step_min, int directions,
                                   double radius, float *beam, float *diffuse, float *global,
                                   hfs_error *err);

/* The same with the sky's shape from a map and the ground's reflection
 * (`--sky-map FILE --sky-north DEG --albedo A`, docs/GIS.md "The sun"):
 * diffuse is the diffuse horizontal irradiation times the share of that
 * sky the texel gets under its horizons, 1 on open flat ground.  sky_rgb:
 * sky_w x sky_h linear RGB (top row the zenith, SPEC's equirectangular
 * rows; what hfs_envmap_load gives), its upper half finite and >= 0 and
 * not all black; its column u looks at compass azimuth sky_north + 360 u
 * (degrees, [-360, 360]); NULL: the isotropic sky.  albedo in [0, 1]: the
 * ground's, global then adds albedo times the clear sky's global
 * horizontal irradiation times the part of the texel's view that is
 * ground or terrain (1 - the isotropic sky's share); 0: none, as
 * hfs_gis_insolation (which the beam alone requires: sky_rgb NULL, albedo
 * 0). */
HFS_GIS_API int hfs_gis_insolation_sky(hfs_renderer *r, const hfs_gis_dem *dem,
                                       const hfs_gis_site *site, double from_unix_utc,
                                       double to_unix_utc, double step_min, int directions,
                                       double radius, const float *sky_rgb, int sky_w,
                                       int sky_h, double sky_north, double albedo,
                                       float *beam, float *diffuse, float *global,
                                       hfs_error *err);

#ifdef __cplusplus
}
#endif
#endif /* HFSHADE_GIS_H */
