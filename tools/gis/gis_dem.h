/*
 * gis_dem.h — a DEM for the GIS commands, read through GDAL on its OWN
 * grid (issue 39: the products come back with the input's size,
 * geotransform, CRS and nodata), and the square-celled field the renderer
 * computes on.  The render command's loader (tools/gdal/height_gdal.h)
 * turns a DEM north-up and resamples it; this keeps the file's grid and
 * row order and reuses that loader's steps:
 *   - hfs_gdal_check_dataset: a band, the size guard, no rotation; a DEM
 *     without a geotransform is refused here (its cells' metres unknown);
 *   - hfs_gdal_read_heights: band 1, its nodata value (or --nodata's, which
 *     replaces it, as for render) and NaN/Inf are holes, kept in `hole`;
 *   - holes filled (hfs_height_fill_holes) only to compute their
 *     neighbours; every hole is nodata in every product;
 *   - hfs_gdal_cell_metres: the cells' metres (a geographic CRS's degrees
 *     on its ellipsoid at the centre latitude);
 *   - hfs_gdal_make_square when the cells are not square (gis_resample.h
 *     brings the products back).
 * A grid whose columns run west or rows run north (positive row step)
 * stays as it is: ex, ey say so and the commands turn their azimuths
 * (gis_grid_phi).
 */
#ifndef HFS_GIS_DEM_H
#define HFS_GIS_DEM_H

#include "hfs_io.h"

typedef struct gis_dem {
    int width, height;          /* the input's grid                          */
    unsigned char *hole;        /* width*height, 1 where the input has none  */
    long holes;
    double gt[6];               /* the input's geotransform                  */
    char *wkt;                  /* its CRS ("" none), malloc'ed              */
    int has_nodata;             /* a declared nodata value (band's or opts') */
    double nodata;
    double cx, cy;              /* metres per cell east-west, north-south    */
    int ex, ey;                 /* +x east 1 / west -1; +y south 1 / north -1 */
    /* The square grid the renderer takes (the input's, when square). */
    int sw, sh;
    float *sz;                  /* sw*sh finite heights                      */
    double d;                   /* its cell, metres                          */
    double centre_z;            /* the input's height at texel (w/2, h/2),
                                   filled where it is a hole (its units)     */
} gis_dem;

/* Reads path (opts: --nodata; NULL none).  0, or an error naming path;
 * *dem is zeroed on failure. */
int gis_dem_read(const char *path, const hfs_height_load_opts *opts, gis_dem *dem,
                 hfs_error *err);

void gis_dem_free(gis_dem *dem);

/* The WGS84 longitude and latitude (degrees, east and north positive) of
 * the centre of dem's extent (the geotransform at (w/2, h/2)), through
 * GDAL/OSR (OAMS_TRADITIONAL_GIS_ORDER: longitude first).  0, or an error
 * naming path: a DEM without a CRS, a CRS GDAL cannot transform. */
int gis_dem_lonlat(const gis_dem *dem, const char *path, double *lon, double *lat,
                   hfs_error *err);

#endif /* HFS_GIS_DEM_H */
