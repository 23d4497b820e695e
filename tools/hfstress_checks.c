/*
 * hfstress_checks.c — the checks hfstress applies to one image, and the
 * bounds they compare against (hfstress.h; derivations in docs/STRESS.md).
 */
#include "hfstress.h"

#include "field_geom.h"
#include "sh.h"

#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846

void stress_sh_range(const double sh[HFS_SH_COEFFS], double *neg, double *absmax)
{
    /* The function is a polynomial of degree 3 on the sphere: a 1-degree
     * grid finds its extremes to ~1e-4 of its range, far inside the
     * tolerances these are used with. */
    double lmin = INFINITY, amax = 0.0;
    for (int r = 0; r <= 180; ++r) {
        const double e = PI / 2 - PI * r / 180.0;
        for (int a = 0; a < 360; ++a) {
            double y[HFS_SH_N];
            hfs_sh_eval_dir(2.0 * PI * a / 360.0, e, y);
            const double v = hfs_sh_dot(y, sh);
            lmin = v < lmin ? v : lmin;
            amax = fabs(v) > amax ? fabs(v) : amax;
        }
    }
    *neg = lmin < 0.0 ? -lmin : 0.0;
    *absmax = amax;
}

void stress_check_bound(const hfs_image *out, const hfs_image *un, double umax,
                        const double lneg[3], double albedo, stress_bound *b)
{
    b->nonfinite = 0;
    b->over = 0.0;
    b->min_out = INFINITY;
    b->max_out = -INFINITY;
    b->worst_x = b->worst_y = b->worst_c = -1;
    b->worst_out = b->worst_u = 0.0;
    double worst = 0.0;
    for (int j = 0; j < out->height; ++j)
        for (int i = 0; i < out->width; ++i)
            for (int c = 0; c < 3; ++c) {
                const size_t at = ((size_t)j * (size_t)out->width + (size_t)i) * 3 + (size_t)c;
                const double o = out->rgb[at], u = un->rgb[at];
                if (!isfinite(o)) {
                    b->nonfinite++;
                    continue;
                }
                b->min_out = o < b->min_out ? o : b->min_out;
                b->max_out = o > b->max_out ? o : b->max_out;
                const double slack = albedo * lneg[c];
                const double lo = -slack, hi = u + slack;
                const double v = fmax(lo - o, o - hi);
                if (v > worst) {
                    worst = v;
                    b->worst_x = i;
                    b->worst_y = j;
                    b->worst_c = c;
                    b->worst_out = o;
                    b->worst_u = u;
                }
            }
    b->over = umax > 0.0 ? worst / umax : worst;
}

double stress_max_diff_at(const hfs_image *a, const hfs_image *b, double norm, size_t *at)
{
    const size_t n = (size_t)a->width * (size_t)a->height * 3;
    double m = 0.0;
    *at = 0;
    for (size_t i = 0; i < n; ++i) {
        const double d = fabs((double)a->rgb[i] - (double)b->rgb[i]);
        if (!(d <= m))
            m = d, *at = i; /* NaN propagates as a failure */
    }
    return norm > 0.0 ? m / norm : m;
}

double stress_max_diff(const hfs_image *a, const hfs_image *b, double norm)
{
    size_t at;
    return stress_max_diff_at(a, b, norm, &at);
}

double stress_const_err(const hfs_image *out, double value)
{
    const size_t n = (size_t)out->width * (size_t)out->height * 3;
    double m = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const double d = fabs((double)out->rgb[i] - value);
        if (!(d <= m))
            m = d;
    }
    return m / fmax(value, 1e-300);
}

/* Unit roundoff of fp16 (11 significand bits) and of an fp16 (hi, lo) pair
 * (lo keeps hi's rounding error to its own 2^-11: 2^-22 of the value). */
#define U16 (1.0 / 2048.0)
#define U_PAIR (U16 * U16)

/* A light's share of the frame: its largest exit radiance over umax. */
static double share(double albedo, const float le[3], double e_max, double umax)
{
    const double l = fmax(le[0], fmax(le[1], le[2]));
    return albedo / PI * l * e_max / umax;
}

/* 2 pi (1 - cos a), without its cancellation for small a. */
static double cap_solid_angle(double a)
{
    const double h = sin(0.5 * a);
    return 4.0 * PI * h * h;
}

void stress_fp16_bound(const stress_scene *sc, double umax, stress_fp16_terms *t)
{
    memset(t, 0, sizeof *t);
    if (!(umax > 0.0))
        return;
    const hfs_field *f = &sc->f;
    const hfs_lighting *l = &sc->l;
    /* The terrain's slope scale S = hscale zscale / dx.  Heights are
     * normalized to v in [-1, 1] (v = (z - base) / hscale) and kept as
     * pairs to <= 2^-22 (the upload rounds both halves: 2^-24; pyramid
     * levels written by shaders: 2^-22), float keeps 2^-25; a height
     * difference between receiver and sample is then off by <= 2 2^-22,
     * its slope D = dv S / d by 2^-21 S / d and the angle atan(D) by as
     * much (d >= 1). */
    double zmin = f->z[0], zmax = f->z[0];
    for (size_t i = 1; i < (size_t)f->width * (size_t)f->height; ++i) {
        zmin = f->z[i] < zmin ? f->z[i] : zmin;
        zmax = f->z[i] > zmax ? f->z[i] : zmax;
    }
    const double slope = 0.5 * (zmax - zmin) * f->zscale / f->dx;
    const double dh = fmin(PI / 2, 2.0 * U_PAIR * slope); /* |dw| from heights */
    /* Normals come from the same heights (hfs_normal_at, heights 2^-24
     * each): a one-sided difference's slope is off by 2^-23 S, the normal's
     * direction by as much; plus float's rounding, a few 2^-22 (the bound
     * of the stored octahedral pairs they once were). */
    const double dn = fmin(PI / 2, 0.5 * U_PAIR * slope + 4.0 * U_PAIR);

    /* Environment: V - hemisphere(N) is stored as one fp16 per coefficient,
     * |dV_k| <= U16 |V_k - hemi_k| and |V - hemi|_2 <= sqrt(4 pi) (a
     * function in [-1, 0] projected: sqrt(2 pi), doubled in area for the
     * approximations' overshoot); its error in Lo is
     * rho/pi dV . (H(N) * L) <= rho/pi U16 sqrt(4 pi) |H(N) * L|_2.
     * Horizons moved by dh change Lo by at most 2 rho max|L| dh (a band of
     * height dh in every azimuth, weighted by cos e (N.s) <= 1). */
    if (l->has_env) {
        double zh[HFS_ZH_N];
        hfs_zh_clamped_cosine(zh);
        double env[3][HFS_SH_N], lmax = 0.0;
        for (int c = 0; c < 3; ++c) {
            double neg, amax;
            hfs_sh_rotate_z(l->env_sh[c], l->env_rotate, env[c]);
            stress_sh_range(env[c], &neg, &amax);
            lmax = fmax(lmax, amax);
        }
        double worst = 0.0;
        for (int j = 0; j < f->height; ++j)
            for (int i = 0; i < f->width; ++i) {
                double n[3], h[HFS_SH_N], p[HFS_SH_N];
                hfs_field_normal(f, i, j, n);
                hfs_sh_rotate_zonal(zh, n[0], n[1], n[2], h);
                for (int c = 0; c < 3; ++c) {
                    hfs_sh_product(h, env[c], p);
                    worst = fmax(worst, sqrt(hfs_sh_dot(p, p)));
                }
            }
        /* The wedge-table path also reads V's wedges from fp16 tables: one
         * more U16 per wedge, |wedge_j|_2 <= sqrt(its solid angle), summed
         * over n wedges <= sqrt(n 4 pi). */
        const double tables = sc->q.visibility == HFS_VIS_WEDGE_TABLE ? sqrt(sc->q.nphi_env) : 0.0;
        t->env = l->albedo / PI * U16 * (1.0 + tables) * sqrt(4.0 * PI) * worst / umax;
        /* The slice path stores the grid's horizons in fp16 instead: as
         * u = tan(x / 2), |dx| <= 2 U16 |u| / (1 + u^2) <= U16; as an
         * occluder (height h, distance d, each to U16), the slope h / d to
         * 2 U16, |dx| <= 2 U16 |t| / (1 + t^2) <= U16.  A band of U16 in
         * every azimuth: 2 rho max|L| U16, as for the heights below. */
        if (sc->q.visibility == HFS_VIS_SLICE)
            t->env += 2.0 * U16 * l->albedo * lmax / umax;
        t->heights += fmin(2.0 * dh, 1.0) * l->albedo * lmax / umax; /* <= its whole share */
        /* A normal turned by dn moves max(0, N.s) by <= |dN.s|, which
         * integrates to 2 pi dn over the sphere: 2 rho max|L| dn. */
        t->normals += fmin(2.0 * dn, 1.0) * l->albedo * lmax / umax;
    }
    /* Key and local lights, ratio form: an angle error dw at a penumbra
     * texel moves the visible fraction of a disk of angular radius alpha
     * by at most dw / alpha.  dw: the horizon excess's (hi, lo) pair,
     * 2^-22 pi, and the heights' dh. */
    const double dx = f->dx;
    const double box_lo[3] = {0.0, 0.0, f->zscale * zmin};
    const double box_hi[3] = {(f->width - 1) * dx, (f->height - 1) * dx,
                              f->zscale * zmax + 1e-4 * dx};
    for (int k = 0; k < l->n_key; ++k) {
        const hfs_key_light *kl = &l->key[k];
        if (kl->disabled)
            continue;
        const double w = share(l->albedo, kl->radiance, PI * pow(sin(kl->alpha), 2), umax);
        t->excess += w * fmin(1.0, U_PAIR * PI / kl->alpha);
        t->heights += w * fmin(1.0, dh / kl->alpha);
        /* E_cap of a turned normal: <= (cap's solid angle) dn. */
        t->normals += share(l->albedo, kl->radiance, cap_solid_angle(kl->alpha) * dn, umax);
        /* Tables: num and den each from fp16 wedges, the ratio off by 2 U16. */
        if (sc->q.visibility == HFS_VIS_WEDGE_TABLE)
            t->excess += w * 2.0 * U16;
    }
    for (int k = 0; k < l->n_local; ++k) {
        const hfs_local_light *o = &l->local[k];
        if (o->disabled || !(o->radius > 0.0))
            continue;
        /* Nearest and farthest points of the field's box from the centre. */
        double dmin2 = 0.0, dmax2 = 0.0;
        for (int a = 0; a < 3; ++a) {
            const double c = o->pos[a];
            const double e = c < box_lo[a] ? box_lo[a] - c : (c > box_hi[a] ? c - box_hi[a] : 0.0);
            const double far = fmax(fabs(c - box_lo[a]), fabs(c - box_hi[a]));
            dmin2 += e * e;
            dmax2 += far * far;
        }
        const double r = o->radius;
        const double e_max = dmin2 <= r * r ? PI : PI * r * r / dmin2;
        const double a_min = dmax2 <= r * r ? PI / 2 : asin(r / sqrt(dmax2));
        const double a_max = dmin2 <= r * r ? PI / 2 : asin(r / sqrt(dmin2));
        const double w = share(l->albedo, o->radiance, e_max, umax);
        t->excess += w * fmin(1.0, U_PAIR * PI / a_min);
        t->heights += w * fmin(1.0, dh / a_min);
        t->normals += share(l->albedo, o->radiance, cap_solid_angle(a_max) * dn, umax);
    }
    /* Stored normals and the output are (hi, lo) pairs too: 2^-22 each, a
     * few of them per texel; 2^-18 covers them with room. */
    t->pairs = 16.0 * U_PAIR;
    t->total = t->env + t->excess + t->heights + t->normals + t->pairs;
}
