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
