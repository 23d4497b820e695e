/*
 * io_util.c — reader, strict number parsing, size guards and atomic output
 * shared by every format of hfshade_io (see io_internal.h for the contract).
 *
 * Invariants: the reader never hands out bytes it has not read and never
 * reads beyond what a caller asks for plus one buffer; all offsets are 64-bit;
 * temporaries of the atomic writer never outlive a failed call.
 */
#include "io_internal.h"

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
    char why[128];
    struct stat st;

    memset(rd, 0, sizeof *rd);
    rd->path = path;
    rd->file_size = -1;
    if (!path || !*path)
        return hfs_fail(err, HFS_E_INVALID, "(no file): empty path");
    rd->f = fopen(path, "rb");
    if (!rd->f) {
        hfs_io_strerror(errno, why, sizeof why);
        memset(rd, 0, sizeof *rd);
        return hfs_fail(err, HFS_E_IO, "%s: cannot open: %s", path, why);
    }
    /* fopen() happily opens a directory on Linux; reading it then fails
     * with a confusing EISDIR, so say what is wrong up front. */
    if (fstat(fileno(rd->f), &st) == 0) {
        if (S_ISDIR(st.st_mode)) {
            fclose(rd->f);
            memset(rd, 0, sizeof *rd);
            return hfs_fail(err, HFS_E_IO, "%s: is a directory, not a file", path);
        }
        if (S_ISREG(st.st_mode))
            rd->file_size = (long long)st.st_size;
    }
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

/* ---- atomic output --------------------------------------------------------- */

static uint64_t splitmix64(uint64_t x)
{
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

int hfs_io_atomic_open(hfs_io_atomic *a, const char *path, hfs_error *err)
{
    static const char alphabet[] =
        "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    struct timespec ts;
    size_t n;
    int fd = -1;

    memset(a, 0, sizeof *a);
    if (!path || !*path)
        return hfs_fail(err, HFS_E_INVALID, "(no file): empty output path");
    n = strlen(path);
    a->tmp = malloc(n + sizeof ".tmp-XXXXXX");
    if (!a->tmp)
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", path);
    clock_gettime(CLOCK_REALTIME, &ts);
    /* open(O_EXCL) with our own random suffix rather than mkstemp(): mkstemp
     * creates mode 0600, and reading the umask to fix that is process-global
     * and racy.  O_EXCL makes a collision a retry, never a clobber. */
    for (unsigned attempt = 0; attempt < 100; ++attempt) {
        uint64_t r = splitmix64((uint64_t)ts.tv_nsec ^ ((uint64_t)ts.tv_sec << 30) ^
                                ((uint64_t)getpid() << 40) ^ (uint64_t)(uintptr_t)a ^
                                ((uint64_t)attempt << 20));
        memcpy(a->tmp, path, n);
        memcpy(a->tmp + n, ".tmp-", 5);
        for (int k = 0; k < 6; ++k) {
            a->tmp[n + 5 + k] = alphabet[r % 62];
            r /= 62;
        }
        a->tmp[n + 11] = '\0';
        fd = open(a->tmp, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0 || errno != EEXIST)
            break;
    }
    if (fd < 0) {
        char why[128];
        hfs_io_strerror(errno, why, sizeof why);
        free(a->tmp);
        a->tmp = NULL;
        return hfs_fail(err, HFS_E_IO, "%s: cannot create a temporary file next to it: %s",
                        path, why);
    }
    a->f = fdopen(fd, "wb");
    if (!a->f) {
        char why[128];
        hfs_io_strerror(errno, why, sizeof why);
        close(fd);
        unlink(a->tmp);
        free(a->tmp);
        a->tmp = NULL;
        return hfs_fail(err, HFS_E_IO, "%s: cannot open for writing: %s", path, why);
    }
    a->path = path;
    return HFS_OK;
}

int hfs_io_atomic_write(hfs_io_atomic *a, const void *data, size_t n, hfs_error *err)
{
    if (n && fwrite(data, 1, n, a->f) != n) {
        char why[128];
        hfs_io_strerror(errno ? errno : EIO, why, sizeof why);
        return hfs_fail(err, HFS_E_IO, "%s: write error: %s", a->path, why);
    }
    return HFS_OK;
}

void hfs_io_atomic_abort(hfs_io_atomic *a)
{
    if (!a)
        return;
    if (a->f)
        fclose(a->f);
    if (a->tmp) {
        unlink(a->tmp);
        free(a->tmp);
    }
    memset(a, 0, sizeof *a);
}

int hfs_io_atomic_commit(hfs_io_atomic *a, hfs_error *err)
{
    char why[128];
    const char *step = NULL;
    int e = 0;

    if (fflush(a->f) != 0 || ferror(a->f)) {
        step = "write error";
        e = errno ? errno : EIO;
    } else if (fsync(fileno(a->f)) != 0) {
        /* Without this a crash after rename could expose an empty file. */
        step = "cannot sync";
        e = errno;
    }
    if (fclose(a->f) != 0 && !step) {
        step = "write error";
        e = errno ? errno : EIO;
    }
    a->f = NULL;
    if (!step && rename(a->tmp, a->path) != 0) {
        step = "cannot replace the file";
        e = errno;
    }
    if (step) {
        int rc;
        hfs_io_strerror(e, why, sizeof why);
        rc = hfs_fail(err, HFS_E_IO, "%s: %s: %s", a->path, step, why);
        hfs_io_atomic_abort(a);
        return rc;
    }
    free(a->tmp);
    memset(a, 0, sizeof *a);
    return HFS_OK;
}
