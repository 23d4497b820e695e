/*
 * truth_bounce.h — indirect light in the ground truth (SPEC "Indirect
 * light"): one bounce by Monte Carlo over the bilinear surface.
 *
 *   Lo_b(x) = rho(x)/pi Int_{dirs that hit} Lo_{b-1}(y(x, s)) max(0, N.s) ds
 *           = rho(x) E[Lo_{b-1}(y(x, s))] over s cosine-distributed about N,
 *
 * s from a jittered sqrt(n) x sqrt(n) grid over (r^2, psi) of the
 * cosine-weighted disk (Malley's method: every stratum has equal cosine
 * measure, so the plain mean is unbiased), each an exact first-hit ray
 * (hfs_truth_ray_first_hit) from the receiver lifted by 1e-4 dx; y's
 * radiance is Lo_{b-1}'s bilinear interpolant at y's grid position; a ray
 * that leaves the grid brings nothing.  Directions below the horizontal
 * are sampled too where the tangent plane allows (they hit the terrain).
 * rho(x) = albedo * albedo_map(x) (albedo.h).  A glossy receiver
 * (gloss.h) adds the lobe's share,
 *   ks (S+2)/(S+1) E[Lo_{b-1}(y(x, s)) max(0, N.s)] over s from the lobe
 *   about R (truth_sampling.h lobe_direction, k x k strata as the
 *   cosine's), R for the view at x (hfs_gloss_reflect); 0 where N.V <= 0.
 * Deterministic: the jitter
 * is seeded per receiver and bounce (truth_sampling.h), so the output is
 * bit identical for any thread count.
 */
#ifndef HFS_TRUTH_BOUNCE_H
#define HFS_TRUTH_BOUNCE_H

#include "gloss.h"
#include "hfshade.h"
#include "truth_raycast.h"

typedef struct hfs_truth_bounce_in {
    const hfs_truth_grid *grid;  /* over the field (its f)                   */
    const float *prev;           /* Lo_{b-1}, W*H*3                          */
    double albedo;
    const float *albedo_map;     /* NULL or W*H*3 in [0, 1]                  */
    int samples;                 /* rays per receiver: the largest k^2 <= it  */
    int bounce;                  /* b >= 1: seeds the jitter                  */
    int threads;
    const hfs_gloss *gloss;      /* NULL or off: diffuse receivers            */
} hfs_truth_bounce_in;

/* Lo_b at receiver (i, j), in double. */
void hfs_truth_bounce_at(const hfs_truth_bounce_in *in, int i, int j, double lo[3]);

/* out (W*H*3) = Lo_b, each value hfs_truth_bounce_at's rounded to float.
 * Never fails (no allocation). */
void hfs_truth_bounce(const hfs_truth_bounce_in *in, float *out, hfs_progress_fn progress,
                      void *user);

#endif /* HFS_TRUTH_BOUNCE_H */
