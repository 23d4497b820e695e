/*
 * input_gpio_none.c — hfs_gpio_ops when libgpiod was not found at build
 * time: opening any chip fails with ENOSYS, which the GPIO source reports as
 * "gpio CHIP: not built (libgpiod was not found at build time)" and
 * HFS_E_UNSUPPORTED.  Sources with a test's ops table still work.
 */
#include <errno.h>
#include <stddef.h>

#include "input_gpio.h"

static void *none_open_chip(void *ctx, const char *chip)
{
    (void)ctx;
    (void)chip;
    errno = ENOSYS;
    return NULL;
}

static int none_request(void *h, const unsigned *offsets, int n, const char *consumer)
{
    (void)h, (void)offsets, (void)n, (void)consumer;
    return -ENOSYS;
}

static int none_fd(void *h)
{
    (void)h;
    return -1;
}

static int none_read_edges(void *h, hfs_gpio_edge *out, int max)
{
    (void)h, (void)out, (void)max;
    return -ENOSYS;
}

static int none_get_values(void *h, int *values)
{
    (void)h, (void)values;
    return -ENOSYS;
}

static void none_close(void *h)
{
    (void)h;
}

static const hfs_gpio_ops none_ops = {
    .name = "none",
    .open_chip = none_open_chip,
    .request = none_request,
    .fd = none_fd,
    .read_edges = none_read_edges,
    .get_values = none_get_values,
    .close = none_close,
};

const hfs_gpio_ops *hfs_gpio_ops_libgpiod(void)
{
    return &none_ops;
}

int hfs_gpio_available(void)
{
    return 0;
}
