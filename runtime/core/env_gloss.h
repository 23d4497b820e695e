/*
 * env_gloss.h — an environment map's glossy lobe beyond order 4 (issue 36;
 * DESIGN.md "Shading from the map itself", "The glossy lobe").
 *
 * The renderers' environment lobe (gloss.h hfs_gloss_env) is
 *     Lo_s = ks (N.R) v P(R),   P(R) = Int L(w) (S+1)/(2 pi) max(0, R.w)^S dw,
 * the map convolved with the normalized Phong lobe about R, v the lobe's
 * visible fraction.  Through the map's order-4 SH, P is
 * P_sh(R) = sum_lm g_l L_lm y_lm(R) (the lobe's exact ZH): order 4 blurs
 * the lobe to ~40 degrees where S = 32 is ~12 wide, so a glossy surface
 * under a real map (the courtyard's walls and sunlit openings) reflects a
 * smear.  P depends on R alone, so it can come from the map itself:
 *     D_g(R) = P_map(R) - P_sh(R)
 * tabulated once per map and exponent, added to the SH's lobe by every
 * backend (ks (N.R) v (P_sh(R) + D_g(R')), R' = R turned by -env_rotate:
 * the table lives in the map's frame, so turning the sky costs nothing).
 * The residual beyond order 4 is thus the map's own lobe; the visible
 * fraction v stays the order-4 ratio of gloss.h.
 *
 * The table: (HFS_ENV_GLOSS_NW + 1) x HFS_ENV_GLOSS_NH RGB floats, row-major,
 * node (i, j) at azimuth 2 pi i / NW (column NW repeats column 0, so a
 * bilinear lookup never wraps) and elevation pi/2 - pi j / (NH - 1) (rows
 * 0 and NH - 1 the poles), in the map's frame (SPEC's equirect: column u at
 * phi = 2 pi u, row 0 the zenith): 2.8 degrees apart.  P_map is the
 * lobe's weighted mean of the map gathered into cells, NW columns (the
 * nodes' azimuths, offset by half a column) by at most 64 rows, each
 * cell's radiance times solid angle at its centre's azimuth and its row's
 * solid-angle centroid elevation:
 *     P_map(R) = sum_c E_c lobe(R.d_c) / sum_c Omega_c lobe(R.d_c),
 * the same cells' solid angles in the denominator so that a constant map
 * gives its constant exactly (D_g = 0 up to the SH's own rounding), cells
 * where the lobe is below 1e-4 of its peak skipped (their share is < 1e-3
 * at S = 32).  Within a row of nodes the weight of a cell depends only on
 * the difference of columns, so each row is a circular convolution along
 * azimuth (and one denominator): O(65 x cells in the lobe's reach x 128)
 * per build, a few tens of ms for S = 32 (BENCHMARKS.md).  Good while the
 * lobe spans a few cells (S up to a few hundred: 1/sqrt(S) rad against
 * 2.8 degrees); narrower lobes are blurred to about a cell.  A map too
 * small for any cell to fall in the lobe's reach gives its mean radiance.
 * libc and libm only.
 */
#ifndef HFS_ENV_GLOSS_H
#define HFS_ENV_GLOSS_H

#include "hfshade.h"

#define HFS_ENV_GLOSS_NW 128
#define HFS_ENV_GLOSS_NH 65
#define HFS_ENV_GLOSS_FLOATS ((HFS_ENV_GLOSS_NW + 1) * HFS_ENV_GLOSS_NH * 3)

/* Writes D_g for the w x h linear RGB map, sh its order-4 projection
 * (hfs_sh_project_equirect, the map's frame) and Phong exponent s (>= 1)
 * into table (HFS_ENV_GLOSS_FLOATS floats).  Returns HFS_OK, or
 * HFS_E_INVALID (a size below 1, s below 1) or HFS_E_NOMEM (one line in
 * err). */
int hfs_env_gloss_build(const float *rgb, int w, int h, const double sh[3][HFS_SH_COEFFS],
                        double s, float *table, hfs_error *err);

/* The table's node coordinates (x in [0, NW], y in [0, NH - 1]) of unit
 * direction r (world frame) for a sky turned by rotate.  GLES mirrors it
 * (shade.frag env_gloss). */
void hfs_env_gloss_xy(const double r[3], double rotate, double xy[2]);

/* D_g at r: bilinear between the nodes around hfs_env_gloss_xy(r). */
void hfs_env_gloss_lookup(const float *table, const double r[3], double rotate, double out[3]);

/* The largest |D_g| of the table (the GLES path stores D_g / this). */
double hfs_env_gloss_max(const float *table);

#endif /* HFS_ENV_GLOSS_H */
