/*
 * slice_light.h — exact per-slice lighting (issue 15): the environment's
 * transfer vector integrated exactly along each azimuth slice above its
 * horizon, instead of projecting visibility to order 4 and multiplying by
 * the clamped cosine in SH (the seeds' method, whose order-4 product holds
 * the error at ~1% of the unshadowed maximum whatever the horizons).
 *
 * Along the slice of azimuth phi a direction is w(e) = cos e d + sin e z,
 * d = (cos phi, sin phi, 0), and the receiver of normal N sees
 *     S_k(phi) = Int_x^{pi/2} Y_k(w(e)) (a cos e + b sin e) cos e de,
 *     a = N.d, b = N_z, x = the horizon's elevation (>= the tangent plane's,
 *     where a cos e + b sin e = 0: cpu_horizon.h hfs_horizon_floor),
 * and E = sum_k L_k T_k with T_k = dphi sum_j S_k(phi_j): the SPEC sphere
 * integral of an order-4 environment, exact but for the azimuth sampling.
 * T is linear in the lighting, so it is kept per texel like the seeds'
 * H * V (a turned or re-tinted sky costs a dot product).  For L = 1,
 * S = (a/2)(pi/2 - x - sin(2x)/2) + (b/4)(1 + cos 2x), and on an open flat
 * plane (1/pi) sum_j S dphi = 1.
 *
 * How: restricted to a vertical great circle, Y_k is a trigonometric
 * polynomial of degree <= 3 in e, Y_k(w(e)) = sum_m P_km(phi) f_m(e) with
 * f = (1, cos e, sin e, cos 2e, sin 2e, cos 3e, sin 3e) (P by an exact
 * 8-point DFT, per slice, once per swath).  Times cos^2 e or sin e cos e it
 * has degree <= 5, integrated in closed form from x: only x, cos kx and
 * sin kx (k <= 5) per slice and receiver.
 *
 * Used by the CPU reference (cpu_render.c); the GLES path writes the same
 * closed forms (gles_lib.frag hfs_slice_g) and contracts them in the
 * factored form below (env_slices.frag, gles/uniform_blocks.c).  No state
 * but the table, no I/O.
 */
#ifndef HFS_SLICE_LIGHT_H
#define HFS_SLICE_LIGHT_H

#include "sh.h"
#include "visibility.h"

#define HFS_SLICE_F 7 /* 1, cos e, sin e, cos 2e, sin 2e, cos 3e, sin 3e */

/* P_km(phi_j) for the samples of a swath, and each slice's (cos, sin). */
typedef struct hfs_slice_table {
    int n;
    double dphi;
    double *p;    /* n x HFS_SH_N x HFS_SLICE_F */
    double *dir;  /* n x 2: (cos phi_j, sin phi_j), snapped as the horizons' */
} hfs_slice_table;

/* For the samples of swath s (a full swath: the environment's).  Returns
 * HFS_OK or HFS_E_NOMEM. */
int hfs_slice_table_init(hfs_slice_table *t, const hfs_swath *s, hfs_error *err);
void hfs_slice_table_free(hfs_slice_table *t);

/* Adds slice j's whole transfer, dphi S_k(phi_j) for k < 16, to T (the
 * tests check the open hemisphere's sum against H(N) with it; rendering
 * uses hfs_slice_add_occluded below): normal
 * n (unit, n_z > 0), horizon elevation x in [-pi/2, pi/2] (clamped). */
void hfs_slice_add(const hfs_slice_table *t, int j, const double n[3], double x,
                   double T[HFS_SH_N]);

/* The occluded part of slice j: dphi (S_k(x) - S_k(floor)) with floor the
 * tangent plane's elevation in that slice (<= x): 0 for an open slice, and
 * T = H(N) + the sum over the slices, H(N) the clamped cosine's SH (exact:
 * the open hemisphere needs no azimuth sampling).  What both backends
 * compute. */
void hfs_slice_add_occluded(const hfs_slice_table *t, int j, const double n[3], double x,
                            double T[HFS_SH_N]);

/* Split horizons (split_horizon.h): the mean of slice j's occluded part
 * over the nx horizons x[0..nx-1] of its sub-directions, each with slice
 * j's own kernel (its azimuth's N.d). */
void hfs_slice_add_occluded_mean(const hfs_slice_table *t, int j, const double n[3],
                                 const double *x, int nx, double T[HFS_SH_N]);

/* The factored form the GLES path uses (uniform_blocks.c, env_slices.frag):
 * Y_k along the slice of azimuth phi is trig_k(phi) * sum_m a[k][m] f_m(e),
 * trig_k = 1, cos(m phi) or sin(|m| phi) for k's order m = 0, > 0, < 0
 * (real SH, SPEC), so P_km(phi) = trig_k(phi) a[k][m] (test_slice_light
 * checks it).  a is sparse: each k's profile has at most two terms. */
void hfs_slice_profile(double a[HFS_SH_N][HFS_SLICE_F]);
int hfs_slice_order(int k);            /* m of k = l(l+1) + m */
double hfs_slice_trig(int k, double phi);

/* The clamped cosine's weight of the slice's elevations above x:
 * Int_x^{pi/2} (a cos e + b sin e) cos e de
 *   = (a/2)(pi/2 - x - sin(2x)/2) + (b/4)(1 + cos 2x)
 * (a = N.d(phi), b = N_z).  With uniform radiance 1, (1/pi) sum_j dphi of
 * it from each slice's tangent plane is 1 on an open plane; a band (x1, x2]
 * weighs hfs_slice_cosine(x1) - hfs_slice_cosine(x2). */
double hfs_slice_cosine(double a, double b, double x);

/* A glossy receiver's slice (issue 16, glossy indirect light): the
 * Phong lobe about R and the clamped cosine about N along the slice's
 * elevations, t_R = A cos e + B sin e (A = R.d(phi), B = R_z) and
 * t_N = a cos e + b sin e.  Its bands (x1, x2] weigh
 *     Int_x1^x2 max(0, t_R)^S max(0, t_N) cos e de,
 * by 2-point Gauss-Legendre on steps of at most min(0.1, sqrt(2/S)/2)
 * over the part of the band where the lobe exceeds 1e-6 of its peak
 * (|e - atan2(B, A)| < acos(1e-6^(1/S) / |(A, B)|)): about 15 steps
 * whatever S (bounded at HFS_LOBE_STEPS).  The exact lobe, not its
 * order-4 ZH: NS09's order-4 lobe is ~45 degrees wide at S = 8, and its
 * tails over the terrain near the horizon made the glossy bounce clearly
 * too bright against the truth on cones (DESIGN.md "Glossy surfaces").  bounce_gather.frag mirrors it. */
#define HFS_LOBE_STEPS 64
typedef struct hfs_lobe_slice {
    double A, B, a, b, s;
    double lo, hi;   /* the lobe's support along the slice (lo > hi: none) */
    double h;        /* the step */
} hfs_lobe_slice;
void hfs_lobe_slice_init(hfs_lobe_slice *ls, const double r[3], const double n[3], double c,
                         double s, double gloss);
double hfs_lobe_slice_band(const hfs_lobe_slice *ls, double x1, double x2);

/* The 7 slice integrals g_m = Int_x^{pi/2} f_m(e) (a cos e + b sin e) cos e
 * de (exposed for the tests). */
void hfs_slice_integrals(double a, double b, double x, double g[HFS_SLICE_F]);

#endif /* HFS_SLICE_LIGHT_H */
