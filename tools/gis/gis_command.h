/*
 * gis_command.h — `hfshade svf | horizon | openness` (issue 39), once the
 * command line is parsed (tools/cli_gis.c parses it; docs/GIS.md is the
 * user's page).  One run: the output files checked against the DEM and
 * each other (gis_outputs.h), the DEM read on its own grid (gis_dem.h),
 * horizons on its square-celled field (gis_horizons.h), the product
 * (gis_products.h) brought back to the input's grid (gis_resample.h) and
 * written as GeoTIFF (gis_raster.h), all files committed together.
 * Needs GDAL; the parsing does not.
 */
#ifndef HFS_GIS_COMMAND_H
#define HFS_GIS_COMMAND_H

#include "gis_math.h"
#include "hfs_io.h"

typedef enum gis_product { GIS_SVF = 0, GIS_HORIZON, GIS_OPENNESS } gis_product;

typedef struct gis_args {
    gis_product product;
    const char *dem;            /* the input                                  */
    const char *out;            /* -o: the file (svf, openness) or PREFIX     */
    int directions;             /* svf, openness: equally spaced from east    */
    gis_svf_kind svf;           /* svf: --lambertian                          */
    double radius;              /* metres, 0: the whole DEM                   */
    int radius_given;           /* openness: else 10 cells (gis_products.h)   */
    hfs_backend backend;
    double zscale;
    hfs_height_load_opts load;  /* --nodata                                   */
    int cog, quiet;
    /* horizon: the azimuths, degrees in `convention`, as the user gave them;
     * file names with `decimals` decimals (gis_horizon_name). */
    double *azimuth;            /* n_azimuths, the caller's                   */
    int n_azimuths, decimals;
    gis_convention convention;
} gis_args;

/* Runs the command.  0, or an error (one line in err: the input or output
 * named, and the problem); nothing is written on failure. */
int gis_command_run(const gis_args *a, hfs_error *err);

#endif /* HFS_GIS_COMMAND_H */
