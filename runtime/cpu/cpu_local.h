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
#include "local_geometry.h"
#include "sh.h"

/* ---- options (candidates for hfs_quality; see the report to the lead) ------ */

typedef struct hfs_cpu_local_options {
    hfs_local_swath_mode swath;
} hfs_cpu_local_options;

void hfs_cpu_local_options_default(hfs_cpu_local_options *o);

/* ---- renderer hook ----------------------------------------------------------------- */

typedef struct hfs_cpu_local hfs_cpu_local;

/* Prepares the contributing local lights of l for rendering f with quality q
 * over pyramid p (levels min(k*o, N-1)..N-1 reconstructed) with `threads`
 * workers.  opt NULL = defaults.  *out = NULL (and HFS_OK) when no local
 * light contributes. */
int hfs_cpu_local_create(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                         const hfs_cpu_local_options *opt, const hfs_cpu_pyramid *p,
                         int threads, hfs_cpu_local **out, hfs_error *err);
void hfs_cpu_local_destroy(hfs_cpu_local *lc);

/* On a sub-sampled visibility grid (subsample sub = 2, 4; issue 36 item
 * 5, cpu_local_grid.c): each light's visible fraction at the grid's
 * receivers, as the GLES path's local pass computes it, which
 * hfs_cpu_local_row then reads bilinearly per texel (E_cap, the inside
 * test and the glossy lobe stay per texel).  Call once after create,
 * before the rows; lc NULL: nothing. */
int hfs_cpu_local_grid_build(hfs_cpu_local *lc, int sub, int threads, hfs_error *err);

/* Exit radiance of every local light at receivers (0..W-1, j): lo_row
 * (W x 3 doubles) is overwritten.  normals: the row's unit normals (W x 3).
 * worker in 0..threads-1 selects the scratch.  sp_row (W x 3, or NULL when
 * the lighting is not glossy) gets the lights' glossy term (gloss.h): ks Le
 * E_cap ratio times the lobe at the light's centre, ks Le inside a light. */
void hfs_cpu_local_row(const hfs_cpu_local *lc, int worker, int j, const double *normals,
                       double *lo_row, double *sp_row);

/* hfs_cpu_render (backends.h) with explicit local-light options (NULL =
 * defaults); defined in cpu_render.c. */
int hfs_cpu_render_with(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                        const hfs_cpu_local_options *local_opt, hfs_image *out,
                        hfs_progress_fn progress, void *user, hfs_error *err);

#endif /* HFS_CPU_LOCAL_H */
