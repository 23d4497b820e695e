/*
 * pass_env_horizons.c — the environment's visibility on the sub-sampled
 * grid (env_horizons.frag): per receiver the horizon in each direction of
 * the full swath (q->nphi_env), projected to order-4 SH (folded Legendre
 * matrices, or wedge tables on the table path), written as 4 RGBA targets
 * (DESIGN.md "Horizons", "GLES path"); on the slice path the horizons
 * themselves (as tan(x/2)), 16 directions a draw into the grid's horizon
 * array, for env_slices.frag (pass_env_transfer.c).  With split horizons
 * the grid's search stops at far-from and a second stage, "far", fills the
 * far grid (env_far_grid.c).  Kept with the terrain while the environment's
 * settings do not change: a turned or re-tinted environment does not rerun
 * it.
 */
#include "gles_backend.h"

#include "gl_util.h"
#include "pyramid_layout.h"

/* Slice path: horizons a layer (an RGBA texel): 4, or 2 occluders as
 * (height, distance) pairs (hor_pairs). */
#define SLICE_DIRS_PER_LAYER(pairs) ((pairs) ? 2 : 4)

static int present(const hfs_gles_frame *fr)
{
    return fr->has_env;
}

/* "far": split horizons only. */
static int stage_present(const hfs_gles_frame *fr, int s)
{
    return s == 0 || fr->split.on;
}

/* HfsSwath: the Legendre/wedge swath, or the slices' (uniform_blocks.h). */
static size_t block_vec4(const hfs_gles_frame *fr)
{
    return fr->slice ? hfs_gles_slices_vec4(fr->q->nphi_env)
                     : hfs_gles_swath_vec4(fr->q->nphi_env);
}

/* The swath's block, or (too large for the profile's blocks) its texture. */
static int layout_grid(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err)
{
    const size_t n4 = block_vec4(fr);
    int rc;
    fr->hor_layers = 0;
    fr->env_near = 0;
    fr->hor_pairs = 0;
    if (fr->slice) {
        /* On a sub-sampled grid each horizon comes with its occluder's
         * distance, which moves it to each texel's height (env_slices.frag). */
        fr->hor_pairs = fr->L.sub > 1;
        /* As few draws as the context's targets allow, each no wider
         * than the directions need (a wider one costs its fragments). */
        const int layers = (fr->q->nphi_env + SLICE_DIRS_PER_LAYER(fr->hor_pairs) - 1) /
                           SLICE_DIRS_PER_LAYER(fr->hor_pairs);
        /* Up to HFS_GLES_MAX_OUTS targets a draw where the context has
         * them (ES 3.0 guarantees 4): 12 directions as pairs fill 6. */
        const int max_outs = g->caps.max_draw_buffers < HFS_GLES_MAX_OUTS
                                 ? g->caps.max_draw_buffers : HFS_GLES_MAX_OUTS;
        const int draws = (layers + max_outs - 1) / max_outs;
        fr->hor_outs = (layers + draws - 1) / draws;
        const int per = fr->hor_outs * SLICE_DIRS_PER_LAYER(fr->hor_pairs);
        const int groups = (fr->q->nphi_env + per - 1) / per;
        fr->hor_layers = groups * fr->hor_outs;
        /* The texel's own cell (holding the finest scale, distance 1) is
         * searched at each texel, not at the grid (env_slices.frag says
         * why; BENCHMARKS.md, "Exact slice lighting"). */
        fr->env_near = 1;
        if ((rc = hfs_gl_caps_check_texture(&g->caps, fr->L.vw, fr->L.vh, fr->hor_layers,
                                            "environment horizons (--nphi-env)", err)))
            return rc;
    }
    fr->env_swath_tex = hfs_gles_block_too_big(&g->caps, n4);
    return fr->env_swath_tex
               ? hfs_gles_block_texture_check(&g->caps, n4, "environment swath (--nphi-env)", err)
               : hfs_gl_caps_check_uniform_block(&g->caps, n4 * 16,
                                                 "environment swath (--nphi-env)", err);
}

/* The grid's and the far grid's (split horizons) sizes and limits. */
static int layout(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err)
{
    int rc = layout_grid(g, fr, err);
    return rc ? rc : hfs_gles_env_far_layout(g, fr, err);
}

/* The swath's visibility object (kept while nphi_env holds), its block and
 * tables when the pass runs. */
static int prepare(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err)
{
    const hfs_quality *q = fr->q;
    int rc;
    if (!g->env_vis || g->env_vis_n != q->nphi_env) {
        hfs_visibility_destroy(g->env_vis);
        g->env_vis = NULL;
        hfs_swath s;
        hfs_swath_full(q->nphi_env, &s);
        if ((rc = hfs_visibility_create(&s, HFS_VIS_LEGENDRE, &g->env_vis, err)))
            return rc;
        g->env_vis_n = q->nphi_env;
    }
    g->stats.offset_mismatches += hfs_gles_offset_mismatches(&fr->L, hfs_visibility_swath(g->env_vis));
    if (!fr->run[HFS_PASS_ENV_HORIZONS][0])
        return HFS_OK;
    const size_t bytes = block_vec4(fr) * 16;
    if (fr->slice && g->env_slices_n != q->nphi_env) {
        hfs_slice_table_free(&g->env_slices);
        g->env_slices_n = 0;
        if ((rc = hfs_slice_table_init(&g->env_slices, hfs_visibility_swath(g->env_vis), err)))
            return rc;
        g->env_slices_n = q->nphi_env;
    }
    float *sw = hfs_gles_scratch(g, 2 * bytes); /* the block, then its texels */
    if (!sw)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory");
    if (fr->slice)
        hfs_gles_pack_slices(&fr->L, g->env_vis, &g->env_slices, sw);
    else
        hfs_gles_pack_swath(&fr->L, g->env_vis, sw);
    if (fr->env_swath_tex) {
        if ((rc = hfs_gles_block_texture_upload(&g->env_swath_tex, &g->gl, &g->caps, sw,
                                                bytes / 16, (char *)sw + bytes,
                                                "environment swath (--nphi-env)", err)))
            return rc;
    } else {
        hfs_gles_ubo_upload(&g->gl, g->ubo[HFS_UBO_ENV_SWATH], sw, bytes);
    }
    if ((rc = hfs_gles_env_far_prepare(g, fr, err)))
        return rc;
    if (!fr->tables)
        return HFS_OK;
    void *scratch = hfs_gles_scratch(g, hfs_gles_wedge_scratch_bytes());
    if (!scratch)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for wedge tables");
    return hfs_gles_wedge_env(&g->wedge, &g->gl, &g->caps, hfs_visibility_swath(g->env_vis)->dphi,
                              scratch, err);
}

int hfs_gles_bind_env_swath(hfs_gles *g, const hfs_gles_frame *fr, const hfs_gles_program *prog,
                            hfs_error *err)
{
    if (fr->env_swath_tex)
        return hfs_gles_program_texture(&g->gl, prog, "u_swath_tex", GL_TEXTURE_2D,
                                        g->env_swath_tex.tex, err);
    g->gl.BindBufferBase(GL_UNIFORM_BUFFER, HFS_BLOCK_SWATH, g->ubo[HFS_UBO_ENV_SWATH]);
    return HFS_OK;
}

/* The pass (fetch_sum: its counting twin, the fetches added there) into
 * the visibility targets, or the slice path's horizon layers. */
static int draw(hfs_gles *g, const hfs_gles_frame *fr, double *fetch_sum, hfs_error *err)
{
    const int count = fetch_sum != NULL;
    const hfs_gl *gl = &g->gl;
    const hfs_gles_layout *L = &fr->L;
    const hfs_gles_variant v = {.n_layers = L->n_layers,
                                .n_dir = g->env_vis_n, .tables = fr->tables,
                                .fp32 = g->caps.fp32, .count = count,
                                .swath_tex = fr->env_swath_tex, .slice = fr->slice,
                                .pairs = fr->hor_pairs, .n_out = fr->slice ? fr->hor_outs : 0};
    const hfs_gles_program *prog;
    int rc = hfs_gles_program_use(&g->programs, gl, HFS_PROG_ENV_HORIZONS, &v, &prog, err);
    if (rc || (rc = hfs_gles_bind_grid_inputs(g, prog, L, err)))
        return rc;
    if (fr->tables &&
        (rc = hfs_gles_program_texture(gl, prog, "u_tab", GL_TEXTURE_2D_ARRAY, g->wedge.env, err)))
        return rc;
    /* A hair above the largest height: rounding in the pyramid's hi+lo
     * pairs and the bilinear filter must never make the bound too tight. */
    hfs_gles_set_f1(gl, prog, "u_vmax", (float)(L->vmax + 1e-5));
    hfs_gles_set_i1(gl, prog, "u_refine", fr->split.on ? fr->split.near_refine : fr->q->refine);
    hfs_gles_set_f1(gl, prog, "u_lk", (float)L->k);
    hfs_gles_set_f1(gl, prog, "u_tie", (float)hfs_horizon_tie_slope(L->hscale, L->zscale, L->dx));
    if ((rc = hfs_gles_bind_env_swath(g, fr, prog, err)))
        return rc;
    if (!fr->slice) {
        hfs_gles_draw(gl, g->r.venv_fbo, L->vw, L->vh);
        if (fetch_sum)
            rc = hfs_gles_sum_counts(g, L, g->r.venv_fbo, fetch_sum, err);
    }
    if (fr->slice)
        hfs_gles_set_i1(gl, prog, "u_near", fr->env_near);
    hfs_gles_set_i1(gl, prog, "u_coarsest", fr->env_coarsest); /* split horizons' near part */
    const int per_layer = SLICE_DIRS_PER_LAYER(fr->hor_pairs), per = fr->hor_outs * per_layer;
    for (int d0 = 0; fr->slice && !rc && d0 < g->env_vis_n; d0 += per) {
        hfs_gles_set_i1(gl, prog, "u_dir0", d0);
        rc = hfs_gles_draw_grid_layers(g, L, g->r.hor_fbo, g->r.hor, d0 / per_layer,
                                       fr->hor_outs, "environment horizons",
                                       fr->edit && !count ? &g->edit.env : NULL, fetch_sum, err);
    }
    /* hfs_gles_fbo_layers resets the first 4 attachments only: leave none
     * past them behind for a later frame that fills fewer. */
    if (fr->slice && fr->hor_outs > 4) {
        gl->BindFramebuffer(GL_FRAMEBUFFER, g->r.hor_fbo);
        for (int o = 4; o < fr->hor_outs; ++o)
            gl->FramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + (GLenum)o, 0, 0, 0);
    }
    gl->UseProgram(0);
    return rc ? rc : hfs_gl_check(gl, "backend gles: env pass", err);
}

static int run(hfs_gles *g, hfs_gles_frame *fr, const int *which, hfs_error *err)
{
    (void)which;
    hfs_gles_stage_begin(g, HFS_PASS_ENV_HORIZONS, 0);
    int rc = draw(g, fr, NULL, err);
    hfs_gles_stage_end(g, HFS_PASS_ENV_HORIZONS, 0);
    if (!rc && fr->split.on) {
        /* After an edit the far grid is drawn whole (its searches reach the
         * field's end) and compared with what it held: only the texels
         * around the receivers that changed take the new pairs. */
        hfs_gles_stage_begin(g, HFS_PASS_ENV_HORIZONS, 1);
        if (fr->edit)
            rc = hfs_gles_edit_far_before(g, fr, err);
        if (!rc)
            rc = hfs_gles_env_far_draw(g, fr, NULL, err);
        if (!rc && fr->edit)
            rc = hfs_gles_edit_far_after(g, fr, err);
        hfs_gles_stage_end(g, HFS_PASS_ENV_HORIZONS, 1);
    }
    if (!rc)
        g->stats.env_recomputed = 1;
    return rc;
}

static int count(hfs_gles *g, hfs_gles_frame *fr, double *fetches, hfs_error *err)
{
    int rc = draw(g, fr, &fetches[0], err);
    return rc || !fr->split.on ? rc : hfs_gles_env_far_draw(g, fr, &fetches[1], err);
}

const hfs_gles_pass hfs_pass_env_horizons = {
    .id = HFS_PASS_ENV_HORIZONS,
    .plan_name = "env",
    .scope = HFS_SCOPE_FRAME,
    .deferrable = 1,
    .reads = {"pyramid", "subsample", "env settings"},
    .writes = {"env visibility"},
    .stages = {"env", "far"},
    .present = present,
    .stage_present = stage_present,
    .layout = layout,
    .prepare = prepare,
    .run = run,
    .count = count,
};
