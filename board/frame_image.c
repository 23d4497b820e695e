/*
 * frame_image.c — render to display picture (frame_image.h): row flip and
 * the PNG writer's tone map, shared through hfs_srgb8_encode_rgb so the bytes
 * cannot drift apart.
 *
 * Cost: one pow() per channel (about 3 ms for 256 x 256 on this machine);
 * a lookup table cannot be exact for float inputs, and exactness against
 * the PNG is what the tests check.
 */
#include "frame_image.h"

#include <math.h>
#include <stddef.h>

int hfs_frame_to_rgba8(const hfs_image *img, const hfs_png_opts *opts, uint8_t *rgba,
                       hfs_error *err)
{
    if (!img || !img->rgb || img->width < 1 || img->height < 1 || !rgba)
        return hfs_fail(err, HFS_E_INVALID, "frame: empty image or no output");
    double exposure = opts && opts->exposure != 0.0 ? opts->exposure : 1.0;
    hfs_tonemap tm = opts ? opts->tonemap : HFS_TONEMAP_CLAMP;
    if (!(exposure > 0.0) || !isfinite(exposure))
        return hfs_fail(err, HFS_E_INVALID, "frame: exposure %g must be positive", exposure);
    if (tm != HFS_TONEMAP_CLAMP && tm != HFS_TONEMAP_REINHARD && tm != HFS_TONEMAP_HUE)
        return hfs_fail(err, HFS_E_INVALID, "frame: unknown tone map %d", (int)tm);
    const size_t w = (size_t)img->width, h = (size_t)img->height;
    for (size_t k = 0; k < w * h * 3; ++k)
        if (!isfinite(img->rgb[k]))
            return hfs_fail(err, HFS_E_INVALID, "frame: non-finite value at texel (%zu, %zu)",
                            (k / 3) % w, (k / 3) / w);

    for (size_t j = 0; j < h; ++j) {
        const float *src = img->rgb + j * w * 3;
        uint8_t *dst = rgba + j * w * 4; /* row j = 0 at the top (SPEC) */
        for (size_t i = 0; i < w; ++i) {
            hfs_srgb8_encode_rgb(src + 3 * i, exposure, tm, dst + 4 * i);
            dst[4 * i + 3] = 255;
        }
    }
    return HFS_OK;
}

double hfs_exposure_smooth(double ev, double target, double dt, double tau)
{
    if (!(dt > 0.0) || !(tau > 0.0))
        return ev;
    return ev + (target - ev) * -expm1(-dt / tau);
}

int hfs_shrink_factor(int w, int h, int max_side)
{
    const int side = w > h ? w : h;
    return side <= max_side ? 1 : (side + max_side - 1) / max_side;
}

void hfs_image_shrink(const hfs_image *img, int f, hfs_image *out)
{
    const int w = img->width, h = img->height;
    for (int y = 0; y < out->height; ++y)
        for (int x = 0; x < out->width; ++x) {
            double sum[3] = {0.0, 0.0, 0.0};
            int n = 0;
            for (int j = y * f; j < h && j < (y + 1) * f; ++j)
                for (int i = x * f; i < w && i < (x + 1) * f; ++i, ++n)
                    for (int c = 0; c < 3; ++c)
                        sum[c] += img->rgb[((size_t)j * w + (size_t)i) * 3 + (size_t)c];
            for (int c = 0; c < 3; ++c)
                out->rgb[((size_t)y * out->width + (size_t)x) * 3 + (size_t)c] =
                    (float)(sum[c] / n);
        }
}
