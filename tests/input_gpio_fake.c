/*
 * input_gpio_fake.c — see input_gpio_fake.h.
 */
#include "input_gpio_fake.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef struct fake_handle {
    fake_gpio *f;
    int generation;
    int n;
    unsigned offsets[FAKE_GPIO_LINES];
} fake_handle;

static void signal_on(fake_gpio *f)
{
    if (!f->signalled && write(f->pipe[1], "x", 1) == 1)
        f->signalled = 1;
}

static void signal_off(fake_gpio *f)
{
    char c;
    if (f->signalled && read(f->pipe[0], &c, 1) == 1)
        f->signalled = 0;
}

static void *fake_open_chip(void *ctx, const char *chip)
{
    fake_gpio *f = ctx;
    char dev[64];
    snprintf(dev, sizeof dev, "/dev/%s", f->name);
    if (f->open_errno) {
        errno = f->open_errno;
        return NULL;
    }
    if (!f->present || (strcmp(chip, f->name) && strcmp(chip, f->label) && strcmp(chip, dev))) {
        errno = ENOENT;
        return NULL;
    }
    fake_handle *h = calloc(1, sizeof *h);
    if (!h)
        return NULL;
    h->f = f;
    h->generation = f->generation;
    f->open_handles++;
    f->opens++;
    return h;
}

static int fake_request(void *vh, const unsigned *offsets, int n, const char *consumer)
{
    fake_handle *h = vh;
    fake_gpio *f = h->f;
    (void)consumer;
    if (h->generation != f->generation)
        return -ENODEV;
    for (int i = 0; i < n; ++i) {
        if ((int)offsets[i] >= f->n_lines)
            return -EINVAL;
        if ((int)offsets[i] == f->busy_line || f->requested[offsets[i]])
            return -EBUSY;
    }
    for (int i = 0; i < n; ++i) {
        f->requested[offsets[i]] = 1;
        h->offsets[i] = offsets[i];
    }
    h->n = n;
    return 0;
}

static int fake_fd(void *vh)
{
    return ((fake_handle *)vh)->f->pipe[0];
}

static int fake_read_edges(void *vh, hfs_gpio_edge *out, int max)
{
    fake_handle *h = vh;
    fake_gpio *f = h->f;
    if (h->generation != f->generation)
        return -ENODEV;
    int n = 0;
    while (n < max && f->q_n > 0) {
        out[n++] = f->queue[f->q_head];
        f->q_head = (f->q_head + 1) % FAKE_GPIO_QUEUE;
        f->q_n--;
    }
    if (f->q_n == 0)
        signal_off(f);
    return n;
}

static int fake_get_values(void *vh, int *values)
{
    fake_handle *h = vh;
    if (h->generation != h->f->generation)
        return -ENODEV;
    for (int i = 0; i < h->n; ++i)
        values[i] = h->f->level[h->offsets[i]];
    return 0;
}

static void fake_close(void *vh)
{
    fake_handle *h = vh;
    if (!h)
        return;
    if (h->generation == h->f->generation)
        for (int i = 0; i < h->n; ++i)
            h->f->requested[h->offsets[i]] = 0;
    h->f->open_handles--;
    free(h);
}

void fake_gpio_init(fake_gpio *f, const char *name, const char *label, int n_lines)
{
    memset(f, 0, sizeof *f);
    snprintf(f->name, sizeof f->name, "%s", name);
    snprintf(f->label, sizeof f->label, "%s", label);
    f->present = 1;
    f->busy_line = -1;
    f->n_lines = n_lines;
    if (pipe(f->pipe) != 0) {
        perror("pipe");
        exit(1);
    }
    fcntl(f->pipe[0], F_SETFL, O_NONBLOCK);
    f->ops.name = "fake";
    f->ops.ctx = f;
    f->ops.open_chip = fake_open_chip;
    f->ops.request = fake_request;
    f->ops.fd = fake_fd;
    f->ops.read_edges = fake_read_edges;
    f->ops.get_values = fake_get_values;
    f->ops.close = fake_close;
}

void fake_gpio_fini(fake_gpio *f)
{
    close(f->pipe[0]);
    close(f->pipe[1]);
}

void fake_gpio_set(fake_gpio *f, unsigned line, int level, int64_t t_ns)
{
    if ((int)line >= f->n_lines)
        return;
    int changed = f->level[line] != level;
    f->level[line] = level;
    if (!changed || !f->present || !f->requested[line] || f->q_n == FAKE_GPIO_QUEUE)
        return;
    int tail = (f->q_head + f->q_n) % FAKE_GPIO_QUEUE;
    f->queue[tail] = (hfs_gpio_edge){.offset = line, .level = level, .t_ns = t_ns};
    f->q_n++;
    signal_on(f);
}

void fake_gpio_unplug(fake_gpio *f)
{
    f->present = 0;
    f->generation++;
    f->q_n = 0;
    memset(f->requested, 0, sizeof f->requested);
    signal_on(f);   /* a poll loop must wake up and find the loss */
}

void fake_gpio_plug(fake_gpio *f)
{
    f->present = 1;
    signal_off(f);
}
