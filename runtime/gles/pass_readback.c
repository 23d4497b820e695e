/*
 * pass_readback.c — the lit targets (hi, lo: hfs_gles_lit_targets) read back, summed in
 * double, the output scale divided out (pass_shade.c), into the caller's
 * image; the image is also kept, handed out again while nothing changes.
 */
#include "gles_backend.h"

#include "gl_util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int run(hfs_gles *g, hfs_gles_frame *fr, const int *which, hfs_error *err)
{
    (void)which;
    const hfs_gl *gl = &g->gl;
    const hfs_gles_layout *L = &fr->L;
    const size_t npx = (size_t)L->w * L->h, n_img = npx * 3;
    float *px = hfs_gles_scratch(g, npx * 8 * sizeof(float));
    if (!px)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for the readback");
    float *lo = px + npx * 4;
    /* The lit result (hfs_gles_lit_targets): hi, then lo alone. */
    const GLuint hi_fbo = fr->bounces > 0 ? g->bounce.fin_fbo : g->r.out_fbo;
    const GLuint lo_fbo = fr->bounces > 0 ? g->bounce.fin_lo_fbo : g->r.out_lo_fbo;
    int rc;
    if ((rc = hfs_gl_read_rgba(gl, hi_fbo, 0, 0, L->w, L->h, HFS_GL_READ_AUTO, px, NULL, err)) ||
        (rc = hfs_gl_read_rgba(gl, lo_fbo, 0, 0, L->w, L->h, HFS_GL_READ_AUTO, lo, NULL, err)))
        return rc;
    const double inv = 1.0 / fr->out_scale;
    float *rgb = fr->out->rgb;
    for (size_t i = 0; i < npx; ++i)
        for (int c = 0; c < 3; ++c) {
            const double v = ((double)px[4 * i + (size_t)c] + lo[4 * i + (size_t)c]) * inv;
            rgb[3 * i + (size_t)c] = isfinite(v) ? (float)v : 0.0f;
        }
    if (g->last_img_cap < n_img) {
        float *k = realloc(g->last_img, n_img * sizeof *k);
        if (!k)
            return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for the kept image");
        g->last_img = k;
        g->last_img_cap = n_img;
    }
    memcpy(g->last_img, rgb, n_img * sizeof *rgb);
    return HFS_OK;
}

const hfs_gles_pass hfs_pass_readback = {
    .id = HFS_PASS_READBACK,
    .plan_name = "readback",
    .scope = HFS_SCOPE_FRAME,
    /* And the bounced targets when the frame has bounces (plan.c). */
    .reads = {"output targets", "bounce settings"},
    .writes = {"image"},
    .stages = {"readback"},
    .run = run,
};
