/*
 * slice_light.c — see slice_light.h.
 */
#include "slice_light.h"

#include <math.h>
#include <stdlib.h>

#define PI 3.14159265358979323846
#define DEG 5                  /* products have degree <= 5 */
#define NB (1 + 2 * DEG)       /* basis 1, cos ke, sin ke (k = 1..5) */

/* A trigonometric polynomial: c[0] + sum_k c[2k-1] cos ke + c[2k] sin ke. */
typedef struct trig {
    double c[NB];
} trig;

/* r += coef * (is_sin ? sin : cos)(f e), f of either sign. */
static void trig_add(trig *r, int is_sin, int f, double coef)
{
    if (is_sin) {
        if (f == 0)
            return;
        if (f < 0) {
            f = -f;
            coef = -coef;
        }
        if (f <= DEG)
            r->c[2 * f] += coef;
        return;
    }
    f = f < 0 ? -f : f;
    if (f <= DEG)
        r->c[f ? 2 * f - 1 : 0] += coef;
}

/* Term index t: 0 the constant, 2k-1 cos ke, 2k sin ke. */
static int term_freq(int t)
{
    return (t + 1) / 2;
}

static trig trig_product(const trig *u, const trig *v)
{
    trig r = {{0}};
    for (int i = 0; i < NB; ++i)
        for (int k = 0; k < NB; ++k) {
            const double p = u->c[i] * v->c[k];
            if (p == 0.0)
                continue;
            const int fi = term_freq(i), fk = term_freq(k);
            const int si = i > 0 && i % 2 == 0, sk = k > 0 && k % 2 == 0;
            if (!si && !sk) { /* cos cos */
                trig_add(&r, 0, fi + fk, 0.5 * p);
                trig_add(&r, 0, fi - fk, 0.5 * p);
            } else if (si && sk) { /* sin sin */
                trig_add(&r, 0, fi - fk, 0.5 * p);
                trig_add(&r, 0, fi + fk, -0.5 * p);
            } else if (si) { /* sin(fi) cos(fk) */
                trig_add(&r, 1, fi + fk, 0.5 * p);
                trig_add(&r, 1, fi - fk, 0.5 * p);
            } else { /* cos(fi) sin(fk) */
                trig_add(&r, 1, fi + fk, 0.5 * p);
                trig_add(&r, 1, fk - fi, 0.5 * p);
            }
        }
    return r;
}

/* Coefficients of f_m(e) cos^2 e (A) and f_m(e) sin e cos e (B). */
static trig basis_a[HFS_SLICE_F], basis_b[HFS_SLICE_F];
static int basis_ready; /* written once, idempotently: same values each time */

static void basis_init(void)
{
    if (basis_ready)
        return;
    const trig cos2 = {{0.5, 0, 0, 0.5}};   /* (1 + cos 2e) / 2 */
    const trig sincos = {{0, 0, 0, 0, 0.5}}; /* sin 2e / 2 */
    for (int m = 0; m < HFS_SLICE_F; ++m) {
        trig f = {{0}};
        f.c[m] = 1.0; /* f_m: index m is 1, cos e, sin e, cos 2e, ... */
        basis_a[m] = trig_product(&f, &cos2);
        basis_b[m] = trig_product(&f, &sincos);
    }
    basis_ready = 1;
}

/* J_i(x) = Int_x^{pi/2} (1, cos ke, sin ke) de. */
static void integrals_from(double x, double J[NB])
{
    J[0] = 0.5 * PI - x;
    for (int k = 1; k <= DEG; ++k) {
        const double ck = cos(k * x), sk = sin(k * x);
        const double c_top = cos(k * 0.5 * PI), s_top = sin(k * 0.5 * PI);
        J[2 * k - 1] = (s_top - sk) / k;
        J[2 * k] = (ck - c_top) / k;
    }
}

void hfs_slice_integrals(double a, double b, double x, double g[HFS_SLICE_F])
{
    basis_init();
    x = x < -0.5 * PI ? -0.5 * PI : (x > 0.5 * PI ? 0.5 * PI : x);
    double J[NB];
    integrals_from(x, J);
    for (int m = 0; m < HFS_SLICE_F; ++m) {
        double ga = 0.0, gb = 0.0;
        for (int i = 0; i < NB; ++i) {
            ga += basis_a[m].c[i] * J[i];
            gb += basis_b[m].c[i] * J[i];
        }
        g[m] = a * ga + b * gb;
    }
}

int hfs_slice_table_init(hfs_slice_table *t, const hfs_swath *s, hfs_error *err)
{
    basis_init();
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
        /* Exact DFT of a degree-3 trigonometric polynomial: 8 samples. */
        double y[8][HFS_SH_N];
        for (int q = 0; q < 8; ++q) {
            const double e = 2.0 * PI * q / 8.0;
            hfs_sh_eval(cos(e) * c, cos(e) * sn, sin(e), y[q]);
        }
        double *p = t->p + (size_t)j * HFS_SH_N * HFS_SLICE_F;
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
    return HFS_OK;
}

void hfs_slice_table_free(hfs_slice_table *t)
{
    free(t->p);
    free(t->dir);
    t->p = NULL;
    t->dir = NULL;
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
