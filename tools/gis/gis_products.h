/*
 * gis_products.h — the GIS products of a DEM (SPEC.md "Terrain rasters"),
 * computed on its square-celled field (gis_dem.h) from
 * hfs_renderer_horizons and brought back to the input's own grid
 * (gis_resample.h), nodata where the input has none.  The arithmetic is
 * gis_math.h's; this is the plumbing between the renderer and the rasters.
 * Azimuths come in map terms (SPEC's phi: clockwise from east on a
 * north-up map) and are turned to the grid's own (gis_grid_phi) here.
 * No GDAL.
 */
#ifndef HFS_GIS_PRODUCTS_H
#define HFS_GIS_PRODUCTS_H

#include "gis_dem.h"
#include "gis_math.h"

/* Openness's default search radius when none is given: 10 cells of the
 * input's larger side, so that every direction reaches 10 input cells
 * (the Relief Visualization Toolbox's default radius for sky-view factor
 * and openness, Zaksek, Kokalj et al.: openness is a local measure, and a
 * whole-DEM radius would let distant ranges swamp it). */
#define GIS_OPENNESS_DEFAULT_CELLS 10

typedef struct gis_compute {
    hfs_renderer *r;
    const gis_dem *dem;
    double zscale;
    double radius;           /* metres, 0: the whole DEM                   */
    float nodata;            /* written where the input has no data        */
    /* sun, insolation: zscale times the whole DEM's highest minus lowest
     * height (the shadows' reach), when the field computed on is only a
     * window of it (has_relief); else taken from dem. */
    int has_relief;
    double relief;
    int sweep;               /* 1: horizons by the sweep (gis_sweep.h), radius 0 */
    double convergence_deg;  /* sun, insolation: the grid convergence at the
                                site (gis_dem_lonlat): a true compass azimuth
                                A is the grid's A - convergence_deg; 0: the
                                grid's north is true north                */
} gis_compute;

/* The n_dirs map azimuths of the sky-view factor and openness: ccw-east
 * 0, 360/n, 2 * 360/n, ... degrees (starting east, going north), as SPEC
 * phi in radians into phi[n_dirs]. */
void gis_product_directions(double *phi, int n_dirs);

/* out[w*h] (the input's grid): the sky-view factor of kind over n_dirs
 * directions (gis_product_directions). */
int gis_product_svf(const gis_compute *c, int n_dirs, gis_svf_kind kind, float *out,
                    hfs_error *err);

/* pos[w*h], neg[w*h]: positive and negative openness in degrees over
 * n_dirs directions; negative openness is the positive openness of the
 * negated DEM (its horizons searched on -z). */
int gis_product_openness(const gis_compute *c, int n_dirs, float *pos, float *neg,
                         hfs_error *err);

/* Azimuth k's horizon raster (the input's grid, degrees >= 0). */
typedef int (*gis_raster_fn)(void *user, int k, const float *deg, hfs_error *err);

/* For each of the n map azimuths phi[k] (radians), its horizon elevation
 * angles in degrees, clamped to >= 0 (r.horizon -d), to fn in order. */
int gis_product_horizons(const gis_compute *c, const double *phi, int n, gis_raster_fn fn,
                         void *user, hfs_error *err);

#endif /* HFS_GIS_PRODUCTS_H */
