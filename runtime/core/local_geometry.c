/*
 * local_geometry.c — see local_geometry.h.
 */
#include "local_geometry.h"

#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846
#define HALF_PI 1.57079632679489661923

/* ---- geometry ------------------------------------------------------------------- */

void hfs_local_view_make(const hfs_local_light *l, const double p[3], hfs_local_view *lv)
{
    memset(lv, 0, sizeof *lv);
    for (int k = 0; k < 3; ++k)
        lv->v[k] = l->pos[k] - p[k];
    const double d = sqrt(lv->v[0] * lv->v[0] + lv->v[1] * lv->v[1] + lv->v[2] * lv->v[2]);
    const double r = l->radius;
    lv->d = d;
    lv->r = r;
    if (d > 0.0) {
        for (int k = 0; k < 3; ++k)
            lv->dir[k] = lv->v[k] / d;
    } else {
        lv->dir[2] = 1.0;
    }
    lv->rho_h = hypot(lv->v[0], lv->v[1]);
    lv->phi_l = atan2(lv->v[1], lv->v[0]);
    lv->elev_l = atan2(lv->v[2], lv->rho_h);
    lv->surround = r >= lv->rho_h;
    if (r > 0.0 && d <= r) {
        lv->inside = 1;
        lv->alpha = PI;
        return;
    }
    /* Outside (d > r >= 0, so d > 0). */
    lv->c_tan = (d - r) * (d + r);
    lv->sin_a = r / d;
    lv->cos_a = sqrt(lv->c_tan) / d;
    lv->alpha = atan2(lv->sin_a, lv->cos_a);
}

int hfs_local_cap_window(const hfs_local_view *lv, double c, double s, double *lo, double *hi)
{
    /* Points of the vertical great circle of azimuth u = (c, s, 0):
     * t(e) = cos e u + sin e z, angle to the axis: cos = R cos(e - psi) with
     * (A, B) = (dir.u, dir_z) = R (cos psi, sin psi).  The cap is cos >= cos a,
     * so e in psi +- half, cos half = cos a / R, sin half * R =
     * sqrt(sin^2 a - w^2), w = dir . (-s, c, 0) (1 - R^2 = w^2: stable form). */
    const double a = lv->dir[0] * c + lv->dir[1] * s, b = lv->dir[2];
    const double w = -lv->dir[0] * s + lv->dir[1] * c;
    const double q = lv->sin_a * lv->sin_a - w * w;
    if (!(q > 0.0) || !(lv->cos_a >= 0.0)) {
        *lo = *hi = 0.0;
        return 0;
    }
    const double psi = atan2(b, a), half = atan2(sqrt(q), lv->cos_a);
    double l = psi - half, h = psi + half;
    /* psi in (-pi, pi], half < pi/2: the arc never wraps into this half-plane
     * from the other side; clipping is enough. */
    l = l < -HALF_PI ? -HALF_PI : l;
    h = h > HALF_PI ? HALF_PI : h;
    if (!(l < h)) {
        *lo = *hi = 0.0;
        return 0;
    }
    *lo = l;
    *hi = h;
    return 1;
}

double hfs_local_entry_distance(const hfs_local_view *lv, double c, double s, double ce,
                                double se)
{
    const double b = ce * (c * lv->v[0] + s * lv->v[1]) + se * lv->v[2]; /* ray . v */
    const double disc = b * b - lv->c_tan;
    double t;
    if (b > 0.0 && disc >= 0.0)
        t = lv->c_tan / (b + sqrt(disc)); /* = b - sqrt(disc), without cancellation */
    else
        t = b > 0.0 ? b : 0.0;            /* misses: closest approach */
    const double th = t * ce;
    return th > 0.0 ? th : 0.0;
}

/* ---- swath and Legendre visibility --------------------------------------------------- */

void hfs_local_swath_make(const hfs_local_view *lv, int nphi_local,
                          hfs_local_swath_mode mode, hfs_visibility_path path,
                          hfs_local_swath *sw)
{
    const int nfull = nphi_local < 1 ? 1 : nphi_local;
    if (path == HFS_VIS_WEDGE_TABLE || mode == HFS_LOCAL_SWATH_FULL || lv->surround ||
        !(lv->r < lv->rho_h)) {
        sw->n = nfull;
        sw->full = 1;
        sw->phi0 = 0.0;
        sw->dphi = 2.0 * PI / nfull;
        return;
    }
    const double h = asin(lv->r / lv->rho_h);
    int n = (int)ceil(nfull * h / PI);
    n = n < HFS_LOCAL_PARTIAL_MIN ? HFS_LOCAL_PARTIAL_MIN : n;
    n = n > nfull ? nfull : n;
    sw->n = n;
    sw->full = 0;
    sw->dphi = 2.0 * h / n;
    sw->phi0 = lv->phi_l - h + 0.5 * sw->dphi;
}

/* integral_0^w (1 - u/w) cos(m u) du = 2 sin^2(m w/2) / (m^2 w). */
static double tri_cos(double w, int m)
{
    if (!(w > 0.0))
        return 0.0;
    if (m == 0)
        return 0.5 * w;
    const double x = m * w, hs = sin(0.5 * x);
    return 2.0 * hs * hs / (m * x);
}

/* integral_0^w (1 - u/w) sin(m u) du = (x - sin x) / (m x), x = m w. */
static double tri_sin(double w, int m)
{
    if (!(w > 0.0) || m == 0)
        return 0.0;
    const double x = m * w;
    if (x < 0.1) {
        const double x2 = x * x;
        return x2 * (1.0 / 6.0 - x2 * (1.0 / 120.0 - x2 * (1.0 / 5040.0 - x2 / 362880.0))) / m;
    }
    return (x - sin(x)) / (m * x);
}

static void hat_make(double wl, double wr, hfs_local_hat *hm)
{
    for (int m = 0; m < 4; ++m) {
        hm->gc[m] = tri_cos(wl, m) + tri_cos(wr, m);
        hm->gs[m] = tri_sin(wr, m) - tri_sin(wl, m);
    }
}

void hfs_local_swath_hats(const hfs_local_swath *sw, hfs_local_hat hats[3])
{
    const double d = sw->dphi, b = sw->full ? d : 0.5 * d;
    hat_make(b, sw->n == 1 ? b : d, &hats[0]);
    hat_make(d, d, &hats[1]);
    hat_make(sw->n == 1 ? b : d, b, &hats[2]);
}

const hfs_local_hat *hfs_local_sample_hat(const hfs_local_swath *sw, const hfs_local_hat hats[3],
                                          int k)
{
    return k == 0 ? &hats[0] : (k == sw->n - 1 ? &hats[2] : &hats[1]);
}

void hfs_local_weights_at(double c, double s, const hfs_local_hat *hm, double A[HFS_SH_N])
{
    const double *gc = hm->gc, *gs = hm->gs;
    double cm[4], sm[4];
    cm[0] = 1.0;
    sm[0] = 0.0;
    cm[1] = c;
    sm[1] = s;
    for (int m = 2; m < 4; ++m) { /* angle addition */
        cm[m] = cm[m - 1] * cm[1] - sm[m - 1] * sm[1];
        sm[m] = sm[m - 1] * cm[1] + cm[m - 1] * sm[1];
    }
    for (int r = 0; r < HFS_SH_N; ++r) {
        const int m = hfs_sh_order(r);
        if (m == 0)
            A[r] = gc[0];
        else if (m > 0)
            A[r] = cm[m] * gc[m] - sm[m] * gs[m];
        else
            A[r] = sm[-m] * gc[-m] + cm[-m] * gs[-m];
    }
}

void hfs_local_sample_weights(const hfs_local_swath *sw, int k, double A[HFS_SH_N])
{
    hfs_local_hat hats[3];
    hfs_local_swath_hats(sw, hats);
    hfs_local_weights_at(cos(sw->phi0 + k * sw->dphi), sin(sw->phi0 + k * sw->dphi),
                   hfs_local_sample_hat(sw, hats, k), A);
}

void hfs_local_legendre_eval(const hfs_local_swath *sw, const double *E, const double *nlp,
                             double V[HFS_SH_N])
{
    for (int r = 0; r < HFS_SH_N; ++r)
        V[r] = 0.0;
    hfs_local_hat hats[3];
    hfs_local_swath_hats(sw, hats);
    for (int k = 0; k < sw->n; ++k) {
        double A[HFS_SH_N];
        hfs_local_weights_at(cos(sw->phi0 + k * sw->dphi), sin(sw->phi0 + k * sw->dphi),
                   hfs_local_sample_hat(sw, hats, k), A);
        const double *x = nlp + (size_t)k * HFS_NLP_N;
        for (int r = 0; r < HFS_SH_N; ++r) {
            const double *e = E + r * HFS_NLP_N;
            V[r] += A[r] * (e[0] * x[0] + e[1] * x[1] + e[2] * x[2] + e[3] * x[3]);
        }
    }
}
