/*
 * albedo_load.c — albedo maps for a height field (hfs_io.h
 * hfs_albedo_load): PNG through libpng's simplified API (which decodes
 * any colour type and bit depth and owns the transfer function), EXR and
 * Radiance .hdr through the environment-map readers, PFM through the PFM
 * reader; then the size against the field's and every value against
 * [0, 1].
 */
#include "albedo.h"
#include "io_internal.h"

#include <math.h>
#include <png.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* A PNG file read whole: the simplified API reads from memory, so the file
 * is opened the project's way (regular files only, without blocking). */
static int read_whole(const char *path, unsigned char **data, size_t *size, hfs_error *err)
{
    hfs_rd rd;
    int rc = hfs_rd_open(&rd, path, err);
    if (rc)
        return rc;
    if (rd.file_size < 0 || rd.file_size > (1LL << 30)) {
        hfs_rd_close(&rd);
        return hfs_fail(err, HFS_E_INVALID, "%s: not a regular file of at most 1 GiB", path);
    }
    *size = (size_t)rd.file_size;
    *data = malloc(*size ? *size : 1);
    if (!*data) {
        hfs_rd_close(&rd);
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", path);
    }
    if (hfs_rd_read(&rd, *data, *size) != *size) {
        rc = hfs_rd_fail_short(&rd, err, "PNG");
        free(*data);
        *data = NULL;
    }
    hfs_rd_close(&rd);
    return rc;
}

/* The sRGB transfer function's inverse (IEC 61966-2-1), exact: libpng's
 * own 8-bit -> linear conversion uses a 2.2 power law, up to 0.009 off,
 * and hfs_png_write encodes with the exact curve. */
static float srgb_decode(unsigned v)
{
    const double x = v / 255.0;
    return (float)(x <= 0.04045 ? x / 12.92 : pow((x + 0.055) / 1.055, 2.4));
}

/* 16-bit files: libpng's linear 16-bit RGB (no conversion for a linear
 * file); 8-bit files: libpng's 8-bit sRGB RGB (it converts a file whose
 * gAMA/sRGB/iCCP chunks say otherwise), decoded by the exact sRGB curve.
 * Grey becomes R = G = B; alpha is dropped. */
static int load_png(const char *path, int w, int h, float **rgb, hfs_error *err)
{
    unsigned char *data = NULL;
    size_t size = 0;
    int rc = read_whole(path, &data, &size, err);
    if (rc)
        return rc;
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    uint16_t *px = NULL;
    if (!png_image_begin_read_from_memory(&img, data, size)) {
        rc = hfs_fail(err, HFS_E_FORMAT, "%s: not a readable PNG (%s)", path, img.message);
        goto done;
    }
    if ((int)img.width != w || (int)img.height != h) {
        rc = hfs_fail(err, HFS_E_INVALID, "%s: albedo map is %ux%u, the heights are %dx%d", path,
                      img.width, img.height, w, h);
        goto done;
    }
    const int linear = (img.format & PNG_FORMAT_FLAG_LINEAR) != 0;
    img.format = linear ? PNG_FORMAT_LINEAR_RGB : PNG_FORMAT_RGB;
    const size_t n = (size_t)w * (size_t)h;
    px = malloc(n * 3 * sizeof *px); /* room for either */
    *rgb = malloc(n * 3 * sizeof **rgb);
    if (!px || !*rgb) {
        rc = hfs_fail(err, HFS_E_NOMEM, "%s: out of memory for a %dx%d albedo map", path, w, h);
        goto done;
    }
    if (!png_image_finish_read(&img, NULL, px, 0, NULL)) {
        rc = hfs_fail(err, HFS_E_FORMAT, "%s: corrupt PNG (%s)", path, img.message);
        goto done;
    }
    float lut[256];
    for (unsigned v = 0; v < 256 && !linear; ++v)
        lut[v] = srgb_decode(v);
    const uint8_t *p8 = (const uint8_t *)px;
    for (size_t i = 0; i < n * 3; ++i)
        (*rgb)[i] = linear ? (float)px[i] / 65535.0f : lut[p8[i]];
done:
    png_image_free(&img);
    free(px);
    free(data);
    if (rc) {
        free(*rgb);
        *rgb = NULL;
    }
    return rc;
}

/* PFM (colour or grey) or an environment-map format, as linear RGB. */
static int load_float(const char *path, int is_pfm, int w, int h, float **rgb, hfs_error *err)
{
    int mw, mh, rc;
    float *v;
    if (is_pfm) {
        hfs_image im;
        if ((rc = hfs_pfm_read_image(path, &im, err)))
            return rc;
        mw = im.width, mh = im.height, v = im.rgb;
    } else {
        hfs_envmap em;
        if ((rc = hfs_envmap_load(path, &em, err)))
            return rc;
        mw = em.width, mh = em.height, v = em.rgb;
    }
    if (mw != w || mh != h) {
        free(v);
        return hfs_fail(err, HFS_E_INVALID, "%s: albedo map is %dx%d, the heights are %dx%d",
                        path, mw, mh, w, h);
    }
    *rgb = v;
    return HFS_OK;
}

int hfs_albedo_load(const char *path, int width, int height, float **rgb, hfs_error *err)
{
    *rgb = NULL;
    hfs_rd rd;
    int rc = hfs_rd_open(&rd, path, err);
    if (rc)
        return rc;
    const unsigned char *sig;
    const size_t got = hfs_rd_peek(&rd, 8, &sig);
    const int is_png = got >= 8 && !png_sig_cmp(sig, 0, 8);
    const int is_pfm = got >= 2 && sig[0] == 'P' && (sig[1] == 'F' || sig[1] == 'f');
    hfs_rd_close(&rd);
    rc = is_png ? load_png(path, width, height, rgb, err)
                : load_float(path, is_pfm, width, height, rgb, err);
    if (rc)
        return rc;
    hfs_error why;
    if (hfs_albedo_map_check(*rgb, width, height, &why)) {
        free(*rgb);
        *rgb = NULL;
        /* "albedo map: texel ..." -> "PATH: texel ..." */
        const char *detail = strstr(why.msg, ": ");
        return hfs_fail(err, HFS_E_INVALID, "%s: albedo %s", path, detail ? detail + 2 : why.msg);
    }
    return HFS_OK;
}
