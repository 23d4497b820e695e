/*
 * truth_points.c — key-light visibility of points above the field in the
 * ground truth (hfs_renderer_query_points): the disk's solid angle
 * sampled as the truth's key lights are (a jittered sqrt(n) x sqrt(n) grid
 * over (1 - cos theta, psi), truth.c), each sample an exact ray against
 * the bilinear surface up to the grid edge; the visible share of the
 * samples.  A point under the surface sees nothing.
 */
#include "backends.h"
#include "field_geom.h"
#include "truth_raycast.h"
#include "truth_sampling.h"

#include <math.h>

#define PI 3.14159265358979323846

static double point_visibility(const hfs_truth_grid *g, const double o[3],
                               const hfs_key_light *kl, int nt, int np, uint64_t rng)
{
    double d[3], t1[3], t2[3];
    hfs_dir(kl->phi, kl->elev, d);
    frame_around(d, t1, t2);
    const double sh = sin(0.5 * kl->alpha), omc = 2.0 * sh * sh;
    int seen = 0;
    for (int a = 0; a < nt; ++a) {
        const double one_m_ct = omc * ((double)a + rng_uniform(&rng)) / nt;
        const double ct = 1.0 - one_m_ct, st = sqrt(fmax(0.0, one_m_ct * (2.0 - one_m_ct)));
        const double xi = rng_uniform(&rng);
        for (int b = 0; b < np; ++b) {
            const double psi = 2.0 * PI * ((double)b + xi) / np;
            double s[3];
            for (int k = 0; k < 3; ++k)
                s[k] = ct * d[k] + st * (cos(psi) * t1[k] + sin(psi) * t2[k]);
            seen += !hfs_truth_ray_hits(g, o, s, INFINITY);
        }
    }
    return (double)seen / ((double)nt * np);
}

int hfs_truth_query_points(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                           const double *xyz, int n, float *vis, hfs_error *err)
{
    hfs_truth_grid g;
    if (hfs_truth_grid_init(&g, f) != HFS_OK)
        return hfs_fail(err, HFS_E_NOMEM, "query: out of memory for the truth's grid");
    int nt = (int)floor(sqrt((double)q->truth_light_samples));
    nt = nt < 1 ? 1 : nt;
    const int np = (q->truth_light_samples + nt - 1) / nt;
    for (int i = 0; i < n; ++i) {
        const double *p = xyz + 3 * (size_t)i;
        const double o[3] = {p[0] / f->dx, p[1] / f->dx, p[2]}; /* grid xy, world z */
        double zs = -INFINITY; /* the caller checked the point is over the field */
        hfs_field_bilinear(f, o[0], o[1], &zs);
        for (int k = 0; k < l->n_key; ++k) {
            const double v = p[2] < zs
                                 ? 0.0
                                 : point_visibility(&g, o, &l->key[k], nt, np,
                                                    rng_seed((uint64_t)i, 8192 + k));
            vis[(size_t)i * (size_t)l->n_key + (size_t)k] = (float)v;
        }
    }
    hfs_truth_grid_free(&g);
    return HFS_OK;
}
