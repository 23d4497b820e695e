/*
 * file_input.h — opening input files so that no input can hang or fool a
 * reader (issue 13).  Every reader of a user-named file goes through here:
 * heights, environment maps, PFMs, scene files, input configurations,
 * replay files.
 *
 * Why: open(2) of a FIFO with no writer blocks forever, and a FIFO or socket
 * swapped in between a stat() and an fopen() defeats any check made by
 * name.  So the file is opened with O_NONBLOCK (which never blocks), the
 * descriptor is checked with fstat (regular files only: a directory, FIFO,
 * socket or device is a one-line error naming what it is), and only then
 * switched back to blocking reads.
 */
#ifndef HFS_FILE_INPUT_H
#define HFS_FILE_INPUT_H

#include "hfshade.h"

#include <stddef.h>
#include <stdio.h>

/* What kind of file st_mode is, for messages: "a directory", "a FIFO",
 * "a socket", "a character device", "a block device", "a symbolic link",
 * "not a regular file". */
const char *hfs_file_kind(unsigned mode);

/* Opens path for reading as above: *fd (O_CLOEXEC, blocking reads) and
 * HFS_OK, or a negative status with err set ("PATH: cannot open WHAT:
 * reason", "PATH: the WHAT is a FIFO, not a regular file"; HFS_E_IO) and
 * *fd = -1.  *size_out (if non-NULL) gets the file's size. */
int hfs_open_regular(const char *path, const char *what, int *fd, long long *size_out,
                     hfs_error *err);

/* The same as a stdio stream ("rb"). */
int hfs_fopen_regular(const char *path, const char *what, FILE **f, long long *size_out,
                      hfs_error *err);

/* Reads a whole text file of at most max_bytes: *text is malloc'ed and
 * NUL-terminated, *len its length.  A NUL byte inside is an error ("PATH:
 * binary data in WHAT": a NUL would silently end every string parsed from
 * it), as is a larger file ("PATH: WHAT larger than N bytes", HFS_E_FORMAT). */
int hfs_read_text_file(const char *path, const char *what, long long max_bytes, char **text,
                       size_t *len, hfs_error *err);

#endif /* HFS_FILE_INPUT_H */
