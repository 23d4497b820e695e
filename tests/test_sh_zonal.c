/*
 * test_sh_zonal.c — zonal vectors: the clamped cosine against SPEC.md and
 * against brute-force integration, and the cap indicator (thesis A.1)
 * against brute force for half-angles from 0 to pi, plus the irradiance a
 * rotated clamped cosine gives (pi for the full sphere).
 */
#include "sh.h"
#include "test_sh_util.h"

/* 2 pi integral_{z0}^{z1} f(z) sqrt((2l+1)/4pi) P_l(z) dz by Gauss-Legendre
 * (exact: polynomial integrands). */
static double zonal_integral(int l, double z0, double z1, int times_z)
{
    enum { N = 12 };
    double x[N], w[N], s = 0;
    ref_gauss(N, z0, z1, x, w);
    for (int i = 0; i < N; ++i)
        s += w[i] * (times_z ? x[i] : 1.0) * ref_legendre(l, x[i]);
    return 2 * T_PI * sqrt((2 * l + 1) / (4 * T_PI)) * s;
}

int main(void)
{
    int fails = 0;
    double cc[4];
    hfs_zh_clamped_cosine(cc);
    {
        static const double spec[4] = {0.886227, 1.023328, 0.495416, 0};
        double e = 0, eb = 0;
        for (int l = 0; l < 4; ++l) {
            e = ref_max(e, fabs(cc[l] - spec[l]));
            eb = ref_max(eb, fabs(cc[l] - zonal_integral(l, 0, 1, 1)));
        }
        /* SPEC (after NS09's 1.02333) prints 1.023328 for sqrt(pi/3) =
         * 1.02332671, a last-digit slip of 1.3e-6; the other three are
         * correctly rounded. */
        ref_check(&fails, "clamped cosine vs SPEC {0.886227, 1.023328, 0.495416, 0}", e, 1.5e-6);
        ref_check(&fails, "clamped cosine vs brute force", eb, 1e-14);
    }

    /* Cap of half-angle theta: 2 pi integral_{cos theta}^{1} y_l0.  Small
     * caps are also checked relative to their size (band 0 ~ theta^2). */
    {
        static const double th[] = {0, 1e-8, 1e-4, 0.01, 0.3, 1.0, T_PI / 2,
                                    2.0, 3.0, T_PI - 1e-4, T_PI};
        double e = 0, erel = 0;
        for (unsigned i = 0; i < sizeof th / sizeof th[0]; ++i) {
            double zh[4];
            hfs_zh_cap(th[i], zh);
            /* integrate over the smaller side to keep the reference exact */
            for (int l = 0; l < 4; ++l) {
                double ref;
                if (th[i] < T_PI / 2) {
                    /* 1 - cos theta = 2 sin^2(theta/2), without cancellation:
                     * substitute z = 1 - u over u in [0, 2 sin^2(theta/2)] */
                    const double umax = 2 * sin(th[i] / 2) * sin(th[i] / 2);
                    enum { N = 12 };
                    double x[N], w[N], s = 0;
                    ref_gauss(N, 0, umax, x, w);
                    for (int q = 0; q < N; ++q)
                        s += w[q] * ref_legendre(l, 1 - x[q]);
                    ref = 2 * T_PI * sqrt((2 * l + 1) / (4 * T_PI)) * s;
                } else {
                    ref = zonal_integral(l, cos(th[i]), 1, 0);
                }
                e = ref_max(e, fabs(zh[l] - ref));
                if (th[i] > 0 && th[i] < 0.5 && l < 3)
                    erel = ref_max(erel, fabs(zh[l] - ref) / fabs(ref));
            }
        }
        ref_check(&fails, "cap ZH vs brute force, theta in [0, pi]", e, 1e-14);
        ref_check(&fails, "cap ZH relative error, small caps (l < 3)", erel, 1e-12);
        double z0[4], zpi[4];
        hfs_zh_cap(0, z0);
        hfs_zh_cap(T_PI, zpi);
        const double eends = fabs(z0[0]) + fabs(z0[1]) + fabs(z0[2]) + fabs(z0[3]) +
                             fabs(zpi[0] - sqrt(4 * T_PI)) + fabs(zpi[1]) + fabs(zpi[2]) + fabs(zpi[3]);
        ref_check(&fails, "cap(0) = 0, cap(pi) = sphere (sqrt(4 pi), 0, 0, 0)", eends, 1e-15);
    }

    /* Consistency with shading: clamped cosine rotated to N, dotted with a
     * uniform sky sqrt(4 pi), is the irradiance pi. */
    {
        double h[16], sky[16] = {0};
        sky[0] = sqrt(4 * T_PI);
        hfs_sh_rotate_zonal(cc, 0.3, -0.5, 0.8, h);
        ref_check(&fails, "uniform sky irradiance through rotated clamped cosine",
                  fabs(hfs_sh_dot(h, sky) - T_PI), 1e-14);
    }

    printf("%s\n", fails ? "FAILED" : "PASSED");
    return fails ? 1 : 0;
}
