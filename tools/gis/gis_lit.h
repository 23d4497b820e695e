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

/* dem_path (opened with opts) as the render's jobs need it: georeferenced,
 * rows running south and columns east, square cells, so that the lit grid
 * is the file's own, texel for texel, and a job's part has a place in it.
 * 0, or an error naming dem_path and what it lacks. */
int gis_lit_check_grid(const char *dem_path, const hfs_height_load_opts *opts, hfs_error *err);

/* Writes part (a render job's lit part of dem_path's grid: part->width x
 * part->height texels at column ix, row iy; cli_render_job.h) to path
 * through o, as gis_lit_write writes a whole grid: 3 Float32 bands, the
 * part's own geotransform (the DEM's shifted to it), the CRS, the DEM's
 * holes in it as nodata.  The DEM must pass gis_lit_check_grid.  0, or an
 * error naming path. */
int gis_lit_write_part(hfs_outputs *o, const char *path, const char *dem_path,
                       const hfs_height_load_opts *opts, const hfs_image *part, int ix, int iy,
                       hfs_error *err);

#endif /* HFS_GIS_LIT_H */
