/*
 * albedo_texture.h — the albedo map (hfs_lighting albedo_map; albedo.h) as
 * a texture of the shading pass: RGBA16F (RGBA32F at fp32), the map's RGB
 * at the texels, uploaded when its contents, size or precision change and
 * kept otherwise (a kept copy is compared each frame: W*H*3 floats, a
 * small fraction of the shading pass it saves).
 */
#ifndef HFS_GLES_ALBEDO_TEXTURE_H
#define HFS_GLES_ALBEDO_TEXTURE_H

#include "gl_api.h"
#include "gl_caps.h"
#include "hfshade.h"

typedef struct hfs_gles_albedo_texture {
    GLuint tex;
    int w, h, fp32;
    float *copy;          /* the map last uploaded, w*h*3 */
    unsigned gen;         /* bumped whenever the texture's contents change */
    size_t bytes;         /* texture memory */
} hfs_gles_albedo_texture;

/* Makes a->tex hold map (w x h, RGB) at the caps' precision; map NULL
 * frees it (the gen moves on when there was one).  Out of memory: an
 * error, a->tex then deleted. */
int hfs_gles_albedo_texture_follow(hfs_gles_albedo_texture *a, const hfs_gl *gl,
                                   const hfs_gl_caps *c, const float *map, int w, int h,
                                   hfs_error *err);
void hfs_gles_albedo_texture_free(hfs_gles_albedo_texture *a, const hfs_gl *gl);

#endif /* HFS_GLES_ALBEDO_TEXTURE_H */
