/*
 * split_horizon.h — split horizons (issue 15; DESIGN.md "Split horizons"):
 * the slice path's environment horizon in each direction as two parts.
 *
 *   near  the scales within far_from texels (and the receiver's own cell),
 *         searched per receiver in the direction itself, as before;
 *   far   the scales beyond, searched at the receivers of a coarser grid
 *         (step G = far_step) in K = far_dirs sub-directions
 *         spread evenly over the direction's wedge (hfs_split_swath), each
 *         kept as its occluder: the height over its receiver and the
 *         distance, in texels (heights as world z / dx).
 *
 * A texel blends each far occluder bilinearly between the grid receivers
 * around it (hfs_grid_axis, the GLES path's texture filtering; beside a
 * wall's top, on its own side of the wall: hfs_split_far_snap) and moves it
 * to its own height (hfs_split_far_slope), where it rises above its own
 * sub-direction's tangent plane (hfs_split_above_plane); each
 * sub-direction's horizon is max(tangent plane, near, far), and slice j's
 * occluded part is the mean over its K sub-horizons, integrated with
 * slice j's own kernel (its azimuth's N.d): the clamped cosine varies
 * slowly with azimuth, the far horizons do not.
 *
 * Why: on the benchmark scenes the error left by 12 directions lay in the
 * far horizons' azimuths (a far peak between two rays is missed), while the
 * near ones interpolate between directions and the far ones between
 * receivers (BENCHMARKS.md "Split horizons").  More directions would cost
 * every scale at every receiver; this costs the far scales at a coarse
 * grid's receivers and K horizon evaluations per slice.
 *
 * Shared by the CPU reference and the GLES path (the same rules and
 * numbers); pure functions, part of hfs_core.
 */
#ifndef HFS_SPLIT_HORIZON_H
#define HFS_SPLIT_HORIZON_H

#include "hfshade.h"
#include "visibility.h"

#define HFS_SPLIT_MAX_K 8 /* far_dirs' largest value (scene_keys.c) */

/* No far occluder (past the field's edge, or none in the grid): the
 * GLES pass writes this pair, and the blend takes it as it is. */
#define HFS_SPLIT_NONE_H (-3e4)
#define HFS_SPLIT_MAX_H 3e4 /* |height| stored, within fp16 */
/* The largest relief (texels) whose occluder heights are stored as they
 * are: 2^14, within HFS_SPLIT_MAX_H with room for a bilinear sample's
 * rounding. */
#define HFS_SPLIT_H_PLAIN 16384.0
/* A receiver that rises above a texel steeper than this (a slope: height
 * difference over distance, 80.5 degrees) is on a wall's top above it
 * (hfs_split_far_snap); the GLES passes get it as HFS_FAR_STEEP. */
#define HFS_SPLIT_STEEP 6

typedef struct hfs_split {
    int on;       /* split on the slice path */
    double from;  /* far_from, texels */
    int k;        /* far sub-directions per direction */
    int step;     /* the far grid's step G */
    int near_refine; /* samples refining the near part                  */
    int far_refine;  /* samples refining the far part: q->refine at every
                        subsample (the far grid is cheap; the CPU's far
                        grid and the GLES far pass both read it here)     */
    int heights;     /* far occluders a receiver keeps per sub-direction:
                        1, or HFS_SPLIT_HEIGHTS (below)                   */
} hfs_split;

/* Far occluders seen from three heights (issue 36, city blocks): a far
 * receiver keeps, per sub-direction, the occluder seen from its own
 * height and those seen from the lowest and the highest of the 3 x 3
 * far receivers around it (itself included), each stored as its height
 * over the receiver and its distance; a texel takes the largest of the
 * three's slopes, each blended and moved to it as one occluder is.  Why:
 * the far horizon seen from a height z is the tangent from z to the
 * terrain's upper hull beyond far-from, and a lower point's tangent
 * touches it nearer: a texel in a street between receivers on roofs (or
 * on a roof between receivers in the street) read occluders found from
 * the wrong height, which no move to its own height can make right.
 * Each is a real occluder of the ray, so the largest never rises above
 * the horizon beyond far-from but by the move's error (a texel's place
 * and the receivers' differ).  On a far grid of step 2 (subsample 1) the
 * receivers around lie within 2 texels: 1 height there. */
#define HFS_SPLIT_HEIGHTS 3

/* The split of a frame with quality q: on where q->split is and
 * q->visibility is the slice path, with or without bounces (their bands
 * are clipped per sub-horizon, hfs_split_band, so that turning bounces on
 * leaves the direct light as it is); far_* at 0 by q->subsample, and on
 * a sub-sampled grid at most 2 samples refining the near part (at 256^2
 * on the 2x2 grid that pays for the far part, BENCHMARKS.md "Split
 * horizons"). */
void hfs_split_make(const hfs_quality *q, hfs_split *s);

/* A bounce band (top, e] of a slice whose direct light has K
 * sub-horizons (issue 36): the band clipped to each of them, and the mean
 * of the parts, so that what a receiver gathers and the sky it sees never
 * overlap in any sub-direction.  Given as the clamped cosine's integrals
 * from each elevation up (slice_light.h hfs_slice_cosine, S): s_top =
 * S(top) >= s_e = S(e), s_cap[h] = S(sub-horizon h), each sub-horizon at
 * or above the slice's tangent plane (where S is decreasing, so that
 * S(min(x, cap)) = max(S(x), S(cap))):
 *   (1/K) sum_h max(s_top, s_cap[h]) - max(s_e, s_cap[h]).
 * s_e = -HUGE_VAL: the rest up to each sub-horizon (the last band's fill).
 * k = 0: no cap, s_top - s_e. */
double hfs_split_band(const double *s_cap, int k, double s_top, double s_e);

/* The far sub-directions of the environment's full swath env, as a full
 * swath of k n: sub-direction h (0 <= h < k) of direction j is its sample
 * j k + h, at phi_j + ((h + 1/2) / k - 1/2) dphi, evenly over the wedge
 * [phi_j - dphi/2, phi_j + dphi/2]. */
void hfs_split_swath(const hfs_swath *env, int k, hfs_swath *far);
/* Sub-direction h's turn from its direction: ((h + 1/2) / k - 1/2) dphi. */
double hfs_split_turn(int h, int k, double dphi);

/* How many of a pyramid's n_levels scales (k levels per octave, spacing
 * hfs_pyramid_spacing) are near: those at most `from` texels away (plus a
 * hair, so that from = 8 keeps the scale at 8).  The near ones are the
 * finest; scale index n_levels - count is the coarsest near one. */
int hfs_split_near_count(int n_levels, int k, double from);
/* The index of the finest far scale, where the far grid's search starts
 * (going coarser), n_levels - 1 - hfs_split_near_count: the near/far
 * boundary of the CPU's far grid and of the GLES near and far passes
 * alike.  -1: every scale is near. */
int hfs_split_first_far(int n_levels, int k, double from);

/* A far occluder blended at a texel (height h over the receivers, distance
 * d, texels) seen from the texel, which lies dz below the receivers'
 * blended height: the slope (h + dz min(d / g, 1)) / d, or -1e30 where
 * there is none (d <= 0). */
double hfs_split_far_slope(double h, double d, double dz, int g);

/* The unit of the occluder heights a grid stores (the pairs' h, in units
 * of this many texels): 1 where the field's relief (hi - lo) zscale / dx
 * is at most HFS_SPLIT_H_PLAIN texels, else the power of two that brings
 * it there, at most 2^64.  An occluder's height over its receiver is
 * within the relief, so a stored height never reaches HFS_SPLIT_MAX_H,
 * fp16's range, at any relief: without the unit a field of 1e5 texels'
 * relief had its occluders cut to 3e4 and the texels below a receiver
 * lost them (the sky at subsample 2 off by up to the whole of the
 * maximum; the image changed with zscale where slopes are 1e15 and 1e21).
 * A power of two: h / unit * unit is h, and fields within 2^14 texels
 * store what they stored before.  The CPU's grids and the GLES passes
 * (u_hunit, gles_lib.frag hfs_far_slope) both take it from here. */
double hfs_split_h_unit(double lo, double hi, double zscale, double dx);

/* An occluder's distance d (0: none) read at a place `shift` texels behind
 * the texel along its direction (hfs_split_far_snap's offset, dotted with
 * the direction): d + shift, none staying none.  GLSL twin: gles_lib.frag
 * hfs_far_d. */
double hfs_split_far_d(double d, double shift);

/* Where a texel reads a grid of occluders (sx, sy: its bilinear position
 * between receivers 0 = (a0, b0), 1 = (a1, b0), 2 = (a0, b1), 3 = (a1,
 * b1)), from its own position (tx, ty) and each receiver's rise above it
 * (its height less the texel's where it is higher, over its distance: a
 * slope; 0 at no distance): where every receiver that weighs rises at
 * most `steep`, (tx, ty) itself; else along the cell's edge whose two
 * receivers pass (the heavier edge; two as heavy: the receiver they
 * share), else at the one receiver that passes and weighs most (or, none
 * passing, the least steep; a tie: (tx, ty)).  The ties are so broken
 * that a turned or mirrored field reads the turned place.  A receiver on a
 * roof sees over the building across the street that hides the sky from
 * a texel at the wall's foot: its occluders are not the texel's at any
 * blend.  (A receiver below the texel, in the street under a roof's edge,
 * is kept: what it sees is there, and moved up it stays below the edge.)
 * The caller moves each occluder by the place's offset from the texel
 * (DESIGN.md "Split horizons"). */
void hfs_split_far_snap(double tx, double ty, const double rise[4], double steep, double *sx,
                        double *sy);

/* Whether a far sub-horizon of slope t rises above its own
 * sub-direction's tangent plane (a_h = N.d of the sub-direction) by more
 * than HFS_SPLIT_PLANE_TIE: only then does it count, at its own
 * elevation, in its slice (integrated from the slice's tangent plane,
 * whose kernel vanishes there).  So the field's own plane never occludes
 * (a tilted plane stays exact), as it never occludes a slice.  Two other
 * rules measured worse on the four benchmark scenes: carrying the
 * elevation above its own plane into the slice (a first-order shift of
 * every far horizon), and integrating it from its own plane. */
#define HFS_SPLIT_PLANE_TIE 1e-3 /* slope, relative to 1 + |plane's|: the
                                    fp16 storage of the far pairs */
int hfs_split_above_plane(double t, double a_h, const double n[3]);

#endif /* HFS_SPLIT_HORIZON_H */
