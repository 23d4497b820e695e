/*
 * env_decompose.h — an equirectangular HDR environment map split into disk
 * key lights plus a soft residual (issue 17; after Arbree, Walter & Bala,
 * "Pre-processing environment maps for dynamic hardware shadows", section 3;
 * docs/DESIGN.md "Environment map decomposition").
 *
 * Input: a linear RGB map in SPEC's equirect convention (column u -> phi =
 * 2 pi u, row v -> e = pi/2 - pi v, row 0 = zenith, texel centres at
 * (i + 0.5) / W), every value finite and none below -1% of the map's mean
 * luminance radiance (the small negatives lossy EXR compression leaves are
 * kept in the residual; larger ones are an error).  Output: up to max_lights
 * lights (direction, angular radius, RGB radiance) and the residual map,
 * written over the input, whose order-4 SH projection is the soft
 * environment.
 *
 * Energy: every light holds exactly the energy it removes.  A light takes
 * the texels whose centres lie within its removal radius (its angular radius
 * plus 0.75 texel), replaces them with the mean radiance F of a ring around
 * them (so the residual has no black hole for its SH to ring about), and
 * gets E = R - A F per channel (R: the removed texels' energy sum L dOmega,
 * A: their solid angle, F as stored in float); its radiance is E divided by
 * its disk's solid angle 2 pi (1 - cos alpha).  So lights + residual =
 * the map's integral, up to float rounding (tests/test_env_decompose.c).
 *
 * Maps under 16 x 8 texels give no light (a texel over 22.5 degrees).
 * Detection runs on a coarse copy of the map (at most 256 x 128 cells of
 * summed energy and exact solid angle, then 2 x 2 merges): a centre-surround
 * response E_in - contrast * A_in * mean_ring over blocks whose horizontal
 * width grows as 1/cos(latitude) (square on the sphere, whole rings at the
 * poles), azimuth wrapping across the 0/360 seam.  The strongest block is
 * refined on the full-resolution texels around it (energy centroid and the
 * second angular moment of the radiance above the surround give direction
 * and radius).  Stops at max_lights, at the first candidate without a
 * positive response, or when the next light would hold less than min_share
 * of the map's energy (luminance, Rec. 709 weights).
 *
 * Deterministic: the coarse pass is row-parallel with a fixed partition
 * (parallel.h), everything else is serial.  Memory beside the map, which
 * is modified in place: about 3 MiB (the coarse pyramid, the detection's
 * prefix sums, 28 bytes per texel row and column); the tracker adds a copy
 * of the map.  libc, libm and threads only (library hfs_envmap).
 */
#ifndef HFS_ENV_DECOMPOSE_H
#define HFS_ENV_DECOMPOSE_H

#include "hfshade_envmap.h"

/* The options, the lights found and the decomposition's result
 * (hfs_env_decompose_opts, hfs_env_light, hfs_env_decomp), and
 * hfs_env_decompose, hfs_env_decompose_defaults, hfs_env_decomp_keys are
 * public and exported: hfshade_envmap.h declares and documents them. */

/* Largest map taken: 2^28 texels (3 GiB of float RGB, e.g. 23170^2). */
#define HFS_ENVMAP_DECOMP_MAX_TEXELS (1LL << 28)

/* ---- temporal stability (a live probe) --------------------------------------- */

/* Keeps lights' identities across frames: each frame extracts the lights
 * it already tracks first, from their last directions (so an index never
 * swaps), then looks for new ones.  A new light is extracted only after it
 * has held at least appear_share for appear_frames frames in a row; a
 * tracked light is dropped after vanish_frames frames below vanish_share.
 * While a light is not extracted its energy stays in the residual, so every
 * frame still conserves energy exactly.  A tracked light's direction is
 * smoothed by an alpha-beta filter (constant velocity, so a moving sun does
 * not lag): a sun smaller than a texel otherwise jumps from texel centre to
 * texel centre.  The filter moves only the disk's direction, never the
 * energy removed from the map.  Zero-initialise, then
 * hfs_env_tracker_init. */
typedef struct hfs_env_tracker {
    hfs_env_decompose_opts opts;
    double appear_share;         /* default 1.25 x min_share                 */
    double vanish_share;         /* default 0.5 x min_share                  */
    int appear_frames;           /* default 3                                */
    int vanish_frames;           /* default 3                                */
    int n;                       /* tracked lights (extracted)               */
    hfs_env_light tracked[HFS_ENV_MAX_LIGHTS];
    int weak[HFS_ENV_MAX_LIGHTS];    /* frames in a row below vanish_share   */
    double vel[HFS_ENV_MAX_LIGHTS][3]; /* direction change per frame         */
    double gain, vel_gain;       /* alpha-beta filter of the directions;
                                    defaults 0.3, 0.05; gain 1 = raw         */
    int n_pending;               /* candidates not yet shown                 */
    hfs_env_light pending[HFS_ENV_MAX_LIGHTS];
    int seen[HFS_ENV_MAX_LIGHTS];    /* frames in a row above appear_share   */
    int next_id;                 /* last id given                            */
    long frames;                 /* frames tracked so far                    */
} hfs_env_tracker;

/* o may be NULL (defaults). */
void hfs_env_tracker_init(hfs_env_tracker *t, const hfs_env_decompose_opts *o);

/* One frame: as hfs_env_decompose, with identities kept by t.  out's lights
 * carry their id (1, 2, ...; never reused). */
int hfs_env_track(hfs_env_tracker *t, float *rgb, int w, int h, const char *name,
                  hfs_env_decomp *out, hfs_error *err);

#endif /* HFS_ENV_DECOMPOSE_H */
