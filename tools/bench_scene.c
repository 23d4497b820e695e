/*
 * bench_scene.c — see bench_scene.h.
 */
#include "bench_scene.h"

#include "hfs_io.h"
#include "scene.h"
#include "sh.h"
#include "terrain_gen.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int make_field(const char *name, int size, const char *data_dir, bench_scene *s,
                      hfs_error *err)
{
    float *z = malloc((size_t)size * size * sizeof *z);
    if (!z)
        return hfs_fail(err, HFS_E_NOMEM, "scene %s: out of memory at %dx%d", name, size, size);
    s->field = (hfs_field){.width = size, .height = size, .z = z, .dx = 1.0, .zscale = 1.0};
    if (strcmp(name, "dem") != 0) {
        const int rc = hfs_terrain_make(name, z, size, size, 1, 0.25);
        if (rc == -1)
            return hfs_fail(err, HFS_E_INVALID, "scene '%s': unknown (dem|%s)", name,
                            hfs_terrain_names());
        return rc ? hfs_fail(err, HFS_E_NOMEM, "scene %s: out of memory", name) : HFS_OK;
    }
    char path[4096];
    snprintf(path, sizeof path, "%s/jacksboro.png", data_dir);
    hfs_heightmap hm;
    int rc = hfs_height_load(path, NULL, &hm, err);
    if (rc)
        return rc;
    if (size > hm.width || size > hm.height) {
        hfs_heightmap_free(&hm);
        return hfs_fail(err, HFS_E_INVALID, "scene dem: %s is %dx%d, smaller than %d", path,
                        hm.width, hm.height, size);
    }
    const int x0 = 140 + size <= hm.width ? 140 : 0, y0 = 100 + size <= hm.height ? 100 : 0;
    for (int j = 0; j < size; ++j)
        memcpy(z + (size_t)j * size, hm.z + (size_t)(y0 + j) * hm.width + x0,
               (size_t)size * sizeof *z);
    hfs_heightmap_free(&hm);
    s->field.dx = 83.0;
    s->field.zscale = 2.0;
    return HFS_OK;
}

static int set_key(hfs_scene *sc, const char *key, const char *value, hfs_error *err)
{
    char where[64];
    snprintf(where, sizeof where, "lights %s", key);
    return hfs_scene_set(sc, HFS_SOURCE_FLAG, key, value, where, NULL, err);
}

static int make_lighting(const char *lights, const char *data_dir, bench_scene *s,
                         hfs_error *err)
{
    hfs_scene sc;
    hfs_scene_init(&sc);
    const int sky = !strcmp(lights, "sky+sun") || !strcmp(lights, "sky");
    const int sun = !strcmp(lights, "sky+sun") || !strcmp(lights, "sun");
    const int local = !strcmp(lights, "local");
    if (!sky && !sun && !local)
        return hfs_fail(err, HFS_E_INVALID, "lights '%s': unknown (sky+sun|sky|sun|local)",
                        lights);
    int rc = HFS_OK;
    if (sun)
        rc = set_key(&sc, "key", "336,15,2,1500", err);
    if (local) {
        if (!strcmp(s->name, "dem"))
            return hfs_fail(err, HFS_E_INVALID, "lights local: procedural scenes only, not dem");
        /* tools/bench_local.sh's first three cones lights, given for 128^2. */
        static const double set[3][5] = {{64, 64, 12, 2, 100}, {20, 20, 6, 1.5, 60},
                                         {100, 110, 25, 3, 150}};
        const double f = s->size / 128.0;
        for (int i = 0; i < 3 && !rc; ++i) {
            char v[128];
            snprintf(v, sizeof v, "%.17g,%.17g,%.17g,%.17g,%.17g", set[i][0] * f, set[i][1] * f,
                     set[i][2] * f, set[i][3] * f, set[i][4]);
            rc = set_key(&sc, "local", v, err);
        }
    }
    if (rc)
        return rc;
    if (!sky) {
        hfs_scene_lighting(&sc, NULL, &s->lighting);
        return HFS_OK;
    }
    char path[4096];
    snprintf(path, sizeof path, "%s/courtyard.exr", data_dir);
    if ((rc = set_key(&sc, "env-map", path, err)))
        return rc;
    hfs_envmap env;
    if ((rc = hfs_envmap_load(path, &env, err)))
        return rc;
    double sh[3][HFS_SH_N];
    hfs_sh_project_equirect(env.rgb, env.width, env.height, sh);
    hfs_scene_lighting(&sc, (const double(*)[HFS_SH_COEFFS])sh, &s->lighting);
    /* The map itself, as hfshade's scenes: the truth integrates it. */
    s->lighting.env_map = s->env_map = env.rgb;
    s->lighting.env_map_width = env.width;
    s->lighting.env_map_height = env.height;
    return HFS_OK;
}

int bench_scene_make(const char *name, int size, const char *lights, const char *data_dir,
                     bench_scene *out, hfs_error *err)
{
    memset(out, 0, sizeof *out);
    if (size < 2 || size > 16384)
        return hfs_fail(err, HFS_E_INVALID, "scene %s: size %d out of range [2, 16384]", name,
                        size);
    snprintf(out->name, sizeof out->name, "%s", name);
    snprintf(out->lights, sizeof out->lights, "%s", lights);
    out->size = size;
    int rc = make_field(name, size, data_dir, out, err);
    if (!rc)
        rc = make_lighting(lights, data_dir, out, err);
    if (rc)
        bench_scene_free(out);
    return rc;
}

void bench_scene_free(bench_scene *s)
{
    free((void *)s->field.z);
    free(s->env_map);
    s->field.z = NULL;
    s->env_map = NULL;
    s->lighting.env_map = NULL;
}
