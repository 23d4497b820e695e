/*
 * env_map_textures.c — see env_map_textures.h.
 */
#include "env_map_textures.h"

#include "gl_util.h"
#include "resources.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* n RGB values times s as RGBA at the caps' upload type. */
static void *to_rgba(const double *rgb, size_t n, double s, int fp32)
{
    void *buf = malloc(n * 4 * (fp32 ? sizeof(float) : sizeof(uint16_t)));
    if (!buf)
        return NULL;
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < 4; ++c) {
            const float v = c < 3 ? (float)(rgb[3 * i + (size_t)c] * s) : 0.0f;
            if (fp32)
                ((float *)buf)[4 * i + (size_t)c] = v;
            else
                ((uint16_t *)buf)[4 * i + (size_t)c] = hfs_float_to_half(v);
        }
    return buf;
}

static void tex_bytes(hfs_gles_env_map_textures *t)
{
    t->bytes = (t->have_open ? (size_t)HFS_ENV_OPEN_N * HFS_ENV_OPEN_N * 4 *
                                   (t->open_fp32 ? 4 : 2) : 0) +
               (t->slices ? (size_t)HFS_MAP_SLICE_E * 2 * (size_t)t->n_slices * 4 *
                                (t->slices_fp32 ? 4 : 2) : 0) +
               (t->occ ? (size_t)t->occ_w * (size_t)t->occ_h * 4 * (t->occ_fp32 ? 4 : 2) : 0) +
               (t->gloss ? (size_t)HFS_ENV_GLOSS_FLOATS / 3 * 4 * (t->gloss_fp32 ? 4 : 2) : 0);
}

/* Uploads rgb (w x h RGB, times s) into *tex, made at the caps' format. */
static int upload(GLuint *tex, const hfs_gl *gl, const hfs_gl_caps *c, const double *rgb,
                  int w, int h, double s, const char *what, hfs_error *err)
{
    void *buf = to_rgba(rgb, (size_t)w * (size_t)h, s, c->fp32);
    if (!buf)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for %s", what);
    if (!*tex)
        *tex = hfs_gles_tex_new(gl, GL_TEXTURE_2D, c->fmt_rgba, w, h, 1, 1);
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 4);
    gl->BindTexture(GL_TEXTURE_2D, *tex);
    gl->TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RGBA, c->type_upload, buf);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    free(buf);
    return hfs_gl_check(gl, what, err);
}

int hfs_gles_env_open_follow(hfs_gles_env_map_textures *t, const hfs_gl *gl,
                             const hfs_gl_caps *c, const hfs_lighting *l, hfs_error *err)
{
    if (t->have_open && t->open_fp32 == c->fp32 &&
        !memcmp(t->open_copy, l->env_open, sizeof t->open_copy))
        return HFS_OK;
    if (t->open_fp32 != c->fp32)
        hfs_gles_tex_delete(gl, &t->open);
    double d[HFS_ENV_OPEN_FLOATS];
    for (int i = 0; i < HFS_ENV_OPEN_FLOATS; ++i)
        d[i] = l->env_open[i];
    t->dmax = hfs_env_open_max(l->env_open);
    int rc = upload(&t->open, gl, c, d, HFS_ENV_OPEN_N, HFS_ENV_OPEN_N,
                    t->dmax > 0.0 ? 1.0 / t->dmax : 0.0, "the open-sky table", err);
    t->have_open = !rc;
    t->open_fp32 = c->fp32;
    memcpy(t->open_copy, l->env_open, sizeof t->open_copy);
    t->map = NULL; /* a new table: the map it stands for may be new too */
    t->gloss_map = NULL;
    tex_bytes(t);
    return rc;
}

int hfs_gles_env_slices_follow(hfs_gles_env_map_textures *t, const hfs_gl *gl,
                               const hfs_gl_caps *c, const hfs_lighting *l,
                               const hfs_slice_table *st, hfs_error *err)
{
    if (t->slices && t->map == l->env_shade_map && t->map_w == l->env_map_width &&
        t->map_h == l->env_map_height && t->n_slices == st->n && t->dphi == st->dphi &&
        t->rotate == l->env_rotate && t->slices_fp32 == c->fp32)
        return HFS_OK; /* the open table's contents (compared first) stand for the map's */
    hfs_map_slices ms;
    int rc = hfs_map_slices_build(&ms, l->env_shade_map, l->env_map_width, l->env_map_height,
                                  l->env_rotate, st->dir, st->n, st->dphi, err);
    if (rc)
        return rc;
    /* Rows 2j (F) and 2j + 1 (G) of HFS_MAP_SLICE_E texels. */
    const size_t row = HFS_MAP_SLICE_E * 3;
    double *rgb = malloc((size_t)st->n * 2 * row * sizeof *rgb);
    if (!rgb) {
        hfs_map_slices_free(&ms);
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for the map's slices");
    }
    double m = 0.0;
    for (int j = 0; j < st->n; ++j)
        for (int i = 0; i < HFS_MAP_SLICE_E; ++i)
            for (int q = 0; q < 6; ++q) {
                const double v = ms.fg[((size_t)j * HFS_MAP_SLICE_E + (size_t)i) * 6 + (size_t)q];
                rgb[(2 * (size_t)j + (size_t)(q / 3)) * row + 3 * (size_t)i + (size_t)(q % 3)] = v;
                m = fmax(m, fabs(v));
            }
    hfs_map_slices_free(&ms);
    if (t->n_slices != st->n || t->slices_fp32 != c->fp32)
        hfs_gles_tex_delete(gl, &t->slices);
    t->fmax = m;
    rc = upload(&t->slices, gl, c, rgb, HFS_MAP_SLICE_E, 2 * st->n, m > 0.0 ? 1.0 / m : 0.0,
                "the map's slices", err);
    free(rgb);
    t->map = l->env_shade_map;
    t->map_w = l->env_map_width, t->map_h = l->env_map_height;
    t->n_slices = st->n, t->dphi = st->dphi, t->rotate = l->env_rotate;
    t->slices_fp32 = c->fp32;
    if (rc)
        hfs_gles_tex_delete(gl, &t->slices);
    tex_bytes(t);
    return rc;
}

int hfs_gles_env_gloss_follow(hfs_gles_env_map_textures *t, const hfs_gl *gl,
                              const hfs_gl_caps *c, const hfs_lighting *l, double s,
                              hfs_error *err)
{
    if (t->gloss && t->gloss_map == l->env_shade_map && t->gloss_w == l->env_map_width &&
        t->gloss_h == l->env_map_height && t->gloss_s == s && t->gloss_fp32 == c->fp32)
        return HFS_OK; /* the open table's contents (compared first) stand for the map's */
    float *table = malloc(HFS_ENV_GLOSS_FLOATS * sizeof *table);
    double *rgb = malloc(HFS_ENV_GLOSS_FLOATS * sizeof *rgb);
    int rc = !table || !rgb ? hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for the "
                                       "glossy table")
                            : hfs_env_gloss_build(l->env_shade_map, l->env_map_width,
                                                  l->env_map_height,
                                                  (const double(*)[HFS_SH_COEFFS])l->env_sh, s,
                                                  table, err);
    if (!rc) {
        for (int i = 0; i < HFS_ENV_GLOSS_FLOATS; ++i)
            rgb[i] = table[i];
        t->gmax = hfs_env_gloss_max(table);
        if (t->gloss_fp32 != c->fp32)
            hfs_gles_tex_delete(gl, &t->gloss);
        rc = upload(&t->gloss, gl, c, rgb, HFS_ENV_GLOSS_NW + 1, HFS_ENV_GLOSS_NH,
                    t->gmax > 0.0 ? 1.0 / t->gmax : 0.0, "the glossy table", err);
    }
    free(table);
    free(rgb);
    t->gloss_map = rc ? NULL : l->env_shade_map;
    t->gloss_w = l->env_map_width, t->gloss_h = l->env_map_height;
    t->gloss_s = s, t->gloss_fp32 = c->fp32;
    if (rc)
        hfs_gles_tex_delete(gl, &t->gloss);
    tex_bytes(t);
    return rc;
}

int hfs_gles_env_occ_ensure(hfs_gles_env_map_textures *t, const hfs_gl *gl,
                            const hfs_gl_caps *c, int w, int h, hfs_error *err)
{
    if (t->occ && t->occ_w == w && t->occ_h == h && t->occ_fp32 == c->fp32)
        return HFS_OK;
    if (t->occ_fbo)
        gl->DeleteFramebuffers(1, &t->occ_fbo);
    t->occ_fbo = 0;
    hfs_gles_tex_delete(gl, &t->occ);
    ++t->occ_gen;
    t->occ_w = t->occ_h = 0;
    if (w > 0 && h > 0) {
        t->occ = hfs_gles_tex_new(gl, GL_TEXTURE_2D, c->fmt_rgba, w, h, 1, 0);
        int rc = hfs_gles_fbo_new(gl, &t->occ_fbo, 1, &t->occ, NULL, "env map occlusion", err);
        if (rc) {
            hfs_gles_tex_delete(gl, &t->occ);
            return rc;
        }
        t->occ_w = w, t->occ_h = h, t->occ_fp32 = c->fp32;
    }
    tex_bytes(t);
    return HFS_OK;
}

void hfs_gles_env_map_textures_free(hfs_gles_env_map_textures *t, const hfs_gl *gl)
{
    if (t->occ_fbo)
        gl->DeleteFramebuffers(1, &t->occ_fbo);
    if (t->occ)
        ++t->occ_gen;
    hfs_gles_tex_delete(gl, &t->occ);
    hfs_gles_tex_delete(gl, &t->open);
    hfs_gles_tex_delete(gl, &t->slices);
    hfs_gles_tex_delete(gl, &t->gloss);
    const unsigned gen = t->occ_gen;
    memset(t, 0, sizeof *t);
    t->occ_gen = gen;
}
