/*
 * capture_live.h — a configured camera as a live height source or a live
 * sky: the [capture NAME] section (capture_config.h) opened as a V4L2
 * device or a recording, each newest frame recorded (optionally) and
 * converted to heights (depth_heights.h) or to lighting (camera_sky.h),
 * device loss handled (backoff.h).  What the
 * kiosk runs (board/kiosk_capture.c), and what the tests run against the
 * fake device.
 *
 *     n += hfs_capture_live_pollfd(live, fds + n, &deadline);
 *     ... poll ...
 *     if (hfs_capture_live_drain(live, now) == 1)
 *         field.z = hfs_capture_live_heights(live, &w, &h, &serial);
 *
 * Device loss (HFS_E_IO from the source): one log line, the device closed,
 * reopened with the knobs' back-off (100 ms doubling to 5 s; a new reason
 * is logged once, "NAME: back" when it returns); the heights stay those of
 * the last good frame.  A malformed frame, or one the conversion refuses,
 * is skipped with one warning per distinct message.  Never fatal.
 */
#ifndef HFS_BOARD_CAPTURE_LIVE_H
#define HFS_BOARD_CAPTURE_LIVE_H

#include <poll.h>
#include <stdint.h>

#include "camera_sky.h"
#include "capture.h"
#include "capture_config.h"
#include "capture_v4l2.h"

typedef void (*hfs_capture_log_fn)(void *user, int warning, const char *line);

typedef struct hfs_capture_live_desc {
    const hfs_capture_config *config;  /* either role; not kept              */
    const char *config_path;           /* for messages ("kiosk.ini:12: ...") */
    int grid_w, grid_h;                /* when the config gives no grid       */
    const char *record_dir;            /* --capture-record, or NULL           */
    int64_t start_ns;                  /* a replay's clock starts here        */
    const hfs_v4l2_ops *ops;           /* NULL: the real system calls         */
    hfs_capture_log_fn log;            /* NULL: silent                        */
    void *log_user;
    int64_t retry_min_ns, retry_max_ns;/* 0: 100 ms, 5 s                      */
    int scene_env_lights;              /* role = environment: the scene's     */
    int scene_keys;                    /* env-lights and key light count      */
} hfs_capture_live_desc;

typedef struct hfs_capture_live hfs_capture_live;

/* Opens the source (strict, as the knobs: a device missing at start is an
 * error naming it) and the recording. */
int hfs_capture_live_open(const hfs_capture_live_desc *d, hfs_capture_live **out,
                          hfs_error *err);
/* Closes the recording (its error, if any, into err: -1). NULL ok. */
int hfs_capture_live_close(hfs_capture_live *l, hfs_error *err);

/* The source's fd into *fd (returns 1) or none (0); *deadline lowered to
 * a replay's next frame or the next reopen attempt. */
int hfs_capture_live_pollfd(hfs_capture_live *l, struct pollfd *fd, int64_t *deadline);
/* Reopens when due, takes the newest frame, converts it: 1 when the
 * heights (or, role = environment, the lighting) changed, 0 otherwise. */
int hfs_capture_live_drain(hfs_capture_live *l, int64_t now_ns);
/* The heights (grid, finite, world units) and their serial: 0 before the
 * first frame (then NULL), a new one per change, never a scene load's
 * (those count from 1; these from 2^62).  NULL for role = environment. */
const float *hfs_capture_live_heights(const hfs_capture_live *l, int *width, int *height,
                                      uint64_t *serial);

/* role = environment: the lighting (camera_sky.h: smoothed SH, lights) of
 * the frames so far, or NULL (none yet, or role = heights); its serial as
 * the heights'. */
const hfs_camsky_out *hfs_capture_live_sky(const hfs_capture_live *l, uint64_t *serial);

typedef struct hfs_capture_live_stats {
    const char *name;         /* the section's NAME (valid while l is open) */
    uint32_t sequence;        /* the last converted frame                   */
    int64_t t_ns;             /* its capture time                            */
    int64_t cpu_ns;           /* thread CPU of the last drain (read, record, */
                              /* convert, filter)                            */
    long frames, dropped, superseded;
    int lost;                 /* the device is gone, waiting for a reopen    */
    int finished;             /* a replay played to its end                  */
    int replay;               /* the source is a recording                   */
} hfs_capture_live_stats;

void hfs_capture_live_stats_get(const hfs_capture_live *l, hfs_capture_live_stats *s);

#endif /* HFS_BOARD_CAPTURE_LIVE_H */
