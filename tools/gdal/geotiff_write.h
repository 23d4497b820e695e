/*
 * geotiff_write.h — the lit image as a GeoTIFF through GDAL (issue 20:
 * outputs keep the georeferencing): 3 Float32 bands (R, G, B linear exit
 * radiance, SPEC's output quantity, as the PFM holds it), DEFLATE, with the
 * height field's geotransform and CRS when its loader knew them
 * (hfs_heightmap has_georef: the lit image is the height grid's, texel for
 * texel, north-up), else none.  Encoded in GDAL's memory files, then
 * written through the run's output set (hfs_bytes_write_to): nothing is
 * left behind on failure.
 */
#ifndef HFS_GEOTIFF_WRITE_H
#define HFS_GEOTIFF_WRITE_H

#include "hfs_io.h"

#include <gdal.h>

int hfs_gdal_write_geotiff(hfs_outputs *o, const char *path, const hfs_image *img,
                           const hfs_heightmap *hm, hfs_error *err);

/* The dataset src (a MEM dataset, usually) encoded by GDAL's driver
 * `driver` ("GTiff", "COG", ...) with its creation options opts (a CSL
 * NAME=VALUE list, NULL: none) into a memory file of this call's own
 * (/vsimem/), and those bytes written as the output path of o
 * (hfs_bytes_write_to; o NULL: written at once, atomically).  GDAL's
 * messages are kept quiet; on failure err names path and GDAL's last
 * message, and nothing is written.  src NULL is a failure (so a caller
 * can pass what its MEM dataset's creation returned). */
int hfs_gdal_write_copy(hfs_outputs *o, const char *path, GDALDatasetH src, const char *driver,
                        char **opts, hfs_error *err);

/* The encoding alone: *bytes (*len of them; free with VSIFree) the file
 * hfs_gdal_write_copy would write, path only naming it in err.  Calls on
 * other threads with datasets of their own may run at the same time (each
 * its own memory file; GDAL's error state is per thread). */
int hfs_gdal_encode_copy(const char *path, GDALDatasetH src, const char *driver, char **opts,
                         void **bytes, size_t *len, hfs_error *err);

/* A world file beside a PNG or PFM of the grid (the ESRI six lines GDAL
 * and GIS tools read, named PATH + "w": out.png -> out.pngw): the pixel
 * size, no rotation, the upper-left texel's centre, from hm's
 * geotransform (north-up).  Added to o and written through it; nothing
 * when hm has no georeferencing.  The CRS travels in the GeoTIFF only. */
int hfs_gdal_write_world_file(hfs_outputs *o, const char *path, const hfs_heightmap *hm,
                              hfs_error *err);

#endif /* HFS_GEOTIFF_WRITE_H */
