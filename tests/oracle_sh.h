/*
 * oracle_sh.h — SPEC.md's SH table written out for the oracle tests
 * (test_sh_oracle.c, test_sh_glsl_gpu.c), independent of runtime/sh/:
 *   the 16 polynomials of SPEC's table with constants from the
 *   normalization formula (oracle_sh_init fills them; test_sh_oracle checks
 *   them against SPEC's printed 6 digits), and the
 *   exit radiance of an unoccluded receiver with normal n under a rotated
 *   SH environment by exact quadrature.
 * Everything is static inline: each test takes what it uses.
 */
#ifndef HFS_TEST_ORACLE_SH_H
#define HFS_TEST_ORACLE_SH_H

#include <math.h>
#include <stdlib.h>

#include "test_sh_util.h" /* ref_legendre, ref_gauss */

#define ORACLE_PI 3.14159265358979323846

/* k = l(l+1) + m */
static inline int oracle_band(int k) { return k < 1 ? 0 : k < 4 ? 1 : k < 9 ? 2 : 3; }
static inline int oracle_order(int k)
{
    const int l = oracle_band(k);
    return k - l * (l + 1);
}

/* SPEC.md's printed constants, as printed. */
static inline double oracle_spec_const(int k)
{
    static const double c[16] = {0.282095, 0.488603, 0.488603, 0.488603, 1.092548, 1.092548,
                                 0.315392, 1.092548, 0.546274, 0.590044, 2.890611, 0.457046,
                                 0.373176, 0.457046, 1.445306, 0.590044};
    return c[k];
}

/* The polynomial of each row of SPEC's table, constant stripped. */
static inline double oracle_spec_poly(int k, double x, double y, double z)
{
    switch (k) {
    case 0: return 1.0;
    case 1: return y;
    case 2: return z;
    case 3: return x;
    case 4: return x * y;
    case 5: return y * z;
    case 6: return 3 * z * z - 1;
    case 7: return x * z;
    case 8: return x * x - y * y;
    case 9: return y * (3 * x * x - y * y);
    case 10: return x * y * z;
    case 11: return y * (5 * z * z - 1);
    case 12: return z * (5 * z * z - 3);
    case 13: return x * (5 * z * z - 1);
    case 14: return z * (x * x - y * y);
    default: return x * (x * x - 3 * y * y);
    }
}

/* The exact constant of row k: real SH without Condon-Shortley phase,
 *   y_lm = sqrt(2) N_lm P_l^|m|(z) trig(|m| phi)  (m != 0),  N_l0 P_l(z),
 *   N_lm = sqrt((2l+1)/(4 pi) (l-|m|)!/(l+|m|)!),
 * with P_1^1 = rho, P_2^0 = (3z^2-1)/2, P_2^1 = 3 z rho, P_2^2 = 3 rho^2,
 * P_3^0 = z(5z^2-3)/2, P_3^1 = 3/2 (5z^2-1) rho, P_3^2 = 15 z rho^2,
 * P_3^3 = 15 rho^3, and rho^|m| trig(|m| phi) rewritten in x, y as in the
 * table: xy = rho^2 sin(2 phi)/2 (rows 4, 10: a factor 2), x^2-y^2 = rho^2
 * cos(2 phi), y(3x^2-y^2) = rho^3 sin(3 phi), x(x^2-3y^2) = rho^3 cos(3 phi). */
static inline double oracle_exact_const(int k)
{
    static const double pfac[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {0.5, 3, 3, 0}, {0.5, 1.5, 15, 15}};
    const int l = oracle_band(k), m = abs(oracle_order(k));
    double fac_ratio = 1.0; /* (l-m)!/(l+m)! */
    for (int i = l - m + 1; i <= l + m; ++i)
        fac_ratio /= i;
    double n = sqrt((2 * l + 1) / (4 * ORACLE_PI) * fac_ratio);
    if (m != 0)
        n *= sqrt(2.0);
    double c = n * pfac[l][m];
    if (k == 4 || k == 10)
        c *= 2.0;
    return c;
}

static inline void oracle_y(double x, double y, double z, double out[16])
{
    for (int k = 0; k < 16; ++k)
        out[k] = oracle_exact_const(k) * oracle_spec_poly(k, x, y, z);
}

static inline double oracle_f(const double c[16], double x, double y, double z)
{
    double b[16], s = 0.0;
    oracle_y(x, y, z, b);
    for (int k = 0; k < 16; ++k)
        s += c[k] * b[k];
    return s;
}

/* Lo = (1/pi) integral over the hemisphere about unit n of L(R_z(-a) s) (n.s),
 * L = sum c_k y_k (SPEC: the environment rotated about +z by a): u = n.s by
 * Gauss (8 nodes), the azimuth about n uniform (16): exact for the cubic L
 * (odd powers of sqrt(1 - u^2) integrate to zero over the azimuth). */
static inline double oracle_lo_unoccluded(const double c[16], double a, const double n[3])
{
    double t1[3], t2[3];
    const double h[3] = {fabs(n[0]) < 0.9 ? 1.0 : 0.0, fabs(n[0]) < 0.9 ? 0.0 : 1.0, 0.0};
    const double dp = h[0] * n[0] + h[1] * n[1] + h[2] * n[2];
    double l = 0;
    for (int i = 0; i < 3; ++i)
        t1[i] = h[i] - dp * n[i], l += t1[i] * t1[i];
    for (int i = 0; i < 3; ++i)
        t1[i] /= sqrt(l);
    t2[0] = n[1] * t1[2] - n[2] * t1[1];
    t2[1] = n[2] * t1[0] - n[0] * t1[2];
    t2[2] = n[0] * t1[1] - n[1] * t1[0];
    double ux[8], uw[8], sum = 0.0;
    ref_gauss(8, 0, 1, ux, uw);
    const double ca = cos(a), sa = sin(a);
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 16; ++j) {
            const double p = 2 * ORACLE_PI * (j + 0.5) / 16, q = sqrt(1 - ux[i] * ux[i]);
            double s[3];
            for (int k = 0; k < 3; ++k)
                s[k] = q * (cos(p) * t1[k] + sin(p) * t2[k]) + ux[i] * n[k];
            sum += uw[i] * (2 * ORACLE_PI / 16) * ux[i] *
                   oracle_f(c, ca * s[0] + sa * s[1], -sa * s[0] + ca * s[1], s[2]);
        }
    return sum / ORACLE_PI;
}

/* The tilted-plane scene of the env-rotate checks: heights z = gx i + gy j
 * (exact in float), normal n, an environment of 1 plus a strong band 1-2
 * lobe at elevation 0.4 a quarter turn clockwise of the normal's azimuth, so
 * that a rotation by +a ~ pi/2 turns it toward the receiver and -a away. */
#define ORACLE_PLANE_GX 0.5
#define ORACLE_PLANE_GY (-0.25)
static inline void oracle_plane(float *z, int w, int h, double n[3], double c[16])
{
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            z[j * w + i] = (float)(ORACLE_PLANE_GX * i + ORACLE_PLANE_GY * j);
    n[0] = -ORACLE_PLANE_GX, n[1] = -ORACLE_PLANE_GY, n[2] = 1.0;
    const double nl = sqrt(n[0] * n[0] + n[1] * n[1] + 1.0);
    for (int i = 0; i < 3; ++i)
        n[i] /= nl;
    const double phil = atan2(n[1], n[0]) - ORACLE_PI / 2;
    double lobe[16];
    oracle_y(cos(phil) * cos(0.4), sin(phil) * cos(0.4), sin(0.4), lobe);
    for (int k = 0; k < 16; ++k)
        c[k] = k >= 1 && k < 9 ? 2.5 * lobe[k] : 0.0;
    c[0] = sqrt(4 * ORACLE_PI);
}

#endif /* HFS_TEST_ORACLE_SH_H */
