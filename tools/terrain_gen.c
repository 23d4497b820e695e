/*
 * terrain_gen.c — see terrain_gen.h.
 */
#include "terrain_gen.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Cones of slope ~0.8 (38.7 degrees) on a flat base: a few sizes, some
 * overlapping, placed relative to the field so every size looks alike. */
void hfs_terrain_cones(float *z, int w, int h)
{
    static const double cones[][3] = {/* centre x, y (fraction), radius (fraction of min side) */
                                      {0.30, 0.35, 0.16}, {0.70, 0.30, 0.10}, {0.55, 0.70, 0.20},
                                      {0.20, 0.78, 0.07}, {0.85, 0.75, 0.06}};
    const double side = w < h ? w : h;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            double v = 0.0;
            for (size_t c = 0; c < sizeof cones / sizeof cones[0]; ++c) {
                const double cx = cones[c][0] * (w - 1), cy = cones[c][1] * (h - 1);
                const double r = cones[c][2] * side;
                const double d = hypot(i - cx, j - cy);
                const double cone = 0.8 * (r - d);
                if (cone > v)
                    v = cone;
            }
            z[(size_t)j * w + i] = (float)v;
        }
}

static double clamp01(double x)
{
    return x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x);
}

/* A control panel for small local lights close to a surface (issue 4), in
 * units of 1/128 of the short side: a plate at height 2 cut by a grid of
 * grooves (2 deep, 2-unit flat bottom, 1-unit walls) every 32 units at
 * 16 + 32k, and on every grid node between them an embossed feature: square
 * buttons (3 high, 14 wide, 2-unit bevel) and, in checkerboard, round knobs
 * (5 high, radius 6, 1.5-unit bevel).  Heights scale with the size too. */
void hfs_terrain_panel(float *z, int w, int h)
{
    const double s = (w < h ? w : h) / 128.0;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const double x = i / s, y = j / s;
            const double gx = fabs(fmod(x, 32.0) - 16.0), gy = fabs(fmod(y, 32.0) - 16.0);
            const double groove = 2.0 * fmax(clamp01(2.0 - gx), clamp01(2.0 - gy));
            double v = 2.0 - groove;
            const double kx = floor(x / 32.0 + 0.5), ky = floor(y / 32.0 + 0.5);
            const double bx = fabs(x - 32.0 * kx), by = fabs(y - 32.0 * ky);
            double feature;
            if (((long)kx + (long)ky) % 2 == 0)
                feature = 3.0 * clamp01((9.0 - fmax(bx, by)) / 2.0);   /* button */
            else
                feature = 5.0 * clamp01((7.5 - hypot(bx, by)) / 1.5);  /* knob   */
            if (feature > 0.0)
                v = fmax(v, 2.0 + feature);
            z[(size_t)j * w + i] = (float)(v * s);
        }
}

static uint32_t hash3(uint32_t x, uint32_t y, uint32_t s)
{
    uint32_t v = x * 0x8da6b343u ^ y * 0xd8163841u ^ s * 0xcb1ab31fu;
    v ^= v >> 16;
    v *= 0x7feb352du;
    v ^= v >> 15;
    v *= 0x846ca68bu;
    v ^= v >> 16;
    return v;
}

static double lattice(int x, int y, uint32_t seed)
{
    return (double)hash3((uint32_t)x, (uint32_t)y, seed) / 4294967295.0 * 2.0 - 1.0;
}

/* Value noise with quintic fade: C2, so normals are smooth. */
static double value_noise(double x, double y, uint32_t seed)
{
    const int xi = (int)floor(x), yi = (int)floor(y);
    const double fx = x - xi, fy = y - yi;
    const double ux = fx * fx * fx * (fx * (fx * 6 - 15) + 10);
    const double uy = fy * fy * fy * (fy * (fy * 6 - 15) + 10);
    const double a = lattice(xi, yi, seed), b = lattice(xi + 1, yi, seed);
    const double c = lattice(xi, yi + 1, seed), d = lattice(xi + 1, yi + 1, seed);
    return (a + (b - a) * ux) * (1 - uy) + (c + (d - c) * ux) * uy;
}

int hfs_terrain_fractal(float *z, int w, int h, uint32_t seed, double relief)
{
    return hfs_terrain_fbm(z, w, h, seed, relief, 1.0);
}

/* fBm, 8 octaves, gain 2^-hurst, base period = the field's smaller side / 2;
 * rescaled so heights span [0, relief * side]. */
int hfs_terrain_fbm(float *z, int w, int h, uint32_t seed, double relief, double hurst)
{
    const double gain = exp2(-hurst);
    const double side = w < h ? w : h;
    double lo = INFINITY, hi = -INFINITY;
    double *tmp = malloc((size_t)w * h * sizeof *tmp);
    if (!tmp)
        return -1;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            double v = 0.0, amp = 1.0, freq = 2.0 / side;
            for (int o = 0; o < 8; ++o) {
                v += amp * value_noise(i * freq, j * freq, seed + (uint32_t)o * 101u);
                amp *= gain;
                freq *= 2.0;
            }
            tmp[(size_t)j * w + i] = v;
            lo = fmin(lo, v);
            hi = fmax(hi, v);
        }
    const double scale = hi > lo ? relief * side / (hi - lo) : 0.0;
    for (size_t k = 0; k < (size_t)w * h; ++k)
        z[k] = (float)((tmp[k] - lo) * scale);
    free(tmp);
    return 0;
}

#define TWO_PI 6.283185307179586

static double min_side(int w, int h)
{
    return w < h ? w : h;
}

void hfs_terrain_sine(float *z, int w, int h)
{
    const double period = min_side(w, h) / 8.0, a = period / TWO_PI;
    const double cx = cos(TWO_PI / 12.0), sy = sin(TWO_PI / 12.0);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            z[(size_t)j * w + i] = (float)(a * (1.0 + sin(TWO_PI * (i * cx + j * sy) / period)));
}

void hfs_terrain_eggtray(float *z, int w, int h)
{
    const double period = min_side(w, h) / 8.0, a = period / TWO_PI;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            z[(size_t)j * w + i] =
                (float)(a * (1.0 + sin(TWO_PI * i / period) * sin(TWO_PI * j / period)));
}

void hfs_terrain_city(float *z, int w, int h, uint32_t seed)
{
    const double block = min_side(w, h) / 8.0, street = block / 4.0;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const int bx = (int)floor(i / block), by = (int)floor(j / block);
            const double fx = i - bx * block, fy = j - by * block;
            double v = 0.0;
            if (fx >= street && fy >= street) {
                const double u = (double)hash3((uint32_t)bx, (uint32_t)by, seed) / 4294967295.0;
                v = (0.1 + 0.5 * u) * block;
            }
            z[(size_t)j * w + i] = (float)v;
        }
}

void hfs_terrain_spike(float *z, int w, int h)
{
    memset(z, 0, (size_t)w * h * sizeof *z);
    z[(size_t)(h / 2) * w + w / 2] = (float)(min_side(w, h) / 4.0);
}

void hfs_terrain_cliff(float *z, int w, int h)
{
    const double top = min_side(w, h) / 4.0;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            z[(size_t)j * w + i] = i > 0.5 * (w - 1) + 0.2 * (j - 0.5 * (h - 1)) ? (float)top : 0.0f;
}

void hfs_terrain_tower(float *z, int w, int h, int bw, int bh)
{
    memset(z, 0, (size_t)w * h * sizeof *z);
    const int x0 = w / 8, y0 = (h - bw) / 2;
    for (int j = y0 < 0 ? 0 : y0; j < y0 + bw && j < h; ++j)
        for (int i = x0; i < x0 + bw && i < w; ++i)
            z[(size_t)j * w + i] = (float)bh;
}

void hfs_terrain_boxes(float *z, int w, int h, uint32_t seed)
{
    memset(z, 0, (size_t)w * h * sizeof *z);
    const long count = ((long)w * h + 2499) / 2500;
    for (long b = 0; b < count; ++b) {
        const uint32_t u = (uint32_t)b;
        const int bw = 2 + (int)(hash3(u, 1, seed) % 39u), bd = 2 + (int)(hash3(u, 2, seed) % 39u);
        const float bh = (float)(5 + hash3(u, 3, seed) % 36u);
        const int x0 = (int)(hash3(u, 4, seed) % (uint32_t)w), y0 = (int)(hash3(u, 5, seed) % (uint32_t)h);
        for (int j = y0; j < y0 + bd && j < h; ++j)
            for (int i = x0; i < x0 + bw && i < w; ++i)
                if (z[(size_t)j * w + i] < bh)
                    z[(size_t)j * w + i] = bh;
    }
}

int hfs_terrain_make(const char *name, float *z, int w, int h, uint32_t seed, double relief)
{
    if (!strcmp(name, "flat"))
        memset(z, 0, (size_t)w * h * sizeof *z);
    else if (!strcmp(name, "cones"))
        hfs_terrain_cones(z, w, h);
    else if (!strcmp(name, "sine"))
        hfs_terrain_sine(z, w, h);
    else if (!strcmp(name, "eggtray"))
        hfs_terrain_eggtray(z, w, h);
    else if (!strcmp(name, "city"))
        hfs_terrain_city(z, w, h, seed);
    else if (!strcmp(name, "spike"))
        hfs_terrain_spike(z, w, h);
    else if (!strcmp(name, "cliff"))
        hfs_terrain_cliff(z, w, h);
    else if (!strcmp(name, "panel"))
        hfs_terrain_panel(z, w, h);
    else if (!strcmp(name, "tower"))
        hfs_terrain_tower(z, w, h, 40, 30);
    else if (!strcmp(name, "boxes"))
        hfs_terrain_boxes(z, w, h, seed);
    else if (!strcmp(name, "fractal"))
        return hfs_terrain_fractal(z, w, h, seed, relief) ? -2 : 0;
    else
        return -1;
    return 0;
}

const char *hfs_terrain_names(void)
{
    return "flat|cones|sine|eggtray|city|spike|cliff|fractal|panel|tower|boxes";
}
