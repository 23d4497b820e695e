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

#include "hfshade.h"

#define HFS_ENV_MAX_LIGHTS HFS_MAX_KEY_LIGHTS
/* Largest map taken: 2^28 texels (3 GiB of float RGB, e.g. 23170^2). */
#define HFS_ENVMAP_DECOMP_MAX_TEXELS (1LL << 28)

typedef struct hfs_env_decompose_opts {
    int max_lights;     /* 0..HFS_ENV_MAX_LIGHTS; default 4                 */
    double min_share;   /* stop below this share of the map's energy;
                           default 0.02 (the paper's Weber fraction)        */
    double contrast;    /* a block is a light candidate only where its mean
                           exceeds contrast x its surround's; default 4     */
    double max_radius;  /* radians; a candidate wider than this ends the
                           search (0, the default: no limit).  A renderer
                           that shades the residual map itself (env-shade =
                           map) resolves broad lights better than a uniform
                           disk does: it keeps only what its slices cannot */
    int threads;        /* coarse pass workers, 0 = all cores               */
} hfs_env_decompose_opts;

/* One extracted light.  energy[c] = radiance[c] * 2 pi (1 - cos alpha) is
 * the energy removed from the map (sum of L dOmega). */
typedef struct hfs_env_light {
    double phi, elev, alpha;     /* radians (SPEC directions)                */
    float radiance[3];           /* linear RGB, >= 0                         */
    double energy[3];
    double share;                /* luminance energy / the map's             */
    int id;                      /* tracker identity (0 without a tracker)   */
} hfs_env_light;

typedef struct hfs_env_decomp {
    int n_lights;
    hfs_env_light light[HFS_ENV_MAX_LIGHTS];
    double residual_sh[3][HFS_SH_COEFFS]; /* the residual's projection      */
    double total_energy[3];      /* the input map's integral, per channel    */
    double residual_energy[3];   /* the residual map's integral              */
} hfs_env_decomp;

void hfs_env_decompose_defaults(hfs_env_decompose_opts *o);

/* Decomposes the w x h map rgb (modified in place into the residual).
 * o may be NULL (defaults).  Errors (0 or a negative hfs_status, one line
 * naming `name`): a size below 1x1, a NaN or infinite texel ("sky.pfm:
 * texel (3, 7) G is NaN"), a texel below -1% of the mean ("sky.pfm: texel
 * (3, 7) G is -0.5, below -0.01 x the map's mean radiance 1"), an option
 * out of range.  On error
 * *out is zeroed and rgb untouched. */
int hfs_env_decompose(float *rgb, int w, int h, const hfs_env_decompose_opts *o,
                      const char *name, hfs_env_decomp *out, hfs_error *err);

/* The lights as key lights (from_env = 1), at most max; returns the count. */
int hfs_env_decomp_keys(const hfs_env_decomp *d, hfs_key_light *keys, int max);

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
