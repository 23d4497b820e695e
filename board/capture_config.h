/*
 * capture_config.h — the [capture NAME] sections of the kiosk's input
 * configuration (docs/CAPTURE.md "Configuration"); input_config.c reads the
 * file and hands these sections' keys here, so errors are "file:line:
 * problem" as for the knobs.
 *
 *     [capture sandbox]
 *     device = /dev/v4l/by-id/usb-Intel_RealSense-video-index0  ; or replay = DIR
 *     pace = time               ; replay: or shown (no frame skipped)
 *     format = Z16
 *     size = 640x480
 *     rate = 30
 *     role = heights            ; or environment (camera_env.h keys below)
 *     depth_scale = 0.001       ; metres per count
 *     plane = auto              ; or A B C: ground depth = A*u + B*v + C
 *     roi = 64 48 512 384       ; X Y W H pixels
 *     grid = 256x192            ; default: the scene's height field size
 *     zgain = 1                 ; world units per metre
 *     window = 8
 *     gate_mm = 3
 *     hysteresis_mm = 1.5
 *     jump_mm = 10
 *
 *     [capture sky]             ; role = environment
 *     device = /dev/video2
 *     format = YUYV             ; or GREY (the default for this role: YUYV)
 *     role = environment
 *     mapping = mirrorball      ; fisheye, equirect
 *     center = 320 240          ; the circle, pixels
 *     radius = 230
 *     fov = 180                 ; fisheye, degrees
 *     rotate = 90               ; azimuth of the image's up, degrees
 *     hemisphere = upper        ; or lower
 *     transfer = srgb           ; or linear
 *     exposure = 1              ; radiance of a full-scale white pixel
 *     env_size = 256x128        ; the environment map
 *     smoothing = 0.2           ; seconds (SH time constant)
 *     env_lights = auto         ; off, auto, N; default: the scene's
 */
#ifndef HFS_BOARD_CAPTURE_CONFIG_H
#define HFS_BOARD_CAPTURE_CONFIG_H

#include <stddef.h>

#include "camera_env.h"
#include "capture.h"
#include "depth_heights.h"

#define HFS_MAX_CAPTURES 2

typedef enum hfs_capture_role {
    HFS_ROLE_HEIGHTS = 1,
    HFS_ROLE_ENVIRONMENT = 2
} hfs_capture_role;

typedef struct hfs_capture_config {
    char name[32];
    char device[256];            /* a V4L2 node, or ""                     */
    char replay[256];            /* a recording directory, or ""           */
    int loop;                    /* replay: start again at the end         */
    int pace_shown;              /* replay: pace = shown (capture_record.h) */
    hfs_pixfmt format;           /* default Z16                            */
    int width, height;           /* 0: the driver's                        */
    int fps;                     /* 0: the driver's                        */
    int buffers;                 /* default 4                              */
    hfs_capture_role role;       /* default heights                        */
    hfs_depth_params depth;      /* grid_w 0: the scene's field size       */
    hfs_camenv_params env;       /* role = environment                     */
    int config_line;
} hfs_capture_config;

typedef struct hfs_capture_configs {
    int n;
    hfs_capture_config c[HFS_MAX_CAPTURES];
    int key_line[40];            /* parser state: lines of the current keys */
} hfs_capture_configs;

/* Parser hooks (input_config.c).  Each returns 0, or the line of the
 * problem with msg set (without the "file:line: " prefix). */
int hfs_capture_config_begin(hfs_capture_configs *cc, const char *name, int line, char *msg,
                             size_t size);
int hfs_capture_config_key(hfs_capture_configs *cc, const char *key, const char *value,
                           int line, char *msg, size_t size);
int hfs_capture_config_end(hfs_capture_configs *cc, char *msg, size_t size);

#endif /* HFS_BOARD_CAPTURE_CONFIG_H */
