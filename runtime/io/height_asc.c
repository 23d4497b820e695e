/*
 * height_asc.c — ESRI ASCII grid (.asc) height loader.
 *
 * Header: "key value" pairs, keys case-insensitive, any order, each at most
 * once: ncols, nrows, xllcorner|xllcenter, yllcorner|yllcenter, cellsize
 * (required) and NODATA_value (optional).  Then nrows*ncols decimal numbers,
 * the first data row being the NORTH row.  We keep file order: the first data
 * row is j = 0, as the top row of a PNG/PGM is, so +y of the grid points
 * south on the map.  cellsize is returned for the caller's dx default; the
 * lower-left corner is validated but not returned (the renderer's grid starts
 * at 0).
 *
 * Invariants: every token is checked against a strict decimal grammar and
 * converted in the "C" locale; values outside float range are errors (except
 * the declared NODATA_value, which becomes a hole); the count of values must
 * match the header exactly.
 */
#include "io_internal.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define DIM_PARSE_MAX (1LL << 40)

enum { K_NCOLS, K_NROWS, K_XLL, K_YLL, K_CELL, K_NODATA, K_COUNT };

typedef struct asc_header {
    int seen[K_COUNT];
    long long ncols, nrows;
    double xll, yll, cellsize, nodata;
} asc_header;

/* double -> float without undefined behaviour: values that round to +-FLT_MAX
 * (e.g. the common nodata "-3.4028235e+38", just above FLT_MAX) are accepted,
 * anything larger is reported as out of range. */
static int fit_float(double v, float *f)
{
    double a = fabs(v);
    if (a <= FLT_MAX) {
        *f = (float)v;
        return 1;
    }
    if (a < 3.4028235677973366e+38) { /* FLT_MAX + half an ulp */
        *f = v < 0 ? -FLT_MAX : FLT_MAX;
        return 1;
    }
    return 0;
}

static void lower(char *s)
{
    for (; *s; ++s)
        if (*s >= 'A' && *s <= 'Z')
            *s = (char)(*s - 'A' + 'a');
}

static int is_key_token(const char *t)
{
    return (t[0] >= 'a' && t[0] <= 'z') || (t[0] >= 'A' && t[0] <= 'Z');
}

static int parse_key(hfs_rd *rd, asc_header *hd, char *key, const char *val, hfs_error *err)
{
    const char *p = rd->path;
    int slot, r;

    lower(key);
    if (!strcmp(key, "ncols")) slot = K_NCOLS;
    else if (!strcmp(key, "nrows")) slot = K_NROWS;
    else if (!strcmp(key, "xllcorner") || !strcmp(key, "xllcenter")) slot = K_XLL;
    else if (!strcmp(key, "yllcorner") || !strcmp(key, "yllcenter")) slot = K_YLL;
    else if (!strcmp(key, "cellsize")) slot = K_CELL;
    else if (!strcmp(key, "nodata_value")) slot = K_NODATA;
    else if (!strcmp(key, "dx") || !strcmp(key, "dy") || !strcmp(key, "xdim") ||
             !strcmp(key, "ydim"))
        return hfs_fail(err, HFS_E_UNSUPPORTED,
                        "%s: non-square cells (%s) are not supported; resample to one cellsize",
                        p, key);
    else
        return hfs_fail(err, HFS_E_FORMAT, "%s: unknown ESRI grid header key \"%s\"", p, key);
    if (hd->seen[slot])
        return hfs_fail(err, HFS_E_FORMAT, "%s: duplicate ESRI grid header key \"%s\"", p, key);
    hd->seen[slot] = 1;

    if (slot == K_NCOLS || slot == K_NROWS) {
        long long v = 0;
        if (val[0] == '-')
            return hfs_fail(err, HFS_E_FORMAT, "%s: negative %s %s", p, key, val);
        r = hfs_io_parse_uint(val, DIM_PARSE_MAX, &v);
        if (r == -2)
            return hfs_fail(err, HFS_E_FORMAT, "%s: absurd %s %s", p, key, val);
        if (r)
            return hfs_fail(err, HFS_E_FORMAT, "%s: %s is not an integer (\"%s\")", p, key, val);
        if (slot == K_NCOLS)
            hd->ncols = v;
        else
            hd->nrows = v;
        return HFS_OK;
    }
    {
        double v = 0.0;
        r = hfs_io_parse_real(val, &v);
        if (r)
            return hfs_fail(err, HFS_E_FORMAT, "%s: %s is not a finite number (\"%s\")", p, key,
                            val);
        switch (slot) {
        case K_XLL: hd->xll = v; break;
        case K_YLL: hd->yll = v; break;
        case K_NODATA: hd->nodata = v; break;
        default:
            if (!(v > 0.0))
                return hfs_fail(err, HFS_E_FORMAT, "%s: cellsize %s must be positive", p, val);
            hd->cellsize = v;
            break;
        }
    }
    return HFS_OK;
}

/* Parses the header; leaves the first data token in tok (len in *len). */
static int read_header(hfs_rd *rd, asc_header *hd, char *tok, size_t cap, int *len,
                       hfs_error *err)
{
    static const char *const names[K_COUNT] = {"ncols", "nrows", "xllcorner/xllcenter",
                                               "yllcorner/yllcenter", "cellsize",
                                               "NODATA_value"};
    char val[128];
    int rc;

    for (;;) {
        int vlen;
        *len = hfs_rd_token(rd, tok, cap, 0);
        if (*len < 0)
            return hfs_fail(err, HFS_E_FORMAT, "%s: overlong token in the ESRI grid header",
                            rd->path);
        if (*len == 0 || !is_key_token(tok))
            break;
        vlen = hfs_rd_token(rd, val, sizeof val, 0);
        if (vlen == 0)
            return hfs_rd_fail_short(rd, err, "ESRI grid header");
        if (vlen < 0)
            return hfs_fail(err, HFS_E_FORMAT, "%s: overlong value of %s", rd->path, tok);
        if ((rc = parse_key(rd, hd, tok, val, err)))
            return rc;
    }
    if (rd->read_errno)
        return hfs_rd_fail_short(rd, err, "ESRI grid header");
    for (int k = 0; k < K_NODATA; ++k)
        if (!hd->seen[k])
            return hfs_fail(err, HFS_E_FORMAT, "%s: ESRI grid header lacks %s", rd->path,
                            names[k]);
    return HFS_OK;
}

int hfs_io_load_asc(hfs_rd *rd, const hfs_io_hopts *o, hfs_heightmap *out, hfs_error *err)
{
    asc_header hd;
    hfs_io_locale loc;
    char tok[128];
    int len, rc;
    size_t n, k = 0;
    float *z = NULL;
    float nodata_f = 0.0f;
    int nodata_is_float;

    memset(&hd, 0, sizeof hd);
    if ((rc = hfs_io_c_locale_begin(&loc, rd->path, err)))
        return rc;
    if ((rc = read_header(rd, &hd, tok, sizeof tok, &len, err)))
        goto fail;
    if ((rc = hfs_io_check_size(rd->path, hd.ncols, hd.nrows, 2, o->max_w, o->max_h,
                                o->max_texels, err)))
        goto fail;
    nodata_is_float = hd.seen[K_NODATA] && fit_float(hd.nodata, &nodata_f);

    n = (size_t)hd.ncols * (size_t)hd.nrows;
    /* Every value takes at least two bytes ("0 "); a known-size file that is
     * far too small is cut short before the allocation. */
    if (rd->file_size >= 0 && (long long)n > rd->file_size) {
        rc = hfs_fail(err, HFS_E_FORMAT,
                      "%s: truncated ESRI grid (%lld bytes cannot hold %zu values)", rd->path,
                      rd->file_size, n);
        goto fail;
    }
    z = malloc(n * sizeof *z);
    if (!z) {
        rc = hfs_fail(err, HFS_E_NOMEM, "%s: out of memory for %lldx%lld heights", rd->path,
                      hd.ncols, hd.nrows);
        goto fail;
    }

    /* tok already holds the first data token (or nothing). */
    for (; k < n; ++k) {
        double v = 0.0;
        float f = 0.0f;
        int r, fits;
        if (k > 0)
            len = hfs_rd_token(rd, tok, sizeof tok, 0);
        if (len == 0) {
            rc = rd->read_errno ? hfs_rd_fail_short(rd, err, "ESRI grid data")
                                : hfs_fail(err, HFS_E_FORMAT,
                                           "%s: truncated ESRI grid data (%zu of %zu values)",
                                           rd->path, k, n);
            goto fail;
        }
        if (len < 0) {
            rc = hfs_fail(err, HFS_E_FORMAT, "%s: overlong token at row %zu, column %zu",
                          rd->path, k / (size_t)hd.ncols, k % (size_t)hd.ncols);
            goto fail;
        }
        r = hfs_io_parse_real(tok, &v);
        if (r == -1) {
            rc = hfs_fail(err, HFS_E_FORMAT,
                          "%s: value at row %zu, column %zu is not a number (\"%s\")", rd->path,
                          k / (size_t)hd.ncols, k % (size_t)hd.ncols, tok);
            goto fail;
        }
        fits = r == 0 && fit_float(v, &f);
        if (hd.seen[K_NODATA] && r == 0 &&
            (v == hd.nodata || (fits && nodata_is_float && f == nodata_f))) {
            z[k] = NAN;
            continue;
        }
        if (!fits) {
            rc = hfs_fail(err, HFS_E_FORMAT,
                          "%s: value %s at row %zu, column %zu is out of float range", rd->path,
                          tok, k / (size_t)hd.ncols, k % (size_t)hd.ncols);
            goto fail;
        }
        z[k] = f;
    }
    len = hfs_rd_token(rd, tok, sizeof tok, 0);
    if (len != 0) {
        rc = hfs_fail(err, HFS_E_FORMAT,
                      "%s: unexpected data after %zu values (wrong ncols/nrows in the header?)",
                      rd->path, n);
        goto fail;
    }
    if (rd->read_errno) {
        rc = hfs_rd_fail_short(rd, err, "ESRI grid data");
        goto fail;
    }
    hfs_io_c_locale_end(&loc);
    out->width = (int)hd.ncols;
    out->height = (int)hd.nrows;
    out->z = z;
    out->cellsize = hd.cellsize;
    return HFS_OK;

fail:
    hfs_io_c_locale_end(&loc);
    free(z);
    return rc;
}
