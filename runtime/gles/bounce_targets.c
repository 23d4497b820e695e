/*
 * bounce_targets.c — see bounce_targets.h.
 */
#include "bounce_targets.h"

#include "gl_util.h"
#include "resources.h"

void hfs_gles_bounce_targets_free(hfs_gles_bounce_targets *t, const hfs_gl *gl)
{
    if (t->rad)
        ++t->gen;
    const GLuint fbos[5] = {t->rad_fbo, t->e_fbo, t->fin_fbo, t->fin_lo_fbo, t->near_fbo};
    for (int i = 0; i < 5; ++i)
        if (fbos[i])
            gl->DeleteFramebuffers(1, &fbos[i]);
    t->rad_fbo = t->e_fbo = t->fin_fbo = t->fin_lo_fbo = t->near_fbo = 0;
    hfs_gles_tex_delete(gl, &t->rad);
    hfs_gles_tex_delete(gl, &t->e);
    hfs_gles_tex_delete(gl, &t->near);
    hfs_gles_tex_delete(gl, &t->fin[0]);
    hfs_gles_tex_delete(gl, &t->fin[1]);
    t->w = t->h = t->bw = t->bh = t->near_layers = 0;
    t->bytes = 0;
}

int hfs_gles_bounce_targets_ensure(hfs_gles_bounce_targets *t, const hfs_gl *gl,
                                   const hfs_gl_caps *c, int w, int h, int bw, int bh,
                                   int glossy, int near_layers, hfs_error *err)
{
    glossy = glossy != 0;
    if (t->rad && t->w == w && t->h == h && t->bw == bw && t->bh == bh && t->fp32 == c->fp32 &&
        t->glossy == glossy && t->near_layers == near_layers)
        return HFS_OK;
    hfs_gles_bounce_targets_free(t, gl);
    t->w = w, t->h = h, t->bw = bw, t->bh = bh, t->fp32 = c->fp32, t->glossy = glossy;
    t->near_layers = near_layers;
    const int layers = (1 + glossy) * HFS_GLES_MAX_BOUNCES;
    t->rad = hfs_gles_tex_new(gl, GL_TEXTURE_2D, c->fmt_rgba, w, h, 1, 1);
    t->e = hfs_gles_tex_new(gl, GL_TEXTURE_2D_ARRAY, c->fmt_rgba, bw, bh, layers, 1);
    t->fin[0] = hfs_gles_tex_new(gl, GL_TEXTURE_2D, c->fmt_rgba, w, h, 1, 0);
    t->fin[1] = hfs_gles_tex_new(gl, GL_TEXTURE_2D, c->fmt_rgba, w, h, 1, 0);
    t->bytes = (size_t)(3 + near_layers) * w * h * c->bytes_rgba +
               (size_t)layers * bw * bh * c->bytes_rgba;
    gl->GenFramebuffers(1, &t->e_fbo);
    if (near_layers) {
        t->near = hfs_gles_tex_new(gl, GL_TEXTURE_2D_ARRAY, c->fmt_rgba, w, h, near_layers, 0);
        gl->GenFramebuffers(1, &t->near_fbo);
    }
    int rc;
    if ((rc = hfs_gles_fbo_new(gl, &t->rad_fbo, 1, &t->rad, NULL, "bounce radiance", err)) ||
        (rc = hfs_gles_fbo_new(gl, &t->fin_fbo, 2, t->fin, NULL, "bounce output", err)) ||
        (rc = hfs_gles_fbo_new(gl, &t->fin_lo_fbo, 1, &t->fin[1], NULL, "bounce output", err)))
        return rc;
    return hfs_gl_check(gl, "backend gles: allocating the bounce targets", err);
}
