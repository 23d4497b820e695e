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
 *
 * In two steps when the command streams (gis_stream.h): gis_dem_open reads
 * what the file says of itself (grid, georeferencing, nodata, cells) and
 * keeps it open; then either gis_dem_load reads the whole band, or
 * gis_dem_read_window reads one window at a time (GDAL's windowed
 * RasterIO), its holes filled in the window alone.
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
    double cx, cy;              /* metres per cell east-west, north-south;
                                   cy = cx when the cells are square         */
    int square;                 /* cx, cy within 1e-6 (the render loader's
                                   rule): computed on the input's own grid   */
    int ex, ey;                 /* +x east 1 / west -1; +y south 1 / north -1 */
    /* The square grid the renderer takes (the input's, when square). */
    int sw, sh;
    float *sz;                  /* sw*sh finite heights (gis_dem_load)       */
    double d;                   /* its cell, metres (known at gis_dem_open)  */
    double centre_z;            /* the input's height at texel (w/2, h/2),
                                   filled where it is a hole (its units)     */
    void *ds;                   /* the GDAL dataset while open (gis_dem_open
                                   to gis_dem_load or gis_dem_free)          */
} gis_dem;

/* Reads path (opts: --nodata; NULL none): gis_dem_open, then gis_dem_load.
 * 0, or an error naming path; *dem is zeroed on failure. */
int gis_dem_read(const char *path, const hfs_height_load_opts *opts, gis_dem *dem,
                 hfs_error *err);

/* Opens path and reads all but its heights: the grid, geotransform, CRS,
 * nodata, the cells' metres, `square` and the cell computed on (d; sw, sh
 * are the input's size until gis_dem_load resamples).  The dataset stays
 * open in dem->ds.  0, or an error naming path; *dem zeroed on failure. */
int gis_dem_open(const char *path, const hfs_height_load_opts *opts, gis_dem *dem,
                 hfs_error *err);

/* The whole band of an opened dem: hole, holes, sz (resampled to square
 * cells when they are not), centre_z; the dataset closed.  0, or an error
 * naming path (dem then to be freed by the caller). */
int gis_dem_load(gis_dem *dem, const char *path, hfs_error *err);

/* The window of w x h texels at (x0, y0) of an opened dem's band 1, read
 * with GDAL's windowed RasterIO (the band is never read whole): z[w*h] its
 * heights, hole[w*h] its holes (the nodata value gis_dem_open settled,
 * NaN, Inf), *holes their count, the holes filled by push-pull within the
 * window (hfs_height_fill_holes; a hole fills as in the whole DEM when
 * the window's ends are those of the DEM or multiples of the fill's
 * blocks: gis_stream.h).  A window without a valid texel is left as read
 * (*holes == w*h): the caller writes nodata.  0, or an error naming path. */
int gis_dem_read_window(const gis_dem *dem, const char *path, int x0, int y0, int w, int h,
                        float *z, unsigned char *hole, long *holes, hfs_error *err);

/* Of an opened dem, read strip by strip (never whole): *lo and *hi, its
 * lowest and highest valid heights (*lo > *hi when it has none), and
 * dem->centre_z, the height at texel (w/2, h/2), filled from a 64 x 64
 * window around it where it is a hole (as the whole band's fill where the
 * hole is a few texels across).  0, or an error naming path. */
int gis_dem_scan(gis_dem *dem, const char *path, double *lo, double *hi, hfs_error *err);

/* Only dem->centre_z, as gis_dem_scan reads it (a window around it). */
int gis_dem_scan_centre(gis_dem *dem, const char *path, hfs_error *err);

/* Frees what GDAL holds of an opened dem's blocks (read so far). */
void gis_dem_drop_cache(const gis_dem *dem);

/* Frees everything, closing the dataset if it is open.  NULL-safe. */
void gis_dem_free(gis_dem *dem);

/* The WGS84 longitude and latitude (degrees, east and north positive) of
 * the centre of dem's extent (the geotransform at (w/2, h/2)), through
 * GDAL/OSR (OAMS_TRADITIONAL_GIS_ORDER: longitude first), and with
 * convergence_deg not NULL the grid convergence there: the angle from
 * true north to the grid's north (up the columns of the DEM turned
 * north-up), degrees, positive where grid north lies east of true north
 * (a transverse Mercator grid east of its central meridian, north of the
 * equator: about (lon - lon0) sin(lat)); 0 on a longitude-latitude grid.
 * So a true compass azimuth A is the grid's A - convergence.  Found by
 * carrying the meridian 0.001 degrees either side of the centre back into
 * the DEM's pixels.  0, or an error naming path: a DEM without a CRS, a
 * CRS GDAL cannot transform either way. */
int gis_dem_lonlat(const gis_dem *dem, const char *path, double *lon, double *lat,
                   double *convergence_deg, hfs_error *err);

#endif /* HFS_GIS_DEM_H */
