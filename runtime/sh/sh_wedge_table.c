/*
 * sh_wedge_table.c — SN08 section 5 visibility wedges: the exact SH
 * projection of "visible above a horizon that varies linearly in phi over
 * [0, D]", and its 2D (interior) / 1D (boundary) tables with bilinear/linear
 * lookup.
 *
 * Method.  With y_r = elev_r(e) azim_r(phi) (sh.h),
 *   v_r(wa, wb) = integral_0^D azim_r(phi) F_r(h(phi)) dphi,
 *   h(phi) = wa + (wb - wa) phi / D,   F_r(h) = integral_h^{pi/2} elev_r(e) cos e de.
 * elev_r(e) cos e is a trigonometric polynomial of degree <= 4 in e (z = sin e,
 * rho = cos e), so F_r is exactly K_r . g(h) with
 *   g(h) = [1, h, sin h .. sin 4h, cos h .. cos 4h],
 * K obtained from an exact 16-point DFT (closed form of the elevation
 * integral, no quadrature error).  The phi integral is composite
 * Gauss-Legendre with 10 nodes per panel and enough panels that each spans at
 * most 3 rad of phase of the integrand (azimuthal frequency <= 3, horizon
 * frequency <= 4), which keeps the rule at rounding level.  Since only 7
 * distinct azimuthal functions occur, the phi integral accumulates the 7x10
 * moments S[a][q] = integral azim_a g_q(h) and contracts with K at the end.
 *
 * Accuracy (tests/test_sh_wedge_table.c against brute-force quadrature):
 * table entries and hfs_wedge_exact agree with direct integration to ~1e-14.
 * Interpolation error at n = 256 (grid step pi/255), max over 40000 random
 * horizon pairs in [-pi/2, pi/2]^2 and all 16 coefficients, against
 * hfs_wedge_exact (boundary table built with extent D/2):
 *     D         interior (bilinear)   boundary (linear)   max |coef|
 *     2pi/64    1.8e-6                3.0e-7              0.08
 *     2pi/32    3.6e-6                6.0e-7              0.15
 *     2pi/8     1.3e-5                2.4e-6              0.54
 *     2pi/3     2.9e-5                6.3e-6              1.18
 * i.e. ~2.5e-5 of the largest coefficient; it scales exactly as 1/n^2.
 * Creation at n = 256 takes ~0.05 s (one thread, RelWithDebInfo).
 *
 * Invariants: the horizon of index i is -pi/2 + pi i/(n-1) (both ends are
 * table entries); lookups clamp to that range; tables are immutable after
 * create, so one object may be shared by any number of threads.
 */
#include "sh.h"

#include <math.h>
#include <stdlib.h>

#define PI 3.14159265358979323846
#define HALF_PI 1.57079632679489661923

#define NG 10          /* elements of g(h) */
#define NAZ 7          /* distinct azimuthal functions */
#define PANEL_NODES 10
#define PANEL_PHASE 3.0
#define MAX_PANELS 16  /* 3 * 2pi + 4 pi < 16 * 3 */

struct hfs_wedge_tables {
    double dphi, dphi_b;
    int n;
    double *interior;   /* n*n*16, [(b*n + a)*16 + k] */
    double *boundary;   /* n*16,   [a*16 + k] */
};

/* Which azimuthal function each SH index uses: 0 = 1, 1..3 = cos(m phi),
 * 4..6 = sin(m phi). */
static const int az_of_k[HFS_SH_N] = {0, 4, 0, 1, 5, 4, 0, 1, 2,
                                     6, 5, 4, 0, 1, 2, 3};

/* Everything that does not depend on the horizons. */
typedef struct {
    double K[HFS_SH_N][NG];
    double gx[PANEL_NODES], gw[PANEL_NODES];
} wedge_plan;

static void plan_init(wedge_plan *p)
{
    /* Exact DFT of elev_r(e) cos e (degree <= 4, 16 samples: no aliasing).
     * Samples sit at e_j = 2 pi j / 16, so every cos(n e_j), sin(n e_j) is
     * an entry of this table of cos(2 pi q / 16). */
    enum { M = 16 };
    static const double cos16[M] = {
        1.0, 0.92387953251128674, 0.70710678118654752, 0.38268343236508977,
        0.0, -0.38268343236508977, -0.70710678118654752, -0.92387953251128674,
        -1.0, -0.92387953251128674, -0.70710678118654752, -0.38268343236508977,
        0.0, 0.38268343236508977, 0.70710678118654752, 0.92387953251128674};
    double a[HFS_SH_N][5] = {{0}}, b[HFS_SH_N][5] = {{0}};
    for (int j = 0; j < M; ++j) {
        const double rho = cos16[j], z = cos16[(j + 12) % M];  /* sin = cos(. - pi/2) */
        double el[HFS_SH_N];
        hfs_sh_eval_elev(z, rho, el);
        for (int r = 0; r < HFS_SH_N; ++r) {
            const double gval = el[r] * rho;
            a[r][0] += gval / M;
            for (int n = 1; n <= 4; ++n) {
                a[r][n] += 2.0 / M * gval * cos16[(n * j) % M];
                b[r][n] += 2.0 / M * gval * cos16[(n * j + 12) % M];
            }
        }
    }
    /* F_r(h) = a0 (pi/2 - h) + sum_n [a_n (sin(n pi/2) - sin nh)
     *                                + b_n (cos nh - cos(n pi/2))] / n */
    static const double sin_half[5] = {0, 1, 0, -1, 0};
    static const double cos_half[5] = {1, 0, -1, 0, 1};
    for (int r = 0; r < HFS_SH_N; ++r) {
        double k0 = a[r][0] * HALF_PI;
        for (int n = 1; n <= 4; ++n)
            k0 += (a[r][n] * sin_half[n] - b[r][n] * cos_half[n]) / n;
        p->K[r][0] = k0;
        p->K[r][1] = -a[r][0];
        for (int n = 1; n <= 4; ++n) {
            p->K[r][1 + n] = -a[r][n] / n;
            p->K[r][5 + n] = b[r][n] / n;
        }
    }
    hfs_gauss_legendre(PANEL_NODES, p->gx, p->gw);
}

static double clamp_horizon(double w)
{
    if (!(w > -HALF_PI))
        return -HALF_PI;   /* also NaN */
    return w > HALF_PI ? HALF_PI : w;
}

static int panel_count(double d, double dw)
{
    const int np = (int)ceil((3.0 * d + 4.0 * fabs(dw)) / PANEL_PHASE);
    return np < 1 ? 1 : np > MAX_PANELS ? MAX_PANELS : np;
}

/* Azimuthal node tables for `np` panels over [0, d]: phi and
 * weight * azim_a(phi) per node.  One panel layout is shared by every entry
 * with the same panel count, which is what makes table creation cheap. */
static void panel_nodes(const wedge_plan *p, double d, int np, double *phi,
                        double (*waz)[NAZ])
{
    const double plen = d / np;
    for (int q = 0; q < np; ++q) {
        for (int i = 0; i < PANEL_NODES; ++i) {
            const int t = q * PANEL_NODES + i;
            const double f = plen * (q + 0.5 + 0.5 * p->gx[i]);
            const double w = 0.5 * plen * p->gw[i];
            phi[t] = f;
            waz[t][0] = w;
            waz[t][1] = w * cos(f);
            waz[t][2] = w * cos(2.0 * f);
            waz[t][3] = w * cos(3.0 * f);
            waz[t][4] = w * sin(f);
            waz[t][5] = w * sin(2.0 * f);
            waz[t][6] = w * sin(3.0 * f);
        }
    }
}

static void wedge_entry(const wedge_plan *p, double d, double wa, double wb,
                        int nodes, const double *phi,
                        const double (*waz)[NAZ], double out[HFS_SH_N])
{
    double S[NAZ][NG] = {{0}};
    const double slope = (wb - wa) / d;
    for (int t = 0; t < nodes; ++t) {
        const double h = wa + slope * phi[t];
        const double s1 = sin(h), c1 = cos(h);
        const double s2 = 2.0 * s1 * c1, c2 = 2.0 * c1 * c1 - 1.0;
        const double s3 = s2 * c1 + c2 * s1, c3 = c2 * c1 - s2 * s1;
        const double s4 = 2.0 * s2 * c2, c4 = 2.0 * c2 * c2 - 1.0;
        const double g[NG] = {1.0, h, s1, s2, s3, s4, c1, c2, c3, c4};
        for (int a = 0; a < NAZ; ++a) {
            const double wa_t = waz[t][a];
            for (int q = 0; q < NG; ++q)
                S[a][q] += wa_t * g[q];
        }
    }
    for (int r = 0; r < HFS_SH_N; ++r) {
        const double *s = S[az_of_k[r]];
        double v = 0.0;
        for (int q = 0; q < NG; ++q)
            v += p->K[r][q] * s[q];
        out[r] = v;
    }
}

void hfs_wedge_exact(double dphi, double omega_a, double omega_b,
                     double out[HFS_SH_N])
{
    for (int k = 0; k < HFS_SH_N; ++k)
        out[k] = 0.0;
    if (!(dphi > 0.0) || dphi > 2.0 * PI + 1e-12)
        return;
    wedge_plan p;
    plan_init(&p);
    const double wa = clamp_horizon(omega_a), wb = clamp_horizon(omega_b);
    const int np = panel_count(dphi, wb - wa);
    double phi[MAX_PANELS * PANEL_NODES];
    double waz[MAX_PANELS * PANEL_NODES][NAZ];
    panel_nodes(&p, dphi, np, phi, waz);
    wedge_entry(&p, dphi, wa, wb, np * PANEL_NODES, phi,
                (const double (*)[NAZ])waz, out);
}

static double horizon_of_index(int i, int n)
{
    /* Exact at both ends so the last entry is the fully blocked horizon. */
    return i == n - 1 ? HALF_PI : -HALF_PI + PI * i / (n - 1);
}

hfs_wedge_tables *hfs_wedge_tables_create_ext(double dphi, double dphi_boundary,
                                              int n)
{
    const double maxd = 2.0 * PI + 1e-12;
    if (n < 2 || n > 4096 || !(dphi > 0.0) || dphi > maxd ||
        !(dphi_boundary > 0.0) || dphi_boundary > maxd)
        return NULL;
    hfs_wedge_tables *t = calloc(1, sizeof *t);
    if (!t)
        goto err_struct;
    t->dphi = dphi;
    t->dphi_b = dphi_boundary;
    t->n = n;
    t->interior = malloc((size_t)n * (size_t)n * HFS_SH_N * sizeof(double));
    if (!t->interior)
        goto err_interior;
    t->boundary = malloc((size_t)n * HFS_SH_N * sizeof(double));
    if (!t->boundary)
        goto err_boundary;
    /* Node tables for every panel count an interior entry can need, laid
     * out back to back: panel count np starts at offset PN * np(np-1)/2. */
    const size_t total = (size_t)PANEL_NODES * MAX_PANELS * (MAX_PANELS + 1) / 2;
    double *phi = malloc(total * sizeof(double));
    double (*waz)[NAZ] = malloc(total * sizeof *waz);
    if (!phi || !waz)
        goto err_nodes;

    wedge_plan p;
    plan_init(&p);
    for (int np = 1; np <= MAX_PANELS; ++np) {
        const size_t off = (size_t)PANEL_NODES * np * (np - 1) / 2;
        panel_nodes(&p, dphi, np, phi + off, waz + off);
    }
    /* Swapping the two horizons is the reflection phi -> dphi - phi, i.e.
     * mirror_y then rotate_z(+dphi): only the triangle ia <= ib is
     * integrated, the rest is reflected (halves the creation time). */
    hfs_sh_zrot to_end;
    hfs_sh_zrot_init(&to_end, dphi);
    for (int ib = 0; ib < n; ++ib) {
        const double wb = horizon_of_index(ib, n);
        for (int ia = 0; ia <= ib; ++ia) {
            const double wa = horizon_of_index(ia, n);
            const int np = panel_count(dphi, wb - wa);
            const size_t off = (size_t)PANEL_NODES * np * (np - 1) / 2;
            double *v = t->interior + ((size_t)ib * n + ia) * HFS_SH_N;
            wedge_entry(&p, dphi, wa, wb, np * PANEL_NODES, phi + off,
                        (const double (*)[NAZ])(waz + off), v);
            if (ia != ib) {
                double m[HFS_SH_N];
                hfs_sh_mirror_y(v, m);
                hfs_sh_rotate_z_with(&to_end, m,
                                     t->interior + ((size_t)ia * n + ib) * HFS_SH_N);
            }
        }
    }
    /* The boundary wedge is the interior wedge of its own extent with the far
     * horizon at pi/2; its few entries use per-entry nodes. */
    for (int ia = 0; ia < n; ++ia)
        hfs_wedge_exact(dphi_boundary, horizon_of_index(ia, n), HALF_PI,
                        t->boundary + (size_t)ia * HFS_SH_N);
    free(waz);
    free(phi);
    return t;

err_nodes:
    free(waz);
    free(phi);
    free(t->boundary);
err_boundary:
    free(t->interior);
err_interior:
    free(t);
err_struct:
    return NULL;
}

hfs_wedge_tables *hfs_wedge_tables_create(double dphi, int n)
{
    return hfs_wedge_tables_create_ext(dphi, dphi, n);
}

void hfs_wedge_tables_destroy(hfs_wedge_tables *t)
{
    if (!t)
        return;
    free(t->interior);
    free(t->boundary);
    free(t);
}

double hfs_wedge_tables_dphi(const hfs_wedge_tables *t)
{
    return t->dphi;
}

double hfs_wedge_tables_dphi_boundary(const hfs_wedge_tables *t)
{
    return t->dphi_b;
}

int hfs_wedge_tables_size(const hfs_wedge_tables *t)
{
    return t->n;
}

const double *hfs_wedge_interior_data(const hfs_wedge_tables *t)
{
    return t->interior;
}

const double *hfs_wedge_boundary_data(const hfs_wedge_tables *t)
{
    return t->boundary;
}

/* Continuous table coordinate of a horizon, split into a cell index in
 * [0, n-2] and a fraction in [0, 1]. */
static int table_cell(double omega, int n, double *frac)
{
    double u = (clamp_horizon(omega) + HALF_PI) * ((n - 1) / PI);
    if (u > n - 1)
        u = n - 1;
    int i = (int)u;
    if (i > n - 2)
        i = n - 2;
    *frac = u - i;
    return i;
}

void hfs_wedge_interior(const hfs_wedge_tables *t, double omega_a,
                        double omega_b, double out[HFS_SH_N])
{
    const int n = t->n;
    double fa, fb;
    const int ia = table_cell(omega_a, n, &fa);
    const int ib = table_cell(omega_b, n, &fb);
    const double *t00 = t->interior + ((size_t)ib * n + ia) * HFS_SH_N;
    const double *t01 = t00 + HFS_SH_N;                     /* a + 1 */
    const double *t10 = t00 + (size_t)n * HFS_SH_N;         /* b + 1 */
    const double *t11 = t10 + HFS_SH_N;
    const double w00 = (1.0 - fa) * (1.0 - fb), w01 = fa * (1.0 - fb);
    const double w10 = (1.0 - fa) * fb, w11 = fa * fb;
    for (int k = 0; k < HFS_SH_N; ++k)
        out[k] = w00 * t00[k] + w01 * t01[k] + w10 * t10[k] + w11 * t11[k];
}

void hfs_wedge_boundary(const hfs_wedge_tables *t, double omega,
                        double out[HFS_SH_N])
{
    double f;
    const int i = table_cell(omega, t->n, &f);
    const double *t0 = t->boundary + (size_t)i * HFS_SH_N;
    const double *t1 = t0 + HFS_SH_N;
    for (int k = 0; k < HFS_SH_N; ++k)
        out[k] = (1.0 - f) * t0[k] + f * t1[k];
}
