/*
 * pass_terrain.c — the terrain pass: the heights uploaded as fp16 hi+lo
 * pairs (layout.h) into the last layer of the level array (their only
 * copy: every pass reads them there, u_height / u_hlayer), with the gap
 * search's bounds (bounds_texture.h); the pyramid decimated from level N-2
 * down to lmin (terrain_decimate.frag, bilinear) and reconstructed to the
 * full grid (terrain_reconstruct.frag: a B-spline, x passes then y passes
 * with HFS_GLES_RECON_MRT levels per draw).  Kept while the terrain and
 * the settings it reads do not change.
 */
#include "gles_backend.h"

#include "bounds_texture.h"
#include "gl_util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char hfs_gles_heights_changed[] = "heights changed";

const char *hfs_gles_terrain_change(const hfs_gles *g, const hfs_field *f, const hfs_quality *q)
{
    const size_t n = (size_t)f->width * (size_t)f->height;
    if (!g->terrain_valid)
        return "terrain not computed yet";
    if (g->t_w != f->width || g->t_h != f->height)
        return "field size changed";
    if (g->t_k != q->k || g->t_offset != q->offset)
        return "pyramid settings (k, offset) changed";
    if (g->t_fp32 != g->caps.fp32)
        return "precision changed";
    if (g->t_dx != f->dx || g->t_zscale != f->zscale)
        return "dx or zscale changed";
    if (memcmp(g->terrain_z, f->z, n * sizeof *f->z))
        return hfs_gles_heights_changed;
    return NULL;
}

/* Keeps what the pass computed from (0: out of memory, not kept). */
static int terrain_remember(hfs_gles *g, const hfs_gles_frame *fr)
{
    const hfs_field *f = fr->f;
    const hfs_quality *q = fr->q;
    const size_t n = (size_t)f->width * (size_t)f->height;
    if (n > g->terrain_cap) {
        float *z = realloc(g->terrain_z, n * sizeof *z);
        if (!z)
            return 0;
        g->terrain_z = z;
        g->terrain_cap = n;
    }
    memcpy(g->terrain_z, f->z, n * sizeof *f->z);
    g->t_w = f->width, g->t_h = f->height, g->t_k = q->k, g->t_offset = q->offset;
    g->t_fp32 = g->caps.fp32, g->t_dx = f->dx, g->t_zscale = f->zscale;
    g->t_base = fr->L.base, g->t_hscale = fr->L.hscale, g->t_vmax = fr->L.vmax;
    return 1;
}

static int upload(hfs_gles *g, const hfs_gles_frame *fr, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    const hfs_gles_layout *L = &fr->L;
    const int w = L->w, h = L->h, fp32 = g->caps.fp32;
    float *sc = hfs_gles_scratch(g, hfs_gles_scales_vec4() * 16);
    if (!sc)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory");
    hfs_gles_pack_scales(L, sc);
    hfs_gles_ubo_upload(gl, g->ubo[HFS_UBO_SCALES], sc, hfs_gles_scales_vec4() * 16);
    hfs_gles_stage_begin(g, HFS_PASS_TERRAIN, 0);
    void *buf = hfs_gles_scratch(g, (size_t)w * h * 2 * (fp32 ? 4 : 2));
    if (!buf)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for a %dx%d upload", w, h);
    hfs_gles_split_heights(L, fr->f, fp32, buf, 0);
    g->stats.height_scale = L->hscale;
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 4);
    gl->BindTexture(GL_TEXTURE_2D_ARRAY, g->r.arr);
    gl->TexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, L->n_layers - 1, w, h, 1, GL_RG,
                      g->caps.type_upload, buf);
    gl->BindTexture(GL_TEXTURE_2D_ARRAY, 0);
    /* the heights' buffer is free again: the bounds are built in the same
     * scratch */
    void *work = hfs_gles_scratch(g, hfs_gles_bounds_work_bytes(L));
    if (!work)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for the height bounds");
    int rc = hfs_gles_bounds_upload(gl, &g->caps, g->r.bounds, L, fr->f, work, err);
    hfs_gles_stage_end(g, HFS_PASS_TERRAIN, 0);
    return rc ? rc : hfs_gl_check(gl, "backend gles: upload", err);
}

static int decimate(hfs_gles *g, const hfs_gles_layout *L, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    hfs_gles_stage_begin(g, HFS_PASS_TERRAIN, 1);
    double fetches = 0.0;
    for (int l = L->n_levels - 2; l >= L->lmin; --l) {
        /* the first from the heights: the array's last layer (HFS_SRC_LAYERS) */
        const int first = l == L->n_levels - 2;
        const hfs_gles_variant v = {.fp32 = g->caps.fp32, .src_layers = first ? L->n_layers : 0};
        const hfs_gles_program *prog;
        int rc = hfs_gles_program_use(&g->programs, gl, HFS_PROG_TERRAIN_DECIMATE, &v, &prog, err);
        if (!rc)
            rc = first ? hfs_gles_program_texture(gl, prog, "u_src", GL_TEXTURE_2D_ARRAY, g->r.arr,
                                                  err)
                       : hfs_gles_program_texture(gl, prog, "u_src", GL_TEXTURE_2D,
                                                  g->r.lev[l + 1], err);
        if (rc)
            return rc;
        hfs_gles_set_i2(gl, prog, "u_dsize", L->lw[l], L->lh[l]);
        hfs_gles_draw(gl, g->r.lev_fbo[l], L->lw[l], L->lh[l]);
        fetches += (double)L->lw[l] * L->lh[l];
    }
    hfs_gles_stage_end(g, HFS_PASS_TERRAIN, 1);
    hfs_gles_stage_fetches(g, HFS_PASS_TERRAIN, 1, fetches);
    return HFS_OK;
}

/* The y passes: HFS_GLES_RECON_MRT levels per draw into the layer array,
 * over region (NULL: all; after an edit, what the coarsest level's reach
 * from the changed box covers, edit_frame.c). */
static int reconstruct_y(hfs_gles *g, const hfs_gles_layout *L, const hfs_tiles *region,
                         hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    const int w = L->w, h = L->h;
    int rc;
    for (int i = 0; i < L->n_layers - 1; i += HFS_GLES_RECON_MRT) {
        const int left = L->n_layers - 1 - i;
        const int n = left < HFS_GLES_RECON_MRT ? left : HFS_GLES_RECON_MRT;
        const hfs_gles_variant v = {.recon_v = n, .fp32 = g->caps.fp32};
        const hfs_gles_program *prog;
        if ((rc = hfs_gles_program_use(&g->programs, gl, HFS_PROG_TERRAIN_RECONSTRUCT, &v,
                                       &prog, err)))
            return rc;
        hfs_gles_set_i2(gl, prog, "u_dst_size", w, h);
        for (int k = 0; k < n; ++k) {
            const int l = L->lmin + i + k;
            char name[24]; /* room for any int, as the optimiser checks */
            snprintf(name, sizeof name, "u_vsrc[%d]", k);
            if ((rc = hfs_gles_program_texture(gl, prog, name, GL_TEXTURE_2D, g->r.half[l], err)))
                return rc;
            snprintf(name, sizeof name, "u_vsize[%d]", k);
            hfs_gles_set_i2(gl, prog, name, w, L->lh[l]);
        }
        hfs_gles_edit_draw(g, g->r.arr_mrt_fbo[i / HFS_GLES_RECON_MRT], w, h, 1, region);
    }
    return HFS_OK;
}

static int reconstruct(hfs_gles *g, const hfs_gles_layout *L, const hfs_tiles *region,
                       hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    const int w = L->w, h = L->h;
    const hfs_gles_variant v = {.fp32 = g->caps.fp32};
    const hfs_gles_program *prog;
    int rc = hfs_gles_program_use(&g->programs, gl, HFS_PROG_TERRAIN_RECONSTRUCT, &v, &prog, err);
    if (rc)
        return rc;
    hfs_gles_stage_begin(g, HFS_PASS_TERRAIN, 2);
    /* x passes, one per level (the results differ in height)... */
    hfs_gles_set_i1(gl, prog, "u_axis", 0);
    double fetches = 0.0;
    for (int l = L->lmin; l < L->n_levels - 1; ++l) {
        if ((rc = hfs_gles_program_texture(gl, prog, "u_src", GL_TEXTURE_2D, g->r.lev[l], err)))
            return rc;
        hfs_gles_set_i2(gl, prog, "u_src_size", L->lw[l], L->lh[l]);
        hfs_gles_set_i2(gl, prog, "u_dst_size", w, L->lh[l]);
        hfs_gles_draw(gl, g->r.half_fbo[l], w, L->lh[l]);
        fetches += 2.0 * w * L->lh[l] + 2.0 * w * h;
    }
    /* ... then the y passes. */
    if ((rc = reconstruct_y(g, L, region, err)))
        return rc;
    hfs_gles_stage_end(g, HFS_PASS_TERRAIN, 2);
    hfs_gles_stage_fetches(g, HFS_PASS_TERRAIN, 2, fetches);
    gl->UseProgram(0);
    return hfs_gl_check(gl, "backend gles: pyramid", err);
}

static int run(hfs_gles *g, hfs_gles_frame *fr, const int *which, hfs_error *err)
{
    (void)which;
    g->terrain_valid = 0;
    int rc;
    if ((rc = upload(g, fr, err)) ||
        (rc = hfs_gles_pyramid_build_ensure(&g->r, &g->gl, &g->caps, &fr->L, err)) ||
        (rc = decimate(g, &fr->L, err)) ||
        (rc = reconstruct(g, &fr->L, fr->edit ? hfs_gles_edit_levels(g, fr) : NULL, err)))
        return rc;
    hfs_gles_pyramid_build_free(&g->r, &g->gl);
    g->terrain_valid = terrain_remember(g, fr);
    g->stats.terrain_recomputed = 1;
    return HFS_OK;
}

const hfs_gles_pass hfs_pass_terrain = {
    .id = HFS_PASS_TERRAIN,
    .plan_name = "terrain",
    .scope = HFS_SCOPE_FRAME,
    .reads = {"terrain"},
    .writes = {"pyramid"},
    .stages = {"upload", "decimate", "reconstruct"},
    .run = run,
};
