/*
 * tonemap.c — the display mapping of every 8-bit output (hfs_io.h
 * "Display mapping"): the PNG writer, the boards' frames
 * (board/frame_image.c) and, in GLSL, the kiosk's lit texture
 * (shaders_es/lit_texture.frag.glsl, which must stay the same curve: the
 * test test_gles_embed compares its bytes with hfs_srgb8_encode_rgb's).
 * Kept in one place so that a frame on screen and its PNG are the same
 * bytes; and the automatic exposure that meters a frame for it.
 *
 * Nothing here allocates more than the metering sample (at most
 * HFS_EXPOSURE_SAMPLES floats); no global state.
 */
#include "io_internal.h"

#include <math.h>
#include <stdlib.h>

/* The shoulder's white point, in the scaled channel: above it the largest
 * channel shows at 1 (see hfs_io.h). */
#define WHITE 16.0

static double srgb_oetf(double x)
{
    return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

/* Extended Reinhard (Reinhard et al. 2002, eq. 4) with white point WHITE. */
static double shoulder(double n)
{
    return n >= WHITE ? 1.0 : n * (1.0 + n / (WHITE * WHITE)) / (1.0 + n);
}

void hfs_tonemap_rgb(const double in[3], hfs_tonemap tm, double out[3])
{
    double x[3];
    for (int c = 0; c < 3; ++c)
        x[c] = in[c] > 0.0 ? in[c] : 0.0; /* negative light shows as black */
    if (tm == HFS_TONEMAP_HUE) {
        /* One factor for all three channels: their ratios, and so the hue
         * and the saturation, are kept; the largest channel goes through
         * the shoulder, so none ever exceeds 1 and nothing clips. */
        const double n = fmax(x[0], fmax(x[1], x[2]));
        const double s = n > 0.0 ? shoulder(n) / n : 0.0;
        for (int c = 0; c < 3; ++c)
            out[c] = x[c] * s;
        return;
    }
    for (int c = 0; c < 3; ++c)
        out[c] = tm == HFS_TONEMAP_REINHARD ? x[c] / (1.0 + x[c]) : fmin(x[c], 1.0);
}

void hfs_srgb8_encode_rgb(const float rgb[3], double exposure, hfs_tonemap tm,
                          unsigned char out[3])
{
    double x[3], y[3];
    for (int c = 0; c < 3; ++c)
        x[c] = exposure * rgb[c];
    hfs_tonemap_rgb(x, tm, y);
    for (int c = 0; c < 3; ++c)
        out[c] = (unsigned char)lrint(255.0 * srgb_oetf(y[c]));
}

unsigned char hfs_srgb8_encode(float v, double exposure, hfs_tonemap tonemap)
{
    const float grey[3] = {v, v, v};
    unsigned char out[3];
    hfs_srgb8_encode_rgb(grey, exposure, tonemap, out);
    return out[0];
}

/* ---- automatic exposure -------------------------------------------------------- */

static int cmp_float(const void *a, const void *b)
{
    const float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

double hfs_exposure_auto(const hfs_image *img)
{
    if (!img || !img->rgb || img->width < 1 || img->height < 1)
        return 1.0;
    const size_t n = (size_t)img->width * (size_t)img->height;
    /* A regular subsample of at most HFS_EXPOSURE_SAMPLES pixels: the
     * median of a million is the frame's to well under a percent. */
    const size_t step = (n + HFS_EXPOSURE_SAMPLES - 1) / HFS_EXPOSURE_SAMPLES;
    float *lum = malloc((n / step + 1) * sizeof *lum);
    if (!lum)
        return 1.0;
    size_t m = 0;
    for (size_t k = 0; k < n; k += step) {
        const float *p = img->rgb + 3 * k;
        const double y = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
        if (y > 0.0 && isfinite(y)) /* black (umbra, no sky) meters nothing */
            lum[m++] = (float)fmin(y, 3.0e38);
    }
    double e = 1.0;
    if (m > 0) {
        qsort(lum, m, sizeof *lum, cmp_float);
        const double med = m % 2 ? lum[m / 2] : 0.5 * ((double)lum[m / 2 - 1] + lum[m / 2]);
        e = HFS_EXPOSURE_GREY / med;
    }
    free(lum);
    return fmin(fmax(e, HFS_EXPOSURE_MIN), HFS_EXPOSURE_MAX);
}
