/*
 * capture_record.h — recordings of capture frames, and a capture source
 * (capture.h) that plays one back, so demos and tests run without a camera
 * (docs/CAPTURE.md "Recordings").
 *
 * A recording is a directory:
 *
 *     DIR/capture.txt          the index, text:
 *         hfs-capture 1
 *         format Z16           Z16 | Y16 | GREY | YUYV
 *         size 512 384         width height (pixels)
 *         frame 0 1000000000 frame-000000.raw     SEQUENCE T_NS FILE
 *         frame 1 1033333333 frame-000001.raw     ...
 *     DIR/frame-000000.raw     height rows of width * bytes-per-pixel
 *                              bytes, packed, as the device gave them
 *                              (16-bit formats little-endian)
 *
 * T_NS is CLOCK_MONOTONIC at capture; only differences matter on replay.
 * Lines starting with '#' and blank lines are ignored.
 */
#ifndef HFS_BOARD_CAPTURE_RECORD_H
#define HFS_BOARD_CAPTURE_RECORD_H

#include "capture.h"

typedef struct hfs_capture_recorder hfs_capture_recorder;

/* Creates DIR if needed; a DIR that already holds capture.txt is refused
 * (no recording is overwritten). */
int hfs_capture_record_open(const char *dir, hfs_capture_recorder **out, hfs_error *err);
/* Appends one frame (the first fixes format and size; a later frame of
 * another is refused).  The index is flushed per frame. */
int hfs_capture_record_frame(hfs_capture_recorder *r, const hfs_capture_frame *f,
                             hfs_error *err);
/* Closes; -1 (HFS_E_IO) if any write failed.  NULL ok. */
int hfs_capture_record_close(hfs_capture_recorder *r, hfs_error *err);

/* Plays DIR back: frame i is due at start_ns + (T_i - T_0) and reported
 * with that time (when it "arrived"); loop: start again after the last.
 * The index is read and checked at open ("DIR/capture.txt:3: problem");
 * a frame file of the wrong size is an error when it is due. */
int hfs_capture_replay_open(const char *dir, int64_t start_ns, int loop, hfs_capture **out,
                            hfs_error *err);
/* pace = shown (docs/CAPTURE.md): a frame is due no earlier than its
 * recorded time AND one recorded interval after the previous one was
 * returned, so frames are never superseded: a consumer that takes a frame
 * and shows it before asking again (the kiosk's loop) shows every frame,
 * however slow it is.  The replay's clock stops while a due frame waits:
 * its time is when it was returned.  For tests and demos; a camera does not
 * wait. */
void hfs_capture_replay_pace_shown(hfs_capture *c);
int hfs_capture_replay_count(const hfs_capture *c);
/* The recording's format and size. */
void hfs_capture_replay_format(const hfs_capture *c, hfs_pixfmt *format, int *width,
                               int *height);

#endif /* HFS_BOARD_CAPTURE_RECORD_H */
