/*
 * test_gles_scenes.c — see test_gles_scenes.h.
 */
#include "test_gles_scenes.h"

#include "hfs_io.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

/* ---- terrains (tools/hfgen.c) ---------------------------------------------------- */

static void gen_cones(float *z, int w, int h)
{
    static const double cones[][3] = {{0.30, 0.35, 0.16}, {0.70, 0.30, 0.10}, {0.55, 0.70, 0.20},
                                      {0.20, 0.78, 0.07}, {0.85, 0.75, 0.06}};
    const double side = w < h ? w : h;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            double v = 0.0;
            for (size_t c = 0; c < sizeof cones / sizeof cones[0]; ++c) {
                const double cx = cones[c][0] * (w - 1), cy = cones[c][1] * (h - 1);
                const double r = cones[c][2] * side;
                const double cone = 0.8 * (r - hypot(i - cx, j - cy));
                if (cone > v)
                    v = cone;
            }
            z[(size_t)j * w + i] = (float)v;
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

int scene_make(const char *name, int n, const char *data_dir, scene *s)
{
    memset(s, 0, sizeof *s);
    s->z = malloc((size_t)n * n * sizeof *s->z);
    if (!s->z)
        return -1;
    s->f.width = s->f.height = n;
    s->f.z = s->z;
    s->f.dx = 1.0;
    s->f.zscale = 1.0;
    if (!strcmp(name, "cones")) {
        gen_cones(s->z, n, n);
    } else if (!strcmp(name, "fractal")) {
        gen_fractal(s->z, n, n, 1, 1.0);
    } else if (!strcmp(name, "fractal25")) {
        gen_fractal(s->z, n, n, 1, 0.25);
    } else if (!strcmp(name, "flat")) {
        memset(s->z, 0, (size_t)n * n * sizeof *s->z);
    } else if (!strcmp(name, "dem")) {
        hfs_heightmap hm;
        hfs_error err;
        char path[1024];
        snprintf(path, sizeof path, "%s/jacksboro.png", data_dir);
        if (hfs_height_load(path, NULL, &hm, &err)) {
            fprintf(stderr, "%s\n", err.msg);
            return -1;
        }
        const int x0 = hm.width > n + 150 ? 150 : 0, y0 = hm.height > n + 120 ? 120 : 0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                s->z[(size_t)j * n + i] =
                    hm.z[(size_t)(j + y0 % hm.height) * hm.width + (size_t)(i + x0) % hm.width];
        hfs_heightmap_free(&hm);
        s->f.dx = 83.0;
        s->f.zscale = 2.0;
    } else {
        hfs_heightmap hm;
        hfs_error err;
        if (hfs_height_load(name, NULL, &hm, &err)) {
            fprintf(stderr, "%s\n", err.msg);
            return -1;
        }
        free(s->z);
        s->z = hm.z; /* ownership moves to the scene */
        s->f.width = hm.width;
        s->f.height = hm.height;
        s->f.z = s->z;
    }
    return 0;
}

void scene_free(scene *s)
{
    free(s->z);
    memset(s, 0, sizeof *s);
}

hfs_lighting scene_lighting(int env, int key)
{
    hfs_lighting l;
    hfs_lighting_defaults(&l);
    l.has_env = env;
    static const double grey[16] = {3.0, 0.2, 1.6, 0.7, 0.1, -0.15, 0.35, 0.25,
                                    -0.2, 0.05, 0.04, -0.08, 0.12, 0.06, -0.05, 0.03};
    static const double tint[3] = {1.0, 0.9, 0.75};
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 16; ++k)
            l.env_sh[c][k] = grey[k] * (k == 0 ? tint[c] : 1.0);
    l.env_rotate = 0.3;
    l.n_key = key ? 1 : 0;
    l.key[0].phi = 336.0 * PI / 180.0;
    l.key[0].elev = 15.0 * PI / 180.0;
    l.key[0].alpha = 2.0 * PI / 180.0;
    l.key[0].radiance[0] = 300.0f;
    l.key[0].radiance[1] = 280.0f;
    l.key[0].radiance[2] = 250.0f;
    l.albedo = 0.8;
    return l;
}

