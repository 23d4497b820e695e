/*
 * test_slice_light.c — exact per-slice lighting (runtime/core/slice_light.h,
 * issue 15) against independent computations:
 *   integrals  the 7 slice integrals against 64-point Gauss-Legendre
 *              quadrature of the integrand, over random normals and horizons
 *              (including below the horizontal);
 *   table      Y_k(w(e)) equals sum_m P_km f_m(e) at random elevations (the
 *              8-point DFT is exact for degree 3);
 *   flat       an open flat plane under L = 1: (1/pi) T . L = 1 at 16 slices;
 *   open       an unoccluded tilted receiver: T tends to the SH projection of
 *              its clamped cosine (hfs_sh_rotate_zonal of the clamped cosine)
 *              as the slices get finer;
 *   shadow     a receiver under a uniform horizon at elevation x0 on a flat
 *              plane: E = pi cos^2 x0 (the closed form of the cap) under
 *              L = 1;
 *   lobe       hfs_lobe_slice_band (the glossy bounces' band weights)
 *              against a fine midpoint rule, exponents 1 to 10000.
 */
#include "slice_light.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"

#define PI 3.14159265358979323846
#define LOBE_TOL 1e-3 /* measured 1.7e-4 */

static double frand(unsigned *s)
{
    *s = *s * 1103515245u + 12345u;
    return (double)((*s >> 8) & 0xffffff) / 16777216.0;
}

static double f_m(int m, double e)
{
    if (m == 0)
        return 1.0;
    const int k = (m + 1) / 2;
    return m % 2 ? cos(k * e) : sin(k * e);
}

static void full_swath(int n, hfs_swath *s)
{
    hfs_swath_full(n, s);
}

/* The factored form the GLES path contracts (slice_light.h
 * hfs_slice_profile): every slice's P_km(phi_j) is trig_k(phi_j) a[k][m],
 * and a has no term outside the slots env_slices.frag accumulates for k's
 * azimuthal factor (uniform_blocks.h: |m| 0 and 2: f 0, 2, 3, 6; |m| 1:
 * f 1, 4, 5; |m| 3: f 1, 5). */
static void check_profile(void)
{
    static const int slots[4][HFS_SLICE_F] = {{1, 0, 1, 1, 0, 0, 1}, {0, 1, 0, 0, 1, 1, 0},
                                              {1, 0, 1, 1, 0, 0, 1}, {0, 1, 0, 0, 0, 1, 0}};
    double a[HFS_SH_N][HFS_SLICE_F];
    hfs_slice_profile(a);
    double worst = 0.0, outside = 0.0;
    for (int n = 3; n <= 37; n += 17) {
        hfs_swath sw;
        hfs_slice_table t;
        hfs_error err;
        full_swath(n, &sw);
        if (hfs_slice_table_init(&t, &sw, &err)) {
            CHECK(0, "slice table: %s", err.msg);
            return;
        }
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < HFS_SH_N; ++k)
                for (int m = 0; m < HFS_SLICE_F; ++m) {
                    const double p = t.p[((size_t)j * HFS_SH_N + k) * HFS_SLICE_F + m];
                    const double f = hfs_slice_trig(k, hfs_swath_phi(&sw, j)) * a[k][m];
                    worst = fmax(worst, fabs(p - f));
                }
        hfs_slice_table_free(&t);
    }
    for (int k = 0; k < HFS_SH_N; ++k)
        for (int m = 0; m < HFS_SLICE_F; ++m)
            if (!slots[abs(hfs_slice_order(k))][m])
                outside = fmax(outside, fabs(a[k][m]));
    printf("profile: max |P - trig a| %.3e, largest term outside the slots %.3e\n", worst,
           outside);
    CHECK(worst < 1e-14, "P_km(phi_j) != trig_k a_km: %.3e", worst);
    CHECK(outside < 1e-15, "a profile term outside the shader's slots: %.3e", outside);
}

/* hfs_lobe_slice_band against a 20000-point midpoint rule of the same
 * integrand over the whole band, for random R, N, slices, exponents 1 to
 * 10000 and bands; the largest error relative to the band's lobe peak
 * times its width (the scale of the value). */
static void check_lobe(void)
{
    unsigned seed = 777;
    double worst = 0.0;
    for (int trial = 0; trial < 400; ++trial) {
        double r[3], n[3] = {0.3 * (frand(&seed) - 0.5), 0.3 * (frand(&seed) - 0.5), 1.0};
        const double th = 0.5 * PI * frand(&seed), ph = 2.0 * PI * frand(&seed);
        r[0] = sin(th) * cos(ph), r[1] = sin(th) * sin(ph), r[2] = cos(th);
        const double ln = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int k = 0; k < 3; ++k)
            n[k] /= ln;
        const double gloss = exp(log(10000.0) * frand(&seed));
        const double phi = 2.0 * PI * frand(&seed), c = cos(phi), s = sin(phi);
        double x1 = -0.5 * PI + PI * frand(&seed), x2 = -0.5 * PI + PI * frand(&seed);
        if (x1 > x2) {
            const double t = x1;
            x1 = x2, x2 = t;
        }
        hfs_lobe_slice ls;
        hfs_lobe_slice_init(&ls, r, n, c, s, gloss);
        const int m = 20000;
        double want = 0.0;
        for (int k = 0; k < m; ++k) {
            const double e = x1 + (x2 - x1) * (k + 0.5) / m;
            const double tr = (r[0] * c + r[1] * s) * cos(e) + r[2] * sin(e);
            const double tn = (n[0] * c + n[1] * s) * cos(e) + n[2] * sin(e);
            want += tr > 0.0 && tn > 0.0 ? pow(tr, gloss) * tn * cos(e) : 0.0;
        }
        want *= (x2 - x1) / m;
        /* The scale: the lobe's width along the slice, ~sqrt(2 / S). */
        const double scale = fmin(x2 - x1, sqrt(2.0 / gloss));
        worst = fmax(worst, fabs(hfs_lobe_slice_band(&ls, x1, x2) - want) / scale);
    }
    printf("lobe: worst |band - 20000-point quadrature| %.3e of the lobe's width\n", worst);
    CHECK(worst < LOBE_TOL, "lobe bands off by %.3e", worst);
}

int main(void)
{
    double gx[64], gw[64];
    if (hfs_gauss_legendre(64, gx, gw))
        return 1;
    unsigned seed = 12345;
    double worst = 0.0;
    for (int trial = 0; trial < 200; ++trial) {
        const double a = 2.0 * frand(&seed) - 1.0, b = 0.05 + frand(&seed);
        const double floor = atan2(-a, b);
        const double x = floor + (0.5 * PI - floor) * frand(&seed);
        double g[HFS_SLICE_F];
        hfs_slice_integrals(a, b, x, g);
        for (int m = 0; m < HFS_SLICE_F; ++m) {
            double q = 0.0;
            for (int i = 0; i < 64; ++i) {
                const double e = x + (0.5 * PI - x) * 0.5 * (gx[i] + 1.0);
                q += gw[i] * 0.5 * (0.5 * PI - x) * f_m(m, e) * (a * cos(e) + b * sin(e)) * cos(e);
            }
            const double d = fabs(q - g[m]);
            worst = d > worst ? d : worst;
        }
    }
    printf("integrals: worst |closed form - quadrature| %.3e\n", worst);
    CHECK(worst < 1e-13, "slice integrals off by %.3e", worst);

    hfs_swath sw;
    full_swath(24, &sw);
    hfs_slice_table t;
    hfs_error err;
    if (hfs_slice_table_init(&t, &sw, &err))
        return 1;
    worst = 0.0;
    for (int j = 0; j < t.n; ++j)
        for (int q = 0; q < 10; ++q) {
            const double e = 2.0 * PI * frand(&seed);
            double y[HFS_SH_N];
            hfs_sh_eval(cos(e) * t.dir[2 * j], cos(e) * t.dir[2 * j + 1], sin(e), y);
            for (int k = 0; k < HFS_SH_N; ++k) {
                double s = 0.0;
                for (int m = 0; m < HFS_SLICE_F; ++m)
                    s += t.p[((size_t)j * HFS_SH_N + k) * HFS_SLICE_F + m] * f_m(m, e);
                worst = fmax(worst, fabs(s - y[k]));
            }
        }
    printf("table: worst |sum P f - Y| %.3e\n", worst);
    CHECK(worst < 1e-13, "slice table off by %.3e", worst);
    hfs_slice_table_free(&t);

    /* L = 1: only Y_00 = 1 / (2 sqrt(pi)), coefficient 2 sqrt(pi). */
    const double l00 = 2.0 * sqrt(PI);
    full_swath(16, &sw);
    if (hfs_slice_table_init(&t, &sw, &err))
        return 1;
    double T[HFS_SH_N] = {0};
    const double up[3] = {0.0, 0.0, 1.0};
    for (int j = 0; j < t.n; ++j)
        hfs_slice_add(&t, j, up, 0.0, T);
    printf("flat: (1/pi) T . L = %.15f\n", T[0] * l00 / PI);
    CHECK(fabs(T[0] * l00 / PI - 1.0) < 1e-13, "open flat plane: %.15f", T[0] * l00 / PI);

    /* A uniform horizon at x0 on a flat plane: E = pi cos^2 x0. */
    for (int q = 0; q < 5; ++q) {
        const double x0 = 0.3 * q;
        double Tq[HFS_SH_N] = {0};
        for (int j = 0; j < t.n; ++j)
            hfs_slice_add(&t, j, up, x0, Tq);
        const double e = Tq[0] * l00, want = PI * cos(x0) * cos(x0);
        CHECK(fabs(e - want) < 1e-12, "horizon %.2f: E %.15f, want %.15f", x0, e, want);
    }
    hfs_slice_table_free(&t);

    /* Open tilted receiver: T -> H (the clamped cosine's SH about N). */
    const double n[3] = {0.48, -0.36, 0.8};
    double zc[HFS_ZH_N], H[HFS_SH_N];
    hfs_zh_clamped_cosine(zc);
    hfs_sh_rotate_zonal(zc, n[0], n[1], n[2], H);
    double prev = 1e9;
    for (int nphi = 16; nphi <= 1024; nphi *= 4) {
        full_swath(nphi, &sw);
        if (hfs_slice_table_init(&t, &sw, &err))
            return 1;
        double To[HFS_SH_N] = {0};
        for (int j = 0; j < t.n; ++j) {
            const double a = n[0] * t.dir[2 * j] + n[1] * t.dir[2 * j + 1];
            hfs_slice_add(&t, j, n, atan2(-a, n[2]), To);
        }
        double d = 0.0;
        for (int k = 0; k < HFS_SH_N; ++k)
            d = fmax(d, fabs(To[k] - H[k]));
        printf("open tilted, %4d slices: max |T - H| %.3e\n", nphi, d);
        CHECK(d < prev || d < 1e-14, "no convergence at %d slices: %.3e", nphi, d);
        prev = d;
        hfs_slice_table_free(&t);
    }
    CHECK(prev < 1e-12, "open tilted receiver, 1024 slices: %.3e from H", prev);
    check_profile();
    check_lobe();
    printf("slice light: %s\n", failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
