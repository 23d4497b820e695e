/*
 * cpu_horizon.h — multi-scale directional-derivative horizons (DESIGN.md
 * "Horizons"), CPU reference in double precision.
 *
 * For receiver grid point x = (i, j), azimuth phi and scale i_s = 0..N-1:
 *   d      = s_{i_s} texels (hfs_pyramid_spacing; SN08's l = 1),
 *   p      = x + d (cos phi, sin phi)                 (grid coordinates),
 *   L      = min(i_s + k*o, N-1)                      (hfs_pyramid_read_level),
 *   D      = (R_L(p) - R_L(x)) * zscale / (d * dx)    (tangent of blocking angle),
 *   omega  = atan(D); an off-grid p (outside [0,W-1] x [0,H-1]) never occludes
 *            and contributes the floor instead.
 *   floor  = atan2(-N . (cos phi, sin phi, 0), N_z)   (receiver tangent plane).
 * Environment (fast path): max(floor, atan(max_i D_i)) over in-grid scales.
 * Key lights (B-spline max over scale): the uniform cubic B-spline of the
 * omega_i over the scale index, evaluated at every knot (1/6, 2/3, 1/6) and
 * every midpoint (1/48, 23/48, 23/48, 1/48), indices clamped at both ends;
 * max(floor, max of those).  Every horizon lies in [-pi/2, pi/2].
 *
 * Sample positions.  Everything about a sample that does not depend on the
 * receiver is precomputed per (direction, scale) in a plan: the offset
 * d (cos phi, sin phi) split into integer part (ix, iy) and fraction
 * (fx, fy) in [0, 1), the level read and zscale/(d dx).  Since receivers sit
 * on grid points, the bilinear weights of a sample are the same for every
 * receiver.  Offsets are snapped so that exact geometry stays exact: a
 * direction component |cos| or |sin| < 1e-12 becomes 0 (cos(pi/2) is 6e-17 in
 * double, which would otherwise push the samples of a receiver in the last
 * column off the grid), and an offset within 1e-9 texel of an integer becomes
 * that integer.  A sample is in-grid iff 0 <= x + ix + fx <= W-1 (and the same
 * in y), decided exactly on (ix, fx).  The GLES renderer must apply the same
 * rule (with a float tolerance) at the grid border.
 *
 * Two evaluation forms, bit-identical by construction (they share the read):
 *   hfs_horizon_point  one receiver, the readable definition;
 *   hfs_horizon_row    a whole receiver row for one direction, streaming each
 *                      (direction, scale) over contiguous memory (the fast
 *                      path the renderer uses).
 *
 * Ownership: a plan reads the pyramid it was made from, which must outlive it;
 * destroy(NULL) is a no-op.  A plan is immutable after create: any number of
 * threads may evaluate horizons from one plan at once.
 */
#ifndef HFS_CPU_HORIZON_H
#define HFS_CPU_HORIZON_H

#include "cpu_pyramid.h"
#include "hfshade.h"

#include <stddef.h>

/* One (direction, scale) sample, receiver-independent. */
typedef struct hfs_horizon_tap {
    int read;          /* L: full-resolution level read                     */
    int ix, iy;        /* floor of the offset, texels                       */
    double fx, fy;     /* offset - floor, in [0, 1)                          */
    double inv_run;    /* zscale / (d * dx): height difference -> tangent    */
} hfs_horizon_tap;

typedef struct hfs_horizon_plan hfs_horizon_plan;

/* Plans n_dirs azimuths phi[0..n_dirs-1] (radians) over pyramid p, whose
 * levels min(k*offset, N-1)..N-1 must be reconstructed.  dx > 0, zscale >= 0,
 * offset >= 0.  Returns HFS_OK, HFS_E_INVALID or HFS_E_NOMEM. */
int hfs_horizon_plan_create(const hfs_cpu_pyramid *p, double dx, double zscale,
                            int offset, const double *phi, int n_dirs,
                            hfs_horizon_plan **out, hfs_error *err);
void hfs_horizon_plan_destroy(hfs_horizon_plan *hp);

int hfs_horizon_plan_dirs(const hfs_horizon_plan *hp);
int hfs_horizon_plan_levels(const hfs_horizon_plan *hp);   /* N */
/* Snapped (cos phi, sin phi) of direction dir, as used for offsets and floor. */
void hfs_horizon_plan_dir(const hfs_horizon_plan *hp, int dir, double *c, double *s);
/* The N taps of direction dir, indexed by scale. */
const hfs_horizon_tap *hfs_horizon_plan_taps(const hfs_horizon_plan *hp, int dir);

/* Floor -asin(N . (c, s, 0)) for unit normal n, argument clamped to [-1, 1]. */
double hfs_horizon_floor(const double n[3], double c, double s);
/* The same plane's slope, -N.u / N_z: exact at any steepness, where the
 * angle's tan is not (beyond |slope| ~1e9, a double angle near +-pi/2
 * resolves too little: hfs_horizon_refined's seed). */
double hfs_horizon_floor_slope(const double n[3], double c, double s);

/* Horizons of receiver (i, j) along direction dir with the given floor.
 * env (fast path) and key (B-spline max) may each be NULL; omega_levels, if
 * non-NULL, receives the N per-scale angles (floor where off-grid). */
void hfs_horizon_point(const hfs_horizon_plan *hp, int dir, int i, int j,
                       double floor, double *env, double *key,
                       double *omega_levels);

/* Row form for receivers (0..W-1, j) along direction dir:
 *   maxd[x]  (if non-NULL): max_i D_i over in-grid scales, -DBL_MAX if none;
 *   omega[s*W + x] (if non-NULL; needs floor): per-scale angle, atan(D) or
 *            floor[x] off-grid.
 * Finish with hfs_horizon_env_from_maxd / hfs_horizon_bspline_max. */
void hfs_horizon_row(const hfs_horizon_plan *hp, int dir, int j,
                     const double *floor, double *maxd, double *omega);

/* Environment horizon from the row form: max(floor, atan(maxd)). */
double hfs_horizon_env_from_maxd(double maxd, double floor);

/* Environment or key-light horizon with `refine` > 0 taps (DESIGN.md
 * "Horizons", issue 15): the plain max of the per-scale angles
 * omega[s * stride] (the row form's, floor off-grid), and `refine` more
 * samples about the scale t* holding that max, at d_t* 2^(u/k),
 * u = -1 + 2 (q + 1) / (refine + 1), read from t*'s level like t* itself
 * (off-grid ones skipped); then max(floor, that), clamped to [-pi/2,
 * pi/2].  t*: going fine to coarse, a scale takes over when its slope
 * exceeds the current one's by more than HFS_HORIZON_TIE of it plus tie
 * (absolute; pyramid_layout.h), so near-ties go to the finer; a `seed`
 * (the environment: the floor's slope, hfs_horizon_floor_slope) starts
 * the choice from it at the finest scale, so that a scale below the
 * tangent plane never leads (the GLES pass skips what cannot beat it);
 * NULL (key lights) from the finest scale's own.  Slopes beyond 1e9 are
 * taken from the pyramid and the seed, not from the angles' tan (issue
 * 36: scale invariance at any relief).
 * The `skip` finest scales are left out (the caller searches them; 0 or 1,
 * and 0 unless the plan has more scales).  Receiver (i, j), direction dir of hp.  Refining finds the peaks the
 * sparse scales miss between them (SN08's B-spline max for key lights
 * smooths over scale and lowers them further). */
double hfs_horizon_refined(const hfs_horizon_plan *hp, int dir, int i, int j,
                           const double *omega, size_t stride, double floor, int refine,
                           double tie, const double *seed, int skip);

/* The distance factor 2^(u/k), u = -1 + 2 (q + 1) / (refine + 1), of
 * refining sample q of `refine` (k levels per octave): strictly between
 * a scale's neighbours (gles_lib.frag hfs_refine_factor). */
double hfs_horizon_refine_factor(int q, int refine, int k);

/* hfs_horizon_refined over the scales coarsest..N-1-skip only (the near
 * part of split horizons, split_horizon.h; coarsest = 0: all). */
double hfs_horizon_refined_within(const hfs_horizon_plan *hp, int dir, int i, int j,
                                  const double *omega, size_t stride, double floor, int refine,
                                  double tie, const double *seed, int skip, int coarsest);

/* The gap search (ray_bound.h) of receiver (i, j) in direction dir over
 * the pyramid's input heights: the largest of `best` and the slope of
 * every crossing of the ray with the grid's major-axis lines from distance
 * t_first to the grid's edge, so that no occluder
 * between the scales' samples is missed; with `cells` (the key lights)
 * the supremum of the whole ray from that crossing on, every bilinear
 * cell between crossings solved (hfs_ray_bound_search_cells: a spike's
 * cell passed near its corner rises between crossings that do not see
 * it).  *dist becomes the distance of the leading crossing (one takes the
 * lead past the horizons' tie `tie`, hfs_ray_bound_search; left when none
 * beats `best`; a cell's interior raises the value only); *reads (if not
 * NULL) grows by the reads made. */
double hfs_horizon_gap(const hfs_horizon_plan *hp, int dir, int i, int j, double t_first,
                       double tie, double best, int cells, double *dist, long *reads);
/* The same along any snapped direction (c, s) (hfs_horizon_snap_dir), the
 * ray from distance t_first to t_last (ray_bound.h; HUGE_VAL: to the
 * grid's edge), over the heights of hp's pyramid. */
double hfs_horizon_gap_along(const hfs_horizon_plan *hp, double c, double s, int i, int j,
                             double t_first, double t_last, double tie, double best, int cells,
                             double *dist, long *reads);

/* Split horizons' far occluder at receiver (i, j) in direction dir seen
 * from the height of grid point (ci, cj) (split_horizon.h `heights`): the
 * gap search from t_first (hfs_ray_bound_search_from) started from the
 * receiver's own occluder (slope, *dist from its own height; *dist 0:
 * none) seen from there.  Returns the slope from that height; *dist
 * becomes its distance (0: none), *rise that height less the receiver's,
 * texels. */
double hfs_horizon_gap_from(const hfs_horizon_plan *hp, int dir, int i, int j, int ci, int cj,
                            double t_first, double tie, double slope, double *dist, double *rise);

/* The far occluder of split horizons (split_horizon.h) at receiver (i, j)
 * in direction dir, as env_horizons.frag's far pass finds it (and, with
 * `coarsest` > 0, its near pass on a sub-sampled grid): going from
 * scale `first` (the finest far one) to coarser ones, at most to
 * `coarsest`, until one is off the grid (omega[s * stride] at most
 * HFS_HORIZON_OFF: the point form's angles with that floor; not -pi/2,
 * which a slope below -6e15 also rounds to, so that on a field of such
 * relief every falling scale ended the search),
 * the largest slope, then `refine` samples about the scale that leads (a
 * scale takes over when it beats the leader by more than the tie, as in
 * hfs_horizon_refined, unseeded).  *slope: the largest slope (-1e30 if
 * none), *dist its distance in texels (0 if none).  Returns whether there
 * is one. */
int hfs_horizon_occluder(const hfs_horizon_plan *hp, int dir, int i, int j,
                         const double *omega, size_t stride, int first, int coarsest, int refine,
                         double tie, double *slope, double *dist);

/* A key light's horizon at receiver (i, j) of a sub-sampled grid, as
 * key_horizons.frag's grid pass finds it with `refine` > 0 (DESIGN.md
 * "Key lights on the 2x2 grid"): over the scales from N-1-skip (the
 * `skip` finest are each texel's own near search) to coarser ones, the
 * plain max of their slopes, the first scale off the grid contributing
 * the floor's slope and ending the search (omega: the row or point
 * form's angles made with floor HFS_HORIZON_OFF, which marks the off-grid
 * scales), then `refine` samples about the leading scale (a scale takes
 * over past the tie, from the finest one's own), then the gap search
 * from gap_from.  Unlike hfs_horizon_refined it is not raised to the
 * floor: it is the occluder a neighbouring texel, whose floor differs,
 * borrows.  Returns the slope (tan floor where no scale is searched);
 * *dist its distance (the leading scale's, or the refining sample's or
 * crossing's that raised it), *seen whether some scale's sample lay on the
 * grid. */
#define HFS_HORIZON_OFF (-4.0)
double hfs_horizon_key_grid(const hfs_horizon_plan *hp, int dir, int i, int j,
                            const double *omega, double floor, int refine, double tie, int skip,
                            double gap_from, double *dist, int *seen);

/* Key-light horizon, SN08's: max(floor, max over knots and midpoints of the
 * cubic B-spline of omega[0], omega[stride], ..., omega[(n-1)*stride]),
 * clamped to [-pi/2, pi/2]. */
double hfs_horizon_bspline_max(const double *omega, int n, size_t stride,
                               double floor);


/* ---- per-receiver directions (local lights, issue 4; additive) ----------------
 * Local lights sample azimuths that depend on the receiver (a partial swath
 * centred on the light as seen from it), so no per-direction plan can be made
 * ahead.  The receiver-independent part is per scale only: distance d_s
 * (texels), level read, zscale/(d_s dx).  A sample is then exactly what a plan
 * made for the same azimuth would compute (same snapping, same in-grid rule,
 * same bilinear read): hfs_horizon_point_slopes for (c, s) from
 * hfs_horizon_snap_dir(phi) gives bit for bit the tan(omega) that
 * hfs_horizon_point computes for a plan containing phi. */
typedef struct hfs_horizon_scales hfs_horizon_scales;

/* Same preconditions and errors as hfs_horizon_plan_create. */
int hfs_horizon_scales_create(const hfs_cpu_pyramid *p, double dx, double zscale,
                              int offset, hfs_horizon_scales **out, hfs_error *err);
void hfs_horizon_scales_destroy(hfs_horizon_scales *hs);
int hfs_horizon_scales_count(const hfs_horizon_scales *hs);            /* N */
double hfs_horizon_scales_dist(const hfs_horizon_scales *hs, int scale); /* d_s, texels */

/* The snapped unit direction of azimuth phi, as plans use it. */
void hfs_horizon_snap_dir(double phi, double *c, double *s);

/* Receiver (i, j), snapped direction (c, s), scales s_lo..N-1 (0 <= s_lo <= N):
 * in_grid[t] = 1 and slope[t] = D_t = (R_L(p_t) - R_L(x)) zscale/(d_t dx) when
 * the sample lies on the grid, else in_grid[t] = 0 and slope[t] = 0.
 * Entries below s_lo are not touched. */
void hfs_horizon_point_slopes(const hfs_horizon_scales *hs, int i, int j, double c,
                              double s, int s_lo, double *slope, unsigned char *in_grid);

#endif /* HFS_CPU_HORIZON_H */
