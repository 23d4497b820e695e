/*
 * bounds_texture.c — see bounds_texture.h.
 */
#include "bounds_texture.h"

#include "gl_util.h"
#include "ray_bound.h"

#include <math.h>
#include <stdint.h>

uint16_t hfs_gles_half_up(double v)
{
    uint16_t h;
    hfs_half_round_up(&v, 1, &h); /* the upload's own rounding (half_bulk.c) */
    return h;
}

float hfs_gles_float_up(double v)
{
    const float f = (float)v;
    return (double)f >= v ? f : nextafterf(f, INFINITY);
}

size_t hfs_gles_bounds_work_bytes(const hfs_gles_layout *L)
{
    const hfs_ray_bound_layout *rb = &L->rb;
    const size_t n = (size_t)rb->aw * (size_t)rb->ah;
    /* the atlas and the build's scratch in double, then the texels */
    return (n + 2 * (size_t)rb->lw[1] * (size_t)rb->lh[1]) * sizeof(double) + n * sizeof(float);
}

int hfs_gles_bounds_upload(const hfs_gl *gl, const hfs_gl_caps *c, GLuint tex,
                           const hfs_gles_layout *L, const hfs_field *f, void *work,
                           hfs_error *err)
{
    const hfs_ray_bound_layout *rb = &L->rb;
    const size_t n = (size_t)rb->aw * (size_t)rb->ah;
    double *atlas = work;
    double *scratch = atlas + n;
    void *buf = scratch + 2 * (size_t)rb->lw[1] * (size_t)rb->lh[1];
    hfs_ray_bound_build(rb, f->z, L->base, L->hscale, -2.0, atlas, scratch);
    if (c->fp32)
        for (size_t i = 0; i < n; ++i)
            ((float *)buf)[i] = hfs_gles_float_up(atlas[i]);
    else
        hfs_half_round_up(atlas, n, buf);
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl->BindTexture(GL_TEXTURE_2D, tex);
    gl->TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, rb->aw, rb->ah, GL_RED, c->type_upload, buf);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 4);
    return hfs_gl_check(gl, "backend gles: height bounds upload", err);
}
