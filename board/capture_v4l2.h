/*
 * capture_v4l2.h — a V4L2 video capture device as a capture source
 * (capture.h), written against the kernel's API (linux/videodev2.h): no
 * libv4l2 (Z16, Y16, GREY and YUYV need no conversion).
 *
 * Opening: QUERYCAP (video capture + streaming I/O required), S_FMT with
 * the requested format and size, the driver's answer re-read (bytesperline,
 * sizeimage; another pixel format is an error; another size is accepted
 * only when no size was asked for), S_PARM for a rate, REQBUFS (MMAP) with
 * the granted count, QUERYBUF + mmap + QBUF of each, STREAMON.  Reading:
 * DQBUF (O_NONBLOCK: EAGAIN = nothing yet, EINTR retried), the newest
 * buffer kept until the next read, the others queued back at once.
 * Timestamps: the buffer's own when V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC,
 * else the time of the dequeue.  Closing: STREAMOFF, munmap, close.
 *
 * Every system call goes through an ops table: the tests substitute a fake
 * device (tests/capture_fake.c) with the kernel's semantics.
 */
#ifndef HFS_BOARD_CAPTURE_V4L2_H
#define HFS_BOARD_CAPTURE_V4L2_H

#include <poll.h>
#include <stdio.h>
#include <sys/types.h>

#include "capture.h"

typedef struct hfs_v4l2_ops {
    int (*open)(void *user, const char *path, int flags);
    int (*close)(void *user, int fd);
    int (*ioctl)(void *user, int fd, unsigned long request, void *arg);
    void *(*mmap)(void *user, size_t length, int prot, int flags, int fd, off_t offset);
    int (*munmap)(void *user, void *addr, size_t length);
    int (*poll)(void *user, struct pollfd *fds, nfds_t n, int timeout_ms);
    void *user;
} hfs_v4l2_ops;

/* The real system calls. */
const hfs_v4l2_ops *hfs_v4l2_sys_ops(void);

#define HFS_V4L2_MAX_BUFFERS 16

typedef struct hfs_v4l2_desc {
    const char *path;          /* /dev/video0 or a /dev/v4l/by-id link       */
    hfs_pixfmt format;         /* required                                   */
    int width, height;         /* 0: the driver's choice; else required      */
    int fps;                   /* 0: the driver's rate                       */
    int buffers;               /* asked for; 0 = 4; the driver may grant more */
    const hfs_v4l2_ops *ops;   /* NULL: hfs_v4l2_sys_ops()                   */
} hfs_v4l2_desc;

/* Opens and starts streaming.  Errors name the device:
 * "video /dev/video0: not a video capture device". */
int hfs_v4l2_open(const hfs_v4l2_desc *d, hfs_capture **out, hfs_error *err);

/* Waits up to timeout_ms for a frame (the ops' poll): 1 ready, 0 timeout,
 * HFS_E_IO on a lost device. */
int hfs_v4l2_wait(hfs_capture *c, int timeout_ms, hfs_error *err);

/* The negotiated format (after open or a reopen). */
void hfs_v4l2_format(const hfs_capture *c, int *width, int *height, int *stride,
                     size_t *sizeimage, int *buffers);

/* hfs-capture-info: the driver, card and every format with its frame
 * sizes and intervals, written to out like `v4l2-ctl --list-formats-ext`. */
int hfs_v4l2_list(const char *path, const hfs_v4l2_ops *ops, FILE *out, hfs_error *err);

/* ioctl through ops, retried on EINTR; -1 with errno as the call left it. */
int hfs_v4l2_xioctl(const hfs_v4l2_ops *ops, int fd, unsigned long request, void *arg);

#endif /* HFS_BOARD_CAPTURE_V4L2_H */
