/*
 * ray_bound.h — horizon searches that cannot step over an occluder
 * (issue 36; DESIGN.md "Horizons", "Gap search").
 *
 * The scales sample a direction at distances d_i = b^m (and `refine` more
 * about the best): between two samples lies a band d_i (b - 1) long, 128
 * texels at distance 512 with k = 2, and a block narrower than the band
 * casts no shadow there. The gap search closes every band:
 *
 *   crossings  in direction (c, s) from grid point (i, j), the ray meets
 *              the lines of its major axis (x when |c| >= |s|) at
 *              m = 1, 2, ...: the point (i + m sgn c, j + m s / |c|), at
 *              distance t_m = m / |c|, where the surface is the linear
 *              interpolation of two grid points along the minor axis
 *              (SPEC's bilinear surface, exactly). Crossing m's slope is
 *              (z_m - z_0) zscale / (t_m dx).
 *   bounds     a max pyramid of the grid points: level l (l >= 1) holds,
 *              at (a, b), the largest height of the points in
 *              [a 2^l, a 2^l + 2^(l+1)) x [b 2^l, b 2^l + 2^(l+1)) (2x2
 *              blocks of 2^l points, so one read bounds any box whose
 *              corners fall in neighbouring blocks: hfs_ray_bound_level).
 *              A run of crossings [m0, m1] touches the points of its
 *              bounding box (the minor coordinate's floor and ceiling), all
 *              at distance >= t_m0 and <= t_m1, so no crossing in it has a
 *              slope above (bound - z_0) zscale / (t dx), t = t_m0 where
 *              the bound rises above z_0 and t_m1 where it falls below.
 *   search     from crossing m_first to the last inside the grid, runs of
 *              2^l crossings are skipped while their bound is at most the
 *              best slope so far; a run whose bound beats it is halved, a
 *              single crossing is evaluated, and after a skip or an
 *              evaluation the run doubles: a clear ray costs about two
 *              reads per octave of distance.  (Capping runs at a quarter of
 *              their distance, for tighter bounds, read more on every
 *              benchmark scene: 21-35 reads a search against 11-33.)
 *
 * Why it cannot miss: every crossing either is evaluated or lies in a run
 * whose bound was at most the best slope at that moment, and the best only
 * grows; so the result is max(start, every crossing's slope) exactly,
 * whatever the order, the level cap or the rounding of the bounds (as long
 * as they round up: the GLES atlas stores them rounded up to fp16).
 * Between two crossings the surface along the ray is a bilinear cell's
 * quadratic, at most its highest corner, but that corner need not be on a
 * crossing's line segment: a ray that clips the corner of a cell opposite
 * a spike meets its crossings where the spike weighs 0 and the cell's
 * interior where it weighs up to |r|/4 (r the ray's minor/major ratio), so
 * the crossings alone can step over a post's or a pin's whole umbra
 * (tests/test_long_shadow.c "spike's cell").  Searches that must not miss
 * an occluder therefore use the cells below: the key lights' and the GIS
 * horizons'.  The environment's far grid keeps the crossings (a sky's
 * integral over the grid's sub-directions, where a cell's twist is below
 * its other errors).
 *
 * cells      the exact maximum over the whole ray instead (the key lights
 *            and the GIS horizons, which the truth's supremum checks): a twisted cell
 *            rises between its crossings (a corner's peak passed
 *            diagonally: 11 deg above both crossings on a rough fractal).
 *            Each evaluated crossing also solves the ray's cells on to the
 *            next crossing in closed form (ray_bound.c segment), a
 *            run's box also holds the cells on to the crossing past it, so
 *            a skipped run bounds them too, the cells past the last
 *            crossing (to the radius or the grid's side) are solved at the
 *            end, and where t_first lies past crossing 1 and off the
 *            crossings, the stretch from t_first to the first crossing is
 *            bounded (one read) and solved where that can beat the start:
 *            a search continued from where another stopped (a key light's
 *            edge search after its near one) leaves no gap.  Every stretch
 *            of the ray from t_first on (from crossing 1 when t_first <= 1:
 *            the receiver's own cell peaks at an end, which the caller
 *            takes) is then solved or bounded, and the result is the
 *            supremum there.  Costs about twice the crossings' reads a
 *            ray on test_ray_bound's rough fields (30.8 against 15.4),
 *            the last segment's far column kept for the next.
 *
 * Shared by the CPU reference (this file's search) and the GLES path
 * (gles_ray.frag hfs_gap_search, the same steps); pure functions.
 */
#ifndef HFS_RAY_BOUND_H
#define HFS_RAY_BOUND_H

#include <stddef.h>

#define HFS_RAY_BOUND_MAX_LEVELS 16 /* levels 1..15: fields up to 32768 texels */

/* The max pyramid's atlas: level 1 at (0, 0), levels 2.. stacked in a
 * column to its right (width about 3/4 of the field's, height about
 * half). */
typedef struct hfs_ray_bound_layout {
    int w, h;      /* the field's grid points */
    int n_levels;  /* levels 1..n_levels - 1 are stored (index 0 unused) */
    int aw, ah;    /* the atlas' size */
    int x0[HFS_RAY_BOUND_MAX_LEVELS], y0[HFS_RAY_BOUND_MAX_LEVELS];
    int lw[HFS_RAY_BOUND_MAX_LEVELS], lh[HFS_RAY_BOUND_MAX_LEVELS];
} hfs_ray_bound_layout;

/* The layout for a w x h field (w, h >= 1): levels up to the first whose
 * blocks 2^l cover the longer side, so that any box has a level. */
void hfs_ray_bound_layout_make(int w, int h, hfs_ray_bound_layout *L);

/* Fills atlas (aw x ah doubles, row-major) with the bounds of the heights
 * (z[j w + i] - base) / scale (scale > 0), and `fill` where no level lies.
 * scratch: w * h doubles (level 1's plain block maxima, then each
 * coarser one's). */
void hfs_ray_bound_build(const hfs_ray_bound_layout *L, const float *z, double base,
                         double scale, double fill, double *atlas, double *scratch);

/* The level whose one read bounds the grid points [x0, x1] x [y0, y1]
 * (0 <= x0 <= x1, 0 <= y0 <= y1): the smallest l >= 1 with x1 >> l at
 * most one block past x0 >> l and the same in y. */
int hfs_ray_bound_level(int x0, int x1, int y0, int y1);

/* One receiver's gap search, as described above, on the CPU: grid point
 * (i, j) of heights z (row stride `stride`, w x h), direction (c, s)
 * (snapped as the horizon plans snap them), crossings from the first at
 * distance >= t_first to the last at distance <= t_last or the grid's
 * edge, whichever comes first, slopes (z - z_0) * zs / t with zs = zscale / dx,
 * bounds from atlas (built with base 0, scale 1).  Returns the largest of
 * `best` and every crossing's slope, exactly; *dist becomes the distance
 * of the crossing that leads (unchanged when none beat `best`), where a
 * crossing takes the lead only when it beats the leader by more than the
 * horizons' tie (HFS_HORIZON_TIE |lead| + tie, pyramid_layout.h), as a
 * scale does: so that float and double searches name the same crossing on
 * a plateau's top, where slopes tie, while the value stays the max (a tie
 * from the field's height range must not move it: a border far below
 * would).  *reads, when
 * not NULL, grows by the reads made (bounds and heights). */
double hfs_ray_bound_search(const hfs_ray_bound_layout *L, const double *atlas, const double *z,
                            size_t stride, int i, int j, double c, double s, double t_first,
                            double t_last, double zs, double tie, double best, double *dist,
                            long *reads);

/* hfs_ray_bound_search to the grid's edge as seen from height z0 (in z's
 * units) at (i, j) instead of the grid point's own: split horizons' far
 * occluders from the heights of the receivers around (split_horizon.h
 * `heights`; GLES: env_horizons.frag's far pass, the same steps). */
double hfs_ray_bound_search_from(const hfs_ray_bound_layout *L, const double *atlas,
                                 const double *z, size_t stride, int i, int j, double z0,
                                 double c, double s, double t_first, double zs, double tie,
                                 double best, double *dist);

/* The same over the whole ray from t_first (from crossing 1 where t_first
 * <= 1) to t_last or the grid's edge: the supremum of the bilinear
 * surface's slopes there, each cell between crossings in closed form
 * ("cells" above).  *dist still names a crossing: a cell's interior raises
 * the value only, so that the lead (the occluder a key light's grid
 * receiver lends its texels) does not move to a point a rounding above
 * the crossing beside it, where float and double, fp16 and fp32 would
 * part. */
double hfs_ray_bound_search_cells(const hfs_ray_bound_layout *L, const double *atlas,
                                  const double *z, size_t stride, int i, int j, double c,
                                  double s, double t_first, double t_last, double zs, double tie,
                                  double best, double *dist, long *reads);

#endif /* HFS_RAY_BOUND_H */
