/*
 * gis_sun_command.c — `hfshade sun` and `hfshade insolation` in a GIS
 * command's run (gis_run.h; gis_command.c makes the run, commits the files
 * and prints the summary): the site from the DEM's georeference, the sun
 * or the period, the rasters and their metadata (docs/GIS.md).
 */
#include "gis_run.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hfs_io.h"

#define RAD (3.14159265358979323846 / 180.0)

/* t as ISO 8601 UTC: 2026-06-21T07:30:00Z (seconds with decimals only when
 * it has them). */
static void utc_string(const hfs_solar_time *t, char *buf, size_t n)
{
    const int whole = t->second == floor(t->second);
    snprintf(buf, n, "%04d-%02d-%02dT%02d:%02d:%0*.*fZ", t->year, t->month, t->day, t->hour,
             t->minute, whole ? 2 : 6, whole ? 0 : 3, t->second);
}

/* The site: the DEM's centre, its height in metres in the range the sun's
 * and the clear sky's formulas take. */
static int site_of(gis_run *r, hfs_error *err)
{
    const gis_args *a = r->a;
    double lon = 0.0, lat = 0.0, convergence = 0.0;
    const int rc = gis_dem_lonlat(&r->dem, a->dem, &lon, &lat, &convergence, err);
    if (rc)
        return rc;
    const double z = r->dem.centre_z * a->zscale;
    if (!(z >= -1000.0 && z <= 9000.0))
        return hfs_fail(err, HFS_E_INVALID, "%s: the height at its centre, %.6g m, is outside "
                        "-1000..9000 m (the site of the sun and the clear sky; heights not "
                        "in metres? --zscale)", a->dem, z);
    r->site = (hfs_solar_site){.lat_deg = lat, .lon_deg = lon, .elevation_m = z};
    r->c.convergence_deg = convergence;
    gis_run_meta(r, "HFS_SITE_LON=%.6f", lon);
    gis_run_meta(r, "HFS_SITE_LAT=%.6f", lat);
    gis_run_meta(r, "HFS_GRID_CONVERGENCE_DEG=%.6f", convergence);
    gis_run_meta(r, "HFS_SITE_ELEVATION_M=%.6g", z);
    gis_run_meta(r, "HFS_LINKE=%.6g", a->linke);
    gis_run_meta(r, "HFS_RADIUS_M=%.9g", a->radius);
    gis_run_meta(r, "HFS_SOLAR_POSITION=NOAA solar calculator (Meeus 1998), apparent "
                 "elevation with refraction");
    gis_run_meta(r, "HFS_CLEAR_SKY=ESRA (Rigollier et al. 2000), as GRASS r.sun");
    return HFS_OK;
}

static int describe_sun(gis_run *r, hfs_error *err)
{
    const gis_args *a = r->a;
    if (gis_sun_compute(a->jd, &r->site, a->linke, &r->sun))
        return hfs_fail(err, HFS_E_INVALID, "%s: no sun for this site and instant", a->dem);
    r->no_render = !gis_sun_up(&r->sun);
    char utc[40];
    utc_string(&a->at, utc, sizeof utc);
    gis_run_meta(r, "HFS_UTC=%s", utc);
    gis_run_meta(r, "HFS_AZIMUTH_CONVENTION=compass");
    gis_run_meta(r, "HFS_SUN_AZIMUTH=%.4f", r->sun.pos.azimuth_deg);
    gis_run_meta(r, "HFS_SUN_ELEVATION=%.4f", r->sun.pos.elevation_deg);
    gis_run_meta(r, "HFS_SUN_RADIUS=%.5f", r->sun.alpha_deg);
    gis_run_meta(r, "HFS_BEAM_NORMAL_WM2=%.3f", r->sun.beam_normal);
    gis_run_meta(r, "HFS_DIFFUSE_HORIZONTAL_WM2=%.3f", r->sun.diffuse_horizontal);
    return HFS_OK;
}

/* --sky-map: the map's sky over the period's azimuths (gis_sky_map.h). */
static int load_sky(gis_run *r, hfs_error *err)
{
    const gis_args *a = r->a;
    hfs_envmap m = {0};
    int rc = hfs_envmap_load(a->sky_map, &m, err);
    if (rc)
        return rc;
    /* the map's azimuths are true compass ones, the sectors the grid's */
    rc = gis_sky_map_make(m.rgb, m.width, m.height, a->sky_north - r->c.convergence_deg,
                          a->directions, a->sky_map, &r->sky, err);
    hfs_envmap_free(&m);
    if (rc)
        return rc;
    r->period.sky = &r->sky;
    const char *base = strrchr(a->sky_map, '/');
    gis_run_meta(r, "HFS_SKY_MAP=%.100s", base ? base + 1 : a->sky_map);
    gis_run_meta(r, "HFS_SKY_NORTH=%.6g", a->sky_north);
    gis_run_meta(r, "HFS_DIFFUSE_MODEL=sky map (upper half, luminance, scaled to the clear "
                 "sky) over the terrain's horizons");
    return HFS_OK;
}

static int describe_period(gis_run *r, hfs_error *err)
{
    const gis_args *a = r->a;
    r->period = (gis_period){.jd_from = a->jd_from, .jd_to = a->jd_to, .step_min = a->step_min,
                             .n_steps = a->n_steps, .site = r->site, .linke = a->linke,
                             .sky_directions = a->directions, .albedo = a->albedo,
                             .beam_only = a->beam_only};
    if (a->sky_map) {
        const int rc = load_sky(r, err);
        if (rc)
            return rc;
    }
    if (gis_period_scan(&r->period, &r->stats))
        return hfs_fail(err, HFS_E_INVALID, "%s: no sun for this site and period", a->dem);
    r->no_render = r->stats.steps_sun == 0;
    char from[40], to[40];
    utc_string(&a->from, from, sizeof from);
    utc_string(&a->to, to, sizeof to);
    gis_run_meta(r, "HFS_FROM=%s", from);
    gis_run_meta(r, "HFS_TO=%s", to);
    gis_run_meta(r, "HFS_STEP_MIN=%.9g", a->step_min);
    gis_run_meta(r, "HFS_STEPS=%ld", a->n_steps);
    gis_run_meta(r, "HFS_STEPS_SUN=%ld", r->stats.steps_sun);
    gis_run_meta(r, "HFS_BEAM_NORMAL_WH=%.3f", r->stats.beam_normal_wh);
    gis_run_meta(r, "HFS_DIFFUSE_HORIZONTAL_WH=%.3f", r->stats.diffuse_wh);
    if (a->beam_only) {
        gis_run_meta(r, "HFS_BANDS=beam");
        return HFS_OK;
    }
    if (!a->sky_map)
        gis_run_meta(r, "HFS_DIFFUSE_MODEL=isotropic sky (upper hemisphere) over the "
                     "terrain's horizons");
    gis_run_meta(r, "HFS_DIRECTIONS=%d", a->directions);
    if (a->albedo > 0.0) {
        gis_run_meta(r, "HFS_ALBEDO=%.6g", a->albedo);
        gis_run_meta(r, "HFS_GLOBAL_HORIZONTAL_WH=%.3f", r->stats.global_wh);
        gis_run_meta(r, "HFS_REFLECTED_MODEL=albedo x global horizontal x (1 - isotropic sky "
                     "share): the view's ground and terrain, lit as open ground");
    }
    return HFS_OK;
}

int gis_sun_describe(gis_run *r, hfs_error *err)
{
    /* Every value >= 0 and finite: the input's nodata when negative. */
    r->c.nodata = gis_nodata_for(r->dem.has_nodata, r->dem.nodata, 0.0, FLT_MAX);
    r->c.radius = r->a->radius;
    const int rc = site_of(r, err);
    if (rc)
        return rc;
    return r->a->product == GIS_SUN ? describe_sun(r, err) : describe_period(r, err);
}

gis_stream_mode gis_sun_choose(gis_run *r)
{
    const gis_args *a = r->a;
    const gis_dem *d = &r->dem;
    if (a->tile <= 0 || (d->width <= a->tile && d->height <= a->tile))
        return GIS_WHOLE;
    if (a->backend == HFS_BACKEND_TRUTH)
        return GIS_WHOLE_TRUTH;
    if (r->no_render) /* no sun up (sun), or none in the period (insolation) */
        return GIS_WHOLE_NIGHT;
    double radius = a->radius; /* insolation: its sky's, and no farther for the suns */
    if (a->product == GIS_SUN) {
        const double low = (r->sun.pos.elevation_deg - r->sun.alpha_deg) * RAD;
        const double reach = fmin(gis_shadow_reach(r->c.relief, low),
                                  a->radius > 0.0 ? a->radius : HUGE_VAL);
        radius = fmax(reach, 2.0 * d->d); /* as the search's own (gis_sun.c) */
    }
    return gis_stream_choose(d, a->tile, radius, &r->halo);
}

int gis_sun_write(gis_run *r, hfs_error *err)
{
    const gis_args *a = r->a;
    const int sun = a->product == GIS_SUN, bands = gis_run_bands(r);
    const size_t n = (size_t)r->dem.width * (size_t)r->dem.height;
    float *v = malloc((size_t)bands * n * sizeof *v);
    if (!v)
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", a->out);
    int rc = sun ? gis_product_sun(&r->c, &r->sun, v, v + n, err)
                 : gis_product_insolation(&r->c, &r->period, v, bands > 1 ? v + n : NULL,
                                          bands > 1 ? v + 2 * n : NULL, &r->stats, err);
    if (!rc) {
        const gis_raster g = gis_run_product_raster(r, v, n);
        rc = gis_raster_write(gis_outputs_set(r->outs, a->out), a->out, &g, err);
    }
    free(v);
    return rc;
}

void gis_sun_summary(const gis_run *r, char *buf, size_t n)
{
    const gis_sun_at *s = &r->sun;
    if (r->a->product == GIS_INSOLATION)
        snprintf(buf, n, "%ld step%s of %g min, %ld with the sun up (clear sky: beam normal "
                 "%.0f, diffuse horizontal %.0f Wh/m^2)", r->a->n_steps,
                 r->a->n_steps == 1 ? "" : "s", r->a->step_min, r->stats.steps_sun,
                 r->stats.beam_normal_wh, r->stats.diffuse_wh);
    else if (gis_sun_up(s))
        snprintf(buf, n, "sun at azimuth %.2f, elevation %.2f deg (beam normal %.1f W/m^2)",
                 s->pos.azimuth_deg, s->pos.elevation_deg, s->beam_normal);
    else
        snprintf(buf, n, "sun below the horizon (elevation %.2f deg): zeros",
                 s->pos.elevation_deg);
}
