/*
 * capture_fake.h — a fake V4L2 capture device behind hfs_v4l2_ops
 * (board/capture_v4l2.h), with the kernel's semantics where the capture
 * source depends on them: buffers are owned by the application or queued
 * (FIFO) or done; QBUF of a buffer the application does not hold is
 * EINVAL; DQBUF with nothing done is EAGAIN; REQBUFS while mapped or
 * streaming is EBUSY; STREAMOFF takes every buffer back; a device that is
 * `gone` answers ENODEV to everything (open included) and POLLERR.
 * Frames appear only when the test calls capture_fake_produce.
 */
#ifndef HFS_TEST_CAPTURE_FAKE_H
#define HFS_TEST_CAPTURE_FAKE_H

#include <stddef.h>
#include <stdint.h>

#include "capture_v4l2.h"

#define FAKE_MAX_BUF 16

typedef void (*fake_fill_fn)(void *user, uint8_t *dst, int w, int h, int stride, uint32_t seq);

typedef struct capture_fake {
    /* Set by the test. */
    char path[64];            /* the one path that opens                      */
    uint32_t caps;            /* device_caps (default capture + streaming)    */
    int force_w, force_h;     /* S_FMT answers this size whatever is asked    */
    int max_buffers;          /* REQBUFS grants at most this (default 8)      */
    int min_buffers;          /* ... and at least this (default 2)            */
    int gone;                 /* unplugged: ENODEV                            */
    int dqbuf_errno;          /* not 0: DQBUF fails with it (a device dying
                                 mid-stream: EIO), the rest still works       */
    int seq_restarts;         /* the sequence starts at 0 again at STREAMON,
                                 as real drivers do (default: it goes on)     */
    int skip_seq;             /* the next produced frame skips this many      */
    int short_next;           /* the next produced frame has too few bytes    */
    int not_monotonic;        /* timestamps flagged UNKNOWN                    */
    fake_fill_fn fill;
    void *fill_user;

    /* State. */
    int open_fds, streaming;
    uint32_t fourcc;
    int width, height, stride;
    size_t sizeimage;
    int n_buf;
    uint8_t *mem[FAKE_MAX_BUF];
    int state[FAKE_MAX_BUF];  /* 0 application, 1 queued, 2 done               */
    uint32_t seq_of[FAKE_MAX_BUF], used_of[FAKE_MAX_BUF];
    int64_t t_of[FAKE_MAX_BUF];
    int queue[FAKE_MAX_BUF], qn;
    int done[FAKE_MAX_BUF], dn;
    uint32_t seq;
    int64_t t_ns;
    int64_t frame_ns;         /* produce() advances t_ns by this (33 ms)      */

    /* Counters the tests check. */
    long maps, unmaps, bad_qbuf, streamons, streamoffs, opens, closes, reqbufs_busy;
} capture_fake;

/* Z16/GREY/YUYV at 640x480 and 320x240, Y16 at 640x480 (30 and 15 fps),
 * and an MJPG entry hfshade does not support. */
void capture_fake_init(capture_fake *f, const char *path);
void capture_fake_free(capture_fake *f);
/* The ops table with user = f. */
hfs_v4l2_ops capture_fake_ops(capture_fake *f);
/* Moves up to n queued buffers to done (oldest first), filled; returns how
 * many (fewer when the application holds the rest). */
int capture_fake_produce(capture_fake *f, int n);
/* Buffers queued to the driver now. */
int capture_fake_queued(const capture_fake *f);

#endif /* HFS_TEST_CAPTURE_FAKE_H */
