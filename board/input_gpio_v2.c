/*
 * input_gpio_v2.c — hfs_gpio_ops over libgpiod 2.x (Debian 13: 2.1).
 *
 * NOT COMPILED IN CI: the CI machine (Debian 12) has libgpiod 1.6.3 and
 * board/input_devices.cmake picks input_gpio_v1.c there.  Written against
 * the libgpiod 2.0 API (gpiod.h of v2.0..v2.2); build it on Debian 13 or with
 * a libgpiod 2 pkg-config in PKG_CONFIG_PATH and run test_input_gpio_sim.
 *
 * libgpiod 2 speaks the kernel's v2 uAPI: one request covers all the lines,
 * with one fd and one event queue, so edges arrive already in order across
 * lines (unlike v1, see input_gpio_v1.c).  The event clock is asked for
 * explicitly (MONOTONIC, the kiosk's clock).  Reads never block: we ask
 * gpiod_line_request_wait_edge_events with a zero timeout first.
 */
#include <dirent.h>
#include <errno.h>
#include <gpiod.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "input_gpio.h"

#define V2_BATCH 64

typedef struct v2_handle {
    struct gpiod_chip *chip;
    struct gpiod_line_request *req;
    struct gpiod_edge_event_buffer *buf;
    int n;
    unsigned offsets[2 * HFS_MAX_CONTROLS];
} v2_handle;

static int all_digits(const char *s)
{
    if (!*s)
        return 0;
    for (; *s; ++s)
        if (*s < '0' || *s > '9')
            return 0;
    return 1;
}

/* Finds the chip whose label is `label` among /dev/gpiochip*. */
static struct gpiod_chip *open_by_label(const char *label)
{
    DIR *dir = opendir("/dev");
    if (!dir)
        return NULL;
    struct gpiod_chip *found = NULL;
    int denied = 0;
    struct dirent *de;
    while (!found && (de = readdir(dir)) != NULL) {
        if (strncmp(de->d_name, "gpiochip", 8) != 0)
            continue;
        char path[300];
        snprintf(path, sizeof path, "/dev/%s", de->d_name);
        if (!gpiod_is_gpiochip_device(path))
            continue;
        struct gpiod_chip *chip = gpiod_chip_open(path);
        if (!chip) {
            denied |= errno == EACCES || errno == EPERM;
            continue;
        }
        struct gpiod_chip_info *info = gpiod_chip_get_info(chip);
        if (info && strcmp(gpiod_chip_info_get_label(info), label) == 0)
            found = chip;
        else
            gpiod_chip_close(chip);
        gpiod_chip_info_free(info);
    }
    closedir(dir);
    if (!found)
        errno = denied ? EACCES : ENOENT;
    return found;
}

static void *v2_open_chip(void *ctx, const char *chip)
{
    (void)ctx;
    v2_handle *h = calloc(1, sizeof *h);
    if (!h)
        return NULL;
    char path[300];
    errno = 0;
    if (chip[0] == '/') {
        h->chip = gpiod_chip_open(chip);
    } else if (strncmp(chip, "gpiochip", 8) == 0) {
        snprintf(path, sizeof path, "/dev/%s", chip);
        h->chip = gpiod_chip_open(path);
    } else if (all_digits(chip)) {
        snprintf(path, sizeof path, "/dev/gpiochip%s", chip);
        h->chip = gpiod_chip_open(path);
    } else {
        h->chip = open_by_label(chip);
    }
    if (!h->chip) {
        int e = errno ? errno : ENOENT;
        free(h);
        errno = e;
        return NULL;
    }
    return h;
}

static void v2_close(void *vh)
{
    v2_handle *h = vh;
    if (!h)
        return;
    if (h->req)
        gpiod_line_request_release(h->req);
    gpiod_edge_event_buffer_free(h->buf);
    gpiod_chip_close(h->chip);
    free(h);
}

static int v2_request(void *vh, const unsigned *offsets, int n, const char *consumer)
{
    v2_handle *h = vh;
    if (n < 1 || n > (int)(sizeof h->offsets / sizeof h->offsets[0]))
        return -EINVAL;
    memcpy(h->offsets, offsets, (size_t)n * sizeof *offsets);
    h->n = n;

    int ret = -ENOMEM;
    struct gpiod_line_settings *ls = gpiod_line_settings_new();
    struct gpiod_line_config *lc = gpiod_line_config_new();
    struct gpiod_request_config *rc = gpiod_request_config_new();
    h->buf = gpiod_edge_event_buffer_new(V2_BATCH);
    if (!ls || !lc || !rc || !h->buf)
        goto out;
    if (gpiod_line_settings_set_direction(ls, GPIOD_LINE_DIRECTION_INPUT) < 0 ||
        gpiod_line_settings_set_edge_detection(ls, GPIOD_LINE_EDGE_BOTH) < 0 ||
        gpiod_line_settings_set_event_clock(ls, GPIOD_LINE_CLOCK_MONOTONIC) < 0 ||
        gpiod_line_config_add_line_settings(lc, h->offsets, (size_t)n, ls) < 0) {
        ret = -(errno ? errno : EINVAL);
        goto out;
    }
    gpiod_request_config_set_consumer(rc, consumer);
    /* Room for a fast knob between two frames (the default is 16 x lines). */
    gpiod_request_config_set_event_buffer_size(rc, (size_t)(32 * n));
    errno = 0;
    h->req = gpiod_chip_request_lines(h->chip, rc, lc);
    ret = h->req ? 0 : -(errno ? errno : EIO);
out:
    gpiod_request_config_free(rc);
    gpiod_line_config_free(lc);
    gpiod_line_settings_free(ls);
    return ret;
}

static int v2_fd(void *vh)
{
    return gpiod_line_request_get_fd(((v2_handle *)vh)->req);
}

static int v2_read_edges(void *vh, hfs_gpio_edge *out, int max)
{
    v2_handle *h = vh;
    if (max > V2_BATCH)
        max = V2_BATCH;
    if (max < 1)
        return 0;
    int w = gpiod_line_request_wait_edge_events(h->req, 0);
    if (w < 0)
        return -(errno ? errno : EIO);
    if (w == 0)
        return 0;
    int r = gpiod_line_request_read_edge_events(h->req, h->buf, (size_t)max);
    if (r < 0)
        return -(errno ? errno : EIO);
    for (int i = 0; i < r; ++i) {
        struct gpiod_edge_event *ev = gpiod_edge_event_buffer_get_event(h->buf, (unsigned long)i);
        out[i].offset = gpiod_edge_event_get_line_offset(ev);
        out[i].level = gpiod_edge_event_get_event_type(ev) == GPIOD_EDGE_EVENT_RISING_EDGE;
        out[i].t_ns = (int64_t)gpiod_edge_event_get_timestamp_ns(ev);
    }
    return r;
}

static int v2_get_values(void *vh, int *values)
{
    v2_handle *h = vh;
    enum gpiod_line_value v[2 * HFS_MAX_CONTROLS];
    if (gpiod_line_request_get_values_subset(h->req, (size_t)h->n, h->offsets, v) < 0)
        return -(errno ? errno : EIO);
    for (int i = 0; i < h->n; ++i) {
        if (v[i] == GPIOD_LINE_VALUE_ERROR)
            return -EIO;
        values[i] = v[i] == GPIOD_LINE_VALUE_ACTIVE; /* active-high: physical */
    }
    return 0;
}

static const hfs_gpio_ops v2_ops = {
    .name = "libgpiod 2",
    .ctx = NULL,
    .open_chip = v2_open_chip,
    .request = v2_request,
    .fd = v2_fd,
    .read_edges = v2_read_edges,
    .get_values = v2_get_values,
    .close = v2_close,
};

const hfs_gpio_ops *hfs_gpio_ops_libgpiod(void)
{
    return &v2_ops;
}

int hfs_gpio_available(void)
{
    return 1;
}
