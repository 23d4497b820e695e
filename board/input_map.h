/*
 * input_map.h — what an input event does to the scene.
 *
 * The kiosk owns one hfs_input_state next to its hfs_scene and hands every
 * event from every source to hfs_input_apply, which edits the scene in
 * place (angles in degrees, as in scene.h) according to the control's
 * configuration (input_config.h).  The caller re-renders when it returns 1;
 * after a preset change it recomputes the quality (hfs_scene_quality).
 *
 * Lights are numbered as one list for selection: key lights first
 * (0..n_key-1), then local lights (n_key..n_key+n_local-1).  A control with
 * light = "selected" acts on the selected light when it is of the action's
 * kind (a key.* knob does nothing while a local light is selected); a control
 * with a fixed light index acts on that key (or local) light, if the scene
 * has it (hfs_input_check_scene says at start-up when it does not).
 *
 * Acceleration (docs/INPUT.md "Acceleration"): a turn whose detents come
 * less than accel_ms apart, in the same direction as the previous turn of
 * that knob, moves by step * gain per detent, where the gain rises linearly
 * from 1 (at accel_ms apart) to accel (at 0 apart):
 *     spacing = (t - t_previous) / |delta|
 *     gain    = 1 + (accel - 1) * (1 - spacing / accel_ms)   if spacing < accel_ms
 *             = 1                                          otherwise
 * Additive actions add delta * step * gain; multiplicative ones (radiance)
 * multiply by step ^ (delta * gain).  Then the value wraps into [min, max)
 * or is clamped to [min, max].
 *
 * No allocation, no I/O; deterministic for a given event sequence.
 */
#ifndef HFS_BOARD_INPUT_MAP_H
#define HFS_BOARD_INPUT_MAP_H

#include <stdint.h>

#include "input_config.h"
#include "scene.h"

/* The quality presets a preset.next control cycles through, in order. */
#define HFS_INPUT_N_PRESETS 3

typedef struct hfs_input_state {
    int selected;       /* selected light, in the numbering above          */
    int preset;         /* 0..HFS_INPUT_N_PRESETS-1 (kiosk, panel, headless) */
    int overlay;        /* frame-time overlay shown (overlay.toggle)       */
    int view;           /* the 3-D view shown (view.toggle)                 */
    double cam_azimuth, cam_elevation; /* degrees (camera.azimuth, .elevation) */
    double cam_zoom;    /* distance over the framing one (camera.zoom)     */
    /* The map (board/kiosk_map.h: a field larger than the display), set
     * by the kiosk: map_levels 0 = no map, the map.* actions do nothing.
     * map_x, map_y: the view's centre in texels of the field (level 0),
     * kept within [0, map_w] x [0, map_h]; map_level: the level shown,
     * 0 (a texel a pixel) .. map_levels - 1 (the whole field). */
    int map_levels, map_w, map_h;
    int map_level;
    double map_x, map_y;
    /* Per control (same index as cfg->control): the last turn, for
     * acceleration.  Bookkeeping only: it does not count as a change. */
    struct {
        int64_t t_ns;
        int dir;        /* +1, -1; 0 = no turn yet                         */
    } last_turn[HFS_MAX_CONTROLS];
} hfs_input_state;

/* Light 0 selected, the scene's preset ("" = kiosk), overlay and view
 * off, the camera at HFS_INPUT_CAMERA_* (a view from the south-west, 38
 * degrees up, framing the field). */
#define HFS_INPUT_CAMERA_AZIMUTH 250.0
#define HFS_INPUT_CAMERA_ELEVATION 38.0
void hfs_input_state_init(hfs_input_state *st, const hfs_scene *scene);

/* Applies one event.  Returns 1 if the scene or the state (selection,
 * preset, overlay) changed, 0 if not (clamped at a limit, a release, a key
 * action while a local light is selected, a light the scene lacks), or
 * HFS_E_INVALID with a one-line message for an event no configured control
 * can take (unknown control; a turn for a button or a press for a knob). */
int hfs_input_apply(const hfs_input_config *cfg, hfs_input_state *st,
                    const hfs_input_event *ev, hfs_scene *scene, hfs_error *err);

/* The acceleration gain for |delta| detents dt_ns after the previous
 * turn of the same knob (same direction); >= 1.  See above. */
double hfs_input_gain(const hfs_control_config *k, int64_t dt_ns, int delta);

/* "kiosk", "panel", "headless" for 0..2; NULL otherwise. */
const char *hfs_input_preset_name(int index);

/* Checks that every control with a fixed light index names a light the
 * scene has: 0, or HFS_E_INVALID "CONTROL: light N: the scene has M key
 * lights". */
int hfs_input_check_scene(const hfs_input_config *cfg, const hfs_scene *scene,
                          hfs_error *err);

#endif /* HFS_BOARD_INPUT_MAP_H */
