/*
 * pass_lit_texture.c — embedding without a read-back (issue 20): the lit
 * targets (hi, lo: hfs_gles_lit_targets) summed and the output scale
 * divided out on the GPU, into a texture of the application's share group
 * (hfshade.h hfs_renderer_render_texture, lit_texture.frag): linear
 * radiance in RGBA16F, or the kiosk's sRGB picture in RGBA8.  Only frames
 * that want the texture plan this pass (instead of the read-back), and
 * only when the targets or the encoding changed: a frame with nothing
 * changed hands out the kept texture.
 *
 * Both formats are colour-renderable under every profile the capability
 * layer admits (RGBA8 in core ES 3.0, RGBA16F through
 * EXT_color_buffer_half_float, which each profile requires), and the
 * encoding is one fullscreen draw: no float32 texture, whatever the
 * precision of the frame.
 */
#include "gles_backend.h"

#include "gl_util.h"

#include <float.h>
#include <math.h>

static int present(const hfs_gles_frame *fr)
{
    return fr->lit != NULL;
}

static int layout(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err)
{
    return hfs_gl_caps_check_texture(&g->caps, fr->f->width, fr->f->height, 1, "lit texture",
                                     err);
}

static GLenum format_of(const hfs_lit_texture_desc *how)
{
    return how->encoding == HFS_LIT_SRGB8 ? GL_RGBA8 : GL_RGBA16F;
}

void hfs_gles_lit_texture_free(hfs_gles *g)
{
    const hfs_gl *gl = &g->gl;
    hfs_gles_lit_texture *t = &g->lit;
    if (t->fence)
        gl->DeleteSync(t->fence);
    if (t->fbo)
        gl->DeleteFramebuffers(1, &t->fbo);
    hfs_gles_tex_delete(gl, &t->tex);
    *t = (hfs_gles_lit_texture){0};
}

/* The texture at w x h in the encoding's format: kept when it is so
 * already (its name then stays the application's from frame to frame). */
static int fit(hfs_gles *g, int w, int h, GLenum format, hfs_error *err)
{
    hfs_gles_lit_texture *t = &g->lit;
    if (t->tex && t->w == w && t->h == h && t->format == format)
        return HFS_OK;
    const GLsync fence = t->fence;
    t->fence = NULL; /* the fence outlives the texture: handed out until the next call */
    hfs_gles_lit_texture_free(g);
    t->fence = fence;
    t->tex = hfs_gles_tex_new(&g->gl, GL_TEXTURE_2D, format, w, h, 1, 1);
    t->w = w, t->h = h, t->format = format;
    int rc = hfs_gles_fbo_new(&g->gl, &t->fbo, 1, &t->tex, NULL, "lit texture", err);
    if (rc)
        return rc;
    return hfs_gl_check(&g->gl, "lit texture: allocation", err);
}

static int run(hfs_gles *g, hfs_gles_frame *fr, const int *which, hfs_error *err)
{
    (void)which;
    const hfs_gl *gl = &g->gl;
    const hfs_gles_layout *L = &fr->L;
    const hfs_lit_texture_desc *how = fr->lit;
    int rc = fit(g, L->w, L->h, format_of(how), err);
    if (rc)
        return rc;
    GLuint lit[2];
    hfs_gles_lit_targets(g, fr, lit);
    const hfs_gles_variant v = {0};
    const hfs_gles_program *prog;
    if ((rc = hfs_gles_program_use(&g->programs, gl, HFS_PROG_LIT_TEXTURE, &v, &prog, err)) ||
        (rc = hfs_gles_program_texture(gl, prog, "u_hi", GL_TEXTURE_2D, lit[0], err)) ||
        (rc = hfs_gles_program_texture(gl, prog, "u_lo", GL_TEXTURE_2D, lit[1], err)))
        return rc;
    /* The scale the targets were shaded with (the shading may not have run
     * this frame); 1 / scale within float's range: see lit_texture.frag. */
    const double inv = fmin(fmax(1.0 / g->lit_scale, (double)FLT_MIN), (double)FLT_MAX / 65536.0);
    hfs_gles_set_f1(gl, prog, "u_inv_scale", (float)inv);
    hfs_gles_set_i1(gl, prog, "u_encoding", how->encoding == HFS_LIT_SRGB8);
    hfs_gles_set_i1(gl, prog, "u_tonemap", how->tonemap); /* 0..2, checked by the renderer */
    hfs_gles_set_f1(gl, prog, "u_exposure", (float)how->exposure);
    hfs_gles_draw(gl, g->lit.fbo, L->w, L->h);
    return hfs_gl_check(gl, "lit texture", err);
}

int hfs_gles_lit_texture_black(hfs_gles *g, int w, int h, const hfs_lit_texture_desc *how,
                               hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    int rc = fit(g, w, h, format_of(how), err);
    if (rc)
        return rc;
    /* Black in both encodings: sRGB(0) = 0; alpha 1 as the pass writes. */
    gl->BindFramebuffer(GL_FRAMEBUFFER, g->lit.fbo);
    const GLfloat black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    gl->ClearBufferfv(GL_COLOR, 0, black);
    /* The planner still keeps the lit frame's targets; the texture no
     * longer holds their encoding. */
    hfs_plan_drop(&g->plan.p, g->plan.pr_lit);
    return hfs_gl_check(gl, "lit texture: black", err);
}

int hfs_gles_lit_texture_hand_out(hfs_gles *g, hfs_lit_texture *out, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    hfs_gles_lit_texture *t = &g->lit;
    if (t->fence)
        gl->DeleteSync(t->fence);
    t->fence = gl->FenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    /* A fence another context waits on must reach the GPU: flush. */
    gl->Flush();
    int rc = hfs_gl_check(gl, "lit texture: fence", err);
    if (rc || !t->fence)
        return rc ? rc : hfs_fail(err, HFS_E_GL, "lit texture: glFenceSync returned 0");
    *out = (hfs_lit_texture){.texture = t->tex, .internal_format = t->format, .width = t->w,
                             .height = t->h, .fence = (void *)t->fence};
    return HFS_OK;
}

const hfs_gles_pass hfs_pass_lit_texture = {
    .id = HFS_PASS_LIT_TEXTURE,
    .plan_name = "lit texture",
    .scope = HFS_SCOPE_FRAME,
    /* And the bounced targets when the frame has bounces (plan.c). */
    .reads = {"output targets", "bounce settings", "lit texture settings"},
    .writes = {"lit texture"},
    .stages = {"littexture"},
    .present = present,
    .layout = layout,
    .run = run,
};
