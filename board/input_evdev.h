/*
 * input_evdev.h — knobs and buttons on a Linux input device, as a source.
 *
 * One source per device path serves every control of the configuration on
 * that path (device == HFS_DEVICE_EVDEV).  Mapping, per configured
 * (evdev_type, evdev_code):
 *   EV_REL (knob)   value v != 0 -> TURN by v detents (the rotary-encoder
 *                   driver's relative mode, REL_X/REL_DIAL/REL_WHEEL ...);
 *   EV_ABS (knob)   TURN by the change of the value since the last one.  An
 *                   axis is taken as circular with period max - min (the
 *                   rotary-encoder driver's "rollover" mode reports
 *                   0..steps-1 with max = steps): a change of more than half
 *                   the period is the short way round the wrap.  A clamped
 *                   axis never jumps that far between two events;
 *   EV_KEY (button) 1 -> PRESS, 0 -> RELEASE, 2 (autorepeat) ignored.
 * A knob must use EV_REL or EV_ABS, a button EV_KEY; a code is used by one
 * control per device.  SYN_DROPPED (the kernel queue overflowed) is handled
 * by libevdev's resync (LIBEVDEV_READ_FLAG_SYNC): keys and absolute axes
 * catch up with the device's state, relative motion in the gap is lost.
 *
 * Timestamps: the source asks the kernel for CLOCK_MONOTONIC event times
 * (EVIOCSCLOCKID, Linux >= 3.4).  Where that ioctl fails (emulators such as
 * umockdev) the device's timestamps are passed through unchanged.
 *
 * libevdev sits behind hfs_evdev_ops so tests can replace it; the core
 * (input_evdev.c) includes no libevdev header.
 */
#ifndef HFS_BOARD_INPUT_EVDEV_H
#define HFS_BOARD_INPUT_EVDEV_H

#include <linux/input.h>

#include "input.h"
#include "input_config.h"

/* next_event results besides -errno (same meaning as libevdev's
 * LIBEVDEV_READ_STATUS_SUCCESS / _SYNC). */
#define HFS_EVDEV_EVENT 0
#define HFS_EVDEV_SYNC 1

typedef struct hfs_evdev_ops {
    const char *name;           /* "libevdev", "fake"                       */
    void *ctx;
    /* Opens path read-only, non-blocking; *clock_monotonic = whether the
     * kernel agreed to CLOCK_MONOTONIC timestamps.  NULL + errno (ENOENT,
     * EACCES, ENOTTY: not an input device). */
    void *(*open)(void *ctx, const char *path, int *clock_monotonic);
    int (*fd)(void *h);
    int (*has_code)(void *h, unsigned type, unsigned code);
    /* An EV_ABS axis: range and current value; 0 or -errno. */
    int (*abs_info)(void *h, unsigned code, int *min, int *max, int *value);
    /* libevdev_next_event: sync = 0 normal reading, 1 draining a resync.
     * HFS_EVDEV_EVENT / HFS_EVDEV_SYNC with *ev, -EAGAIN (nothing now; in
     * sync mode: the resync is over), or -errno (-ENODEV: device gone). */
    int (*next_event)(void *h, int sync, struct input_event *ev);
    /* "REL_X" for messages, or NULL. */
    const char *(*code_name)(unsigned type, unsigned code);
    void (*close)(void *h);     /* NULL ok */
} hfs_evdev_ops;

/* The libevdev implementation (libevdev is required by the build). */
const hfs_evdev_ops *hfs_evdev_ops_libevdev(void);

/*
 * Creates the source for the device at path, serving every control of cfg
 * with device == HFS_DEVICE_EVDEV and path == path, and opens it (checking
 * the device has every configured code).  ops NULL = libevdev.
 * Returns 0 and *out (free with hfs_input_source_destroy), or
 *   HFS_E_INVALID      no control on that path, a wrong type for the kind,
 *                      a code used twice, or the device lacks a code;
 *   HFS_E_IO           cannot open ("evdev /dev/input/event3: permission
 *                      denied");
 *   HFS_E_NOMEM.
 * Name "evdev PATH".  Loss (ENODEV or any read error) -> HFS_E_IO "evdev
 * PATH: device removed (...)", closed until reopen succeeds.
 */
int hfs_evdev_source_create(const hfs_input_config *cfg, const char *path,
                            const hfs_evdev_ops *ops, hfs_input_source **out,
                            hfs_error *err);

/* Whether the open device delivers CLOCK_MONOTONIC timestamps (0 when
 * EVIOCSCLOCKID was refused, or closed). */
int hfs_evdev_source_monotonic(const hfs_input_source *src);

#endif /* HFS_BOARD_INPUT_EVDEV_H */
