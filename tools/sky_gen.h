/*
 * sky_gen.h — deterministic synthetic equirectangular skies (SPEC's convention,
 * row 0 = zenith): a gradient sky, a ground, any number of uniform disks
 * (suns, windows) and optional per-texel noise.  One definition for
 * `hfgen sky`, the decomposition tests (tests/test_env_decompose.c) and the
 * tracking benchmark (tools/bench_env_track.c).
 *
 * Disks are anti-aliased: texels within a texel of a disk's edge take the
 * covered fraction of 8 x 8 sub-samples; each disk's energy as rendered
 * (sum of radiance x coverage x texel solid angle) is reported, so a test
 * knows exactly what a decomposition should recover.
 */
#ifndef HFS_SKY_GEN_H
#define HFS_SKY_GEN_H

#define HFS_SKY_MAX_DISKS 8

typedef struct hfs_sky_disk {
    double phi, elev, radius;    /* degrees (SPEC azimuth/elevation)        */
    float radiance[3];           /* added to the sky over the disk          */
} hfs_sky_disk;

typedef struct hfs_sky_desc {
    int width, height;
    float zenith[3], horizon[3]; /* sky: horizon + (zenith - horizon) sin e */
    float ground[3];             /* below the horizon                       */
    int n_disks;
    hfs_sky_disk disk[HFS_SKY_MAX_DISKS];
    double noise;                /* texel x (1 + noise * u), u in [-1, 1)   */
    unsigned seed;               /* of the noise (integer hash)             */
} hfs_sky_desc;

/* The defaults: a blue sky, brown ground, no disk, no noise. */
void hfs_sky_defaults(hfs_sky_desc *d, int width, int height);

/* Renders d into rgb (width*height*3 floats).  energy (may be NULL) gets
 * each disk's rendered energy per channel.  0, or -1 for a bad size. */
int hfs_sky_render(const hfs_sky_desc *d, float *rgb, double (*energy)[3]);

/* Luminance energy (Rec. 709) of a rendered map: sum Y dOmega. */
double hfs_sky_lum_energy(const float *rgb, int width, int height);

/* Adds disk k's radiance again, scaled to hold `share` of the whole map's
 * luminance energy (0 < share < 1): the map was rendered with disk k's
 * radiance as its colour; returns the factor applied. */
double hfs_sky_set_share(const hfs_sky_desc *d, int k, double share, float *rgb,
                         double (*energy)[3]);

#endif /* HFS_SKY_GEN_H */
