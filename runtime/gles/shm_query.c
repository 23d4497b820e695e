/*
 * shm_query.c — key-light visibility of points above the field on the
 * GLES path (hfs_renderer_query_points; runtime/core/shm.h): each key light's
 * shadow height maps at HFS_SHM_LAYERS elevations across its disk, built
 * on the GPU by shm_double.frag's doubling passes (ping-pong between two
 * fp16 targets holding the normalized S as hi + lo, as the heights), read
 * back and sampled at each point exactly as the CPU reference samples its
 * own (hfs_shm_sample, hfs_shm_disk_fraction).  Outside the frame: the
 * frame's caches and plan are untouched.
 */
#include "gles_backend.h"

#include "gl_util.h"
#include "shm.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

typedef struct shm_targets {
    GLuint tex[2], fbo[2];
} shm_targets;

static void targets_free(const hfs_gl *gl, shm_targets *t)
{
    for (int k = 0; k < 2; ++k) {
        if (t->fbo[k])
            gl->DeleteFramebuffers(1, &t->fbo[k]);
        hfs_gles_tex_delete(gl, &t->tex[k]);
    }
}

/* Uploads the normalized heights (hi, lo, 0, 0) into target 0 (RGBA: the
 * targets are read back as every target is). */
static int upload(hfs_gles *g, const hfs_gles_layout *L, const hfs_field *f, shm_targets *t,
                  hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    const int fp32 = g->caps.fp32;
    const size_t n = (size_t)L->w * (size_t)L->h, unit = fp32 ? 4 : 2;
    unsigned char *buf = hfs_gles_scratch(g, n * 6 * unit);
    if (!buf)
        return hfs_fail(err, HFS_E_NOMEM, "query: out of memory for a %dx%d upload", L->w, L->h);
    unsigned char *rg = buf + n * 4 * unit;
    hfs_gles_split_heights(L, f, fp32, rg, 0);
    memset(buf, 0, n * 4 * unit);
    for (size_t i = 0; i < n; ++i)
        memcpy(buf + 4 * unit * i, rg + 2 * unit * i, 2 * unit);
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 4);
    gl->BindTexture(GL_TEXTURE_2D, t->tex[0]);
    gl->TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, L->w, L->h, GL_RGBA, g->caps.type_upload, buf);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    return hfs_gl_check(gl, "query: height upload", err);
}

/* S of the light (phi, elev) in world z into s (W*H): the doubling passes
 * from the heights in target 0, read back. */
static int build(hfs_gles *g, const hfs_gles_layout *L, const hfs_field *f, shm_targets *t,
                 double phi, double elev, float *s, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    int rc = upload(g, L, f, t, err);
    if (rc)
        return rc;
    int cur = 0;
    /* A light at or past the zenith, or a flat world: S = H. */
    if (elev < 0.5 * PI - 1e-9 && f->zscale > 0.0) {
        const hfs_gles_variant v = {.fp32 = g->caps.fp32};
        const hfs_gles_program *prog;
        if ((rc = hfs_gles_program_use(&g->programs, gl, HFS_PROG_SHM, &v, &prog, err)))
            return rc;
        hfs_gles_set_i2(gl, prog, "u_size", L->w, L->h);
        const double rise = f->dx * tan(elev) / (f->zscale * L->hscale); /* normalized */
        for (int j = 0; j < hfs_shm_passes(L->w, L->h) && !rc; ++j) {
            const double step = ldexp(1.0, j);
            rc = hfs_gles_program_texture(gl, prog, "u_src", GL_TEXTURE_2D, t->tex[cur], err);
            hfs_gles_set_f2(gl, prog, "u_off", (float)(step * cos(phi)), (float)(step * sin(phi)));
            hfs_gles_set_f1(gl, prog, "u_drop", (float)(step * rise));
            hfs_gles_draw(gl, t->fbo[1 - cur], L->w, L->h);
            cur = 1 - cur;
        }
        gl->UseProgram(0);
    }
    const size_t n = (size_t)L->w * (size_t)L->h;
    float *px = hfs_gles_scratch(g, n * 4 * sizeof *px);
    if (!px)
        return hfs_fail(err, HFS_E_NOMEM, "query: out of memory for a %dx%d read-back", L->w,
                        L->h);
    if (!rc && (rc = hfs_gl_read_rgba(gl, t->fbo[cur], 0, 0, L->w, L->h, HFS_GL_READ_AUTO, px,
                                      NULL, err)) == HFS_OK)
        for (size_t i = 0; i < n; ++i) /* v = (z - base) / hscale, world = zscale z */
            s[i] = (float)(f->zscale * (L->base + L->hscale * ((double)px[4 * i] + px[4 * i + 1])));
    return rc;
}

/* The call begun (hfs_gles_begin_outside) and the two targets. */
static int begin(hfs_gles *g, const hfs_field *f, const hfs_quality *q, hfs_gles_layout *L,
                 shm_targets *t, hfs_error *err)
{
    int rc = hfs_gles_begin_outside(g, f, q, L, "shadow height map", err);
    if (rc)
        return rc;
    for (int k = 0; k < 2 && !rc; ++k) { /* RGBA: read back as every target is */
        t->tex[k] = hfs_gles_tex_new(&g->gl, GL_TEXTURE_2D, g->caps.fmt_rgba, L->w, L->h, 1, 0);
        rc = hfs_gles_fbo_new(&g->gl, &t->fbo[k], 1, &t->tex[k], NULL, "shadow height map", err);
    }
    return rc;
}

int hfs_gles_shadow_height_map(hfs_gles *g, const hfs_field *f, const hfs_key_light *k,
                               const hfs_quality *q, int layer, float *out, hfs_error *err)
{
    hfs_gles_layout L;
    shm_targets t = {{0, 0}, {0, 0}};
    int rc = begin(g, f, q, &L, &t, err);
    if (!rc)
        rc = build(g, &L, f, &t, k->phi, hfs_shm_layer_elevation(k->elev, k->alpha, layer), out,
                   err);
    targets_free(&g->gl, &t);
    return rc ? rc : hfs_gl_check(&g->gl, "backend gles: shadow height map", err);
}

int hfs_gles_query_points(hfs_gles *g, const hfs_field *f, const hfs_lighting *l,
                          const hfs_quality *q, const double *xyz, int n, float *vis,
                          hfs_error *err)
{
    hfs_gles_layout L;
    shm_targets t = {{0, 0}, {0, 0}};
    int rc = begin(g, f, q, &L, &t, err);
    const hfs_gl *gl = &g->gl;
    const size_t cells = (size_t)f->width * (size_t)f->height;
    float *maps = rc ? NULL : malloc(HFS_SHM_LAYERS * cells * sizeof *maps);
    if (!rc && !maps)
        rc = hfs_fail(err, HFS_E_NOMEM, "query: out of memory for %d shadow height maps",
                      HFS_SHM_LAYERS);
    for (int k = 0; k < l->n_key && !rc; ++k) {
        const hfs_key_light *kl = &l->key[k];
        for (int m = 0; m < HFS_SHM_LAYERS && !rc; ++m)
            rc = build(g, &L, f, &t, kl->phi, hfs_shm_layer_elevation(kl->elev, kl->alpha, m),
                       maps + (size_t)m * cells, err);
        for (int i = 0; i < n && !rc; ++i) {
            const double *p = xyz + 3 * (size_t)i;
            double s[HFS_SHM_LAYERS];
            for (int m = 0; m < HFS_SHM_LAYERS; ++m)
                s[m] = hfs_shm_sample(maps + (size_t)m * cells, L.w, L.h, p[0] / f->dx,
                                      p[1] / f->dx);
            vis[(size_t)i * (size_t)l->n_key + (size_t)k] = (float)hfs_shm_disk_fraction(s, p[2]);
        }
    }
    targets_free(gl, &t);
    free(maps);
    return rc ? rc : hfs_gl_check(gl, "backend gles: shadow height maps", err);
}
