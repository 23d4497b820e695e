/*
 * terrain_gen.h — deterministic procedural height fields shared by the
 * hfgen tool, the tests and the benchmarks, so that every one of them means
 * the same terrain by the same name.  Heights are in texel units (dx = 1)
 * and scale with the field's smaller side, so a scene looks alike at every
 * size.  Randomness is integer hashing (no libc random): the same arguments
 * give the same heights, bit for bit, with the same libm.
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

/* The same with Hurst exponent `hurst`: each octave's amplitude 2^-hurst
 * of the previous one's (hfs_terrain_fractal: 1).  A lower exponent puts
 * more of the relief at the texel scale (issue 36's "Hurst 0.25" field: a
 * rough surface of pits and spikes; 0.8 a realistic terrain). */
int hfs_terrain_fbm(float *z, int w, int h, uint32_t seed, double relief, double hurst);

/* A sine grating: ridges along 30 degrees from +x, period side/8, heights
 * in [0, 2a] with a = period / (2 pi) (steepest slope 1). */
void hfs_terrain_sine(float *z, int w, int h);

/* An egg tray: sin(2 pi x / P) sin(2 pi y / P) bumps and pits, P = side/8,
 * amplitude P / (2 pi), lifted to heights >= 0. */
void hfs_terrain_eggtray(float *z, int w, int h);

/* City blocks: a street grid (blocks side/8, streets a quarter of that)
 * with a box building per block, height from a hash in [0.1, 0.6] of the
 * block: vertical walls, flat roofs, flat streets at 0. */
void hfs_terrain_city(float *z, int w, int h, uint32_t seed);

/* A flat field with one texel at the centre raised to side/4. */
void hfs_terrain_spike(float *z, int w, int h);

/* A vertical cliff of height side/4 across the field (a slanted line, so
 * no direction is axis-aligned with it): 0 on one side, side/4 beyond. */
void hfs_terrain_cliff(float *z, int w, int h);

/* One square block bw x bw texels, bh tall, on a flat field: its near
 * side at x = w/8, centred in y (issue 36: the long shadow of a narrow
 * feature under a low sun from -x). */
void hfs_terrain_tower(float *z, int w, int h, int bw, int bh);

/* Random boxes on a flat field, one per 2500 texels: sides 2-40 texels,
 * heights 5-40 (the taller wins where two overlap). */
void hfs_terrain_boxes(float *z, int w, int h, uint32_t seed);

/* Every generator by name, for the tools: flat, cones, sine, eggtray,
 * city, spike, cliff, fractal (seed, relief), panel, tower (40 x 30; hfgen's
 * --block W,H sets it), boxes (seed).  Returns 0, -1 for an
 * unknown name, -2 when out of memory.  hfs_terrain_names() lists them
 * separated by '|'. */
int hfs_terrain_make(const char *name, float *z, int w, int h, uint32_t seed, double relief);
const char *hfs_terrain_names(void);

#endif /* HFS_TERRAIN_GEN_H */
