/*
 * gis_api.c — libhfshade_gis (hfshade_gis.h): the GIS products of a DEM in
 * memory, through the commands' own plumbing (gis_products.h, gis_sun.h)
 * on a gis_dem made as gis_dem_read makes one from a north-up,
 * square-celled file: the hole mask, the holes filled by push-pull, the
 * grid the renderer takes the input's own (sampled back 1:1).  The sun's
 * site, instants and period are checked and made as tools/cli_gis.c and
 * gis_sun_command.c make them from the command line and the DEM.
 */
#include "hfshade_gis.h"

#include "clear_sky.h"
#include "gis_command.h"
#include "gis_products.h"
#include "gis_sun.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Each product's largest value (gis_command.c describe; the sun's and
 * insolation's are any finite number, gis_sun_describe). */
static const double product_hi[] = {1.0, 90.0, 180.0, FLT_MAX, FLT_MAX};

float hfs_gis_nodata(const hfs_gis_dem *dem, hfs_gis_product product)
{
    const int p = product >= HFS_GIS_SVF && product <= HFS_GIS_INSOLATION ? (int)product : 0;
    const float v = dem ? gis_nodata_for(dem->has_nodata, dem->nodata, 0.0, product_hi[p])
                        : GIS_NODATA;
    return isfinite(v) ? v : GIS_NODATA; /* a NaN nodata is not written: outputs are finite */
}

static int check_dem(const hfs_gis_dem *dem, hfs_error *err)
{
    if (!dem || !dem->z)
        return hfs_fail(err, HFS_E_INVALID, "dem: no heights given");
    if (dem->width < 2 || dem->height < 2 || dem->width > HFS_HEIGHT_MAX_DIM ||
        dem->height > HFS_HEIGHT_MAX_DIM ||
        (long long)dem->width * dem->height > HFS_HEIGHT_MAX_TEXELS)
        return hfs_fail(err, HFS_E_INVALID, "dem: %dx%d heights (2..%dx%d allowed)", dem->width,
                        dem->height, HFS_HEIGHT_MAX_DIM, HFS_HEIGHT_MAX_DIM);
    if (!(dem->cell > 0.0 && dem->cell <= DBL_MAX))
        return hfs_fail(err, HFS_E_INVALID, "cell_size: %g metres is not a finite size above 0",
                        dem->cell);
    if (!(dem->zscale >= 1e-9 && dem->zscale <= 1e6))
        return hfs_fail(err, HFS_E_INVALID, "zscale: %g is not a number in [1e-9, 1e6]",
                        dem->zscale);
    return HFS_OK;
}

static int check_radius(double radius, hfs_error *err)
{
    if (radius == HFS_GIS_RADIUS_DEFAULT || (radius >= 0.0 && radius <= 1e9))
        return HFS_OK;
    return hfs_fail(err, HFS_E_INVALID, "radius: %g is not a distance in [0, 1e9] metres",
                    radius);
}

static int check_directions(int n, hfs_error *err)
{
    if (n >= 1 && n <= HFS_MAX_HORIZON_AZIMUTHS)
        return HFS_OK;
    return hfs_fail(err, HFS_E_INVALID, "directions: %d is not a whole number in [1, %d]", n,
                    HFS_MAX_HORIZON_AZIMUTHS);
}

/* The commands' gis_dem of dem (gis_dem.c georef + to_field on a square,
 * north-up grid): the holes marked and filled.  Freed by gis_dem_free's
 * GDAL-free part: free(hole), free(sz). */
static int make_dem(const hfs_gis_dem *dem, gis_dem *d, hfs_error *err)
{
    memset(d, 0, sizeof *d);
    const size_t n = (size_t)dem->width * (size_t)dem->height;
    d->width = d->sw = dem->width;
    d->height = d->sh = dem->height;
    d->cx = d->cy = d->d = dem->cell;
    d->square = 1;
    d->ex = d->ey = 1;
    d->has_nodata = dem->has_nodata;
    d->nodata = dem->nodata;
    d->hole = malloc(n);
    d->sz = malloc(n * sizeof *d->sz);
    if (!d->hole || !d->sz)
        return hfs_fail(err, HFS_E_NOMEM, "dem: out of memory for %dx%d heights", dem->width,
                        dem->height);
    const float nd = (float)dem->nodata;
    for (size_t p = 0; p < n; ++p) {
        float z = dem->z[p];
        if ((dem->has_nodata && z == nd) || (dem->hole && dem->hole[p]))
            z = NAN; /* a hole, as hfs_gdal_read_heights marks them */
        d->hole[p] = !isfinite(z);
        d->sz[p] = z;
    }
    hfs_error ferr;
    const int rc = hfs_height_fill_holes(d->sz, d->width, d->height, 0, 0.0f, &d->holes, &ferr);
    if (rc)
        return hfs_fail(err, rc, "dem: %s", ferr.msg);
    d->centre_z = d->sz[(size_t)(d->height / 2) * (size_t)d->width + (size_t)(d->width / 2)];
    return HFS_OK;
}

static void free_dem(gis_dem *d)
{
    free(d->hole);
    free(d->sz);
    memset(d, 0, sizeof *d);
}

/* Checks, the gis_dem and the compute of product p (radius resolved as
 * gis_command_radius: openness's default 10 cells); no renderer: the
 * sweep, whose radius must be 0. */
static int begin(hfs_renderer *r, const hfs_gis_dem *dem, hfs_gis_product p, double radius,
                 gis_dem *d, gis_compute *c, hfs_error *err)
{
    memset(d, 0, sizeof *d);
    if (!r && (radius > 0.0 || (p == HFS_GIS_OPENNESS && radius == HFS_GIS_RADIUS_DEFAULT)))
        return hfs_fail(err, HFS_E_INVALID, "radius: the sweep (no renderer) searches the "
                        "whole DEM: give 0%s", p == HFS_GIS_OPENNESS && radius < 0.0
                        ? " (openness searches 10 cells by default)" : "");
    int rc = check_dem(dem, err);
    if (!rc)
        rc = check_radius(radius, err);
    if (!rc)
        rc = make_dem(dem, d, err);
    if (rc)
        return rc;
    if (radius == HFS_GIS_RADIUS_DEFAULT)
        radius = p == HFS_GIS_OPENNESS ? GIS_OPENNESS_DEFAULT_CELLS * fmax(d->cx, d->cy) : 0.0;
    *c = (gis_compute){.r = r, .dem = d, .zscale = dem->zscale, .radius = radius,
                       .nodata = hfs_gis_nodata(dem, p), .sweep = r == NULL};
    return HFS_OK;
}

int hfs_gis_svf(hfs_renderer *r, const hfs_gis_dem *dem, int directions, int lambertian,
                double radius, float *out, hfs_error *err)
{
    gis_dem d;
    gis_compute c;
    int rc = check_directions(directions, err);
    if (!rc && !out)
        rc = hfs_fail(err, HFS_E_INVALID, "out: no output given");
    if (!rc)
        rc = begin(r, dem, HFS_GIS_SVF, radius, &d, &c, err);
    if (!rc)
        rc = gis_product_svf(&c, directions, lambertian ? GIS_SVF_LAMBERTIAN : GIS_SVF_ZAKSEK,
                             out, err);
    free_dem(&d);
    return rc;
}

/* The one azimuth's raster into out (the callback's user). */
typedef struct horizon_out {
    float *out;
    size_t n;
} horizon_out;

static int take_horizon(void *user, int k, const float *deg, hfs_error *err)
{
    horizon_out *h = user;
    (void)k, (void)err;
    memcpy(h->out, deg, h->n * sizeof *deg);
    return HFS_OK;
}

int hfs_gis_horizon(hfs_renderer *r, const hfs_gis_dem *dem, double azimuth, int compass,
                    double radius, float *out, hfs_error *err)
{
    gis_dem d;
    gis_compute c;
    int rc = azimuth >= -1e6 && azimuth <= 1e6
                 ? HFS_OK
                 : hfs_fail(err, HFS_E_INVALID, "azimuth: %g is not an angle in [-1e6, 1e6] "
                            "degrees", azimuth);
    if (!rc && !out)
        rc = hfs_fail(err, HFS_E_INVALID, "out: no output given");
    if (!rc)
        rc = begin(r, dem, HFS_GIS_HORIZON, radius, &d, &c, err);
    if (!rc) {
        const double phi = gis_phi_of(azimuth, compass ? GIS_COMPASS : GIS_CCW_EAST);
        horizon_out h = {.out = out, .n = (size_t)d.width * (size_t)d.height};
        rc = gis_product_horizons(&c, &phi, 1, take_horizon, &h, err);
    }
    free_dem(&d);
    return rc;
}

int hfs_gis_openness(hfs_renderer *r, const hfs_gis_dem *dem, int directions, double radius,
                     float *positive, float *negative, hfs_error *err)
{
    gis_dem d;
    gis_compute c;
    int rc = check_directions(directions, err);
    if (!rc && (!positive || !negative))
        rc = hfs_fail(err, HFS_E_INVALID, "out: no output given");
    if (!rc)
        rc = begin(r, dem, HFS_GIS_OPENNESS, radius, &d, &c, err);
    if (!rc)
        rc = gis_product_openness(&c, directions, positive, negative, err);
    free_dem(&d);
    return rc;
}

/* The UTC calendar fields of POSIX time unix_utc (finite, |t| < 1e11 s:
 * beyond the years the sun takes anyway), the days by Hinnant's
 * civil_from_days, as solar_position.c's to_utc turns a local date-time
 * into UTC; the seconds keep the instant's fraction. */
static hfs_solar_time utc_of(double unix_utc)
{
    const double whole = floor(unix_utc);
    const long long s = (long long)whole;
    const long long days = (s >= 0 ? s : s - 86399) / 86400; /* floor */
    const long long sod = s - days * 86400;
    const long long z = days + 719468, era = (z >= 0 ? z : z - 146096) / 146097;
    const long long doe = z - era * 146097;
    const long long yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    const long long doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    const long long mp = (5 * doy + 2) / 153;
    hfs_solar_time t;
    t.day = (int)(doy - (153 * mp + 2) / 5 + 1);
    t.month = (int)(mp < 10 ? mp + 3 : mp - 9);
    t.year = (int)(yoe + era * 400 + (t.month <= 2));
    t.hour = (int)(sod / 3600);
    t.minute = (int)(sod / 60 % 60);
    t.second = (double)(sod % 60) + (unix_utc - whole); /* whole seconds: exact */
    return t;
}

/* The Julian day of the instant unix_utc, the argument `name`. */
static int julian_day(const char *name, double unix_utc, double *jd, hfs_error *err)
{
    char why[96] = "";
    hfs_solar_time t;
    if (isfinite(unix_utc) && fabs(unix_utc) < 1e11) {
        t = utc_of(unix_utc);
        if (!hfs_solar_time_check(&t, why, sizeof why)) {
            *jd = hfs_solar_julian_day(&t); /* the command's, for the same fields */
            return HFS_OK;
        }
    }
    return hfs_fail(err, HFS_E_INVALID, "%s: %.17g s is not an instant in the years %d..%d "
                    "(seconds since 1970-01-01T00:00:00Z)%s%s", name, unix_utc,
                    HFS_SOLAR_YEAR_MIN, HFS_SOLAR_YEAR_MAX, *why ? ": " : "", why);
}

int hfs_gis_julian_day(double unix_utc, double *jd, hfs_error *err)
{
    if (!jd)
        return hfs_fail(err, HFS_E_INVALID, "jd: no output given");
    return julian_day("unix_utc", unix_utc, jd, err);
}

/* The site's fields that do not need the DEM, in the commands' ranges
 * (hfs_solar_site's; --linke's). */
static int check_site(const hfs_gis_site *s, hfs_error *err)
{
    if (!s)
        return hfs_fail(err, HFS_E_INVALID, "site: none given");
    if (!(s->lat >= -90.0 && s->lat <= 90.0))
        return hfs_fail(err, HFS_E_INVALID, "lat: %g is not a latitude in [-90, 90] degrees",
                        s->lat);
    if (!(s->lon >= -360.0 && s->lon <= 360.0))
        return hfs_fail(err, HFS_E_INVALID, "lon: %g is not a longitude in [-360, 360] degrees",
                        s->lon);
    if (!(s->convergence_deg >= -180.0 && s->convergence_deg <= 180.0))
        return hfs_fail(err, HFS_E_INVALID, "convergence: %g is not an angle in [-180, 180] "
                        "degrees", s->convergence_deg);
    if (s->linke != 0.0 && !(s->linke >= HFS_LINKE_MIN && s->linke <= HFS_LINKE_MAX))
        return hfs_fail(err, HFS_E_INVALID, "linke: %g is not a Linke turbidity in [%g, %g]",
                        s->linke, HFS_LINKE_MIN, HFS_LINKE_MAX);
    if (!isnan(s->elevation_m) && !(s->elevation_m >= -1000.0 && s->elevation_m <= 9000.0))
        return hfs_fail(err, HFS_E_INVALID, "elevation: %g m is not in [-1000, 9000] metres",
                        s->elevation_m);
    return HFS_OK;
}

/* The solar site of s over d, its height the centre texel's where s has
 * none (gis_sun_command.c site_of). */
static int site_of(const hfs_gis_site *s, const gis_dem *d, double zscale,
                   hfs_solar_site *out, hfs_error *err)
{
    const double z = isnan(s->elevation_m) ? d->centre_z * zscale : s->elevation_m;
    if (!(z >= -1000.0 && z <= 9000.0))
        return hfs_fail(err, HFS_E_INVALID, "dem: the height at its centre, %.6g m, is outside "
                        "-1000..9000 m (the site of the sun and the clear sky; heights not "
                        "in metres? zscale; or give the elevation)", z);
    *out = (hfs_solar_site){.lat_deg = s->lat, .lon_deg = s->lon, .elevation_m = z};
    return HFS_OK;
}

/* The checks and the compute shared by sun and insolation: radius 0 (or
 * the default) is as far as shadows reach; a radius on the truth is
 * refused, as the command refuses it (it renders the whole DEM's exact
 * shadows and would ignore it). */
static int begin_sun(hfs_renderer *r, const hfs_gis_dem *dem, const hfs_gis_site *site,
                     hfs_gis_product p, double radius, gis_dem *d, gis_compute *c,
                     hfs_solar_site *ss, hfs_error *err)
{
    memset(d, 0, sizeof *d);
    int rc = check_site(site, err);
    if (!rc && r && radius > 0.0 && !strcmp(hfs_renderer_backend_name(r), "truth"))
        rc = hfs_fail(err, HFS_E_INVALID, "radius: not with the truth backend (it renders the "
                      "sun's exact shadows from the whole DEM)");
    if (!rc)
        rc = begin(r, dem, p, radius, d, c, err);
    if (!rc)
        rc = site_of(site, d, dem->zscale, ss, err);
    if (!rc)
        c->convergence_deg = site->convergence_deg;
    return rc;
}

static double linke_of(const hfs_gis_site *s)
{
    return s->linke == 0.0 ? HFS_LINKE_DEFAULT : s->linke;
}

int hfs_gis_sun(hfs_renderer *r, const hfs_gis_dem *dem, const hfs_gis_site *site,
                double unix_utc, double radius, float *beam, float *visible, hfs_error *err)
{
    gis_dem d = {0};
    gis_compute c;
    hfs_solar_site ss;
    gis_sun_at sun;
    double jd = 0.0;
    int rc = beam && visible ? HFS_OK : hfs_fail(err, HFS_E_INVALID, "out: no output given");
    if (!rc)
        rc = julian_day("when", unix_utc, &jd, err);
    if (!rc)
        rc = begin_sun(r, dem, site, HFS_GIS_SUN, radius, &d, &c, &ss, err);
    if (!rc && gis_sun_compute(jd, &ss, linke_of(site), &sun))
        rc = hfs_fail(err, HFS_E_INVALID, "when: no sun for this site and instant");
    if (!rc)
        rc = gis_product_sun(&c, &sun, beam, visible, err);
    free_dem(&d);
    return rc;
}

/* The period [from, to) in steps of step_min minutes, as tools/cli_gis.c
 * check_sun makes it (gis_period_length), at most GIS_MAX_STEPS steps. */
static int period_of(double from, double to, double step_min, gis_period *p, hfs_error *err)
{
    if (!(step_min > 0.0 && step_min <= 1e9))
        return hfs_fail(err, HFS_E_INVALID, "step: %g is not a number of minutes in (0, 1e9]",
                        step_min);
    int rc = julian_day("start", from, &p->jd_from, err);
    if (!rc)
        rc = julian_day("end", to, &p->jd_to, err);
    if (rc)
        return rc;
    double minutes, steps;
    gis_period_length(p->jd_from, p->jd_to, step_min, &minutes, &steps);
    if (!(minutes > 0.0))
        return hfs_fail(err, HFS_E_INVALID, "end: %.17g s is not after start %.17g s", to,
                        from);
    if (steps > GIS_MAX_STEPS)
        return hfs_fail(err, HFS_E_INVALID, "step: %g minutes over %g minutes makes %.0f steps "
                        "(at most %ld)", step_min, minutes, steps, GIS_MAX_STEPS);
    p->step_min = step_min;
    p->n_steps = (long)steps;
    return HFS_OK;
}

int hfs_gis_insolation(hfs_renderer *r, const hfs_gis_dem *dem, const hfs_gis_site *site,
                       double from_unix_utc, double to_unix_utc, double step_min,
                       int directions, double radius, float *beam, float *diffuse,
                       float *global, hfs_error *err)
{
    return hfs_gis_insolation_sky(r, dem, site, from_unix_utc, to_unix_utc, step_min, directions,
                                  radius, NULL, 0, 0, 0.0, 0.0, beam, diffuse, global, err);
}

/* The sky map of hfs_gis_insolation_sky over the directions' azimuths,
 * its north at true compass `north` on a grid whose own north lies
 * `convergence` east of true north. */
static int sky_of(const float *rgb, int w, int h, double north, double convergence,
                  int directions, gis_sky_map *out, hfs_error *err)
{
    if (!(w >= 1 && h >= 1 && (size_t)w * (size_t)h <= ((size_t)1 << 28)))
        return hfs_fail(err, HFS_E_INVALID, "sky: %d x %d is not a map size (1 .. 2^28 "
                        "pixels)", w, h);
    if (!(north >= -360.0 && north <= 360.0))
        return hfs_fail(err, HFS_E_INVALID, "sky_north: %g is not an angle in [-360, 360] "
                        "degrees", north);
    return gis_sky_map_make(rgb, w, h, north - convergence, directions, "sky", out, err);
}

int hfs_gis_insolation_sky(hfs_renderer *r, const hfs_gis_dem *dem, const hfs_gis_site *site,
                           double from_unix_utc, double to_unix_utc, double step_min,
                           int directions, double radius, const float *sky_rgb, int sky_w,
                           int sky_h, double sky_north, double albedo, float *beam,
                           float *diffuse, float *global, hfs_error *err)
{
    gis_dem d = {0};
    gis_compute c;
    gis_period p = {0};
    gis_period_stats st;
    gis_sky_map sky = {0};
    const int beam_only = beam && !diffuse && !global; /* the sky not searched */
    int rc = beam && (beam_only || (diffuse && global))
                 ? HFS_OK
                 : hfs_fail(err, HFS_E_INVALID, "out: %s", beam ? "diffuse and global: give both "
                            "or neither (the beam alone)" : "no output given");
    if (!rc && beam_only && (sky_rgb || albedo != 0.0))
        rc = hfs_fail(err, HFS_E_INVALID, "out: the beam alone takes no sky map and no albedo");
    if (!rc)
        rc = period_of(from_unix_utc, to_unix_utc, step_min, &p, err);
    if (!rc)
        rc = check_directions(directions, err);
    if (!rc && !(albedo >= 0.0 && albedo <= 1.0))
        rc = hfs_fail(err, HFS_E_INVALID, "albedo: %g is not an albedo in [0, 1]", albedo);
    if (!rc)
        rc = begin_sun(r, dem, site, HFS_GIS_INSOLATION, radius, &d, &c, &p.site, err);
    if (!rc && sky_rgb &&
        !(rc = sky_of(sky_rgb, sky_w, sky_h, sky_north, c.convergence_deg, directions, &sky, err)))
        p.sky = &sky;
    if (!rc) {
        p.linke = linke_of(site);
        p.sky_directions = directions;
        p.albedo = albedo;
        p.beam_only = beam_only;
        rc = gis_product_insolation(&c, &p, beam, diffuse, global, &st, err);
    }
    gis_sky_map_free(&sky);
    free_dem(&d);
    return rc;
}
