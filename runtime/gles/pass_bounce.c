/*
 * pass_bounce.c — indirect diffuse bounces on the GLES path (issue 16;
 * the CPU reference's walk, cpu_bounce.h; DESIGN.md "Indirect light"):
 * per bounce b, the radiance it gathers (the shading pass's output, or
 * rho E_{b-1}) into a full-resolution texture (bounce_light.frag), then
 * the walk on the bounce grid (every fr->bsub texels, quality
 * bounce_subsample) into E_b and the receivers' occluded part
 * (bounce_gather.frag); last, direct + rho sum E_b into the frame's final
 * targets, which the read-back and the view take (hfs_gles_lit_targets).
 * Each bounce's E stays on the grid, interpolated at each texel like the
 * local lights' ratios, scaled to the texel's own occluded part (slice
 * path) and multiplied by its own albedo.  A glossy surface's receivers
 * also weigh each band by the lobe about their R (G_b beside E_b, added
 * after the albedo).  With split horizons the bands are clipped to each
 * sub-horizon (the far grid's occluders, hfs_gles_bind_env_far), so that
 * the direct light stays the frame's without bounces (issue 36).
 * On a sub-sampled bounce grid under an environment (not glossy) the
 * gather's near part, the own cell and the scales within bounce_near
 * texels (quality; 0: none), is gathered at every texel instead
 * (bounce_gather.frag HFS_NEAR, before the grid's walk; issue 36): on
 * rough relief it is what changes from texel to texel.
 *
 * A bounce depends on the radiance of every light, so the pass reruns
 * whenever the shading does, and when its own settings change (plan.h
 * "bounce settings"); its textures exist only once a frame has bounces
 * (bounce_targets.h).
 */
#include "gles_backend.h"

#include "gl_util.h"
#include "lights.h"
#include "pyramid_layout.h"

#include <math.h>

#define PI 3.14159265358979323846
/* Does the frame gather the near part at every texel? */
static int near_part(const hfs_gles_frame *fr)
{
    return fr->capped && !fr->gloss.on && fr->bsub > 1 && fr->q->bounce_near > 0;
}

static int present(const hfs_gles_frame *fr)
{
    return fr->bounces > 0;
}

static size_t block_bytes(const hfs_gles_frame *fr)
{
    return sizeof(hfs_gles_bounce_head) + (size_t)fr->q->nphi_env * 16;
}

static int layout(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err)
{
    int rc;
    /* The bounce grid's receivers are visibility receivers (their horizons
     * cap the bands): its step is a multiple of the visibility grid's. */
    fr->bsub = fr->q->bounce_subsample > fr->L.sub ? fr->q->bounce_subsample : fr->L.sub;
    fr->bw = hfs_grid_count(fr->L.w, fr->bsub);
    fr->bh = hfs_grid_count(fr->L.h, fr->bsub);
    if (fr->bounces > HFS_GLES_MAX_BOUNCES)
        return hfs_fail(err, HFS_E_INVALID, "bounces %d: at most %d", fr->bounces,
                        HFS_GLES_MAX_BOUNCES);
    if ((rc = hfs_gl_caps_check_texture(&g->caps, fr->bw, fr->bh, HFS_GLES_MAX_BOUNCES,
                                        "bounces (the grid's irradiance)", err)))
        return rc;
    return hfs_gl_caps_check_uniform_block(&g->caps, block_bytes(fr),
                                           "bounce directions (--nphi-env)", err);
}

/* HfsBounce: dphi / pi, k, the stride, the environment's directions
 * (the bounces' are every stride-th). */
static int upload_block(hfs_gles *g, const hfs_gles_frame *fr, hfs_error *err)
{
    const int n_env = fr->q->nphi_env, n = hfs_bounce_dirs(fr->q), stride = n_env / n;
    float *blk = hfs_gles_scratch(g, block_bytes(fr) + (size_t)n_env * 2 * sizeof(float));
    if (!blk)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for the bounces");
    hfs_gles_bounce_head *head = (hfs_gles_bounce_head *)blk;
    *head = (hfs_gles_bounce_head){.weight = (float)(2.0 / n), .k = (float)fr->L.k,
                                   .stride = (float)stride};
    float *dirs = blk + 4, *cs = dirs + 4 * n_env;
    hfs_swath s;
    hfs_swath_full(n_env, &s);
    hfs_gles_swath_float_dirs(&fr->L, &s, cs);
    for (int j = 0; j < n_env; ++j) {
        dirs[4 * j] = cs[2 * j], dirs[4 * j + 1] = cs[2 * j + 1];
        dirs[4 * j + 2] = dirs[4 * j + 3] = 0.0f;
    }
    hfs_gles_ubo_upload(&g->gl, g->ubo[HFS_UBO_BOUNCE], blk, block_bytes(fr));
    return HFS_OK;
}

/* bounce_light.frag into fbo (w x h): direct (0/1) + rho sum of E layers
 * [first, first + count). */
static int light(hfs_gles *g, const hfs_gles_frame *fr, GLuint fbo, int direct, int first,
                 int count, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    const hfs_gles_layout *L = &fr->L;
    const hfs_gles_variant v = {.fp32 = g->caps.fp32, .albedo_map = fr->albedo != NULL,
                                .slice = fr->capped, .glossy = fr->gloss.on,
                                .near = near_part(fr)};
    const hfs_gles_program *prog;
    int rc = hfs_gles_program_use(&g->programs, gl, HFS_PROG_BOUNCE_LIGHT, &v, &prog, err);
    if (rc || (rc = hfs_gles_program_texture(gl, prog, "u_hi", GL_TEXTURE_2D, g->r.out[0], err)) ||
        (rc = hfs_gles_program_texture(gl, prog, "u_lo", GL_TEXTURE_2D, g->r.out[1], err)) ||
        (rc = hfs_gles_program_texture(gl, prog, "u_e", GL_TEXTURE_2D_ARRAY, g->bounce.e, err)))
        return rc;
    if (fr->albedo &&
        (rc = hfs_gles_program_texture(gl, prog, "u_albedo", GL_TEXTURE_2D, g->albedo.tex, err)))
        return rc;
    if (fr->capped && (rc = hfs_gles_program_texture(gl, prog, "u_t0", GL_TEXTURE_2D,
                                                     g->r.transfer[0], err)))
        return rc;
    if (v.near && (rc = hfs_gles_program_texture(gl, prog, "u_en", GL_TEXTURE_2D_ARRAY,
                                                 g->bounce.near, err)))
        return rc;
    hfs_gles_set_i2(gl, prog, "u_size", L->w, L->h);
    hfs_gles_set_i2(gl, prog, "u_vsize", fr->bw, fr->bh);
    hfs_gles_set_i1(gl, prog, "u_sub", fr->bsub);
    hfs_gles_set_f1(gl, prog, "u_direct", (float)direct);
    hfs_gles_set_f1(gl, prog, "u_rho", (float)(fr->rho_pi * PI));
    hfs_gles_set_i1(gl, prog, "u_first", first);
    hfs_gles_set_i1(gl, prog, "u_count", count);
    hfs_gles_draw(gl, fbo, L->w, L->h);
    return HFS_OK;
}

/* The glossy receivers' uniforms (bounce_gather.frag HFS_GLOSSY). */
static void set_gloss(const hfs_gl *gl, const hfs_gles_program *prog, const hfs_gles_frame *fr)
{
    const hfs_gloss *gs = &fr->gloss;
    const hfs_gles_layout *L = &fr->L;
    const double par[4] = {gs->s, fmin(0.1, 0.5 * sqrt(2.0 / gs->s)), exp(log(1e-6) / gs->s),
                           0.0}; /* slice_light.c hfs_lobe_slice_init */
    const double view[4] = {gs->view[0], gs->view[1], gs->view[2],
                            gs->ks * gs->norm * 2.0 * PI / hfs_bounce_dirs(fr->q)};
    const double eye[4] = {gs->eye[0] / L->dx, gs->eye[1] / L->dx, gs->eye[2] / L->dx, 0.0};
    const double hgt[4] = {L->base, L->hscale, L->zscale / L->dx, 0.0};
    hfs_gles_set_f4(gl, prog, "u_gpar", par);
    hfs_gles_set_f4(gl, prog, "u_gview", view);
    hfs_gles_set_f4(gl, prog, "u_geye", eye);
    hfs_gles_set_f4(gl, prog, "u_ghgt", hgt);
}

/* bounce_gather.frag over the bounce grid into layer `layer` of E (and
 * the next, G, for a glossy surface); near: its near pass at every texel
 * into layer `layer` of the near targets. */
static int gather(hfs_gles *g, const hfs_gles_frame *fr, int layer, int near, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    const hfs_gles_layout *L = &fr->L;
    const int capped = fr->capped;
    const hfs_gles_variant v = {.n_layers = L->n_layers,
                                .n_dir = fr->q->nphi_env, .n_bdir = hfs_bounce_dirs(fr->q),
                                .fp32 = g->caps.fp32, .slice = capped,
                                .glossy = fr->gloss.on ? 1 + fr->gloss.at_eye : 0,
                                .pairs = capped && fr->hor_pairs,
                                .far_k = capped && fr->split.on ? fr->split.k : 0,
                                .far_h = capped && fr->split.on ? fr->split.heights : 0,
                                .near = near};
    const hfs_gles_program *prog;
    int rc = hfs_gles_program_use(&g->programs, gl, HFS_PROG_BOUNCE_GATHER, &v, &prog, err);
    if (rc || (rc = hfs_gles_bind_grid_inputs(g, prog, L, err)) ||
        (rc = hfs_gles_program_texture(gl, prog, "u_rad", GL_TEXTURE_2D, g->bounce.rad, err)))
        return rc;
    if (capped &&
        ((rc = hfs_gles_program_texture(gl, prog, "u_hor", GL_TEXTURE_2D_ARRAY, g->r.hor, err)) ||
         (rc = hfs_gles_bind_env_far(g, fr, prog, err)))) /* split horizons' far part */
        return rc;
    hfs_gles_set_f1(gl, prog, "u_vmax", (float)(L->vmax + 1e-5));
    hfs_gles_set_i1(gl, prog, "u_refine", fr->q->bounce_refine);
    hfs_gles_set_f1(gl, prog, "u_near_d", near_part(fr) ? (float)fr->q->bounce_near : 0.0f);
    hfs_gles_set_f1(gl, prog, "u_tie", (float)hfs_horizon_tie_slope(L->hscale, L->zscale, L->dx));
    hfs_gles_set_i1(gl, prog, "u_sub", near ? 1 : fr->bsub); /* the receivers */
    hfs_gles_set_i1(gl, prog, "u_vsub", L->sub);  /* the visibility grid's, for u_hor */
    hfs_gles_set_i2(gl, prog, "u_vsize", L->vw, L->vh);
    gl->BindBufferBase(GL_UNIFORM_BUFFER, HFS_BLOCK_BOUNCE, g->ubo[HFS_UBO_BOUNCE]);
    const int glossy = fr->gloss.on;
    if (glossy)
        set_gloss(gl, prog, fr);
    if (near) {
        if ((rc = hfs_gles_fbo_layers(gl, g->bounce.near_fbo, g->bounce.near, layer, 1,
                                      "bounce near part", err)))
            return rc;
        hfs_gles_draw(gl, g->bounce.near_fbo, L->w, L->h);
        return HFS_OK;
    }
    if ((rc = hfs_gles_fbo_layers(gl, g->bounce.e_fbo, g->bounce.e, (1 + glossy) * layer,
                                  1 + glossy, "bounce irradiance", err)))
        return rc;
    hfs_gles_draw(gl, g->bounce.e_fbo, fr->bw, fr->bh);
    return HFS_OK;
}

static int run(hfs_gles *g, hfs_gles_frame *fr, const int *which, hfs_error *err)
{
    (void)which;
    const hfs_gl *gl = &g->gl;
    int rc;
    const int near = near_part(fr);
    if ((rc = hfs_gles_bounce_targets_ensure(&g->bounce, gl, &g->caps, fr->L.w, fr->L.h, fr->bw,
                                             fr->bh, fr->gloss.on, near ? fr->bounces : 0,
                                             err)) ||
        (rc = upload_block(g, fr, err)))
        return rc;
    for (int b = 1; b <= fr->bounces && !rc; ++b) {
        /* Lo_{b-1}: the direct light, or rho E_{b-1}. */
        if ((rc = light(g, fr, g->bounce.rad_fbo, b == 1, b - 2, b == 1 ? 0 : 1, err)))
            break;
        if (near && (rc = gather(g, fr, b - 1, 1, err)))
            break;
        rc = gather(g, fr, b - 1, 0, err);
    }
    if (!rc)
        rc = light(g, fr, g->bounce.fin_fbo, 1, 0, fr->bounces, err);
    gl->UseProgram(0);
    return rc ? rc : hfs_gl_check(gl, "backend gles: bounce pass", err);
}

const hfs_gles_pass hfs_pass_bounce = {
    .id = HFS_PASS_BOUNCE,
    .plan_name = "bounce",
    .scope = HFS_SCOPE_FRAME,
    /* Also the grid's horizons when they cap the bands; plan.c sets that
     * each frame (hfs_gles_plan_frame). */
    .reads = {"output targets", "pyramid", "subsample", "albedo", "bounce settings"},
    .writes = {"bounced targets"},
    .stages = {"bounce"},
    .present = present,
    .layout = layout,
    .run = run,
};
