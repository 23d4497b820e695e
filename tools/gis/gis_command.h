/*
 * gis_command.h — `hfshade svf | horizon | openness | sun | insolation`
 * (issue 39), once the command line is parsed (tools/cli_gis.c parses it;
 * docs/GIS.md is the user's page).  One run: the output files checked
 * against the DEM and each other (gis_outputs.h), the DEM read on its own
 * grid (gis_dem.h), horizons or renders on its square-celled field
 * (gis_horizons.h, gis_sun.h), the product (gis_products.h,
 * gis_sun_command.c) brought back to the input's grid (gis_resample.h)
 * and written as GeoTIFF (gis_raster.h), all files committed together.
 * Needs GDAL; the parsing does not.
 */
#ifndef HFS_GIS_COMMAND_H
#define HFS_GIS_COMMAND_H

#include "gis_math.h"
#include "hfs_io.h"
#include "solar_position.h"

typedef enum gis_product {
    GIS_SVF = 0,
    GIS_HORIZON,
    GIS_OPENNESS,
    GIS_SUN,        /* one instant's beam on the terrain (gis_sun.h)        */
    GIS_INSOLATION, /* irradiation over a period, r.sun's mode 2            */
    GIS_N_PRODUCTS
} gis_product;

/* insolation: at most this many steps (--from, --to, --step). */
#define GIS_MAX_STEPS 100000L

/* svf, horizon, openness: --tile, the windows' side in texels when a DEM
 * streams (gis_stream.h): 0 (never), or GIS_TILE_MIN .. GIS_TILE_MAX. */
#define GIS_TILE_DEFAULT 4096
#define GIS_TILE_MIN 16
#define GIS_TILE_MAX 1048576

typedef struct gis_args {
    gis_product product;
    const char *dem;            /* the input                                  */
    const char *out;            /* -o: the file (svf, openness) or PREFIX     */
    int directions;             /* svf, openness: equally spaced from east    */
    gis_svf_kind svf;           /* svf: --lambertian                          */
    double radius;              /* metres, 0: the whole DEM                   */
    int radius_given;           /* openness: else 10 cells (gis_products.h)   */
    double relief;              /* sun, insolation: --relief, the DEM's highest
                                 * minus lowest valid height (its units)     */
    int relief_given;           /* else measured by reading the DEM           */
    int tile;                   /* --tile: texels a side, 0 never streams     */
    int job;                    /* --job K: only window K (from 1, row by row)
                                 * of the streamed windows, as a raster of its
                                 * own extent (hfshade tiles run); 0: all     */
    hfs_backend backend;
    int sweep;                  /* --method sweep: horizons by gis_sweep.h     */
    double zscale;
    hfs_height_load_opts load;  /* --nodata                                   */
    int cog, quiet;
    /* horizon: the azimuths, degrees in `convention`, as the user gave them;
     * file names with `decimals` decimals (gis_horizon_name). */
    double *azimuth;            /* n_azimuths, the caller's                   */
    int n_azimuths, decimals;
    gis_convention convention;
    /* sun, insolation: UTC instants (the command line's local date-times
     * with their time zone), Julian days of them (hfs_solar_julian_day). */
    hfs_solar_time at, from, to; /* sun: at; insolation: [from, to)       */
    double jd, jd_from, jd_to;
    double step_min;             /* insolation: minutes, > 0              */
    long n_steps;                /* insolation: ceil((to - from) / step)  */
    double linke;                /* Linke turbidity (clear_sky.h)         */
    const char *sky_map;         /* insolation: --sky-map, the sky's shape
                                  * (gis_sky_map.h); NULL: isotropic       */
    double sky_north;            /* --sky-north: the map's left edge, compass
                                  * degrees                               */
    double albedo;               /* insolation --albedo: the ground's, for the
                                  * reflected part of band 3; 0: none      */
    int beam_only;               /* insolation --beam-only: band 1 alone, no
                                  * sky's horizons searched                */
} gis_args;

struct gis_dem;

/* svf, horizon, openness: the search radius of a on dem, metres (0: the
 * whole DEM): --radius, or openness's default of 10 cells. */
double gis_command_radius(const gis_args *a, const struct gis_dem *d);

/* Runs the command.  0, or an error (one line in err: the input or output
 * named, and the problem); nothing is written on failure. */
int gis_command_run(const gis_args *a, hfs_error *err);

#endif /* HFS_GIS_COMMAND_H */
