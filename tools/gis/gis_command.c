/*
 * gis_command.c — see gis_command.h.  The order keeps a failure cheap and
 * clean: the outputs are checked before the DEM is read, the DEM before a
 * renderer (a GL context) is made, and every file is a temporary until
 * the last one is written.  svf, horizon and openness are written here
 * when the DEM is computed whole, window by window in gis_stream.c; sun
 * and insolation in gis_sun_command.c (gis_run.h).
 */
#include "gis_command.h"

#include "gis_horizon_files.h"
#include "gis_run.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static const char *const product_name[] = {"svf", "horizon", "openness", "sun", "insolation"};
static const char *const backend_name[] = {"gles", "gles", "cpu", "truth"};

/* The horizon command's file names: PREFIX (a trailing .tif dropped) and
 * each azimuth, as r.horizon names its maps; two azimuths of one name are
 * an error (0 and 360 are one direction). */
static int horizon_names(gis_run *r, hfs_error *err)
{
    const gis_args *a = r->a;
    char *prefix = r->prefix;
    if (snprintf(prefix, sizeof r->prefix, "%s", a->out) >= (int)sizeof r->prefix)
        return hfs_fail(err, HFS_E_INVALID, "%s: output prefix too long", a->out);
    const size_t len = strlen(prefix);
    if (len > 4 && !strcmp(prefix + len - 4, ".tif"))
        prefix[len - 4] = '\0';
    if (!(r->names = calloc((size_t)a->n_azimuths, sizeof *r->names)))
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", a->out);
    for (int k = 0; k < a->n_azimuths; ++k) {
        char name[sizeof r->prefix + 32];
        if (gis_horizon_name(name, sizeof name, prefix, a->azimuth[k], a->decimals) ||
            !(r->names[k] = malloc(strlen(name) + 1)))
            return hfs_fail(err, HFS_E_INVALID, "%s: output prefix too long", a->out);
        memcpy(r->names[k], name, strlen(name) + 1);
        for (int l = 0; l < k; ++l)
            if (!strcmp(r->names[l], name))
                return hfs_fail(err, HFS_E_INVALID, "--azimuths: %g and %g are the same "
                                "direction (both %s)", a->azimuth[l], a->azimuth[k], name);
    }
    return HFS_OK;
}

/* Every output checked against the DEM and each other, nothing written. */
static int plan_outputs(gis_run *r, hfs_error *err)
{
    const gis_args *a = r->a;
    const int n = a->product == GIS_HORIZON ? a->n_azimuths : 1;
    int rc = a->product == GIS_HORIZON ? horizon_names(r, err) : HFS_OK;
    if (!rc)
        rc = gis_outputs_create(&r->outs, a->dem, n, err);
    for (int k = 0; k < n && !rc; ++k)
        rc = gis_outputs_add(r->outs, a->product == GIS_HORIZON ? r->names[k] : a->out, err);
    return rc;
}

double gis_command_radius(const gis_args *a, const gis_dem *d)
{
    return a->product == GIS_OPENNESS && !a->radius_given
               ? GIS_OPENNESS_DEFAULT_CELLS * fmax(d->cx, d->cy)
               : a->radius;
}

/* The DEM's product: radius, nodata, and the metadata every file carries. */
static int describe(gis_run *r, hfs_error *err)
{
    const gis_args *a = r->a;
    const gis_dem *d = &r->dem;
    static const double hi[] = {1.0, 90.0, 180.0}; /* each product's largest value */
    r->c.dem = d;
    r->c.zscale = a->zscale;
    r->c.sweep = a->sweep;
    gis_run_meta(r, "HFS_PRODUCT=%s", product_name[a->product]);
    gis_run_meta(r, "HFS_BACKEND=%s", backend_name[a->backend]);
    gis_run_meta(r, "HFS_HORIZON_METHOD=%s", a->sweep ? "sweep" : "exact");
    gis_run_meta(r, "HFS_ZSCALE=%.9g", a->zscale);
    gis_run_meta(r, "HFS_CELL_M=%.9g", d->d);
    gis_run_meta(r, "HFS_SOFTWARE=hfshade %s", hfs_version());
    if (a->product == GIS_SUN || a->product == GIS_INSOLATION)
        return gis_sun_describe(r, err);
    r->c.radius = gis_command_radius(a, d);
    r->c.nodata = gis_nodata_for(d->has_nodata, d->nodata, 0.0, hi[a->product]);
    gis_run_meta(r, "HFS_RADIUS_M=%.9g", r->c.radius);
    if (a->product == GIS_HORIZON) {
        gis_run_meta(r, "HFS_AZIMUTH_CONVENTION=%s", gis_convention_name(a->convention));
        gis_run_meta(r, "HFS_HORIZON=degrees above the horizontal, 0 where nothing rises "
                     "above it");
        return HFS_OK;
    }
    gis_run_meta(r, "HFS_DIRECTIONS=%d", a->directions);
    gis_run_meta(r, "HFS_AZIMUTH_CONVENTION=ccw-east");
    gis_run_meta(r, "HFS_AZIMUTH_FIRST=0");
    gis_run_meta(r, "HFS_AZIMUTH_STEP=%.9g", 360.0 / a->directions);
    if (a->product == GIS_SVF)
        gis_run_meta(r, "HFS_SVF=%s", a->svf == GIS_SVF_LAMBERTIAN ? "lambertian" : "zaksek");
    return HFS_OK;
}

static int write_horizon(void *user, int k, const float *deg, hfs_error *err)
{
    return gis_horizon_files_add(user, k, deg, err);
}

static int compute_and_write(gis_run *r, hfs_error *err)
{
    const gis_args *a = r->a;
    const size_t n = (size_t)r->dem.width * (size_t)r->dem.height;
    if (r->mode == GIS_STREAMED)
        return gis_stream_write(r, err);
    if (a->product == GIS_SUN || a->product == GIS_INSOLATION)
        return gis_sun_write(r, err);
    if (a->product == GIS_HORIZON) {
        double *phi = malloc((size_t)a->n_azimuths * sizeof *phi);
        if (!phi)
            return hfs_fail(err, HFS_E_NOMEM, "horizon: out of memory");
        for (int k = 0; k < a->n_azimuths; ++k)
            phi[k] = gis_phi_of(a->azimuth[k], a->convention);
        gis_horizon_files *files = NULL;
        int rc = gis_horizon_files_create(&files, r, err);
        if (!rc)
            rc = gis_product_horizons(&r->c, phi, a->n_azimuths, write_horizon, files, err);
        gis_horizon_files_destroy(files);
        free(phi);
        return rc;
    }
    float *v = malloc(2 * n * sizeof *v);
    if (!v)
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", a->out);
    int rc = a->product == GIS_SVF ? gis_product_svf(&r->c, a->directions, a->svf, v, err)
                                   : gis_product_openness(&r->c, a->directions, v, v + n, err);
    const gis_raster g = gis_run_product_raster(r, v, n);
    if (!rc)
        rc = gis_raster_write(gis_outputs_set(r->outs, a->out), a->out, &g, err);
    free(v);
    return rc;
}

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The summary's words on windows: how many, or why the DEM over the tile
 * size was computed whole ("" when it fits a tile). */
static void windows_words(const gis_run *r, char *buf, size_t n)
{
    if (r->mode == GIS_STREAMED && r->a->job)
        snprintf(buf, n, ", window %d of --tile %d (halo %d)", r->a->job, r->a->tile, r->halo);
    else if (r->mode == GIS_STREAMED)
        snprintf(buf, n, ", %d windows of at most %d texels a side (halo %d)", r->windows,
                 r->a->tile, r->halo);
    else if (r->mode != GIS_WHOLE)
        snprintf(buf, n, ", whole (over --tile %d, but %s)", r->a->tile,
                 gis_stream_why(r->mode));
    else
        buf[0] = '\0';
}

/* The one line a successful run prints on stderr. */
static void summary(const gis_run *r, double seconds)
{
    const gis_dem *d = &r->dem;
    const gis_args *a = r->a;
    char grid[96] = "", what[320], windows[160];
    if (d->sw != d->width || d->sh != d->height)
        snprintf(grid, sizeof grid, " (computed on %dx%d square cells of %.4g m)", d->sw, d->sh,
                 d->d);
    if (a->product == GIS_SUN || a->product == GIS_INSOLATION)
        gis_sun_summary(r, what, sizeof what);
    else
        snprintf(what, sizeof what, "%d %s", a->product == GIS_HORIZON ? a->n_azimuths
                                                                        : a->directions,
                 a->product == GIS_HORIZON ? "azimuths" : "directions");
    windows_words(r, windows, sizeof windows);
    fprintf(stderr, "%s%s: %s of %dx%d%s%s, %s, %ld nodata texel%s, backend %s, %.3f s\n",
            a->product == GIS_HORIZON ? r->prefix : a->out,
            a->product == GIS_HORIZON ? "_*.tif" : "", product_name[a->product], d->width,
            d->height, grid, windows, what, d->holes, d->holes == 1 ? "" : "s",
            a->sweep ? "none (horizons by the sweep)"
            : r->c.r ? hfs_renderer_backend_name(r->c.r)
                     : backend_name[a->backend],
            seconds);
}

/* sun, insolation: 1 when the DEM may stream (gis_sun_choose's first
 * tests), so that its relief and centre are scanned window by window
 * rather than read whole. */
static int sun_may_stream(const gis_run *r)
{
    const gis_args *a = r->a;
    const gis_dem *d = &r->dem;
    return a->tile > 0 && (d->width > a->tile || d->height > a->tile) && d->square &&
           a->backend != HFS_BACKEND_TRUTH;
}

/* svf, horizon, openness: the mode, then the DEM read whole unless it
 * streams; the product described. */
static int open_horizons(gis_run *r, int load, hfs_error *err)
{
    const gis_args *a = r->a;
    r->mode = gis_stream_choose(&r->dem, a->tile, gis_command_radius(a, &r->dem), &r->halo);
    int rc = load && r->mode != GIS_STREAMED ? gis_dem_load(&r->dem, a->dem, err) : HFS_OK;
    return rc ? rc : describe(r, err);
}

/* sun, insolation: the site needs the DEM's centre and the mode the sun
 * and the relief, so a DEM that may stream is scanned first (its relief
 * and centre, window by window), described, and only then read whole if
 * it does not stream after all. */
static int open_sun(gis_run *r, int load, hfs_error *err)
{
    const gis_args *a = r->a;
    int rc;
    if (sun_may_stream(r) && a->relief_given) { /* tiles plan measured it */
        rc = gis_dem_scan_centre(&r->dem, a->dem, err);
        r->c.has_relief = 1;
        r->c.relief = a->zscale * a->relief;
    } else if (sun_may_stream(r)) {
        double lo, hi;
        rc = gis_dem_scan(&r->dem, a->dem, &lo, &hi, err);
        r->c.has_relief = 1;
        r->c.relief = a->zscale * (hi >= lo ? hi - lo : 0.0);
        r->relief = hi >= lo ? hi - lo : 0.0;
    } else {
        rc = load ? gis_dem_load(&r->dem, a->dem, err) : HFS_OK;
    }
    if (!rc)
        rc = describe(r, err);
    if (!rc)
        r->mode = gis_sun_choose(r);
    if (!rc && load && r->mode != GIS_STREAMED && !r->dem.sz)
        rc = gis_dem_load(&r->dem, a->dem, err);
    if (!rc && a->relief_given) /* the whole run's search as the jobs' */
        r->c.has_relief = 1, r->c.relief = a->zscale * a->relief;
    return rc;
}

int gis_run_open(gis_run *r, int load, hfs_error *err)
{
    const gis_args *a = r->a;
    int rc = gis_dem_open(a->dem, &a->load, &r->dem, err);
    if (!rc)
        rc = a->product == GIS_SUN || a->product == GIS_INSOLATION ? open_sun(r, load, err)
                                                                   : open_horizons(r, load, err);
    if (!rc && a->job && r->mode != GIS_STREAMED)
        rc = hfs_fail(err, HFS_E_INVALID, "%s: --job %d: the DEM is not computed window by "
                      "window (%s)", a->dem, a->job, r->mode == GIS_WHOLE
                      ? "it fits one --tile" : gis_stream_why(r->mode));
    return rc;
}

/* The products, their error naming the DEM unless it names a file already
 * (the DEM, or an output it could not write): the renderer's and the
 * sweep's messages speak of "horizons" and "the field". */
static int compute_named(gis_run *r, hfs_error *err)
{
    hfs_error why = {""};
    const int rc = compute_and_write(r, &why);
    if (!rc)
        return HFS_OK;
    const char *out = r->a->product == GIS_HORIZON ? r->prefix : r->a->out;
    const char *m = why.msg;
    if (!strncmp(m, r->a->dem, strlen(r->a->dem)) || (out && *out && !strncmp(m, out, strlen(out))))
        return hfs_fail(err, rc, "%s", m);
    return hfs_fail(err, rc, "%s: %s", r->a->dem, m);
}

int gis_command_run(const gis_args *a, hfs_error *err)
{
    gis_run r = {.a = a};
    const double t0 = now_seconds();
    int rc = plan_outputs(&r, err);
    if (!rc)
        rc = gis_run_open(&r, 1, err);
    if (!rc && !r.no_render && !a->sweep) { /* the sweep needs no renderer */
        const hfs_renderer_desc desc = {.backend = a->backend};
        rc = hfs_renderer_create(&desc, &r.c.r, err);
    }
    if (!rc)
        rc = compute_named(&r, err);
    if (!rc)
        rc = gis_outputs_commit(r.outs, err);
    if (!rc && !a->quiet)
        summary(&r, now_seconds() - t0);
    hfs_renderer_destroy(r.c.r);
    gis_sky_map_free(&r.sky);
    gis_dem_free(&r.dem);
    gis_outputs_destroy(r.outs);
    for (int k = 0; r.names && k < a->n_azimuths; ++k)
        free(r.names[k]);
    free(r.names);
    return rc;
}
