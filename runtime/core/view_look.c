/*
 * view_look.c — see view_look.h.
 */
#include "view_look.h"

#include "field_geom.h"
#include "key_setup.h"
#include "lights.h"
#include "sh.h"

#include <math.h>

#define PI 3.14159265358979323846
#define LN2 0.69314718055994531
#define HAZE_MAX 50.0
#define COLOR_MAX 1e30

static double luminance(const double rgb[3])
{
    return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

int hfs_view_look_check(const hfs_view *v, hfs_error *err)
{
    if (v->background != HFS_BACKGROUND_SKY && v->background != HFS_BACKGROUND_STUDIO &&
        v->background != HFS_BACKGROUND_COLOR)
        return hfs_fail(err, HFS_E_INVALID, "view: unknown background %d", (int)v->background);
    for (int c = 0; c < 3 && v->background == HFS_BACKGROUND_COLOR; ++c)
        if (!(v->background_rgb[c] >= 0.0 && v->background_rgb[c] <= COLOR_MAX))
            return hfs_fail(err, HFS_E_INVALID, "view: background colour %g is out of range "
                            "[0, %g]", v->background_rgb[c], COLOR_MAX);
    if (v->haze != HFS_HAZE_AUTO && !(v->haze >= 0.0 && v->haze <= HAZE_MAX))
        return hfs_fail(err, HFS_E_INVALID, "view: haze %g is out of range [0, %g] (or "
                        "HFS_HAZE_AUTO)", v->haze, HAZE_MAX);
    return HFS_OK;
}

int hfs_view_look_equal(const hfs_view_look *a, const hfs_view_look *b)
{
    int same = a->background == b->background && a->sigma == b->sigma && a->z0 == b->z0 &&
               a->scale_h == b->scale_h;
    for (int c = 0; c < 3; ++c)
        same &= a->rgb[c] == b->rgb[c] && a->in[c] == b->in[c];
    return same;
}

/* The environment's cosine-weighted mean radiance over the upper
 * hemisphere, negative SH lobes clamped to 0: a midpoint rule in
 * mu = cos(theta) (weight mu) and azimuth, fine enough for order 4. */
static void sky_mean_up(const double sh[3][HFS_SH_N], double out[3])
{
    enum { NMU = 16, NPHI = 32 };
    double sum[3] = {0.0, 0.0, 0.0}, wsum = 0.0;
    for (int i = 0; i < NMU; ++i) {
        const double mu = (i + 0.5) / NMU, s = sqrt(1.0 - mu * mu);
        for (int j = 0; j < NPHI; ++j) {
            const double phi = 2.0 * PI * (j + 0.5) / NPHI;
            double y[HFS_SH_N];
            hfs_sh_eval(s * cos(phi), s * sin(phi), mu, y);
            for (int c = 0; c < 3; ++c)
                sum[c] += mu * fmax(hfs_sh_dot(y, sh[c]), 0.0);
            wsum += mu;
        }
    }
    for (int c = 0; c < 3; ++c)
        out[c] = sum[c] / wsum;
}

/* The studio's level: the unshadowed radiance of a white level surface at
 * the field's centre, mid height, under every light (luminance); 1 in a
 * scene without light, so the backdrop still shows. */
static double studio_level(const hfs_field *f, const hfs_lighting *l, const double env_up[3])
{
    double e = hfs_env_contributes(l) ? PI * luminance(env_up) : 0.0;
    for (int i = 0; i < l->n_key; ++i) {
        const hfs_key_light *k = &l->key[i];
        if (k->disabled)
            continue;
        const double le[3] = {k->radiance[0], k->radiance[1], k->radiance[2]};
        e += luminance(le) * hfs_cap_irradiance(sin(k->elev), k->alpha);
    }
    double lo, hi;
    hfs_field_range(f, &lo, &hi);
    const double p[3] = {0.5 * (f->width - 1) * f->dx, 0.5 * (f->height - 1) * f->dx,
                         0.5 * f->zscale * (lo + hi)};
    for (int i = 0; i < l->n_local; ++i) {
        const hfs_local_light *q = &l->local[i];
        if (!hfs_local_light_contributes(q))
            continue;
        const double d[3] = {q->pos[0] - p[0], q->pos[1] - p[1], q->pos[2] - p[2]};
        const double dist = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        const double le[3] = {q->radiance[0], q->radiance[1], q->radiance[2]};
        e += luminance(le) * (dist <= q->radius ? PI
                                                : hfs_cap_irradiance(d[2] / dist,
                                                                     asin(q->radius / dist)));
    }
    const double level = e / PI;
    return level > 0.0 && isfinite(level) ? level : 1.0;
}

void hfs_view_look_make(const hfs_view *v, const hfs_field *f, const hfs_lighting *l,
                        hfs_view_look *out)
{
    *out = (hfs_view_look){.background = v->background};
    double sh[3][HFS_SH_N] = {{0.0}}, up[3] = {0.0, 0.0, 0.0};
    const int env = hfs_env_contributes(l);
    if (env) {
        hfs_env_rotated(l, sh);
        sky_mean_up(sh, up);
    }
    if (v->background == HFS_BACKGROUND_COLOR)
        for (int c = 0; c < 3; ++c)
            out->rgb[c] = v->background_rgb[c];
    if (v->background == HFS_BACKGROUND_STUDIO)
        out->rgb[0] = out->rgb[1] = out->rgb[2] = studio_level(f, l, up);
    const double tau = v->haze == HFS_HAZE_AUTO ? (env ? LN2 : 0.0) : v->haze;
    const double diag = f->dx * hypot(f->width - 1.0, f->height - 1.0);
    if (!(tau > 0.0 && diag > 0.0))
        return;
    double lo, hi;
    hfs_field_range(f, &lo, &hi);
    out->sigma = tau / diag;
    out->scale_h = 0.25 * diag;
    out->z0 = lo * f->zscale * v->exaggeration;
    for (int c = 0; c < 3; ++c)
        out->in[c] = up[c];
}

void hfs_env_map_bilinear(const float *map, int w, int h, double rot, const double d[3],
                          double rgb[3])
{
    /* Pixel centres at u = c + 0.5 (azimuth 2 pi u / w, turned by rot) and
     * v = r + 0.5 (elevation pi/2 - pi v / h, row 0 the zenith). */
    const double phi = atan2(d[1], d[0]) - rot;
    const double el = asin(fmax(-1.0, fmin(1.0, d[2])));
    double u = phi / (2.0 * PI);
    u = (u - floor(u)) * w - 0.5;
    const double v = fmin(fmax((0.5 - el / PI) * h - 0.5, 0.0), h - 1.0);
    const double fu = floor(u), fv = floor(v);
    const double au = u - fu, av = v - fv;
    const int c0 = ((int)fu + w) % w, c1 = (c0 + 1) % w;
    const int r0 = (int)fv, r1 = r0 + 1 < h ? r0 + 1 : r0;
    for (int c = 0; c < 3; ++c) {
        const double a = map[3 * ((size_t)r0 * w + c0) + c] * (1.0 - au) +
                         map[3 * ((size_t)r0 * w + c1) + c] * au;
        const double b = map[3 * ((size_t)r1 * w + c0) + c] * (1.0 - au) +
                         map[3 * ((size_t)r1 * w + c1) + c] * au;
        rgb[c] = a * (1.0 - av) + b * av;
    }
}

void hfs_view_background(const hfs_view_look *k, const hfs_lighting *l,
                         const double sh[3][HFS_SH_COEFFS], const double d[3], double rgb[3])
{
    if (k && k->background != HFS_BACKGROUND_SKY) {
        const double g = k->background == HFS_BACKGROUND_STUDIO
                             ? HFS_STUDIO_BASE + HFS_STUDIO_SLOPE * (1.0 + d[2])
                             : 1.0;
        for (int c = 0; c < 3; ++c)
            rgb[c] = k->rgb[c] * g;
        return;
    }
    rgb[0] = rgb[1] = rgb[2] = 0.0;
    if (!l->has_env)
        return;
    if (l->env_map) {
        hfs_env_map_bilinear(l->env_map, l->env_map_width, l->env_map_height, l->env_rotate,
                             d, rgb);
        return;
    }
    double y[HFS_SH_N];
    hfs_sh_eval(d[0], d[1], d[2], y);
    for (int c = 0; c < 3; ++c)
        rgb[c] = hfs_sh_dot(y, sh[c]);
}

double hfs_haze_transmittance(const hfs_view_look *k, double dist, double za, double zb)
{
    const double a = fmax(za - k->z0, 0.0) / k->scale_h;
    const double b = fmax(zb - k->z0, 0.0) / k->scale_h;
    const double x = b - a;
    const double g = fabs(x) < HFS_HAZE_SERIES ? exp(-a) * (1.0 - x / 2.0 + x * x / 6.0)
                                               : (exp(-a) - exp(-b)) / x;
    return exp(-k->sigma * dist * g);
}

void hfs_haze_apply(const hfs_view_look *k, double dist, double za, double zb, double rgb[3])
{
    const double t = hfs_haze_transmittance(k, dist, za, zb);
    for (int c = 0; c < 3; ++c)
        rgb[c] = rgb[c] * t + k->in[c] * (1.0 - t);
}
