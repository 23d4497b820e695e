/*
 * gis_raster.h — a GIS product written as a GeoTIFF through GDAL, on the
 * input DEM's grid (issue 39):
 *   - Float32 bands, each with its description and unit;
 *   - the input's geotransform and CRS (WKT), and a nodata value on every
 *     band (the holes of the input);
 *   - dataset metadata items NAME=VALUE naming the product and how it was
 *     made (HFS_PRODUCT, HFS_DIRECTIONS, ...; docs/GIS.md lists them);
 *   - GTiff: TILED=YES, 256 x 256 blocks, COMPRESS=DEFLATE, PREDICTOR=3
 *     (floating-point prediction; none for a plain raster); with cog set,
 *     GDAL's COG driver instead (a Cloud Optimized GeoTIFF:
 *     COMPRESS=DEFLATE, PREDICTOR=YES or NO, OVERVIEWS=AUTO).
 * Encoded in a GDAL memory file and written through the run's output set
 * (hfs_gdal_write_copy): nothing is left behind on failure.  A value that
 * is neither finite nor the nodata value is refused (SPEC: no NaN or Inf
 * reaches an output, unless the nodata value is NaN itself).
 */
#ifndef HFS_GIS_RASTER_H
#define HFS_GIS_RASTER_H

#include "hfs_io.h"

#include <gdal.h>

#define GIS_RASTER_MAX_BANDS 3
#define GIS_RASTER_MAX_META 32

typedef struct gis_band {
    const float *v;           /* width*height values, row 0 first (NULL for
                                 a file written window by window)           */
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
    int plain; /* no predictor: values in long runs (horizon angles, 0
                  wherever the sky is open) shrink more, and faster,
                  without one */
} gis_raster;

int gis_raster_write(hfs_outputs *o, const char *path, const gis_raster *r, hfs_error *err);

/* The encoding alone (thread-safe for rasters of their own): *bytes (*len
 * of them; free with VSIFree) the file gis_raster_write would write. */
int gis_raster_encode(const char *path, const gis_raster *r, void **bytes, size_t *len,
                      hfs_error *err);

/* What a file written window by window (gis_raster_stream.h) shares with
 * gis_raster_write's: */
/* the creation options, GTiff's or the COG driver's, with the predictor
 * or plain (a list to CSLDestroy); */
char **gis_raster_options(int cog, int plain);

/* r's georeferencing, bands' descriptions, units and nodata value, and
 * metadata items set on ds (r's band values are not read); */
void gis_raster_describe(GDALDatasetH ds, const gis_raster *r);

/* and the first of the n values of planes v[0 .. n_bands - 1] that is
 * neither finite nor the nodata value (its band, from 1, in *band), or -1. */
long gis_raster_bad_value(const float *const *v, int n_bands, size_t n, double nodata,
                          int *band);

#endif /* HFS_GIS_RASTER_H */
