/*
 * env_map_textures.h — an environment map as the GLES path shades it
 * (env-shade = map; hfs_lighting env_open, env_shade_map; DESIGN.md
 * "Shading from the map itself"), allocated only for such a frame:
 *   open   33 x 33, LINEAR: the open-sky table D(N) over its largest
 *          |D| (env_open.h), read by the shading pass;
 *   slices 257 x 2n, LINEAR (slice path): per slice its F row then its G
 *          row (env_map_slices.h) over their largest |value|, read by the
 *          map-occlusion pass;
 *   occ    full resolution, RGBA: each texel's occluded irradiance from
 *          the map over that largest value (pass_env_map_slices.c);
 *   gloss  129 x 65, LINEAR (glossy surfaces): the map's lobe beyond
 *          order 4 D_g(R) over its largest |D_g| (env_gloss.h), read by
 *          the shading pass.
 * The tables are rebuilt only when what they are made from changes (the
 * map's pointer and size, its open-sky table's contents, the rotation,
 * the slices, the Phong exponent); values are stored normalised so fp16 never saturates, and
 * their scales (dmax, fmax) go to the shading pass.
 */
#ifndef HFS_GLES_ENV_MAP_TEXTURES_H
#define HFS_GLES_ENV_MAP_TEXTURES_H

#include "env_gloss.h"
#include "env_map_slices.h"
#include "env_open.h"
#include "gl_api.h"
#include "gl_caps.h"
#include "hfshade.h"
#include "slice_light.h"

typedef struct hfs_gles_env_map_textures {
    GLuint open, slices;
    GLuint occ, occ_fbo, gloss;
    double dmax, fmax, gmax;    /* the scales the tables were divided by     */
    /* What open and slices hold (fp32: the caps' precision). */
    float open_copy[HFS_ENV_OPEN_FLOATS];
    int open_fp32, have_open;
    const float *map;
    int map_w, map_h, n_slices, slices_fp32;
    double rotate, dphi;
    int occ_w, occ_h, occ_fp32;
    const float *gloss_map;     /* what gloss holds: map, size, exponent      */
    int gloss_w, gloss_h, gloss_fp32;
    double gloss_s;
    unsigned occ_gen;           /* bumped when occ is reallocated            */
    size_t bytes;
} hfs_gles_env_map_textures;

/* The open-sky table of l (l->env_open non-NULL) into t->open. */
int hfs_gles_env_open_follow(hfs_gles_env_map_textures *t, const hfs_gl *gl,
                             const hfs_gl_caps *c, const hfs_lighting *l, hfs_error *err);
/* The map's slices for the slice table st into t->slices. */
int hfs_gles_env_slices_follow(hfs_gles_env_map_textures *t, const hfs_gl *gl,
                               const hfs_gl_caps *c, const hfs_lighting *l,
                               const hfs_slice_table *st, hfs_error *err);
/* The map's glossy lobe beyond order 4 (l->env_shade_map and env_sh) for
 * Phong exponent s into t->gloss. */
int hfs_gles_env_gloss_follow(hfs_gles_env_map_textures *t, const hfs_gl *gl,
                              const hfs_gl_caps *c, const hfs_lighting *l, double s,
                              hfs_error *err);
/* The occlusion target at w x h (0 x 0 frees it). */
int hfs_gles_env_occ_ensure(hfs_gles_env_map_textures *t, const hfs_gl *gl,
                            const hfs_gl_caps *c, int w, int h, hfs_error *err);
void hfs_gles_env_map_textures_free(hfs_gles_env_map_textures *t, const hfs_gl *gl);

#endif /* HFS_GLES_ENV_MAP_TEXTURES_H */
