/*
 * pass_local_lights.c — per local spherical light, the ratio of its
 * shadowed to its unshadowed irradiance on the sub-sampled grid
 * (local_visibility.frag; the thesis on local spherical lights, DESIGN.md
 * "Local lights"): light i in layer i / 2 of the ratio array (RG for even
 * i, BA for odd), up to 8 lights per draw.  A light beyond the terrain's
 * shadow range needs none (ratio 1, lights.h hfs_local_light_open).  Also
 * the local lights' block HfsLocal, which the shading reads too.
 */
#include "gles_backend.h"

#include "gl_util.h"

#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846

static int present(const hfs_gles_frame *fr)
{
    return fr->n_local > 0;
}

/* HfsLocal in vec4: the head, then the full swath's directions and wedge
 * placements. */
static size_t block_vec4(int nphi)
{
    return (sizeof(hfs_gles_local_block) + (size_t)nphi * sizeof(hfs_gles_swath_sample) +
            (size_t)nphi * sizeof(hfs_gles_wedge_rot)) / 16;
}

/* The ratio layers; the block, or (too large for the profile's blocks) its
 * head in the block and the whole in a texture. */
static int layout(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err)
{
    const int layers = (fr->n_local + 1) / 2;
    const size_t n4 = block_vec4(fr->q->nphi_local);
    fr->local_tex = hfs_gles_block_too_big(&g->caps, n4);
    int rc = hfs_gl_caps_check_texture(&g->caps, fr->L.vw, fr->L.vh, layers > 0 ? layers : 1,
                                       "local-light visibility", err);
    if (rc)
        return rc;
    return fr->local_tex
               ? hfs_gles_block_texture_check(&g->caps, n4, "local lights (--nphi-local)", err)
               : hfs_gl_caps_check_uniform_block(&g->caps, n4 * 16, "local lights (--nphi-local)",
                                                 err);
}

/* The full swath after the head: u_ldir[nphi] (the robust floats of
 * hfs_gles_swath_float_dirs: (cos, sin, 0, 0)), then per wedge its
 * z-rotation for the wedge tables (hfs_gles_wedge_rot, interior wedges: no
 * mirror); cs: scratch for 2 nphi floats. */
static void pack_swath(const hfs_gles_layout *L, int nphi, float *dst, float *cs)
{
    hfs_swath sw;
    hfs_swath_full(nphi, &sw);
    hfs_gles_swath_float_dirs(L, &sw, cs);
    hfs_gles_swath_sample *dir = (hfs_gles_swath_sample *)dst;
    for (int k = 0; k < nphi; ++k) {
        dir[k].cos = cs[2 * k];
        dir[k].sin = cs[2 * k + 1];
    }
    hfs_gles_wedge_rot *rot = (hfs_gles_wedge_rot *)(dir + nphi);
    for (int w = 0; w < hfs_swath_wedge_count(&sw) && w < nphi; ++w) {
        hfs_swath_wedge wd;
        hfs_swath_get_wedge(&sw, w, &wd);
        hfs_gles_wedge_rot_set(&rot[w], wd.start, 0);
    }
}

/* HfsLocal: the fixed head (hfs_gles_local_block) and the swath. */
static int upload_block(hfs_gles *g, const hfs_gles_frame *fr, hfs_error *err)
{
    const hfs_gles_layout *L = &fr->L;
    const int nphi = fr->q->nphi_local;
    const size_t n4 = block_vec4(nphi);
    /* The block, 2 floats a direction (cs), then the texels. */
    float *u = hfs_gles_scratch(g, n4 * 16 + (size_t)nphi * 2 * sizeof(float) + n4 * 16);
    if (!u)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory");
    memset(u, 0, n4 * 16);
    hfs_gles_local_block *lb = (hfs_gles_local_block *)u;
    double E[HFS_SH_N * HFS_NLP_N];
    _Static_assert(HFS_SH_N * HFS_NLP_N == 16 * 4, "u_lE[16]");
    hfs_wedge_elevation_moments(E);
    for (int i = 0; i < HFS_SH_N * HFS_NLP_N; ++i)
        lb->moments[i / 4][i % 4] = (float)E[i];
    /* Lengths in texel units (dx = 1): the shaders' float arithmetic is then
     * the same for a scene scaled as a whole (dx, zscale and the lights
     * together), so knife-edge decisions (a scale exactly at a light's
     * entry distance) fall the same way at every scale. */
    const double inv_dx = 1.0 / L->dx;
    lb->geom[0] = 1.0f;
    lb->geom[1] = (float)L->base;
    lb->geom[2] = (float)L->hscale;
    lb->geom[3] = (float)(L->zscale * inv_dx);
    lb->swath[0] = (float)nphi;
    lb->swath[1] = fr->q->local_full_swath ? 1.0f : 0.0f;
    for (int i = 0; i < fr->n_local; ++i) {
        for (int c = 0; c < 3; ++c)
            lb->lights[i][0][c] = (float)(fr->local[i].pos[c] * inv_dx);
        lb->lights[i][0][3] = (float)(fr->local[i].radius * inv_dx);
        /* Le is the shading block's (u_lle, scaled); here only whether the
         * terrain can shadow the light at all (ratio 1, none stored). */
        lb->lights[i][1][3] = fr->local_open[i] ? 1.0f : 0.0f;
    }
    pack_swath(L, nphi, u + sizeof(hfs_gles_local_block) / sizeof(float), u + n4 * 4);
    if (fr->local_tex) {
        /* The head for the shading and the pass; the whole for the swath. */
        hfs_gles_ubo_upload(&g->gl, g->ubo[HFS_UBO_LOCAL], u, sizeof(hfs_gles_local_block));
        int rc = hfs_gles_block_texture_upload(&g->local_tex, &g->gl, &g->caps, u, n4,
                                               (char *)u + n4 * 16 + (size_t)nphi * 2 * 4,
                                               "local lights (--nphi-local)", err);
        if (rc)
            return rc;
    } else {
        hfs_gles_ubo_upload(&g->gl, g->ubo[HFS_UBO_LOCAL], u, n4 * 16);
    }
    hfs_swath sw;
    hfs_swath_full(nphi, &sw);
    g->stats.offset_mismatches += hfs_gles_offset_mismatches(L, &sw);
    return HFS_OK;
}

static int any_run(const hfs_gles_frame *fr)
{
    int any = 0;
    for (int i = 0; i < fr->n_local; ++i)
        any |= fr->run[HFS_PASS_LOCAL_LIGHTS][i];
    return any;
}

/* The block when the ratios or the shading run; the table when they run. */
static int prepare(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err)
{
    const int any = any_run(fr);
    int rc;
    if ((any || fr->run[HFS_PASS_SHADE][0]) && (rc = upload_block(g, fr, err)))
        return rc;
    if (!any || !fr->tables)
        return HFS_OK;
    void *scratch = hfs_gles_scratch(g, hfs_gles_wedge_scratch_bytes());
    if (!scratch)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for wedge tables");
    return hfs_gles_wedge_local(&g->wedge, &g->gl, &g->caps, 2.0 * PI / fr->q->nphi_local,
                                scratch, err);
}

/* Wanted lights of layer k (bit 0: light 2k, bit 1: light 2k + 1). */
static int layer_want(int k, int n_local, const int *which)
{
    int want = 0;
    for (int b = 0; b < 2 && 2 * k + b < n_local; ++b)
        want |= (!which || which[2 * k + b]) << b;
    return want;
}

/* One draw: `layers` layers from k, computing the lights of `mask`. */
static int draw_layers(hfs_gles *g, const hfs_gles_frame *fr, int k, int layers, int mask,
                       int partial, int count, const hfs_tiles *region, double *fetch_sum,
                       hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    const hfs_gles_layout *L = &fr->L;
    const int n_local = fr->n_local, l0 = 2 * k;
    const int cnt = 2 * (k + layers) < n_local ? 2 * layers : n_local - l0;
    const hfs_gles_variant v = {.n_layers = L->n_layers,
                                .n_out = layers, .local_dirs = fr->q->nphi_local,
                                .tables = fr->tables, .fp32 = g->caps.fp32, .count = count,
                                .local_tex = fr->local_tex, .cells = 1};
    const hfs_gles_program *prog;
    int rc;
    if ((rc = hfs_gles_program_use(&g->programs, gl, HFS_PROG_LOCAL_VISIBILITY, &v, &prog, err)) ||
        (rc = hfs_gles_bind_grid_inputs(g, prog, L, err)) ||
        (rc = hfs_gles_bind_ray(gl, prog, L, g->r.arr, L->n_layers - 1, g->r.bounds, err)))
        return rc;
    /* each sample's own ray (local_visibility.frag ray_horizon) */
    hfs_gles_set_f1(gl, prog, "u_rise", (float)(L->hscale * L->zscale / L->dx));
    hfs_gles_set_i1(gl, prog, "u_light0", l0);
    hfs_gles_set_i1(gl, prog, "u_nl", cnt);
    hfs_gles_set_i1(gl, prog, "u_lmask", mask);
    if (fr->tables &&
        (rc = hfs_gles_program_texture(gl, prog, "u_tab", GL_TEXTURE_2D_ARRAY, g->wedge.local,
                                       err)))
        return rc;
    gl->BindBufferBase(GL_UNIFORM_BUFFER, HFS_BLOCK_LOCAL, g->ubo[HFS_UBO_LOCAL]);
    if (fr->local_tex &&
        (rc = hfs_gles_program_texture(gl, prog, "u_local_tex", GL_TEXTURE_2D, g->local_tex.tex,
                                       err)))
        return rc;
    if (partial)
        gl->ColorMask(mask & 1, mask & 1, (mask >> 1) & 1, (mask >> 1) & 1);
    rc = hfs_gles_draw_grid_layers(g, L, g->r.localv_fbo, g->r.localv, k, layers, "local-light",
                                   region, count ? fetch_sum : NULL, err);
    if (partial)
        gl->ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    return rc ? rc : hfs_gl_check(gl, "backend gles: local-light pass", err);
}

/* The lights with which[i] set (NULL: all).  Layers whose lights are all
 * wanted (or absent) are drawn 4 at a time (8 lights per draw); a layer
 * with one wanted and one kept light is drawn alone with a colour mask
 * that protects the kept light's channels (ES 3.0 has no per-target mask)
 * and computes only the wanted one (u_lmask). */
static int draw(hfs_gles *g, const hfs_gles_frame *fr, const int *which, int count,
                double *fetch_sum, hfs_error *err)
{
    const int n_local = fr->n_local, n_layers = (n_local + 1) / 2;
    int rc = HFS_OK;
    /* after an edit: the receivers it can reach (edit_frame.c) */
    const hfs_tiles *region = fr->edit && !count ? hfs_gles_edit_local(g, fr) : NULL;
    for (int k = 0; k < n_layers && !rc;) {
        const int want = layer_want(k, n_local, which);
        const int both = 2 * k + 1 < n_local ? 3 : 1;
        if (!want) {
            ++k;
            continue;
        }
        int layers = 1, mask = want;
        if (want == both) { /* extend over the following whole layers */
            while (layers < 4 && k + layers < n_layers) {
                const int w2 = layer_want(k + layers, n_local, which);
                if (w2 != (2 * (k + layers) + 1 < n_local ? 3 : 1))
                    break;
                mask |= w2 << (2 * layers);
                ++layers;
            }
        }
        const int partial = layers == 1 && want != both && !count;
        rc = draw_layers(g, fr, k, layers, mask, partial, count, region, fetch_sum, err);
        k += layers;
    }
    g->gl.UseProgram(0);
    return rc;
}

static int run(hfs_gles *g, hfs_gles_frame *fr, const int *which, hfs_error *err)
{
    return draw(g, fr, which, 0, NULL, err);
}

static int count(hfs_gles *g, hfs_gles_frame *fr, double *fetches, hfs_error *err)
{
    return draw(g, fr, NULL, 1, fetches, err);
}

const hfs_gles_pass hfs_pass_local_lights = {
    .id = HFS_PASS_LOCAL_LIGHTS,
    .plan_name = "local %d",
    .scope = HFS_SCOPE_LOCAL,
    .deferrable = 1,
    .reads = {"pyramid", "subsample", "local settings", "local %d geometry"},
    .writes = {"local %d ratios"},
    .stages = {"local"},
    .present = present,
    .layout = layout,
    .prepare = prepare,
    .run = run,
    .count = count,
};
