/*
 * capture_fake.c — see capture_fake.h.
 */
#include "capture_fake.h"

#include <errno.h>
#include <linux/videodev2.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

#define FAKE_FD 700
#define PAGE 4096u

static const uint32_t fake_fmts[] = {V4L2_PIX_FMT_Z16, V4L2_PIX_FMT_Y16, V4L2_PIX_FMT_GREY,
                                     V4L2_PIX_FMT_YUYV, V4L2_PIX_FMT_MJPEG};
static const int fake_sizes[][2] = {{640, 480}, {320, 240}};

void capture_fake_init(capture_fake *f, const char *path)
{
    memset(f, 0, sizeof *f);
    snprintf(f->path, sizeof f->path, "%s", path);
    f->caps = V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING;
    f->max_buffers = 8;
    f->min_buffers = 2;
    f->fourcc = V4L2_PIX_FMT_Z16;
    f->width = 640, f->height = 480, f->stride = 1280;
    f->sizeimage = 1280u * 480u;
    f->t_ns = 1000000000LL;
    f->frame_ns = 33333333;
}

static void free_buffers(capture_fake *f)
{
    for (int i = 0; i < f->n_buf; ++i)
        free(f->mem[i]);
    memset(f->mem, 0, sizeof f->mem);
    f->n_buf = f->qn = f->dn = 0;
}

void capture_fake_free(capture_fake *f)
{
    free_buffers(f);
}

static int n_sizes(uint32_t fourcc)
{
    return fourcc == V4L2_PIX_FMT_Y16 || fourcc == V4L2_PIX_FMT_MJPEG ? 1 : 2;
}

static int bpp(uint32_t fourcc)
{
    return fourcc == V4L2_PIX_FMT_GREY ? 1 : 2;
}

static int has_fmt(uint32_t fourcc)
{
    for (size_t i = 0; i < sizeof fake_fmts / sizeof fake_fmts[0]; ++i)
        if (fake_fmts[i] == fourcc)
            return 1;
    return 0;
}

static int fail(int e)
{
    errno = e;
    return -1;
}

static int s_fmt(capture_fake *f, struct v4l2_format *fmt)
{
    if (f->streaming || f->n_buf)
        return fail(EBUSY);
    struct v4l2_pix_format *p = &fmt->fmt.pix;
    if (!has_fmt(p->pixelformat) || p->pixelformat == V4L2_PIX_FMT_MJPEG)
        p->pixelformat = V4L2_PIX_FMT_YUYV; /* a driver's substitute */
    /* The nearest size it has (as drivers do), or the forced one. */
    int best = 0;
    for (int i = 1; i < n_sizes(p->pixelformat); ++i)
        if (abs(fake_sizes[i][0] - (int)p->width) < abs(fake_sizes[best][0] - (int)p->width))
            best = i;
    p->width = (uint32_t)(f->force_w ? f->force_w : fake_sizes[best][0]);
    p->height = (uint32_t)(f->force_h ? f->force_h : fake_sizes[best][1]);
    /* Rows padded to 64 bytes, as many drivers do. */
    p->bytesperline = (p->width * (uint32_t)bpp(p->pixelformat) + 63u) & ~63u;
    p->sizeimage = p->bytesperline * p->height;
    p->field = V4L2_FIELD_NONE;
    f->fourcc = p->pixelformat;
    f->width = (int)p->width, f->height = (int)p->height, f->stride = (int)p->bytesperline;
    f->sizeimage = p->sizeimage;
    return 0;
}

static int reqbufs(capture_fake *f, struct v4l2_requestbuffers *rb)
{
    if (rb->memory != V4L2_MEMORY_MMAP || rb->type != V4L2_BUF_TYPE_VIDEO_CAPTURE)
        return fail(EINVAL);
    if (f->streaming || f->maps != f->unmaps) {
        f->reqbufs_busy++;
        return fail(EBUSY);
    }
    free_buffers(f);
    if (rb->count == 0)
        return 0;
    int n = (int)rb->count;
    n = n > f->max_buffers ? f->max_buffers : n < f->min_buffers ? f->min_buffers : n;
    for (int i = 0; i < n; ++i) {
        f->mem[i] = calloc(1, (f->sizeimage + PAGE - 1) / PAGE * PAGE);
        if (!f->mem[i])
            return fail(ENOMEM);
        f->state[i] = 0;
    }
    f->n_buf = n;
    rb->count = (uint32_t)n;
    return 0;
}

static size_t buf_len(const capture_fake *f)
{
    return (f->sizeimage + PAGE - 1) / PAGE * PAGE;
}

static int buf_ioctl(capture_fake *f, unsigned long req, struct v4l2_buffer *b)
{
    if (b->type != V4L2_BUF_TYPE_VIDEO_CAPTURE || b->memory != V4L2_MEMORY_MMAP)
        return fail(EINVAL);
    if (req == VIDIOC_DQBUF) {
        if (f->dqbuf_errno)
            return fail(f->dqbuf_errno);
        if (f->dn == 0)
            return fail(EAGAIN);
        const int i = f->done[0];
        memmove(f->done, f->done + 1, (size_t)(--f->dn) * sizeof *f->done);
        f->state[i] = 0;
        b->index = (uint32_t)i;
        b->sequence = f->seq_of[i];
        b->bytesused = f->used_of[i];
        b->flags = f->not_monotonic ? V4L2_BUF_FLAG_TIMESTAMP_UNKNOWN
                                    : V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC;
        b->timestamp.tv_sec = f->t_of[i] / 1000000000LL;
        b->timestamp.tv_usec = (f->t_of[i] % 1000000000LL) / 1000;
        return 0;
    }
    if (b->index >= (uint32_t)f->n_buf)
        return fail(EINVAL);
    const int i = (int)b->index;
    if (req == VIDIOC_QUERYBUF) {
        b->length = (uint32_t)buf_len(f);
        b->m.offset = (uint32_t)(i * 0x100000);
        return 0;
    }
    /* QBUF: only a buffer the application holds. */
    if (f->state[i] != 0) {
        f->bad_qbuf++;
        return fail(EINVAL);
    }
    f->state[i] = 1;
    f->queue[f->qn++] = i;
    return 0;
}

static int enum_ioctl(capture_fake *f, unsigned long req, void *arg)
{
    (void)f;
    if (req == VIDIOC_ENUM_FMT) {
        struct v4l2_fmtdesc *d = arg;
        if (d->index >= sizeof fake_fmts / sizeof fake_fmts[0])
            return fail(EINVAL);
        d->pixelformat = fake_fmts[d->index];
        snprintf((char *)d->description, sizeof d->description, "fake %u", d->index);
        return 0;
    }
    if (req == VIDIOC_ENUM_FRAMESIZES) {
        struct v4l2_frmsizeenum *s = arg;
        if (!has_fmt(s->pixel_format) || s->index >= (uint32_t)n_sizes(s->pixel_format))
            return fail(EINVAL);
        s->type = V4L2_FRMSIZE_TYPE_DISCRETE;
        s->discrete.width = (uint32_t)fake_sizes[s->index][0];
        s->discrete.height = (uint32_t)fake_sizes[s->index][1];
        return 0;
    }
    struct v4l2_frmivalenum *v = arg; /* VIDIOC_ENUM_FRAMEINTERVALS */
    if (v->index >= 2 || !has_fmt(v->pixel_format))
        return fail(EINVAL);
    v->type = V4L2_FRMIVAL_TYPE_DISCRETE;
    v->discrete.numerator = 1;
    v->discrete.denominator = v->index == 0 ? 30 : 15;
    return 0;
}

static int fake_ioctl(void *user, int fd, unsigned long req, void *arg)
{
    capture_fake *f = user;
    if (fd != FAKE_FD || f->open_fds == 0)
        return fail(EBADF);
    if (f->gone)
        return fail(ENODEV);
    switch (req) {
    case VIDIOC_QUERYCAP: {
        struct v4l2_capability *c = arg;
        memset(c, 0, sizeof *c);
        snprintf((char *)c->driver, sizeof c->driver, "fake");
        snprintf((char *)c->card, sizeof c->card, "Fake Depth Camera");
        snprintf((char *)c->bus_info, sizeof c->bus_info, "test:0");
        c->capabilities = f->caps | V4L2_CAP_DEVICE_CAPS;
        c->device_caps = f->caps;
        return 0;
    }
    case VIDIOC_G_FMT: {
        struct v4l2_format *fmt = arg;
        fmt->fmt.pix.pixelformat = f->fourcc;
        fmt->fmt.pix.width = (uint32_t)f->width, fmt->fmt.pix.height = (uint32_t)f->height;
        fmt->fmt.pix.bytesperline = (uint32_t)f->stride;
        fmt->fmt.pix.sizeimage = (uint32_t)f->sizeimage;
        return 0;
    }
    case VIDIOC_S_FMT:
        return s_fmt(f, arg);
    case VIDIOC_S_PARM:
        return 0;
    case VIDIOC_REQBUFS:
        return reqbufs(f, arg);
    case VIDIOC_QUERYBUF:
    case VIDIOC_QBUF:
    case VIDIOC_DQBUF:
        return buf_ioctl(f, req, arg);
    case VIDIOC_STREAMON:
        if (f->n_buf == 0)
            return fail(EINVAL);
        f->streaming = 1;
        f->streamons++;
        if (f->seq_restarts)
            f->seq = 0;
        return 0;
    case VIDIOC_STREAMOFF:
        f->streaming = 0;
        f->streamoffs++;
        for (int i = 0; i < f->n_buf; ++i)
            f->state[i] = 0;
        f->qn = f->dn = 0;
        return 0;
    case VIDIOC_ENUM_FMT:
    case VIDIOC_ENUM_FRAMESIZES:
    case VIDIOC_ENUM_FRAMEINTERVALS:
        return enum_ioctl(f, req, arg);
    default:
        return fail(ENOTTY);
    }
}

static int fake_open(void *user, const char *path, int flags)
{
    capture_fake *f = user;
    (void)flags;
    if (strcmp(path, f->path))
        return fail(ENOENT);
    if (f->gone)
        return fail(ENODEV);
    if (f->open_fds)
        return fail(EBUSY);
    f->open_fds = 1;
    f->opens++;
    return FAKE_FD;
}

static int fake_close(void *user, int fd)
{
    capture_fake *f = user;
    if (fd != FAKE_FD || !f->open_fds)
        return fail(EBADF);
    f->open_fds = 0;
    f->closes++;
    f->streaming = 0; /* the kernel stops the stream and frees the buffers */
    if (f->maps == f->unmaps)
        free_buffers(f);
    return 0;
}

static void *fake_mmap(void *user, size_t len, int prot, int flags, int fd, off_t off)
{
    capture_fake *f = user;
    (void)prot, (void)flags;
    const int i = (int)(off / 0x100000);
    if (fd != FAKE_FD || f->gone || off % 0x100000 || i >= f->n_buf || len > buf_len(f)) {
        errno = EINVAL;
        return MAP_FAILED;
    }
    f->maps++;
    return f->mem[i];
}

static int fake_munmap(void *user, void *addr, size_t len)
{
    capture_fake *f = user;
    (void)addr, (void)len;
    f->unmaps++;
    return 0;
}

static int fake_poll(void *user, struct pollfd *fds, nfds_t n, int timeout_ms)
{
    capture_fake *f = user;
    (void)timeout_ms;
    int ready = 0;
    for (nfds_t i = 0; i < n; ++i) {
        fds[i].revents = f->gone ? POLLERR : f->dn > 0 ? POLLIN : 0;
        ready += fds[i].revents != 0;
    }
    return ready;
}

hfs_v4l2_ops capture_fake_ops(capture_fake *f)
{
    hfs_v4l2_ops ops = {fake_open, fake_close, fake_ioctl, fake_mmap,
                        fake_munmap, fake_poll, f};
    return ops;
}

int capture_fake_produce(capture_fake *f, int n)
{
    int made = 0;
    while (made < n && f->streaming && f->qn > 0) {
        const int i = f->queue[0];
        memmove(f->queue, f->queue + 1, (size_t)(--f->qn) * sizeof *f->queue);
        f->seq += (uint32_t)f->skip_seq;
        f->skip_seq = 0;
        f->t_ns += f->frame_ns;
        if (f->fill)
            f->fill(f->fill_user, f->mem[i], f->width, f->height, f->stride, f->seq);
        f->seq_of[i] = f->seq++;
        f->t_of[i] = f->t_ns;
        f->used_of[i] = f->short_next ? (uint32_t)f->sizeimage / 2 : (uint32_t)f->sizeimage;
        f->short_next = 0;
        f->state[i] = 2;
        f->done[f->dn++] = i;
        made++;
    }
    return made;
}

int capture_fake_queued(const capture_fake *f)
{
    return f->qn;
}
