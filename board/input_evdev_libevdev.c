/*
 * input_evdev_libevdev.c — hfs_evdev_ops over libevdev.
 *
 * libevdev keeps the device's state (keys, axes), which is what makes its
 * SYN_DROPPED resync possible; we only add the open (non-blocking, CLOEXEC)
 * and the EVIOCSCLOCKID request for CLOCK_MONOTONIC timestamps.  libevdev's
 * own log lines (it reports caller bugs there) are dropped: this library
 * never prints, errors come back as return codes.
 */
#include <errno.h>
#include <fcntl.h>
#include <libevdev/libevdev.h>
#include <stdarg.h>
#include <stdlib.h>
#include <sys/ioctl.h>
#include <time.h>
#include <unistd.h>

#include "input_evdev.h"

typedef struct lev_handle {
    int fd;
    struct libevdev *dev;
} lev_handle;

static void quiet_log(const struct libevdev *dev, enum libevdev_log_priority priority,
                      void *data, const char *file, int line, const char *func,
                      const char *format, va_list args)
{
    (void)dev, (void)priority, (void)data, (void)file, (void)line, (void)func;
    (void)format, (void)args;
}

static void *lev_open(void *ctx, const char *path, int *clock_monotonic)
{
    (void)ctx;
    *clock_monotonic = 0;
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        return NULL;
    /* Before libevdev reads anything, so every event it hands out is on
     * the kiosk's clock.  Refused only by emulators (kernel >= 3.4). */
    int clk = CLOCK_MONOTONIC;
    *clock_monotonic = ioctl(fd, EVIOCSCLOCKID, &clk) == 0;
    lev_handle *h = calloc(1, sizeof *h);
    struct libevdev *dev = libevdev_new();
    if (!h || !dev) {
        free(h);
        libevdev_free(dev);
        close(fd);
        errno = ENOMEM;
        return NULL;
    }
    libevdev_set_device_log_function(dev, quiet_log, LIBEVDEV_LOG_ERROR, NULL);
    int r = libevdev_set_fd(dev, fd);
    if (r < 0) {
        libevdev_free(dev);
        free(h);
        close(fd);
        errno = -r;
        return NULL;
    }
    h->fd = fd;
    h->dev = dev;
    return h;
}

static int lev_fd(void *vh)
{
    return ((lev_handle *)vh)->fd;
}

static int lev_has_code(void *vh, unsigned type, unsigned code)
{
    return libevdev_has_event_code(((lev_handle *)vh)->dev, type, code);
}

static int lev_abs_info(void *vh, unsigned code, int *min, int *max, int *value)
{
    const struct input_absinfo *a = libevdev_get_abs_info(((lev_handle *)vh)->dev, code);
    if (!a)
        return -EINVAL;
    *min = a->minimum;
    *max = a->maximum;
    *value = a->value;
    return 0;
}

static int lev_next_event(void *vh, int sync, struct input_event *ev)
{
    int r = libevdev_next_event(((lev_handle *)vh)->dev,
                                sync ? LIBEVDEV_READ_FLAG_SYNC : LIBEVDEV_READ_FLAG_NORMAL, ev);
    if (r == LIBEVDEV_READ_STATUS_SUCCESS)
        return HFS_EVDEV_EVENT;
    if (r == LIBEVDEV_READ_STATUS_SYNC)
        return HFS_EVDEV_SYNC;
    return r < 0 ? r : -EIO;
}

static const char *lev_code_name(unsigned type, unsigned code)
{
    return libevdev_event_code_get_name(type, code);
}

static void lev_close(void *vh)
{
    lev_handle *h = vh;
    if (!h)
        return;
    libevdev_free(h->dev);
    close(h->fd);
    free(h);
}

static const hfs_evdev_ops lev_ops = {
    .name = "libevdev",
    .open = lev_open,
    .fd = lev_fd,
    .has_code = lev_has_code,
    .abs_info = lev_abs_info,
    .next_event = lev_next_event,
    .code_name = lev_code_name,
    .close = lev_close,
};

const hfs_evdev_ops *hfs_evdev_ops_libevdev(void)
{
    return &lev_ops;
}
