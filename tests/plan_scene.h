/*
 * plan_scene.h — the lighting the frame-planner tests share: a sky (with a
 * +z and, when tilted, a +x gradient so that rotation shows), two key
 * lights and two local lights over a field of side n (the local lights sit
 * at fractions of it).
 */
#ifndef HFS_TESTS_PLAN_SCENE_H
#define HFS_TESTS_PLAN_SCENE_H

#include "hfshade.h"

static inline void plan_scene_lighting(hfs_lighting *l, int n, int tilted)
{
    hfs_lighting_defaults(l);
    l->has_env = 1;
    l->albedo = 0.8;
    for (int c = 0; c < 3; ++c) {
        l->env_sh[c][0] = 2.0;
        l->env_sh[c][2] = 0.8;
        l->env_sh[c][3] = tilted ? 0.3 : 0.0;
    }
    l->n_key = 2;
    l->key[0] = (hfs_key_light){.phi = 0.5, .elev = 0.4, .alpha = 0.04, .radiance = {20, 20, 20}};
    l->key[1] = (hfs_key_light){.phi = 2.5, .elev = 0.7, .alpha = 0.06, .radiance = {10, 9, 8}};
    l->n_local = 2;
    l->local[0] = (hfs_local_light){.pos = {0.5 * n, 0.5 * n, 10.0 * n / 32},
                                    .radius = 1.5, .radiance = {30, 30, 30}};
    l->local[1] = (hfs_local_light){.pos = {0.25 * n, 0.75 * n, 6.0 * n / 32},
                                    .radius = 1.0, .radiance = {20, 25, 30}};
}

#endif /* HFS_TESTS_PLAN_SCENE_H */
