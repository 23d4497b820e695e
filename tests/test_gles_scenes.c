/*
 * test_gles_scenes.c — see test_gles_scenes.h.  Terrains come from
 * tools/terrain_gen.c, the generators hfgen uses.
 */
#include "test_gles_scenes.h"

#include "hfs_io.h"
#include "terrain_gen.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

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
        hfs_terrain_cones(s->z, n, n);
    } else if (!strcmp(name, "fractal") || !strcmp(name, "fractal25")) {
        if (hfs_terrain_fractal(s->z, n, n, 1, !strcmp(name, "fractal") ? 1.0 : 0.25)) {
            fprintf(stderr, "scene %s: out of memory\n", name);
            scene_free(s);
            return -1;
        }
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
                    hm.z[(size_t)((j + y0) % hm.height) * hm.width + (size_t)((i + x0) % hm.width)];
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

