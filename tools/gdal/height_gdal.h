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

#include <gdal.h>

/* hfs_height_loader_fn for GDAL: HFS_E_UNSUPPORTED when GDAL cannot open
 * path as a raster. */
int hfs_gdal_height_load(const char *path, const hfs_height_load_opts *opts,
                         hfs_heightmap *out, hfs_error *err);

/* The steps of hfs_gdal_height_load, for the tools that keep the file's
 * own grid (the GIS commands, tools/gis/gis_dem.h):
 *
 * The opened dataset's checks: at least one band, 2x2 .. the opts' (or
 * the default) size guard, a geotransform without rotation terms.  gt is
 * the file's geotransform, or {0, 0, 0, 0, 0, -1} (gt[1] = 0: no cell
 * size known) when it has none. */
int hfs_gdal_check_dataset(GDALDatasetH ds, const char *path, const hfs_height_load_opts *opts,
                           double gt[6], hfs_error *err);

/* Band 1 as floats into *z (malloc'ed, the caller's; NULL on failure), in
 * the file's row order, with its nodata value (or opts' when opts has
 * one: it replaces the band's) made NaN; NaN and Inf stay as they are:
 * every non-finite height is a hole for hfs_height_fill_holes. */
int hfs_gdal_read_heights(GDALDatasetH ds, const char *path, const hfs_height_load_opts *opts,
                          float **z, hfs_error *err);

/* The east-west (*cx) and north-south (*cy) sizes in metres of a cell of
 * a grid of h rows with geotransform gt in the CRS wkt (NULL or "": none,
 * the geotransform's own units), as the header above says. */
void hfs_gdal_cell_metres(const char *wkt, const double gt[6], int h, double *cx, double *cy);

/* Resamples z (w x h, cells cx x cy) to square cells of d = min(cx, cy),
 * bilinearly and node-aligned: the new node (i, j) is the old grid's point
 * (i d / cx, j d / cy), clamped to its last node; the new size is
 * lround((w - 1) cx / d) + 1 by lround((h - 1) cy / d) + 1.  *z, *w, *h
 * replaced (the old *z freed), *cell = d.  0, or HFS_E_NOMEM (all kept). */
int hfs_gdal_make_square(float **z, int *w, int *h, double cx, double cy, double *cell);

/* Registers hfs_gdal_height_load with the height loader: the tools call
 * it once at start-up.  GDAL itself is loaded, and its drivers
 * registered, by the first file only this loader reads (gdal_lazy.h). */
void hfs_gdal_register(void);

#endif /* HFS_HEIGHT_GDAL_H */
