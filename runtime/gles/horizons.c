/*
 * horizons.c — the GIS horizons on the GLES path (hfs_renderer_horizons):
 * the heights as the frame uploads them (normalized fp16 hi + lo) and the
 * gap search's bounds (bounds_texture.h) in textures of this call's own,
 * then horizons.frag over the field, two azimuths a draw into one RGBA
 * target (each angle an fp16 hi + lo pair), read back after each draw.
 * Outside the frame like the point queries (shm_query.c): the frame's
 * caches and plan are untouched.
 *
 * A field over the profile's texture limit is searched in tiles: each
 * tile's inner part with a halo of the radius (+ 2 texels) around it, cut
 * to the field. A search within the radius reads only crossings within
 * it, so an inner texel's answer is the whole field's (up to each tile's
 * own fp16 normalization); the grid's exit (horizons.frag exit_slope)
 * lies past the radius at a halo's cut and counts only at the field's own
 * edge. Without a radius no halo is enough: the call says so.
 */
#include "gles_backend.h"

#include "bounds_texture.h"
#include "field_geom.h"
#include "gl_util.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct horizon_targets {
    GLuint heights, bounds, out, fbo;
} horizon_targets;

static void targets_free(const hfs_gl *gl, horizon_targets *t)
{
    if (t->fbo)
        gl->DeleteFramebuffers(1, &t->fbo);
    hfs_gles_tex_delete(gl, &t->heights);
    hfs_gles_tex_delete(gl, &t->bounds);
    hfs_gles_tex_delete(gl, &t->out);
}

/* The call begun (hfs_gles_begin_outside), the heights and bounds
 * uploaded. */
static int begin(hfs_gles *g, const hfs_field *f, const hfs_quality *q, hfs_gles_layout *L,
                 horizon_targets *t, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    int rc = hfs_gles_begin_outside(g, f, q, L, "horizons", err);
    if (rc)
        return rc;
    const hfs_gl_caps *c = &g->caps;
    /* one layer of an array: the gap search reads the frame's level array */
    t->heights = hfs_gles_tex_new(gl, GL_TEXTURE_2D_ARRAY, c->fmt_rg, L->w, L->h, 1, 0);
    t->bounds = hfs_gles_tex_new(gl, GL_TEXTURE_2D, c->fmt_r, L->rb.aw, L->rb.ah, 1, 0);
    t->out = hfs_gles_tex_new(gl, GL_TEXTURE_2D, c->fmt_rgba, L->w, L->h, 1, 0);
    if ((rc = hfs_gles_fbo_new(gl, &t->fbo, 1, &t->out, NULL, "horizons", err)))
        return rc;
    const size_t n = (size_t)L->w * (size_t)L->h, up = n * 2 * (c->fp32 ? 4 : 2);
    const size_t work = hfs_gles_bounds_work_bytes(L);
    void *buf = hfs_gles_scratch(g, up > work ? up : work);
    if (!buf)
        return hfs_fail(err, HFS_E_NOMEM, "horizons: out of memory for a %dx%d upload", L->w,
                        L->h);
    hfs_gles_split_heights(L, f, c->fp32, buf, 0);
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 4);
    gl->BindTexture(GL_TEXTURE_2D_ARRAY, t->heights);
    gl->TexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, 0, L->w, L->h, 1, GL_RG, c->type_upload, buf);
    gl->BindTexture(GL_TEXTURE_2D_ARRAY, 0);
    if ((rc = hfs_gles_bounds_upload(gl, c, t->bounds, L, f, buf, err)))
        return rc;
    return hfs_gl_check(gl, "horizons: upload", err);
}

/* Where a sub-field's results go: its origin in the whole field (fw x fh,
 * out's planes) and the part of it that is kept (inner, in its own
 * coordinates). */
typedef struct horizon_window {
    int fw, fh, x0, y0;
    int ix, iy, iw, ih;
} horizon_window;

/* Azimuths a and a + 1 (or a alone, the last of an odd count) into out. */
static int draw_pair(hfs_gles *g, const hfs_gles_layout *L, const horizon_targets *t,
                     const hfs_horizon_desc *d, int a, const horizon_window *win, float *out,
                     hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    const hfs_gles_variant v = {.fp32 = g->caps.fp32, .cells = 1};
    const hfs_gles_program *prog;
    int rc = hfs_gles_program_use(&g->programs, gl, HFS_PROG_HORIZONS, &v, &prog, err);
    if (rc || (rc = hfs_gles_bind_ray(gl, prog, L, t->heights, 0, t->bounds, err)))
        return rc;
    const int two = a + 1 < d->n_azimuths;
    double cs[4];
    hfs_horizon_dir(d->azimuth[a], &cs[0], &cs[1]);
    hfs_horizon_dir(d->azimuth[two ? a + 1 : a], &cs[2], &cs[3]);
    const double reach = d->radius > 0.0 ? d->radius / L->dx : 1e9;
    hfs_gles_set_i2(gl, prog, "u_size", L->w, L->h);
    hfs_gles_set_f1(gl, prog, "u_reach", (float)(reach < 1e9 ? reach : 1e9));
    hfs_gles_set_f4(gl, prog, "u_cs", cs);
    hfs_gles_set_i1(gl, prog, "u_pair", two);
    /* the window's slopes: where the search starts and where it stops */
    const double win_lo = d->window ? fmax(tan(d->lo), -1e30) : -1e30;
    const double win_hi = d->window && d->hi < 1.5707 ? tan(d->hi) : 1e30;
    hfs_gles_set_f2(gl, prog, "u_window", (float)win_lo, (float)win_hi);
    hfs_gles_draw(gl, t->fbo, L->w, L->h);
    gl->UseProgram(0);
    float *px = hfs_gles_scratch(g, (size_t)win->iw * (size_t)win->ih * 4 * sizeof *px);
    if (!px)
        return hfs_fail(err, HFS_E_NOMEM, "horizons: out of memory for a %dx%d read-back",
                        win->iw, win->ih);
    if ((rc = hfs_gl_read_rgba(gl, t->fbo, win->ix, win->iy, win->iw, win->ih,
                               HFS_GL_READ_AUTO, px, NULL, err)))
        return rc;
    const size_t plane = (size_t)win->fw * (size_t)win->fh;
    for (int k = 0; k <= two; ++k)
        for (int j = 0; j < win->ih; ++j) {
            float *dst = out + plane * (size_t)(a + k) +
                         (size_t)(win->y0 + win->iy + j) * (size_t)win->fw + win->x0 + win->ix;
            const float *src = px + (size_t)j * (size_t)win->iw * 4 + 2 * k;
            for (int i = 0; i < win->iw; ++i) { /* hi + lo; -2: no terrain, 2: the window's top */
                const float hl = src[4 * i] + src[4 * i + 1];
                dst[i] = hl > 1.75f ? (float)d->hi : hl > -1.75f ? hl : HFS_HORIZON_NONE;
            }
        }
    return HFS_OK;
}

/* Every azimuth of field f (a sub-field at win) into out. */
static int search(hfs_gles *g, const hfs_field *f, const hfs_quality *q,
                  const hfs_horizon_desc *d, const horizon_window *win, float *out,
                  hfs_error *err)
{
    hfs_gles_layout L;
    horizon_targets t = {0, 0, 0, 0};
    int rc = begin(g, f, q, &L, &t, err);
    for (int a = 0; a < d->n_azimuths && !rc; a += 2)
        rc = draw_pair(g, &L, &t, d, a, win, out, err);
    targets_free(&g->gl, &t);
    return rc;
}

/* The tiles of a field over the texture limit m: inner parts of m - 2 halo
 * texels, each searched with its halo. */
static int search_tiles(hfs_gles *g, const hfs_field *f, const hfs_quality *q,
                        const hfs_horizon_desc *d, int m, float *out, hfs_error *err)
{
    if (!(d->radius > 0.0))
        return hfs_fail(err, HFS_E_UNSUPPORTED, "horizons: a %dx%d field exceeds the %d-texel "
                        "texture limit and the search has no radius: give a radius (the tiles' "
                        "halo) or use the cpu backend", f->width, f->height, m);
    const double rt = ceil(d->radius / f->dx) + 2.0;
    const int inner = rt < m ? m - 2 * (int)rt : 0;
    if (inner < 16)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "horizons: a radius of %.0f texels leaves no "
                        "room in tiles of %d texels: a smaller radius, or the cpu backend", rt,
                        m);
    const int halo = (int)rt;
    float *z = malloc((size_t)m * (size_t)m * sizeof *z);
    if (!z)
        return hfs_fail(err, HFS_E_NOMEM, "horizons: out of memory for a %d-texel tile", m);
    int rc = HFS_OK;
    for (int ty = 0; ty < f->height && !rc; ty += inner)
        for (int tx = 0; tx < f->width && !rc; tx += inner) {
            const int x0 = tx > halo ? tx - halo : 0, y0 = ty > halo ? ty - halo : 0;
            const int x1 = tx + inner + halo < f->width ? tx + inner + halo : f->width;
            const int y1 = ty + inner + halo < f->height ? ty + inner + halo : f->height;
            for (int j = y0; j < y1; ++j)
                memcpy(z + (size_t)(j - y0) * (size_t)(x1 - x0),
                       f->z + (size_t)j * (size_t)f->width + x0, (size_t)(x1 - x0) * sizeof *z);
            const hfs_field sub = {x1 - x0, y1 - y0, z, f->dx, f->zscale};
            const int iw = tx + inner < f->width ? inner : f->width - tx;
            const int ih = ty + inner < f->height ? inner : f->height - ty;
            const horizon_window win = {f->width, f->height, x0, y0, tx - x0, ty - y0, iw, ih};
            rc = search(g, &sub, q, d, &win, out, err);
        }
    free(z);
    return rc;
}

int hfs_gles_horizons(hfs_gles *g, const hfs_field *f, const hfs_quality *q,
                      const hfs_horizon_desc *d, float *out, hfs_error *err)
{
    int rc = hfs_gles_select_caps(g, q, err);
    if (rc)
        return rc;
    const int m = g->caps.max_texture_size;
    const horizon_window whole = {f->width, f->height, 0, 0, 0, 0, f->width, f->height};
    rc = f->width <= m && f->height <= m ? search(g, f, q, d, &whole, out, err)
                                         : search_tiles(g, f, q, d, m, out, err);
    return rc ? rc : hfs_gl_check(&g->gl, "backend gles: horizons", err);
}
