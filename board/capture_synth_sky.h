/*
 * capture_synth_sky.h — synthetic environment cameras: a known sky seen
 * through a mapping's forward direction (camera_env.h), encoded as a camera
 * would (radiance / exposure, clipped at full scale, the transfer, 8 bits,
 * BT.601 limited-range YUYV or full-range GREY), for the round-trip tests
 * and the environment recordings (hfs-capture-synth DIR --sky MAPPING).
 *
 * The moving sun (hfs_synth_sky_desc): a dim blue sky (0.02..0.06 linear
 * per channel, brighter toward the zenith), a darker ground below the
 * horizon, and a white sun disc of radius sun_radius degrees at full
 * scale (1.0: an 8-bit camera clips the sun; docs/CAPTURE.md says how to
 * set the exposure) whose azimuth sweeps linearly from az_from to az_to
 * degrees over the frames at elevation elev degrees.  Sensor noise:
 * Gaussian, noise codes (8-bit) on Y', a fresh draw per pixel and frame.
 * Deterministic.
 */
#ifndef HFS_BOARD_CAPTURE_SYNTH_SKY_H
#define HFS_BOARD_CAPTURE_SYNTH_SKY_H

#include <stdint.h>

#include "camera_env.h"

/* Linear RGB radiance the sky sends from unit direction d. */
typedef void (*hfs_sky_fn)(void *user, const double d[3], double rgb[3]);

/* A w x h frame (GREY: w bytes a row, YUYV: 2w; packed) of `sky` seen
 * through p (2 x 2 samples per pixel, averaged in linear radiance; pixels
 * that see nothing are black), plus Gaussian noise of `noise` codes on Y'
 * drawn from *rng (NULL: none). */
void hfs_synth_sky_render(const hfs_camenv_params *p, int w, int h, hfs_pixfmt fmt,
                          hfs_sky_fn sky, void *user, double noise, uint64_t *rng,
                          uint8_t *out);

typedef struct hfs_synth_sky_desc {
    hfs_camenv_params cam;        /* mapping etc.; default mirrorball        */
    int width, height;            /* default 320x240                         */
    int frames;                   /* default 60                              */
    double fps;                   /* default 30                              */
    double az_from, az_to, elev;  /* degrees; default 30, 150, 40            */
    double sun_radius;            /* degrees; default 8                      */
    double noise;                 /* Y' codes; default 1.5                   */
    uint32_t seed;                /* default 1                               */
} hfs_synth_sky_desc;

void hfs_synth_sky_defaults(hfs_synth_sky_desc *d);
/* The sun's direction at frame k, degrees. */
void hfs_synth_sky_sun(const hfs_synth_sky_desc *d, int k, double *az, double *elev);
/* The moving-sun sky's radiance at frame k (user: a {desc, k} pair). */
typedef struct hfs_synth_sky_at {
    const hfs_synth_sky_desc *d;
    int k;
} hfs_synth_sky_at;
void hfs_synth_sky_radiance(void *user, const double d[3], double rgb[3]);
/* Frame k (YUYV, 2 * width * height bytes). */
void hfs_synth_sky_frame(const hfs_synth_sky_desc *d, int k, uint8_t *yuyv);
/* The whole sequence as a YUYV recording in dir. */
int hfs_synth_sky_record(const hfs_synth_sky_desc *d, const char *dir, hfs_error *err);

#endif /* HFS_BOARD_CAPTURE_SYNTH_SKY_H */
