/*
 * albedo_texture.c — see albedo_texture.h.
 */
#include "albedo_texture.h"

#include "gl_util.h"
#include "resources.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

void hfs_gles_albedo_texture_free(hfs_gles_albedo_texture *a, const hfs_gl *gl)
{
    if (a->tex)
        ++a->gen;
    hfs_gles_tex_delete(gl, &a->tex);
    free(a->copy);
    a->copy = NULL;
    a->w = a->h = 0;
    a->bytes = 0;
}

/* RGB -> RGBA at the upload type, into a scratch of w*h*4 elements. */
static void *to_rgba(const float *map, size_t n, int fp32)
{
    void *buf = malloc(n * 4 * (fp32 ? sizeof(float) : sizeof(uint16_t)));
    if (!buf)
        return NULL;
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < 4; ++c) {
            const float v = c < 3 ? map[3 * i + (size_t)c] : 1.0f;
            if (fp32)
                ((float *)buf)[4 * i + (size_t)c] = v;
            else
                ((uint16_t *)buf)[4 * i + (size_t)c] = hfs_float_to_half(v);
        }
    return buf;
}

int hfs_gles_albedo_texture_follow(hfs_gles_albedo_texture *a, const hfs_gl *gl,
                                   const hfs_gl_caps *c, const float *map, int w, int h,
                                   hfs_error *err)
{
    if (!map) {
        if (a->tex)
            hfs_gles_albedo_texture_free(a, gl);
        return HFS_OK;
    }
    const size_t n = (size_t)w * (size_t)h;
    if (a->tex && a->w == w && a->h == h && a->fp32 == c->fp32 &&
        !memcmp(a->copy, map, n * 3 * sizeof *map))
        return HFS_OK;
    if (!a->tex || a->w != w || a->h != h || a->fp32 != c->fp32) {
        hfs_gles_albedo_texture_free(a, gl);
        a->copy = malloc(n * 3 * sizeof *map);
        if (!a->copy)
            return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for the albedo map");
        a->tex = hfs_gles_tex_new(gl, GL_TEXTURE_2D, c->fmt_rgba, w, h, 1, 0);
        a->w = w, a->h = h, a->fp32 = c->fp32;
        a->bytes = n * 4 * (c->fp32 ? 4 : 2);
    }
    void *buf = to_rgba(map, n, c->fp32);
    if (!buf) {
        hfs_gles_albedo_texture_free(a, gl);
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for the albedo map");
    }
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 4);
    gl->BindTexture(GL_TEXTURE_2D, a->tex);
    gl->TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RGBA, c->type_upload, buf);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    free(buf);
    memcpy(a->copy, map, n * 3 * sizeof *map);
    ++a->gen;
    return hfs_gl_check(gl, "backend gles: albedo map upload", err);
}
