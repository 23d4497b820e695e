/*
 * pass_key_horizons.c — per key light, the horizon and the distance it
 * was found at in each direction of its swath (the azimuths about the
 * light's direction, visibility.h hfs_swath_key) on the sub-sampled grid
 * (key_horizons.frag, DIRS_PER_DRAW directions per draw, one per RGBA
 * layer).  A light moved
 * inside its swath keeps them: only its visibility (pass_key_visibility.c)
 * runs again.  Also the key lights' uniform data: the swath blocks
 * (HfsSwath, one buffer bound by range) and the records (HfsKeys) the
 * visibility pass reads, and the wedge tables of the table path.
 */
#include "gles_backend.h"

#include "gl_util.h"
#include "pyramid_layout.h"

#include <math.h>
#include <string.h>

#define DIRS_PER_DRAW 4 /* 4 RGBA targets (ES 3.0's minimum), one direction each */

hfs_key_near hfs_gles_key_near_make(const hfs_gles_layout *L, const hfs_swath *s)
{
    return hfs_key_near_make(L->sub, L->n_levels, L->k, s);
}

static int present(const hfs_gles_frame *fr)
{
    return fr->n_keys > 0;
}

static size_t align_up(size_t v, size_t a)
{
    return (v + a - 1) / a * a;
}

/* Each key slot owns a run of g->key_stride horizon layers, the most any
 * key swath of this renderer has needed (a high-water mark, from room for a
 * partial swath's nphi_key + 1 samples): a light whose swath grows or
 * shrinks within it does not move the other lights' horizons, and the
 * texture is not reallocated.  When the mark rises (a light covering the
 * zenith takes the full swath) every slot moves: the planner sees new
 * layers (hz_layer is in the signature). */
static void assign_layers(hfs_gles *g, hfs_gles_frame *fr)
{
    if (g->key_stride < fr->q->nphi_key + 1)
        g->key_stride = fr->q->nphi_key + 1;
    for (int i = 0; i < fr->n_keys; ++i)
        if (g->key_stride < fr->keys[i].k.swath.n)
            g->key_stride = fr->keys[i].k.swath.n;
    fr->key_layers = 0;
    for (int i = 0; i < fr->n_keys; ++i) {
        fr->keys[i].k.hz_layer = i * g->key_stride;
        /* a light whose texels search their rays to the field's end
         * (hfs_key_near.whole) stores nothing on the grid */
        if (!hfs_gles_key_near_make(&fr->L, &fr->keys[i].k.swath).whole)
            fr->key_layers = (i + 1) * g->key_stride;
    }
}

/* Swaths, visibility objects, block offsets; the limits they meet. */
static int layout(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err)
{
    const hfs_gl_caps *caps = &g->caps;
    const size_t align = (size_t)caps->uniform_buffer_offset_alignment;
    int rc, rec = 0;
    assign_layers(g, fr);
    fr->key_swath_bytes = 0;
    for (int i = 0; i < fr->n_keys; ++i) {
        hfs_gles_frame_key *k = &fr->keys[i];
        if ((rc = hfs_visibility_create(&k->k.swath, HFS_VIS_LEGENDRE, &k->vis, err)))
            return rc;
        k->swath_off = fr->key_swath_bytes;
        k->swath_size = hfs_gles_swath_vec4(k->k.swath.n) * 16;
        fr->key_swath_bytes = align_up(fr->key_swath_bytes + k->swath_size, align);
        k->rec_off = rec;
        rec += (int)hfs_gles_key_vec4(k->k.swath.n);
        /* A swath too large for a block: every key's from one texture. */
        fr->key_swath_tex |= hfs_gles_block_too_big(caps, k->swath_size / 16);
    }
    if (fr->key_swath_tex &&
        (rc = hfs_gles_block_texture_check(caps, fr->key_swath_bytes / 16,
                                           "key-light swaths (--nphi-key)", err)))
        return rc;
    /* The records' declared size (HFS_KEY_VEC4) goes in size classes, so
     * that a swath gaining or losing a sample as its light moves does not
     * recompile the visibility pass (a 100-400 ms hitch on llvmpipe): the
     * next power of two from 1024 vec4 (16 KiB, ES 3.0's minimum block: one
     * class, so one program, for any key set that fits it), or the exact
     * size where that would not fit the block limit.  The buffer is
     * uploaded at that size. */
    int rec_block = 1024;
    while (rec_block < rec)
        rec_block *= 2;
    if ((size_t)rec_block * 16 > (size_t)caps->max_uniform_block_size)
        rec_block = rec > 0 ? rec : 1;
    fr->key_rec_block = rec_block;
    fr->keys_tex = hfs_gles_block_too_big(caps, (size_t)rec_block);
    if ((rc = hfs_gles_block_texture_check(caps, (size_t)rec_block,
                                           "key-light records (fewer keys or --nphi-key)", err)))
        return rc;
    return hfs_gl_caps_check_texture(caps, fr->L.vw, fr->L.vh, fr->key_layers,
                                     "key-light horizons", err);
}

/* Block data into its uniform buffer, or its texture (block_texture.h). */
static int upload(hfs_gles *g, hfs_gles_block_texture *bt, int ubo, int as_texture,
                  const float *data, size_t bytes, void *texels, const char *what,
                  hfs_error *err)
{
    if (as_texture)
        return hfs_gles_block_texture_upload(bt, &g->gl, &g->caps, data, bytes / 16, texels,
                                             what, err);
    hfs_gles_ubo_upload(&g->gl, g->ubo[ubo], data, bytes);
    return HFS_OK;
}

/* Swath blocks, records and (table path) the wedge-table sets, every frame
 * with key lights: the visibility pass reads the records. */
static int prepare(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err)
{
    const size_t bytes = fr->key_swath_bytes + (size_t)fr->key_rec_block * 16;
    float *ks = hfs_gles_scratch(g, 2 * bytes); /* the blocks, then texels */
    if (!ks)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory");
    memset(ks, 0, bytes);
    float *recs = ks + fr->key_swath_bytes / sizeof(float);
    int n_sets = 0;
    double set_dphi[HFS_MAX_KEY_LIGHTS];
    for (int i = 0; i < fr->n_keys; ++i) {
        hfs_gles_frame_key *k = &fr->keys[i];
        g->stats.offset_mismatches += hfs_gles_offset_mismatches(&fr->L, &k->k.swath);
        hfs_gles_pack_swath(&fr->L, k->vis, ks + k->swath_off / sizeof(float));
        k->k.table_set = 0;
        if (fr->tables) { /* one set of tables per distinct dphi */
            int s = 0;
            while (s < n_sets && set_dphi[s] != k->k.swath.dphi)
                ++s;
            if (s == n_sets)
                set_dphi[n_sets++] = k->k.swath.dphi;
            k->k.table_set = s;
        }
        hfs_gles_pack_key(&fr->L, &k->k, k->vis, recs + (size_t)k->rec_off * 4);
    }
    int rc;
    if ((rc = upload(g, &g->key_swath_tex, HFS_UBO_KEY_SWATHS, fr->key_swath_tex, ks,
                     fr->key_swath_bytes, (char *)ks + bytes, "key-light swaths", err)) ||
        (rc = upload(g, &g->keys_tex, HFS_UBO_KEYS, fr->keys_tex, recs,
                     (size_t)fr->key_rec_block * 16, (char *)ks + bytes, "key-light records",
                     err)))
        return rc;
    if (!fr->tables)
        return HFS_OK;
    void *scratch = hfs_gles_scratch(g, hfs_gles_wedge_scratch_bytes());
    if (!scratch)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for wedge tables");
    return hfs_gles_wedge_keys(&g->wedge, &g->gl, &g->caps, set_dphi, n_sets, scratch, err);
}

/* The keys q with which[q] set (NULL: all), or their counting twins. */
static int draw(hfs_gles *g, const hfs_gles_frame *fr, const int *which, int count,
                double *fetch_sum, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    const hfs_gles_layout *L = &fr->L;
    int rc;
    for (int q = 0; q < fr->n_keys; ++q) {
        if (which && !which[q])
            continue;
        const hfs_gles_frame_key *k = &fr->keys[q];
        const hfs_key_near nr = hfs_gles_key_near_make(L, &k->k.swath);
        if (nr.whole)
            continue; /* its texels search their rays to the field's end */
        const int n = k->k.swath.n;
        for (int d0 = 0; d0 < n; d0 += DIRS_PER_DRAW) {
            const int cnt = n - d0 < DIRS_PER_DRAW ? n - d0 : DIRS_PER_DRAW;
            const int outs = cnt;
            const hfs_gles_variant v = {.n_layers = L->n_layers,
                                        .n_out = outs, .n_dir = n, .fp32 = g->caps.fp32,
                                        .count = count, .swath_tex = fr->key_swath_tex,
                                        .cells = 1};
            const hfs_gles_program *prog;
            if ((rc = hfs_gles_program_use(&g->programs, gl, HFS_PROG_KEY_HORIZONS, &v, &prog,
                                           err)) ||
                (rc = hfs_gles_bind_grid_inputs(g, prog, L, err)))
                return rc;
            /* the gap search starts where the grid's scales do: the near
             * ones are searched per texel (key_visibility.frag) */
            const int near = nr.n_grid;
            if ((rc = hfs_gles_bind_bounds(g, prog, L, (float)exp2((double)near / L->k), err)))
                return rc;
            hfs_gles_set_i1(gl, prog, "u_dir0", d0);
            hfs_gles_set_i1(gl, prog, "u_ndir", cnt);
            hfs_gles_set_i1(gl, prog, "u_near", near);
            hfs_gles_set_f1(gl, prog, "u_lk", (float)L->k);
            hfs_gles_set_i1(gl, prog, "u_refine", fr->q->refine);
            hfs_gles_set_f1(gl, prog, "u_tie",
                            (float)hfs_horizon_tie_slope(L->hscale, L->zscale, L->dx));
            if (fr->key_swath_tex) {
                if ((rc = hfs_gles_program_texture(gl, prog, "u_swath_tex", GL_TEXTURE_2D,
                                                   g->key_swath_tex.tex, err)))
                    return rc;
                hfs_gles_set_i1(gl, prog, "u_swath_base", (int)(k->swath_off / 16));
            } else {
                gl->BindBufferRange(GL_UNIFORM_BUFFER, HFS_BLOCK_SWATH,
                                    g->ubo[HFS_UBO_KEY_SWATHS], (GLintptr)k->swath_off,
                                    (GLsizeiptr)k->swath_size);
            }
            if ((rc = hfs_gles_draw_grid_layers(g, L, g->r.keyhz_fbo, g->r.keyhz,
                                                k->k.hz_layer + d0, outs, "key", NULL,
                                                count ? fetch_sum : NULL, err)) ||
                (rc = hfs_gl_check(gl, "backend gles: key pass", err)))
                return rc;
        }
    }
    gl->UseProgram(0);
    return HFS_OK;
}

static int run(hfs_gles *g, hfs_gles_frame *fr, const int *which, hfs_error *err)
{
    return draw(g, fr, which, 0, NULL, err);
}

static int count(hfs_gles *g, hfs_gles_frame *fr, double *fetches, hfs_error *err)
{
    return draw(g, fr, NULL, 1, fetches, err);
}

const hfs_gles_pass hfs_pass_key_horizons = {
    .id = HFS_PASS_KEY_HORIZONS,
    .plan_name = "key %d",
    .scope = HFS_SCOPE_KEY,
    .deferrable = 1,
    .reads = {"pyramid", "subsample", "key %d swath"},
    .writes = {"key %d horizons"},
    .stages = {"key"},
    .present = present,
    .layout = layout,
    .prepare = prepare,
    .run = run,
    .count = count,
};
