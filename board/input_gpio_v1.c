/*
 * input_gpio_v1.c — hfs_gpio_ops over libgpiod 1.x (Debian 12: 1.6.3).
 *
 * libgpiod 1.x speaks the kernel's v1 GPIO uAPI, where every line requested
 * for events gets its own event fd and its own 16-entry kernel queue.  The
 * source wants one fd and one ordered stream, so this file:
 *   - puts the line fds (made non-blocking) in an epoll set and hands out the
 *     epoll fd: it is readable when any line is, and also on HUP/ERR, which
 *     read_edges turns into -ENODEV (the chip went away);
 *   - reads every line's queue completely, then merges the edges by kernel
 *     timestamp.  Edges on two lines microseconds apart across a read
 *     boundary can still come out of order; the quadrature decoder counts
 *     that as an invalid transition and resynchronises (no false detent).
 * Event timestamps: CLOCK_MONOTONIC on Linux >= 5.7 (CLOCK_REALTIME before;
 * see DEVICES.md).  The v1 uAPI has no debounce and no overflow counter.
 */
#include <errno.h>
#include <fcntl.h>
#include <gpiod.h>
#include <stdlib.h>
#include <string.h>
#include <sys/epoll.h>
#include <unistd.h>

#include "input_gpio.h"

#define V1_QUEUE 16     /* the kernel's per-line event queue (v1 uAPI) */

typedef struct v1_handle {
    struct gpiod_chip *chip;
    struct gpiod_line_bulk bulk;
    int requested;
    int epfd;
    /* Edges merged from every line, handed out from `pos`. */
    hfs_gpio_edge staged[GPIOD_LINE_BULK_MAX_LINES * V1_QUEUE];
    int pos, n;
} v1_handle;

static void *v1_open_chip(void *ctx, const char *chip)
{
    (void)ctx;
    v1_handle *h = calloc(1, sizeof *h);
    if (!h)
        return NULL;
    h->epfd = -1;
    /* Name ("gpiochip0"), number, label or /dev path. */
    errno = 0;
    h->chip = gpiod_chip_open_lookup(chip);
    if (!h->chip) {
        int e = errno ? errno : ENOENT;
        free(h);
        errno = e;
        return NULL;
    }
    gpiod_line_bulk_init(&h->bulk);
    return h;
}

static void v1_close(void *vh)
{
    v1_handle *h = vh;
    if (!h)
        return;
    if (h->epfd >= 0)
        close(h->epfd);
    if (h->requested)
        gpiod_line_release_bulk(&h->bulk);
    gpiod_chip_close(h->chip);
    free(h);
}

static int v1_request(void *vh, const unsigned *offsets, int n, const char *consumer)
{
    v1_handle *h = vh;
    if (n < 1 || n > GPIOD_LINE_BULK_MAX_LINES)
        return -EINVAL;
    if (gpiod_chip_get_lines(h->chip, (unsigned *)offsets, (unsigned)n, &h->bulk) < 0)
        return -(errno ? errno : EINVAL);
    if (gpiod_line_request_bulk_both_edges_events(&h->bulk, consumer) < 0)
        return -(errno ? errno : EIO);
    h->requested = 1;
    h->epfd = epoll_create1(EPOLL_CLOEXEC);
    if (h->epfd < 0)
        return -errno;
    for (int i = 0; i < n; ++i) {
        int fd = gpiod_line_event_get_fd(gpiod_line_bulk_get_line(&h->bulk, (unsigned)i));
        if (fd < 0)
            return -(errno ? errno : EIO);
        int fl = fcntl(fd, F_GETFL);
        if (fl < 0 || fcntl(fd, F_SETFL, fl | O_NONBLOCK) < 0)
            return -errno;
        struct epoll_event ev = {.events = EPOLLIN, .data.u32 = (uint32_t)i};
        if (epoll_ctl(h->epfd, EPOLL_CTL_ADD, fd, &ev) < 0)
            return -errno;
    }
    return 0;
}

static int v1_fd(void *vh)
{
    return ((v1_handle *)vh)->epfd;
}

/* Stable insertion sort by time: per-line order is already right, and the
 * batch is small (at most 64 lines x 16). */
static void sort_by_time(hfs_gpio_edge *e, int n)
{
    for (int i = 1; i < n; ++i) {
        hfs_gpio_edge x = e[i];
        int j = i;
        while (j > 0 && e[j - 1].t_ns > x.t_ns) {
            e[j] = e[j - 1];
            --j;
        }
        e[j] = x;
    }
}

static int v1_fill(v1_handle *h)
{
    /* A removed chip shows as HUP/ERR on the line fds. */
    struct epoll_event ready[GPIOD_LINE_BULK_MAX_LINES];
    int nr = epoll_wait(h->epfd, ready, GPIOD_LINE_BULK_MAX_LINES, 0);
    if (nr < 0 && errno != EINTR)
        return -errno;
    for (int i = 0; i < nr; ++i)
        if (ready[i].events & (EPOLLHUP | EPOLLERR))
            return -ENODEV;
    h->pos = h->n = 0;
    unsigned nl = gpiod_line_bulk_num_lines(&h->bulk);
    for (unsigned i = 0; i < nl; ++i) {
        struct gpiod_line *line = gpiod_line_bulk_get_line(&h->bulk, i);
        int fd = gpiod_line_event_get_fd(line);
        unsigned offset = gpiod_line_offset(line);
        for (;;) {
            struct gpiod_line_event ev[V1_QUEUE];
            int r = gpiod_line_event_read_fd_multiple(fd, ev, V1_QUEUE);
            if (r < 0) {
                if (errno == EAGAIN || errno == EINTR)
                    break;
                return -(errno ? errno : EIO);
            }
            for (int k = 0; k < r && h->n < (int)(sizeof h->staged / sizeof h->staged[0]); ++k) {
                hfs_gpio_edge *e = &h->staged[h->n++];
                e->offset = offset;
                e->level = ev[k].event_type == GPIOD_LINE_EVENT_RISING_EDGE;
                e->t_ns = (int64_t)ev[k].ts.tv_sec * 1000000000 + ev[k].ts.tv_nsec;
            }
            if (r < V1_QUEUE)
                break;
        }
    }
    sort_by_time(h->staged, h->n);
    return 0;
}

static int v1_read_edges(void *vh, hfs_gpio_edge *out, int max)
{
    v1_handle *h = vh;
    if (h->pos == h->n) {
        int r = v1_fill(h);
        if (r < 0)
            return r;
    }
    int n = 0;
    while (n < max && h->pos < h->n)
        out[n++] = h->staged[h->pos++];
    return n;
}

static int v1_get_values(void *vh, int *values)
{
    v1_handle *h = vh;
    if (gpiod_line_get_value_bulk(&h->bulk, values) < 0)
        return -(errno ? errno : EIO);
    return 0;
}

static const hfs_gpio_ops v1_ops = {
    .name = "libgpiod 1",
    .ctx = NULL,
    .open_chip = v1_open_chip,
    .request = v1_request,
    .fd = v1_fd,
    .read_edges = v1_read_edges,
    .get_values = v1_get_values,
    .close = v1_close,
};

const hfs_gpio_ops *hfs_gpio_ops_libgpiod(void)
{
    return &v1_ops;
}

int hfs_gpio_available(void)
{
    return 1;
}
