/*
 * bounce_targets.h — the textures of the indirect-light pass
 * (pass_bounce.c), allocated on the first frame with bounces and kept
 * while the sizes and precision hold; none exist for a scene without
 * bounces:
 *   rad      full resolution, RGBA, LINEAR: the exit radiance the next
 *            bounce gathers (Lo_{b-1}, times the frame's output scale);
 *   e        the bounce grid (quality bounce_subsample), 3 layers, LINEAR:
 *            each bounce's gathered irradiance over pi, E_b, and the
 *            receivers' occluded part (pass_bounce.c); 6 for a glossy
 *            surface, E_b at 2 (b-1) and the lobe's G_b after it;
 *   near     full resolution, a layer a bounce (only on a sub-sampled
 *            bounce grid under an environment): each texel's own near part
 *            of the gather, (E_near, W_near) (bounce_gather.frag HFS_NEAR);
 *   fin      full resolution hi + lo pair: direct + indirect, what the
 *            read-back (and any later pass) takes instead of the shading
 *            pass's output.
 */
#ifndef HFS_GLES_BOUNCE_TARGETS_H
#define HFS_GLES_BOUNCE_TARGETS_H

#include "gl_api.h"
#include "gl_caps.h"
#include "hfshade.h"
#include "layout.h"

#define HFS_GLES_MAX_BOUNCES 3

typedef struct hfs_gles_bounce_targets {
    GLuint rad, rad_fbo;
    GLuint e, e_fbo;            /* e_fbo: one layer attached at a time */
    GLuint near, near_fbo;      /* near_fbo: likewise */
    GLuint fin[2], fin_fbo;     /* hi, lo drawn together */
    GLuint fin_lo_fbo;          /* lo alone, for the read-back */
    int w, h, bw, bh, fp32, glossy, near_layers;
    unsigned gen;               /* bumped when reallocated (contents lost) */
    size_t bytes;
} hfs_gles_bounce_targets;

/* Fits t to a w x h field and a bw x bh bounce grid at the caps'
 * precision, with the glossy layers or not and near_layers near layers
 * (0: none; a no-op while they hold). */
int hfs_gles_bounce_targets_ensure(hfs_gles_bounce_targets *t, const hfs_gl *gl,
                                   const hfs_gl_caps *c, int w, int h, int bw, int bh,
                                   int glossy, int near_layers, hfs_error *err);
void hfs_gles_bounce_targets_free(hfs_gles_bounce_targets *t, const hfs_gl *gl);

#endif /* HFS_GLES_BOUNCE_TARGETS_H */
