/*
 * camera_env.h — one camera frame (a mirror ball, a fisheye, or an
 * equirectangular panorama) as an equirectangular environment map in
 * linear radiance (docs/CAPTURE.md "Camera to environment").  No V4L2 here:
 * frames are bytes (GREY or YUYV), the output is float RGB.
 *
 * Output map: SPEC's equirect convention: column i -> phi = 2 pi (i + 0.5)
 * / W, row j -> e = pi/2 - pi (j + 0.5) / H (row 0 = zenith); directions
 * s(phi, e) = (cos phi cos e, sin phi cos e, sin e); azimuth phi from +x
 * toward +y.
 *
 * Decoding: GREY is full-range luma (code / 255, grey RGB).  YUYV is
 * BT.601 limited range (Y' 16..235, Cb/Cr 16..240 around 128):
 *     R' = 1.164 (Y' - 16) + 1.596 (Cr - 128)
 *     G' = 1.164 (Y' - 16) - 0.392 (Cb - 128) - 0.813 (Cr - 128)
 *     B' = 1.164 (Y' - 16) + 2.017 (Cb - 128)
 * (in 8.8 fixed point: 298, 409, 100, 208, 516 / 256; rounded, clamped to
 * 0..255; chroma shared by the pixel pair).  Then the
 * transfer: sRGB (IEC 61966-2-1 decoding, the default) or linear; then
 * radiance = exposure x linear code value (so `exposure` is the radiance
 * of a full-scale white pixel).
 *
 * Mappings (the inverse is used: each output texel's direction is looked
 * up in the frame, bilinearly, in linear radiance):
 *   - equirect: the frame is itself an equirect map; column x -> phi =
 *     rotate + 2 pi (x + 0.5) / w, row 0 = zenith.
 *   - mirrorball: an orthographic view of a mirror ball whose image is the
 *     circle (cx, cy, radius): a pixel at normalised distance r from the
 *     centre sees the direction at angle theta = 2 asin(r) from the axis
 *     toward the camera (centre: straight back at the camera; rim: straight
 *     behind the ball, unseen).
 *   - fisheye: equidistant, theta = r x fov / 2 from the lens axis (r = 1
 *     at `radius` pixels from the centre).
 * Orientation: `hemisphere` upper: the axis (mirror ball: toward the
 * camera, i.e. the camera above the ball looking down; fisheye: the lens
 * looking up) is +z; lower: -z.  `rotate`: the azimuth (degrees, SPEC:
 * from +x toward +y) of the direction the image's up points to.  The image
 * in-plane azimuth psi is measured counter-clockwise from the image's
 * right; right = up x axis for a mirror ball (seen from outside), axis x
 * up for a fisheye (seen from inside: east appears left of north looking
 * up, as on a star chart).
 *
 * Directions the camera cannot see (outside the circle, outside the frame,
 * behind a fisheye's field of view) are filled with the mean radiance of
 * the nearest output row (ring of constant elevation) that has visible
 * texels: a fisheye's ground becomes its lowest seen ring, grey, rather
 * than black, so the SH projection does not ring around a hard horizon and
 * the ground does not read as a black void; the height field hides most
 * of those directions anyway.  A frame with no visible texel gives black.
 */
#ifndef HFS_BOARD_CAMERA_ENV_H
#define HFS_BOARD_CAMERA_ENV_H

#include <stdint.h>

#include "capture.h"
#include "hfshade.h"

typedef enum hfs_camenv_mapping {
    HFS_MAP_MIRRORBALL = 0,
    HFS_MAP_FISHEYE,
    HFS_MAP_EQUIRECT
} hfs_camenv_mapping;

typedef struct hfs_camenv_params {
    hfs_camenv_mapping mapping;  /* default mirrorball                        */
    double cx, cy, radius;       /* pixels, the circle in the frame           */
    int has_center;              /* 0: the frame's centre                      */
                                 /* radius 0: min(w, h) / 2                    */
    double fov_deg;              /* fisheye, (0, 360]; default 180             */
    double rotate_deg;           /* azimuth of the image's up; default 0       */
    int lower;                   /* hemisphere = lower (axis -z)               */
    int linear;                  /* transfer = linear (else sRGB)              */
    double exposure;             /* radiance per unit linear code; default 1   */
    int map_w, map_h;            /* output map; default 256 x 128              */
    double smoothing_s;          /* SH time constant, seconds; default 0.2     */
    int env_lights;              /* -2: the scene's; 0 off; -1 auto; N         */
} hfs_camenv_params;

void hfs_camenv_defaults(hfs_camenv_params *p);
const char *hfs_camenv_mapping_name(hfs_camenv_mapping m);

/* The frame pixel (continuous, pixel centres at + 0.5) that sees unit
 * direction d for a w x h frame: 1 when seen, 0 when not. */
int hfs_camenv_dir_to_pixel(const hfs_camenv_params *p, int w, int h, const double d[3],
                            double *x, double *y);
/* The direction pixel position (x, y) sees (the forward mapping, for
 * synthetic frames): 1, or 0 outside the circle/field. */
int hfs_camenv_pixel_to_dir(const hfs_camenv_params *p, int w, int h, double x, double y,
                            double d[3]);

/* A converter: its lookup table (4 pixels and weights per output texel)
 * is built for a frame size and rebuilt when the size changes. */
typedef struct hfs_camenv hfs_camenv;

int hfs_camenv_create(const hfs_camenv_params *p, hfs_camenv **out, hfs_error *err);
void hfs_camenv_destroy(hfs_camenv *c);
/* Frame f (GREY or YUYV) to the map (map_w x map_h x 3 floats, finite,
 * >= 0).  Errors: another format, a frame smaller than 2x2. */
int hfs_camenv_convert(hfs_camenv *c, const hfs_capture_frame *f, float *map, hfs_error *err);

/* Linear value of an 8-bit code under the params' transfer (exposure not
 * applied); YUYV to 8-bit R'G'B' (BT.601 limited range). */
float hfs_camenv_decode(const hfs_camenv_params *p, int code);
void hfs_camenv_yuv_to_rgb(int y, int cb, int cr, int rgb[3]);

#endif /* HFS_BOARD_CAMERA_ENV_H */
