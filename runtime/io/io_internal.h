/*
 * io_internal.h — shared plumbing of hfshade_io (not installed, not public).
 *
 * - hfs_rd: a buffered reader over a FILE that never reads past what it is
 *   asked for, can peek at the signature before a decoder sees the stream, and
 *   tells a short file ("truncated") from a read error ("I/O error").
 * - Strict number parsers: tokens are checked against a grammar before any
 *   conversion, so "12abc", "0x10", "nan" or an empty token never become a
 *   value, and the C library's locale can never turn "1.5" into 1.
 * - hfs_io_atomic (io_output.c): "TARGET.tmp-XXXXXX" next to the target,
 *   renamed over it only on success; every failure path removes the
 *   temporary; an existing non-regular target (a device) is written in
 *   place, never replaced.
 *
 * Invariants: every function that fails fills err with "PATH: problem" and
 * returns a negative hfs_status; none prints; none keeps global state.
 */
#ifndef HFS_IO_INTERNAL_H
#define HFS_IO_INTERNAL_H

#include "hfs_io.h"

#include <locale.h>
#include <stddef.h>
#include <stdio.h>

/* ---- buffered reader ------------------------------------------------------- */

typedef struct hfs_rd {
    FILE *f;
    const char *path;
    unsigned char *buf;
    size_t cap, pos, len;   /* buf[pos..len) is unread data                    */
    long long file_size;    /* from fstat for regular files, else -1           */
    long long offset;       /* bytes consumed so far                           */
    int read_errno;         /* non-zero once a read failed (not EOF)           */
} hfs_rd;

/* Opens path for reading; rejects directories.  rd is zeroed on failure. */
int hfs_rd_open(hfs_rd *rd, const char *path, hfs_error *err);
void hfs_rd_close(hfs_rd *rd);

/* Makes up to n (<= rd->cap) bytes available without consuming them;
 * returns how many are (fewer only at end of file or on a read error). */
size_t hfs_rd_peek(hfs_rd *rd, size_t n, const unsigned char **p);

/* Next byte, or -1 at end of file / on error. */
int hfs_rd_getc(hfs_rd *rd);
/* Next byte without consuming it, or -1. */
int hfs_rd_peekc(hfs_rd *rd);

/* Reads up to n bytes into dst; returns the count (< n only at EOF/error). */
size_t hfs_rd_read(hfs_rd *rd, void *dst, size_t n);

/* Error for "expected more data": an I/O error if a read failed, otherwise
 * "truncated <what>" (HFS_E_FORMAT). */
int hfs_rd_fail_short(hfs_rd *rd, hfs_error *err, const char *what);

/* 0 if the stream is at its end; otherwise fails with "trailing data after
 * <what>" (HFS_E_FORMAT).  With ws_ok, trailing ASCII whitespace is allowed. */
int hfs_rd_expect_end(hfs_rd *rd, int ws_ok, hfs_error *err, const char *what);

/* Header token: skips ASCII whitespace (and '#' comments to end of line when
 * comments != 0), then copies the token (non-whitespace, not '#' when
 * comments) into tok (NUL-terminated) WITHOUT consuming the byte after it.
 * Returns the token length, 0 at end of file, -1 if longer than cap - 1.
 * A NUL byte inside a token is stored as the two characters "\0", so the
 * token is never cut short (no parser accepts it; messages show it). */
int hfs_rd_token(hfs_rd *rd, char *tok, size_t cap, int comments);

static inline int hfs_io_isspace(int c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' ||
           c == '\f';
}

/* ---- numbers -------------------------------------------------------------- */

/* Unsigned decimal integer (digits only, optional leading '+').  Returns 0 and
 * the value, -1 if tok is not such an integer, -2 if it exceeds max. */
int hfs_io_parse_uint(const char *tok, long long max, long long *out);

/* Decimal real: [+-] digits [. digits] [(e|E) [+-] digits], at least one
 * mantissa digit; no hex, inf or nan.  Returns 0 and the value, -1 if not a
 * number, -2 if it overflows double.  Converted with strtod in the "C"
 * locale of the calling thread (set by hfs_io_c_locale). */
int hfs_io_parse_real(const char *tok, double *out);

/* Switches the calling thread (uselocale, thread-local, no global state) to
 * the "C" numeric locale until hfs_io_c_locale_end(). */
typedef struct hfs_io_locale {
    locale_t c_locale;
    locale_t saved;
} hfs_io_locale;
int hfs_io_c_locale_begin(hfs_io_locale *l, const char *path, hfs_error *err);
void hfs_io_c_locale_end(hfs_io_locale *l);

/* ---- sizes ---------------------------------------------------------------- */

/* Validates a declared size: HFS_E_FORMAT below min_side (zero/negative),
 * HFS_E_INVALID above the guard.  w, h are as parsed (64-bit). */
int hfs_io_check_size(const char *path, long long w, long long h, int min_side,
                      long long max_w, long long max_h, long long max_texels,
                      hfs_error *err);

/* ---- errors --------------------------------------------------------------- */

/* strerror() without the shared static buffer. */
void hfs_io_strerror(int errnum, char *buf, size_t cap);

/* Lower-case extension of path's last component ("" if none), at most
 * cap - 1 characters (longer ones are returned as ""). */
void hfs_io_extension(const char *path, char *ext, size_t cap);

/* ---- atomic output -------------------------------------------------------- */

typedef struct hfs_io_atomic {
    FILE *f;
    char *tmp;              /* temporary name, owned (NULL when in place)      */
    char *target;           /* path with symbolic links resolved, owned        */
    const char *path;       /* name as given, borrowed (for messages)          */
    int in_place;           /* an existing device or FIFO: written directly    */
    int created;            /* the target did not exist before this run        */
} hfs_io_atomic;

/* Creates the temporary next to the target (or opens a device target in
 * place); a->f is ready for writing.  A directory or a dangling symbolic
 * link is an error. */
int hfs_io_atomic_open(hfs_io_atomic *a, const char *path, hfs_error *err);
/* hfs_io_atomic_finish (flush, sync, close: the temporary is complete) then
 * hfs_io_atomic_rename (over the target).  On failure the temporary is
 * removed.  Either way a is released. */
int hfs_io_atomic_commit(hfs_io_atomic *a, hfs_error *err);
int hfs_io_atomic_finish(hfs_io_atomic *a, hfs_error *err);
int hfs_io_atomic_rename(hfs_io_atomic *a, hfs_error *err);
/* Finishes a and hands it to the output set, which renames it at
 * hfs_outputs_commit; a's path must have been added to o. */
int hfs_io_outputs_adopt(hfs_outputs *o, hfs_io_atomic *a, hfs_error *err);
/* fwrite that reports a short write as "PATH: write error: ..." (HFS_E_IO). */
int hfs_io_atomic_write(hfs_io_atomic *a, const void *data, size_t n,
                        hfs_error *err);
/* Closes and removes the temporary.  Safe on a zeroed or released a. */
void hfs_io_atomic_abort(hfs_io_atomic *a);

/* ---- format loaders (height_*.c) -------------------------------------------- */

/* Resolved options: guards filled in, raw size validated. */
typedef struct hfs_io_hopts {
    long long max_w, max_h, max_texels;
    int raw_w, raw_h;
} hfs_io_hopts;

/* Each loader reads the whole stream from rd (positioned at the start), sets
 * out->width/height/z (z malloc'ed, format-specific holes already NaN) and
 * format-specific fields, and on failure frees what it allocated and leaves
 * out untouched. */
int hfs_io_load_png(hfs_rd *rd, const hfs_io_hopts *o, hfs_heightmap *out,
                    hfs_error *err);
int hfs_io_load_pgm(hfs_rd *rd, const hfs_io_hopts *o, hfs_heightmap *out,
                    hfs_error *err);
int hfs_io_load_pfm(hfs_rd *rd, const hfs_io_hopts *o, hfs_heightmap *out,
                    hfs_error *err);
int hfs_io_load_asc(hfs_rd *rd, const hfs_io_hopts *o, hfs_heightmap *out,
                    hfs_error *err);

/* PFM body shared by the height loader and hfs_pfm_read_image: "Pf" (and "PF"
 * if allow_colour), size checked against o and min_side, values as stored
 * (NaN/Inf kept), *channels = 1 or 3, *data malloc'ed w*h*channels. */
int hfs_io_read_pfm(hfs_rd *rd, const hfs_io_hopts *o, int min_side, int allow_colour,
                    int *width, int *height, int *channels, float **data, hfs_error *err);

/* Little-endian / big-endian float32 from 4 bytes, independent of the host. */
float hfs_io_f32_le(const unsigned char *b);
float hfs_io_f32_be(const unsigned char *b);

/* EXR loader (envmap_exr.c); path already known to carry the EXR magic. */
int hfs_io_envmap_load_exr(const char *path, hfs_envmap *out, hfs_error *err);

#endif /* HFS_IO_INTERNAL_H */
