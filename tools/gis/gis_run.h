/*
 * gis_run.h — one run of a GIS command, as the products' writers share it
 * (internal to the commands): gis_command.c makes the run (outputs, DEM,
 * renderer), writes svf, horizon and openness, commits and prints the
 * summary; gis_sun_command.c describes and writes sun and insolation;
 * gis_stream.c writes svf, horizon and openness window by window;
 * gis_run.c holds what they take from the run (metadata, the rasters of
 * the input's grid), so none of them calls another back.  Needs GDAL (the
 * writers' rasters).
 */
#ifndef HFS_GIS_RUN_H
#define HFS_GIS_RUN_H

#include "gis_command.h"
#include "gis_dem.h"
#include "gis_outputs.h"
#include "gis_products.h"
#include "gis_raster.h"
#include "gis_stream.h"
#include "gis_sun.h"

#define GIS_RUN_META_LEN 128

typedef struct gis_run {
    const gis_args *a;
    gis_outputs *outs;
    char prefix[4096];       /* horizon: -o without a trailing .tif         */
    char **names;            /* horizon: the n_azimuths file names          */
    gis_dem dem;
    gis_compute c;
    char meta[GIS_RASTER_MAX_META - 2][GIS_RUN_META_LEN]; /* every file's items */
    int n_meta;
    int no_render;           /* nothing to render: no renderer is made      */
    /* whole or window by window (gis_stream.h) */
    gis_stream_mode mode;
    int halo;                /* streamed: texels around each window         */
    int windows;             /* streamed: windows computed                  */
    double relief;           /* sun, insolation: the DEM's relief as scanned
                                (its units), when c.has_relief without
                                --relief                                   */
    /* sun, insolation (gis_sun_command.c) */
    hfs_solar_site site;
    gis_sun_at sun;          /* sun: the instant's                          */
    gis_period period;       /* insolation                                  */
    gis_sky_map sky;         /* insolation --sky-map (period.sky points here) */
    gis_period_stats stats;
} gis_run;

/* Adds one "NAME=VALUE" item to every file of the run. */
void gis_run_meta(gis_run *r, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* A one-band raster of the input's grid with the run's metadata and
 * `extra` (NULL: none). */
gis_raster gis_run_raster(const gis_run *r, const char *extra);

/* The product's raster (bands' descriptions and units) with the values
 * v, n a band: svf one band, openness and sun two (v, v + n), insolation
 * three (one with --beam-only); v NULL for a file written window by
 * window.  Not horizon's (gis_run_horizon_raster). */
gis_raster gis_run_product_raster(const gis_run *r, const float *v, size_t n);

/* The bands of r's product (svf 1, openness and sun 2, insolation 3, or 1
 * with --beam-only; horizon 1 a file). */
int gis_run_bands(const gis_run *r);

/* The strings of a horizon file's raster (the caller's: alive while the
 * raster is used). */
typedef struct gis_horizon_text {
    char value[64], item[GIS_RUN_META_LEN], what[160];
} gis_horizon_text;

/* horizon: azimuth k's raster, deg its values (NULL: window by window). */
gis_raster gis_run_horizon_raster(const gis_run *r, int k, const float *deg,
                                  gis_horizon_text *t);

/* Opens the run's DEM, describes the product (radius, nodata, metadata;
 * sun and insolation: the site, the sun or the period) and settles
 * whether it is computed whole or window by window (r->mode, r->halo:
 * gis_stream.h); with load, a DEM computed whole is read whole.  What
 * `hfshade tiles plan` (load 0) and the commands share, so a plan's
 * windows are the streamed command's.  0, or an error naming the DEM
 * (--job on a DEM that does not stream, among them). */
int gis_run_open(gis_run *r, int load, hfs_error *err);

/* sun, insolation: the site (the DEM's centre: WGS84 longitude and
 * latitude, its height), the sun or the period, nodata and the metadata.
 * 0, or an error (a DEM without a CRS, a site out of range). */
int gis_sun_describe(gis_run *r, hfs_error *err);

/* sun, insolation: how the DEM is computed (r->mode, r->halo), the
 * site and sun described: window by window when --tile asks for it, the
 * cells are square, the backend is not the truth (it renders the whole
 * DEM) and the shadows' search radius (the sun's reach from the whole
 * DEM's relief r->c.relief, cut by --radius; insolation: --radius, which
 * its sky needs) leaves a halo narrower than the DEM. */
gis_stream_mode gis_sun_choose(gis_run *r);

/* sun, insolation: renders and writes the raster (whole). */
int gis_sun_write(gis_run *r, hfs_error *err);

/* sun, insolation: the summary line's middle ("sun at azimuth ..."). */
void gis_sun_summary(const gis_run *r, char *buf, size_t n);

#endif /* HFS_GIS_RUN_H */
