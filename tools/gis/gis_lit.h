/*
 * gis_lit.h — `hfshade render --geotiff` on the DEM's own grid (issue 39:
 * "resample inside, not in what users get").  The render command's loader
 * resamples a DEM of non-square cells (a geographic one) to square cells
 * and fills its holes; the lit image is of that grid.  Here the DEM is read
 * again on its own grid (gis_dem.h: the same checks, fill and
 * make_square), the lit RGB sampled back at the input's texels
 * (gis_resample.h), the input's holes written as nodata, with the input's
 * geotransform and CRS: 3 Float32 bands of linear exit radiance.
 */
#ifndef HFS_GIS_LIT_H
#define HFS_GIS_LIT_H

#include "hfs_io.h"

/* Writes lit (the render of dem_path, loaded with opts as hm) to path
 * through o: on dem_path's own grid when hm has a geotransform and the
 * file's rows run south and columns east; else (the render's loader turns
 * other grids north-up, and a file without a geotransform has no grid to
 * go back to) the grid as rendered, hfs_gdal_write_geotiff.  0, or an
 * error naming path. */
int gis_lit_write(hfs_outputs *o, const char *path, const char *dem_path,
                  const hfs_height_load_opts *opts, const hfs_image *lit,
                  const hfs_heightmap *hm, hfs_error *err);

#endif /* HFS_GIS_LIT_H */
