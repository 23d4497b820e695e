/*
 * key_setup.h — what every backend derives from a key light and from the
 * environment before it renders (shared by the CPU reference and the GLES
 * path, so the two cannot drift):
 *   - a key light's swath: the azimuth samples about its direction that
 *     its visible fraction reads (visibility.h hfs_swath_key), built with
 *     the visibility radius hfs_key_vis_alpha (lights.h: a disk below
 *     ~1e-7 rad is taken as one of HFS_MIN_VIS_ALPHA about the same centre,
 *     or the float angle differences collapse), its unit direction, the SH
 *     of the unit-radiance disk of that radius and its norm; E_cap keeps
 *     the true alpha;
 *   - the environment's SH rotated about z by env_rotate.
 */
#ifndef HFS_KEY_SETUP_H
#define HFS_KEY_SETUP_H

#include "hfshade.h"
#include "sh.h"
#include "visibility.h"

typedef struct hfs_key_setup {
    hfs_swath swath;
    double dir[3];              /* unit, toward the light                     */
    double alpha;               /* angular radius, radians (E_cap's)          */
    double le[3];               /* radiance, RGB                              */
    double l_sh[HFS_SH_N];      /* SH of the unit-radiance disk (vis radius)  */
    double l_norm;              /* its norm, sqrt(l_sh . l_sh)                */
} hfs_key_setup;

void hfs_key_setup_make(const hfs_key_light *k, const hfs_quality *q, hfs_key_setup *out);

/* out[c] = environment channel c rotated about z by l->env_rotate. */
void hfs_env_rotated(const hfs_lighting *l, double out[3][HFS_SH_N]);

#endif /* HFS_KEY_SETUP_H */
