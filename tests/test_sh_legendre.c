/*
 * test_sh_legendre.c — NS09 section 4: NLP basis orthonormality and its
 * relation to the zonal SH (eq. 9), the occlusion vector against NS09's
 * printed analytic order-4 form and against direct integration (eq. 10),
 * and visible bands (eq. 11) including empty and clamped bands.
 */
#include "sh.h"
#include "test_sh_util.h"

/* NS09's analytic occlusion vector, transcribed from the paper. */
static void ns09_occlusion(double s, double o[4])
{
    const double c2 = cos(s) * cos(s);
    o[0] = (sin(s) + 1) / sqrt(2.0);
    o[1] = -3 * c2 / (2 * sqrt(6.0));
    o[2] = -5 * sin(s) * c2 / (2 * sqrt(10.0));
    o[3] = 7 * c2 * (-4 + 5 * c2) / (8 * sqrt(14.0));
}

/* integral_{z0}^{z1} sqrt((2l+1)/2) P_l(z) dz by Gauss (exact). */
static double nlp_integral(int l, double z0, double z1)
{
    enum { N = 8 };
    double x[N], w[N], s = 0;
    ref_gauss(N, z0, z1, x, w);
    for (int i = 0; i < N; ++i)
        s += w[i] * sqrt((2 * l + 1) / 2.0) * ref_legendre(l, x[i]);
    return s;
}

int main(void)
{
    int fails = 0;
    ref_rng rng = {99};

    {   /* orthonormality on [-1, 1] and eq. 9 */
        enum { N = 10 };
        double x[N], w[N], G[4][4] = {{0}}, e9 = 0;
        ref_gauss(N, -1, 1, x, w);
        for (int i = 0; i < N; ++i) {
            double p[4], y[16];
            hfs_nlp_eval(x[i], p);
            for (int a = 0; a < 4; ++a)
                for (int b = 0; b < 4; ++b)
                    G[a][b] += w[i] * p[a] * p[b];
            ref_y(sqrt(1 - x[i] * x[i]), 0, x[i], y);
            for (int l = 0; l < 4; ++l)
                e9 = ref_max(e9, fabs(y[l * (l + 1)] - p[l] / sqrt(2 * T_PI)));
        }
        double e = 0;
        for (int a = 0; a < 4; ++a)
            for (int b = 0; b < 4; ++b)
                e = ref_max(e, fabs(G[a][b] - (a == b)));
        ref_check(&fails, "NLP orthonormality on [-1, 1]", e, 1e-14);
        ref_check(&fails, "NS09 eq. 9: y_l0 = P^_l / sqrt(2 pi)", e9, 1e-15);
    }

    {   /* occlusion: analytic form and direct integration */
        double ea = 0, ed = 0;
        for (int t = 0; t <= 400; ++t) {
            double s = -T_PI / 2 + T_PI * t / 400;
            if (t % 2)
                s = ref_uniform(&rng, -T_PI / 2, T_PI / 2);
            double o[4], r[4];
            hfs_nlp_occlusion(s, o);
            ns09_occlusion(s, r);
            for (int l = 0; l < 4; ++l) {
                ea = ref_max(ea, fabs(o[l] - r[l]));
                ed = ref_max(ed, fabs(o[l] - nlp_integral(l, -1, sin(s))));
            }
        }
        ref_check(&fails, "occlusion vs NS09 analytic order-4 form", ea, 1e-15);
        ref_check(&fails, "occlusion vs integral_{-1}^{sin sigma} P^(z) dz", ed, 1e-14);
        double o[4];
        hfs_nlp_occlusion(T_PI / 2, o);
        ref_check(&fails, "occlusion(pi/2) = (sqrt 2, 0, 0, 0)",
                  fabs(o[0] - sqrt(2.0)) + fabs(o[1]) + fabs(o[2]) + fabs(o[3]), 1e-15);
    }

    {   /* visible band (lo, hi] = integral_{sin lo}^{sin hi} P^ */
        double e = 0;
        for (int t = 0; t < 500; ++t) {
            double lo = ref_uniform(&rng, -2, 2), hi = ref_uniform(&rng, -2, 2);
            double v[4];
            hfs_nlp_visible_band(lo, hi, v);
            const double clo = lo < -T_PI / 2 ? -T_PI / 2 : lo > T_PI / 2 ? T_PI / 2 : lo;
            const double chi = hi < -T_PI / 2 ? -T_PI / 2 : hi > T_PI / 2 ? T_PI / 2 : hi;
            for (int l = 0; l < 4; ++l) {
                const double ref = clo < chi ? nlp_integral(l, sin(clo), sin(chi)) : 0.0;
                e = ref_max(e, fabs(v[l] - ref));
            }
        }
        ref_check(&fails, "visible band vs direct integration (clamped, empty)", e, 1e-14);
        /* the NLP-reconstructed band integrates to its true solid-angle share */
        double v[4];
        hfs_nlp_visible_band(0.2, 1.1, v);
        ref_check(&fails, "band mean: v_0 * sqrt(2) = sin hi - sin lo",
                  fabs(v[0] * sqrt(2.0) - (sin(1.1) - sin(0.2))), 1e-15);
    }

    printf("%s\n", fails ? "FAILED" : "PASSED");
    return fails ? 1 : 0;
}
