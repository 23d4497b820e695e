/*
 * key_setup.c — see key_setup.h.
 */
#include "key_setup.h"

#include "field_geom.h"
#include "lights.h"

#include <math.h>

void hfs_key_setup_make(const hfs_key_light *k, const hfs_quality *q, hfs_key_setup *out)
{
    const double a_vis = hfs_key_vis_alpha(k->alpha);
    hfs_swath_key(k->phi, k->elev, a_vis, q->nphi_key, q->nphi_env, &out->swath);
    hfs_dir(k->phi, k->elev, out->dir);
    out->alpha = k->alpha;
    for (int c = 0; c < 3; ++c)
        out->le[c] = k->radiance[c];
    double zh[HFS_ZH_N];
    hfs_zh_cap(a_vis, zh);
    hfs_sh_rotate_zonal(zh, out->dir[0], out->dir[1], out->dir[2], out->l_sh);
    out->l_norm = sqrt(hfs_sh_dot(out->l_sh, out->l_sh));
}

void hfs_env_rotated(const hfs_lighting *l, double out[3][HFS_SH_N])
{
    for (int c = 0; c < 3; ++c)
        hfs_sh_rotate_z(l->env_sh[c], l->env_rotate, out[c]);
}

hfs_key_near hfs_key_near_make(int sub, int n_levels, int k, const hfs_swath *s)
{
    hfs_key_near nr = {0, 0, 0, 0, 1.0, 1.0, 1.0, 0.0, {1.0, 0.0}};
    if (sub == 1 || n_levels < 2)
        return nr;
    if (s->full) {
        nr.n = nr.n_grid = nr.per_dir = 1;
        return nr;
    }
    const double span = 0.5 * (s->n - 1) * s->dphi, centre = s->phi0 + span;
    /* scales d_m = 2^(m / k) <= reach, at least the finest, at most all
     * of the pyramid's: a swath of one direction has no sideways */
    int n = n_levels - 1;
    if (sin(span) * exp2((double)(n - 1) / k) > HFS_KEY_NEAR_SIDE) {
        const double reach = HFS_KEY_NEAR_SIDE / sin(span);
        const int nr_reach = reach > 1.0 ? (int)floor(k * log2(reach) + 1e-9) + 1 : 1;
        n = nr_reach < n ? nr_reach : n;
    }
    /* and one octave more per doubling of the grid's step, each direction
     * on its own ray: to where the disk's penumbra is a step wide */
    int n_grid = n + (int)lround(k * log2((double)sub));
    n_grid = n_grid < n_levels - 1 ? n_grid : n_levels - 1;
    nr.n = n;
    nr.n_grid = n_grid;
    nr.reach = exp2((double)(n_grid - 1) / k);
    nr.to = exp2((double)n / k);
    nr.edge = HUGE_VAL; /* each direction's ray to the field's end */
    nr.whole = 1;
    nr.centre = centre;
    nr.cs[0] = cos(centre);
    nr.cs[1] = sin(centre);
    return nr;
}
