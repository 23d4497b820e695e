/*
 * capture_preload.c — an LD_PRELOAD shim that makes /dev/video-fake a
 * camera for a whole process (hfshade-kiosk in kiosk_capture_loss.sh): the
 * fake device of capture_fake.c behind the real open/close/ioctl/mmap/
 * munmap, with an eventfd as its file descriptor (readable when a frame is
 * done, so the kiosk's own ppoll works) and a thread producing a 320x240
 * Z16 frame every 33 ms: a floor 1 m away with a block 20 cm high moving
 * across.  Every other path goes to the C library.
 *
 * Environment: HFS_FAKE_GONE_AT (frame number at which the device is
 * unplugged: ENODEV to everything, open included; default 20) and
 * HFS_FAKE_GONE_MS (how long it stays away; default 400).
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/eventfd.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <time.h>
#include <unistd.h>

#include "capture_fake.h"

#define FAKE_PATH "/dev/video-fake"

static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_once_t once = PTHREAD_ONCE_INIT;
static capture_fake fake;
static hfs_v4l2_ops ops;
static int efd = -1;                 /* the fd the process sees, -1: closed */
static long frames_made, gone_at = 20, gone_ms = 400;

static void fill_block(void *user, uint8_t *dst, int w, int h, int stride, uint32_t seq)
{
    (void)user;
    const int bx = (int)(seq * 4 % (uint32_t)w);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int block = x >= bx && x < bx + w / 5 && y > h / 3 && y < 2 * h / 3;
            const unsigned c = block ? 800 : 1000;
            dst[(size_t)y * stride + 2 * x] = (uint8_t)(c & 0xff);
            dst[(size_t)y * stride + 2 * x + 1] = (uint8_t)(c >> 8);
        }
}

static void signal_fd(void)
{
    if (efd >= 0) {
        const uint64_t one = 1;
        if (write(efd, &one, sizeof one) < 0) { /* a full counter is readable too */
        }
    }
}

static void *producer(void *arg)
{
    (void)arg;
    struct timespec tick = {0, 33333333};
    long back_after = 0; /* ticks left while unplugged */
    for (;;) {
        nanosleep(&tick, NULL);
        pthread_mutex_lock(&lock);
        if (fake.gone && --back_after <= 0) {
            fake.gone = 0; /* plugged in again: the next open works */
        } else if (!fake.gone && frames_made == gone_at) {
            fake.gone = 1;
            frames_made++;
            back_after = gone_ms / 33 + 1;
            signal_fd(); /* the process wakes, DQBUF says ENODEV */
        } else if (!fake.gone && capture_fake_produce(&fake, 1) == 1) {
            frames_made++;
            signal_fd();
        }
        pthread_mutex_unlock(&lock);
    }
    return NULL;
}

static void init(void)
{
    capture_fake_init(&fake, FAKE_PATH);
    fake.fill = fill_block;
    ops = capture_fake_ops(&fake);
    const char *a = getenv("HFS_FAKE_GONE_AT"), *b = getenv("HFS_FAKE_GONE_MS");
    if (a)
        gone_at = atol(a);
    if (b)
        gone_ms = atol(b);
    pthread_t t;
    pthread_create(&t, NULL, producer, NULL);
    pthread_detach(t);
}

static int fake_open_path(const char *path)
{
    pthread_once(&once, init);
    pthread_mutex_lock(&lock);
    int fd = ops.open(ops.user, path, O_RDWR);
    if (fd >= 0) {
        efd = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
        fd = efd;
    }
    const int e = errno;
    pthread_mutex_unlock(&lock);
    errno = e;
    return fd;
}

int open(const char *path, int flags, ...)
{
    if (!strcmp(path, FAKE_PATH))
        return fake_open_path(path);
    va_list ap;
    va_start(ap, flags);
    const mode_t mode = (mode_t)va_arg(ap, int);
    va_end(ap);
    int (*real)(const char *, int, ...) = (int (*)(const char *, int, ...))dlsym(RTLD_NEXT, "open");
    return real(path, flags, mode);
}

int open64(const char *path, int flags, ...)
{
    if (!strcmp(path, FAKE_PATH))
        return fake_open_path(path);
    va_list ap;
    va_start(ap, flags);
    const mode_t mode = (mode_t)va_arg(ap, int);
    va_end(ap);
    int (*real)(const char *, int, ...) =
        (int (*)(const char *, int, ...))dlsym(RTLD_NEXT, "open64");
    return real(path, flags, mode);
}

int close(int fd)
{
    int (*real)(int) = (int (*)(int))dlsym(RTLD_NEXT, "close");
    if (fd >= 0 && fd == efd) {
        pthread_mutex_lock(&lock);
        ops.close(ops.user, 700);
        efd = -1;
        pthread_mutex_unlock(&lock);
    }
    return real(fd);
}

int ioctl(int fd, unsigned long req, ...)
{
    va_list ap;
    va_start(ap, req);
    void *arg = va_arg(ap, void *);
    va_end(ap);
    if (fd < 0 || fd != efd) {
        int (*real)(int, unsigned long, ...) =
            (int (*)(int, unsigned long, ...))dlsym(RTLD_NEXT, "ioctl");
        return real(fd, req, arg);
    }
    pthread_mutex_lock(&lock);
    const int r = ops.ioctl(ops.user, 700, req, arg);
    const int e = errno;
    if (r < 0 && e == EAGAIN) { /* nothing done: not readable any more */
        uint64_t n;
        if (read(efd, &n, sizeof n) < 0) {
        }
    }
    pthread_mutex_unlock(&lock);
    errno = e;
    return r;
}

void *mmap(void *addr, size_t len, int prot, int flags, int fd, off_t off)
{
    if (fd >= 0 && fd == efd) {
        pthread_mutex_lock(&lock);
        void *p = ops.mmap(ops.user, len, prot, flags, 700, off);
        pthread_mutex_unlock(&lock);
        return p;
    }
    void *(*real)(void *, size_t, int, int, int, off_t) =
        (void *(*)(void *, size_t, int, int, int, off_t))dlsym(RTLD_NEXT, "mmap");
    return real(addr, len, prot, flags, fd, off);
}

int munmap(void *addr, size_t len)
{
    pthread_mutex_lock(&lock);
    for (int i = 0; i < fake.n_buf; ++i)
        if (fake.mem[i] == addr) {
            const int r = ops.munmap(ops.user, addr, len);
            pthread_mutex_unlock(&lock);
            return r;
        }
    pthread_mutex_unlock(&lock);
    int (*real)(void *, size_t) = (int (*)(void *, size_t))dlsym(RTLD_NEXT, "munmap");
    return real(addr, len);
}
