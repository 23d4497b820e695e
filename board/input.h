/*
 * input.h — the board's input layer: knobs and buttons as one event stream.
 *
 * Every source (GPIO lines through libgpiod, Linux input devices through
 * libevdev, a recorded script) turns what it reads into the same small event:
 * a named control was turned by a number of detents, or pressed, or
 * released.  Decoding (quadrature, debounce) happens inside the source, so the
 * rest of the program sees detents, never edges.
 *
 * The kiosk polls every source's fd (hfs_input_source_fd) together with its
 * own timers, calls hfs_input_source_read when one is readable or when the
 * source's deadline (hfs_input_source_deadline) has passed, and hands each
 * event to the mapping (input_map.h), which edits the scene.
 *
 * Device loss: read returns HFS_E_IO ("gpiochip0: device removed") and the
 * source stays alive but closed (fd -1); the owner reports the line and calls
 * hfs_input_source_reopen later (input_set.h retries with a back-off).  Never
 * a crash, never an exit.
 *
 * Time is CLOCK_MONOTONIC nanoseconds throughout (hfs_input_now_ns), the
 * clock of the kernel's GPIO and evdev event timestamps, so latency can be
 * measured from the edge that completed a detent to the frame that shows it.
 */
#ifndef HFS_BOARD_INPUT_H
#define HFS_BOARD_INPUT_H

#include <stdint.h>

#include "hfshade.h"

#define HFS_CONTROL_NAME_MAX 32

typedef enum hfs_input_kind {
    HFS_INPUT_TURN = 1,    /* a knob moved by delta detents (+ = clockwise) */
    HFS_INPUT_PRESS = 2,   /* a button went down (after debounce)           */
    HFS_INPUT_RELEASE = 3  /* a button went up (after debounce)             */
} hfs_input_kind;

typedef struct hfs_input_event {
    int64_t t_ns;          /* CLOCK_MONOTONIC time of the edge or device
                              event that completed it                       */
    hfs_input_kind kind;
    int delta;             /* TURN only: signed detents, never 0            */
    char control[HFS_CONTROL_NAME_MAX]; /* the control's name (config)      */
} hfs_input_event;

typedef struct hfs_input_source hfs_input_source;

typedef struct hfs_input_source_ops {
    const char *kind;      /* "gpio", "evdev", "replay"                     */
    /* The fd to poll for POLLIN, or -1 (closed after a loss, or a source
     * driven by its deadline only, like a replay). */
    int (*fd)(hfs_input_source *src);
    /* CLOCK_MONOTONIC ns at which read must be called even without fd
     * activity (a pending debounce, the next replayed event), or INT64_MAX. */
    int64_t (*deadline_ns)(hfs_input_source *src);
    /* Drains what is pending without blocking; writes at most max events.
     * Returns the number written (>= 0), or a negative hfs_status with a
     * one-line message naming the device (HFS_E_IO: the device is gone; the
     * source is then closed until reopen succeeds). */
    int (*read)(hfs_input_source *src, int64_t now_ns, hfs_input_event *out,
                int max, hfs_error *err);
    /* Tries to open the device again after a loss: 0, or a negative status
     * (still gone) with a message. */
    int (*reopen)(hfs_input_source *src, hfs_error *err);
    void (*destroy)(hfs_input_source *src);
} hfs_input_source_ops;

/* Every source starts with this header; its ops do the rest. */
struct hfs_input_source {
    const hfs_input_source_ops *ops;
    char name[64];         /* for messages: "gpio gpiochip0", "replay FILE" */
};

static inline int hfs_input_source_fd(hfs_input_source *s) { return s->ops->fd(s); }
static inline int64_t hfs_input_source_deadline(hfs_input_source *s)
{
    return s->ops->deadline_ns(s);
}
static inline int hfs_input_source_read(hfs_input_source *s, int64_t now_ns,
                                        hfs_input_event *out, int max, hfs_error *err)
{
    return s->ops->read(s, now_ns, out, max, err);
}
static inline int hfs_input_source_reopen(hfs_input_source *s, hfs_error *err)
{
    return s->ops->reopen(s, err);
}
static inline void hfs_input_source_destroy(hfs_input_source *s)
{
    if (s)
        s->ops->destroy(s);
}

/* CLOCK_MONOTONIC now, in ns. */
int64_t hfs_input_now_ns(void);

#endif /* HFS_BOARD_INPUT_H */
