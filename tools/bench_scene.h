/*
 * bench_scene.h — the scenes and lightings hfbench measures, by name, built
 * in memory so that a benchmark point is fully described by its CSV row.
 *
 *   scene    a procedural kind of terrain_gen.h (cones, sine, eggtray, city,
 *            spike, cliff, fractal, panel, flat; dx = 1, zscale = 1) or
 *            "dem": the Jacksboro DEM (data/jacksboro.png) cropped to
 *            size x size at (140, 100) — or the top-left corner when that
 *            does not fit — with dx 83, zscale 2, as tools/bench_reference.sh;
 *   lights   "sky+sun" the demo lighting (data/courtyard.exr, the map kept
 *            for the truth and projected to SH, key light 336,15,2,1500), "sky", "sun", or "local" (three local
 *            lights of tools/bench_local.sh's cones set, placed in proportion
 *            to the field; procedural scenes only).
 * Lightings are applied through the scene keys (runtime/scene/scene.h), so
 * they mean exactly what the same keys mean to hfshade.
 */
#ifndef HFS_BENCH_SCENE_H
#define HFS_BENCH_SCENE_H

#include "hfshade.h"

typedef struct bench_scene {
    char name[32], lights[32];
    int size;
    hfs_field field;      /* field.z owned */
    hfs_lighting lighting; /* lighting.env_map = env_map */
    float *env_map;        /* the environment map (owned), or NULL */
} bench_scene;

/* Builds scene `name` at size x size under `lights`; data_dir holds the DEM
 * and the environment map.  One-line errors name the scene or the file. */
int bench_scene_make(const char *name, int size, const char *lights, const char *data_dir,
                     bench_scene *out, hfs_error *err);
void bench_scene_free(bench_scene *s);

#endif /* HFS_BENCH_SCENE_H */
