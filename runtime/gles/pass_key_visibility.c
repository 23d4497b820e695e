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
    if ((rc = hfs_gles_bind_normals(g, prog, L, err)) ||
        (rc = hfs_gles_program_texture(gl, prog, "u_keyhz", GL_TEXTURE_2D_ARRAY, g->r.keyhz, err)))
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

/* The factors of the lights `which` marks (all: NULL) into their layers;
 * fetch_sum not NULL: the counting twin (HFS_COUNT), its fetches added
 * there. */
static int draw(hfs_gles *g, hfs_gles_frame *fr, const int *which, double *fetch_sum,
                hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    const hfs_gles_layout *L = &fr->L;
    const hfs_gles_variant v = {.key_vec4 = fr->key_rec_block > 0 ? fr->key_rec_block : 1,
                                .tables = fr->tables, .fp32 = g->caps.fp32,
                                .keys_tex = fr->keys_tex, .count = fetch_sum != NULL,
                                .cells = 1};
    const hfs_gles_program *prog;
    int rc = hfs_gles_program_use(&g->programs, gl, HFS_PROG_KEY_VISIBILITY, &v, &prog, err);
    if (rc || (rc = bind_inputs(g, fr, prog, err)))
        return rc;
    for (int q = 0; q < fr->n_keys; ++q) {
        if (which && !which[q])
            continue;
        hfs_gles_set_i1(gl, prog, "u_kb", fr->keys[q].rec_off);
        const hfs_key_near nr = hfs_gles_key_near_make(L, &fr->keys[q].k.swath);
        hfs_gles_set_f1(gl, prog, "u_emax", (float)hfs_gles_key_emax(&fr->keys[q].k));
        hfs_gles_set_i1(gl, prog, "u_near", nr.n);
        hfs_gles_set_i1(gl, prog, "u_near_dir", nr.per_dir);
        hfs_gles_set_f1(gl, prog, "u_reach", (float)nr.reach);
        hfs_gles_set_f2(gl, prog, "u_near_cs", (float)nr.cs[0], (float)nr.cs[1]);
        hfs_gles_set_f1(gl, prog, "u_near_to", (float)nr.to);
        /* whole: to the field's end, beyond any distance on it */
        hfs_gles_set_f1(gl, prog, "u_edge", nr.whole ? (float)(L->w + L->h) : (float)nr.edge);
        hfs_gles_set_i1(gl, prog, "u_whole", nr.whole);
        if ((rc = hfs_gles_fbo_layers(gl, g->r.kf_fbo, g->r.kf, q, 1, "key factor", err)))
            return rc;
        /* after an edit: the texels it can reach (edit_frame.c) */
        const hfs_tiles *region = fetch_sum ? NULL : hfs_gles_edit_key(g, fr, prog, q, &nr);
        if (fetch_sum)
            hfs_gles_set_i1(gl, prog, "u_edit", 0);
        hfs_gles_edit_draw(g, g->r.kf_fbo, L->w, L->h, 1, region);
        if (fetch_sum && (rc = hfs_gles_sum_counts_rect(g, g->r.kf_fbo, L->w, L->h, fetch_sum,
                                                        err)))
            return rc;
        if ((rc = hfs_gl_check(gl, "backend gles: key factor pass", err)))
            return rc;
    }
    gl->UseProgram(0);
    return HFS_OK;
}

static int run(hfs_gles *g, hfs_gles_frame *fr, const int *which, hfs_error *err)
{
    return draw(g, fr, which, NULL, err);
}

/* Its counting twin: the fetches of every light's factor (the layers then
 * hold counts: the frame after drops them, gles_frame.c). */
static int count(hfs_gles *g, hfs_gles_frame *fr, double *fetches, hfs_error *err)
{
    return draw(g, fr, NULL, &fetches[0], err);
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
    .count = count,
};
