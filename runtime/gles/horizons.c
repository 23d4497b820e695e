/*
 * horizons.c — the GIS horizons on the GLES path (hfs_renderer_horizons):
 * the heights as the frame uploads them (normalized fp16 hi + lo) and the
 * gap search's bounds (bounds_texture.h) in textures of this call's own,
 * then horizons.frag over the field, two azimuths a draw into one RGBA
 * target (each angle an fp16 hi + lo pair), read back after each draw.
 * Outside the frame like the point queries (shm_query.c): the frame's
 * caches and plan are untouched.
 */
#include "gles_backend.h"

#include "bounds_texture.h"
#include "field_geom.h"
#include "gl_util.h"

#include <math.h>
#include <stdlib.h>

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
    t->heights = hfs_gles_tex_new(gl, GL_TEXTURE_2D, c->fmt_rg, L->w, L->h, 1, 0);
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
    hfs_gles_split_heights(L, f, c->fp32, buf);
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 4);
    gl->BindTexture(GL_TEXTURE_2D, t->heights);
    gl->TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, L->w, L->h, GL_RG, c->type_upload, buf);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    if ((rc = hfs_gles_bounds_upload(gl, c, t->bounds, L, f, buf, err)))
        return rc;
    return hfs_gl_check(gl, "horizons: upload", err);
}

/* Azimuths a and a + 1 (or a alone, the last of an odd count) into out. */
static int draw_pair(hfs_gles *g, const hfs_gles_layout *L, const horizon_targets *t,
                     const hfs_horizon_desc *d, int a, float *out, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    const hfs_gles_variant v = {.fp32 = g->caps.fp32};
    const hfs_gles_program *prog;
    int rc = hfs_gles_program_use(&g->programs, gl, HFS_PROG_HORIZONS, &v, &prog, err);
    if (rc || (rc = hfs_gles_bind_ray(gl, prog, L, t->heights, t->bounds, err)))
        return rc;
    const int two = a + 1 < d->n_azimuths;
    double cs[4];
    hfs_horizon_dir(d->azimuth[a], &cs[0], &cs[1]);
    hfs_horizon_dir(d->azimuth[two ? a + 1 : a], &cs[2], &cs[3]);
    const double reach = d->radius > 0.0 ? d->radius / L->dx : 1e9;
    hfs_gles_set_i2(gl, prog, "u_size", L->w, L->h);
    hfs_gles_set_f1(gl, prog, "u_reach", (float)(reach < 1e9 ? reach : 1e9));
    hfs_gles_set_f4(gl, prog, "u_cs", cs);
    hfs_gles_draw(gl, t->fbo, L->w, L->h);
    gl->UseProgram(0);
    const size_t n = (size_t)L->w * (size_t)L->h;
    float *px = hfs_gles_scratch(g, n * 4 * sizeof *px);
    if (!px)
        return hfs_fail(err, HFS_E_NOMEM, "horizons: out of memory for a %dx%d read-back",
                        L->w, L->h);
    if ((rc = hfs_gl_read_rgba(gl, t->fbo, 0, 0, L->w, L->h, HFS_GL_READ_AUTO, px, NULL, err)))
        return rc;
    for (int k = 0; k <= two; ++k) {
        float *dst = out + n * (size_t)(a + k);
        for (size_t i = 0; i < n; ++i) { /* hi + lo; -2: no terrain */
            const float hl = px[4 * i + 2 * k] + px[4 * i + 2 * k + 1];
            dst[i] = hl > -1.75f ? hl : HFS_HORIZON_NONE;
        }
    }
    return HFS_OK;
}

int hfs_gles_horizons(hfs_gles *g, const hfs_field *f, const hfs_quality *q,
                      const hfs_horizon_desc *d, float *out, hfs_error *err)
{
    hfs_gles_layout L;
    horizon_targets t = {0, 0, 0, 0};
    int rc = begin(g, f, q, &L, &t, err);
    for (int a = 0; a < d->n_azimuths && !rc; a += 2)
        rc = draw_pair(g, &L, &t, d, a, out, err);
    targets_free(&g->gl, &t);
    return rc ? rc : hfs_gl_check(&g->gl, "backend gles: horizons", err);
}
