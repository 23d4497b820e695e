/*
 * sh.c — order-4 real SH basis (SPEC.md table, no Condon-Shortley phase),
 * equirect projection, z and zonal rotation, zonal vectors, mirror, and the
 * Gauss-Legendre rule the rest of the SH module integrates with.
 *
 * Invariants: index k = l(l+1)+m; m > 0 varies as cos(m phi), m < 0 as
 * sin(|m| phi); constants are the exact normalizations (SPEC rounds them to 6
 * digits).  No allocation, no global mutable state; everything is reentrant.
 */
#include "sh.h"

#include <math.h>
#include <stddef.h>

#define PI 3.14159265358979323846

/* Exact normalizations; the comment gives SPEC's rounded value. */
#define K00 0.28209479177387814  /* 1/(2 sqrt(pi))      0.282095 */
#define K1  0.4886025119029199   /* sqrt(3/(4pi))       0.488603 */
#define K2A 1.0925484305920792   /* sqrt(15/(4pi))      1.092548 */
#define K20 0.31539156525252005  /* sqrt(5/(16pi))      0.315392 */
#define K22 0.5462742152960396   /* sqrt(15/(16pi))     0.546274 */
#define K33 0.5900435899266435   /* sqrt(35/(32pi))     0.590044 */
#define K32 2.890611442640554    /* sqrt(105/(4pi))     2.890611 */
#define K31 0.4570457994644658   /* sqrt(21/(32pi))     0.457046 */
#define K30 0.3731763325901154   /* sqrt(7/(16pi))      0.373176 */
#define K32H 1.445305721320277   /* sqrt(105/(16pi))    1.445306 */

void hfs_sh_eval(double x, double y, double z, double out[HFS_SH_N])
{
    const double x2 = x * x, y2 = y * y, z2 = z * z;
    out[0] = K00;
    out[1] = K1 * y;
    out[2] = K1 * z;
    out[3] = K1 * x;
    out[4] = K2A * x * y;
    out[5] = K2A * y * z;
    out[6] = K20 * (3.0 * z2 - 1.0);
    out[7] = K2A * x * z;
    out[8] = K22 * (x2 - y2);
    out[9] = K33 * y * (3.0 * x2 - y2);
    out[10] = K32 * x * y * z;
    out[11] = K31 * y * (5.0 * z2 - 1.0);
    out[12] = K30 * z * (5.0 * z2 - 3.0);
    out[13] = K31 * x * (5.0 * z2 - 1.0);
    out[14] = K32H * z * (x2 - y2);
    out[15] = K33 * x * (x2 - 3.0 * y2);
}

void hfs_sh_eval_dir(double phi, double e, double out[HFS_SH_N])
{
    const double ce = cos(e);
    hfs_sh_eval(cos(phi) * ce, sin(phi) * ce, sin(e), out);
}

/* The SPEC polynomials rewritten with x = rho cos phi, y = rho sin phi:
 * xy = rho^2 sin(2phi)/2, x^2 - y^2 = rho^2 cos(2phi),
 * y(3x^2 - y^2) = rho^3 sin(3phi), x(x^2 - 3y^2) = rho^3 cos(3phi). */
void hfs_sh_eval_elev(double z, double rho, double out[HFS_SH_N])
{
    const double r2 = rho * rho, z2 = z * z;
    out[0] = K00;
    out[1] = K1 * rho;
    out[2] = K1 * z;
    out[3] = K1 * rho;
    out[4] = 0.5 * K2A * r2;
    out[5] = K2A * z * rho;
    out[6] = K20 * (3.0 * z2 - 1.0);
    out[7] = K2A * z * rho;
    out[8] = K22 * r2;
    out[9] = K33 * r2 * rho;
    out[10] = 0.5 * K32 * z * r2;
    out[11] = K31 * rho * (5.0 * z2 - 1.0);
    out[12] = K30 * z * (5.0 * z2 - 3.0);
    out[13] = K31 * rho * (5.0 * z2 - 1.0);
    out[14] = K32H * z * r2;
    out[15] = K33 * r2 * rho;
}

void hfs_sh_eval_azim(double phi, double out[HFS_SH_N])
{
    const double c1 = cos(phi), s1 = sin(phi);
    /* Chebyshev recurrence: one sin/cos pair instead of three. */
    const double c2 = 2.0 * c1 * c1 - 1.0, s2 = 2.0 * s1 * c1;
    const double c3 = c2 * c1 - s2 * s1, s3 = s2 * c1 + c2 * s1;
    out[0] = 1.0;
    out[1] = s1; out[2] = 1.0; out[3] = c1;
    out[4] = s2; out[5] = s1; out[6] = 1.0; out[7] = c1; out[8] = c2;
    out[9] = s3; out[10] = s2; out[11] = s1; out[12] = 1.0; out[13] = c1;
    out[14] = c2; out[15] = c3;
}

int hfs_gauss_legendre(int n, double *x, double *w)
{
    if (n < 1 || n > 256 || !x || !w)
        return -1;
    /* Newton on P_n from the Tricomi initial guess; nodes are symmetric, so
     * only half are solved and mirrored (keeps the rule exactly symmetric). */
    for (int i = 0; i < (n + 1) / 2; ++i) {
        double t = cos(PI * (i + 0.75) / (n + 0.5));
        double dp = 1.0;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1.0, p1 = t;
            for (int k = 2; k <= n; ++k) {
                const double p2 = ((2.0 * k - 1.0) * t * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (t * p1 - p0) / (t * t - 1.0);
            const double dt = p1 / dp;
            t -= dt;
            if (fabs(dt) < 1e-16)
                break;
        }
        /* Recompute the derivative at the converged node for the weight. */
        {
            double p0 = 1.0, p1 = t;
            for (int k = 2; k <= n; ++k) {
                const double p2 = ((2.0 * k - 1.0) * t * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (t * p1 - p0) / (t * t - 1.0);
        }
        const double wi = 2.0 / ((1.0 - t * t) * dp * dp);
        x[i] = -t;
        x[n - 1 - i] = t;
        w[i] = wi;
        w[n - 1 - i] = wi;
    }
    if (n % 2 == 1)
        x[n / 2] = 0.0;
    return 0;
}

/* Texel solid angle is exact (dphi * (sin e_top - sin e_bottom)); the basis is
 * sampled at the texel centre.  The basis is separable, so each row only
 * needs the 7 distinct azimuthal sums of its radiance, and the azimuthal
 * factors are tabulated per block of columns on the stack (no allocation). */
#define EQ_BLOCK 128
void hfs_sh_project_equirect(const float *rgb, int w, int h,
                             double out[3][HFS_SH_N])
{
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < HFS_SH_N; ++k)
            out[c][k] = 0.0;
    if (!rgb || w <= 0 || h <= 0)
        return;
    const double dphi = 2.0 * PI / w;
    /* Azimuthal function index per k: 0 = 1, 1..3 = cos m phi, 4..6 = sin. */
    static const int az_of_k[HFS_SH_N] = {0, 4, 0, 1, 5, 4, 0, 1, 2,
                                         6, 5, 4, 0, 1, 2, 3};
    double az[EQ_BLOCK][7];
    for (int i0 = 0; i0 < w; i0 += EQ_BLOCK) {
        const int nb = (w - i0 < EQ_BLOCK) ? w - i0 : EQ_BLOCK;
        for (int b = 0; b < nb; ++b) {
            const double phi = (i0 + b + 0.5) * dphi;
            const double c1 = cos(phi), s1 = sin(phi);
            az[b][0] = 1.0;
            az[b][1] = c1;
            az[b][2] = cos(2.0 * phi);
            az[b][3] = cos(3.0 * phi);
            az[b][4] = s1;
            az[b][5] = sin(2.0 * phi);
            az[b][6] = sin(3.0 * phi);
        }
        for (int j = 0; j < h; ++j) {
            const double e = 0.5 * PI - PI * (j + 0.5) / h;
            const double e_top = 0.5 * PI - PI * j / h;
            const double e_bot = 0.5 * PI - PI * (j + 1.0) / h;
            const double domega = dphi * (sin(e_top) - sin(e_bot));
            double sums[3][7] = {{0}};
            const float *row = rgb + ((size_t)j * (size_t)w + (size_t)i0) * 3;
            for (int b = 0; b < nb; ++b) {
                for (int c = 0; c < 3; ++c) {
                    const double v = row[b * 3 + c];
                    for (int q = 0; q < 7; ++q)
                        sums[c][q] += v * az[b][q];
                }
            }
            double el[HFS_SH_N];
            hfs_sh_eval_elev(sin(e), cos(e), el);
            for (int c = 0; c < 3; ++c)
                for (int k = 0; k < HFS_SH_N; ++k)
                    out[c][k] += el[k] * domega * sums[c][az_of_k[k]];
        }
    }
}

double hfs_sh_negative_bound(const double c[HFS_SH_N])
{
    /* sqrt((2l + 1) / (4 pi)), l = 0..3 */
    static const double w[HFS_ZH_N] = {0.28209479177387814, 0.4886025119029199,
                                       0.6307831305050401, 0.7463526651802308};
    double band[HFS_ZH_N] = {0.0, 0.0, 0.0, 0.0};
    for (int k = 1; k < HFS_SH_N; ++k)
        band[hfs_sh_band(k)] += c[k] * c[k];
    double b = -w[0] * c[0];
    for (int l = 1; l < HFS_ZH_N; ++l)
        b += w[l] * sqrt(band[l]);
    return b > 0.0 ? b : 0.0;
}

/* Per band, the (m, -m) pair is a 2D rotation of (cos m phi, sin m phi)
 * coefficients by m*angle (derivation: f(phi - a) expanded with the angle
 * sum identities).  Chebyshev recurrence: one sin/cos pair for m = 1..3. */
void hfs_sh_zrot_init(hfs_sh_zrot *r, double angle)
{
    const double c1 = cos(angle), s1 = sin(angle);
    const double c2 = 2.0 * c1 * c1 - 1.0, s2 = 2.0 * s1 * c1;
    r->c[0] = 1.0;
    r->s[0] = 0.0;
    r->c[1] = c1;
    r->s[1] = s1;
    r->c[2] = c2;
    r->s[2] = s2;
    r->c[3] = c2 * c1 - s2 * s1;
    r->s[3] = s2 * c1 + c2 * s1;
}

void hfs_sh_rotate_z_with(const hfs_sh_zrot *r, const double in[HFS_SH_N],
                          double out[HFS_SH_N])
{
    double t[HFS_SH_N];   /* copy: in may alias out */
    for (int k = 0; k < HFS_SH_N; ++k)
        t[k] = in[k];
    out[0] = t[0];
    for (int l = 1; l < 4; ++l) {
        const int c = l * (l + 1);
        out[c] = t[c];
        for (int m = 1; m <= l; ++m) {
            const double a = t[c + m], b = t[c - m];
            out[c + m] = a * r->c[m] - b * r->s[m];
            out[c - m] = a * r->s[m] + b * r->c[m];
        }
    }
}

void hfs_sh_rotate_z(const double in[HFS_SH_N], double angle,
                     double out[HFS_SH_N])
{
    hfs_sh_zrot r;
    hfs_sh_zrot_init(&r, angle);
    hfs_sh_rotate_z_with(&r, in, out);
}

void hfs_sh_rotate_zonal(const double zh[HFS_ZH_N], double dx, double dy,
                         double dz, double out[HFS_SH_N])
{
    double len = sqrt(dx * dx + dy * dy + dz * dz);
    if (!(len > 0.0)) {
        /* Degenerate axis: keep the zonal function in canonical +z. */
        dx = 0.0, dy = 0.0, dz = 1.0, len = 1.0;
    }
    double y[HFS_SH_N];
    hfs_sh_eval(dx / len, dy / len, dz / len, y);
    /* sqrt(4 pi / (2l + 1)) */
    static const double scale[HFS_ZH_N] = {
        3.5449077018110318, 2.046653415892977, 1.5853309190424043,
        1.3398491713813576};
    for (int k = 0; k < HFS_SH_N; ++k) {
        const int l = hfs_sh_band(k);
        out[k] = scale[l] * zh[l] * y[k];
    }
}

/* z_l = 2 pi sqrt((2l+1)/(4 pi)) integral_0^1 z P_l(z) dz, in closed form. */
void hfs_zh_clamped_cosine(double out[HFS_ZH_N])
{
    out[0] = 0.8862269254527579;  /* sqrt(pi)/2   */
    out[1] = 1.0233267079464885;   /* sqrt(pi/3)   */
    out[2] = 0.4954159122007514;  /* sqrt(5 pi)/8 */
    out[3] = 0.0;
}

/* z_l = 2 pi sqrt((2l+1)/(4 pi)) integral_{cos theta}^1 P_l(z) dz (thesis
 * A.1).  Written with sin^2 theta and 2 sin^2(theta/2) = 1 - cos theta so that
 * small caps keep full relative precision. */
void hfs_zh_cap(double theta, double out[HFS_ZH_N])
{
    if (!(theta > 0.0))
        theta = 0.0;
    if (theta > PI)
        theta = PI;
    const double c = cos(theta), s = sin(theta), s2 = s * s;
    const double h = sin(0.5 * theta);
    out[0] = 1.7724538509055159 * 2.0 * h * h;                /* sqrt(pi)     */
    out[1] = 0.5 * 3.0699801238394655 * s2;                   /* sqrt(3 pi)   */
    out[2] = 0.5 * 3.963327297606011 * c * s2;               /* sqrt(5 pi)   */
    out[3] = 0.125 * 4.689472099834751 * s2 * (5.0 * c * c - 1.0); /* sqrt(7 pi) */
}

void hfs_sh_mirror_y(const double in[HFS_SH_N], double out[HFS_SH_N])
{
    for (int k = 0; k < HFS_SH_N; ++k)
        out[k] = hfs_sh_order(k) < 0 ? -in[k] : in[k];
}
