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

/* A key light's near search on a sub-sampled grid (DESIGN.md "Key lights
 * on the 2x2 grid", "Sharp edges on the grid"), what each texel searches
 * itself, so that a shadow edge falls on its own texel:
 *   - along the swath's centre azimuth cs, for all its directions: the n
 *     finest scales (within 0.5 / sin(half the swath's extent) texels,
 *     HFS_KEY_NEAR_SIDE: no direction lies more than half a texel
 *     sideways of the centre there), refined, and every crossing of the
 *     ray with the grid's lines up to `to` = 2^(n / k);
 *   - along each direction's own ray, every crossing from `to` to the
 *     field's end (whole = 1, edge = HUGE_VAL): the grid is not used.
 *     Until issue 36's last change the search stopped at 2^(n_grid / k),
 *     one octave more per doubling of the grid's step (where the disk's
 *     penumbra is a step wide), and the texels blended their four
 *     receivers' occluders beyond; on relief that changes every texel a
 *     receiver's occluder is a peak on its own ray that a ray a texel
 *     aside misses, and the blend over-shadowed (the Hurst-0.25 field's
 *     key light 1.48% of the unshadowed maximum at subsample 2, now
 *     0.48%; the 128² fractal 0.34% -> 0.22%, subsample 1's), while the
 *     windowed search costs a clear ray two reads an octave;
 * n_grid, reach: the grid's split when whole = 0 (a full swath): the grid
 * leaves the n_grid finest scales out and searches from `edge` on; an
 * occluder of the grid's less than `reach` = 2^((n_grid - 1) / k) ahead of
 * a texel lends its floor.  A full swath (a disk over the pole) has no
 * centre: its finest scale alone (reach 1) is searched in each of its
 * directions (per_dir), unrefined, the rest on the grid.  n = 0 (reach 1) at subsample 1
 * and on a one-level pyramid.  A function of the grid step, the pyramid
 * (n_levels, k levels per octave) and the swath only, so horizons kept
 * for a swath stay consistent with it.  The GLES passes
 * (key_horizons.frag, key_visibility.frag) and the CPU reference
 * (cpu_grid.c) both take theirs from here. */
#define HFS_KEY_NEAR_SIDE 0.5
typedef struct hfs_key_near {
    int n, n_grid, per_dir;
    int whole;              /* 1: each direction's ray searched to the field's end */
    double reach, to, edge; /* texels (edge HUGE_VAL when whole) */
    double centre;          /* the swath's centre azimuth, radians */
    double cs[2];           /* its (cos, sin) */
} hfs_key_near;
hfs_key_near hfs_key_near_make(int sub, int n_levels, int k, const hfs_swath *s);

/* out[c] = environment channel c rotated about z by l->env_rotate. */
void hfs_env_rotated(const hfs_lighting *l, double out[3][HFS_SH_N]);

#endif /* HFS_KEY_SETUP_H */
