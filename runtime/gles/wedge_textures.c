/*
 * wedge_textures.c — see wedge_textures.h.
 */
#include "wedge_textures.h"

#include "gl_util.h"
#include "resources.h"
#include "visibility.h"

#include <stdint.h>

#define TABLE_N HFS_VIS_TABLE_SIZE

size_t hfs_gles_wedge_scratch_bytes(void)
{
    return (size_t)TABLE_N * TABLE_N * 4 * sizeof(float);
}

/* Tables of extent dphi (boundary dphi/2), cached (visibility.c builds
 * exactly these: hfs_wedge_tables_create_ext(dphi, dphi/2, 257)). */
static hfs_wedge_tables *tables_get(hfs_gles_wedge_textures *w, double dphi, hfs_error *err)
{
    ++w->clock;
    int victim = 0;
    for (int i = 0; i < HFS_GLES_TABLE_CACHE; ++i) {
        if (w->cache[i].t && w->cache[i].dphi == dphi) {
            w->cache[i].used = w->clock;
            return w->cache[i].t;
        }
        if (!w->cache[i].t || w->cache[i].used < w->cache[victim].used)
            victim = i;
        if (!w->cache[i].t)
            break;
    }
    hfs_wedge_tables *t = hfs_wedge_tables_create_ext(dphi, 0.5 * dphi, TABLE_N);
    if (!t) {
        hfs_fail(err, HFS_E_NOMEM, "backend gles: cannot build wedge tables for dphi = %g", dphi);
        return NULL;
    }
    hfs_wedge_tables_destroy(w->cache[victim].t);
    w->cache[victim].t = t;
    w->cache[victim].dphi = dphi;
    w->cache[victim].used = w->clock;
    return t;
}

/* Uploads interior (and boundary) tables as set `set` of 4 layers
 * (coefficients 4g..4g+3 in layer 4*set + g). */
static int tables_upload(const hfs_gl *gl, const hfs_gl_caps *c, const hfs_wedge_tables *t,
                         GLuint tab, GLuint tabb, int set, void *buf, hfs_error *err)
{
    const int n = hfs_wedge_tables_size(t), fp32 = c->fp32;
    for (int pass = 0; pass < 2; ++pass) {
        GLuint tex = pass ? tabb : tab;
        if (!tex)
            continue;
        const double *src = pass ? hfs_wedge_boundary_data(t) : hfs_wedge_interior_data(t);
        const size_t rows = pass ? 1 : (size_t)n;
        for (int grp = 0; grp < 4; ++grp) {
            for (size_t e = 0; e < rows * (size_t)n; ++e)
                for (int k = 0; k < 4; ++k) {
                    const double v = src[e * 16 + (size_t)(4 * grp + k)];
                    if (fp32)
                        ((float *)buf)[e * 4 + (size_t)k] = (float)v;
                    else
                        ((uint16_t *)buf)[e * 4 + (size_t)k] = hfs_float_to_half((float)v);
                }
            gl->BindTexture(GL_TEXTURE_2D_ARRAY, tex);
            gl->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
            gl->TexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, 4 * set + grp, n, (GLsizei)rows, 1,
                              GL_RGBA, c->type_upload, buf);
            gl->PixelStorei(GL_UNPACK_ALIGNMENT, 4);
        }
    }
    gl->BindTexture(GL_TEXTURE_2D_ARRAY, 0);
    return hfs_gl_check(gl, "backend gles: wedge table upload", err);
}

void hfs_gles_wedge_textures_follow(hfs_gles_wedge_textures *w, const hfs_gl *gl,
                                    const hfs_gl_caps *c)
{
    if ((w->env || w->keys || w->local) && w->fp32 != c->fp32) {
        hfs_gles_tex_delete(gl, &w->env);
        hfs_gles_tex_delete(gl, &w->keys);
        hfs_gles_tex_delete(gl, &w->keys_boundary);
        hfs_gles_tex_delete(gl, &w->local);
        w->key_sets = 0;
        w->bytes = 0;
    }
    w->fp32 = c->fp32;
}

/* One full-swath table texture (environment or local lights). */
static int single_table(hfs_gles_wedge_textures *w, const hfs_gl *gl, const hfs_gl_caps *c,
                        GLuint *tex, double *tex_dphi, double dphi, void *buf, hfs_error *err)
{
    if (*tex && *tex_dphi == dphi)
        return HFS_OK;
    hfs_wedge_tables *t = tables_get(w, dphi, err);
    if (!t)
        return HFS_E_NOMEM;
    if (!*tex) {
        *tex = hfs_gles_tex_new(gl, GL_TEXTURE_2D_ARRAY, c->fmt_rgba, TABLE_N, TABLE_N, 4, 1);
        w->bytes += (size_t)TABLE_N * TABLE_N * 4 * c->bytes_rgba;
    }
    int rc = tables_upload(gl, c, t, *tex, 0, 0, buf, err);
    if (!rc)
        *tex_dphi = dphi;
    return rc;
}

int hfs_gles_wedge_env(hfs_gles_wedge_textures *w, const hfs_gl *gl, const hfs_gl_caps *c,
                       double dphi, void *scratch, hfs_error *err)
{
    return single_table(w, gl, c, &w->env, &w->env_dphi, dphi, scratch, err);
}

int hfs_gles_wedge_local(hfs_gles_wedge_textures *w, const hfs_gl *gl, const hfs_gl_caps *c,
                         double dphi, void *scratch, hfs_error *err)
{
    return single_table(w, gl, c, &w->local, &w->local_dphi, dphi, scratch, err);
}

int hfs_gles_wedge_keys(hfs_gles_wedge_textures *w, const hfs_gl *gl, const hfs_gl_caps *c,
                        const double *dphi, int n_sets, void *scratch, hfs_error *err)
{
    int same = w->keys && w->key_sets >= n_sets;
    for (int s = 0; s < n_sets && same; ++s)
        same = w->key_dphi[s] == dphi[s];
    if (same)
        return HFS_OK;
    const size_t set_bytes = (size_t)TABLE_N * (TABLE_N + 1) * 4 * c->bytes_rgba;
    if (w->key_sets < n_sets) {
        if (w->keys)
            w->bytes -= set_bytes * (size_t)w->key_sets;
        hfs_gles_tex_delete(gl, &w->keys);
        hfs_gles_tex_delete(gl, &w->keys_boundary);
        w->keys = hfs_gles_tex_new(gl, GL_TEXTURE_2D_ARRAY, c->fmt_rgba, TABLE_N, TABLE_N,
                                   4 * n_sets, 1);
        w->keys_boundary = hfs_gles_tex_new(gl, GL_TEXTURE_2D_ARRAY, c->fmt_rgba, TABLE_N, 1,
                                            4 * n_sets, 1);
        w->key_sets = n_sets;
        w->bytes += set_bytes * (size_t)n_sets;
    }
    for (int s = 0; s < n_sets; ++s) {
        hfs_wedge_tables *t = tables_get(w, dphi[s], err);
        if (!t)
            return HFS_E_NOMEM;
        int rc = tables_upload(gl, c, t, w->keys, w->keys_boundary, s, scratch, err);
        if (rc)
            return rc;
        w->key_dphi[s] = dphi[s];
    }
    return HFS_OK;
}

void hfs_gles_wedge_textures_free(hfs_gles_wedge_textures *w, const hfs_gl *gl)
{
    if (gl) {
        hfs_gles_tex_delete(gl, &w->env);
        hfs_gles_tex_delete(gl, &w->keys);
        hfs_gles_tex_delete(gl, &w->keys_boundary);
        hfs_gles_tex_delete(gl, &w->local);
    }
    for (int i = 0; i < HFS_GLES_TABLE_CACHE; ++i) {
        hfs_wedge_tables_destroy(w->cache[i].t);
        w->cache[i].t = NULL;
    }
}
