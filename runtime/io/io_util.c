/*
 * io_util.c — reader, strict number parsing, size guards and atomic output
 * shared by every format of hfshade_io (see io_internal.h for the contract).
 *
 * Invariants: the reader never hands out bytes it has not read and never
 * reads beyond what a caller asks for plus one buffer; all offsets are 64-bit;
 * temporaries of the atomic writer never outlive a failed call.
 */
#include "io_internal.h"
#include "file_input.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

/* Large enough that header sniffing and text tokens never span a refill in
 * practice, small enough to be irrelevant next to the images themselves. */
#define HFS_RD_CAP (64 * 1024)

void hfs_io_strerror(int errnum, char *buf, size_t cap)
{
    /* XSI strerror_r (we build with _POSIX_C_SOURCE, not _GNU_SOURCE). */
    if (strerror_r(errnum, buf, cap) != 0)
        snprintf(buf, cap, "error %d", errnum);
}

int hfs_rd_open(hfs_rd *rd, const char *path, hfs_error *err)
{
    memset(rd, 0, sizeof *rd);
    if (!path || !*path)
        return hfs_fail(err, HFS_E_INVALID, "(no file): empty path");
    /* Regular files only, opened without blocking (file_input.h): a FIFO
     * would hang the open, a directory fail later with a confusing EISDIR. */
    int rc = hfs_fopen_regular(path, "input file", &rd->f, &rd->file_size, err);
    if (rc) {
        memset(rd, 0, sizeof *rd);
        return rc;
    }
    rd->path = path;
    rd->cap = HFS_RD_CAP;
    rd->buf = malloc(rd->cap);
    if (!rd->buf) {
        fclose(rd->f);
        memset(rd, 0, sizeof *rd);
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", path);
    }
    return HFS_OK;
}

void hfs_rd_close(hfs_rd *rd)
{
    if (!rd)
        return;
    if (rd->f)
        fclose(rd->f);
    free(rd->buf);
    memset(rd, 0, sizeof *rd);
}

/* Ensures n unread bytes are buffered if the file has them. */
static void rd_fill(hfs_rd *rd, size_t n)
{
    if (rd->len - rd->pos >= n || rd->read_errno)
        return;
    if (rd->pos > 0) {
        memmove(rd->buf, rd->buf + rd->pos, rd->len - rd->pos);
        rd->len -= rd->pos;
        rd->pos = 0;
    }
    while (rd->len < n && rd->len < rd->cap) {
        size_t got = fread(rd->buf + rd->len, 1, rd->cap - rd->len, rd->f);
        if (got == 0) {
            if (ferror(rd->f))
                rd->read_errno = errno ? errno : EIO;
            break;
        }
        rd->len += got;
    }
}

size_t hfs_rd_peek(hfs_rd *rd, size_t n, const unsigned char **p)
{
    if (n > rd->cap)
        n = rd->cap;
    rd_fill(rd, n);
    *p = rd->buf + rd->pos;
    return rd->len - rd->pos < n ? rd->len - rd->pos : n;
}

int hfs_rd_getc(hfs_rd *rd)
{
    if (rd->pos == rd->len) {
        rd_fill(rd, 1);
        if (rd->pos == rd->len)
            return -1;
    }
    rd->offset++;
    return rd->buf[rd->pos++];
}

int hfs_rd_peekc(hfs_rd *rd)
{
    if (rd->pos == rd->len) {
        rd_fill(rd, 1);
        if (rd->pos == rd->len)
            return -1;
    }
    return rd->buf[rd->pos];
}

size_t hfs_rd_read(hfs_rd *rd, void *dst, size_t n)
{
    unsigned char *d = dst;
    size_t have = rd->len - rd->pos, done;

    if (have > n)
        have = n;
    memcpy(d, rd->buf + rd->pos, have);
    rd->pos += have;
    done = have;
    /* Bulk data goes straight to the caller: no double copy of a 1 GiB
     * raw file through the small buffer. */
    while (done < n && !rd->read_errno) {
        size_t got = fread(d + done, 1, n - done, rd->f);
        if (got == 0) {
            if (ferror(rd->f))
                rd->read_errno = errno ? errno : EIO;
            break;
        }
        done += got;
    }
    rd->offset += (long long)done;
    return done;
}

int hfs_rd_fail_short(hfs_rd *rd, hfs_error *err, const char *what)
{
    if (rd->read_errno) {
        char why[128];
        hfs_io_strerror(rd->read_errno, why, sizeof why);
        return hfs_fail(err, HFS_E_IO, "%s: read error: %s", rd->path, why);
    }
    return hfs_fail(err, HFS_E_FORMAT, "%s: truncated %s (file ends after %lld bytes)",
                    rd->path, what, rd->offset);
}

int hfs_rd_expect_end(hfs_rd *rd, int ws_ok, hfs_error *err, const char *what)
{
    for (;;) {
        long long at = rd->offset;
        int c = hfs_rd_getc(rd);
        if (c < 0) {
            if (rd->read_errno)
                return hfs_rd_fail_short(rd, err, what);
            return HFS_OK;
        }
        if (ws_ok && hfs_io_isspace(c))
            continue;
        return hfs_fail(err, HFS_E_FORMAT,
                        "%s: unexpected data after the %s at byte %lld "
                        "(wrong size in the header?)", rd->path, what, at);
    }
}

int hfs_rd_token(hfs_rd *rd, char *tok, size_t cap, int comments)
{
    size_t n = 0;
    int c;

    for (;;) {
        c = hfs_rd_peekc(rd);
        if (c < 0)
            return 0;
        if (hfs_io_isspace(c)) {
            hfs_rd_getc(rd);
        } else if (comments && c == '#') {
            while ((c = hfs_rd_getc(rd)) >= 0 && c != '\n' && c != '\r')
                ;
        } else {
            break;
        }
    }
    for (;;) {
        c = hfs_rd_peekc(rd);
        if (c < 0 || hfs_io_isspace(c) || (comments && c == '#'))
            break;
        if (c == 0) {
            /* A NUL byte would end the C string early ("12\0abc" read as
             * 12): it becomes the two characters \0, which no number
             * grammar accepts and every message shows where it was. */
            if (n + 2 >= cap)
                return -1;
            tok[n++] = '\\';
            tok[n++] = '0';
            hfs_rd_getc(rd);
            continue;
        }
        if (n + 1 >= cap)
            return -1;
        tok[n++] = (char)c;
        hfs_rd_getc(rd);
    }
    tok[n] = '\0';
    return (int)n;
}

/* ---- numbers --------------------------------------------------------------- */

int hfs_io_parse_uint(const char *tok, long long max, long long *out)
{
    const char *p = tok;
    long long v = 0;
    int big = 0;

    if (*p == '+')
        ++p;
    if (!*p)
        return -1;
    for (; *p; ++p) {
        if (*p < '0' || *p > '9')
            return -1;
        /* Saturate instead of overflowing; keep scanning so "99999x" is
         * reported as not-a-number rather than too-big. */
        if (!big && v > (max - (*p - '0')) / 10)
            big = 1;
        else if (!big)
            v = v * 10 + (*p - '0');
    }
    if (big)
        return -2;
    *out = v;
    return 0;
}

int hfs_io_parse_real(const char *tok, double *out)
{
    const char *p = tok;
    int digits = 0;
    char *end;
    double v;

    if (*p == '+' || *p == '-')
        ++p;
    while (*p >= '0' && *p <= '9')
        ++p, ++digits;
    if (*p == '.') {
        ++p;
        while (*p >= '0' && *p <= '9')
            ++p, ++digits;
    }
    if (!digits)
        return -1;
    if (*p == 'e' || *p == 'E') {
        int ed = 0;
        ++p;
        if (*p == '+' || *p == '-')
            ++p;
        while (*p >= '0' && *p <= '9')
            ++p, ++ed;
        if (!ed)
            return -1;
    }
    if (*p)
        return -1;
    errno = 0;
    v = strtod(tok, &end);
    if (*end)
        return -1; /* cannot happen after the grammar check unless the locale differs */
    if (!isfinite(v))
        return -2;
    *out = v;
    return 0;
}

int hfs_io_c_locale_begin(hfs_io_locale *l, const char *path, hfs_error *err)
{
    l->c_locale = newlocale(LC_NUMERIC_MASK, "C", (locale_t)0);
    if (l->c_locale == (locale_t)0) {
        l->saved = (locale_t)0;
        return hfs_fail(err, HFS_E_NOMEM, "%s: cannot create the C locale", path);
    }
    l->saved = uselocale(l->c_locale);
    return HFS_OK;
}

void hfs_io_c_locale_end(hfs_io_locale *l)
{
    if (l->c_locale == (locale_t)0)
        return;
    uselocale(l->saved);
    freelocale(l->c_locale);
    l->c_locale = (locale_t)0;
}

float hfs_io_f32_le(const unsigned char *b)
{
    uint32_t u = (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 |
                 (uint32_t)b[3] << 24;
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

float hfs_io_f32_be(const unsigned char *b)
{
    uint32_t u = (uint32_t)b[3] | (uint32_t)b[2] << 8 | (uint32_t)b[1] << 16 |
                 (uint32_t)b[0] << 24;
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

/* ---- sizes and names ------------------------------------------------------- */

int hfs_io_check_size(const char *path, long long w, long long h, int min_side,
                      long long max_w, long long max_h, long long max_texels,
                      hfs_error *err)
{
    if (w < min_side || h < min_side)
        return hfs_fail(err, HFS_E_FORMAT, "%s: invalid size %lldx%lld (must be at least %dx%d)",
                        path, w, h, min_side, min_side);
    /* Sides first: once both are <= INT_MAX their product fits in 64 bits. */
    if (w > max_w || h > max_h || w * h > max_texels)
        return hfs_fail(err, HFS_E_INVALID,
                        "%s: size %lldx%lld exceeds the limit (%lldx%lld, %lld texels)",
                        path, w, h, max_w, max_h, max_texels);
    return HFS_OK;
}

void hfs_io_extension(const char *path, char *ext, size_t cap)
{
    const char *base = strrchr(path, '/');
    const char *dot;
    size_t n, k;

    base = base ? base + 1 : path;
    dot = strrchr(base, '.');
    ext[0] = '\0';
    if (!dot || dot == base)
        return;
    n = strlen(dot + 1);
    if (n + 1 > cap)
        return;
    for (k = 0; k < n; ++k) {
        char c = dot[1 + k];
        ext[k] = (c >= 'A' && c <= 'Z') ? (char)(c - 'A' + 'a') : c;
    }
    ext[n] = '\0';
}
