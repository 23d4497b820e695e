/*
 * input_replay.h — a scripted input source: events read from a text file
 * and delivered at their times, for tests, demos and latency measurements
 * without hardware.  It implements hfs_input_source_ops (input.h), kind
 * "replay".
 *
 * File format (docs/INPUT.md "Replay files"), one event per line:
 *
 *     # comment (also after an event)
 *     TIME_MS CONTROL turn N
 *     TIME_MS CONTROL press
 *     TIME_MS CONTROL release
 *
 * N is signed detents (+ = clockwise), non-zero, |N| <= 10000. *
 * TIME_MS is milliseconds after start_ns (a decimal number, fractions
 * allowed, 0 <= TIME_MS <= 1e9), non-decreasing from line to line.  CONTROL
 * is a control name as in the configuration (checked by the mapping, not
 * here: a replay file does not know the configuration).  Blank lines are
 * ignored.  Errors: "PATH:LINE: problem", HFS_E_FORMAT (HFS_E_IO when the
 * file cannot be read).
 *
 * Timing: read(now) returns, in file order, every event whose time
 * start_ns + TIME_MS * 1e6 is <= now, each with t_ns = that time (not now),
 * at most max per call (the rest on the next call).  deadline_ns is the
 * next event's time, INT64_MAX after the last; fd is always -1 (the source
 * is driven by its deadline); reopen does nothing.
 */
#ifndef HFS_BOARD_INPUT_REPLAY_H
#define HFS_BOARD_INPUT_REPLAY_H

#include "input.h"

/* Reads the whole file now.  On success *out is a source the caller
 * destroys with hfs_input_source_destroy; on failure *out is NULL. */
int hfs_replay_source_create(const char *path, int64_t start_ns, hfs_input_source **out,
                             hfs_error *err);

/* 1 when every event has been read, 0 before; -1 if src is not a replay
 * source. */
int hfs_replay_source_finished(hfs_input_source *src);

/* The number of events in the file; -1 if src is not a replay source. */
int hfs_replay_source_count(hfs_input_source *src);

#endif /* HFS_BOARD_INPUT_REPLAY_H */
