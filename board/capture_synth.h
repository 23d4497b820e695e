/*
 * capture_synth.h — a synthetic depth camera over a sandbox, for tests,
 * demos and the measurements (docs/CAPTURE.md "Synthetic recordings").
 *
 * The camera looks down from about 1 m at sand (a tilted ground plane,
 * dunes up to ~8 cm).  A hand (an ellipse 25 cm above the sand) enters at
 * frame hand_from, sweeps across until hand_stop, stays still until
 * hand_to and is gone after.  Sensor noise: Gaussian, noise_m metres per
 * pixel, a fresh draw per frame; holes: hole_frac of the pixels read 0
 * (no data), plus the hand's shadow strip.  Z16 counts of `scale` metres.
 * Deterministic: the same description gives the same bytes.
 */
#ifndef HFS_BOARD_CAPTURE_SYNTH_H
#define HFS_BOARD_CAPTURE_SYNTH_H

#include <stdint.h>

#include "hfshade.h"

typedef struct hfs_synth_desc {
    int width, height;          /* depth pixels (default 512x384)            */
    int frames;                 /* default 90                                */
    double fps;                 /* default 30                                */
    double scale;               /* metres per count (default 0.001)          */
    double noise_m;             /* default 0.0015                            */
    double hole_frac;           /* default 0.005                             */
    int hand_from, hand_stop, hand_to;  /* default 30, 45, 70; from < 0: none */
    uint32_t seed;              /* default 1                                 */
} hfs_synth_desc;

void hfs_synth_defaults(hfs_synth_desc *d);

/* Frame k: depth counts (width*height, row-major) and, if truth is not
 * NULL, the noise-free height above the ground plane in metres per pixel. */
void hfs_synth_frame(const hfs_synth_desc *d, int k, uint16_t *depth, float *truth);

/* The ground plane the synthetic camera sees: depth = a*u + b*v + c. */
void hfs_synth_plane(const hfs_synth_desc *d, double plane[3]);

/* The generators' random numbers: splitmix64 and a uniform in (0, 1). */
uint64_t hfs_synth_u64(uint64_t *state);
double hfs_synth_uniform(uint64_t *state);

/* Writes the whole sequence as a recording (capture_record.h) into dir. */
int hfs_synth_record(const hfs_synth_desc *d, const char *dir, hfs_error *err);

#endif /* HFS_BOARD_CAPTURE_SYNTH_H */
