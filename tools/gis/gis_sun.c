/*
 * gis_sun.c — see gis_sun.h.  Sums are kept in double on the square grid
 * (a year of 15-minute steps adds 17 000 terms a texel) and brought back
 * to the input's grid once.
 */
#include "gis_sun.h"

#include "clear_sky.h"
#include "field_geom.h"
#include "gis_horizons.h"
#include "gis_resample.h"
#include "lights.h"
#include "parallel.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define RAD (PI / 180.0)

/* Texels below which a step's per-texel work stays on the calling thread. */
#define SUN_TEXELS_THREADED GIS_SUMS_THREADED

int gis_sun_compute(double jd, const hfs_solar_site *site, double linke, gis_sun_at *out)
{
    if (hfs_solar_position_jd(jd, site, &out->pos))
        return -1;
    out->jd = jd;
    out->alpha_deg = GIS_SUN_RADIUS_ARCSEC / 3600.0 / out->pos.distance_au;
    return hfs_clear_sky_g0(out->pos.elevation_true_deg, site->elevation_m, linke,
                            HFS_SOLAR_CONSTANT_WM2 * out->pos.distance_factor,
                            &out->beam_normal, &out->diffuse_horizontal);
}

int gis_sun_up(const gis_sun_at *s)
{
    return s->pos.elevation_deg > 0.0;
}

void gis_sun_key(const gis_sun_at *s, int ex, int ey, double convergence_deg, hfs_key_light *k)
{
    const double alpha = s->alpha_deg * RAD, s2 = sin(alpha) * sin(alpha);
    const double grid_azimuth = s->pos.azimuth_deg - convergence_deg;
    *k = (hfs_key_light){
        .phi = gis_grid_phi(gis_phi_of(grid_azimuth, GIS_COMPASS), ex, ey),
        .elev = s->pos.elevation_deg * RAD,
        .alpha = alpha,
        .radiance = {(float)(1.0 / s2), (float)(1.0 / s2), (float)(1.0 / s2)}};
}

/* f = Lo / (Le sin^2 alpha) of key light k's render (channel 0). */
static double factor_of(const hfs_key_light *k, float lo)
{
    const double s = sin(k->alpha);
    return (double)lo / ((double)k->radiance[0] * s * s);
}

/* The renders' settings: the defaults but the visibility at every texel
 * (subsample 1): a raster is made once, at the DEM's own resolution. */
static void quality(hfs_quality *q)
{
    hfs_quality_defaults(q);
    q->subsample = 1;
}

static hfs_field field_of(const gis_compute *c)
{
    const gis_dem *d = c->dem;
    return (hfs_field){.width = d->sw, .height = d->sh, .z = d->sz, .dx = d->d,
                       .zscale = c->zscale};
}

/* sq (the square grid) onto the input's grid. */
static void back(const gis_compute *c, const float *sq, float *out)
{
    const gis_dem *d = c->dem;
    gis_sample_back(sq, d->sw, d->sh, d->cx / d->d, d->cy / d->d, d->width, d->height, d->hole,
                    c->nodata, out);
}

/* The sun s alone, as a key light, and the renders' settings. */
static void sun_scene(const gis_compute *c, const gis_sun_at *s, hfs_lighting *l, hfs_quality *q)
{
    hfs_lighting_defaults(l);
    l->n_key = 1;
    gis_sun_key(s, c->dem->ex, c->dem->ey, c->convergence_deg, &l->key[0]);
    quality(q);
}

/* f on the square grid (sq) and, with vis not NULL, V, from a render
 * with the sun as a key light: the truth's exact disk behind the exact
 * surface, the oracle of the horizon path below. */
static int sun_factor_render(const gis_compute *c, const gis_sun_at *s, float *f, float *vis,
                             hfs_error *err)
{
    const hfs_field field = field_of(c);
    hfs_lighting l;
    hfs_quality q;
    sun_scene(c, s, &l, &q);
    hfs_image lit = {0}, open = {0};
    int rc = hfs_image_alloc(&lit, field.width, field.height, err);
    if (!rc && vis)
        rc = hfs_image_alloc(&open, field.width, field.height, err);
    if (!rc)
        rc = hfs_renderer_render(c->r, &field, &l, &q, &lit, NULL, NULL, err);
    if (!rc && vis)
        rc = hfs_render_unshadowed(&field, &l, &q, &open, err);
    const size_t n = (size_t)field.width * (size_t)field.height;
    for (size_t p = 0; p < n && !rc; ++p) {
        const double fp = fmax(factor_of(&l.key[0], lit.rgb[3 * p]), 0.0);
        f[p] = (float)fp;
        if (vis) {
            const double fu = factor_of(&l.key[0], open.rgb[3 * p]);
            vis[p] = fu > GIS_SUN_SELF_SHADOW ? (float)fmin(fp / fu, 1.0) : 0.0f;
        }
    }
    hfs_image_free(&lit);
    hfs_image_free(&open);
    return rc;
}

/* zscale times the highest minus the lowest height: the whole DEM's when
 * c is a window of it, else the square grid's (its holes left out where
 * it is the input's own grid, as a window's scan leaves them out). */
static double relief_of(const gis_compute *c)
{
    if (c->has_relief)
        return c->relief;
    const gis_dem *d = c->dem;
    const size_t n = (size_t)d->sw * (size_t)d->sh;
    const int own = d->sw == d->width && d->sh == d->height && d->hole;
    float lo = INFINITY, hi = -INFINITY;
    for (size_t p = 0; p < n; ++p) {
        if (own && d->hole[p])
            continue;
        lo = fminf(lo, d->sz[p]);
        hi = fmaxf(hi, d->sz[p]);
    }
    return hi >= lo ? c->zscale * ((double)hi - (double)lo) : 0.0;
}

/* What every step of a product shares: the square grid's normals and
 * relief. */
typedef struct sun_ground {
    double *normal; /* 3 a texel */
    double relief;
} sun_ground;

static int ground_make(const gis_compute *c, sun_ground *g, hfs_error *err)
{
    const hfs_field field = field_of(c);
    const size_t n = (size_t)field.width * (size_t)field.height;
    g->relief = relief_of(c);
    g->normal = malloc(3 * n * sizeof *g->normal);
    if (!g->normal)
        return hfs_fail(err, HFS_E_NOMEM, "sun: out of memory");
    for (size_t p = 0; p < n; ++p)
        hfs_field_normal(&field, (int)(p % (size_t)field.width), (int)(p / (size_t)field.width),
                         g->normal + 3 * p);
    return HFS_OK;
}

/* One step's texels: f and V from the horizon at the sun's azimuth. */
typedef struct sun_texels {
    const double *normal;
    const float *gamma;
    hfs_key_light key;
    double dir[3]; /* towards the disk's centre */
    float *f, *vis;
} sun_texels;

/* The unshadowed f is the exact cap's irradiance over the disk's own
 * (hfs_render_unshadowed's, albedo 1: E / (pi sin^2 alpha)), times the
 * disk's fraction above the horizon. */
static void sun_texel_range(void *ctx, size_t begin, size_t end, int chunk)
{
    const sun_texels *t = ctx;
    const hfs_key_light *k = &t->key;
    const double s = sin(k->alpha), disk = PI * s * s, s2 = s * s;
    /* a disk wholly above the texel's plane (n.d >= sin alpha, with room
     * for acos' rounding) is hfs_cap_irradiance's first case, the same
     * product without its arccosine (a disk of up to a hemisphere) */
    const double above = k->alpha > 0.0 && k->alpha <= 0.5 * PI ? s + 1e-12 : HUGE_VAL;
    (void)chunk;
    for (size_t p = begin; p < end; ++p) {
        const double *n = t->normal + 3 * p;
        const double nd = n[0] * t->dir[0] + n[1] * t->dir[1] + n[2] * t->dir[2];
        const double e = nd >= above && nd <= 1.0 ? PI * s2 * nd : hfs_cap_irradiance(nd, k->alpha);
        const double fu = e / disk;
        const double v = gis_disk_visible(n, k->phi, k->elev, k->alpha, t->gamma[p]);
        t->f[p] = (float)(fmax(fu, 0.0) * v);
        if (t->vis)
            t->vis[p] = fu > GIS_SUN_SELF_SHADOW ? (float)v : 0.0f;
    }
}

/* The same f and V through one horizon: the unshadowed f (the exact cap)
 * times the disk's fraction above the horizon at the sun's azimuth
 * (gis_disk_visible), the horizon searched only as far as terrain can
 * shadow the disk's lowest point (gis_shadow_reach) and only for angles
 * across the disk (the desc's window): a high sun's search ends within a
 * few reads, where a frame's key-light passes search the whole field at
 * every step.  The texels on all cores (parallel.h: the same bits for any
 * count). */
static int sun_factor_horizon(const gis_compute *c, const gis_sun_at *s, const sun_ground *g,
                              float *f, float *vis, hfs_error *err)
{
    const hfs_field field = field_of(c);
    hfs_lighting l;
    hfs_quality q;
    sun_scene(c, s, &l, &q);
    const double low = l.key[0].elev - l.key[0].alpha, high = l.key[0].elev + l.key[0].alpha;
    const double reach = fmin(gis_shadow_reach(g->relief, low), c->radius > 0.0 ? c->radius
                                                                                 : HUGE_VAL);
    const hfs_horizon_desc desc = {.n_azimuths = 1, .azimuth = &l.key[0].phi,
                                   /* the sweep reads the whole field: the window's
                                    * clamp makes what lies beyond the reach moot */
                                   .radius = isfinite(reach) && !c->sweep
                                                 ? fmax(reach, 2.0 * field.dx) : 0.0,
                                   .window = 1, .lo = fmax(low, -PI / 2), .hi = fmin(high, PI / 2)};
    const size_t n = (size_t)field.width * (size_t)field.height;
    float *gamma = malloc(n * sizeof *gamma);
    int rc = gamma ? HFS_OK : hfs_fail(err, HFS_E_NOMEM, "sun: out of memory");
    if (!rc)
        rc = gis_horizons_get(c->r, c->sweep, &field, &q, &desc, gamma, err);
    if (!rc) {
        sun_texels t = {.normal = g->normal, .gamma = gamma, .key = l.key[0], .f = f, .vis = vis};
        hfs_dir(t.key.phi, t.key.elev, t.dir);
        hfs_parallel_ranges(n, SUN_TEXELS_THREADED, sun_texel_range, &t);
    }
    free(gamma);
    return rc;
}

/* f and V by the backend's path: the truth renders its exact disk, the
 * others search the horizon. */
static int sun_factor(const gis_compute *c, const gis_sun_at *s, const sun_ground *g, float *f,
                      float *vis, hfs_error *err)
{
    if (!c->sweep && !strcmp(hfs_renderer_backend_name(c->r), "truth"))
        return sun_factor_render(c, s, f, vis, err);
    return sun_factor_horizon(c, s, g, f, vis, err);
}

int gis_product_sun(const gis_compute *c, const gis_sun_at *s, float *beam, float *vis,
                    hfs_error *err)
{
    const gis_dem *d = c->dem;
    const size_t n = (size_t)d->sw * (size_t)d->sh;
    float *f = calloc(n, sizeof *f), *v = calloc(n, sizeof *v);
    sun_ground g = {0};
    int rc = f && v ? HFS_OK : hfs_fail(err, HFS_E_NOMEM, "sun: out of memory");
    if (!rc && gis_sun_up(s) && !(rc = ground_make(c, &g, err)))
        rc = sun_factor(c, s, &g, f, v, err);
    free(g.normal);
    if (!rc) {
        for (size_t p = 0; p < n; ++p)
            f[p] = (float)(s->beam_normal * f[p]);
        back(c, f, beam);
        back(c, v, vis);
    }
    free(f);
    free(v);
    return rc;
}

void gis_period_length(double jd_from, double jd_to, double step_min, double *minutes,
                       double *steps)
{
    *minutes = round((jd_to - jd_from) * 1440.0 * 1e6) / 1e6;
    *steps = ceil(*minutes / step_min - 1e-9);
}

void gis_period_step(const gis_period *p, long k, double *jd_mid, double *hours)
{
    const double step = p->step_min / 1440.0, t0 = p->jd_from + (double)k * step;
    const double len = fmin(step, p->jd_to - t0);
    *jd_mid = t0 + 0.5 * len;
    *hours = 24.0 * len;
}

int gis_period_scan(const gis_period *p, gis_period_stats *st)
{
    *st = (gis_period_stats){0};
    for (long k = 0; k < p->n_steps; ++k) {
        double jd, hours;
        gis_sun_at s;
        gis_period_step(p, k, &jd, &hours);
        if (gis_sun_compute(jd, &p->site, p->linke, &s))
            return -1;
        st->steps_sun += s.pos.elevation_true_deg > 0.0;
        st->beam_normal_wh += s.beam_normal * hours;
        st->diffuse_wh += s.diffuse_horizontal * hours;
        st->global_wh += (s.beam_normal * fmax(sin(s.pos.elevation_true_deg * RAD), 0.0) +
                          s.diffuse_horizontal) * hours;
    }
    return 0;
}

/* What the sky's horizons are summed into. */
typedef struct sky_sums {
    double *acc;           /* the sky's share: the map's, or isotropic     */
    double *iso;           /* with a map, the isotropic share (the ground's
                              part); NULL: not wanted                      */
    const float *normal;   /* 3 a texel                                   */
    const double *phi;     /* the grid's azimuths                         */
    const gis_sky_map *map; /* NULL: the isotropic sky                    */
    size_t n;
    int k;                 /* the azimuth at hand, and its angles         */
    const float *gamma;
} sky_sums;

/* Texels b..e of azimuth k's sums (each texel its own: any split of the
 * texels among the cores gives the same values, parallel.h). */
static void sky_range(void *ctx, size_t b, size_t e, int chunk)
{
    const sky_sums *s = ctx;
    const float *gamma = s->gamma + b, *normal = s->normal + 3 * b;
    (void)chunk;
    if (s->map)
        gis_sky_map_add(s->map, s->k, s->phi[s->k], s->acc + b, gamma, normal, e - b);
    else
        gis_sky_add(s->acc + b, gamma, normal, e - b, s->phi[s->k]);
    if (s->iso)
        gis_sky_add(s->iso + b, gamma, normal, e - b, s->phi[s->k]);
}

static int add_sky(void *user, int k, const float *gamma, hfs_error *err)
{
    sky_sums *s = user;
    (void)err;
    s->k = k, s->gamma = gamma;
    hfs_parallel_ranges(s->n, GIS_SUMS_THREADED, sky_range, s);
    return HFS_OK;
}

/* The sky's share on the tilted surface under the horizons of n_dirs
 * azimuths, on the square grid: the isotropic sky's (gis_sky_add) or, with
 * map, the map's (gis_sky_map_add); ground (when not NULL): 1 - the
 * isotropic share, the terrain's and the ground's part of the view. */
static int sky_share(const gis_compute *c, int n_dirs, const gis_sky_map *map, float *sky,
                     float *ground, hfs_error *err)
{
    const hfs_field field = field_of(c);
    const size_t n = (size_t)field.width * (size_t)field.height;
    sky_sums s = {.acc = calloc(n, sizeof(double)), .n = n};
    float *normal = malloc(3 * n * sizeof *normal);
    double *phi = malloc((size_t)n_dirs * sizeof *phi);
    if (map && ground)
        s.iso = calloc(n, sizeof(double));
    if (!s.acc || !normal || !phi || (map && ground && !s.iso)) {
        free(s.acc), free(s.iso), free(normal), free(phi);
        return hfs_fail(err, HFS_E_NOMEM, "insolation: out of memory");
    }
    for (size_t p = 0; p < n; ++p) {
        double nrm[3];
        hfs_field_normal(&field, (int)(p % (size_t)field.width),
                         (int)(p / (size_t)field.width), nrm);
        for (int a = 0; a < 3; ++a)
            normal[3 * p + (size_t)a] = (float)nrm[a];
    }
    gis_product_directions(phi, n_dirs);
    for (int k = 0; k < n_dirs; ++k)
        phi[k] = gis_grid_phi(phi[k], c->dem->ex, c->dem->ey);
    s.normal = normal, s.phi = phi, s.map = map;
    hfs_quality q;
    hfs_quality_defaults(&q);
    /* the sums clamp each angle at the horizontal (and at the texel's own
     * plane): nothing below 0 is wanted */
    const int rc = gis_horizons_each(c->r, c->sweep, &field, &q, phi, n_dirs, c->radius, 0.0,
                                     add_sky, &s, err);
    if (!rc && map)
        gis_sky_map_finish(map, sky, s.acc, n);
    else if (!rc)
        gis_sky_finish(sky, s.acc, n, n_dirs);
    if (!rc && ground) {
        if (s.iso)
            gis_sky_finish(ground, s.iso, n, n_dirs);
        else
            memcpy(ground, sky, n * sizeof *ground);
        for (size_t i = 0; i < n; ++i)
            ground[i] = 1.0f - ground[i];
    }
    free(phi);
    free(normal);
    free(s.acc);
    free(s.iso);
    return rc;
}

/* The beam irradiation (Wh/m^2) of every step with h0 > 0 summed into acc
 * (the square grid), f of each into f. */
static int beam_sum(const gis_compute *c, const gis_period *p, double *acc, float *f,
                    hfs_error *err)
{
    const size_t n = (size_t)c->dem->sw * (size_t)c->dem->sh;
    sun_ground g = {0};
    int rc = ground_make(c, &g, err);
    for (long k = 0; k < p->n_steps && !rc; ++k) {
        double jd, hours;
        gis_sun_at s;
        gis_period_step(p, k, &jd, &hours);
        if (gis_sun_compute(jd, &p->site, p->linke, &s)) {
            rc = hfs_fail(err, HFS_E_INVALID, "insolation: no sun for step %ld", k + 1);
            break;
        }
        if (!(s.beam_normal > 0.0) || (rc = sun_factor(c, &s, &g, f, NULL, err)))
            continue;
        for (size_t q = 0; q < n; ++q)
            acc[q] += s.beam_normal * f[q] * hours;
    }
    free(g.normal);
    return rc;
}

int gis_product_insolation(const gis_compute *c, const gis_period *p, float *beam,
                           float *diffuse, float *global, gis_period_stats *st, hfs_error *err)
{
    const gis_dem *d = c->dem;
    const size_t n = (size_t)d->sw * (size_t)d->sh;
    const int with_sky = !p->beam_only, reflect = with_sky && p->albedo > 0.0;
    double *acc = calloc(n, sizeof *acc);
    float *f = calloc(n, sizeof *f), *sky = with_sky ? calloc(n, sizeof *sky) : NULL;
    float *ground = reflect ? calloc(n, sizeof *ground) : NULL;
    int rc = acc && f && (sky || !with_sky) && (ground || !reflect)
                 ? HFS_OK : hfs_fail(err, HFS_E_NOMEM, "insolation: out of memory");
    if (!rc && gis_period_scan(p, st))
        rc = hfs_fail(err, HFS_E_INVALID, "insolation: the site or period is out of range");
    if (!rc && with_sky && st->steps_sun > 0)
        rc = sky_share(c, p->sky_directions, p->sky, sky, ground, err);
    if (!rc)
        rc = beam_sum(c, p, acc, f, err);
    if (!rc) {
        for (size_t q = 0; q < n; ++q)
            f[q] = (float)acc[q];
        back(c, f, beam);
    }
    if (!rc && with_sky) {
        for (size_t q = 0; q < n; ++q)
            sky[q] = (float)(st->diffuse_wh * sky[q]);
        back(c, sky, diffuse);
        for (size_t q = 0; q < n; ++q) {
            double g = acc[q] + sky[q];
            if (reflect)
                g += p->albedo * st->global_wh * ground[q];
            f[q] = (float)g;
        }
        back(c, f, global);
    }
    free(acc);
    free(f);
    free(sky);
    free(ground);
    return rc;
}
