/*
 * pass_common.c — what the passes share: scratch memory, the lit targets,
 * timing by stage, the grid passes' inputs and layered draws.  Its own file
 * (not gles_frame.c, which runs the passes) so that the passes depend on it
 * and the frame on the passes, never the reverse.
 */
#include "gles_backend.h"

#include "gl_util.h"

#include <stdlib.h>

void *hfs_gles_scratch(hfs_gles *g, size_t bytes)
{
    if (bytes > g->scratch_cap) {
        char *p = realloc(g->scratch, bytes);
        if (!p)
            return NULL;
        g->scratch = p;
        g->scratch_cap = bytes;
    }
    return g->scratch;
}

void hfs_gles_lit_targets(const hfs_gles *g, const hfs_gles_frame *fr, GLuint tex[2])
{
    const GLuint *t = fr->bounces > 0 ? g->bounce.fin : g->r.out;
    tex[0] = t[0], tex[1] = t[1];
}

void hfs_gles_stage_begin(hfs_gles *g, hfs_gles_pass_id p, int stage)
{
    hfs_gles_timing_begin(&g->timing, &g->gl, g->stage_slot[p] + stage);
}

void hfs_gles_stage_end(hfs_gles *g, hfs_gles_pass_id p, int stage)
{
    hfs_gles_timing_end(&g->timing, &g->gl, g->stage_slot[p] + stage);
}

void hfs_gles_stage_fetches(hfs_gles *g, hfs_gles_pass_id p, int stage, double fetches)
{
    g->timing.fetch[g->stage_slot[p] + stage] += fetches;
}

int hfs_gles_select_caps(hfs_gles *g, const hfs_quality *q, hfs_error *err)
{
    const int rc = hfs_gl_context_make_current(g->ctx, err);
    return rc ? rc : hfs_gl_caps_select(&g->driver, g->profile[0] ? g->profile : NULL,
                                        q->precision == HFS_PRECISION_FP32, g->strict_limits,
                                        &g->caps, err);
}

int hfs_gles_begin_outside(hfs_gles *g, const hfs_field *f, const hfs_quality *q,
                           hfs_gles_layout *L, const char *what, hfs_error *err)
{
    int rc = hfs_gles_select_caps(g, q, err);
    if (rc || (rc = hfs_gles_layout_init(L, f, q, err)))
        return rc;
    return hfs_gl_caps_check_texture(&g->caps, L->w, L->h, 1, what, err);
}

/* u_zf: a normalized height difference a texel apart as a world slope,
 * hscale zscale / dx, clamped to 1e30 (the normals and the gap search);
 * u_hunit: the unit of the grids' occluder heights (gles_lib.frag
 * hfs_far_slope). */
static void set_slope_factor(const hfs_gl *gl, const hfs_gles_program *prog,
                             const hfs_gles_layout *L)
{
    const double zf = L->hscale * L->zscale / L->dx;
    hfs_gles_set_f1(gl, prog, "u_zf", (float)(zf < 1e30 ? zf : 1e30));
    hfs_gles_set_f1(gl, prog, "u_hunit", (float)L->hunit);
}

int hfs_gles_bind_normals(hfs_gles *g, const hfs_gles_program *prog, const hfs_gles_layout *L,
                          hfs_error *err)
{
    const int rc = hfs_gles_program_texture(&g->gl, prog, "u_height", GL_TEXTURE_2D_ARRAY,
                                             g->r.arr, err);
    if (!rc) {
        hfs_gles_set_i1(&g->gl, prog, "u_hlayer", L->n_layers - 1);
        set_slope_factor(&g->gl, prog, L);
    }
    return rc;
}

int hfs_gles_bind_grid_inputs(hfs_gles *g, const hfs_gles_program *prog,
                              const hfs_gles_layout *L, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    int rc;
    if ((rc = hfs_gles_program_texture(gl, prog, "u_levels", GL_TEXTURE_2D_ARRAY, g->r.arr, err)) ||
        (rc = hfs_gles_bind_normals(g, prog, L, err)))
        return rc;
    hfs_gles_set_i2(gl, prog, "u_size", L->w, L->h);
    hfs_gles_set_i1(gl, prog, "u_sub", L->sub);
    gl->BindBufferBase(GL_UNIFORM_BUFFER, HFS_BLOCK_SCALES, g->ubo[HFS_UBO_SCALES]);
    return HFS_OK;
}

int hfs_gles_bind_ray(const hfs_gl *gl, const hfs_gles_program *prog, const hfs_gles_layout *L,
                      GLuint heights, int layer, GLuint bounds, hfs_error *err)
{
    int rc;
    if ((rc = hfs_gles_program_texture(gl, prog, "u_height", GL_TEXTURE_2D_ARRAY, heights, err)) ||
        (rc = hfs_gles_program_texture(gl, prog, "u_bounds", GL_TEXTURE_2D, bounds, err)))
        return rc;
    GLint at[2 * HFS_RAY_BOUND_MAX_LEVELS] = {0};
    for (int l = 1; l < L->rb.n_levels; ++l)
        at[2 * l] = L->rb.x0[l], at[2 * l + 1] = L->rb.y0[l];
    const GLint loc = gl->GetUniformLocation(prog->name, "u_rb_at");
    if (loc >= 0)
        gl->Uniform2iv(loc, HFS_RAY_BOUND_MAX_LEVELS, at);
    hfs_gles_set_i1(gl, prog, "u_hlayer", layer);
    set_slope_factor(gl, prog, L);
    return HFS_OK;
}

int hfs_gles_bind_bounds(hfs_gles *g, const hfs_gles_program *prog, const hfs_gles_layout *L,
                         float gap_from, hfs_error *err)
{
    const int rc = hfs_gles_bind_ray(&g->gl, prog, L, g->r.arr, L->n_layers - 1, g->r.bounds,
                                     err);
    if (!rc)
        hfs_gles_set_f1(&g->gl, prog, "u_gap_from", gap_from);
    return rc;
}

int hfs_gles_sum_counts_rect(hfs_gles *g, GLuint fbo, int w, int h, double *sum, hfs_error *err)
{
    float *px = hfs_gles_scratch(g, (size_t)w * h * 4 * sizeof(float));
    if (!px)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory");
    int rc = hfs_gl_read_rgba(&g->gl, fbo, 0, 0, w, h, HFS_GL_READ_AUTO, px, NULL, err);
    if (rc)
        return rc;
    for (size_t i = 0; i < (size_t)w * h; ++i)
        *sum += px[4 * i] + 1024.0 * px[4 * i + 1];
    return HFS_OK;
}

int hfs_gles_sum_counts(hfs_gles *g, const hfs_gles_layout *L, GLuint fbo, double *sum,
                        hfs_error *err)
{
    return hfs_gles_sum_counts_rect(g, fbo, L->vw, L->vh, sum, err);
}

int hfs_gles_draw_grid_layers(hfs_gles *g, const hfs_gles_layout *L, GLuint fbo, GLuint tex,
                              int layer0, int outs, const char *what, const hfs_tiles *region,
                              double *fetch_sum, hfs_error *err)
{
    int rc = hfs_gles_fbo_layers(&g->gl, fbo, tex, layer0, outs, what, err);
    if (rc)
        return rc;
    hfs_gles_edit_draw(g, fbo, L->vw, L->vh, L->sub, region);
    return fetch_sum ? hfs_gles_sum_counts(g, L, fbo, fetch_sum, err) : HFS_OK;
}
