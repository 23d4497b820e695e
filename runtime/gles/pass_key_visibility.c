/*
 * pass_key_visibility.c — per key light, its factor E_cap * ratio / E_max
 * at full resolution (key_visibility.frag): the disk's visible fraction
 * above this texel's horizons (the grid's occluders moved to the texel, the
 * light's SH visibility from the records HfsKeys), times the irradiance of
 * the visible cap, over the largest possible (pi sin^2 alpha) so the fp16
 * layer holds a value in [0, 1].  Layer q of the factor array; the shading
 * multiplies by rho/pi Le E_max.  Independent of the light's radiance.
 */
#include "gles_backend.h"

#include "gl_util.h"

#include <float.h>
#include <math.h>

double hfs_gles_key_emax(const hfs_gles_key *k)
{
    return fmax(hfs_cap_irradiance(1.0, k->alpha), (double)FLT_MIN);
}

/* Texture fetches per texel of key_visibility.frag for swath s: normal
 * and height; on a sub-sampled grid the four grid neighbours' heights, the
 * near scales and their refinement (at most; fewer near the edges), the
 * gap search to nr.to (a clear ray's: about two reads per octave,
 * ray_bound.h; a blocked one stops sooner, a partly lit one reads more),
 * and per direction its own gap search to nr.edge and four horizon
 * fetches; at subsample 1 one per direction. */
static double factor_fetches(const hfs_gles_layout *L, const hfs_swath *s, int refine)
{
    if (L->sub == 1)
        return 2.0 + s->n;
    const hfs_key_near nr = hfs_gles_key_near_make(L, s);
    if (nr.per_dir)
        return 2.0 + 4.0 + 5.0 * s->n;
    const double dir_gap = 2.0 * ceil(log2(nr.edge / nr.to));
    return 2.0 + 4.0 + (nr.n > 0 ? nr.n + refine + 2.0 * ceil(log2(nr.to)) : 0) +
           (4.0 + dir_gap) * s->n;
}

static int present(const hfs_gles_frame *fr)
{
    return fr->n_keys > 0;
}

static int bind_inputs(hfs_gles *g, const hfs_gles_frame *fr, const hfs_gles_program *prog,
                       hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    const hfs_gles_layout *L = &fr->L;
    int rc;
    if ((rc = hfs_gles_program_texture(gl, prog, "u_normals", GL_TEXTURE_2D, g->r.normals, err)) ||
        (rc = hfs_gles_program_texture(gl, prog, "u_keyhz", GL_TEXTURE_2D_ARRAY, g->r.keyhz, err)) ||
        (rc = hfs_gles_program_texture(gl, prog, "u_height", GL_TEXTURE_2D, g->r.input, err)))
        return rc;
    if (fr->tables &&
        ((rc = hfs_gles_program_texture(gl, prog, "u_ktab", GL_TEXTURE_2D_ARRAY, g->wedge.keys,
                                        err)) ||
         (rc = hfs_gles_program_texture(gl, prog, "u_ktabb", GL_TEXTURE_2D_ARRAY,
                                        g->wedge.keys_boundary, err))))
        return rc;
    hfs_gles_set_i2(gl, prog, "u_size", L->w, L->h);
    hfs_gles_set_i2(gl, prog, "u_vsize", L->vw, L->vh);
    hfs_gles_set_i1(gl, prog, "u_sub", L->sub);
    hfs_gles_set_f1(gl, prog, "u_lk", (float)L->k);
    hfs_gles_set_i1(gl, prog, "u_refine", fr->q->refine);
    hfs_gles_set_f1(gl, prog, "u_far", (float)(2 * L->sub));
    hfs_gles_set_f1(gl, prog, "u_rise", (float)(L->hscale * L->zscale / L->dx));
    if ((rc = hfs_gles_bind_bounds(g, prog, L, 0.0f, err)))
        return rc;
    if (fr->keys_tex)
        return hfs_gles_program_texture(gl, prog, "u_keys_tex", GL_TEXTURE_2D, g->keys_tex.tex,
                                        err);
    gl->BindBufferBase(GL_UNIFORM_BUFFER, HFS_BLOCK_KEYS, g->ubo[HFS_UBO_KEYS]);
    return HFS_OK;
}

static int run(hfs_gles *g, hfs_gles_frame *fr, const int *which, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    const hfs_gles_layout *L = &fr->L;
    const hfs_gles_variant v = {.key_vec4 = fr->key_rec_block > 0 ? fr->key_rec_block : 1,
                                .tables = fr->tables, .fp32 = g->caps.fp32,
                                .keys_tex = fr->keys_tex};
    const hfs_gles_program *prog;
    int rc = hfs_gles_program_use(&g->programs, gl, HFS_PROG_KEY_VISIBILITY, &v, &prog, err);
    if (rc || (rc = bind_inputs(g, fr, prog, err)))
        return rc;
    for (int q = 0; q < fr->n_keys; ++q) {
        if (!which[q])
            continue;
        hfs_gles_set_i1(gl, prog, "u_kb", fr->keys[q].rec_off);
        const hfs_key_near nr = hfs_gles_key_near_make(L, &fr->keys[q].k.swath);
        hfs_gles_set_f1(gl, prog, "u_emax", (float)hfs_gles_key_emax(&fr->keys[q].k));
        hfs_gles_set_i1(gl, prog, "u_near", nr.n);
        hfs_gles_set_i1(gl, prog, "u_near_dir", nr.per_dir);
        hfs_gles_set_f1(gl, prog, "u_reach", (float)nr.reach);
        hfs_gles_set_f2(gl, prog, "u_near_cs", (float)nr.cs[0], (float)nr.cs[1]);
        hfs_gles_set_f1(gl, prog, "u_near_to", (float)nr.to);
        hfs_gles_set_f1(gl, prog, "u_edge", (float)nr.edge);
        if ((rc = hfs_gles_fbo_layers(gl, g->r.kf_fbo, g->r.kf, q, 1, "key factor", err)))
            return rc;
        hfs_gles_draw(gl, g->r.kf_fbo, L->w, L->h);
        hfs_gles_stage_fetches(g, HFS_PASS_KEY_VISIBILITY, 0,
                               (double)L->w * L->h *
                                   factor_fetches(L, &fr->keys[q].k.swath, fr->q->refine));
        if ((rc = hfs_gl_check(gl, "backend gles: key factor pass", err)))
            return rc;
    }
    gl->UseProgram(0);
    return HFS_OK;
}

const hfs_gles_pass hfs_pass_key_visibility = {
    .id = HFS_PASS_KEY_VISIBILITY,
    .plan_name = "key %d factor",
    .scope = HFS_SCOPE_KEY,
    .reads = {"pyramid", "key %d horizons", "key %d direction"},
    .writes = {"key %d factor"},
    .stages = {"keyfactor"},
    .present = present,
    .run = run,
};
