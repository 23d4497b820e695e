/*
 * block_texture.c — see block_texture.h.
 */
#include "block_texture.h"

#include "gl_util.h"
#include "resources.h"

#include <stdint.h>
#include <string.h>

static int rows_for(size_t n_vec4)
{
    const size_t texels = 2 * n_vec4;
    return (int)((texels + HFS_GLES_BLOCK_TEX_W - 1) / HFS_GLES_BLOCK_TEX_W);
}

int hfs_gles_block_too_big(const hfs_gl_caps *c, size_t n_vec4)
{
    return n_vec4 * 16 > (size_t)c->max_uniform_block_size;
}

int hfs_gles_block_texture_check(const hfs_gl_caps *c, size_t n_vec4, const char *what,
                                 hfs_error *err)
{
    const int rows = rows_for(n_vec4);
    return hfs_gl_caps_check_texture(c, HFS_GLES_BLOCK_TEX_W, rows > 0 ? rows : 1, 1, what, err);
}

int hfs_gles_block_texture_upload(hfs_gles_block_texture *bt, const hfs_gl *gl,
                                  const hfs_gl_caps *c, const float *data, size_t n_vec4,
                                  void *scratch, const char *what, hfs_error *err)
{
    int rc = hfs_gles_block_texture_check(c, n_vec4, what, err);
    if (rc)
        return rc;
    const int rows = rows_for(n_vec4) > 0 ? rows_for(n_vec4) : 1;
    if (!bt->tex || bt->rows < rows) {
        hfs_gles_tex_delete(gl, &bt->tex);
        bt->tex = hfs_gles_tex_new(gl, GL_TEXTURE_2D, c->fmt_block, HFS_GLES_BLOCK_TEX_W, rows, 1,
                                   0);
        bt->rows = rows;
        bt->bytes = (size_t)HFS_GLES_BLOCK_TEX_W * rows * 8;
    }
    /* Each float's bits as (high, low) 16-bit halves, in the float's order. */
    uint16_t *px = scratch;
    const size_t n_float = 4 * n_vec4;
    for (size_t i = 0; i < n_float; ++i) {
        uint32_t u;
        memcpy(&u, &data[i], sizeof u);
        px[2 * i] = (uint16_t)(u >> 16);
        px[2 * i + 1] = (uint16_t)(u & 0xffffu);
    }
    const size_t texels = 2 * n_vec4;
    const int full_rows = (int)(texels / HFS_GLES_BLOCK_TEX_W);
    const int tail = (int)(texels % HFS_GLES_BLOCK_TEX_W);
    gl->BindTexture(GL_TEXTURE_2D, bt->tex);
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 4);
    if (full_rows > 0)
        gl->TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, HFS_GLES_BLOCK_TEX_W, full_rows,
                          GL_RGBA_INTEGER, GL_UNSIGNED_SHORT, px);
    if (tail > 0)
        gl->TexSubImage2D(GL_TEXTURE_2D, 0, 0, full_rows, tail, 1, GL_RGBA_INTEGER,
                          GL_UNSIGNED_SHORT, px + (size_t)full_rows * HFS_GLES_BLOCK_TEX_W * 4);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    return hfs_gl_check(gl, what, err);
}

void hfs_gles_block_texture_free(hfs_gles_block_texture *bt, const hfs_gl *gl)
{
    hfs_gles_tex_delete(gl, &bt->tex);
    bt->rows = 0;
    bt->bytes = 0;
}
