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

int hfs_gdal_write_geotiff(hfs_outputs *o, const char *path, const hfs_image *img,
                           const hfs_heightmap *hm, hfs_error *err);

/* A world file beside a PNG or PFM of the grid (the ESRI six lines GDAL
 * and GIS tools read, named PATH + "w": out.png -> out.pngw): the pixel
 * size, no rotation, the upper-left texel's centre, from hm's
 * geotransform (north-up).  Added to o and written through it; nothing
 * when hm has no georeferencing.  The CRS travels in the GeoTIFF only. */
int hfs_gdal_write_world_file(hfs_outputs *o, const char *path, const hfs_heightmap *hm,
                              hfs_error *err);

#endif /* HFS_GEOTIFF_WRITE_H */
