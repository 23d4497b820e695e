/*
 * scene_load.h — a scene (scene.h) made into what a renderer takes: the
 * height field loaded, the environment map projected to SH, the lighting
 * and quality filled in and validated.
 *
 * Shared by the command-line tool (one render) and the kiosk (many frames):
 * the expensive part — reading the height file, reading the environment
 * map, decomposing it into lights (env-lights, runtime/envmap/env_decompose.h)
 * and projecting it to SH — is done once by hfs_scene_inputs_load; a
 * caller that edits only lights, the environment rotation or the preset
 * (the kiosk's knobs) calls hfs_scene_inputs_relight, which recomputes the
 * lighting and quality from the scene and touches no file.  The map itself
 * is kept too (env_map; 12 bytes a pixel, 24 MiB for 2048x1024): every
 * backend receives it in lighting.env_map, the ground truth integrates it.
 *
 * Kept out of libhfshade (hfshade_lib): it needs the file formats
 * (hfshade_io) and the scene parser (hfshade_scene), which the renderer
 * core must not depend on.  Library: hfshade_scene.
 *
 * Ownership: hfs_scene_inputs_load fills a caller-owned struct whose heights
 * it allocates; hfs_scene_inputs_free releases them (a zeroed struct is
 * fine).  field.z points into hm: do not copy the struct and free both.
 * Errors: 0 or a negative hfs_status with a one-line message naming the
 * file; nothing is printed (hm.holes says how many holes were filled, for
 * the caller to report).
 */
#ifndef HFS_SCENE_LOAD_H
#define HFS_SCENE_LOAD_H

#include "hfs_io.h"
#include "env_open.h"
#include "hfshade.h"
#include "scene.h"

typedef struct hfs_scene_inputs {
    hfs_heightmap hm;            /* the loaded heights (owned)               */
    hfs_field field;             /* view of hm with the scene's dx, zscale   */
    int has_env_map;             /* env_map_sh holds the map's projection    */
    double env_map_sh[3][HFS_SH_COEFFS]; /* with env-lights: the residual's   */
    float *env_map;              /* the map itself, env_map_width x
                                    env_map_height x 3 (owned), or NULL:
                                    lighting.env_map points here (the truth
                                    integrates it; other backends env_sh)   */
    int env_map_width, env_map_height;
    float *env_residual;         /* with lights decomposed from the map, the
                                    map without them (owned), else NULL     */
    int has_env_open;            /* env_open holds the open sky beyond order
                                    4 of env_residual or env_map; with
                                    env-shade = map lighting.env_open points
                                    here, env_shade_map to that map         */
    float env_open[HFS_ENV_OPEN_FLOATS];
    int n_env_keys;              /* env-lights: the map's lights (from_env),
                                    unrotated; relight appends them to the
                                    scene's key lights, rotated by env-rotate */
    hfs_key_light env_keys[HFS_MAX_KEY_LIGHTS];
    float *albedo_map;           /* the scene's albedo map, W*H*3 (owned), or NULL */
    hfs_lighting lighting;       /* from the scene (degrees -> radians)      */
    hfs_quality quality;         /* preset + quality keys of the scene       */
    uint64_t serial;             /* names the heights, for
                                    hfs_renderer_set_field_serial: not 0,
                                    never two loads the same in a process    */
} hfs_scene_inputs;

/* Validates the scene (hfs_scene_validate), loads its height field and
 * environment map, and fills lighting and quality: every input validated
 * (hfs_validate_field, then as hfs_scene_inputs_relight), the heights once
 * here.  On failure *in is freed and zeroed. */
int hfs_scene_inputs_load(const hfs_scene *s, hfs_scene_inputs *in, hfs_error *err);

/* Recomputes lighting and quality from s, which must describe the same
 * height field and environment as the scene in was loaded from (only
 * lights, env-rotate, albedo, preset and quality keys may differ), and
 * validates them (hfs_validate_lighting, hfs_validate_quality: no pass over
 * the heights, which do not change here).  Reads no file.  On failure (a
 * value the renderer refuses) in->lighting and in->quality are unchanged. */
int hfs_scene_inputs_relight(const hfs_scene *s, hfs_scene_inputs *in, hfs_error *err);

/* Frees the heights and zeroes *in.  NULL-safe. */
void hfs_scene_inputs_free(hfs_scene_inputs *in);

#endif /* HFS_SCENE_LOAD_H */
