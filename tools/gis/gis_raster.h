/*
 * gis_raster.h — a GIS product written as a GeoTIFF through GDAL, on the
 * input DEM's grid (issue 39):
 *   - Float32 bands, each with its description and unit;
 *   - the input's geotransform and CRS (WKT), and a nodata value on every
 *     band (the holes of the input);
 *   - dataset metadata items NAME=VALUE naming the product and how it was
 *     made (HFS_PRODUCT, HFS_DIRECTIONS, ...; docs/GIS.md lists them);
 *   - GTiff: TILED=YES, 256 x 256 blocks, COMPRESS=DEFLATE, PREDICTOR=3
 *     (floating-point prediction); with cog set, GDAL's COG driver instead
 *     (a Cloud Optimized GeoTIFF: COMPRESS=DEFLATE, PREDICTOR=YES,
 *     OVERVIEWS=AUTO).
 * Encoded in a GDAL memory file and written through the run's output set
 * (hfs_gdal_write_copy): nothing is left behind on failure.  A value that
 * is neither finite nor the nodata value is refused (SPEC: no NaN or Inf
 * reaches an output, unless the nodata value is NaN itself).
 */
#ifndef HFS_GIS_RASTER_H
#define HFS_GIS_RASTER_H

#include "hfs_io.h"

#define GIS_RASTER_MAX_BANDS 3
#define GIS_RASTER_MAX_META 24

typedef struct gis_band {
    const float *v;           /* width*height values, row 0 first           */
    const char *description;  /* GDAL's band description                    */
    const char *unit;         /* "degrees", "" for none                     */
} gis_band;

typedef struct gis_raster {
    int width, height, n_bands;
    gis_band band[GIS_RASTER_MAX_BANDS];
    const double *geotransform; /* 6 numbers                                */
    const char *wkt;            /* "" or NULL: no CRS                       */
    double nodata;
    const char *meta[GIS_RASTER_MAX_META]; /* "NAME=VALUE", NULL-terminated */
    int cog;
} gis_raster;

int gis_raster_write(hfs_outputs *o, const char *path, const gis_raster *r, hfs_error *err);

#endif /* HFS_GIS_RASTER_H */
