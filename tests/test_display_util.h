/*
 * test_display_util.h — helpers of the display tests: read a PNG back as
 * RGBA8 (libpng, independent of the writer under test), compare pictures,
 * scale by nearest neighbour.  Header-only, static inline functions; include once
 * per test program, after check.h.
 */
#ifndef HFS_TEST_DISPLAY_UTIL_H
#define HFS_TEST_DISPLAY_UTIL_H

#include <png.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

/* Reads any 8-bit RGB or RGBA PNG into malloc'ed RGBA (alpha 255 for RGB).
 * Returns NULL on any problem. */
static inline uint8_t *read_png_rgba(const char *path, int *w, int *h)
{
    FILE *f = fopen(path, "rb");
    png_structp png = NULL;
    png_infop info = NULL;
    uint8_t *volatile px = NULL;
    if (!f)
        return NULL;
    png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    info = png ? png_create_info_struct(png) : NULL;
    if (!png || !info || setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, NULL);
        fclose(f);
        free(px);
        return NULL;
    }
    png_init_io(png, f);
    png_read_info(png, info);
    int ct = png_get_color_type(png, info);
    if (png_get_bit_depth(png, info) != 8 ||
        (ct != PNG_COLOR_TYPE_RGB && ct != PNG_COLOR_TYPE_RGB_ALPHA))
        png_error(png, "not 8-bit RGB(A)");
    if (ct == PNG_COLOR_TYPE_RGB)
        png_set_filler(png, 0xff, PNG_FILLER_AFTER);
    png_read_update_info(png, info);
    *w = (int)png_get_image_width(png, info);
    *h = (int)png_get_image_height(png, info);
    px = malloc((size_t)*w * (size_t)*h * 4);
    if (!px)
        png_error(png, "out of memory");
    for (int j = 0; j < *h; ++j)
        png_read_row(png, px + (size_t)j * (size_t)*w * 4, NULL);
    png_destroy_read_struct(&png, &info, NULL);
    fclose(f);
    return px;
}

/* Largest channel difference (RGB only) between two w x h RGBA pictures;
 * *count receives the number of pixels that differ at all. */
static inline int max_rgb_diff(const uint8_t *a, const uint8_t *b, int w, int h, long *count)
{
    int worst = 0;
    *count = 0;
    for (size_t k = 0; k < (size_t)w * (size_t)h; ++k) {
        int px = 0;
        for (int c = 0; c < 3; ++c) {
            int d = abs((int)a[4 * k + c] - (int)b[4 * k + c]);
            px = d > px ? d : px;
        }
        worst = px > worst ? px : worst;
        *count += px > 0;
    }
    return worst;
}

/* src (sw x sh) scaled by the whole number k into dst, alpha 255. */
static inline void scale_nearest(const uint8_t *src, int sw, int sh, int k, uint8_t *dst)
{
    for (int y = 0; y < sh * k; ++y)
        for (int x = 0; x < sw * k; ++x) {
            const uint8_t *s = src + ((size_t)(y / k) * (size_t)sw + (size_t)(x / k)) * 4;
            uint8_t *d = dst + ((size_t)y * (size_t)(sw * k) + (size_t)x) * 4;
            d[0] = s[0];
            d[1] = s[1];
            d[2] = s[2];
            d[3] = 255;
        }
}

#endif /* HFS_TEST_DISPLAY_UTIL_H */
