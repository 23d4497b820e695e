/*
 * height_png.c — greyscale PNG height loader (libpng).
 *
 * Accepted: colour type GRAY (1, 2, 4, 8, 16 bit) and GRAY_ALPHA (8, 16 bit).
 * Height = the stored sample (16-bit samples are big-endian in the file;
 * sub-byte samples are unpacked without scaling, so a 4-bit 15 is 15).
 * Alpha 0 marks a hole; other alpha values are ignored.  PALETTE, RGB and RGBA
 * are refused: their greys are an accident of the colour map and would make
 * silent, wrong heights.  No gamma, sBIT or tRNS transform is applied, and
 * ancillary chunks are skipped without being parsed.  The
 * file must be complete through IEND (png_read_end), which also verifies the
 * remaining chunk CRCs.  The size in IHDR is checked against the guard and,
 * for a file of known size, against what its bytes can decompress to
 * before anything of that size is allocated.
 *
 * Invariants: libpng errors longjmp back into png_run() only, never past a
 * frame that owns memory: everything allocated lives in the png_state owned
 * by hfs_io_load_png(), which frees it on every path.  Warnings are dropped
 * (the library never prints); errors become one-line messages.
 */
#include "io_internal.h"

#include <math.h>
#include <png.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

/* Deflate's largest expansion: a 258-byte match in two 1-bit codes. */
#define PNG_DEFLATE_MAX_RATIO 1032LL

typedef struct png_state {
    hfs_rd *rd;
    hfs_error *err;
    png_structp png;
    png_infop info;
    unsigned char *row;     /* one row (non-interlaced) or the whole image   */
    png_bytep *rows;        /* row pointers into `row` for interlaced images */
    float *z;
    int short_read;         /* the stream ended inside libpng's read         */
    char msg[200];          /* libpng's error text                           */
    char warn[200];         /* its last warning: often the real reason       */
} png_state;

static void png_on_error(png_structp png, png_const_charp msg)
{
    png_state *s = png_get_error_ptr(png);
    snprintf(s->msg, sizeof s->msg, "%s", msg ? msg : "unknown error");
    png_longjmp(png, 1);
}

static void png_on_warning(png_structp png, png_const_charp msg)
{
    /* Kept, never printed: libpng explains e.g. a bad IHDR in a warning and
     * then fails with a generic "Invalid IHDR data". */
    png_state *s = png_get_error_ptr(png);
    snprintf(s->warn, sizeof s->warn, "%s", msg ? msg : "");
}

static void png_on_read(png_structp png, png_bytep data, size_t n)
{
    png_state *s = png_get_io_ptr(png);
    if (hfs_rd_read(s->rd, data, n) != n) {
        s->short_read = 1;
        png_error(png, "unexpected end of file");
    }
}

static void convert_row(const unsigned char *row, int w, int depth, int channels, float *dst)
{
    for (int i = 0; i < w; ++i) {
        unsigned v, a;
        if (depth == 16) {
            const unsigned char *p = row + (size_t)i * 2 * (size_t)channels;
            v = (unsigned)p[0] << 8 | p[1];
            a = channels == 2 ? ((unsigned)p[2] << 8 | p[3]) : 1;
        } else {
            const unsigned char *p = row + (size_t)i * (size_t)channels;
            v = p[0];
            a = channels == 2 ? p[1] : 1;
        }
        dst[i] = a ? (float)v : NAN;
    }
}

/* Everything that can longjmp.  Returns 0, a status (our own checks), or 1
 * after a libpng error (message in s->msg). */
static int png_run(png_state *s, const hfs_io_hopts *o, hfs_heightmap *out)
{
    png_uint_32 w, h;
    int depth, ctype, interlace, channels, passes, rc;
    size_t rowbytes;

    if (setjmp(png_jmpbuf(s->png)))
        return 1;
    /* Lift libpng's own size guard (1e6 per side) to the format's maximum so
     * that ours, below, decides and explains; nothing large is allocated
     * before our check. */
    png_set_user_limits(s->png, 0x7fffffffu, 0x7fffffffu);
    /* Ancillary chunks (text, ICC profile, gamma, ...) hold nothing a height
     * field uses.  Skipped unparsed, they cannot make libpng allocate and
     * clear a buffer of whatever length they claim (up to 2 GiB from a
     * 200-byte file); tRNS is still read, and ignored. */
    png_set_keep_unknown_chunks(s->png, PNG_HANDLE_CHUNK_NEVER, NULL, -1);
    png_read_info(s->png, s->info);
    png_get_IHDR(s->png, s->info, &w, &h, &depth, &ctype, &interlace, NULL, NULL);

    if (ctype != PNG_COLOR_TYPE_GRAY && ctype != PNG_COLOR_TYPE_GRAY_ALPHA)
        return hfs_fail(s->err, HFS_E_UNSUPPORTED,
                        "%s: %s PNG is not a height field; convert it to greyscale", s->rd->path,
                        ctype == PNG_COLOR_TYPE_PALETTE ? "palette"
                        : ctype == PNG_COLOR_TYPE_RGB   ? "RGB"
                                                        : "RGBA");
    rc = hfs_io_check_size(s->rd->path, w, h, 2, o->max_w, o->max_h, o->max_texels, s->err);
    if (rc)
        return rc;
    channels = ctype == PNG_COLOR_TYPE_GRAY_ALPHA ? 2 : 1;
    /* A 60-byte file may claim 16384 x 16384; its image data must follow,
     * and deflate expands at most 1032:1.  A known-size file that cannot
     * hold the claimed samples is refused before the big allocations. */
    if (s->rd->file_size >= 0 && s->rd->file_size < (1LL << 40)) {
        long long bytes = (long long)w * h * depth * channels / 8;
        if (bytes > PNG_DEFLATE_MAX_RATIO * (s->rd->file_size + 1))
            return hfs_fail(s->err, HFS_E_FORMAT,
                            "%s: truncated PNG image data (%lld bytes cannot hold %ux%u "
                            "%d-bit samples, even at deflate's maximum ratio)", s->rd->path,
                            s->rd->file_size, (unsigned)w, (unsigned)h, depth);
    }
    if (depth < 8)
        png_set_packing(s->png); /* one byte per sample, values unscaled */
    passes = png_set_interlace_handling(s->png);
    png_read_update_info(s->png, s->info);
    rowbytes = png_get_rowbytes(s->png, s->info);
    if (rowbytes != (size_t)w * (size_t)channels * (depth == 16 ? 2 : 1))
        return hfs_fail(s->err, HFS_E_FORMAT, "%s: unexpected PNG row layout", s->rd->path);

    s->z = malloc((size_t)w * (size_t)h * sizeof *s->z);
    if (!s->z)
        return hfs_fail(s->err, HFS_E_NOMEM, "%s: out of memory for %ux%u heights",
                        s->rd->path, (unsigned)w, (unsigned)h);
    if (passes == 1) {
        /* Row by row: a 16384^2 16-bit field needs no second full copy. */
        s->row = malloc(rowbytes);
        if (!s->row)
            return hfs_fail(s->err, HFS_E_NOMEM, "%s: out of memory", s->rd->path);
        for (png_uint_32 j = 0; j < h; ++j) {
            png_read_row(s->png, s->row, NULL);
            convert_row(s->row, (int)w, depth, channels, s->z + (size_t)j * w);
        }
    } else {
        s->row = malloc(rowbytes * h);
        s->rows = malloc(h * sizeof *s->rows);
        if (!s->row || !s->rows)
            return hfs_fail(s->err, HFS_E_NOMEM, "%s: out of memory for an interlaced PNG",
                            s->rd->path);
        for (png_uint_32 j = 0; j < h; ++j)
            s->rows[j] = s->row + (size_t)j * rowbytes;
        png_read_image(s->png, s->rows);
        for (png_uint_32 j = 0; j < h; ++j)
            convert_row(s->rows[j], (int)w, depth, channels, s->z + (size_t)j * w);
    }
    png_read_end(s->png, NULL);
    out->width = (int)w;
    out->height = (int)h;
    return HFS_OK;
}

int hfs_io_load_png(hfs_rd *rd, const hfs_io_hopts *o, hfs_heightmap *out, hfs_error *err)
{
    png_state s;
    int rc;

    memset(&s, 0, sizeof s);
    s.rd = rd;
    s.err = err;
    s.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &s, png_on_error, png_on_warning);
    if (s.png)
        s.info = png_create_info_struct(s.png);
    if (!s.png || !s.info) {
        png_destroy_read_struct(s.png ? &s.png : NULL, NULL, NULL);
        return hfs_fail(err, HFS_E_NOMEM, "%s: cannot initialise libpng", rd->path);
    }
    png_set_read_fn(s.png, &s, png_on_read);

    rc = png_run(&s, o, out);
    if (rc == 1) {
        if (s.short_read)
            rc = hfs_rd_fail_short(rd, err, "PNG");
        else
            rc = hfs_fail(err, HFS_E_FORMAT, "%s: corrupt PNG (%s%s%s)", rd->path, s.msg,
                          s.warn[0] ? ": " : "", s.warn);
    }
    png_destroy_read_struct(&s.png, &s.info, NULL);
    free(s.rows);
    free(s.row);
    if (rc) {
        free(s.z);
        out->width = out->height = 0;
        return rc;
    }
    out->z = s.z;
    return HFS_OK;
}
