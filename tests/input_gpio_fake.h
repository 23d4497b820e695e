/*
 * input_gpio_fake.h — a scripted GPIO chip behind hfs_gpio_ops, for tests.
 *
 * The chip answers to its name ("gpiochip0"), its label and "/dev/NAME".
 * A test sets line levels, queues edges with kernel-like timestamps, and
 * can unplug the chip (open fails with ENOENT, open handles read -ENODEV,
 * the fd turns readable so a poll loop notices) and plug it back.  The fd
 * is a pipe that is readable while edges are queued (or after a removal).
 * Counts open handles so tests can check nothing leaks.
 */
#ifndef HFS_TEST_INPUT_GPIO_FAKE_H
#define HFS_TEST_INPUT_GPIO_FAKE_H

#include "input_gpio.h"

#define FAKE_GPIO_LINES 64
#define FAKE_GPIO_QUEUE 256

typedef struct fake_gpio {
    hfs_gpio_ops ops;               /* pass &f->ops to the source          */
    char name[32], label[32];
    int present;                    /* 0: unplugged                        */
    int open_errno;                 /* forced open failure (EACCES), or 0   */
    int busy_line;                  /* request fails EBUSY if asked, or -1  */
    int n_lines;
    int level[FAKE_GPIO_LINES];     /* physical levels                     */
    int requested[FAKE_GPIO_LINES]; /* 1 while a handle holds the line     */
    hfs_gpio_edge queue[FAKE_GPIO_QUEUE];
    int q_head, q_n;
    int pipe[2];
    int signalled;                  /* one byte sits in the pipe           */
    int generation;                 /* bumped on unplug: old handles dead  */
    int open_handles;
    int opens;                      /* successful open_chip calls          */
} fake_gpio;

void fake_gpio_init(fake_gpio *f, const char *name, const char *label, int n_lines);
void fake_gpio_fini(fake_gpio *f);
/* Line `line` goes to `level` at t_ns; queued as an edge if requested and
 * the level changed. */
void fake_gpio_set(fake_gpio *f, unsigned line, int level, int64_t t_ns);
void fake_gpio_unplug(fake_gpio *f);
void fake_gpio_plug(fake_gpio *f);

#endif
