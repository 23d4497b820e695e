/*
 * height_netpbm.c — PGM (P5 binary, P2 ASCII) and PFM ("Pf") height loaders,
 * and hfs_pfm_read_image() (Pf or PF into an RGB image, for comparisons).
 *
 * PGM (netpbm pgm(5)): "P5"|"P2", width, height, maxval as decimal tokens with
 * '#' comments, then for P5 exactly one whitespace byte and width*height
 * samples of 1 byte (maxval < 256) or 2 bytes big-endian; for P2 decimal
 * tokens.  Heights are the raw samples (not divided by maxval).
 * PFM: "Pf" (or, for hfs_pfm_read_image, also "PF"), width, height, scale
 * (negative = little-endian), one whitespace byte, width*height*channels
 * float32.  SPEC: the first row in the file is j = 0 (the
 * opposite of the customary bottom-up PFM); PFM writers in this project
 * follow the same rule, so a round trip is exact.
 *
 * Invariants: header numbers are checked before any allocation; a file that
 * is shorter than its header promises is rejected before the big allocation
 * when its size is known; samples above maxval, bytes after the image and
 * non-numeric tokens are errors.  Nothing is read past what the header
 * describes except to prove the file ends there.
 */
#include "io_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Largest dimension we even try to represent; anything above is "absurd"
 * and reported as such instead of as an overflow. */
#define DIM_PARSE_MAX (1LL << 40)

static int read_dim(hfs_rd *rd, const char *fmt, const char *name, int comments,
                    long long *v, hfs_error *err)
{
    char tok[64];
    int n = hfs_rd_token(rd, tok, sizeof tok, comments);
    int r;

    if (n == 0) {
        char what[16];
        snprintf(what, sizeof what, "%s header", fmt);
        return hfs_rd_fail_short(rd, err, what);
    }
    if (n < 0)
        return hfs_fail(err, HFS_E_FORMAT, "%s: malformed %s header (overlong %s)", rd->path,
                        fmt, name);
    if (tok[0] == '-')
        return hfs_fail(err, HFS_E_FORMAT, "%s: negative %s %s in the %s header", rd->path,
                        name, tok, fmt);
    r = hfs_io_parse_uint(tok, DIM_PARSE_MAX, v);
    if (r == -2)
        return hfs_fail(err, HFS_E_FORMAT, "%s: absurd %s %s in the %s header", rd->path, name,
                        tok, fmt);
    if (r)
        return hfs_fail(err, HFS_E_FORMAT, "%s: %s is not a number (\"%s\") in the %s header",
                        rd->path, name, tok, fmt);
    return HFS_OK;
}

/* The single whitespace byte that separates a binary header from its data. */
static int header_end(hfs_rd *rd, const char *fmt, hfs_error *err)
{
    int c = hfs_rd_getc(rd);
    if (c < 0) {
        char what[16];
        snprintf(what, sizeof what, "%s header", fmt);
        return hfs_rd_fail_short(rd, err, what);
    }
    if (!hfs_io_isspace(c))
        return hfs_fail(err, HFS_E_FORMAT,
                        "%s: malformed %s header (expected one whitespace byte before the data)",
                        rd->path, fmt);
    return HFS_OK;
}

/* Rejects a known-size file that cannot hold `bytes` more bytes, before we
 * allocate memory for a header's claim. */
static int check_remaining(hfs_rd *rd, long long bytes, const char *what, hfs_error *err)
{
    if (rd->file_size >= 0 && rd->file_size - rd->offset < bytes)
        return hfs_fail(err, HFS_E_FORMAT,
                        "%s: truncated %s (%lld bytes needed after the header, %lld present)",
                        rd->path, what, bytes, rd->file_size - rd->offset);
    return HFS_OK;
}

static int load_p5(hfs_rd *rd, int w, int h, unsigned maxval, float *z, hfs_error *err)
{
    size_t bps = maxval < 256 ? 1 : 2;
    size_t row = (size_t)w * bps;
    unsigned char *buf;
    int rc = HFS_OK;

    rc = check_remaining(rd, (long long)row * h, "PGM data", err);
    if (rc)
        return rc;
    buf = malloc(row);
    if (!buf)
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", rd->path);
    for (int j = 0; j < h && !rc; ++j) {
        if (hfs_rd_read(rd, buf, row) != row) {
            rc = hfs_rd_fail_short(rd, err, "PGM data");
            break;
        }
        for (int i = 0; i < w; ++i) {
            unsigned v = bps == 1 ? buf[i] : (unsigned)buf[2 * i] << 8 | buf[2 * i + 1];
            if (v > maxval) {
                rc = hfs_fail(err, HFS_E_FORMAT, "%s: sample %u at (%d, %d) exceeds maxval %u",
                              rd->path, v, i, j, maxval);
                break;
            }
            z[(size_t)j * (size_t)w + (size_t)i] = (float)v;
        }
    }
    free(buf);
    if (!rc)
        rc = hfs_rd_expect_end(rd, 0, err, "PGM image");
    return rc;
}

static int load_p2(hfs_rd *rd, int w, int h, unsigned maxval, float *z, hfs_error *err)
{
    size_t n = (size_t)w * (size_t)h;
    char tok[64];

    for (size_t k = 0; k < n; ++k) {
        long long v;
        int len = hfs_rd_token(rd, tok, sizeof tok, 1), r;
        if (len == 0) {
            if (rd->read_errno)
                return hfs_rd_fail_short(rd, err, "PGM data");
            return hfs_fail(err, HFS_E_FORMAT, "%s: truncated PGM data (%zu of %zu samples)",
                            rd->path, k, n);
        }
        if (len < 0)
            return hfs_fail(err, HFS_E_FORMAT, "%s: overlong token in PGM data at sample %zu",
                            rd->path, k);
        r = hfs_io_parse_uint(tok, maxval, &v);
        if (r == -2)
            return hfs_fail(err, HFS_E_FORMAT, "%s: sample %s at (%zu, %zu) exceeds maxval %u",
                            rd->path, tok, k % (size_t)w, k / (size_t)w, maxval);
        if (r)
            return hfs_fail(err, HFS_E_FORMAT, "%s: sample at (%zu, %zu) is not a number (\"%s\")",
                            rd->path, k % (size_t)w, k / (size_t)w, tok);
        z[k] = (float)v;
    }
    if (hfs_rd_token(rd, tok, sizeof tok, 1) != 0)
        return hfs_fail(err, HFS_E_FORMAT,
                        "%s: unexpected data after the PGM image (wrong size in the header?)",
                        rd->path);
    if (rd->read_errno)
        return hfs_rd_fail_short(rd, err, "PGM data");
    return HFS_OK;
}

int hfs_io_load_pgm(hfs_rd *rd, const hfs_io_hopts *o, hfs_heightmap *out, hfs_error *err)
{
    long long w, h, maxval;
    int kind, rc;
    float *z;

    if (hfs_rd_getc(rd) != 'P')
        return hfs_fail(err, HFS_E_FORMAT, "%s: not a PGM file (bad signature)", rd->path);
    kind = hfs_rd_getc(rd);
    if (kind != '5' && kind != '2')
        return hfs_fail(err, HFS_E_FORMAT, "%s: not a PGM file (bad signature)", rd->path);
    if ((rc = read_dim(rd, "PGM", "width", 1, &w, err)) ||
        (rc = read_dim(rd, "PGM", "height", 1, &h, err)))
        return rc;
    rc = hfs_io_check_size(rd->path, w, h, 2, o->max_w, o->max_h, o->max_texels, err);
    if (rc)
        return rc;
    if ((rc = read_dim(rd, "PGM", "maxval", 1, &maxval, err)))
        return rc;
    if (maxval < 1 || maxval > 65535)
        return hfs_fail(err, HFS_E_FORMAT, "%s: PGM maxval %lld is out of range 1..65535",
                        rd->path, maxval);
    if (kind == '5' && (rc = header_end(rd, "PGM", err)))
        return rc;
    /* P2: every sample takes at least two bytes ("0 "), so a known-size file
     * that is far too small is refused before the allocation. */
    if (kind == '2' && rd->file_size >= 0 && w * h > rd->file_size)
        return hfs_fail(err, HFS_E_FORMAT,
                        "%s: truncated PGM data (%lld bytes cannot hold %lld samples)", rd->path,
                        rd->file_size, w * h);

    z = malloc((size_t)w * (size_t)h * sizeof *z);
    if (!z)
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory for %lldx%lld heights", rd->path,
                        w, h);
    rc = kind == '5' ? load_p5(rd, (int)w, (int)h, (unsigned)maxval, z, err)
                     : load_p2(rd, (int)w, (int)h, (unsigned)maxval, z, err);
    if (rc) {
        free(z);
        return rc;
    }
    out->width = (int)w;
    out->height = (int)h;
    out->z = z;
    return HFS_OK;
}

/* Shared PFM reader: "Pf" always, "PF" only with allow_colour.  Returns the
 * values as stored (NaN/Inf included), channels 1 or 3, rows in file order. */
int hfs_io_read_pfm(hfs_rd *rd, const hfs_io_hopts *o, int min_side, int allow_colour,
                    int *width, int *height, int *channels, float **data, hfs_error *err)
{
    long long w, h;
    double scale = 0.0;
    char tok[64];
    int len, rc, little, nch;
    size_t row;
    unsigned char *buf;
    float *z;

    if (hfs_rd_getc(rd) != 'P')
        return hfs_fail(err, HFS_E_FORMAT, "%s: not a PFM file (bad signature)", rd->path);
    switch (hfs_rd_getc(rd)) {
    case 'f':
        nch = 1;
        break;
    case 'F':
        if (!allow_colour)
            return hfs_fail(err, HFS_E_UNSUPPORTED,
                            "%s: colour PFM (PF); a height field must be greyscale (Pf)", rd->path);
        nch = 3;
        break;
    default:
        return hfs_fail(err, HFS_E_FORMAT, "%s: not a PFM file (bad signature)", rd->path);
    }
    if ((rc = read_dim(rd, "PFM", "width", 0, &w, err)) ||
        (rc = read_dim(rd, "PFM", "height", 0, &h, err)))
        return rc;
    rc = hfs_io_check_size(rd->path, w, h, min_side, o->max_w, o->max_h, o->max_texels, err);
    if (rc)
        return rc;
    len = hfs_rd_token(rd, tok, sizeof tok, 0);
    if (len == 0)
        return hfs_rd_fail_short(rd, err, "PFM header");
    {
        hfs_io_locale loc;
        int r = -1;
        if (len > 0) {
            if ((rc = hfs_io_c_locale_begin(&loc, rd->path, err)))
                return rc;
            r = hfs_io_parse_real(tok, &scale);
            hfs_io_c_locale_end(&loc);
        }
        if (r || scale == 0.0)
            return hfs_fail(err, HFS_E_FORMAT,
                            "%s: PFM scale \"%s\" is not a finite non-zero number", rd->path,
                            len > 0 ? tok : "(overlong)");
    }
    little = scale < 0.0;
    if ((rc = header_end(rd, "PFM", err)))
        return rc;

    row = (size_t)w * (size_t)nch * 4;
    if ((rc = check_remaining(rd, (long long)row * h, "PFM data", err)))
        return rc;
    z = malloc((size_t)w * (size_t)h * (size_t)nch * sizeof *z);
    buf = malloc(row);
    if (!z || !buf) {
        free(z);
        free(buf);
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory for a %lldx%lld PFM", rd->path, w,
                        h);
    }
    for (long long j = 0; j < h; ++j) {
        /* SPEC: the first row stored is row j = 0, so no flip. */
        float *dst = z + (size_t)j * (size_t)w * (size_t)nch;
        if (hfs_rd_read(rd, buf, row) != row) {
            rc = hfs_rd_fail_short(rd, err, "PFM data");
            break;
        }
        for (size_t k = 0; k < (size_t)w * (size_t)nch; ++k)
            dst[k] = little ? hfs_io_f32_le(buf + 4 * k) : hfs_io_f32_be(buf + 4 * k);
    }
    free(buf);
    if (!rc)
        rc = hfs_rd_expect_end(rd, 0, err, "PFM image");
    if (rc) {
        free(z);
        return rc;
    }
    *width = (int)w;
    *height = (int)h;
    *channels = nch;
    *data = z;
    return HFS_OK;
}

int hfs_io_load_pfm(hfs_rd *rd, const hfs_io_hopts *o, hfs_heightmap *out, hfs_error *err)
{
    int w, h, nch, rc;
    float *z;

    rc = hfs_io_read_pfm(rd, o, 2, 0, &w, &h, &nch, &z, err);
    if (rc)
        return rc;
    out->width = w;
    out->height = h;
    out->z = z;
    return HFS_OK;
}

int hfs_pfm_read_image(const char *path, hfs_image *out, hfs_error *err)
{
    hfs_io_hopts o;
    hfs_rd rd;
    int w, h, nch, rc;
    float *v;

    if (!out)
        return hfs_fail(err, HFS_E_INVALID, "%s: no output", path ? path : "(no file)");
    memset(out, 0, sizeof *out);
    if (!path)
        return hfs_fail(err, HFS_E_INVALID, "(no file): no image path");
    memset(&o, 0, sizeof o);
    o.max_w = HFS_HEIGHT_MAX_DIM;
    o.max_h = HFS_HEIGHT_MAX_DIM;
    o.max_texels = HFS_HEIGHT_MAX_TEXELS;
    if ((rc = hfs_rd_open(&rd, path, err)))
        return rc;
    rc = hfs_io_read_pfm(&rd, &o, 1, 1, &w, &h, &nch, &v, err);
    hfs_rd_close(&rd);
    if (rc)
        return rc;
    if (nch == 1) {
        /* Grey to RGB in place, from the end so no value is overwritten
         * before it is read. */
        size_t n = (size_t)w * (size_t)h;
        float *rgb = realloc(v, n * 3 * sizeof *rgb);
        if (!rgb) {
            free(v);
            return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory for a %dx%d image", path, w, h);
        }
        for (size_t k = n; k-- > 0;)
            rgb[3 * k] = rgb[3 * k + 1] = rgb[3 * k + 2] = rgb[k];
        v = rgb;
    }
    out->width = w;
    out->height = h;
    out->rgb = v;
    return HFS_OK;
}
