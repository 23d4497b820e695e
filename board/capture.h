/*
 * capture.h — a source of camera frames (docs/CAPTURE.md): a V4L2 device
 * (capture_v4l2.h) or a recording played back (capture_record.h), behind
 * one interface, so the kiosk and the tests treat both alike.
 *
 *     int fd = hfs_capture_fd(cap);            // -1: none (replay: timed)
 *     int64_t due = hfs_capture_deadline(cap); // INT64_MAX: fd only
 *     ... poll ...
 *     hfs_capture_frame f;
 *     int r = hfs_capture_next(cap, now, &f, &err); // 1 frame, 0 none, <0
 *
 * next() never blocks.  It returns the NEWEST frame waiting (older ones are
 * handed back unread and counted in `superseded`: a display wants the
 * latest), valid until the next call to next(), reopen() or destroy().
 * HFS_E_IO means the device is gone (unplugged, ENODEV): the caller closes
 * it (hfs_capture_close) and reopens it later (backoff.h).  Frames are
 * checked before they are returned (size, bytes used); a malformed one is
 * skipped and counted in `dropped`, as are gaps in the driver's sequence
 * numbers.
 */
#ifndef HFS_BOARD_CAPTURE_H
#define HFS_BOARD_CAPTURE_H

#include <stddef.h>
#include <stdint.h>

#include "hfshade.h"

typedef enum hfs_pixfmt {
    HFS_PIX_NONE = 0,
    HFS_PIX_Z16,        /* depth, 16-bit little-endian counts (V4L2 'Z16 ') */
    HFS_PIX_Y16,        /* 16-bit grey, little-endian ('Y16 ')              */
    HFS_PIX_GREY,       /* 8-bit grey ('GREY')                              */
    HFS_PIX_YUYV,       /* 4:2:2 packed Y0 U Y1 V ('YUYV')                  */
    HFS_PIX_COUNT
} hfs_pixfmt;

/* "Z16", "Y16", "GREY", "YUYV"; NULL for none. */
const char *hfs_pixfmt_name(hfs_pixfmt f);
hfs_pixfmt hfs_pixfmt_from_name(const char *name);      /* HFS_PIX_NONE: unknown */
uint32_t hfs_pixfmt_fourcc(hfs_pixfmt f);
hfs_pixfmt hfs_pixfmt_from_fourcc(uint32_t fourcc);     /* HFS_PIX_NONE: other */
int hfs_pixfmt_bytes(hfs_pixfmt f);                     /* per pixel: 2 or 1 */
/* The fourcc as text ("Z16 "), into buf[5]. */
const char *hfs_fourcc_text(uint32_t fourcc, char buf[5]);

typedef struct hfs_capture_frame {
    const uint8_t *data;     /* height rows of stride bytes                 */
    size_t bytes;            /* >= (height - 1) * stride + width * bpp      */
    int width, height;
    int stride;              /* bytes per row                               */
    hfs_pixfmt format;
    int64_t t_ns;            /* CLOCK_MONOTONIC when the frame was captured  */
    uint32_t sequence;       /* the driver's frame number                    */
} hfs_capture_frame;

typedef struct hfs_capture hfs_capture;

typedef struct hfs_capture_vt {
    int (*fd)(hfs_capture *c);
    int64_t (*deadline)(hfs_capture *c);
    int (*next)(hfs_capture *c, int64_t now_ns, hfs_capture_frame *out, hfs_error *err);
    int (*reopen)(hfs_capture *c, hfs_error *err);
    void (*close)(hfs_capture *c);
    void (*destroy)(hfs_capture *c);
} hfs_capture_vt;

struct hfs_capture {
    const hfs_capture_vt *vt;
    char name[300];          /* "video /dev/video0", "replay DIR": messages */
    long frames;             /* frames returned                             */
    long dropped;            /* sequence gaps + malformed frames            */
    long superseded;         /* older frames skipped for a newer one        */
    int finished;            /* replay: played to the end (no loop)         */
    /* Called for EVERY good frame a device delivers, superseded ones too
     * (--capture-record records them all), before next() returns; NULL:
     * none.  A replay calls it for the frames it returns only. */
    void (*tap)(void *user, const hfs_capture_frame *f);
    void *tap_user;
};

static inline int hfs_capture_fd(hfs_capture *c) { return c->vt->fd(c); }
static inline int64_t hfs_capture_deadline(hfs_capture *c) { return c->vt->deadline(c); }
static inline int hfs_capture_next(hfs_capture *c, int64_t now_ns, hfs_capture_frame *out,
                                   hfs_error *err)
{
    return c->vt->next(c, now_ns, out, err);
}
static inline int hfs_capture_reopen(hfs_capture *c, hfs_error *err)
{
    return c->vt->reopen(c, err);
}
/* Releases the device (after a loss); reopen() takes it again. */
static inline void hfs_capture_close(hfs_capture *c) { c->vt->close(c); }
static inline void hfs_capture_destroy(hfs_capture *c)
{
    if (c)
        c->vt->destroy(c);
}

/* Checks that a frame's buffer holds its rows; HFS_E_FORMAT naming `who`. */
int hfs_capture_frame_check(const hfs_capture_frame *f, const char *who, hfs_error *err);

#endif /* HFS_BOARD_CAPTURE_H */
