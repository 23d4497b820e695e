/*
 * gl_bits.h — running GLSL on the driver and reading its floats back
 * exactly, for the tests that check shader code against C (test_sh_glsl_gpu,
 * test_glsl_numerics_gpu): a GL context by gl_test.h's skip rule, and an
 * RGBA32UI target that a shader fills with floatBitsToUint(result) (core ES
 * 3.0: no float render target needed), drawn by fullscreen.vert's one
 * triangle and read with RGBA_INTEGER / UNSIGNED_INT.
 *
 * Header-only (static inline); link hfs_gl.
 */
#ifndef HFS_TEST_GL_BITS_H
#define HFS_TEST_GL_BITS_H

#include <stdint.h>
#include <stdio.h>

#include "gl_api.h"
#include "gl_context.h"
#include "gl_shaders.h"
#include "gl_test.h"
#include "gl_util.h"
#include "hfshade.h"

typedef struct gl_bits {
    const hfs_gl *gl;
    GLuint program, vao;
    hfs_gl_target target; /* RGBA32UI, w x h */
} gl_bits;

/* Context `name` made and its GL table loaded into *gl, or the test exits
 * (77 where no GLES context can be made here, else 1). */
static inline hfs_gl_context *gl_bits_context(const char *name, hfs_gl *gl)
{
    hfs_error err = {""};
    hfs_gl_context *ctx = NULL;
    if (hfs_gl_context_create(name, &ctx, &err))
        gl_test_unavailable("gl context", &err);
    printf("context %s\n", hfs_gl_context_describe(ctx));
    if (hfs_gl_load(gl, hfs_gl_context_loader, ctx, &err)) {
        hfs_gl_context_destroy(ctx);
        gl_test_unavailable("gl table", &err);
    }
    return ctx;
}

/* The program (fullscreen.vert + frag, with defines) and a w x h target. */
static inline int gl_bits_init(gl_bits *b, const hfs_gl *gl, const char *frag_name,
                               const char *frag, const char *const *defines, int w, int h,
                               hfs_error *err)
{
    *b = (gl_bits){.gl = gl};
    int rc = hfs_gl_program_from_sources(gl, "fullscreen.vert",
                                         hfs_shader_source("fullscreen.vert"), frag_name, frag,
                                         defines, &b->program, err);
    if (rc || (rc = hfs_gl_target_create(gl, w, h, GL_RGBA32UI, &b->target, err)))
        return rc;
    gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl->GenVertexArrays(1, &b->vao);
    return hfs_gl_check(gl, "bits target setup", err);
}

static inline void gl_bits_free(gl_bits *b)
{
    const hfs_gl *gl = b->gl;
    if (!gl)
        return;
    if (b->vao)
        gl->DeleteVertexArrays(1, &b->vao);
    hfs_gl_target_destroy(gl, &b->target);
    if (b->program)
        gl->DeleteProgram(b->program);
    b->gl = NULL;
}

/* Draws the program (current, its uniforms and textures set by the caller)
 * over the target, NaN bits where it writes nothing, and reads the target
 * into bits (w h 4 words, rows from the bottom). */
static inline int gl_bits_draw(gl_bits *b, uint32_t *bits, hfs_error *err)
{
    const hfs_gl *gl = b->gl;
    const int w = b->target.width, h = b->target.height;
    gl->BindFramebuffer(GL_FRAMEBUFFER, b->target.framebuffer);
    const GLenum att = GL_COLOR_ATTACHMENT0;
    gl->DrawBuffers(1, &att);
    gl->Viewport(0, 0, w, h);
    const GLuint nan[4] = {0x7fc00000u, 0x7fc00000u, 0x7fc00000u, 0x7fc00000u};
    gl->ClearBufferuiv(GL_COLOR, 0, nan);
    gl->BindVertexArray(b->vao);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    gl->BindVertexArray(0);
    gl->UseProgram(0);
    gl->BindFramebuffer(GL_READ_FRAMEBUFFER, b->target.framebuffer);
    gl->ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl->PixelStorei(GL_PACK_ALIGNMENT, 4);
    gl->ReadPixels(0, 0, w, h, GL_RGBA_INTEGER, GL_UNSIGNED_INT, bits);
    gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
    return hfs_gl_check(gl, "bits draw/readback", err);
}

#endif /* HFS_TEST_GL_BITS_H */
