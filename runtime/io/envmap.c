/*
 * envmap.c — hfs_envmap_load(): format by signature, Radiance .hdr through
 * stb_image, OpenEXR through envmap_exr.c, PFM through the shared PFM
 * reader (height_netpbm.c); final finiteness check.
 *
 * Radiance: we parse the header ourselves first (signature line, FORMAT,
 * resolution line) so that errors are specific and the size guard applies
 * before stb allocates anything; stb then decodes from our reader through
 * callbacks.  Headers with a NUL byte are refused, so that stb's reading of
 * the header (C strings) cannot differ from ours.  stb reads 0 at end of file instead of failing, so the callbacks
 * record any request it makes past the end ("overrun"): a file that ends
 * before its last pixel is reported as truncated rather than decoded black.
 * stb refills its buffer with requests of a fixed size (its first request
 * tells us which); any other request is an exact need, so a short answer to
 * it is also an overrun.  Past the end we feed 0xFF bytes, because stb's RLE
 * loop never advances on the zeros it would otherwise read (a truncated file
 * hangs plain stbi_loadf).  A known-size file smaller than the smallest
 * possible encoding of its declared size is refused before stb allocates.
 *
 * Limits: stb's vertical-flip flag is never set here; a program that sets it
 * process-wide with stbi_set_flip_vertically_on_load() would flip our maps,
 * which is why no hfshade code calls it.  Only the "-Y H +X W" orientation
 * and the RGBE encoding are accepted (stb supports no other).
 */
#include "io_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <stb_image.h>

/* The header (signature, variables, blank line, resolution) must fit in the
 * reader's peek window; real headers are a few hundred bytes. */
#define HDR_HEADER_MAX (60 * 1024)

typedef struct hdr_src {
    hfs_rd *rd;
    int refill_size;        /* size of stb's buffer refills (first request)   */
    int overrun;
} hdr_src;

static int hdr_read(void *user, char *data, int size)
{
    hdr_src *s = user;
    size_t got;

    if (size <= 0)
        return 0;
    if (!s->refill_size)
        s->refill_size = size;
    got = hfs_rd_read(s->rd, data, (size_t)size);
    if (got == 0 || (size != s->refill_size && got < (size_t)size)) {
        s->overrun = 1;
        /* stb reads zeros past the end, and a zero RLE count never advances,
         * so a truncated file would hang it.  Feed bytes that always make
         * progress (0xFF = a maximal run) until it finishes or fails; the
         * overrun flag turns the result into an error either way. */
        memset(data + got, 0xFF, (size_t)size - got);
        got = (size_t)size;
    }
    return (int)got;
}

static void hdr_skip(void *user, int n)
{
    hdr_src *s = user;
    char sink[256];

    /* stb's HDR decoder never skips; stay correct if it ever does. */
    if (n < 0) {
        s->overrun = 1;
        return;
    }
    while (n > 0) {
        int k = n < (int)sizeof sink ? n : (int)sizeof sink;
        if (hfs_rd_read(s->rd, sink, (size_t)k) != (size_t)k) {
            s->overrun = 1;
            return;
        }
        n -= k;
    }
}

static int hdr_eof(void *user)
{
    hdr_src *s = user;
    return hfs_rd_peekc(s->rd) < 0;
}

/* Next header line [p, eol) within [*pos, n); returns 0 if no newline. */
static int next_line(const unsigned char *h, size_t n, size_t *pos, size_t *start, size_t *len)
{
    const unsigned char *nl;
    if (*pos >= n)
        return 0;
    nl = memchr(h + *pos, '\n', n - *pos);
    if (!nl)
        return 0;
    *start = *pos;
    *len = (size_t)(nl - (h + *pos));
    *pos = (size_t)(nl - h) + 1;
    return 1;
}

static int line_is(const unsigned char *h, size_t start, size_t len, const char *s)
{
    return strlen(s) == len && memcmp(h + start, s, len) == 0;
}

/* The header is parsed from the peek window, so nothing is consumed yet and
 * the reader's offset would say 0: report the size we looked at instead. */
static int hdr_header_short(hfs_rd *rd, size_t n, hfs_error *err)
{
    if (rd->read_errno)
        return hfs_rd_fail_short(rd, err, "Radiance HDR header");
    return hfs_fail(err, HFS_E_FORMAT,
                    "%s: truncated Radiance HDR header (%zu bytes without the blank line and "
                    "resolution line that end it)", rd->path, n);
}

static int hdr_check_header(hfs_rd *rd, int *w, int *h, hfs_error *err)
{
    const unsigned char *hd;
    size_t n = hfs_rd_peek(rd, HDR_HEADER_MAX, &hd), pos = 0, st, len;
    int has_format = 0;
    char res[128], ax1[8], ax2[8];
    long long hh, ww;
    char *tok, *save = NULL;

    if (!next_line(hd, n, &pos, &st, &len))
        return hdr_header_short(rd, n, err);
    if (!line_is(hd, st, len, "#?RADIANCE") && !line_is(hd, st, len, "#?RGBE"))
        return hfs_fail(err, HFS_E_FORMAT,
                        "%s: not a Radiance HDR file (first line must be #?RADIANCE or #?RGBE)",
                        rd->path);
    for (;;) {
        if (!next_line(hd, n, &pos, &st, &len)) {
            if (n >= HDR_HEADER_MAX)
                return hfs_fail(err, HFS_E_FORMAT, "%s: Radiance HDR header is too long",
                                rd->path);
            return hdr_header_short(rd, n, err);
        }
        if (len == 0)
            break;
        if (len >= 7 && memcmp(hd + st, "FORMAT=", 7) == 0) {
            if (!line_is(hd, st, len, "FORMAT=32-bit_rle_rgbe"))
                return hfs_fail(err, HFS_E_UNSUPPORTED,
                                "%s: Radiance HDR format \"%.*s\" is not supported (need "
                                "32-bit_rle_rgbe)", rd->path, (int)(len > 60 ? 60 : len),
                                (const char *)hd + st);
            has_format = 1;
        }
    }
    if (!has_format)
        return hfs_fail(err, HFS_E_FORMAT, "%s: Radiance HDR header lacks FORMAT=32-bit_rle_rgbe",
                        rd->path);
    if (!next_line(hd, n, &pos, &st, &len))
        return hdr_header_short(rd, n, err);
    /* stb reads header lines as C strings: for it a NUL ends a line, and a
     * line that starts with one ends the header, so it could take another
     * line than ours for the resolution and allocate for that, past our
     * guard.  Radiance headers are text. */
    if (memchr(hd, '\0', pos))
        return hfs_fail(err, HFS_E_FORMAT, "%s: malformed Radiance HDR header (NUL byte)", rd->path);
    if (len >= sizeof res)
        return hfs_fail(err, HFS_E_FORMAT, "%s: malformed Radiance HDR resolution line", rd->path);
    memcpy(res, hd + st, len);
    res[len] = '\0';
    /* Exactly four tokens: axis, size, axis, size. */
    {
        char *t[5];
        int k = 0;
        for (tok = strtok_r(res, " \t\r", &save); tok && k < 5; tok = strtok_r(NULL, " \t\r", &save))
            t[k++] = tok;
        if (k != 4 || strlen(t[0]) >= sizeof ax1 || strlen(t[2]) >= sizeof ax2)
            return hfs_fail(err, HFS_E_FORMAT, "%s: malformed Radiance HDR resolution line",
                            rd->path);
        strcpy(ax1, t[0]);
        strcpy(ax2, t[2]);
        if (t[1][0] == '-' || t[3][0] == '-')
            return hfs_fail(err, HFS_E_FORMAT, "%s: negative size in the Radiance HDR resolution line",
                            rd->path);
        if (hfs_io_parse_uint(t[1], 1LL << 40, &hh) || hfs_io_parse_uint(t[3], 1LL << 40, &ww))
            return hfs_fail(err, HFS_E_FORMAT, "%s: malformed or absurd size in the Radiance HDR "
                            "resolution line", rd->path);
    }
    if (strcmp(ax1, "-Y") != 0 || strcmp(ax2, "+X") != 0)
        return hfs_fail(err, HFS_E_UNSUPPORTED,
                        "%s: Radiance HDR orientation %s/%s is not supported (need -Y H +X W)",
                        rd->path, ax1, ax2);
    {
        int rc = hfs_io_check_size(rd->path, ww, hh, 1, HFS_ENVMAP_MAX_DIM, HFS_ENVMAP_MAX_DIM,
                                   HFS_ENVMAP_MAX_TEXELS, err);
        if (rc)
            return rc;
    }
    /* A known-size file must at least hold the smallest possible encoding
     * (flat: 4 bytes a pixel; RLE: a 4-byte scanline header and, per
     * component, 2 bytes per run of up to 127 pixels), checked before stb
     * allocates the full float image a header may merely claim. */
    if (rd->file_size >= 0) {
        long long need = (ww >= 8 && ww < 32768) ? hh * (4 + 8 * ((ww + 126) / 127)) : ww * hh * 4;
        long long have = rd->file_size - (long long)pos;
        if (have < need)
            return hfs_fail(err, HFS_E_FORMAT,
                            "%s: truncated Radiance HDR pixel data (%lld bytes after the header, "
                            "a %lldx%lld image needs at least %lld)", rd->path, have, ww, hh, need);
    }
    *w = (int)ww;
    *h = (int)hh;
    return HFS_OK;
}

static int load_hdr(hfs_rd *rd, hfs_envmap *out, hfs_error *err)
{
    stbi_io_callbacks cb = {hdr_read, hdr_skip, hdr_eof};
    hdr_src src;
    int w = 0, h = 0, sw = 0, sh = 0, comp = 0, rc;
    float *px;
    size_t n;

    if ((rc = hdr_check_header(rd, &w, &h, err)))
        return rc;
    memset(&src, 0, sizeof src);
    src.rd = rd;
    px = stbi_loadf_from_callbacks(&cb, &src, &sw, &sh, &comp, 3);
    if (src.overrun || rd->read_errno) {
        stbi_image_free(px);
        return hfs_rd_fail_short(rd, err, "Radiance HDR pixel data");
    }
    if (!px) {
        const char *why = stbi_failure_reason();
        return hfs_fail(err, HFS_E_FORMAT, "%s: corrupt Radiance HDR data (stb_image: %s)",
                        rd->path, why ? why : "unknown error");
    }
    if (sw != w || sh != h) {
        stbi_image_free(px);
        return hfs_fail(err, HFS_E_FORMAT, "%s: Radiance HDR decoded as %dx%d, header says %dx%d",
                        rd->path, sw, sh, w, h);
    }
    n = (size_t)w * (size_t)h * 3;
    /* Our own allocation, so hfs_envmap_free() never depends on stb's
     * allocator being malloc. */
    out->rgb = malloc(n * sizeof *out->rgb);
    if (!out->rgb) {
        stbi_image_free(px);
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory for a %dx%d map", rd->path, w, h);
    }
    memcpy(out->rgb, px, n * sizeof *out->rgb);
    stbi_image_free(px);
    out->width = w;
    out->height = h;
    return HFS_OK;
}

/* PFM ("PF" RGB or "Pf" grey, R = G = B): the project's row order, first
 * row stored = top row = zenith (SPEC), values as stored (the finiteness
 * check below names a NaN). */
static int load_pfm(hfs_rd *rd, hfs_envmap *out, hfs_error *err)
{
    hfs_io_hopts o;
    memset(&o, 0, sizeof o);
    o.max_w = HFS_ENVMAP_MAX_DIM;
    o.max_h = HFS_ENVMAP_MAX_DIM;
    o.max_texels = HFS_ENVMAP_MAX_TEXELS;
    int w, h, nch;
    float *v;
    int rc = hfs_io_read_pfm(rd, &o, 1, 1, &w, &h, &nch, &v, err);
    if (rc)
        return rc;
    if (nch == 1) {
        const size_t n = (size_t)w * (size_t)h;
        float *rgb = malloc(n * 3 * sizeof *rgb);
        if (!rgb) {
            free(v);
            return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory for a %dx%d map", rd->path, w, h);
        }
        for (size_t k = 0; k < n; ++k)
            rgb[3 * k] = rgb[3 * k + 1] = rgb[3 * k + 2] = v[k];
        free(v);
        v = rgb;
    }
    out->width = w;
    out->height = h;
    out->rgb = v;
    return HFS_OK;
}

int hfs_envmap_load(const char *path, hfs_envmap *out, hfs_error *err)
{
    hfs_rd rd;
    const unsigned char *p;
    size_t n;
    int rc;

    if (!out)
        return hfs_fail(err, HFS_E_INVALID, "%s: no output", path ? path : "(no file)");
    memset(out, 0, sizeof *out);
    if (!path)
        return hfs_fail(err, HFS_E_INVALID, "(no file): no environment map path");
    if ((rc = hfs_rd_open(&rd, path, err)))
        return rc;
    n = hfs_rd_peek(&rd, 16, &p);
    const int is_exr = n >= 4 && memcmp(p, "\x76\x2f\x31\x01", 4) == 0;
    const int is_hdr = n >= 2 && p[0] == '#' && p[1] == '?';
    const int is_pfm = n >= 2 && p[0] == 'P' && (p[1] == 'F' || p[1] == 'f');
    char ext[8];
    hfs_io_extension(path, ext, sizeof ext);
    if (n == 0) {
        rc = rd.read_errno ? hfs_rd_fail_short(&rd, err, "file")
                           : hfs_fail(err, HFS_E_FORMAT, "%s: empty file", path);
    } else if ((!strcmp(ext, "hdr") && !is_hdr) || (!strcmp(ext, "exr") && !is_exr) ||
               (!strcmp(ext, "pfm") && !is_pfm)) {
        /* The name says one format and the content another: a mislabelled
         * file is more likely a mistake than a choice. */
        rc = hfs_fail(err, HFS_E_FORMAT, "%s: named .%s but the content is %s", path, ext,
                      is_exr ? "OpenEXR" : is_hdr ? "Radiance .hdr" : is_pfm ? "PFM"
                      : "neither .hdr, .exr nor PFM");
    } else if (is_exr) {
        hfs_rd_close(&rd); /* OpenEXRCore does its own reading */
        rc = hfs_io_envmap_load_exr(path, out, err);
    } else if (is_hdr) {
        rc = load_hdr(&rd, out, err);
    } else if (is_pfm) {
        rc = load_pfm(&rd, out, err);
    } else if (n >= 8 && memcmp(p, "\x89PNG\r\n\x1a\n", 8) == 0) {
        rc = hfs_fail(err, HFS_E_UNSUPPORTED,
                      "%s: PNG is not a high-dynamic-range environment map (use .hdr, .exr or .pfm)",
                      path);
    } else {
        rc = hfs_fail(err, HFS_E_FORMAT,
                      "%s: not a Radiance .hdr, OpenEXR or PFM file (bad signature)", path);
    }
    hfs_rd_close(&rd);

    if (!rc) {
        /* SPEC: no NaN/Inf may reach an output, and an environment map feeds
         * every pixel of it. */
        size_t total = (size_t)out->width * (size_t)out->height * 3;
        for (size_t k = 0; k < total; ++k) {
            if (!isfinite(out->rgb[k])) {
                size_t px = k / 3;
                rc = hfs_fail(err, HFS_E_FORMAT, "%s: pixel (%zu, %zu) is %s", path,
                              px % (size_t)out->width, px / (size_t)out->width,
                              isnan(out->rgb[k]) ? "NaN" : "infinite");
                break;
            }
        }
    }
    if (rc)
        hfs_envmap_free(out);
    return rc;
}

void hfs_envmap_free(hfs_envmap *m)
{
    if (!m)
        return;
    free(m->rgb);
    memset(m, 0, sizeof *m);
}
