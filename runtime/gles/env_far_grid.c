/*
 * env_far_grid.c — split horizons' far part on the GLES path
 * (split_horizon.h; DESIGN.md "Split horizons"): a stage of the
 * environment's horizon pass (pass_env_horizons.c), which also stops its
 * near search at far-from.  env_horizons.frag's far pass (HFS_FAR_ATLAS)
 * runs on the far grid (step split.step): for each of the K x nphi_env
 * sub-directions the occluder beyond the near scales, as a (height,
 * distance) pair, 2 a texel, in an atlas of tiles drawn at once;
 * env_slices.frag blends and moves them per texel (hfs_gles_bind_env_far).
 * The CPU reference computes the same pairs (cpu_far_grid.c).
 */
#include "gles_backend.h"

#include "gl_util.h"
#include "pyramid_layout.h"

#include <math.h>
#include <stdio.h>

static int n_sub(const hfs_gles_frame *fr)
{
    return fr->q->nphi_env * fr->split.k;
}

int hfs_gles_env_far_layout(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err)
{
    const hfs_gles_layout *L = &fr->L;
    hfs_split_make(fr->q, &fr->split);
    fr->env_coarsest = 0;
    fr->far_near = fr->far_w = fr->far_h = fr->far_cols = fr->far_aw = fr->far_ah = 0;
    fr->far_swath_tex = 0;
    if (!fr->split.on)
        return HFS_OK;
    const int first_far = hfs_split_first_far(L->n_levels, L->k, fr->split.from);
    fr->far_near = L->n_levels - 1 - first_far;
    fr->env_coarsest = first_far + 1;
    fr->far_w = hfs_grid_count(L->w, fr->split.step);
    fr->far_h = hfs_grid_count(L->h, fr->split.step);
    /* Tiles of 2 sub-directions, as many a row as the profile's textures
     * hold. */
    const int tiles = (n_sub(fr) + 1) / 2;
    int cols = g->caps.max_texture_size / fr->far_w;
    cols = cols < 1 ? 1 : (cols > tiles ? tiles : cols);
    fr->far_cols = cols;
    fr->far_aw = cols * fr->far_w;
    fr->far_ah = (tiles + cols - 1) / cols * fr->far_h;
    int rc = hfs_gl_caps_check_texture(&g->caps, fr->far_aw, fr->far_ah, 1,
                                       "far horizons (--far-dirs, --far-step)", err);
    if (rc)
        return rc;
    const size_t n4 = hfs_gles_slices_vec4(n_sub(fr));
    fr->far_swath_tex = hfs_gles_block_too_big(&g->caps, n4);
    return fr->far_swath_tex
               ? hfs_gles_block_texture_check(&g->caps, n4, "far directions (--far-dirs)", err)
               : hfs_gl_caps_check_uniform_block(&g->caps, n4 * 16, "far directions (--far-dirs)",
                                                 err);
}

int hfs_gles_env_far_prepare(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err)
{
    if (!fr->split.on)
        return HFS_OK;
    hfs_swath sub;
    hfs_split_swath(hfs_visibility_swath(g->env_vis), fr->split.k, &sub);
    const size_t bytes = hfs_gles_slices_vec4(sub.n) * 16;
    float *blk = hfs_gles_scratch(g, 2 * bytes); /* the block, then its texels */
    if (!blk)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory");
    hfs_gles_pack_dirs(&fr->L, &sub, blk);
    if (fr->far_swath_tex)
        return hfs_gles_block_texture_upload(&g->far_swath_tex, &g->gl, &g->caps, blk, bytes / 16,
                                             (char *)blk + bytes, "far directions (--far-dirs)",
                                             err);
    hfs_gles_ubo_upload(&g->gl, g->ubo[HFS_UBO_FAR_SWATH], blk, bytes);
    return HFS_OK;
}

int hfs_gles_env_far_draw(hfs_gles *g, const hfs_gles_frame *fr, double *fetch_sum,
                          hfs_error *err)
{
    if (!fr->split.on)
        return HFS_OK;
    const hfs_gl *gl = &g->gl;
    const hfs_gles_layout *L = &fr->L;
    const hfs_gles_variant v = {.n_layers = L->n_layers,
                                .n_dir = n_sub(fr), .fp32 = g->caps.fp32,
                                .swath_tex = fr->far_swath_tex, .slice = 1,
                                .n_out = fr->split.heights, /* a layer each */
                                .far_atlas = 1, .count = fetch_sum != NULL};
    const hfs_gles_program *prog;
    int rc = hfs_gles_program_use(&g->programs, gl, HFS_PROG_ENV_HORIZONS, &v, &prog, err);
    if (rc || (rc = hfs_gles_bind_grid_inputs(g, prog, L, err)) ||
        (rc = hfs_gles_bind_bounds(g, prog, L, (float)fr->split.from, err)))
        return rc;
    hfs_gles_set_i1(gl, prog, "u_sub", fr->split.step); /* receivers on the far grid */
    hfs_gles_set_i2(gl, prog, "u_fgrid", fr->far_w, fr->far_h);
    hfs_gles_set_i1(gl, prog, "u_fcols", fr->far_cols);
    hfs_gles_set_f1(gl, prog, "u_vmax", (float)(L->vmax + 1e-5));
    hfs_gles_set_i1(gl, prog, "u_refine", fr->split.far_refine);
    hfs_gles_set_f1(gl, prog, "u_lk", (float)L->k);
    hfs_gles_set_f1(gl, prog, "u_tie", (float)hfs_horizon_tie_slope(L->hscale, L->zscale, L->dx));
    hfs_gles_set_i1(gl, prog, "u_near", fr->far_near);
    hfs_gles_set_i1(gl, prog, "u_coarsest", 0);
    /* after an edit, only the receivers whose search can end differently
     * (the counting twin counts them all) */
    if (fetch_sum)
        hfs_gles_set_i1(gl, prog, "u_edit", 0);
    else
        hfs_gles_edit_far_uniforms(g, fr, prog);
    if (fr->far_swath_tex)
        rc = hfs_gles_program_texture(gl, prog, "u_swath_tex", GL_TEXTURE_2D,
                                      g->far_swath_tex.tex, err);
    else
        gl->BindBufferBase(GL_UNIFORM_BUFFER, HFS_BLOCK_SWATH, g->ubo[HFS_UBO_FAR_SWATH]);
    if (!rc && !(rc = hfs_gles_fbo_layers(gl, g->r.far_fbo, g->r.far, 0, fr->split.heights,
                                                    "far horizons", err)))
        hfs_gles_draw(gl, g->r.far_fbo, fr->far_aw, fr->far_ah);
    if (!rc && fetch_sum)
        rc = hfs_gles_sum_counts_rect(g, g->r.far_fbo, fr->far_aw, fr->far_ah, fetch_sum, err);
    gl->UseProgram(0);
    return rc ? rc : hfs_gl_check(gl, "backend gles: far horizon pass", err);
}

int hfs_gles_bind_env_far(hfs_gles *g, const hfs_gles_frame *fr, const hfs_gles_program *prog,
                          hfs_error *err)
{
    if (!fr->split.on)
        return HFS_OK;
    const hfs_gl *gl = &g->gl;
    int rc = hfs_gles_program_texture(gl, prog, "u_far", GL_TEXTURE_2D_ARRAY, g->r.far, err);
    hfs_gles_set_i2(gl, prog, "u_fsize", fr->far_w, fr->far_h);
    hfs_gles_set_i1(gl, prog, "u_fstep", fr->split.step);
    hfs_gles_set_i1(gl, prog, "u_fcols", fr->far_cols);
    hfs_gles_set_f2(gl, prog, "u_fatlas", (float)fr->far_aw, (float)fr->far_ah);
    /* the sub-directions' turns from their direction */
    const double dphi = hfs_visibility_swath(g->env_vis)->dphi;
    for (int h = 0; h < fr->split.k; ++h) {
        char name[24];
        const double delta = hfs_split_turn(h, fr->split.k, dphi);
        snprintf(name, sizeof name, "u_fsub[%d]", h);
        hfs_gles_set_f2(gl, prog, name, (float)cos(delta), (float)sin(delta));
    }
    return rc;
}
