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

/* Band l and order m of index k (k = l(l+1)+m), 0 <= k < HFS_SH_N. */
static inline int hfs_sh_band(int k)
{
    return k < 1 ? 0 : k < 4 ? 1 : k < 9 ? 2 : 3;
}
static inline int hfs_sh_order(int k)
{
    const int l = hfs_sh_band(k);
    return k - l * (l + 1);
}

/* Separable form of the basis: y_k(phi, e) = elev_k(e) * azim_k(phi), with
 * azim_k = 1 (m = 0), cos(m phi) (m > 0), sin(|m| phi) (m < 0).
 * hfs_sh_eval_elev takes z = sin e and rho = cos e; elev_k is a polynomial in
 * (z, rho), so any (z, rho) on the unit circle is accepted (rho < 0 continues
 * the functions as trigonometric polynomials in e, which the wedge code uses). */
void hfs_sh_eval_elev(double z, double rho, double out[HFS_SH_N]);
void hfs_sh_eval_azim(double phi, double out[HFS_SH_N]);

/* Gauss-Legendre rule with n nodes on [-1, 1] (1 <= n <= 256), ascending
 * nodes; exact for polynomials of degree 2n-1.  Returns 0, or -1 if n is out
 * of range (x, w untouched). */
int hfs_gauss_legendre(int n, double *x, double *w);

/* ---- projection ------------------------------------------------------------ */

/* Solid-angle-weighted projection of an equirectangular RGB map (SPEC:
 * column u = (i+0.5)/w -> phi = 2*pi*u, row v = (j+0.5)/h -> e = pi/2 - pi*v,
 * row 0 = zenith) onto the basis: out[c][k] = sum_texels L_c * y_k * dOmega,
 * with dOmega the exact solid angle of each texel.  rgb is w*h*3 floats,
 * row-major, row 0 first.  Non-finite texels propagate (callers validate the
 * map).  NULL or w, h <= 0 gives zeros. */
void hfs_sh_project_equirect(const float *rgb, int w, int h,
                             double out[3][HFS_SH_N]);

/* ---- bounds ------------------------------------------------------------------ */

/* An upper bound on the negative part max(0, -min_s f(s)) of the function
 * f = sum_k c_k y_k, in closed form: by the addition theorem the band-l
 * basis functions satisfy sum_m y_lm(s)^2 = (2l+1)/(4 pi) for every s, so by
 * Cauchy-Schwarz per band f(s) >= c_0/sqrt(4 pi) - sum_{l >= 1}
 * sqrt((2l+1)/(4 pi)) |c_l|_2.  Rotation invariant; exact for a constant
 * plus band 1; 0 for any sky whose constant term dominates (then every
 * shadowed exit radiance lies in [0, unshadowed]); conservative otherwise
 * (a single hot pixel: 0.88 x its peak, where the true ringing is 0.25 x). */
double hfs_sh_negative_bound(const double c[HFS_SH_N]);

/* ---- rotation --------------------------------------------------------------- */

/* out = coefficients of f(R_z(-angle) s), i.e. the function rotated by +angle
 * about +z (a feature at azimuth phi moves to phi + angle).  in may == out. */
void hfs_sh_rotate_z(const double in[HFS_SH_N], double angle,
                     double out[HFS_SH_N]);
/* Per band l and 1 <= m <= l, with c = cos(m angle), s = sin(m angle):
 *   out[l(l+1)+m] = c in[l(l+1)+m] - s in[l(l+1)-m]
 *   out[l(l+1)-m] = s in[l(l+1)+m] + c in[l(l+1)-m]
 * (e.g. y_3 = x rotated by +pi/2 becomes y_1 = y). */

/* The same rotation with its cos/sin precomputed, for loops that rotate many
 * vectors by the same few angles (the wedge azimuths of a swath). */
typedef struct {
    double c[4], s[4];   /* cos(m angle), sin(m angle), m = 0..3 */
} hfs_sh_zrot;
void hfs_sh_zrot_init(hfs_sh_zrot *r, double angle);
void hfs_sh_rotate_z_with(const hfs_sh_zrot *r, const double in[HFS_SH_N],
                          double out[HFS_SH_N]);

/* Zonal rotation rule: the ZH vector zh (symmetric about +z) rotated so its
 * axis points along unit d: out_k = sqrt(4 pi / (2l+1)) zh_l y_k(d).
 * ZH convention: f(s) = sum_l zh_l y_{l(l+1)}(s) for the canonical +z axis.
 * d is normalized here; d = 0 keeps the +z axis. */
void hfs_sh_rotate_zonal(const double zh[HFS_ZH_N], double dx, double dy,
                         double dz, double out[HFS_SH_N]);

/* ---- products ----------------------------------------------------------------- */

/* out = projection of the product of the functions a and b onto the basis,
 * through the sparse triple-product tensor C_ijk = integral y_i y_j y_k
 * (nonzero entries only, generated once by quadrature).  out may alias
 * neither a nor b. */
void hfs_sh_product(const double a[HFS_SH_N], const double b[HFS_SH_N],
                    double out[HFS_SH_N]);

/* Number of nonzero tensor entries used by hfs_sh_product (for tests/docs):
 * the distinct C_ijk != 0 with i <= j (each is one multiply-add term of the
 * unrolled product; C is symmetric in all three indices). */
int hfs_sh_product_nonzeros(void);

/* Entry idx (0 <= idx < hfs_sh_product_nonzeros()) of that list: indices
 * i <= j, output k, and the value C_ijk.  Returns 0, or -1 if idx is out of
 * range. */
int hfs_sh_product_entry(int idx, int *i, int *j, int *k, double *c);

static inline double hfs_sh_dot(const double a[HFS_SH_N], const double b[HFS_SH_N])
{
    double s = 0.0;
    for (int k = 0; k < HFS_SH_N; ++k)
        s += a[k] * b[k];
    return s;
}

/* ---- zonal functions ------------------------------------------------------------ */

/* Clamped cosine max(0, z): exactly {sqrt(pi)/2, sqrt(pi/3), sqrt(5 pi)/8, 0}
 * = {0.886227, 1.023327, 0.495416, 0}.  (SPEC and NS09 print 1.023328 /
 * 1.02333 for the second; the exact value 1.02332671 is what we return.) */
void hfs_zh_clamped_cosine(double out[HFS_ZH_N]);

/* Indicator of the spherical cap of half-angle theta about +z (thesis A.1):
 * zh_l = 2 pi integral_{cos theta}^{1} y_{l(l+1)}(z) dz, theta clamped to
 * [0, pi] (cap(pi) = whole sphere = {sqrt(4 pi), 0, 0, 0}); multiply by the
 * radiance for a uniform disk/sphere light and rotate with
 * hfs_sh_rotate_zonal to the light's direction. */
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
 * Computed numerically (quadrature), valid for any dphi in (0, 2 pi]; other
 * dphi (or NaN) give a zero matrix.  Column 4q + c multiplies NLP coefficient c
 * of sample q (q = 0: w_j, q = 1: w_{j+1}).  ~20 us a call: compute once
 * per dphi, not per texel. */
void hfs_wedge_mlin(double dphi, double m[HFS_SH_N * 2 * HFS_NLP_N]);

/* The elevation moments that M_lin factors into: E[r][c] = integral over
 * e in [-pi/2, pi/2] of P^_c(sin e) elev_r(e) cos e de, 16 x 4 row-major
 * (32-node Gauss rule: exact to rounding).  The local-light path folds
 * M_lin per sample in closed form from the same numbers. */
void hfs_wedge_elevation_moments(double E[HFS_SH_N * HFS_NLP_N]);

/* M_bspl(dphi), 16x32 row-major, the same for the uniform cubic B-spline blend
 * of w_{j-1}, w_j, w_{j+1}, w_{j+2} (SN08's beta_0..beta_3 with u = a);
 * column 4q + c, q = 0..3 for w_{j-1} .. w_{j+2}. */
void hfs_wedge_mbspl(double dphi, double m[HFS_SH_N * 4 * HFS_NLP_N]);

/* ---- SN08 visibility wedge tables --------------------------------------------------- */

/* Tabulated SH projection of one visibility wedge of extent dphi starting at
 * phi = 0: visible above the horizon that varies linearly in phi.  Horizons
 * span [-pi/2, pi/2] (SN08 clamps at 0; we keep negative horizons, NS09).
 *   interior: 2D table over (omega_a at phi=0, omega_b at phi=dphi);
 *   boundary: 1D table over omega at phi = 0, rising linearly to pi/2 (fully
 *             blocked) at phi = dphi_boundary (= dphi unless made with
 *             hfs_wedge_tables_create_ext).
 * Partial swath with samples phi_0 .. phi_{n-1}, boundary width Db:
 *   end wedge [phi_{n-1}, phi_{n-1} + Db]:  rotate_z(boundary(omega_{n-1}), phi_{n-1})
 *   start wedge [phi_0 - Db, phi_0]:        rotate_z(mirror_y(boundary(omega_0)), phi_0)
 * Lookups interpolate bilinearly/linearly between table entries (~30 ns);
 * the interpolation error at n = 256 is ~2.5e-5 of the largest coefficient
 * (table in sh_wedge_table.c).  Creation at n = 256: ~0.05 s.  A table is
 * immutable after creation and may be shared between threads. */
typedef struct hfs_wedge_tables hfs_wedge_tables;

/* n = samples per horizon axis (e.g. 256). Returns NULL on allocation failure
 * or bad arguments (n < 2, dphi not in (0, 2 pi]).  Caller frees with
 * hfs_wedge_tables_destroy (NULL is a no-op).  Both tables use extent dphi. */
hfs_wedge_tables *hfs_wedge_tables_create(double dphi, int n);
/* Same, with a separate extent for the boundary table: SN08 / DESIGN.md make
 * boundary wedges half as wide as interior ones, so a partial swath wants
 * create_ext(dphi, dphi / 2, n) (one n x n table instead of two). */
hfs_wedge_tables *hfs_wedge_tables_create_ext(double dphi, double dphi_boundary,
                                              int n);
void hfs_wedge_tables_destroy(hfs_wedge_tables *t);
double hfs_wedge_tables_dphi(const hfs_wedge_tables *t);
double hfs_wedge_tables_dphi_boundary(const hfs_wedge_tables *t);
void hfs_wedge_interior(const hfs_wedge_tables *t, double omega_a,
                        double omega_b, double out[HFS_SH_N]);
void hfs_wedge_boundary(const hfs_wedge_tables *t, double omega,
                        double out[HFS_SH_N]);
/* Table contents (kept in double) for upload to textures: the interior table
 * is n*n*16 values, entry (a, b) at [(b*n + a)*16 + k]; the boundary table n*16
 * at [a*16 + k]; the horizon of index i is -pi/2 + pi*i/(n-1).
 * hfs_wedge_tables_size returns n.  Lookups clamp horizons to [-pi/2, pi/2]
 * (NaN reads as -pi/2). */
int hfs_wedge_tables_size(const hfs_wedge_tables *t);
const double *hfs_wedge_interior_data(const hfs_wedge_tables *t);
const double *hfs_wedge_boundary_data(const hfs_wedge_tables *t);

/* The exact (untabulated) projection of the interior wedge of extent dphi
 * with horizons omega_a at phi = 0 and omega_b at phi = dphi (clamped to
 * [-pi/2, pi/2]): what the tables sample.  The boundary wedge is
 * hfs_wedge_exact(dphi_boundary, omega, pi/2, out).  ~6 us a call. */
void hfs_wedge_exact(double dphi, double omega_a, double omega_b,
                     double out[HFS_SH_N]);

/* Reflection y -> -y (phi -> -phi): negates the m < 0 coefficients.
 * in may == out. */
void hfs_sh_mirror_y(const double in[HFS_SH_N], double out[HFS_SH_N]);

#endif /* HFS_SH_H */
