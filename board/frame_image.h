/*
 * frame_image.h — a render (linear RGB floats, hfs_image) made into the
 * picture a display shows (sRGB RGBA8, hfs_display_present).
 *
 * Which way is up: SPEC fixes the grid (row j = 0 is y = 0), not the screen.
 * We show the field like a map: +x to the right, +y UP, so row j = 0 is the
 * BOTTOM row of the picture and picture row 0 (the top) is j = height - 1.
 * (The PNG writer, hfs_png_write, keeps file order instead: its top row is
 * j = 0.  A frame and that PNG are the same bytes with the rows reversed.)
 *
 * Colour: per channel exactly hfs_png_write's mapping (hfs_srgb8_encode in
 * runtime/io: exposure, clamp or Reinhard, sRGB OETF, round), alpha 255, so
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

#ifdef __cplusplus
}
#endif
#endif /* HFS_FRAME_IMAGE_H */
