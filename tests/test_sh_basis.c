/*
 * test_sh_basis.c — the SH basis against SPEC.md and against brute-force
 * integration over the sphere: table constants, orthonormality, the
 * separable form, eval_dir, the y -> -y mirror, and the Gauss-Legendre rule.
 */
#include "sh.h"
#include "test_sh_util.h"

static double max_abs_diff(const double *a, const double *b, int n)
{
    double m = 0.0;
    for (int i = 0; i < n; ++i)
        m = ref_max(m, fabs(a[i] - b[i]));
    return m;
}

int main(void)
{
    int fails = 0;
    ref_rng rng = {0x9e3779b97f4a7c15ull};

    /* SPEC's printed 6-digit constants, in table order. */
    static const double spec6[16] = {0.282095, 0.488603, 0.488603, 0.488603,
                                     1.092548, 1.092548, 0.315392, 1.092548,
                                     0.546274, 0.590044, 2.890611, 0.457046,
                                     0.373176, 0.457046, 1.445306, 0.590044};
    /* Polynomial part of each row of the table (constant stripped). */
    double err_spec = 0.0, err_exact = 0.0;
    for (int s = 0; s < 2000; ++s) {
        const double z = ref_uniform(&rng, -1, 1), ph = ref_uniform(&rng, 0, 2 * T_PI);
        const double r = sqrt(1 - z * z), x = r * cos(ph), y = r * sin(ph);
        const double poly[16] = {1, y, z, x, x * y, y * z, 3 * z * z - 1, x * z,
                                 x * x - y * y, y * (3 * x * x - y * y), x * y * z,
                                 y * (5 * z * z - 1), z * (5 * z * z - 3),
                                 x * (5 * z * z - 1), z * (x * x - y * y),
                                 x * (x * x - 3 * y * y)};
        double lib[16], ref[16];
        hfs_sh_eval(x, y, z, lib);
        ref_y(x, y, z, ref);
        for (int k = 0; k < 16; ++k) {
            /* 6-digit rounding: |const - spec6| <= 5e-7 times |poly| <= 3.1 */
            const double e = fabs(lib[k] - spec6[k] * poly[k]);
            err_spec = ref_max(err_spec, e);
        }
        const double e2 = max_abs_diff(lib, ref, 16);
        err_exact = ref_max(err_exact, e2);
    }
    ref_check(&fails, "hfs_sh_eval vs SPEC table (6-digit constants)", err_spec, 1.6e-6);
    ref_check(&fails, "hfs_sh_eval vs SPEC table (exact constants)", err_exact, 1e-14);

    /* No Condon-Shortley phase: +y, +x, cos/sin orientation are positive. */
    {
        double y[16];
        hfs_sh_eval(0, 1, 0, y);
        double e = (y[1] > 0 ? 0 : 1) + (y[3] == 0 ? 0 : 1) + (y[8] < 0 ? 0 : 1);
        hfs_sh_eval(1, 0, 0, y);
        e += (y[3] > 0 ? 0 : 1) + (y[13] < 0 ? 0 : 1) + (y[15] > 0 ? 0 : 1);
        ref_check(&fails, "signs at +x, +y (no Condon-Shortley phase)", e, 0);
    }

    /* Orthonormality by Gauss in z (exact for the degree-6 products) and a
     * uniform rule in phi (exact for trigonometric degree < 24). */
    {
        enum { NZ = 16, NP = 24 };
        double zx[NZ], zw[NZ], G[16][16] = {{0}};
        ref_gauss(NZ, -1, 1, zx, zw);
        for (int a = 0; a < NZ; ++a)
            for (int b = 0; b < NP; ++b) {
                const double ph = 2 * T_PI * (b + 0.5) / NP, r = sqrt(1 - zx[a] * zx[a]);
                double y[16];
                hfs_sh_eval(r * cos(ph), r * sin(ph), zx[a], y);
                for (int i = 0; i < 16; ++i)
                    for (int j = 0; j < 16; ++j)
                        G[i][j] += zw[a] * (2 * T_PI / NP) * y[i] * y[j];
            }
        double e = 0.0;
        for (int i = 0; i < 16; ++i)
            for (int j = 0; j < 16; ++j)
                e = ref_max(e, fabs(G[i][j] - (i == j)));
        ref_check(&fails, "orthonormality integral y_i y_j = delta_ij", e, 1e-13);
    }

    /* eval_dir, separable form and band/order helpers. */
    {
        double e_dir = 0.0, e_sep = 0.0, e_lm = 0.0;
        for (int s = 0; s < 1000; ++s) {
            const double ph = ref_uniform(&rng, -7, 7), el = ref_uniform(&rng, -T_PI / 2, T_PI / 2);
            double a[16], b[16], ev[16], az[16];
            hfs_sh_eval_dir(ph, el, a);
            ref_y_dir(ph, el, b);
            e_dir = ref_max(e_dir, max_abs_diff(a, b, 16));
            hfs_sh_eval_elev(sin(el), cos(el), ev);
            hfs_sh_eval_azim(ph, az);
            for (int k = 0; k < 16; ++k)
                e_sep = ref_max(e_sep, fabs(ev[k] * az[k] - b[k]));
        }
        for (int l = 0; l < 4; ++l)
            for (int m = -l; m <= l; ++m)
                e_lm += (hfs_sh_band(l * (l + 1) + m) != l) + (hfs_sh_order(l * (l + 1) + m) != m);
        ref_check(&fails, "hfs_sh_eval_dir vs SPEC", e_dir, 1e-14);
        ref_check(&fails, "elev_k(e) * azim_k(phi) == y_k", e_sep, 1e-14);
        ref_check(&fails, "hfs_sh_band / hfs_sh_order", e_lm, 0);
    }

    /* Mirror y -> -y: mirrored coefficients at (x, y, z) equal the originals
     * at (x, -y, z); also in place. */
    {
        double e = 0.0;
        for (int s = 0; s < 200; ++s) {
            double c[16], m[16];
            for (int k = 0; k < 16; ++k)
                c[k] = ref_uniform(&rng, -1, 1);
            hfs_sh_mirror_y(c, m);
            const double z = ref_uniform(&rng, -1, 1), ph = ref_uniform(&rng, 0, 2 * T_PI);
            const double r = sqrt(1 - z * z), x = r * cos(ph), y = r * sin(ph);
            e = ref_max(e, fabs(ref_eval(m, x, y, z) - ref_eval(c, x, -y, z)));
            hfs_sh_mirror_y(c, c);
            e = ref_max(e, max_abs_diff(c, m, 16));
        }
        ref_check(&fails, "mirror_y: f'(x,y,z) = f(x,-y,z)", e, 1e-14);
    }

    /* Gauss-Legendre: integral_{-1}^{1} t^p dt exactly for p <= 2n-1. */
    {
        double e = 0.0;
        static const int ns[] = {1, 2, 5, 12, 32, 64};
        for (unsigned q = 0; q < sizeof ns / sizeof ns[0]; ++q) {
            const int n = ns[q];
            double x[64], w[64];
            if (hfs_gauss_legendre(n, x, w) != 0) {
                e = INFINITY;
                break;
            }
            for (int p = 0; p <= 2 * n - 1 && p <= 40; ++p) {
                double s = 0.0;
                for (int i = 0; i < n; ++i)
                    s += w[i] * pow(x[i], p);
                e = ref_max(e, fabs(s - (p % 2 ? 0.0 : 2.0 / (p + 1))));
            }
        }
        double x1, w1;
        e += (hfs_gauss_legendre(0, &x1, &w1) == -1) ? 0 : 1;
        ref_check(&fails, "hfs_gauss_legendre exact for degree <= 2n-1", e, 1e-14);
    }

    /* hfs_sh_negative_bound >= the true negative part (a dense grid's
     * minimum), equal to it for constant + band 1, 0 for a dominant c_0. */
    {
        double e = 0.0;
        for (int t = 0; t < 40; ++t) {
            double c[16];
            for (int k = 0; k < 16; ++k)
                c[k] = ref_uniform(&rng, -1, 1);
            c[0] = ref_uniform(&rng, -2, 8);
            double fmin = INFINITY;
            for (int r = 0; r <= 90; ++r)
                for (int a = 0; a < 180; ++a) {
                    double y[16];
                    const double el = T_PI / 2 - T_PI * r / 90.0, ph = 2 * T_PI * a / 180.0;
                    ref_y(cos(ph) * cos(el), sin(ph) * cos(el), sin(el), y);
                    double f = 0.0;
                    for (int k = 0; k < 16; ++k)
                        f += c[k] * y[k];
                    fmin = f < fmin ? f : fmin;
                }
            const double neg = fmin < 0 ? -fmin : 0.0, b = hfs_sh_negative_bound(c);
            e += b < neg - 1e-12 ? 1 : 0;
        }
        /* c_0 = 1, c_2 = 0.6 (f = 0.2821 + 0.2932 z): min -0.0111 at the nadir. */
        const double band1[16] = {1, 0, 0.6};
        e += fabs(hfs_sh_negative_bound(band1) - (0.6 * 0.4886025119029199 - 0.28209479177387814));
        const double sky[16] = {3.5449, 0.1, 0.4, 0.3};
        e += hfs_sh_negative_bound(sky);
        ref_check(&fails, "hfs_sh_negative_bound: a bound, exact for bands 0 + 1", e, 1e-12);
    }

    printf("%s\n", fails ? "FAILED" : "PASSED");
    return fails ? 1 : 0;
}
