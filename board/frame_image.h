/*
 * frame_image.h — a render (linear RGB floats, hfs_image) made into the
 * picture a display shows (sRGB RGBA8, hfs_display_present).
 *
 * Which way is up: SPEC ("Orientation"): every picture -- PNG, kiosk frame,
 * window -- shows row j = 0 at the top, as the source image does (a
 * north-up DEM stays north-up).  A frame and the PNG `hfshade render -o`
 * writes are the same pixels in the same order.  (Before issue 14 frames
 * were flipped, so the kiosk showed a DEM mirrored north-south.)
 *
 * Colour: per pixel exactly hfs_png_write's mapping (hfs_srgb8_encode_rgb in
 * runtime/io: exposure, the tone curve, sRGB OETF, round), alpha 255, so
 * what the kiosk shows is what `hfshade render -o` writes.
 */
#ifndef HFS_FRAME_IMAGE_H
#define HFS_FRAME_IMAGE_H

#include <stdint.h>

#include "hfs_io.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Converts img into rgba (img->width * img->height * 4 bytes, allocated by
 * the caller; reuse it every frame).  opts as for hfs_png_write (NULL =
 * exposure 1, clamp).  Fails with HFS_E_INVALID, writing nothing, on an
 * empty image, an exposure that is not positive and finite, an unknown tone
 * map, or a non-finite value (the renderer never produces one). */
int hfs_frame_to_rgba8(const hfs_image *img, const hfs_png_opts *opts, uint8_t *rgba,
                       hfs_error *err);

/* The box-filter shrink of img by an integer factor f >= 1, in linear
 * radiance (before the sRGB encoding, so a shrunk picture is the average
 * light, not the average of encoded values): out is ceil(w / f) x
 * ceil(h / f), each texel the mean of its f x f block (fewer at the right
 * and bottom edges).  out must be allocated at that size. */
void hfs_image_shrink(const hfs_image *img, int f, hfs_image *out);

/* The kiosk's automatic exposure over time (kiosk_frame.c): the exposure
 * in stops, ev, moved towards the frame's metered target (log2 of
 * hfs_exposure_auto) by exponential smoothing of the log-luminance with
 * time constant tau seconds, dt seconds after the last step:
 *   ev + (target - ev) (1 - exp(-dt / tau)).
 * The step is a fraction in [0, 1) of the distance, so a step change of
 * the scene's brightness converges monotonically and never overshoots,
 * at any frame rate; a knob turned through bright and dark frames moves
 * the exposure by their average, not frame by frame (no pumping).  dt <= 0
 * (or not a number) leaves ev as it is. */
#define HFS_KIOSK_EXPOSURE_TAU 0.5
double hfs_exposure_smooth(double ev, double target, double dt, double tau);

/* The smallest factor that brings w x h within max_side per side. */
int hfs_shrink_factor(int w, int h, int max_side);

#ifdef __cplusplus
}
#endif
#endif /* HFS_FRAME_IMAGE_H */
