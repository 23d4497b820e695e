/*
 * camera_sky.h — camera frames as the lighting: each frame converted to an
 * environment map (camera_env.h), its lights extracted with identities
 * (env_decompose.h's tracker, when lights are asked for), and the SH of
 * the rest smoothed in time (docs/CAPTURE.md "Camera to environment").
 *
 * Smoothing: an exponential moving average of the SH coefficients (and of
 * each tracked light's radiance, matched by identity) with time constant
 * tau = smoothing_s: a frame dt seconds after the previous one moves the
 * average by a = 1 - exp(-dt / tau) toward it (tau 0: no smoothing; dt from
 * the frames' capture times, clamped to [0, 10] s).  8-bit sensor noise is
 * already averaged by the projection over ~32k texels; the average keeps
 * what is left, and auto-exposure steps, from flickering the image.  When
 * the set of lights changes (one appears or vanishes) the average restarts
 * at that frame (a = 1), so lights + residual keep the map's energy.
 * Light directions are not averaged here: the tracker's alpha-beta filter
 * follows a moving sun without lag.
 */
#ifndef HFS_BOARD_CAMERA_SKY_H
#define HFS_BOARD_CAMERA_SKY_H

#include "camera_env.h"
#include "env_decompose.h"

typedef struct hfs_camsky_out {
    double sh[3][HFS_SH_COEFFS];   /* the residual's (no lights: the map's)  */
    int n_keys;                    /* extracted lights, from_env = 1          */
    hfs_key_light keys[HFS_MAX_KEY_LIGHTS];
    int ids[HFS_MAX_KEY_LIGHTS];   /* the tracker's identities               */
} hfs_camsky_out;

typedef struct hfs_camsky hfs_camsky;

/* max_lights: 0 no extraction, 1..HFS_MAX_KEY_LIGHTS at most that many. */
int hfs_camsky_create(const hfs_camenv_params *p, int max_lights, hfs_camsky **out,
                      hfs_error *err);
void hfs_camsky_destroy(hfs_camsky *s);
/* One frame; the lighting in hfs_camsky_get afterwards.  On error (a frame
 * of the wrong format) the lighting stays as it was. */
int hfs_camsky_push(hfs_camsky *s, const hfs_capture_frame *f, hfs_error *err);
const hfs_camsky_out *hfs_camsky_get(const hfs_camsky *s);
/* The last frame's map (map_w x map_h x 3; with lights: the residual). */
const float *hfs_camsky_map(const hfs_camsky *s, int *w, int *h);

/* The lights the capture section and the scene ask for: cfg_lights (-2:
 * the scene's), scene_lights (scene env-lights: 0, -1 auto, N), limited to
 * what fits beside scene_keys key lights.  Auto: the decomposition's
 * default (4). */
int hfs_camsky_max_lights(int cfg_lights, int scene_lights, int scene_keys);

#endif /* HFS_BOARD_CAMERA_SKY_H */
