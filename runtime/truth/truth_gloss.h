/*
 * truth_gloss.h — the ground truth's glossy environment term (DESIGN.md
 * "Glossy surfaces", "Ground truth"): the Phong lobe importance-sampled.
 */
#ifndef HFS_TRUTH_GLOSS_H
#define HFS_TRUTH_GLOSS_H

#include "gloss.h"
#include "truth_envmap.h"
#include "truth_raycast.h"

#include <stdint.h>

/* out_c += Int L_c(w) V(w) f_s(w) max(0, N.w) dw for the SH sky env (rotated,
 * per channel) or, when map is not NULL, the environment map itself (the
 * pixel each sample direction falls in: the map is piecewise constant), the receiver at o (grid xy, world z) with normal n and
 * reflection vector r: a jittered k x k grid (k^2 <= n_samples, k >= 1)
 * over the lobe's (cos^(S+1) theta, psi), each stratum an equal share of
 * (S+1)/(2 pi) cos^S, so every sample weighs ks (S+2)/(S+1) L V max(0, N.w)
 * / k^2; V from the exact ray test (hfs_truth_ray_hits) up to the grid
 * edge.  rng: the receiver's own stream (truth_sampling.h). */
void hfs_truth_gloss_env(const hfs_truth_grid *g, const hfs_gloss *gl,
                         const double env[3][HFS_SH_N], const hfs_truth_envmap *map,
                         int n_samples, const double o[3],
                         const double n[3], const double r[3], uint64_t rng, double out[3]);

#endif /* HFS_TRUTH_GLOSS_H */
