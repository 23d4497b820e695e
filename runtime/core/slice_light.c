/*
 * slice_light.c — see slice_light.h.
 */
#include "slice_light.h"

#include <math.h>
#include <stdlib.h>

#define PI 3.14159265358979323846
/* The 7 integrals in closed form.  With J0 = pi/2 - x, Jc_k = Int_x^{pi/2}
 * cos ke de = (sin(k pi/2) - sin kx) / k and Js_k = Int sin ke de =
 * (cos kx - cos(k pi/2)) / k, the products of f_m with cos^2 e =
 * (1 + cos 2e)/2 (A) and with sin e cos e = sin 2e / 2 (B) are
 *   m  f_m      A_m                                 B_m
 *   0  1        (J0 + Jc2) / 2                      Js2 / 2
 *   1  cos e    (3 Jc1 + Jc3) / 4                   (Js1 + Js3) / 4
 *   2  sin e    (Js1 + Js3) / 4                     (Jc1 - Jc3) / 4
 *   3  cos 2e   J0 / 4 + Jc2 / 2 + Jc4 / 4          Js4 / 4
 *   4  sin 2e   Js2 / 2 + Js4 / 4                   (J0 - Jc4) / 4
 *   5  cos 3e   Jc1 / 4 + Jc3 / 2 + Jc5 / 4         (Js5 - Js1) / 4
 *   6  sin 3e   Js1 / 4 + Js3 / 2 + Js5 / 4         (Jc1 - Jc5) / 4
 * and g_m = a A_m + b B_m.  shaders_es/gles_lib.frag (hfs_slice_g) writes
 * the same table. */
void hfs_slice_integrals(double a, double b, double x, double g[HFS_SLICE_F])
{
    x = x < -0.5 * PI ? -0.5 * PI : (x > 0.5 * PI ? 0.5 * PI : x);
    const double c1 = cos(x), s1 = sin(x);
    const double c2 = c1 * c1 - s1 * s1, s2 = 2.0 * s1 * c1;
    const double c3 = c2 * c1 - s2 * s1, s3 = s2 * c1 + c2 * s1;
    const double c4 = c3 * c1 - s3 * s1, s4 = s3 * c1 + c3 * s1;
    const double c5 = c4 * c1 - s4 * s1, s5 = s4 * c1 + c4 * s1;
    const double J0 = 0.5 * PI - x;
    const double Jc1 = 1.0 - s1, Js1 = c1;
    const double Jc2 = -s2 / 2.0, Js2 = (c2 + 1.0) / 2.0;
    const double Jc3 = (-1.0 - s3) / 3.0, Js3 = c3 / 3.0;
    const double Jc4 = -s4 / 4.0, Js4 = (c4 - 1.0) / 4.0;
    const double Jc5 = (1.0 - s5) / 5.0, Js5 = c5 / 5.0;
    const double A[HFS_SLICE_F] = {(J0 + Jc2) / 2.0,
                                   (3.0 * Jc1 + Jc3) / 4.0,
                                   (Js1 + Js3) / 4.0,
                                   J0 / 4.0 + Jc2 / 2.0 + Jc4 / 4.0,
                                   Js2 / 2.0 + Js4 / 4.0,
                                   Jc1 / 4.0 + Jc3 / 2.0 + Jc5 / 4.0,
                                   Js1 / 4.0 + Js3 / 2.0 + Js5 / 4.0};
    const double B[HFS_SLICE_F] = {Js2 / 2.0,          (Js1 + Js3) / 4.0, (Jc1 - Jc3) / 4.0,
                                   Js4 / 4.0,          (J0 - Jc4) / 4.0,  (Js5 - Js1) / 4.0,
                                   (Jc1 - Jc5) / 4.0};
    for (int m = 0; m < HFS_SLICE_F; ++m)
        g[m] = a * A[m] + b * B[m];
}

/* p[k][m]: Y_k along the vertical great circle of direction (c, sn) in the
 * basis f_m, by an exact DFT of the degree-3 trigonometric polynomial (8
 * samples). */
static void profile_at(double c, double sn, double *p)
{
    double y[8][HFS_SH_N];
    for (int q = 0; q < 8; ++q) {
        const double e = 2.0 * PI * q / 8.0;
        hfs_sh_eval(cos(e) * c, cos(e) * sn, sin(e), y[q]);
    }
    for (int k = 0; k < HFS_SH_N; ++k) {
        double sum0 = 0.0;
        for (int q = 0; q < 8; ++q)
            sum0 += y[q][k];
        p[k * HFS_SLICE_F] = sum0 / 8.0;
        for (int m = 1; m <= 3; ++m) {
            double sc = 0.0, ss = 0.0;
            for (int q = 0; q < 8; ++q) {
                const double e = 2.0 * PI * q / 8.0;
                sc += y[q][k] * cos(m * e);
                ss += y[q][k] * sin(m * e);
            }
            p[k * HFS_SLICE_F + 2 * m - 1] = sc / 4.0;
            p[k * HFS_SLICE_F + 2 * m] = ss / 4.0;
        }
    }
}

int hfs_slice_order(int k)
{
    const int l = (int)floor(sqrt((double)k) + 1e-9);
    return k - l * (l + 1);
}

double hfs_slice_trig(int k, double phi)
{
    const int m = hfs_slice_order(k);
    return m == 0 ? 1.0 : (m > 0 ? cos(m * phi) : sin(-m * phi));
}

void hfs_slice_profile(double a[HFS_SH_N][HFS_SLICE_F])
{
    for (int k = 0; k < HFS_SH_N; ++k) {
        /* Where the azimuthal factor is 1: phi = 0 for cos(m phi) and the
         * zonal ones, pi / (2|m|) for sin(|m| phi). */
        const int m = hfs_slice_order(k);
        const double phi = m < 0 ? PI / (2.0 * -m) : 0.0;
        double p[HFS_SH_N * HFS_SLICE_F];
        profile_at(cos(phi), sin(phi), p);
        for (int f = 0; f < HFS_SLICE_F; ++f)
            a[k][f] = p[k * HFS_SLICE_F + f];
    }
}

int hfs_slice_table_init(hfs_slice_table *t, const hfs_swath *s, hfs_error *err)
{
    t->n = s->n;
    t->dphi = s->dphi;
    t->p = malloc((size_t)s->n * HFS_SH_N * HFS_SLICE_F * sizeof *t->p);
    t->dir = malloc((size_t)s->n * 2 * sizeof *t->dir);
    if (!t->p || !t->dir) {
        hfs_slice_table_free(t);
        return hfs_fail(err, HFS_E_NOMEM, "slice lighting: out of memory");
    }
    for (int j = 0; j < s->n; ++j) {
        const double phi = hfs_swath_phi(s, j);
        /* Snapped as the horizons' directions (cpu_horizon.c): an axis
         * exactly. */
        double c = cos(phi), sn = sin(phi);
        c = fabs(c) < 1e-12 ? 0.0 : c;
        sn = fabs(sn) < 1e-12 ? 0.0 : sn;
        t->dir[2 * j] = c;
        t->dir[2 * j + 1] = sn;
        profile_at(c, sn, t->p + (size_t)j * HFS_SH_N * HFS_SLICE_F);
    }
    return HFS_OK;
}

void hfs_slice_table_free(hfs_slice_table *t)
{
    free(t->p);
    free(t->dir);
    t->p = NULL;
    t->dir = NULL;
}

void hfs_slice_add_occluded(const hfs_slice_table *t, int j, const double n[3], double x,
                            double T[HFS_SH_N])
{
    const double a = n[0] * t->dir[2 * j] + n[1] * t->dir[2 * j + 1], b = n[2];
    const double floor = atan2(-a, b);
    if (!(x > floor))
        return; /* open: nothing occluded */
    double gx[HFS_SLICE_F], gf[HFS_SLICE_F];
    hfs_slice_integrals(a, b, x, gx);
    hfs_slice_integrals(a, b, floor, gf);
    const double *p = t->p + (size_t)j * HFS_SH_N * HFS_SLICE_F;
    for (int k = 0; k < HFS_SH_N; ++k) {
        double s = 0.0;
        for (int m = 0; m < HFS_SLICE_F; ++m)
            s += p[k * HFS_SLICE_F + m] * (gx[m] - gf[m]);
        T[k] += t->dphi * s;
    }
}

void hfs_slice_add_occluded_mean(const hfs_slice_table *t, int j, const double n[3],
                                 const double *x, int nx, double T[HFS_SH_N])
{
    const double a = n[0] * t->dir[2 * j] + n[1] * t->dir[2 * j + 1], b = n[2];
    const double floor = atan2(-a, b);
    double d[HFS_SLICE_F] = {0}, gx[HFS_SLICE_F], gf[HFS_SLICE_F];
    int any = 0;
    hfs_slice_integrals(a, b, floor, gf);
    for (int h = 0; h < nx; ++h) {
        if (!(x[h] > floor))
            continue; /* open: nothing occluded */
        hfs_slice_integrals(a, b, x[h], gx);
        for (int m = 0; m < HFS_SLICE_F; ++m)
            d[m] += (gx[m] - gf[m]) / nx;
        any = 1;
    }
    if (!any)
        return;
    const double *p = t->p + (size_t)j * HFS_SH_N * HFS_SLICE_F;
    for (int k = 0; k < HFS_SH_N; ++k) {
        double s = 0.0;
        for (int m = 0; m < HFS_SLICE_F; ++m)
            s += p[k * HFS_SLICE_F + m] * d[m];
        T[k] += t->dphi * s;
    }
}

void hfs_slice_add(const hfs_slice_table *t, int j, const double n[3], double x,
                   double T[HFS_SH_N])
{
    const double a = n[0] * t->dir[2 * j] + n[1] * t->dir[2 * j + 1], b = n[2];
    double g[HFS_SLICE_F];
    hfs_slice_integrals(a, b, x, g);
    const double *p = t->p + (size_t)j * HFS_SH_N * HFS_SLICE_F;
    for (int k = 0; k < HFS_SH_N; ++k) {
        double s = 0.0;
        for (int m = 0; m < HFS_SLICE_F; ++m)
            s += p[k * HFS_SLICE_F + m] * g[m];
        T[k] += t->dphi * s;
    }
}

double hfs_slice_cosine(double a, double b, double x)
{
    return 0.5 * a * (0.5 * PI - x - 0.5 * sin(2.0 * x)) + 0.25 * b * (1.0 + cos(2.0 * x));
}

void hfs_lobe_slice_init(hfs_lobe_slice *ls, const double r[3], const double n[3], double c,
                         double s, double gloss)
{
    ls->A = r[0] * c + r[1] * s, ls->B = r[2];
    ls->a = n[0] * c + n[1] * s, ls->b = n[2];
    ls->s = gloss;
    ls->h = fmin(0.1, 0.5 * sqrt(2.0 / gloss));
    const double rho = sqrt(ls->A * ls->A + ls->B * ls->B);
    const double cmin = exp(log(1e-6) / gloss); /* t_R^S >= 1e-6 for t_R >= cmin */
    ls->lo = 1.0, ls->hi = 0.0;
    if (rho > cmin) {
        const double eps = atan2(ls->B, ls->A), u = acos(cmin / rho);
        ls->lo = eps - u, ls->hi = eps + u;
    }
}

static double lobe_integrand(const hfs_lobe_slice *ls, double e)
{
    const double ce = cos(e), se = sin(e);
    const double tr = ls->A * ce + ls->B * se, tn = ls->a * ce + ls->b * se;
    return tr > 0.0 && tn > 0.0 ? pow(tr, ls->s) * tn * ce : 0.0;
}

double hfs_lobe_slice_band(const hfs_lobe_slice *ls, double x1, double x2)
{
    const double lo = fmax(x1, ls->lo), hi = fmin(x2, ls->hi);
    if (!(hi > lo))
        return 0.0;
    int n = (int)ceil((hi - lo) / ls->h);
    n = n < 1 ? 1 : (n > HFS_LOBE_STEPS ? HFS_LOBE_STEPS : n);
    const double step = (hi - lo) / n, g = 0.5 * step / sqrt(3.0);
    double sum = 0.0;
    for (int k = 0; k < n; ++k) {
        const double mid = lo + (k + 0.5) * step;
        sum += lobe_integrand(ls, mid - g) + lobe_integrand(ls, mid + g);
    }
    return 0.5 * step * sum;
}
