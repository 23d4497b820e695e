/*
 * input_gpio.h — knobs and buttons wired to GPIO lines, as an input source.
 *
 * One source per GPIO chip serves every control of the configuration wired
 * to that chip (hfs_control_config.device == HFS_DEVICE_GPIO and .path naming
 * the chip): a knob's two lines feed a quadrature decoder (quadrature.h), a
 * button's line feeds a debouncer (debounce.h) after active_low is applied.
 * Lines are requested as inputs with events on both edges; the kernel's edge
 * timestamps (CLOCK_MONOTONIC) become the events' t_ns.
 *
 * The chip is reached through a small table of operations (hfs_gpio_ops):
 * the real one wraps libgpiod (1.6.x or 2.x, chosen at build time, see
 * board/DEVICES.md); tests pass a scripted fake.  The source never calls
 * libgpiod directly.
 *
 * Errors are one line naming the chip: "gpio gpiochip7: no such chip",
 * "gpio gpiochip0: lines 17,18 busy (requested by another program)",
 * "gpio gpiochip0: device removed (No such device)".
 */
#ifndef HFS_BOARD_INPUT_GPIO_H
#define HFS_BOARD_INPUT_GPIO_H

#include <stddef.h>
#include <stdint.h>

#include "input.h"
#include "input_config.h"

/* One edge on one requested line. */
typedef struct hfs_gpio_edge {
    unsigned offset;   /* the line's offset on the chip                    */
    int level;         /* the physical level after the edge: 1 rising      */
    int64_t t_ns;      /* kernel timestamp, CLOCK_MONOTONIC                */
} hfs_gpio_edge;

/*
 * The chip, as the source needs it.  A handle is one open chip with (after
 * request) one set of requested lines.  Functions returning int give 0 /
 * a count, or -errno; open gives NULL with errno set.  errno values the
 * source turns into messages: ENOENT (no such chip), EACCES/EPERM, EBUSY
 * (line in use), EINVAL (bad offset), ENODEV (chip gone), ENOSYS (not
 * built).  Handles are not shared between threads.
 */
typedef struct hfs_gpio_ops {
    const char *name;  /* "libgpiod 1.6", "libgpiod 2", "fake" ...          */
    void *ctx;         /* passed to open_chip (the fake keeps its script)  */
    /* chip: a name ("gpiochip0"), a label ("pinctrl-bcm2711") or a path
     * ("/dev/gpiochip0"). */
    void *(*open_chip)(void *ctx, const char *chip);
    /* Requests n lines as inputs with both-edge events, labelled consumer.
     * Once per handle. */
    int (*request)(void *h, const unsigned *offsets, int n, const char *consumer);
    /* The one fd that is readable when any requested line has edges. */
    int (*fd)(void *h);
    /* Up to max pending edges, oldest first, without blocking: a count
     * (0 when none), or -errno (-ENODEV: the chip is gone). */
    int (*read_edges)(void *h, hfs_gpio_edge *out, int max);
    /* The physical levels of the n requested lines, in request order. */
    int (*get_values)(void *h, int *values);
    void (*close)(void *h);       /* releases the lines and the chip; NULL ok */
} hfs_gpio_ops;

/* The libgpiod implementation this build has; its open_chip fails with
 * ENOSYS when the library was built without libgpiod. */
const hfs_gpio_ops *hfs_gpio_ops_libgpiod(void);

/* Whether libgpiod was found at build time (0 = the ops above say ENOSYS). */
int hfs_gpio_available(void);

/*
 * Creates the source for chip, serving every control of cfg with
 * device == HFS_DEVICE_GPIO and path == chip (compared as written), and
 * opens it: opens the chip, requests the lines (consumer "hfshade"), reads
 * their levels to initialise the decoders.  ops NULL = libgpiod.
 *
 * Returns 0 and *out (free with hfs_input_source_destroy), or
 *   HFS_E_INVALID  no control on that chip, a line used twice, lines < 0;
 *   HFS_E_IO       the chip cannot be opened or its lines requested;
 *   HFS_E_UNSUPPORTED  built without libgpiod;
 *   HFS_E_NOMEM,
 * with a one-line message; *out is then NULL.
 *
 * The source's name is "gpio CHIP".  read() reports a lost chip as HFS_E_IO
 * and closes it; reopen() redoes the whole open (chip, request, levels) and
 * restarts the decoders from the lines' levels then (a turn or press under
 * way during the loss is dropped, never invented).
 */
int hfs_gpio_source_create(const hfs_input_config *cfg, const char *chip,
                           const hfs_gpio_ops *ops, hfs_input_source **out,
                           hfs_error *err);

#endif /* HFS_BOARD_INPUT_GPIO_H */
