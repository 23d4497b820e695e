/*
 * edit_frame.c — a frame after an edit of the heights: the regions each
 * pass recomputes, the far grid's change found by comparison, the key
 * factor's test, and the scissored draws (edit_frame.h, edit_region.h).
 */
#include "gles_backend.h"

#include "gl_util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void hfs_gles_edit_free(hfs_gles_edit *e)
{
    hfs_tiles_free(&e->normals);
    hfs_tiles_free(&e->levels);
    hfs_tiles_free(&e->env);
    hfs_tiles_free(&e->far);
    hfs_tiles_free(&e->transfer);
    hfs_tiles_free(&e->key);
    hfs_tiles_free(&e->local);
    hfs_tiles_free(&e->shade);
    free(e->far_old);
    free(e->far_now);
    free(e->rects);
    memset(e, 0, sizeof *e);
}

const char *hfs_gles_edit_begin(hfs_gles *g, const hfs_gles_frame *fr)
{
    hfs_gles_edit *e = &g->edit;
    const hfs_gles_layout *L = &fr->L;
    const int w = L->w, h = L->h;
    /* the normalization: every normalized height the same but the box's */
    if (L->base != g->t_base || L->hscale != g->t_hscale || L->vmax != g->t_vmax ||
        !hfs_edit_find(g->terrain_z, fr->f->z, w, h, &e->box))
        return NULL;
    /* A change over most of the field would redraw most of every pass, and
     * the regions' bookkeeping (the far grid read twice) would be on top:
     * a cold frame is the cheaper way to the same bits. */
    if ((double)(e->box.x1 - e->box.x0 + 1) * (e->box.y1 - e->box.y0 + 1) >
        HFS_EDIT_MAX_SHARE * w * h)
        return NULL;
    snprintf(e->why, sizeof e->why, "heights edited: %dx%d texels at (%d, %d)",
             e->box.x1 - e->box.x0 + 1, e->box.y1 - e->box.y0 + 1, e->box.x0, e->box.y0);
    return e->why;
}

int hfs_gles_edit_regions(hfs_gles *g, const hfs_gles_frame *fr)
{
    hfs_gles_edit *e = &g->edit;
    const hfs_gles_layout *L = &fr->L;
    const int w = L->w, h = L->h;
    const size_t n = (size_t)((w + HFS_EDIT_TILE - 1) / HFS_EDIT_TILE) *
                     ((h + HFS_EDIT_TILE - 1) / HFS_EDIT_TILE);
    if (n > e->rects_cap) {
        hfs_edit_rect *r = realloc(e->rects, n * sizeof *r);
        if (!r)
            return -1;
        e->rects = r;
        e->rects_cap = n;
    }
    if (hfs_tiles_init(&e->normals, w, h) || hfs_tiles_init(&e->levels, w, h) ||
        hfs_tiles_init(&e->env, w, h) ||
        hfs_tiles_init(&e->far, w, h) || hfs_tiles_init(&e->transfer, w, h) ||
        hfs_tiles_init(&e->key, w, h) || hfs_tiles_init(&e->local, w, h) ||
        hfs_tiles_init(&e->shade, w, h))
        return -1;
    /* A sample that reads a changed texel also reads its unchanged
     * neighbours, which may stand higher: the top over 3 around (a sample
     * within 2 of the box, key_visibility.frag, reads texels within 1 of
     * itself). */
    e->top = hfs_edit_top(L, g->terrain_z, fr->f->z, w, hfs_edit_box_grow(e->box, 3, w, h));
    for (int l = 0; l < L->n_layers && l < HFS_GLES_MAX_LEVELS; ++l) {
        e->layer_reach[l] = hfs_edit_layer_reach(L, l);
        const hfs_edit_box around = hfs_edit_box_grow(e->box, (int)ceil(2.0 * e->layer_reach[l]),
                                                      w, h);
        e->layer_top[l] = hfs_edit_top(L, g->terrain_z, fr->f->z, w, around);
    }
    e->transfer_made = 0;
    hfs_tiles_add_box(&e->normals, hfs_edit_box_grow(e->box, 1, w, h));
    /* The grid's horizons reach far-from when the horizons are split;
     * otherwise each searches to the field's end. */
    if (fr->slice && fr->split.on)
        hfs_tiles_add_grown(&e->env, &e->normals,
                            (int)ceil(hfs_edit_env_near_reach(L, fr->env_coarsest)));
    else
        hfs_tiles_set_all(&e->env);
    hfs_tiles_add_grown(&e->shade, &e->normals, 0);
    return 0;
}

void hfs_gles_edit_draw(hfs_gles *g, GLuint fbo, int w, int h, int step, const hfs_tiles *region)
{
    const hfs_gl *gl = &g->gl;
    if (!region || region->all) {
        hfs_gles_draw(gl, fbo, w, h);
        return;
    }
    hfs_edit_rect *r = g->edit.rects;
    const int n = hfs_tiles_rects(region, r);
    gl->Enable(GL_SCISSOR_TEST);
    for (int i = 0; i < n; ++i) {
        /* the receivers a whose texel a step falls in the rectangle (one
         * more each side: a receiver clamped to the field's last texel) */
        const int x0 = r[i].x / step, y0 = r[i].y / step;
        int x1 = (r[i].x + r[i].w + step - 1) / step + 1;
        int y1 = (r[i].y + r[i].h + step - 1) / step + 1;
        x1 = x1 < w ? x1 : w;
        y1 = y1 < h ? y1 : h;
        gl->Scissor(x0, y0, x1 - x0, y1 - y0);
        hfs_gles_draw(gl, fbo, w, h);
    }
    gl->Disable(GL_SCISSOR_TEST);
}

/* Bytes a layer of the far atlas takes in far_old and far_now (as floats,
 * the larger of the read-back's forms). */
static size_t far_layer_bytes(const hfs_gles_frame *fr)
{
    return (size_t)fr->far_aw * fr->far_ah * 4 * sizeof(float);
}

/* The far atlas, each of its layers (the occluders' heights,
 * split_horizon.h) far_layer_bytes apart, read into buf (floats or halves,
 * *half says which). */
static int far_read(hfs_gles *g, const hfs_gles_frame *fr, void *buf, int *half, hfs_error *err)
{
    int rc = HFS_OK;
    for (int c = 0; !rc && c < fr->split.heights; ++c) {
        hfs_gl_read_path used = HFS_GL_READ_FLOAT;
        rc = hfs_gles_fbo_layers(&g->gl, g->r.far_fbo, g->r.far, c, 1, "far horizons", err);
        if (!rc)
            rc = hfs_gl_read_rgba_raw(&g->gl, g->r.far_fbo, 0, 0, fr->far_aw, fr->far_ah,
                                      HFS_GL_READ_AUTO, (char *)buf + c * far_layer_bytes(fr),
                                      &used, err);
        if (!rc)
            *half = used == HFS_GL_READ_HALF; /* one path a context */
    }
    return rc;
}

int hfs_gles_edit_far_before(hfs_gles *g, const hfs_gles_frame *fr, hfs_error *err)
{
    hfs_gles_edit *e = &g->edit;
    const size_t bytes = far_layer_bytes(fr) * (size_t)fr->split.heights;
    if (bytes > e->far_cap) {
        void *b = realloc(e->far_old, bytes), *c = b ? realloc(e->far_now, bytes) : NULL;
        if (b)
            e->far_old = b;
        if (c)
            e->far_now = c;
        if (!b || !c)
            return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for the far grid");
        e->far_cap = bytes;
    }
    return far_read(g, fr, e->far_old, &e->far_half, err);
}

/* Marks, grown by the far grid's step (the slices blend the four far
 * receivers around each texel), every far receiver whose pairs differ
 * between the atlas as it was and as it is now. */
int hfs_gles_edit_far_after(hfs_gles *g, const hfs_gles_frame *fr, hfs_error *err)
{
    hfs_gles_edit *e = &g->edit;
    void *now = e->far_now; /* far_before made it as large as far_old */
    int half = 0, rc;
    if ((rc = far_read(g, fr, now, &half, err)))
        return rc;
    if (half != e->far_half) { /* the driver changed its mind: take all */
        hfs_tiles_set_all(&e->far);
        return HFS_OK;
    }
    const size_t each = half ? 4 * sizeof(uint16_t) : 4 * sizeof(float);
    const int step = fr->split.step, r = step + 1;
    for (int y = 0; y < fr->far_ah; ++y)
        for (int x = 0; x < fr->far_aw; ++x) {
            const size_t i = (size_t)y * fr->far_aw + x;
            int same = 1;
            for (int c = 0; c < fr->split.heights; ++c) {
                const size_t at = c * far_layer_bytes(fr) + i * each;
                same = same && !memcmp((char *)e->far_old + at, (char *)now + at, each);
            }
            if (same)
                continue;
            /* the receiver's texel, as the far pass places it */
            int gx = (x % fr->far_w) * step, gy = (y % fr->far_h) * step;
            gx = gx < fr->L.w - 1 ? gx : fr->L.w - 1;
            gy = gy < fr->L.h - 1 ? gy : fr->L.h - 1;
            const hfs_edit_box b = {gx - r, gy - r, gx + r, gy + r};
            hfs_tiles_add_box(&e->far, b);
        }
    return HFS_OK;
}

const hfs_tiles *hfs_gles_edit_transfer(hfs_gles *g, const hfs_gles_frame *fr)
{
    hfs_gles_edit *e = &g->edit;
    if (!e->transfer_made) {
        /* the texel's own 3 x 3 and the grid receivers' heights around it
         * (grid_rise: up to a step of either grid away) */
        const int step = fr->split.on && fr->split.step > fr->L.sub ? fr->split.step : fr->L.sub;
        hfs_tiles_add_grown(&e->transfer, &e->normals, step + 1);
        /* the grid's horizons, blended from the four receivers around */
        hfs_tiles_add_grown(&e->transfer, &e->env, fr->L.sub + 1);
        hfs_tiles_add_grown(&e->transfer, &e->far, 0);
        hfs_tiles_add_grown(&e->shade, &e->transfer, 0);
        e->transfer_made = 1;
    }
    return &e->transfer;
}

/* Box b swept backwards along direction phi of swath s for t_max texels
 * into the key's mask (the shader's own float direction). */
static void sweep_dir(hfs_gles_edit *e, const hfs_gles_layout *L, const hfs_swath *s, int j,
                      hfs_edit_box b, double t_max)
{
    const hfs_swath one = {.n = 1, .full = s->full, .phi0 = hfs_swath_phi(s, j), .dphi = s->dphi};
    float cs[2];
    hfs_gles_swath_float_dirs(L, &one, cs);
    hfs_tiles_add_box(&e->key, hfs_edit_sweep(b, cs[0], cs[1], t_max, L->w, L->h));
}

const hfs_tiles *hfs_gles_edit_key(hfs_gles *g, const hfs_gles_frame *fr,
                                   const hfs_gles_program *prog, int q, const hfs_key_near *nr)
{
    const hfs_gl *gl = &g->gl;
    const hfs_gles_layout *L = &fr->L;
    hfs_gles_edit *e = &g->edit;
    /* Only where each texel searches its own rays (at subsample 1 it reads
     * the key grid's horizons, which search theirs to the field's end). */
    const int on = fr->edit && L->sub > 1 && nr->whole;
    hfs_gles_set_i1(gl, prog, "u_edit", on);
    if (!on) {
        if (fr->edit)
            hfs_tiles_set_all(&e->shade);
        return NULL;
    }
    /* key_visibility.frag edit_reaches: the changed texels grown by 2 (a
     * bilinear sample's cell, a clamped ray's slack), their top, and the
     * light's lowest slope less the margin (twice here: the host's bound
     * must hold the shader's float one) */
    const hfs_edit_box b = hfs_edit_box_grow(e->box, 2, L->w, L->h);
    const double box[4] = {b.x0, b.y0, b.x1, b.y1};
    hfs_gles_set_f4(gl, prog, "u_edit_box", box);
    hfs_gles_set_f1(gl, prog, "u_edit_top", (float)e->top);
    const hfs_swath *s = hfs_visibility_swath(fr->keys[q].vis);
    const double slope = fr->tables ? -HUGE_VAL : tan(fmax(s->elev_lo, -1.5));
    const double t_max = hfs_edit_reach_above(e->top, -1.0, L->hscale * L->zscale / L->dx,
                                              slope - 2.0 * hfs_edit_slope_margin(slope));
    hfs_tiles_clear(&e->key);
    hfs_tiles_add_box(&e->key, b);
    if (nr->n > 0 && !nr->per_dir) {
        const double t_near = fmax(nr->to, 2.0 * nr->reach) + 2.0;
        const hfs_edit_box nb = hfs_edit_sweep(b, nr->cs[0], nr->cs[1], fmin(t_near, t_max), L->w,
                                               L->h);
        hfs_tiles_add_box(&e->key, nb);
    }
    for (int j = 0; j < s->n; ++j)
        sweep_dir(e, L, s, j, b, t_max);
    hfs_tiles_add_grown(&e->shade, &e->key, 0);
    return &e->key;
}

void hfs_gles_edit_far_uniforms(hfs_gles *g, const hfs_gles_frame *fr,
                                const hfs_gles_program *prog)
{
    const hfs_gl *gl = &g->gl;
    const hfs_gles_edit *e = &g->edit;
    hfs_gles_set_i1(gl, prog, "u_edit", fr->edit);
    if (!fr->edit)
        return;
    const double box[4] = {e->box.x0, e->box.y0, e->box.x1, e->box.y1};
    hfs_gles_set_f4(gl, prog, "u_edit_box", box);
    double reach = 0.0, top = -HUGE_VAL;
    for (int l = 0; l < fr->L.n_layers; ++l) {
        char name[32];
        snprintf(name, sizeof name, "u_edit_reach[%d]", l);
        hfs_gles_set_f1(gl, prog, name, (float)e->layer_reach[l]);
        snprintf(name, sizeof name, "u_edit_top[%d]", l);
        hfs_gles_set_f1(gl, prog, name, (float)e->layer_top[l]);
        reach = fmax(reach, e->layer_reach[l]);
        top = fmax(top, e->layer_top[l]);
    }
    hfs_gles_set_f1(gl, prog, "u_edit_reach_max", (float)reach);
    hfs_gles_set_f1(gl, prog, "u_edit_top_max", (float)top);
}

const hfs_tiles *hfs_gles_edit_levels(hfs_gles *g, const hfs_gles_frame *fr)
{
    hfs_gles_edit *e = &g->edit;
    double reach = 0.0;
    for (int l = 0; l + 1 < fr->L.n_layers; ++l)
        reach = fmax(reach, e->layer_reach[l]);
    hfs_tiles_clear(&e->levels);
    hfs_tiles_add_box(&e->levels, hfs_edit_box_grow(e->box, (int)ceil(reach), fr->L.w, fr->L.h));
    return &e->levels;
}

/* Whether grid receiver (gx, gy) (texels) can read box b (texels, grown by
 * its samples' reach) for local light p (local_visibility.frag): no sample
 * beyond its distance to the light's centre (the cut, min(d, rho + r) <=
 * d; `up` the most the receiver can stand below or above the centre), and
 * on a partial swath none outside the wedge of half-width asin(r / rho)
 * about the light's azimuth.  full: the frame takes the full swath
 * (tables, local_full_swath); a receiver the sphere surrounds does too. */
static int receiver_reads(const hfs_gles_layout *L, const hfs_local_light *p, double gx,
                          double gy, hfs_edit_box b, int full, double up)
{
    const double lx = p->pos[0] / L->dx, ly = p->pos[1] / L->dx;
    const double rho = hypot(lx - gx, ly - gy) * L->dx;
    const double nx = gx < b.x0 ? b.x0 - gx : (gx > b.x1 ? gx - b.x1 : 0.0);
    const double ny = gy < b.y0 ? b.y0 - gy : (gy > b.y1 ? gy - b.y1 : 0.0);
    if (hypot(nx, ny) * L->dx > sqrt(rho * rho + up * up) + p->radius + L->dx)
        return 0;
    if (nx == 0.0 && ny == 0.0)
        return 1;
    if (full || p->radius >= rho - 2.0 * L->dx)
        return 1;
    /* the box's angles from the receiver about the light's azimuth: an
     * interval wider than pi wraps through the back (the box is behind) */
    const double phi = atan2(ly - gy, lx - gx);
    const double half = asin(p->radius / (rho - L->dx)) + 0.02;
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (int c = 0; c < 4; ++c) {
        const double a =
            remainder(atan2((c & 2 ? b.y1 : b.y0) - gy, (c & 1 ? b.x1 : b.x0) - gx) - phi,
                      2.0 * 3.14159265358979323846);
        lo = fmin(lo, a);
        hi = fmax(hi, a);
    }
    return hi - lo <= 3.14159265358979323846 && hi >= -half && lo <= half;
}

const hfs_tiles *hfs_gles_edit_local(hfs_gles *g, const hfs_gles_frame *fr)
{
    hfs_gles_edit *e = &g->edit;
    const hfs_gles_layout *L = &fr->L;
    double reach = 0.0;
    for (int l = 0; l < L->n_layers; ++l)
        reach = fmax(reach, e->layer_reach[l]);
    /* each sample within its level's reach of what it reads */
    const hfs_edit_box b = hfs_edit_box_grow(e->box, (int)ceil(reach) + 2, 1 << 30, 1 << 30);
    /* the receivers' heights lie in the field's range (lifted by 1e-4 dx) */
    const double zmin = L->zscale * (L->base - L->hscale);
    const double zmax = L->zscale * (L->base + L->hscale);
    const int full = fr->tables || fr->q->local_full_swath;
    hfs_tiles_clear(&e->local);
    for (int a = 0; a < L->vh; ++a) {
        const int gy = a * L->sub < L->h - 1 ? a * L->sub : L->h - 1;
        for (int c = 0; c < L->vw; ++c) {
            const int gx = c * L->sub < L->w - 1 ? c * L->sub : L->w - 1;
            unsigned char *on =
                &e->local.on[(size_t)(gy / HFS_EDIT_TILE) * e->local.tw + gx / HFS_EDIT_TILE];
            for (int i = 0; i < fr->n_local && !*on; ++i) {
                const hfs_local_light *p = &fr->local[i];
                const double up =
                    fmax(fabs(p->pos[2] - zmin), fabs(p->pos[2] - zmax)) + 1e-3 * L->dx;
                *on = (unsigned char)receiver_reads(L, p, gx, gy, b, full, up);
            }
        }
    }
    /* the shading reads the ratios bilinearly from the receivers around */
    hfs_tiles_add_grown(&e->shade, &e->local, L->sub + 1);
    return &e->local;
}
