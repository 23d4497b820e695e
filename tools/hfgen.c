/*
 * hfgen — deterministic procedural height fields for tests and benchmarks.
 *
 *   hfgen flat    --size WxH -o OUT.pfm
 *   hfgen cones   --size WxH -o OUT.pfm     (SN08 figs. 3-10 style cones)
 *   hfgen fractal --size WxH -o OUT.pfm [--seed N] [--relief R]
 *   hfgen panel   --size WxH -o OUT.pfm     (grooved, embossed control panel)
 *   hfgen crop    IN --rect X,Y,W,H -o OUT.pfm   (any loadable height file)
 *
 * Heights are in texel units (use dx = 1, zscale = 1 to keep proportions);
 * the same arguments give the same file, bit for bit, on any machine
 * (integer hashing, no libc random).  Output is PFM "Pf", row j = 0 first.
 */
#include "hfs_io.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void usage(void)
{
    fprintf(stderr, "usage: hfgen flat|cones|fractal|panel --size WxH -o OUT.pfm [--seed N] [--relief R]\n"
                    "       hfgen crop IN --rect X,Y,W,H -o OUT.pfm\n");
}

/* Cones of slope ~0.8 (38.7 degrees) on a flat base: a few sizes, some
 * overlapping, placed relative to the field so every size looks alike. */
static void gen_cones(float *z, int w, int h)
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
static void gen_panel(float *z, int w, int h)
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

/* fBm, 8 octaves, gain 0.5, base period = the field's smaller side / 2;
 * rescaled so heights span [0, relief * side]. */
static void gen_fractal(float *z, int w, int h, uint32_t seed, double relief)
{
    const double side = w < h ? w : h;
    double lo = INFINITY, hi = -INFINITY;
    double *tmp = malloc((size_t)w * h * sizeof *tmp);
    if (!tmp)
        return;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            double v = 0.0, amp = 1.0, freq = 2.0 / side;
            for (int o = 0; o < 8; ++o) {
                v += amp * value_noise(i * freq, j * freq, seed + (uint32_t)o * 101u);
                amp *= 0.5;
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
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        usage();
        return 2;
    }
    const char *kind = argv[1], *out = NULL, *in = NULL, *rect = NULL;
    int w = 0, h = 0;
    unsigned seed = 1;
    double relief = 0.25;
    for (int i = 2; i < argc; ++i) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--size") && v) {
            if (sscanf(v, "%dx%d", &w, &h) != 2 || w < 2 || h < 2 || w > 16384 || h > 16384) {
                fprintf(stderr, "hfgen: --size: '%s' is not WxH within [2, 16384]\n", v);
                return 2;
            }
            ++i;
        } else if (!strcmp(a, "-o") && v) {
            out = v;
            ++i;
        } else if (!strcmp(a, "--seed") && v) {
            seed = (unsigned)strtoul(v, NULL, 10);
            ++i;
        } else if (!strcmp(a, "--relief") && v) {
            relief = strtod(v, NULL);
            if (!(relief >= 0.0 && relief <= 100.0)) {
                fprintf(stderr, "hfgen: --relief: '%s' is out of range [0, 100]\n", v);
                return 2;
            }
            ++i;
        } else if (!strcmp(a, "--rect") && v) {
            rect = v;
            ++i;
        } else if (a[0] != '-' && !in) {
            in = a;
        } else {
            fprintf(stderr, "hfgen: %s: unexpected argument\n", a);
            usage();
            return 2;
        }
    }
    if (!out) {
        usage();
        return 2;
    }
    hfs_error err = {{0}};
    float *z = NULL;
    if (!strcmp(kind, "crop")) {
        int x0, y0;
        hfs_heightmap hm;
        if (!in || !rect || sscanf(rect, "%d,%d,%d,%d", &x0, &y0, &w, &h) != 4) {
            usage();
            return 2;
        }
        if (hfs_height_load(in, NULL, &hm, &err)) {
            fprintf(stderr, "hfgen: %s\n", err.msg);
            return 1;
        }
        if (x0 < 0 || y0 < 0 || w < 2 || h < 2 || x0 + w > hm.width || y0 + h > hm.height) {
            fprintf(stderr, "hfgen: --rect %s lies outside %s (%dx%d)\n", rect, in, hm.width, hm.height);
            hfs_heightmap_free(&hm);
            return 2;
        }
        z = malloc((size_t)w * h * sizeof *z);
        if (z)
            for (int j = 0; j < h; ++j)
                memcpy(z + (size_t)j * w, hm.z + (size_t)(y0 + j) * hm.width + x0, (size_t)w * sizeof *z);
        hfs_heightmap_free(&hm);
    } else {
        if (w < 2) {
            fprintf(stderr, "hfgen: %s needs --size WxH\n", kind);
            return 2;
        }
        z = calloc((size_t)w * h, sizeof *z);
        if (z) {
            if (!strcmp(kind, "flat"))
                ;
            else if (!strcmp(kind, "cones"))
                gen_cones(z, w, h);
            else if (!strcmp(kind, "fractal"))
                gen_fractal(z, w, h, seed, relief);
            else if (!strcmp(kind, "panel"))
                gen_panel(z, w, h);
            else {
                fprintf(stderr, "hfgen: unknown kind '%s'\n", kind);
                free(z);
                usage();
                return 2;
            }
        }
    }
    if (!z) {
        fprintf(stderr, "hfgen: out of memory\n");
        return 1;
    }
    int rc = hfs_pfm_write_grey(out, w, h, z, &err);
    free(z);
    if (rc) {
        fprintf(stderr, "hfgen: %s\n", err.msg);
        return 1;
    }
    return 0;
}
