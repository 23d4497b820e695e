/*
 * height_gdal.h — the DEMs people have, through GDAL (issue 20; Debian's
 * libgdal-dev): an optional module of the tools, not of the core library.
 * Registered with hfs_height_set_extra_loader, it reads what the library's
 * own loaders do not (GeoTIFF/COG, SRTM .hgt, VRT, and whatever else GDAL
 * opens as a raster):
 *   - band 1 as float; its nodata value (or the caller's, hfs_height_load_opts)
 *     marks holes, filled as every loader's (hfs_height_fill_holes);
 *   - north-up: a geotransform with rotation terms is refused; a south-up
 *     one (positive row step) is flipped so that row 0 is the north edge;
 *   - cell size from the geotransform: a projected CRS's linear units to
 *     metres; a geographic CRS's degrees to metres at the field's centre
 *     latitude on the CRS's ellipsoid (east-west by the prime vertical's
 *     radius of curvature times cos(latitude), north-south by the
 *     meridian's); without a CRS the geotransform's own units;
 *   - non-square cells resampled (bilinear) to square ones of the smaller
 *     size, said in hfs_heightmap.note for the log.
 * Heights are the band's values as they are (metres for the usual DEMs).
 */
#ifndef HFS_HEIGHT_GDAL_H
#define HFS_HEIGHT_GDAL_H

#include "hfs_io.h"

/* hfs_height_loader_fn for GDAL: HFS_E_UNSUPPORTED when GDAL cannot open
 * path as a raster. */
int hfs_gdal_height_load(const char *path, const hfs_height_load_opts *opts,
                         hfs_heightmap *out, hfs_error *err);

/* Registers hfs_gdal_height_load with the height loader (and GDAL's
 * drivers): the tools call it once at start-up. */
void hfs_gdal_register(void);

#endif /* HFS_HEIGHT_GDAL_H */
