/*
 * pass_env_transfer.c — the environment's transfer vectors at full
 * resolution: per texel the occluded part of T = H(N) * V_env, the SH
 * product of its clamped cosine and the grid's visibility interpolated to
 * it (env_transfer.frag); on the slice path the exact slice integrals above
 * the grid's horizons and the texel's own near ones (env_slices.frag).
 * Independent of the environment's radiance and rotation: a turned or
 * re-tinted sky costs the shading's dot products only.
 */
#include "gles_backend.h"

#include "gl_util.h"

#include <math.h>
#include <stdio.h>

static int present(const hfs_gles_frame *fr)
{
    return fr->has_env;
}

int hfs_gles_draw_env_slices(hfs_gles *g, hfs_gles_frame *fr, hfs_gles_slices_out what,
                             GLuint fbo, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    const hfs_gles_layout *L = &fr->L;
    const int env_map = what == HFS_SLICES_MAP;
    const hfs_gles_variant v = {.n_dir = g->env_vis_n,
                                .fp32 = g->caps.fp32, .swath_tex = fr->env_swath_tex,
                                .env_map = env_map, .env_dot = what == HFS_SLICES_SKY,
                                .pairs = fr->hor_pairs,
                                .far_k = fr->split.on ? fr->split.k : 0,
                                .far_h = fr->split.on ? fr->split.heights : 0};
    const hfs_gles_program *prog;
    int rc = hfs_gles_program_use(&g->programs, gl, HFS_PROG_ENV_SLICES, &v, &prog, err);
    if (rc || (rc = hfs_gles_bind_grid_inputs(g, prog, L, err)) ||
        (rc = hfs_gles_program_texture(gl, prog, "u_hor", GL_TEXTURE_2D_ARRAY, g->r.hor, err)) ||
        (rc = hfs_gles_bind_env_swath(g, fr, prog, err)) ||
        (rc = hfs_gles_bind_env_far(g, fr, prog, err)))
        return rc;
    if (env_map && (rc = hfs_gles_program_texture(gl, prog, "u_mslices", GL_TEXTURE_2D,
                                                  g->envmap.slices, err)))
        return rc;
    if (what == HFS_SLICES_SKY) { /* the same weights as the shading's (uniform_blocks.h) */
        float envo[3][16];
        double m[3];
        hfs_gles_env_occ_weights(fr->l_env, envo, m);
        const GLint loc = gl->GetUniformLocation(prog->name, "u_envo");
        if (loc < 0)
            return hfs_fail(err, HFS_E_GL, "backend gles: sky occlusion: no u_envo");
        gl->Uniform4fv(loc, 12, &envo[0][0]);
    }
    hfs_gles_set_i2(gl, prog, "u_vsize", L->vw, L->vh);
    hfs_gles_set_i1(gl, prog, "u_near", fr->env_near);
    hfs_gles_edit_draw(g, fbo, L->w, L->h, 1, fr->edit ? hfs_gles_edit_transfer(g, fr) : NULL);
    gl->UseProgram(0);
    static const char *const pass_name[] = {"backend gles: slice transfer pass",
                                            "backend gles: map occlusion pass",
                                            "backend gles: sky occlusion pass"};
    return hfs_gl_check(gl, pass_name[what], err);
}

double hfs_gles_env_slices_fetches(const hfs_gles *g, const hfs_gles_frame *fr)
{
    /* Per texel: the normal's 4 heights, or with the near scale the 3 x 3
     * heights about it, which hold the normal's 4 (env_slices.frag
     * near_slopes); a horizon layer per 4 directions; split horizons: a
     * far texel per 2 sub-directions and height (split_horizon.h) and the 4
     * far receivers' heights. */
    const double per_layer = fr->hor_pairs ? 2.0 : 4.0;
    const double far_texels = ceil(g->env_vis_n * fr->split.k / 2.0) * fr->split.heights;
    const double far = fr->split.on ? far_texels + 4.0 : 0.0;
    return (fr->env_near ? 9.0 : 4.0) + ceil(g->env_vis_n / per_layer) + far;
}

/* The slice path: env_slices.frag from the grid's horizons. */
static int run_slices(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err)
{
    const hfs_gles_layout *L = &fr->L;
    hfs_gles_stage_fetches(g, HFS_PASS_ENV_TRANSFER, 0,
                           (double)L->w * L->h * hfs_gles_env_slices_fetches(g, fr));
    return hfs_gles_draw_env_slices(g, fr, HFS_SLICES_TRANSFER, g->r.transfer_fbo, err);
}

static int run(hfs_gles *g, hfs_gles_frame *fr, const int *which, hfs_error *err)
{
    (void)which;
    int rc0 = hfs_gles_transfer_ensure(&g->r, &g->gl, &g->caps, err);
    if (rc0)
        return rc0;
    if (fr->edit) /* the region, into the shading's (all off the slice path) */
        hfs_gles_edit_transfer(g, fr);
    if (fr->slice)
        return run_slices(g, fr, err);
    const hfs_gl *gl = &g->gl;
    const hfs_gles_layout *L = &fr->L;
    const hfs_gles_variant v = {.fp32 = g->caps.fp32};
    const hfs_gles_program *prog;
    int rc = hfs_gles_program_use(&g->programs, gl, HFS_PROG_ENV_TRANSFER, &v, &prog, err);
    if (rc ||
        (rc = hfs_gles_bind_normals(g, prog, L, err)))
        return rc;
    for (int i = 0; i < 4; ++i) {
        char name[16]; /* room for any int, as the optimiser checks */
        snprintf(name, sizeof name, "u_v%d", i);
        if ((rc = hfs_gles_program_texture(gl, prog, name, GL_TEXTURE_2D, g->r.venv[i], err)))
            return rc;
    }
    hfs_gles_set_i2(gl, prog, "u_size", L->w, L->h);
    hfs_gles_set_i2(gl, prog, "u_vsize", L->vw, L->vh);
    hfs_gles_set_i1(gl, prog, "u_sub", L->sub);
    hfs_gles_draw(gl, g->r.transfer_fbo, L->w, L->h);
    gl->UseProgram(0);
    hfs_gles_stage_fetches(g, HFS_PASS_ENV_TRANSFER, 0, (double)L->w * L->h * 8);
    return hfs_gl_check(gl, "backend gles: transfer pass", err);
}

const hfs_gles_pass hfs_pass_env_transfer = {
    .id = HFS_PASS_ENV_TRANSFER,
    .plan_name = "transfer",
    .scope = HFS_SCOPE_FRAME,
    .reads = {"pyramid", "env visibility"},
    .writes = {"env transfer"},
    .stages = {"transfer"},
    .present = present,
    .run = run,
};
