/*
 * test_gles_scenes.h — scenes shared by the GLES tests and the GLES
 * benchmark (test_gles_scenes.c): terrains made with tools/hfgen.c's
 * formulas (so no file is needed), the DEM crop, the test lighting.
 */
#ifndef HFS_TEST_GLES_SCENES_H
#define HFS_TEST_GLES_SCENES_H

#include "hfshade.h"

typedef struct scene {
    hfs_field f;
    float *z;
} scene;

/* name: cones, fractal (relief 1), fractal25 (relief 0.25), flat, dem (crop
 * of data/jacksboro.png at (150, 120), dx 83, zscale 2), or a height file
 * (any loader format; its own size, dx 1).  n: size (square) for the
 * generated ones and the crop.  Returns 0 or -1 (message printed). */
int scene_make(const char *name, int n, const char *data_dir, scene *s);
void scene_free(scene *s);

/* A non-uniform coloured SH sky (brighter to +z and +x, rotated by 0.3 rad)
 * and/or one key light (azimuth 336, elevation 15, radius 2 degrees,
 * radiance (300, 280, 250)); albedo 0.8. */
hfs_lighting scene_lighting(int env, int key);

#endif
