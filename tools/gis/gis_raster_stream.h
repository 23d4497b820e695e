/*
 * gis_raster_stream.h — a GIS product's GeoTIFF written window by window
 * (issue 39: a DEM over the tile size streams, gis_stream.h), so that no
 * whole raster is held in memory at any time:
 *   - created up front at a file the caller names (a temporary of the
 *     run's outputs, gis_outputs_temporary) with GDAL's GTiff driver and
 *     the options of gis_raster_write's files (TILED=YES, 256 x 256,
 *     COMPRESS=DEFLATE, PREDICTOR=3) and BIGTIFF=IF_SAFER (a compressed
 *     file's size is not known when it is created), and the same bands'
 *     descriptions, units, nodata, geotransform, CRS and metadata
 *     (gis_raster_describe);
 *   - windows written with GDAL's windowed RasterIO, each refused when it
 *     holds a value neither finite nor nodata (as gis_raster_write's);
 *   - gis_raster_stream_flush writes the blocks GDAL holds and frees them
 *     (the caller calls it when the rows written end on a block row);
 *   - with r->cog the GTiff is written at FILE.part and, at the finish,
 *     copied to FILE by GDAL's COG driver (GDALCreateCopy reads it block
 *     by block; gis_raster_write's COG options), FILE.part removed.
 * On failure FILE stays for its owner (the output group) to remove; the
 * .part is this module's and always goes.
 */
#ifndef HFS_GIS_RASTER_STREAM_H
#define HFS_GIS_RASTER_STREAM_H

#include "gis_raster.h"

typedef struct gis_raster_stream gis_raster_stream;

/* Creates r's file (r's band values are not read) at file; path names it
 * in messages (the output the user gave; both kept, not copied).  0, or
 * an error naming path (*s NULL). */
int gis_raster_stream_open(gis_raster_stream **s, const char *path, const char *file,
                           const gis_raster *r, hfs_error *err);

/* The window of w x h texels at (x0, y0): v holds the bands' planes of
 * w*h values one after the other, row 0 first.  0, or an error. */
int gis_raster_stream_write(gis_raster_stream *s, int x0, int y0, int w, int h,
                            const float *v, hfs_error *err);

/* The blocks GDAL holds of the file written and freed.  0, or an error. */
int gis_raster_stream_flush(gis_raster_stream *s, hfs_error *err);

/* Finishes the file (closed; with cog the COG made from it) and frees s.
 * 0, or an error naming the output. */
int gis_raster_stream_finish(gis_raster_stream *s, hfs_error *err);

/* Frees s without finishing (its .part removed).  NULL-safe. */
void gis_raster_stream_abort(gis_raster_stream *s);

#endif /* HFS_GIS_RASTER_STREAM_H */
