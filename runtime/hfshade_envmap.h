/*
 * hfshade_envmap.h — environment maps in libhfshade: an equirectangular
 * map's SH projection, its decomposition into disk key lights plus a
 * residual, and the whole lighting state the renderers take from a map
 * (issue 17; issue 40: exported for bindings such as the Python module).
 * Part of the public interface; include it after <hfshade.h>, or alone
 * (it includes hfshade.h).
 *
 * A map is w x h linear RGB floats, rows first, in SPEC's equirectangular
 * convention: column u = (i + 0.5) / w -> azimuth phi = 2 pi u (from +x
 * towards +y), row v = (j + 0.5) / h -> elevation pi/2 - pi v, row 0 the
 * zenith.  Angles are radians.  Errors: 0 or a negative hfs_status with a
 * one-line message naming `name` (the map's file, or what the caller
 * calls it) in err.
 *
 * `hfshade render --env-map MAP` lights a scene exactly through
 * hfs_env_lighting_build + hfs_env_lighting_apply (runtime/scene), so a
 * program that does the same renders the same image, bit for bit.
 */
#ifndef HFSHADE_ENVMAP_H
#define HFSHADE_ENVMAP_H

#include "hfshade.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- SH projection ------------------------------------------------------------ */

/* The solid-angle-weighted projection of the map onto SPEC's order-4 SH
 * basis: sh[c][k] = sum over texels of L_c y_k dOmega (each texel's exact
 * solid angle); what hfs_lighting.env_sh takes.  Errors: a size below 1 or
 * over 2^28 texels, a non-finite texel ("NAME: texel (i, j) G is NaN"). */
HFS_API int hfs_envmap_project(const float *rgb, int w, int h, const char *name,
                               double sh[3][HFS_SH_COEFFS], hfs_error *err);

/* ---- decomposition into key lights + residual ------------------------------------ */

/* After Arbree, Walter & Bala (docs/DESIGN.md "Environment map
 * decomposition"): the map's compact bright regions become disk lights,
 * each holding exactly the energy it removes from the map (the removed
 * texels take the mean of a ring around them), and what is left is the
 * residual.  Deterministic whatever the number of threads. */
#define HFS_ENV_MAX_LIGHTS HFS_MAX_KEY_LIGHTS

typedef struct hfs_env_decompose_opts {
    int max_lights;     /* 0..HFS_ENV_MAX_LIGHTS; default 4                 */
    double min_share;   /* stop below this share of the map's energy
                           (luminance, Rec. 709), [0, 1]; default 0.02      */
    double contrast;    /* a block is a light candidate only where its mean
                           exceeds contrast x its surround's, [1, 1e6];
                           default 4                                        */
    double max_radius;  /* radians, [0, pi]; a candidate wider than this
                           ends the search (0, the default: no limit)      */
    int threads;        /* coarse pass workers, 0 = all cores               */
} hfs_env_decompose_opts;

/* One extracted light.  energy[c] = radiance[c] * 2 pi (1 - cos alpha) is
 * the energy removed from the map (sum of L dOmega). */
typedef struct hfs_env_light {
    double phi, elev, alpha;     /* radians (SPEC directions)                */
    float radiance[3];           /* linear RGB, >= 0                         */
    double energy[3];
    double share;                /* luminance energy / the map's             */
    int id;                      /* tracker identity (0 without a tracker)   */
} hfs_env_light;

typedef struct hfs_env_decomp {
    int n_lights;
    hfs_env_light light[HFS_ENV_MAX_LIGHTS];
    double residual_sh[3][HFS_SH_COEFFS]; /* the residual's projection      */
    double total_energy[3];      /* the input map's integral, per channel    */
    double residual_energy[3];   /* the residual map's integral              */
} hfs_env_decomp;

/* max_lights 4, min_share 0.02, contrast 4, max_radius 0, threads 0. */
HFS_API void hfs_env_decompose_defaults(hfs_env_decompose_opts *o);

/* Decomposes the w x h map rgb (modified in place into the residual).
 * o may be NULL (defaults).  Maps under 16 x 8 texels give no light.
 * Errors (one line naming `name`): a size below 1x1 or over 2^28 texels,
 * a NaN or infinite texel ("sky.pfm: texel (3, 7) G is NaN"), a texel
 * below -1% of the map's mean radiance, an option out of range.  On error
 * *out is zeroed and rgb untouched. */
HFS_API int hfs_env_decompose(float *rgb, int w, int h, const hfs_env_decompose_opts *o,
                              const char *name, hfs_env_decomp *out, hfs_error *err);

/* The lights as key lights (from_env = 1), at most max; returns the count. */
HFS_API int hfs_env_decomp_keys(const hfs_env_decomp *d, hfs_key_light *keys, int max);

/* ---- the lighting state of a map ----------------------------------------------- */

/* The open sky beyond order 4 (hfs_lighting.env_open): HFS_ENV_OPEN_N^2
 * normals x RGB floats. */
#define HFS_ENV_OPEN_N 33
#define HFS_ENV_OPEN_FLOATS (HFS_ENV_OPEN_N * HFS_ENV_OPEN_N * 3)

/* How a map lights a scene: the scene keys env-lights, env-shade,
 * truth-env and the quality's nphi_env (docs/SCENE.md). */
typedef struct hfs_env_lighting_opts {
    int lights;         /* env-lights: 0 none (default), -1 auto (the
                           decomposition's defaults: up to 4), N: at most
                           N (1..HFS_MAX_KEY_LIGHTS)                        */
    int n_scene_keys;   /* key lights the scene has of its own: the map's
                           fit beside them (HFS_MAX_KEY_LIGHTS in all)      */
    int shade_sh;       /* env-shade = sh: the cpu and gles backends light
                           the map through its SH alone (no env_open, no
                           env_shade_map, no limit on the lights' width);
                           0 (default): shaded from the map itself          */
    int truth_sh;       /* truth-env = sh: the truth integrates the SH, not
                           the map (apply leaves env_map NULL)              */
    int nphi_env;       /* the quality's nphi_env (hfs_quality): without
                           shade_sh, lights at most pi / nphi_env wide are
                           taken (what the slices cannot place)             */
} hfs_env_lighting_opts;

/* What a map gives the renderers, built once per map (a relight reuses
 * it).  Owned buffers: free with hfs_env_lighting_free. */
typedef struct hfs_env_lighting {
    double sh[3][HFS_SH_COEFFS]; /* the map's projection, or with lights
                                    their residual's                        */
    int n_keys;                  /* lights decomposed from the map          */
    hfs_key_light keys[HFS_MAX_KEY_LIGHTS]; /* from_env = 1, unrotated      */
    float *residual;             /* the map without them (w x h x 3), or
                                    NULL (no light: the map itself)         */
    float *open;                 /* HFS_ENV_OPEN_FLOATS: the open sky of the
                                    residual (or map) beyond order 4        */
} hfs_env_lighting;

/* Builds the lighting state of the w x h map rgb (read only) as the scene
 * layer does for `--env-map`: without lights its projection and open-sky
 * table; with lights (o->lights != 0) the decomposition of a copy (its
 * defaults, max_lights as asked and at most HFS_MAX_KEY_LIGHTS -
 * n_scene_keys, max_radius pi / nphi_env unless shade_sh), the residual's
 * projection and table.  o NULL: no lights, nphi_env 12.  Errors: as
 * hfs_env_decompose (every texel finite), an option out of range, out of
 * memory; *out is zeroed on failure. */
HFS_API int hfs_env_lighting_build(const float *rgb, int w, int h,
                                   const hfs_env_lighting_opts *o, const char *name,
                                   hfs_env_lighting *out, hfs_error *err);

/* Puts the state into l as the scene layer does, after the scene's own
 * key lights and env_rotate are set: has_env and env_sh; the map's lights
 * appended to l->key (as many as fit), each turned by l->env_rotate (phi
 * + env_rotate, in [0, 2 pi)); env_map = map (w x h, the caller's; NULL
 * under truth_sh); without shade_sh env_open = e->open and env_shade_map
 * the residual, or the map.  o as given to the build (NULL: defaults).
 * l keeps pointers into e and map: keep both while rendering with l. */
HFS_API void hfs_env_lighting_apply(const hfs_env_lighting *e, const hfs_env_lighting_opts *o,
                                    const float *map, int w, int h, hfs_lighting *l);

/* Frees the state's buffers and zeroes it.  NULL-safe. */
HFS_API void hfs_env_lighting_free(hfs_env_lighting *e);

#ifdef __cplusplus
}
#endif
#endif /* HFSHADE_ENVMAP_H */
