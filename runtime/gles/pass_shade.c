/*
 * pass_shade.c — exit radiance at full resolution (shade.frag), RGB as
 * fp16 hi + lo targets: the environment (H(N) . L_env from the kept
 * transfer vectors, clamped against order-4 ringing), each key light
 * (rho/pi Le E_max times its factor) and each local light (E_cap at the
 * texel times its interpolated ratio), times the albedo (and the texel's
 * albedo map value, HFS_ALBEDO_MAP).
 *
 * Every radiance reaches the shader already multiplied by the frame's
 * output scale, a power of two that puts the largest value the frame can
 * hold near 16384 (layout.h hfs_gles_output_scale): fp16 then never
 * saturates and never sinks into subnormals, for any finite scene, and the
 * frame's bits are those of an unscaled computation wherever that one
 * neither overflowed nor underflowed.  The read-back divides it out.
 */
#include "gles_backend.h"

#include "gl_util.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define PI 3.14159265358979323846

/* The largest glossy term the frame's lights can give (gloss.h): the
 * environment's |L . Q| <= 4 sum |L_k| (as the diffuse bound), a key or
 * local light's lobe peak (S+2)/(2 pi) times its largest E_cap, ks Le
 * inside a local light.  0 when not glossy: the diffuse frame's scale. */
static double gloss_bound(const hfs_gles_frame *fr)
{
    const hfs_gloss *gl = &fr->gloss;
    if (!gl->on)
        return 0.0;
    double b = 0.0;
    for (int c = 0; c < 3 && fr->has_env; ++c) {
        double s = 0.0;
        for (int k = 0; k < HFS_SH_N; ++k)
            s += fabs(fr->l_env[c][k]);
        b = fmax(b, 4.0 * s);
    }
    if (fr->gloss_map) /* the map's lobe beyond order 4 (env_gloss.h) */
        b += fr->gloss_map_max;
    for (int i = 0; i < fr->n_keys; ++i)
        b += fmax(fr->keys[i].k.le[0], fmax(fr->keys[i].k.le[1], fr->keys[i].k.le[2])) *
             gl->norm * hfs_cap_irradiance(1.0, fr->keys[i].k.alpha);
    for (int i = 0; i < fr->n_local; ++i)
        b += fmax(fr->local[i].radiance[0], fmax(fr->local[i].radiance[1],
                                                 fr->local[i].radiance[2])) *
             fmax(1.0, gl->norm * hfs_gles_local_max_irradiance(&fr->L, &fr->local[i]));
    return gl->ks * b;
}

/* HfsShade's glossy tail (u_gview ... u_kdir), radiances times s. */
static void fill_gloss(const hfs_gles_frame *fr, double s, hfs_gles_shade_block *sb)
{
    const hfs_gloss *gl = &fr->gloss;
    for (int k = 0; k < 3; ++k)
        sb->gview[k] = (float)gl->view[k];
    sb->gview[3] = (float)gl->ks;
    sb->gpar[0] = (float)gl->s;
    sb->gpar[1] = (float)(gl->ks * gl->norm);
    sb->gpar[2] = (float)(fr->gloss_map_max * s); /* D_g's scale, a radiance */
    /* g_l per coefficient k = l(l+1)+m: bands 0 | 1 1 1 | 2 x5 | 3 x7. */
    for (int k = 0; k < HFS_SH_N; ++k)
        sb->gzh[k] = (float)gl->zh[k < 1 ? 0 : k < 4 ? 1 : k < 9 ? 2 : 3];
    for (int i = 0; i < fr->n_keys; ++i) { /* times the key factor E_cap ratio / E_max */
        for (int c = 0; c < 3; ++c)
            sb->kspec[i][c] = (float)(gl->ks * gl->norm * fr->keys[i].k.le[c] *
                                      hfs_gles_key_emax(&fr->keys[i].k) * s);
        for (int c = 0; c < 3; ++c)
            sb->kdir[i][c] = (float)fr->keys[i].k.dir[c];
    }
    const hfs_gles_layout *L = &fr->L;
    for (int k = 0; k < 3 && gl->at_eye; ++k) /* texel units, as the heights' z */
        sb->geye[k] = (float)(gl->eye[k] / L->dx);
    sb->ghgt[0] = (float)L->base;
    sb->ghgt[1] = (float)L->hscale;
    sb->ghgt[2] = (float)(L->zscale / L->dx);
}

/* The largest exit radiance the frame's lights can give. */
static double radiance_bound(const hfs_gles_frame *fr)
{
    double bound = 0.0;
    if (fr->has_env) {
        double m = 0.0;
        for (int c = 0; c < 3; ++c) {
            double s = 0.0;
            for (int k = 0; k < HFS_SH_N; ++k)
                s += fabs(fr->l_env[c][k]);
            m = s > m ? s : m;
        }
        bound += 4.0 * m;
    }
    bound *= PI;
    if (fr->env_map > 0) /* the open sky beyond order 4 (env_open.h) */
        bound += hfs_env_open_max(fr->l->env_open);
    /* Lights by the irradiance they can actually give (not pi): a bound
     * loose by Le * pi / E_max pushes the frame's values into fp16's
     * subnormals, where hi + lo keep only ~3e-8 of the scale (a 1e-5 rad sun
     * of radiance 3e9 lost 0.7% that way). */
    for (int i = 0; i < fr->n_keys; ++i) /* pi sin^2 alpha, at normal incidence */
        bound += fmax(fr->keys[i].k.le[0], fmax(fr->keys[i].k.le[1], fr->keys[i].k.le[2])) *
                 hfs_cap_irradiance(1.0, fr->keys[i].k.alpha);
    for (int i = 0; i < fr->n_local; ++i)
        bound += fmax(fr->local[i].radiance[0],
                      fmax(fr->local[i].radiance[1], fr->local[i].radiance[2])) *
                 hfs_gles_local_max_irradiance(&fr->L, &fr->local[i]);
    return bound * fr->rho_pi + gloss_bound(fr);
}

/* HfsShade, every radiance times the output scale s. */
static void fill_block(const hfs_gles *g, const hfs_gles_frame *fr, double s,
                       hfs_gles_shade_block *sb)
{
    memset(sb, 0, sizeof *sb);
    for (int c = 0; c < 3 && fr->has_env; ++c)
        for (int k = 0; k < HFS_SH_N; ++k)
            sb->env[c][k] = (float)(fr->l_env[c][k] * s);
    sb->misc[0] = (float)fr->rho_pi;
    sb->misc[1] = 1.0f; /* the scale is in the radiances */
    sb->misc[2] = fr->has_env ? 1.0f : 0.0f;
    if (fr->has_env) { /* T_occ's dot with the sky, in its own scale */
        double m[3];
        hfs_gles_env_occ_weights(fr->l_env, sb->envo, m);
        for (int c = 0; c < 3; ++c)
            sb->occs[c] = (float)(fr->rho_pi * m[c] * s);
    }
    for (int c = 0; c < 3 && fr->has_env; ++c) /* cpu_render.c env_clamp */
        sb->env_neg[c] = (float)(fr->rho_pi * PI * hfs_sh_negative_bound(fr->l_env[c]) * s);
    for (int i = 0; i < fr->n_keys; ++i) /* rho/pi Le E_max: the factor's scale */
        for (int c = 0; c < 3; ++c)
            sb->kle[i][c] = (float)(fr->rho_pi * fr->keys[i].k.le[c] *
                                    hfs_gles_key_emax(&fr->keys[i].k) * s);
    if (fr->slice) /* exact slices: the open part is H(N) itself */
        hfs_gles_cosine_transfer(sb->topen);
    else
        hfs_gles_open_transfer(sb->topen);
    for (int i = 0; i < fr->n_local; ++i)
        for (int c = 0; c < 3; ++c)
            sb->lle[i][c] = (float)(fr->local[i].radiance[c] * s);
    if (fr->env_map > 0) { /* the tables' scales (env_map_textures.h) */
        sb->emap[0] = (float)(fr->rho_pi * g->envmap.dmax * s);
        sb->emap[1] = (float)cos(fr->l->env_rotate);
        sb->emap[2] = (float)sin(fr->l->env_rotate);
        sb->emap[3] = (float)(fr->rho_pi * g->envmap.fmax * g->env_slices.dphi * s);
    }
    if (fr->gloss.on)
        fill_gloss(fr, s, sb);
}

static int bind_inputs(hfs_gles *g, const hfs_gles_frame *fr, const hfs_gles_program *prog,
                       hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    const hfs_gles_resources *r = &g->r;
    int rc;
    if ((rc = hfs_gles_bind_normals(g, prog, &fr->L, err)))
        return rc;
    if (fr->env_fold && /* the sky occlusion, not T_occ */
        ((rc = hfs_gles_program_texture(gl, prog, "u_socc", GL_TEXTURE_2D, r->skyocc[0], err)) ||
         (rc = hfs_gles_program_texture(gl, prog, "u_socclo", GL_TEXTURE_2D, r->skyocc[1], err))))
        return rc;
    for (int i = 0; i < 4 && !fr->env_fold; ++i) {
        char name[16]; /* room for any int, as the optimiser checks */
        snprintf(name, sizeof name, "u_t%d", i);
        if ((rc = hfs_gles_program_texture(gl, prog, name, GL_TEXTURE_2D, r->transfer[i], err)))
            return rc;
    }
    if ((rc = hfs_gles_program_texture(gl, prog, "u_kf", GL_TEXTURE_2D_ARRAY, r->kf, err)))
        return rc;
    if (fr->n_local > 0) {
        if ((rc = hfs_gles_program_texture(gl, prog, "u_localv", GL_TEXTURE_2D_ARRAY, r->localv,
                                           err)))
            return rc;
        gl->BindBufferBase(GL_UNIFORM_BUFFER, HFS_BLOCK_LOCAL, g->ubo[HFS_UBO_LOCAL]);
    }
    if (fr->albedo &&
        (rc = hfs_gles_program_texture(gl, prog, "u_albedo", GL_TEXTURE_2D, g->albedo.tex, err)))
        return rc;
    if (fr->env_map > 0 &&
        (rc = hfs_gles_program_texture(gl, prog, "u_eopen", GL_TEXTURE_2D, g->envmap.open, err)))
        return rc;
    if (fr->env_map == 2 &&
        (rc = hfs_gles_program_texture(gl, prog, "u_mocc", GL_TEXTURE_2D, g->envmap.occ, err)))
        return rc;
    if (fr->gloss_map &&
        (rc = hfs_gles_program_texture(gl, prog, "u_egloss", GL_TEXTURE_2D, g->envmap.gloss,
                                       err)))
        return rc;
    hfs_gles_set_i2(gl, prog, "u_size", fr->L.w, fr->L.h);
    hfs_gles_set_i2(gl, prog, "u_vsize", fr->L.vw, fr->L.vh);
    hfs_gles_set_i1(gl, prog, "u_sub", fr->L.sub);
    gl->BindBufferBase(GL_UNIFORM_BUFFER, HFS_BLOCK_SHADE, g->ubo[HFS_UBO_SHADE]);
    return HFS_OK;
}

static int run(hfs_gles *g, hfs_gles_frame *fr, const int *which, hfs_error *err)
{
    (void)which;
    const hfs_gl *gl = &g->gl;
    const hfs_gles_layout *L = &fr->L;
    const double bound = radiance_bound(fr);
    if (!isfinite(bound))
        return hfs_fail(err, HFS_E_INVALID, "backend gles: the scene's radiance (bound %g) is "
                        "beyond what double precision carries", bound);
    fr->out_scale = hfs_gles_output_scale(bound);
    hfs_gles_shade_block sb;
    fill_block(g, fr, fr->out_scale, &sb);
    hfs_gles_ubo_upload(gl, g->ubo[HFS_UBO_SHADE], &sb, sizeof sb);

    const int local = fr->n_local > 0;
    const hfs_gles_variant v = {.n_keys = fr->n_keys, .env = fr->has_env, .local = local,
                                .local_dirs = local ? fr->q->nphi_local : 0,
                                .n_local = fr->n_local, .fp32 = g->caps.fp32,
                                .albedo_map = fr->albedo != NULL, .glossy = fr->gloss.on ? 1 + fr->gloss.at_eye : 0,
                                .env_map = fr->has_env ? fr->env_map : 0,
                                .env_occ = fr->env_fold, .slice = fr->has_env && fr->slice,
                                .gloss_map = fr->has_env && fr->gloss_map};
    const hfs_gles_program *prog;
    int rc = hfs_gles_program_use(&g->programs, gl, HFS_PROG_SHADE, &v, &prog, err);
    if (rc || (rc = bind_inputs(g, fr, prog, err)))
        return rc;
    /* After an edit: the texels any of its inputs changed at (the local
     * lights' ratios added theirs when they ran: pass_local_lights.c). */
    hfs_gles_edit_draw(g, g->r.out_fbo, L->w, L->h, 1, fr->edit ? &g->edit.shade : NULL);
    gl->UseProgram(0);
    /* The environment: T_occ (not on the map's occlusion unless glossy) or
     * the sky occlusion, the open-sky table and the map's occlusion
     * (pass_env_map_slices.c). */
    const int t_occ = fr->env_fold ? 2 : (fr->env_map == 2 && !fr->gloss.on ? 0 : 4);
    const int env_fetches = !fr->has_env ? 0
                            : t_occ + (fr->env_map > 0) + (fr->env_map == 2) + fr->gloss_map;
    /* the normal's 4 heights (hfs_normal_at) */
    double fetches = (double)L->w * L->h * (4 + env_fetches + fr->n_keys + (fr->albedo != NULL));
    if (local) /* the texel's height, one ratio layer per two lights */
        fetches += (double)L->w * L->h * (1 + (fr->n_local + 1) / 2);
    if (fr->gloss.on && fr->gloss.at_eye) /* the texel's height for its view vector */
        fetches += (double)L->w * L->h;
    hfs_gles_stage_fetches(g, HFS_PASS_SHADE, 0, fetches);
    return hfs_gl_check(gl, "backend gles: shading pass", err);
}

const hfs_gles_pass hfs_pass_shade = {
    .id = HFS_PASS_SHADE,
    .plan_name = "shade",
    .scope = HFS_SCOPE_FRAME,
    /* Reads what the frame's lights use; plan.c sets that each frame
     * (hfs_gles_plan_frame). */
    .reads = {NULL},
    .writes = {"output targets"},
    .stages = {"shade"},
    .run = run,
};
