/*
 * terrain_gen.h — deterministic procedural height fields shared by the
 * hfgen tool, the tests and the benchmarks, so that every one of them means
 * the same terrain by the same name.  Heights are in texel units (dx = 1);
 * integer hashing only, so the same arguments give the same heights, bit for
 * bit, on any machine.
 */
#ifndef HFS_TERRAIN_GEN_H
#define HFS_TERRAIN_GEN_H

#include <stdint.h>

/* Five cones of slope 0.8 on a flat base, placed relative to the field. */
void hfs_terrain_cones(float *z, int w, int h);

/* A control panel: a plate with grooves, embossed buttons and knobs. */
void hfs_terrain_panel(float *z, int w, int h);

/* 8-octave value-noise fBm rescaled to heights in [0, relief * min(w, h)].
 * Returns 0, or -1 when out of memory (z untouched). */
int hfs_terrain_fractal(float *z, int w, int h, uint32_t seed, double relief);

#endif /* HFS_TERRAIN_GEN_H */
