/*
 * capture_v4l2.c — the V4L2 capture source (capture_v4l2.h).
 *
 * Buffer ownership: after STREAMON every buffer is queued (the driver's);
 * next() dequeues all that are done, keeps the newest (the application's
 * until the next call) and queues the rest back at once.  `held` is the
 * index of the kept one, -1 when none.  close() stops the stream (which
 * takes every buffer back), unmaps and closes, so a reopen starts clean.
 */
#include "capture_v4l2.h"

#include <errno.h>
#include <fcntl.h>
#include <linux/videodev2.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <time.h>
#include <unistd.h>

typedef struct v4l2_cap {
    hfs_capture base;
    hfs_v4l2_desc desc;
    char path[256];
    hfs_v4l2_ops ops;
    int fd;
    int width, height, stride;
    size_t sizeimage;
    int n_buf;
    void *map[HFS_V4L2_MAX_BUFFERS];
    size_t map_len[HFS_V4L2_MAX_BUFFERS];
    int streaming;
    int held;                 /* buffer the application holds, -1: none */
    int have_seq;             /* a sequence number was seen             */
    uint32_t last_seq;
} v4l2_cap;

/* ---- the real system calls ------------------------------------------------ */

static int sys_open(void *u, const char *path, int flags)
{
    (void)u;
    return open(path, flags);
}
static int sys_close(void *u, int fd)
{
    (void)u;
    return close(fd);
}
static int sys_ioctl(void *u, int fd, unsigned long req, void *arg)
{
    (void)u;
    return ioctl(fd, req, arg);
}
static void *sys_mmap(void *u, size_t len, int prot, int flags, int fd, off_t off)
{
    (void)u;
    return mmap(NULL, len, prot, flags, fd, off);
}
static int sys_munmap(void *u, void *addr, size_t len)
{
    (void)u;
    return munmap(addr, len);
}
static int sys_poll(void *u, struct pollfd *fds, nfds_t n, int timeout_ms)
{
    (void)u;
    return poll(fds, n, timeout_ms);
}

const hfs_v4l2_ops *hfs_v4l2_sys_ops(void)
{
    static const hfs_v4l2_ops ops = {sys_open, sys_close, sys_ioctl, sys_mmap,
                                     sys_munmap, sys_poll, NULL};
    return &ops;
}

int hfs_v4l2_xioctl(const hfs_v4l2_ops *ops, int fd, unsigned long req, void *arg)
{
    int r;
    do
        r = ops->ioctl(ops->user, fd, req, arg);
    while (r < 0 && errno == EINTR);
    return r;
}

static int64_t mono_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (int64_t)ts.tv_sec * 1000000000LL + ts.tv_nsec;
}

/* A lost device (unplugged) answers ENODEV; the kernel also uses EIO and
 * ENXIO for a device going away. */
static int lost_errno(int e)
{
    return e == ENODEV || e == EIO || e == ENXIO;
}

/* ---- open / close ----------------------------------------------------------- */

static void release(v4l2_cap *c)
{
    if (c->fd < 0)
        return;
    if (c->streaming) {
        int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        hfs_v4l2_xioctl(&c->ops, c->fd, VIDIOC_STREAMOFF, &type);
        c->streaming = 0;
    }
    for (int i = 0; i < c->n_buf; ++i)
        if (c->map[i])
            c->ops.munmap(c->ops.user, c->map[i], c->map_len[i]);
    if (c->n_buf > 0) { /* free the driver's buffers (no stream, none mapped) */
        struct v4l2_requestbuffers rb = {.count = 0, .type = V4L2_BUF_TYPE_VIDEO_CAPTURE,
                                         .memory = V4L2_MEMORY_MMAP};
        hfs_v4l2_xioctl(&c->ops, c->fd, VIDIOC_REQBUFS, &rb);
    }
    memset(c->map, 0, sizeof c->map);
    c->n_buf = 0;
    c->held = -1;
    c->ops.close(c->ops.user, c->fd);
    c->fd = -1;
}

static int fail_errno(v4l2_cap *c, const char *what, hfs_error *err)
{
    const int e = errno;
    return hfs_fail(err, lost_errno(e) ? HFS_E_IO : HFS_E_INVALID, "%s: %s: %s", c->base.name,
                    what, strerror(e));
}

static int check_caps(v4l2_cap *c, hfs_error *err)
{
    struct v4l2_capability cap;
    memset(&cap, 0, sizeof cap);
    if (hfs_v4l2_xioctl(&c->ops, c->fd, VIDIOC_QUERYCAP, &cap) < 0)
        return errno == ENOTTY
                   ? hfs_fail(err, HFS_E_INVALID, "%s: not a V4L2 device", c->base.name)
                   : fail_errno(c, "VIDIOC_QUERYCAP", err);
    const uint32_t caps = (cap.capabilities & V4L2_CAP_DEVICE_CAPS) ? cap.device_caps
                                                                    : cap.capabilities;
    if (!(caps & V4L2_CAP_VIDEO_CAPTURE))
        return hfs_fail(err, HFS_E_INVALID, "%s: not a video capture device (%.32s)",
                        c->base.name, (const char *)cap.card);
    if (!(caps & V4L2_CAP_STREAMING))
        return hfs_fail(err, HFS_E_INVALID, "%s: no streaming I/O (%.32s)", c->base.name,
                        (const char *)cap.card);
    return HFS_OK;
}

/* S_FMT, then what the driver made of it. */
static int set_format(v4l2_cap *c, hfs_error *err)
{
    const hfs_v4l2_desc *d = &c->desc;
    struct v4l2_format f;
    memset(&f, 0, sizeof f);
    f.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    if (hfs_v4l2_xioctl(&c->ops, c->fd, VIDIOC_G_FMT, &f) < 0)
        return fail_errno(c, "VIDIOC_G_FMT", err);
    f.fmt.pix.pixelformat = hfs_pixfmt_fourcc(d->format);
    if (d->width > 0) {
        f.fmt.pix.width = (uint32_t)d->width;
        f.fmt.pix.height = (uint32_t)d->height;
    }
    f.fmt.pix.field = V4L2_FIELD_NONE;
    f.fmt.pix.bytesperline = 0; /* the driver's choice */
    if (hfs_v4l2_xioctl(&c->ops, c->fd, VIDIOC_S_FMT, &f) < 0)
        return fail_errno(c, "VIDIOC_S_FMT", err);
    char got[5];
    if (f.fmt.pix.pixelformat != hfs_pixfmt_fourcc(d->format))
        return hfs_fail(err, HFS_E_INVALID, "%s: format %s not supported (the driver offers "
                        "'%s'; hfs-capture-info lists them)", c->base.name,
                        hfs_pixfmt_name(d->format), hfs_fourcc_text(f.fmt.pix.pixelformat, got));
    if (d->width > 0 && ((int)f.fmt.pix.width != d->width || (int)f.fmt.pix.height != d->height))
        return hfs_fail(err, HFS_E_INVALID, "%s: asked for %dx%d %s, the driver gives %ux%u "
                        "(set size to that, or leave it out)", c->base.name, d->width,
                        d->height, hfs_pixfmt_name(d->format), f.fmt.pix.width,
                        f.fmt.pix.height);
    const int bpp = hfs_pixfmt_bytes(d->format);
    if (f.fmt.pix.width < 1 || f.fmt.pix.height < 1 || f.fmt.pix.width > 16384 ||
        f.fmt.pix.height > 16384 || f.fmt.pix.bytesperline < f.fmt.pix.width * (uint32_t)bpp ||
        f.fmt.pix.sizeimage < (uint64_t)f.fmt.pix.bytesperline * f.fmt.pix.height)
        return hfs_fail(err, HFS_E_FORMAT, "%s: the driver's format is inconsistent: %ux%u, "
                        "%u bytes per line, image %u bytes", c->base.name, f.fmt.pix.width,
                        f.fmt.pix.height, f.fmt.pix.bytesperline, f.fmt.pix.sizeimage);
    c->width = (int)f.fmt.pix.width;
    c->height = (int)f.fmt.pix.height;
    c->stride = (int)f.fmt.pix.bytesperline;
    c->sizeimage = f.fmt.pix.sizeimage;
    return HFS_OK;
}

/* A rate is a wish: drivers without S_PARM or with other rates are fine. */
static void set_rate(v4l2_cap *c)
{
    if (c->desc.fps <= 0)
        return;
    struct v4l2_streamparm p;
    memset(&p, 0, sizeof p);
    p.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    p.parm.capture.timeperframe.numerator = 1;
    p.parm.capture.timeperframe.denominator = (uint32_t)c->desc.fps;
    hfs_v4l2_xioctl(&c->ops, c->fd, VIDIOC_S_PARM, &p);
}

static int map_buffers(v4l2_cap *c, hfs_error *err)
{
    struct v4l2_requestbuffers rb;
    memset(&rb, 0, sizeof rb);
    rb.count = (uint32_t)(c->desc.buffers > 0 ? c->desc.buffers : 4);
    rb.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    rb.memory = V4L2_MEMORY_MMAP;
    if (hfs_v4l2_xioctl(&c->ops, c->fd, VIDIOC_REQBUFS, &rb) < 0)
        return fail_errno(c, "VIDIOC_REQBUFS", err);
    if (rb.count < 2)
        return hfs_fail(err, HFS_E_INVALID, "%s: the driver granted %u buffers (2 needed)",
                        c->base.name, rb.count);
    c->n_buf = rb.count > HFS_V4L2_MAX_BUFFERS ? HFS_V4L2_MAX_BUFFERS : (int)rb.count;
    for (int i = 0; i < c->n_buf; ++i) {
        struct v4l2_buffer b;
        memset(&b, 0, sizeof b);
        b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        b.memory = V4L2_MEMORY_MMAP;
        b.index = (uint32_t)i;
        if (hfs_v4l2_xioctl(&c->ops, c->fd, VIDIOC_QUERYBUF, &b) < 0)
            return fail_errno(c, "VIDIOC_QUERYBUF", err);
        if (b.length < c->sizeimage)
            return hfs_fail(err, HFS_E_FORMAT, "%s: buffer %d holds %u bytes, an image %zu",
                            c->base.name, i, b.length, c->sizeimage);
        void *p = c->ops.mmap(c->ops.user, b.length, PROT_READ | PROT_WRITE, MAP_SHARED, c->fd,
                              (off_t)b.m.offset);
        if (p == MAP_FAILED)
            return fail_errno(c, "mmap", err);
        c->map[i] = p;
        c->map_len[i] = b.length;
        if (hfs_v4l2_xioctl(&c->ops, c->fd, VIDIOC_QBUF, &b) < 0)
            return fail_errno(c, "VIDIOC_QBUF", err);
    }
    return HFS_OK;
}

static int start(v4l2_cap *c, hfs_error *err)
{
    c->fd = c->ops.open(c->ops.user, c->path, O_RDWR | O_NONBLOCK | O_CLOEXEC);
    if (c->fd < 0)
        return hfs_fail(err, errno == ENOENT || lost_errno(errno) ? HFS_E_IO : HFS_E_INVALID,
                        "%s: %s", c->base.name, strerror(errno));
    c->held = -1;
    c->have_seq = 0;
    int rc = check_caps(c, err);
    if (!rc)
        rc = set_format(c, err);
    if (!rc) {
        set_rate(c);
        rc = map_buffers(c, err);
    }
    if (!rc) {
        int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        if (hfs_v4l2_xioctl(&c->ops, c->fd, VIDIOC_STREAMON, &type) < 0)
            rc = fail_errno(c, "VIDIOC_STREAMON", err);
        else
            c->streaming = 1;
    }
    if (rc)
        release(c);
    return rc;
}

/* ---- reading ------------------------------------------------------------------ */

static int requeue(v4l2_cap *c, int index, hfs_error *err)
{
    struct v4l2_buffer b;
    memset(&b, 0, sizeof b);
    b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    b.memory = V4L2_MEMORY_MMAP;
    b.index = (uint32_t)index;
    if (hfs_v4l2_xioctl(&c->ops, c->fd, VIDIOC_QBUF, &b) < 0)
        return fail_errno(c, "VIDIOC_QBUF", err);
    return HFS_OK;
}

/* Counts the frames the driver skipped before this one. */
static void count_gap(v4l2_cap *c, uint32_t seq)
{
    if (c->have_seq && seq != c->last_seq + 1)
        c->base.dropped += (long)(uint32_t)(seq - c->last_seq - 1);
    c->have_seq = 1;
    c->last_seq = seq;
}

static void frame_of(const v4l2_cap *c, const struct v4l2_buffer *b, hfs_capture_frame *out)
{
    const int mono = (b->flags & V4L2_BUF_FLAG_TIMESTAMP_MASK) == V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC;
    out->data = c->map[b->index];
    out->bytes = b->bytesused;
    out->width = c->width;
    out->height = c->height;
    out->stride = c->stride;
    out->format = c->desc.format;
    out->sequence = b->sequence;
    out->t_ns = mono ? (int64_t)b->timestamp.tv_sec * 1000000000LL +
                           (int64_t)b->timestamp.tv_usec * 1000LL
                     : mono_now();
}

/* Dequeues everything done; *best = the newest good buffer (or -1). */
static int dequeue_all(v4l2_cap *c, struct v4l2_buffer *best, hfs_error *err)
{
    best->index = UINT32_MAX;
    for (;;) {
        struct v4l2_buffer b;
        memset(&b, 0, sizeof b);
        b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        b.memory = V4L2_MEMORY_MMAP;
        if (hfs_v4l2_xioctl(&c->ops, c->fd, VIDIOC_DQBUF, &b) < 0) {
            if (errno == EAGAIN)
                return HFS_OK;
            return fail_errno(c, "VIDIOC_DQBUF", err);
        }
        if (b.index >= (uint32_t)c->n_buf)
            return hfs_fail(err, HFS_E_IO, "%s: the driver returned buffer %u of %d",
                            c->base.name, b.index, c->n_buf);
        count_gap(c, b.sequence);
        const int bad = (b.flags & V4L2_BUF_FLAG_ERROR) ||
                        b.bytesused < (uint32_t)c->stride * (uint32_t)(c->height - 1) +
                                          (uint32_t)(c->width * hfs_pixfmt_bytes(c->desc.format));
        int drop = -1;
        if (bad) {
            c->base.dropped++;
            drop = (int)b.index;
        } else {
            if (c->base.tap) {
                hfs_capture_frame f;
                frame_of(c, &b, &f);
                c->base.tap(c->base.tap_user, &f);
            }
            if (best->index != UINT32_MAX) {
                c->base.superseded++;
                drop = (int)best->index;
            }
            *best = b;
        }
        int rc;
        if (drop >= 0 && (rc = requeue(c, drop, err)))
            return rc;
    }
}

static int v_next(hfs_capture *base, int64_t now_ns, hfs_capture_frame *out, hfs_error *err)
{
    v4l2_cap *c = (v4l2_cap *)base;
    (void)now_ns;
    if (c->fd < 0)
        return hfs_fail(err, HFS_E_IO, "%s: closed", base->name);
    struct v4l2_buffer b;
    int rc = dequeue_all(c, &b, err);
    if (rc)
        return rc;
    if (b.index == UINT32_MAX)
        return 0;
    /* The new frame replaces the one the application held. */
    if (c->held >= 0 && (rc = requeue(c, c->held, err)))
        return rc;
    c->held = (int)b.index;
    frame_of(c, &b, out);
    base->frames++;
    return 1;
}

int hfs_v4l2_wait(hfs_capture *base, int timeout_ms, hfs_error *err)
{
    v4l2_cap *c = (v4l2_cap *)base;
    if (c->fd < 0)
        return hfs_fail(err, HFS_E_IO, "%s: closed", base->name);
    struct pollfd p = {.fd = c->fd, .events = POLLIN};
    int r;
    do
        r = c->ops.poll(c->ops.user, &p, 1, timeout_ms);
    while (r < 0 && errno == EINTR);
    if (r < 0)
        return fail_errno(c, "poll", err);
    if (r > 0 && (p.revents & (POLLERR | POLLHUP | POLLNVAL)))
        return hfs_fail(err, HFS_E_IO, "%s: device lost (poll: error)", base->name);
    return r > 0;
}

static int v_fd(hfs_capture *base)
{
    return ((v4l2_cap *)base)->fd;
}

static int64_t v_deadline(hfs_capture *base)
{
    (void)base;
    return INT64_MAX;
}

static int v_reopen(hfs_capture *base, hfs_error *err)
{
    v4l2_cap *c = (v4l2_cap *)base;
    release(c);
    return start(c, err);
}

static void v_close(hfs_capture *base)
{
    release((v4l2_cap *)base);
}

static void v_destroy(hfs_capture *base)
{
    release((v4l2_cap *)base);
    free(base);
}

static const hfs_capture_vt v4l2_vt = {v_fd, v_deadline, v_next, v_reopen, v_close, v_destroy};

int hfs_v4l2_open(const hfs_v4l2_desc *d, hfs_capture **out, hfs_error *err)
{
    *out = NULL;
    if (!d || !d->path || hfs_pixfmt_bytes(d->format) == 0 || (d->width > 0) != (d->height > 0))
        return hfs_fail(err, HFS_E_INVALID, "video: bad description (path, format, size)");
    if (strlen(d->path) >= sizeof ((v4l2_cap *)0)->path)
        return hfs_fail(err, HFS_E_INVALID, "video: path too long");
    v4l2_cap *c = calloc(1, sizeof *c);
    if (!c)
        return hfs_fail(err, HFS_E_NOMEM, "video %s: out of memory", d->path);
    c->base.vt = &v4l2_vt;
    snprintf(c->base.name, sizeof c->base.name, "video %s", d->path);
    c->desc = *d;
    snprintf(c->path, sizeof c->path, "%s", d->path);
    c->desc.path = c->path;
    c->ops = d->ops ? *d->ops : *hfs_v4l2_sys_ops();
    c->fd = -1;
    c->held = -1;
    const int rc = start(c, err);
    if (rc) {
        free(c);
        return rc;
    }
    *out = &c->base;
    return HFS_OK;
}

void hfs_v4l2_format(const hfs_capture *base, int *width, int *height, int *stride,
                     size_t *sizeimage, int *buffers)
{
    const v4l2_cap *c = (const v4l2_cap *)base;
    *width = c->width;
    *height = c->height;
    *stride = c->stride;
    *sizeimage = c->sizeimage;
    *buffers = c->n_buf;
}
