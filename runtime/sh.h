/*
 * sh.h — order-4 real spherical harmonics in SPEC.md's convention, and the
 * visibility machinery of SN08 / NS09 built on them.  Pure math, double
 * precision, no allocation unless stated, no global mutable state.
 *
 * Basis: 16 real SH without the Condon-Shortley phase, index k = l(l+1)+m,
 * y_k(s) for unit s = (x, y, z) as tabulated in SPEC.md.  For m > 0 the
 * function varies as cos(m*phi), for m < 0 as sin(|m|*phi).
 *
 * Elevation angles e are measured from the horizontal plane, e in
 * [-pi/2, pi/2]; NS09's "blocking angle" omega is the same quantity.
 *
 * Every function here is checked against brute-force quadrature over the
 * sphere in tests/test_sh*.c, with the tolerance stated in the test.
 */
#ifndef HFS_SH_H
#define HFS_SH_H

#define HFS_SH_N 16   /* coefficients, order 4 (l = 0..3) */
#define HFS_ZH_N 4    /* zonal coefficients, one per band  */
#define HFS_NLP_N 4   /* normalized Legendre basis size     */

/* ---- basis ---------------------------------------------------------------- */

/* y[k] = y_k(s) for the unit vector s = (x, y, z). */
void hfs_sh_eval(double x, double y, double z, double out[HFS_SH_N]);

/* Same for direction s(phi, e) = (cos phi cos e, sin phi cos e, sin e). */
void hfs_sh_eval_dir(double phi, double e, double out[HFS_SH_N]);

/* ---- projection ------------------------------------------------------------ */

/* Solid-angle-weighted projection of an equirectangular RGB map (SPEC:
 * column u = (i+0.5)/w -> phi = 2*pi*u, row v = (j+0.5)/h -> e = pi/2 - pi*v,
 * row 0 = zenith) onto the basis: out[c][k] = sum_texels L_c * y_k * dOmega,
 * with dOmega the exact solid angle of each texel.  rgb is w*h*3 floats. */
void hfs_sh_project_equirect(const float *rgb, int w, int h,
                             double out[3][HFS_SH_N]);

/* ---- rotation --------------------------------------------------------------- */

/* out = coefficients of f(R_z(-angle) s), i.e. the function rotated by +angle
 * about +z (a feature at azimuth phi moves to phi + angle).  in may == out. */
void hfs_sh_rotate_z(const double in[HFS_SH_N], double angle,
                     double out[HFS_SH_N]);

/* Zonal rotation rule: the ZH vector zh (symmetric about +z) rotated so its
 * axis points along unit d: out_k = sqrt(4 pi / (2l+1)) zh_l y_k(d). */
void hfs_sh_rotate_zonal(const double zh[HFS_ZH_N], double dx, double dy,
                         double dz, double out[HFS_SH_N]);

/* ---- products ----------------------------------------------------------------- */

/* out = projection of the product of the functions a and b onto the basis,
 * through the sparse triple-product tensor C_ijk = integral y_i y_j y_k
 * (nonzero entries only, generated once by quadrature).  out may alias
 * neither a nor b. */
void hfs_sh_product(const double a[HFS_SH_N], const double b[HFS_SH_N],
                    double out[HFS_SH_N]);

/* Number of nonzero tensor entries used by hfs_sh_product (for tests/docs). */
int hfs_sh_product_nonzeros(void);

static inline double hfs_sh_dot(const double a[HFS_SH_N], const double b[HFS_SH_N])
{
    double s = 0.0;
    for (int k = 0; k < HFS_SH_N; ++k)
        s += a[k] * b[k];
    return s;
}

/* ---- zonal functions ------------------------------------------------------------ */

/* Clamped cosine max(0, z): {0.886227, 1.023328, 0.495416, 0}. */
void hfs_zh_clamped_cosine(double out[HFS_ZH_N]);

/* Indicator of the spherical cap of half-angle theta about +z (thesis A.1);
 * multiply by the radiance for a uniform disk/sphere light. */
void hfs_zh_cap(double theta, double out[HFS_ZH_N]);

/* ---- Legendre (NS09 section 4) --------------------------------------------------- */

/* Normalized Legendre basis P^_l(z), l = 0..3, orthonormal on [-1, 1]. */
void hfs_nlp_eval(double z, double out[HFS_NLP_N]);

/* NS09 eq. 10: occlusion vector of the step "blocked for elevation <= sigma",
 * out = integral_{z=-1}^{sin sigma} P^(z) dz.  sigma in [-pi/2, pi/2]. */
void hfs_nlp_occlusion(double sigma, double out[HFS_NLP_N]);

/* NS09 eq. 11 generalized: visibility of the elevation band (lo, hi],
 * out = occlusion(hi) - occlusion(lo); lo >= hi gives zeros. */
void hfs_nlp_visible_band(double lo, double hi, double out[HFS_NLP_N]);

/* ---- wedge integration matrices (NS09 appendix) ------------------------------------ */

/* M_lin(dphi), 16x8 row-major: for a wedge of azimuthal extent dphi starting at
 * phi = 0 whose elevation function is the linear blend (1-a) w_j + a w_{j+1},
 * a = phi/dphi, of two NLP vectors, SH = M_lin * [w_j; w_{j+1}].
 * Computed numerically (quadrature), valid for any dphi in (0, 2 pi]. */
void hfs_wedge_mlin(double dphi, double m[HFS_SH_N * 2 * HFS_NLP_N]);

/* M_bspl(dphi), 16x32 row-major, the same for the uniform cubic B-spline blend
 * of w_{j-1}, w_j, w_{j+1}, w_{j+2} (SN08's beta_0..beta_3 with u = a). */
void hfs_wedge_mbspl(double dphi, double m[HFS_SH_N * 4 * HFS_NLP_N]);

/* ---- SN08 visibility wedge tables --------------------------------------------------- */

/* Tabulated SH projection of one visibility wedge of extent dphi starting at
 * phi = 0: visible above the horizon that varies linearly in phi.  Horizons
 * span [-pi/2, pi/2] (SN08 clamps at 0; we keep negative horizons, NS09).
 *   interior: 2D table over (omega_a at phi=0, omega_b at phi=dphi);
 *   boundary: 1D table over omega at phi = 0, rising linearly to pi/2 (fully
 *             blocked) at phi = dphi (mirror with hfs_sh_mirror_y for the
 *             other end of a swath).
 * Lookups interpolate bilinearly/linearly between table entries. */
typedef struct hfs_wedge_tables hfs_wedge_tables;

/* n = samples per horizon axis (e.g. 256). Returns NULL on allocation failure. */
hfs_wedge_tables *hfs_wedge_tables_create(double dphi, int n);
void hfs_wedge_tables_destroy(hfs_wedge_tables *t);
double hfs_wedge_tables_dphi(const hfs_wedge_tables *t);
void hfs_wedge_interior(const hfs_wedge_tables *t, double omega_a,
                        double omega_b, double out[HFS_SH_N]);
void hfs_wedge_boundary(const hfs_wedge_tables *t, double omega,
                        double out[HFS_SH_N]);
/* Table contents (kept in double) for upload to textures: the interior table
 * is n*n*16 values, entry (a, b) at [(b*n + a)*16 + k]; the boundary table n*16
 * at [a*16 + k]; the horizon of index i is -pi/2 + pi*i/(n-1). */
int hfs_wedge_tables_size(const hfs_wedge_tables *t);
const double *hfs_wedge_interior_data(const hfs_wedge_tables *t);
const double *hfs_wedge_boundary_data(const hfs_wedge_tables *t);

/* Reflection y -> -y (phi -> -phi): negates the m < 0 coefficients. */
void hfs_sh_mirror_y(const double in[HFS_SH_N], double out[HFS_SH_N]);

#endif /* HFS_SH_H */
