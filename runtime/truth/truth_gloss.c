/*
 * truth_gloss.c — hfs_truth_gloss_env (truth_gloss.h).  Sampling the lobe
 * rather than the hemisphere: at S = 32 the lobe covers ~1% of the
 * hemisphere, so uniform or cosine samples would almost all miss it.
 */
#include "truth_gloss.h"

#include "truth_sampling.h"

#include <math.h>


void hfs_truth_gloss_env(const hfs_truth_grid *g, const hfs_gloss *gl,
                         const double env[3][HFS_SH_N], const hfs_truth_envmap *map,
                         int n_samples, const double o[3],
                         const double n[3], const double r[3], uint64_t rng, double out[3])
{
    int k = (int)floor(sqrt((double)n_samples));
    k = k < 1 ? 1 : k;
    double t1[3], t2[3];
    frame_around(r, t1, t2);
    const double inv = 1.0 / (gl->s + 1.0);
    double sum[3] = {0.0, 0.0, 0.0};
    for (int a = 0; a < k; ++a)
        for (int b = 0; b < k; ++b) {
            const double u1 = ((double)a + rng_uniform(&rng)) / k;
            const double u2 = ((double)b + rng_uniform(&rng)) / k;
            double s[3];
            lobe_direction(r, t1, t2, inv, u1, u2, s);
            const double ns = n[0] * s[0] + n[1] * s[1] + n[2] * s[2];
            if (!(ns > 0.0) || hfs_truth_ray_hits(g, o, s, INFINITY))
                continue;
            double y[HFS_SH_N], le[3];
            if (map) /* the map itself: the pixel holding s */
                hfs_truth_envmap_radiance(map, s, le);
            else
                hfs_sh_eval(s[0], s[1], s[2], y);
            for (int ch = 0; ch < 3; ++ch)
                sum[ch] += ns * (map ? le[ch] : hfs_sh_dot(env[ch], y));
        }
    const double w = gl->ks * (gl->s + 2.0) / (gl->s + 1.0) / ((double)k * k);
    for (int ch = 0; ch < 3; ++ch)
        out[ch] += w * sum[ch];
}
