/*
 * input_set.h — all the kiosk's input sources behind one poll loop.
 *
 * Built from an hfs_input_config: one GPIO source per chip named by the
 * controls, one evdev source per device path, in configuration order, plus
 * any extra source the caller adds (the replay source).  The kiosk loop:
 *
 *     struct pollfd fds[HFS_INPUT_SET_MAX];
 *     int64_t deadline;
 *     int nfds = hfs_input_set_pollfds(set, fds, HFS_INPUT_SET_MAX, &deadline);
 *     ... poll(fds, nfds, timeout until min(deadline, own timers)) ...
 *     int n = hfs_input_set_dispatch(set, hfs_input_now_ns(), events, max);
 *
 * Device loss never stops the set: a source whose read reports HFS_E_IO is
 * logged once (its one-line message, via the log callback), closed, and
 * reopened with a back-off (100 ms, doubling to 5 s by default); the
 * deadline includes the next attempt.  Its recovery is logged once
 * ("gpio gpiochip0: back").  A reopen failing for a new reason (e.g.
 * "permission denied" after "no such chip") is logged too; the same reason
 * again is not.
 *
 * Start-up is strict: a device that cannot be opened when the set is created
 * is an error (a typo in kiosk.ini should not look like an unplugged knob).
 * The set owns its sources.  Not thread-safe.
 */
#ifndef HFS_BOARD_INPUT_SET_H
#define HFS_BOARD_INPUT_SET_H

#include <poll.h>
#include <stdint.h>

#include "input.h"
#include "input_config.h"
#include "input_evdev.h"
#include "input_gpio.h"

#define HFS_INPUT_SET_MAX 40    /* sources: every control on its own + extras */

typedef void (*hfs_input_log_fn)(void *user, const char *line);

typedef struct hfs_input_set_desc {
    const hfs_input_config *config;   /* required; not kept after create  */
    hfs_input_log_fn log;             /* NULL: losses are not reported     */
    void *log_user;
    int64_t retry_min_ns;             /* 0 = 100 ms                        */
    int64_t retry_max_ns;             /* 0 = 5 s                           */
    const hfs_gpio_ops *gpio_ops;     /* NULL = libgpiod (tests: a fake)   */
    const hfs_evdev_ops *evdev_ops;   /* NULL = libevdev                   */
} hfs_input_set_desc;

typedef struct hfs_input_set hfs_input_set;

/* Creates the sources of desc->config (none is fine: a replay-only kiosk).
 * 0 and *out, or the first source's error (its message names the device);
 * *out is then NULL. */
int hfs_input_set_create(const hfs_input_set_desc *desc, hfs_input_set **out,
                         hfs_error *err);

/* Adds an open source; the set owns it from now on, also when this fails
 * (HFS_E_INVALID: the set is full; the source is destroyed). */
int hfs_input_set_add(hfs_input_set *set, hfs_input_source *src, hfs_error *err);

void hfs_input_set_destroy(hfs_input_set *set);   /* NULL ok */

int hfs_input_set_count(const hfs_input_set *set);
hfs_input_source *hfs_input_set_source(hfs_input_set *set, int i);
/* 1 while source i is closed after a loss and waiting for a reopen. */
int hfs_input_set_is_lost(const hfs_input_set *set, int i);

/* Fills fds with the open sources' fds (events = POLLIN) and returns how
 * many (<= max); *deadline_ns = the earliest time dispatch must be called
 * without fd activity (a source's deadline or the next reopen attempt), or
 * INT64_MAX. */
int hfs_input_set_pollfds(hfs_input_set *set, struct pollfd *fds, int max,
                          int64_t *deadline_ns);

/* After poll: drains every open source (reads never block), tries the
 * reopens that are due, and writes at most max events, source by source.
 * Returns the number written.  Losses and recoveries go to the log. */
int hfs_input_set_dispatch(hfs_input_set *set, int64_t now_ns, hfs_input_event *out,
                           int max);

#endif /* HFS_BOARD_INPUT_SET_H */
