/*
 * test_sh_wedge.c — NS09 appendix A matrices.  For random NLP vectors and
 * several wedge extents, M_lin [w_j; w_{j+1}] and M_bspl [w_{j-1} .. w_{j+2}]
 * must equal the SH projection of the azimuthally blended elevation function
 * computed by brute-force 2D quadrature over the wedge.  Also: a full swath
 * of identical samples, rotated and summed, reproduces the zonal function.
 */
#include "sh.h"
#include "test_sh_util.h"

enum { NE = 40, NPAN = 8, NPN = 24 };

static void ref_nlp(double z, double p[4])
{
    for (int l = 0; l < 4; ++l)
        p[l] = sqrt((2 * l + 1) / 2.0) * ref_legendre(l, z);
}

static void ref_blend(int nq, double u, double *b)
{
    if (nq == 2) {
        b[0] = 1 - u;
        b[1] = u;
    } else {   /* SN08's cubic B-spline basis */
        b[0] = (1 - u) * (1 - u) * (1 - u) / 6;
        b[1] = (3 * u * u * u - 6 * u * u + 4) / 6;
        b[2] = (-3 * u * u * u + 3 * u * u + 3 * u + 1) / 6;
        b[3] = u * u * u / 6;
    }
}

/* Brute force: integral over [0, D] x [-pi/2, pi/2] of W y_r cos e. */
static void brute_wedge(double D, int nq, const double w[][4], double out[16])
{
    double ex[NE], ew[NE];
    ref_gauss(NE, -T_PI / 2, T_PI / 2, ex, ew);
    for (int k = 0; k < 16; ++k)
        out[k] = 0;
    for (int p = 0; p < NPAN; ++p) {
        double px[NPN], pw[NPN];
        ref_gauss(NPN, D * p / NPAN, D * (p + 1) / NPAN, px, pw);
        for (int i = 0; i < NPN; ++i) {
            double b[4];
            ref_blend(nq, px[i] / D, b);
            for (int j = 0; j < NE; ++j) {
                double P[4], y[16], W = 0;
                ref_nlp(sin(ex[j]), P);
                for (int q = 0; q < nq; ++q)
                    for (int l = 0; l < 4; ++l)
                        W += b[q] * w[q][l] * P[l];
                ref_y_dir(px[i], ex[j], y);
                for (int k = 0; k < 16; ++k)
                    out[k] += pw[i] * ew[j] * cos(ex[j]) * W * y[k];
            }
        }
    }
}

int main(void)
{
    int fails = 0;
    ref_rng rng = {2024};
    static const double dphis[] = {0.05, 2 * T_PI / 32, 0.5, 2 * T_PI / 3, 2 * T_PI};
    static const char *names[] = {"0.05", "2pi/32", "0.5", "2pi/3", "2pi"};

    for (int nqi = 0; nqi < 2; ++nqi) {
        const int nq = nqi ? 4 : 2;
        for (unsigned d = 0; d < sizeof dphis / sizeof dphis[0]; ++d) {
            double M[16 * 16];
            if (nq == 2)
                hfs_wedge_mlin(dphis[d], M);
            else
                hfs_wedge_mbspl(dphis[d], M);
            double e = 0, mag = 0;
            for (int t = 0; t < 6; ++t) {
                double w[4][4], lib[16], bf[16];
                for (int q = 0; q < nq; ++q) {
                    if (t == 0)   /* realistic: visible bands */
                        hfs_nlp_visible_band(ref_uniform(&rng, -1.5, 1.5), T_PI / 2, w[q]);
                    else
                        for (int l = 0; l < 4; ++l)
                            w[q][l] = ref_uniform(&rng, -1, 1);
                }
                for (int r = 0; r < 16; ++r) {
                    lib[r] = 0;
                    for (int q = 0; q < nq; ++q)
                        for (int l = 0; l < 4; ++l)
                            lib[r] += M[r * 4 * nq + 4 * q + l] * w[q][l];
                }
                brute_wedge(dphis[d], nq, (const double (*)[4])w, bf);
                for (int k = 0; k < 16; ++k) {
                    e = ref_max(e, fabs(lib[k] - bf[k]));
                    mag = ref_max(mag, fabs(bf[k]));
                }
            }
            char what[96];
            snprintf(what, sizeof what, "%s dphi=%-6s vs brute force (|coef| <= %.2f)",
                     nq == 2 ? "M_lin " : "M_bspl", names[d], mag);
            ref_check(&fails, what, e, 1e-13);
        }
    }

    {   /* out of domain: zeros */
        double M[16 * 8], s = 0;
        hfs_wedge_mlin(0.0, M);
        for (int i = 0; i < 16 * 8; ++i)
            s += fabs(M[i]);
        hfs_wedge_mlin(7.0, M);
        for (int i = 0; i < 16 * 8; ++i)
            s += fabs(M[i]);
        ref_check(&fails, "M_lin outside (0, 2pi] is zero", s, 0);
    }

    {   /* full swath: n wedges of identical samples, rotated and summed, give
         * the zonal function sqrt(2 pi) v_l in the m = 0 slots */
        const int n = 32;
        const double D = 2 * T_PI / n;
        double M[16 * 8];
        hfs_wedge_mlin(D, M);
        double e = 0;
        for (int t = 0; t < 5; ++t) {
            double v[4], V[16] = {0}, Vj[16], R[16];
            hfs_nlp_visible_band(t == 0 ? -T_PI / 2 : ref_uniform(&rng, -1.5, 1.5), T_PI / 2, v);
            for (int r = 0; r < 16; ++r) {
                Vj[r] = 0;
                for (int c = 0; c < 8; ++c)
                    Vj[r] += M[r * 8 + c] * v[c % 4];
            }
            for (int j = 0; j < n; ++j) {
                hfs_sh_rotate_z(Vj, j * D, R);
                for (int k = 0; k < 16; ++k)
                    V[k] += R[k];
            }
            for (int l = 0; l < 4; ++l)
                for (int m = -l; m <= l; ++m) {
                    const double ref = m == 0 ? sqrt(2 * T_PI) * v[l] : 0.0;
                    e = ref_max(e, fabs(V[l * (l + 1) + m] - ref));
                }
            if (t == 0)
                e = ref_max(e, fabs(V[0] - sqrt(4 * T_PI)));
        }
        ref_check(&fails, "32 rotated M_lin wedges = zonal sqrt(2pi) v (open sky: sqrt(4pi))", e, 1e-13);
    }

    {
        double M[16 * 32];
        const int reps = 2000;
        const double t0 = ref_now();
        for (int r = 0; r < reps; ++r)
            hfs_wedge_mbspl(0.1 + 1e-4 * r, M);
        const double t1 = ref_now();
        for (int r = 0; r < reps; ++r)
            hfs_wedge_mlin(0.1 + 1e-4 * r, M);
        const double t2 = ref_now();
        printf("     timing: hfs_wedge_mlin %.1f us, hfs_wedge_mbspl %.1f us\n",
               1e6 * (t2 - t1) / reps, 1e6 * (t1 - t0) / reps);
    }

    printf("%s\n", fails ? "FAILED" : "PASSED");
    return fails ? 1 : 0;
}
