/*
 * image_write.c — PFM dumps, 8-bit sRGB display PNGs and 16-bit grey height
 * PNGs, all written atomically (io_output.c: temp file + rename).
 *
 * PFM: little-endian (scale -1.0), first row written = row j = 0 (SPEC),
 * "Pf" grey (Rec. 709 luminance in double: exact when R = G = B) or "PF" RGB.
 * PNG 8-bit: the display mapping of tonemap.c (exposure, curve, sRGB OETF,
 * round), with an sRGB chunk so viewers do not re-apply a gamma.  PNG 16-bit grey: the inverse
 * of the PNG height loader.  PNG 8-bit RGBA: already display-encoded pixels
 * (the boards' screen captures), written as they are.
 *
 * Invariants: inputs are validated completely (sizes, NaN/Inf, ranges) before
 * any file is created, so bad input never even leaves a temporary; libpng
 * errors longjmp only into png_emit(), whose caller owns and frees every
 * resource; the library never prints (warnings are dropped).
 */
#include "io_internal.h"

#include <math.h>
#include <png.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static int check_image(const char *path, const hfs_image *img, hfs_error *err)
{
    size_t n;
    if (!path || !*path)
        return hfs_fail(err, HFS_E_INVALID, "(no file): empty output path");
    if (!img || !img->rgb || img->width < 1 || img->height < 1)
        return hfs_fail(err, HFS_E_INVALID, "%s: nothing to write (empty image)", path);
    n = (size_t)img->width * (size_t)img->height * 3;
    for (size_t k = 0; k < n; ++k)
        if (!isfinite(img->rgb[k]))
            return hfs_fail(err, HFS_E_INVALID, "%s: refusing to write a non-finite value at "
                            "pixel (%zu, %zu)", path, (k / 3) % (size_t)img->width,
                            (k / 3) / (size_t)img->width);
    return HFS_OK;
}

static float luminance(const float *p)
{
    double y = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    /* Finite inputs near FLT_MAX could round past it; keep outputs finite. */
    if (y > 3.4028234663852886e+38)
        y = 3.4028234663852886e+38;
    if (y < -3.4028234663852886e+38)
        y = -3.4028234663852886e+38;
    return (float)y;
}

static void put_f32_le(unsigned char *b, float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    b[0] = (unsigned char)u;
    b[1] = (unsigned char)(u >> 8);
    b[2] = (unsigned char)(u >> 16);
    b[3] = (unsigned char)(u >> 24);
}

/* channels_in: 1 (grey array) or 3 (RGB); grey_out: write Pf. */
/* Completes a written temporary: into the output set o, or renamed now. */
static int finish_output(hfs_outputs *o, hfs_io_atomic *a, hfs_error *err)
{
    return o ? hfs_io_outputs_adopt(o, a, err) : hfs_io_atomic_commit(a, err);
}

static int pfm_emit(hfs_outputs *o, const char *path, int w, int h, const float *v,
                    int channels_in, int grey_out, hfs_error *err)
{
    hfs_io_atomic a;
    char header[64];
    int hl, rc, cout = grey_out ? 1 : 3;
    size_t rowbytes = (size_t)w * (size_t)cout * 4;
    unsigned char *row = malloc(rowbytes);

    if (!row)
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", path);
    if ((rc = hfs_io_atomic_open(&a, path, err))) {
        free(row);
        return rc;
    }
    hl = snprintf(header, sizeof header, "%s\n%d %d\n-1.0\n", grey_out ? "Pf" : "PF", w, h);
    rc = hfs_io_atomic_write(&a, header, (size_t)hl, err);
    for (int j = 0; j < h && !rc; ++j) {
        const float *src = v + (size_t)j * (size_t)w * (size_t)channels_in;
        for (int i = 0; i < w; ++i) {
            const float *p = src + (size_t)i * (size_t)channels_in;
            if (grey_out)
                put_f32_le(row + 4 * (size_t)i, channels_in == 1 ? p[0] : luminance(p));
            else
                for (int c = 0; c < 3; ++c)
                    put_f32_le(row + 12 * (size_t)i + 4 * (size_t)c, p[c]);
        }
        rc = hfs_io_atomic_write(&a, row, rowbytes, err);
    }
    free(row);
    if (rc) {
        hfs_io_atomic_abort(&a);
        return rc;
    }
    return finish_output(o, &a, err);
}

int hfs_pfm_write(const char *path, const hfs_image *img, int grey, hfs_error *err)
{
    int rc = check_image(path, img, err);
    if (rc)
        return rc;
    return pfm_emit(NULL, path, img->width, img->height, img->rgb, 3, grey != 0, err);
}

int hfs_pfm_write_to(hfs_outputs *o, const char *path, const hfs_image *img, int grey,
                     hfs_error *err)
{
    int rc = check_image(path, img, err);
    if (rc)
        return rc;
    return pfm_emit(o, path, img->width, img->height, img->rgb, 3, grey != 0, err);
}

int hfs_pfm_write_grey(const char *path, int width, int height, const float *v, hfs_error *err)
{
    if (!path || !*path)
        return hfs_fail(err, HFS_E_INVALID, "(no file): empty output path");
    if (!v || width < 1 || height < 1)
        return hfs_fail(err, HFS_E_INVALID, "%s: nothing to write (empty image)", path);
    for (size_t k = 0, n = (size_t)width * (size_t)height; k < n; ++k)
        if (!isfinite(v[k]))
            return hfs_fail(err, HFS_E_INVALID, "%s: refusing to write a non-finite value at "
                            "(%zu, %zu)", path, k % (size_t)width, k / (size_t)width);
    return pfm_emit(NULL, path, width, height, v, 1, 1, err);
}

/* ---- PNG ---------------------------------------------------------------------- */

typedef struct png_job png_job;
struct png_job {
    const char *path;
    int w, h, depth, ctype;
    unsigned char *row;
    void (*fill)(const png_job *job, int j, unsigned char *row);
    const float *src;
    const unsigned char *src8; /* fill_rgba8 */
    double exposure;
    hfs_tonemap tonemap;
    char msg[200];
};

static void pngw_on_error(png_structp png, png_const_charp msg)
{
    png_job *job = png_get_error_ptr(png);
    snprintf(job->msg, sizeof job->msg, "%s", msg ? msg : "unknown error");
    png_longjmp(png, 1);
}

static void pngw_on_warning(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg; /* the library never prints */
}

static void fill_srgb8(const png_job *job, int j, unsigned char *row)
{
    const float *src = job->src + (size_t)j * (size_t)job->w * 3;
    for (size_t i = 0; i < (size_t)job->w; ++i)
        hfs_srgb8_encode_rgb(src + 3 * i, job->exposure, job->tonemap, row + 3 * i);
}

static void fill_rgba8(const png_job *job, int j, unsigned char *row)
{
    memcpy(row, job->src8 + (size_t)j * (size_t)job->w * 4, (size_t)job->w * 4);
}

static void fill_grey16(const png_job *job, int j, unsigned char *row)
{
    const float *src = job->src + (size_t)j * (size_t)job->w;
    for (int i = 0; i < job->w; ++i) {
        unsigned v = (unsigned)floor((double)src[i] + 0.5); /* range checked before */
        row[2 * i] = (unsigned char)(v >> 8);
        row[2 * i + 1] = (unsigned char)v;
    }
}

/* Everything that can longjmp.  Returns 0, or 1 after a libpng error. */
static int png_emit(png_job *job, png_structp png, png_infop info, FILE *f)
{
    if (setjmp(png_jmpbuf(png)))
        return 1;
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)job->w, (png_uint_32)job->h, job->depth, job->ctype,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (job->ctype == PNG_COLOR_TYPE_RGB || job->ctype == PNG_COLOR_TYPE_RGB_ALPHA)
        png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    for (int j = 0; j < job->h; ++j) {
        job->fill(job, j, job->row);
        png_write_row(png, job->row);
    }
    png_write_end(png, info);
    return 0;
}

static int png_write_job(png_job *job, hfs_outputs *o, hfs_error *err)
{
    hfs_io_atomic a;
    png_structp png = NULL;
    png_infop info = NULL;
    size_t bpp = job->ctype == PNG_COLOR_TYPE_RGB         ? 3
                 : job->ctype == PNG_COLOR_TYPE_RGB_ALPHA ? 4
                                                          : (size_t)job->depth / 8;
    int rc;

    job->row = malloc((size_t)job->w * bpp);
    if (!job->row)
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", job->path);
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, job, pngw_on_error, pngw_on_warning);
    if (png)
        info = png_create_info_struct(png);
    if (!png || !info) {
        png_destroy_write_struct(png ? &png : NULL, NULL);
        free(job->row);
        return hfs_fail(err, HFS_E_NOMEM, "%s: cannot initialise libpng", job->path);
    }
    rc = hfs_io_atomic_open(&a, job->path, err);
    if (!rc) {
        if (png_emit(job, png, info, a.f)) {
            hfs_io_atomic_abort(&a);
            rc = hfs_fail(err, HFS_E_IO, "%s: PNG encoding failed: %s", job->path, job->msg);
        } else {
            rc = finish_output(o, &a, err);
        }
    }
    png_destroy_write_struct(&png, &info);
    free(job->row);
    job->row = NULL;
    return rc;
}

int hfs_png_write_to(hfs_outputs *o, const char *path, const hfs_image *img,
                     const hfs_png_opts *opts, hfs_error *err)
{
    png_job job;
    int rc = check_image(path, img, err);

    if (rc)
        return rc;
    memset(&job, 0, sizeof job);
    job.exposure = opts && opts->exposure != 0.0 ? opts->exposure : 1.0;
    job.tonemap = opts ? opts->tonemap : HFS_TONEMAP_CLAMP;
    if (!(job.exposure > 0.0) || !isfinite(job.exposure))
        return hfs_fail(err, HFS_E_INVALID, "%s: exposure %g must be positive", path,
                        job.exposure);
    if (job.tonemap != HFS_TONEMAP_CLAMP && job.tonemap != HFS_TONEMAP_REINHARD &&
        job.tonemap != HFS_TONEMAP_HUE)
        return hfs_fail(err, HFS_E_INVALID, "%s: unknown tone map %d", path, (int)job.tonemap);
    job.path = path;
    job.w = img->width;
    job.h = img->height;
    job.depth = 8;
    job.ctype = PNG_COLOR_TYPE_RGB;
    job.fill = fill_srgb8;
    job.src = img->rgb;
    return png_write_job(&job, o, err);
}

int hfs_png_write(const char *path, const hfs_image *img, const hfs_png_opts *opts,
                  hfs_error *err)
{
    return hfs_png_write_to(NULL, path, img, opts, err);
}

int hfs_png16_write_grey(const char *path, int width, int height, const float *v,
                         hfs_error *err)
{
    png_job job;

    if (!path || !*path)
        return hfs_fail(err, HFS_E_INVALID, "(no file): empty output path");
    if (!v || width < 1 || height < 1)
        return hfs_fail(err, HFS_E_INVALID, "%s: nothing to write (empty image)", path);
    for (size_t k = 0, n = (size_t)width * (size_t)height; k < n; ++k)
        if (!(v[k] >= -0.5f && v[k] < 65535.5f)) /* also catches NaN */
            return hfs_fail(err, HFS_E_INVALID, "%s: value %g at (%zu, %zu) does not fit a 16-bit "
                            "PNG (0..65535)", path, (double)v[k], k % (size_t)width,
                            k / (size_t)width);
    memset(&job, 0, sizeof job);
    job.path = path;
    job.w = width;
    job.h = height;
    job.depth = 16;
    job.ctype = PNG_COLOR_TYPE_GRAY;
    job.fill = fill_grey16;
    job.src = v;
    return png_write_job(&job, NULL, err);
}

int hfs_png_write_rgba8(const char *path, int width, int height, const uint8_t *rgba,
                        hfs_error *err)
{
    png_job job;

    if (!path || !*path)
        return hfs_fail(err, HFS_E_INVALID, "(no file): empty output path");
    if (!rgba || width < 1 || height < 1)
        return hfs_fail(err, HFS_E_INVALID, "%s: nothing to write (empty image)", path);
    if (width > HFS_HEIGHT_MAX_DIM || height > HFS_HEIGHT_MAX_DIM)
        return hfs_fail(err, HFS_E_INVALID, "%s: image %dx%d is too large to write", path,
                        width, height);
    memset(&job, 0, sizeof job);
    job.path = path;
    job.w = width;
    job.h = height;
    job.depth = 8;
    job.ctype = PNG_COLOR_TYPE_RGB_ALPHA;
    job.fill = fill_rgba8;
    job.src8 = rgba;
    return png_write_job(&job, NULL, err);
}

int hfs_bytes_write_to(hfs_outputs *o, const char *path, const void *data, size_t n,
                       hfs_error *err)
{
    if (!path || !*path)
        return hfs_fail(err, HFS_E_INVALID, "(no file): empty output path");
    if (!data || n == 0)
        return hfs_fail(err, HFS_E_INVALID, "%s: nothing to write", path);
    hfs_io_atomic a;
    int rc = hfs_io_atomic_open(&a, path, err);
    if (rc)
        return rc;
    if ((rc = hfs_io_atomic_write(&a, data, n, err))) {
        hfs_io_atomic_abort(&a);
        return rc;
    }
    return finish_output(o, &a, err);
}
