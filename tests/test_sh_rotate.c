/*
 * test_sh_rotate.c — rotations: hfs_sh_rotate_z against point evaluation of
 * the original function at R_z(-angle) s, and the zonal rotation rule against
 * a brute-force projection of the rotated zonal function.
 */
#include "sh.h"
#include "test_sh_util.h"

int main(void)
{
    int fails = 0;
    ref_rng rng = {0x1234567ull};

    /* rotate_z: g(s) = f(R_z(-a) s); a feature at phi moves to phi + a. */
    {
        double e = 0.0, e_alias = 0.0;
        for (int t = 0; t < 300; ++t) {
            double c[16], r[16];
            for (int k = 0; k < 16; ++k)
                c[k] = ref_uniform(&rng, -1, 1);
            const double a = ref_uniform(&rng, -20, 20);
            hfs_sh_rotate_z(c, a, r);
            for (int s = 0; s < 20; ++s) {
                const double z = ref_uniform(&rng, -1, 1), ph = ref_uniform(&rng, 0, 2 * T_PI);
                const double q = sqrt(1 - z * z);
                const double g = ref_eval(r, q * cos(ph), q * sin(ph), z);
                const double f = ref_eval(c, q * cos(ph - a), q * sin(ph - a), z);
                e = ref_max(e, fabs(g - f));
            }
            double d[16];
            for (int k = 0; k < 16; ++k)
                d[k] = c[k];
            hfs_sh_rotate_z(d, a, d);   /* in == out */
            for (int k = 0; k < 16; ++k)
                e_alias = ref_max(e_alias, fabs(d[k] - r[k]));
        }
        ref_check(&fails, "rotate_z: rotated(s) = original(R_z(-a) s)", e, 1e-13);
        ref_check(&fails, "rotate_z in place", e_alias, 0);

        /* the precomputed form gives bit-identical results */
        double eq = 0;
        for (int t = 0; t < 50; ++t) {
            double c[16], r1[16], r2[16];
            for (int k = 0; k < 16; ++k)
                c[k] = ref_uniform(&rng, -1, 1);
            const double a = ref_uniform(&rng, -7, 7);
            hfs_sh_zrot zr;
            hfs_sh_zrot_init(&zr, a);
            hfs_sh_rotate_z(c, a, r1);
            hfs_sh_rotate_z_with(&zr, c, r2);
            for (int k = 0; k < 16; ++k)
                eq = ref_max(eq, fabs(r1[k] - r2[k]));
        }
        ref_check(&fails, "rotate_z_with(zrot_init(a)) == rotate_z(a)", eq, 0);

        /* Orientation spelled out: y_3 (= x) rotated by +pi/2 becomes y_1 (= y). */
        double c[16] = {0}, r[16];
        c[3] = 1;
        hfs_sh_rotate_z(c, T_PI / 2, r);
        double eo = fabs(r[1] - 1) + fabs(r[3]);
        ref_check(&fails, "rotate_z(+pi/2) maps x to y", eo, 1e-15);
    }

    /* Zonal rotation: f(s) = sum_l zh_l sqrt((2l+1)/4pi) P_l(d . s), projected
     * by Gauss in z x uniform in phi (exact for this polynomial). */
    {
        enum { NZ = 12, NP = 16 };
        double zx[NZ], zw[NZ];
        ref_gauss(NZ, -1, 1, zx, zw);
        double e = 0.0;
        for (int t = 0; t < 40; ++t) {
            double zh[4];
            for (int l = 0; l < 4; ++l)
                zh[l] = ref_uniform(&rng, -1, 1);
            double dz = ref_uniform(&rng, -1, 1), dp = ref_uniform(&rng, 0, 2 * T_PI);
            if (t == 0)
                dz = 1, dp = 0;           /* canonical axis */
            if (t == 1)
                dz = -1, dp = 0;          /* antipode */
            const double dq = sqrt(1 - dz * dz);
            const double d[3] = {dq * cos(dp), dq * sin(dp), dz};
            double lib[16], bf[16] = {0};
            /* a non-unit axis must give the same result */
            hfs_sh_rotate_zonal(zh, 3 * d[0], 3 * d[1], 3 * d[2], lib);
            for (int a = 0; a < NZ; ++a)
                for (int b = 0; b < NP; ++b) {
                    const double ph = 2 * T_PI * (b + 0.5) / NP, q = sqrt(1 - zx[a] * zx[a]);
                    const double s[3] = {q * cos(ph), q * sin(ph), zx[a]};
                    const double cd = s[0] * d[0] + s[1] * d[1] + s[2] * d[2];
                    double f = 0.0, y[16];
                    for (int l = 0; l < 4; ++l)
                        f += zh[l] * sqrt((2 * l + 1) / (4 * T_PI)) * ref_legendre(l, cd);
                    ref_y(s[0], s[1], s[2], y);
                    for (int k = 0; k < 16; ++k)
                        bf[k] += zw[a] * (2 * T_PI / NP) * f * y[k];
                }
            for (int k = 0; k < 16; ++k)
                e = ref_max(e, fabs(lib[k] - bf[k]));
        }
        ref_check(&fails, "rotate_zonal vs brute-force projection", e, 1e-13);
    }

    printf("%s\n", fails ? "FAILED" : "PASSED");
    return fails ? 1 : 0;
}
