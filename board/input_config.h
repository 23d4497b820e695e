/*
 * input_config.h — the board's input configuration: which control is wired
 * where, and what it does.  Parsed from an INI file by libinih
 * (input_config.c); board/kiosk.ini is the commented example.
 *
 *     [knob sun]                  ; a rotary encoder on two GPIO lines
 *     gpio = gpiochip0:17,18      ; chip (name, label or /dev path) : A,B
 *     steps_per_detent = 4        ; quadrature transitions per detent (1|2|4)
 *     action = key.azimuth        ; see hfs_action below
 *     light = 0                   ; which light (index), or "selected"
 *     step = 2                    ; action units per detent (degrees here)
 *     accel = 4                   ; gain at fast turns (1 = none)
 *     accel_ms = 30               ; detents closer than this are "fast"
 *     min = 0
 *     max = 360
 *     wrap = yes                  ; wrap around instead of clamping
 *
 *     [knob dial]                 ; the kernel's rotary-encoder driver
 *     evdev = /dev/input/by-path/platform-rotary-event:REL_X
 *     action = env.rotate
 *
 *     [button next]
 *     gpio = gpiochip0:22
 *     active_low = yes
 *     debounce_ms = 10
 *     action = light.select
 *
 *     [button up]                 ; a keyboard key (desktop use)
 *     evdev = /dev/input/event3:KEY_UP
 *     action = preset.next
 *
 * [capture NAME] sections (a camera whose frames become the heights) are
 * read by capture_config.c, docs/CAPTURE.md.
 *
 * A control whose section names no device (no gpio, no evdev) exists only
 * for the scripted source (replay), which names controls directly.
 * Errors name the file and line: "kiosk.ini:12: unknown action 'x'".
 */
#ifndef HFS_BOARD_INPUT_CONFIG_H
#define HFS_BOARD_INPUT_CONFIG_H

#include "capture_config.h"
#include "input.h"
#include "scene_keys.h"

#define HFS_MAX_CONTROLS 32

typedef enum hfs_action {
    HFS_ACTION_NONE = 0,
    HFS_ACTION_KEY_AZIMUTH,     /* key light phi, degrees                  */
    HFS_ACTION_KEY_ELEVATION,   /* key light elevation, degrees            */
    HFS_ACTION_KEY_RADIUS,      /* key light angular radius alpha, degrees */
    HFS_ACTION_KEY_RADIANCE,    /* key light radiance                      */
    HFS_ACTION_LOCAL_X,         /* local light centre, world units         */
    HFS_ACTION_LOCAL_Y,
    HFS_ACTION_LOCAL_Z,
    HFS_ACTION_LOCAL_RADIUS,    /* local light radius, world units         */
    HFS_ACTION_LOCAL_RADIANCE,
    HFS_ACTION_ENV_ROTATE,      /* environment rotation, degrees           */
    HFS_ACTION_LIGHT_SELECT,    /* knob: step through lights; button: next */
    HFS_ACTION_PRESET,          /* knob/button: next quality preset        */
    HFS_ACTION_OVERLAY,         /* button: frame-time overlay on/off       */
    HFS_ACTION_CAMERA_AZIMUTH,  /* 3-D view: where the camera stands, degrees */
    HFS_ACTION_CAMERA_ELEVATION,
    HFS_ACTION_CAMERA_ZOOM,     /* distance over the framing one (multiplies) */
    HFS_ACTION_VIEW,            /* button: the 3-D view on/off             */
    HFS_ACTION_SURFACE_ALBEDO,  /* the Lambertian albedo                   */
    HFS_ACTION_SURFACE_SPECULAR, /* the Phong lobe's specular albedo       */
    HFS_ACTION_SURFACE_GLOSS,   /* the Phong exponent (multiplies)         */
    HFS_ACTION_MAP_PAN_X,       /* the map (a DEM larger than the display):  */
    HFS_ACTION_MAP_PAN_Y,       /*   its view's centre, display pixels      */
    HFS_ACTION_MAP_ZOOM,        /* knob: +-1 level per detent; button: in   */
    HFS_ACTION_COUNT
} hfs_action;

typedef enum hfs_control_kind {
    HFS_CONTROL_KNOB = 1,
    HFS_CONTROL_BUTTON = 2
} hfs_control_kind;

typedef enum hfs_device_kind {
    HFS_DEVICE_NONE = 0,        /* replay only                             */
    HFS_DEVICE_GPIO,
    HFS_DEVICE_EVDEV
} hfs_device_kind;

typedef struct hfs_control_config {
    char name[HFS_CONTROL_NAME_MAX];
    hfs_control_kind kind;

    /* Where it is wired. */
    hfs_device_kind device;
    char path[256];             /* gpio: chip name/label/path; evdev: path  */
    int lines[2];               /* gpio: knob A,B; button: lines[0]         */
    int active_low;             /* gpio buttons                            */
    int steps_per_detent;       /* gpio knobs: 1, 2 or 4 (default 4)       */
    int debounce_ms;            /* gpio buttons (default 10)               */
    int evdev_type;             /* evdev: EV_REL, EV_ABS or EV_KEY          */
    int evdev_code;             /* evdev: REL_X, KEY_UP, ...                */

    /* What it does. */
    hfs_action action;
    int light;                  /* light index, or -1 = the selected one   */
    double step;                /* units per detent (default per action)   */
    double accel;               /* gain at fast turns (>= 1, default 1)    */
    double accel_ms;            /* detent spacing counted as fast          */
    double min, max;            /* limits (defaults per action)            */
    int wrap;                   /* wrap at the limits instead of clamping  */

    int config_line;            /* line of its [section] header, for messages */
} hfs_control_config;

typedef struct hfs_input_config {
    int n_controls;
    hfs_control_config control[HFS_MAX_CONTROLS];
    hfs_capture_configs captures;   /* [capture NAME] sections (capture_config.h) */
} hfs_input_config;

/* What an action does, its defaults and the values it accepts
 * (docs/INPUT.md "Actions" is this table in prose). */
typedef enum hfs_action_target {
    HFS_TARGET_NONE = 0,        /* no light                                 */
    HFS_TARGET_KEY,             /* a key light: light = key light index      */
    HFS_TARGET_LOCAL            /* a local light: light = local light index  */
} hfs_action_target;

typedef struct hfs_action_info {
    hfs_action action;
    const char *name;           /* "key.azimuth", as written in the file    */
    int knob, button;           /* which control kinds may drive it         */
    hfs_action_target target;
    int continuous;             /* step/accel/min/max/wrap apply            */
    int multiplicative;         /* a detent multiplies by step (radiance)   */
    double step, min, max;      /* defaults                                 */
    int wrap;                   /* default                                  */
    hfs_scene_key_id key;       /* continuous: the scene key and the number */
    int number;                 /* in it that the action edits (HFS_SK_COUNT:
                                   the kiosk's own state, accepting [min, max]) */
} hfs_action_info;

/* The entry for action, or NULL (HFS_ACTION_NONE, out of range). */
const hfs_action_info *hfs_action_get(hfs_action action);

/* What a continuous action accepts, min/max included: the range of the
 * scene key's number it edits (scene_keys.h), with 0 excluded for an action
 * that multiplies (a product never leaves 0). */
hfs_key_range hfs_action_range(const hfs_action_info *a);

/* The action written name ("env.rotate"), or HFS_ACTION_NONE. */
hfs_action hfs_action_from_name(const char *name);
/* The actions' names, ", "-separated, into buf (for messages). */
void hfs_action_names(char *buf, size_t size);

/* Reads an input configuration; 0, or HFS_E_IO / HFS_E_FORMAT with
 * "PATH:LINE: problem".  *cfg is complete and checked on success. */
int hfs_input_config_load(const char *path, hfs_input_config *cfg, hfs_error *err);

/* The control called name, or NULL. */
const hfs_control_config *hfs_input_config_find(const hfs_input_config *cfg,
                                                const char *name);

#endif /* HFS_BOARD_INPUT_CONFIG_H */
