/*
 * hfshade_gis.h — public interface of libhfshade_gis (issue 40): the GIS
 * products of `hfshade svf | horizon | openness` (docs/GIS.md, SPEC.md
 * "Terrain rasters") on a DEM held in memory, for bindings (the Python
 * module) and programs that have their heights already.  The same code as
 * the commands (tools/gis: gis_products, gis_math, gis_horizons,
 * gis_resample), over libhfshade's hfs_renderer_horizons: on the same
 * heights, cell size, options and backend, every value equals the
 * command's GeoTIFF, bit for bit.  No GDAL: the caller reads the DEM.
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
 * (the argument named); nothing is written to out on failure.
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
    HFS_GIS_OPENNESS            /* 0..180 degrees                             */
} hfs_gis_product;

/* radius: the search distance in metres, [0, 1e9], 0 = the whole DEM; or
 * HFS_GIS_RADIUS_DEFAULT, the command's default: the whole DEM for svf and
 * horizon, 10 cells for openness (the Relief Visualization Toolbox's). */
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

#ifdef __cplusplus
}
#endif
#endif /* HFSHADE_GIS_H */
