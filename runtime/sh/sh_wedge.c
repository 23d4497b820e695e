/*
 * sh_wedge.c — NS09 appendix A: the matrices that take the NLP elevation
 * profiles at a wedge's azimuthal samples to the SH projection of the
 * azimuthally blended function over a wedge [0, dphi].
 *
 *   [M]_{r, 4q + c} = integral_0^dphi beta_q(phi/dphi) azim_r(phi) dphi
 *                   * integral_{-pi/2}^{pi/2} P^_c(sin e) elev_r(e) cos e de
 *
 * (y_r = elev_r * azim_r, sh.h).  The product form is exact because the
 * blend weights depend on phi only and the NLP functions on e only.  Both
 * factors are smooth and computed by Gauss-Legendre quadrature to double
 * precision (no closed forms, so small dphi has no cancellation).
 *
 * Layout (row-major): row r = SH index 0..15; column 4q + c, c = NLP index,
 * q = which azimuthal sample (lin: q=0 is w_j at phi=0, q=1 is w_{j+1} at
 * phi=dphi; bspl: q=0..3 are w_{j-1}, w_j, w_{j+1}, w_{j+2}).
 */
#include "sh.h"

#include <math.h>

#define PI 3.14159265358979323846

/* Elevation factor: the integrand is a trigonometric polynomial in e of
 * degree <= 7 over an interval of length pi, which 32 Gauss nodes integrate
 * to rounding error. */
#define ELEV_NODES 32
/* Azimuth: panels of length <= 1 rad with 12 nodes; the integrand is a cubic
 * times cos/sin(m phi), m <= 3, so a panel's phase span is <= 3 rad and the
 * rule's error is far below rounding. */
#define AZ_NODES 12

void hfs_wedge_elevation_moments(double E[HFS_SH_N * HFS_NLP_N])
{
    double x[ELEV_NODES], w[ELEV_NODES];
    hfs_gauss_legendre(ELEV_NODES, x, w);
    for (int i = 0; i < HFS_SH_N * HFS_NLP_N; ++i)
        E[i] = 0.0;
    for (int i = 0; i < ELEV_NODES; ++i) {
        const double e = 0.5 * PI * x[i];
        const double z = sin(e), rho = cos(e);
        const double wt = 0.5 * PI * w[i] * rho;
        double el[HFS_SH_N], p[HFS_NLP_N];
        hfs_sh_eval_elev(z, rho, el);
        hfs_nlp_eval(z, p);
        for (int r = 0; r < HFS_SH_N; ++r)
            for (int c = 0; c < HFS_NLP_N; ++c)
                E[r * HFS_NLP_N + c] += wt * el[r] * p[c];
    }
}

typedef void (*blend_fn)(double u, double *beta);

static void blend_lin(double u, double *beta)
{
    beta[0] = 1.0 - u;
    beta[1] = u;
}

/* Uniform cubic B-spline (SN08 section 4). */
static void blend_bspl(double u, double *beta)
{
    const double v = 1.0 - u, u2 = u * u, u3 = u2 * u;
    beta[0] = v * v * v / 6.0;
    beta[1] = (3.0 * u3 - 6.0 * u2 + 4.0) / 6.0;
    beta[2] = (-3.0 * u3 + 3.0 * u2 + 3.0 * u + 1.0) / 6.0;
    beta[3] = u3 / 6.0;
}

static void wedge_matrix(double dphi, int nq, blend_fn blend, double *m)
{
    const int ncol = nq * HFS_NLP_N;
    for (int i = 0; i < HFS_SH_N * ncol; ++i)
        m[i] = 0.0;
    if (!(dphi > 0.0) || dphi > 2.0 * PI + 1e-12)
        return;   /* outside the documented domain (also NaN): zeros */
    double E[HFS_SH_N * HFS_NLP_N];
    hfs_wedge_elevation_moments(E);

    double x[AZ_NODES], w[AZ_NODES];
    hfs_gauss_legendre(AZ_NODES, x, w);
    int panels = (int)ceil(dphi);
    if (panels < 1)
        panels = 1;
    const double plen = dphi / panels;
    double A[HFS_SH_N][4] = {{0}};
    for (int p = 0; p < panels; ++p) {
        for (int i = 0; i < AZ_NODES; ++i) {
            const double phi = plen * (p + 0.5 + 0.5 * x[i]);
            const double wt = 0.5 * plen * w[i];
            double az[HFS_SH_N], beta[4];
            hfs_sh_eval_azim(phi, az);
            blend(phi / dphi, beta);
            for (int r = 0; r < HFS_SH_N; ++r)
                for (int q = 0; q < nq; ++q)
                    A[r][q] += wt * beta[q] * az[r];
        }
    }
    for (int r = 0; r < HFS_SH_N; ++r)
        for (int q = 0; q < nq; ++q)
            for (int c = 0; c < HFS_NLP_N; ++c)
                m[r * ncol + q * HFS_NLP_N + c] = A[r][q] * E[r * HFS_NLP_N + c];
}

void hfs_wedge_mlin(double dphi, double m[HFS_SH_N * 2 * HFS_NLP_N])
{
    wedge_matrix(dphi, 2, blend_lin, m);
}

void hfs_wedge_mbspl(double dphi, double m[HFS_SH_N * 4 * HFS_NLP_N])
{
    wedge_matrix(dphi, 4, blend_bspl, m);
}
