/*
 * cpu_local.h — local spherical lights in the CPU reference (issue 4;
 * DESIGN.md "Local lights").  Double precision, rows in parallel, bit-identical
 * for any thread count.
 *
 * Per receiver x (grid point lifted by 1e-4 dx, as the truth and the
 * unshadowed normalizer place it) and light (centre c, radius r, radiance Le):
 *   v = c - x, d = |v|, rho_h = |v_xy| (horizontal distance to the centre).
 *   - d <= r (inside or on the sphere): light from every direction, nothing in
 *     between (SPEC): Lo += rho * Le  (E = pi), no visibility work.
 *   - otherwise alpha = asin(r/d), E_cap = hfs_cap_irradiance(N.v/d, alpha)
 *     (0: nothing to do), L = ZH of the cap (hfs_zh_cap) rotated to v/d,
 *     m = H(N) * L, and
 *         Lo += rho/pi * Le * E_cap * clamp(num/den, 0, 1)
 *     with num = V.m, den = V_open.m (the key-light ratio form), V the swath's
 *     visibility and V_open the same with every horizon at the floor.
 *     num == den (no horizon above its floor) gives exactly 1.
 * Swath: the light covers every azimuth iff r >= rho_h (its vertical
 * projection covers the receiver: the cap contains the zenith or the nadir);
 * then, in HFS_LOCAL_SWATH_FULL mode, and always on the wedge-table path, the
 * full swath of nphi_local samples at 2 pi k/n.  Otherwise (partial mode,
 * Legendre) a per-receiver partial swath around the light's azimuth phi_L with
 * half-width h = asin(r/rho_h) (exact: the azimuth range of the sphere does
 * not depend on its height) and n = clamp(ceil(nphi_local h/pi), 3, nphi_local)
 * samples (the full swath's angular density, at least 3), laid out as
 * DESIGN.md's key-light partial swath (boundary wedges of dphi/2).
 * Elevation window of sample k (Legendre): the cap's exact elevation extent in
 * that azimuth when every sample meets the cap (partial swath, or a light
 * covering every azimuth), else the key-light window [e_L - alpha, e_L + alpha].
 * Horizon of sample k: the key-light B-spline max over scale, where a scale
 * counts only if its terrain lies in front of the light: scale s (distance
 * d_s, angle omega_s) counts iff d_s dx <= T(clamp(omega_s, lo, hi)), T(e) =
 * horizontal distance at which the ray of azimuth phi_k and elevation e
 * enters the sphere (the ray's closest approach if it misses); a scale that
 * does not count, like an off-grid one, contributes the floor.
 *
 * Ownership: create/destroy; destroy(NULL) is a no-op.  The pyramid, field and
 * lighting passed to create must outlive the object; it is immutable except
 * for per-worker scratch, so distinct workers may run rows at once.
 */
#ifndef HFS_CPU_LOCAL_H
#define HFS_CPU_LOCAL_H

#include "cpu_pyramid.h"
#include "hfshade.h"
#include "sh.h"

/* ---- options (candidates for hfs_quality; see the report to the lead) ------ */

typedef enum hfs_local_swath_mode {
    HFS_LOCAL_SWATH_PARTIAL = 0, /* per-receiver partial swath where possible (default) */
    HFS_LOCAL_SWATH_FULL = 1     /* always the full swath of nphi_local (thesis) */
} hfs_local_swath_mode;

typedef struct hfs_cpu_local_options {
    hfs_local_swath_mode swath;
} hfs_cpu_local_options;

void hfs_cpu_local_options_default(hfs_cpu_local_options *o);

/* Fewest samples of a partial swath. */
#define HFS_LOCAL_PARTIAL_MIN 3

/* ---- geometry of one light seen from one receiver ---------------------------- */

typedef struct hfs_local_view {
    int inside;          /* receiver in or on the sphere (d <= r, r > 0)       */
    double v[3];         /* centre - receiver, world units                     */
    double d, r;         /* distance to the centre, radius                     */
    double dir[3];       /* v / d (+z when d = 0)                              */
    double alpha;        /* asin(r/d); pi inside                               */
    double sin_a, cos_a; /* r/d and sqrt((d-r)(d+r))/d (outside only)          */
    double c_tan;        /* (d-r)(d+r): squared tangent length (outside only)  */
    double rho_h;        /* horizontal distance to the centre                  */
    double phi_l, elev_l;/* azimuth and elevation of the centre                */
    int surround;        /* r >= rho_h: the light covers every azimuth         */
} hfs_local_view;

/* Fills the view of light l (radius > 0) from receiver point p (world). */
void hfs_local_view_make(const hfs_local_light *l, const double p[3], hfs_local_view *lv);

/* Elevation extent [lo, hi] (clipped to [-pi/2, pi/2]) of the cap in the
 * vertical half-plane of unit azimuth (c, s).  Returns 0 (lo = hi = 0) when
 * that half-plane misses the cap.  Outside the sphere only. */
int hfs_local_cap_window(const hfs_local_view *lv, double c, double s, double *lo, double *hi);

/* Horizontal distance (world) at which the ray of azimuth (c, s) and
 * elevation (cos e, sin e) = (ce, se) enters the sphere; where the ray misses,
 * the horizontal distance of its closest approach to the centre; never < 0. */
double hfs_local_entry_distance(const hfs_local_view *lv, double c, double s, double ce,
                                double se);

/* ---- swath and Legendre visibility ------------------------------------------------- */

/* Same layout as hfs_swath (visibility.h): full = n samples at
 * phi0 + k dphi, dphi = 2 pi/n, hat functions of half-width dphi; partial = n
 * samples at phi0 + k dphi with boundary wedges of dphi/2 that fade to 0. */
typedef struct hfs_local_swath {
    int n, full;
    double phi0, dphi;
} hfs_local_swath;

/* The swath the renderer uses for view lv (see the header comment). */
void hfs_local_swath_make(const hfs_local_view *lv, int nphi_local,
                          hfs_local_swath_mode mode, hfs_visibility_path path,
                          hfs_local_swath *sw);

/* Elevation moments E[r][c] = integral P^_c(sin e) elev_r(e) cos e de (the
 * constant factor of M_lin, sh_wedge.c), 16 x 4 row-major. */
void hfs_local_elevation_moments(double E[HFS_SH_N * HFS_NLP_N]);

/* Azimuthal weights A[r] = integral hat_k(phi) azim_r(phi) dphi of sample k
 * (hat of half-widths: the neighbouring spacing, dphi/2 at a partial swath's
 * ends). */
void hfs_local_sample_weights(const hfs_local_swath *sw, int k, double A[HFS_SH_N]);

/* V = sum_k A_k (.) (E nlp_k): the SH of the linearly blended visible bands,
 * nlp = n x 4 NLP vectors.  Identical (to rounding) to hfs_visibility_eval on
 * the same swath when every sample has the same window: M_lin folded per
 * sample in closed form, for any dphi. */
void hfs_local_legendre_eval(const hfs_local_swath *sw, const double *E, const double *nlp,
                             double V[HFS_SH_N]);

/* ---- renderer hook ----------------------------------------------------------------- */

/* A local light costs something iff it is enabled, has a positive radiance
 * channel and a positive radius (a point has zero solid angle: 0, as truth). */
int hfs_cpu_local_contributes(const hfs_local_light *l);

typedef struct hfs_cpu_local hfs_cpu_local;

/* Prepares the contributing local lights of l for rendering f with quality q
 * over pyramid p (levels min(k*o, N-1)..N-1 reconstructed) with `threads`
 * workers.  opt NULL = defaults.  *out = NULL (and HFS_OK) when no local
 * light contributes. */
int hfs_cpu_local_create(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                         const hfs_cpu_local_options *opt, const hfs_cpu_pyramid *p,
                         int threads, hfs_cpu_local **out, hfs_error *err);
void hfs_cpu_local_destroy(hfs_cpu_local *lc);

/* Exit radiance of every local light at receivers (0..W-1, j): lo_row
 * (W x 3 doubles) is overwritten.  normals: the row's unit normals (W x 3).
 * worker in 0..threads-1 selects the scratch. */
void hfs_cpu_local_row(const hfs_cpu_local *lc, int worker, int j, const double *normals,
                       double *lo_row);

/* hfs_cpu_render (backends.h) with explicit local-light options (NULL =
 * defaults); defined in cpu_render.c. */
int hfs_cpu_render_with(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                        const hfs_cpu_local_options *local_opt, hfs_image *out,
                        hfs_progress_fn progress, void *user, hfs_error *err);

#endif /* HFS_CPU_LOCAL_H */
