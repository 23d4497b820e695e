/*
 * test_sh_product.c — the sparse triple-product tensor: every one of the
 * 16^3 entries (zeros included) against brute-force quadrature, and
 * hfs_sh_product against the brute-force projection of f*g; prints the
 * nonzero count and the cost of one product.
 */
#include "sh.h"
#include "test_sh_util.h"

#include <stdlib.h>

enum { NZ = 12, NP = 24 };   /* exact for the degree-9 integrands */

int main(void)
{
    int fails = 0;
    ref_rng rng = {777};
    static double bf[16][16][16];
    double zx[NZ], zw[NZ];
    ref_gauss(NZ, -1, 1, zx, zw);
    for (int a = 0; a < NZ; ++a)
        for (int b = 0; b < NP; ++b) {
            const double ph = 2 * T_PI * (b + 0.5) / NP, q = sqrt(1 - zx[a] * zx[a]);
            const double w = zw[a] * 2 * T_PI / NP;
            double y[16];
            ref_y(q * cos(ph), q * sin(ph), zx[a], y);
            for (int i = 0; i < 16; ++i)
                for (int j = 0; j < 16; ++j)
                    for (int k = 0; k < 16; ++k)
                        bf[i][j][k] += w * y[i] * y[j] * y[k];
        }

    /* Rebuild the full tensor from the entry list via its symmetry. */
    static double lib[16][16][16];
    const int nnz = hfs_sh_product_nonzeros();
    int bad_entry = 0;
    for (int n = 0; n < nnz; ++n) {
        int i, j, k;
        double c;
        if (hfs_sh_product_entry(n, &i, &j, &k, &c) != 0 || i > j || k < 0 || k > 15) {
            bad_entry = 1;
            continue;
        }
        const int p[6][3] = {{i, j, k}, {j, i, k}, {i, k, j},
                             {k, i, j}, {j, k, i}, {k, j, i}};
        for (int s = 0; s < 6; ++s)
            lib[p[s][0]][p[s][1]][p[s][2]] = c;
    }
    bad_entry += hfs_sh_product_entry(nnz, 0, 0, 0, 0) != -1;
    double e = 0;
    int full = 0, terms = 0;
    for (int i = 0; i < 16; ++i)
        for (int j = 0; j < 16; ++j)
            for (int k = 0; k < 16; ++k) {
                e = ref_max(e, fabs(lib[i][j][k] - bf[i][j][k]));
                if (fabs(bf[i][j][k]) > 1e-12) {
                    ++full;
                    terms += i <= j;
                }
            }
    ref_check(&fails, "all 4096 tensor entries C_ijk vs brute force", e, 1e-14);
    ref_check(&fails, "entry list well-formed", bad_entry, 0);
    printf("     nonzero C_ijk: %d of 4096; product terms (i <= j): %d (library: %d)\n",
           full, terms, nnz);
    ref_check(&fails, "nonzero count matches brute force", abs(terms - nnz), 0);

    /* Product of random functions: brute-force projection of f * g. */
    double ep = 0;
    for (int t = 0; t < 50; ++t) {
        double fa[16], fb[16], out[16], ref[16] = {0};
        for (int k = 0; k < 16; ++k) {
            fa[k] = ref_uniform(&rng, -1, 1);
            fb[k] = ref_uniform(&rng, -1, 1);
        }
        hfs_sh_product(fa, fb, out);
        for (int a = 0; a < NZ; ++a)
            for (int b = 0; b < NP; ++b) {
                const double ph = 2 * T_PI * (b + 0.5) / NP, q = sqrt(1 - zx[a] * zx[a]);
                const double s[3] = {q * cos(ph), q * sin(ph), zx[a]};
                const double w = zw[a] * 2 * T_PI / NP;
                const double fg = ref_eval(fa, s[0], s[1], s[2]) * ref_eval(fb, s[0], s[1], s[2]);
                double y[16];
                ref_y(s[0], s[1], s[2], y);
                for (int k = 0; k < 16; ++k)
                    ref[k] += w * fg * y[k];
            }
        for (int k = 0; k < 16; ++k)
            ep = ref_max(ep, fabs(out[k] - ref[k]));
    }
    ref_check(&fails, "hfs_sh_product vs brute-force projection of f*g", ep, 1e-13);

    /* Cost on the hot path. */
    {
        double fa[16], fb[16], out[16], acc = 0;
        for (int k = 0; k < 16; ++k)
            fa[k] = ref_uniform(&rng, -1, 1), fb[k] = ref_uniform(&rng, -1, 1);
        const int reps = 50000;
        const double t0 = ref_now();
        for (int r = 0; r < reps; ++r) {
            fa[r & 15] += 1e-9;
            hfs_sh_product(fa, fb, out);
            acc += out[r & 15];
        }
        const double dt = ref_now() - t0;
        double fz[16] = {0};
        fz[0] = 1;
        hfs_sh_rotate_z(fa, 0.1, out);
        const double t1 = ref_now();
        for (int r = 0; r < reps; ++r) {
            hfs_sh_rotate_z(fa, 1e-6 * r, out);
            acc += out[r & 15];
        }
        const double dt2 = ref_now() - t1;
        printf("     timing: hfs_sh_product %.1f ns, hfs_sh_rotate_z %.1f ns (checksum %g)\n",
               1e9 * dt / reps, 1e9 * dt2 / reps, acc + fz[0]);
    }

    printf("%s\n", fails ? "FAILED" : "PASSED");
    return fails ? 1 : 0;
}
