/*
 * block_texture.h — uniform data too large for the profile's uniform
 * blocks (GL_MAX_UNIFORM_BLOCK_SIZE: 16 KiB under ES 3.0's minimums), carried
 * by a texture instead of refusing the scene (issue 13): a long swath
 * (--nphi-env, --nphi-key, --nphi-local up to their documented maxima),
 * many key-light records.
 *
 * The texture holds the very std140 data the block would (same packers):
 * each vec4 as two RGBA16UI texels, the bits of x, y (then z, w) as their
 * high and low 16-bit halves, HFS_GLES_BLOCK_TEX_W texels a row.  The
 * shader rebuilds the floats bit for bit (gles_lib.frag hfs_block_vec4:
 * uintBitsToFloat), so a frame is the same whichever carries its data;
 * RGBA16UI is core ES 3.0 and no 32-bit texture enters the GPU path.
 */
#ifndef HFS_GLES_BLOCK_TEXTURE_H
#define HFS_GLES_BLOCK_TEXTURE_H

#include "gl_api.h"
#include "gl_caps.h"
#include "hfshade.h"

#define HFS_GLES_BLOCK_TEX_W 1024 /* texels a row; gles_lib.frag HFS_BLOCK_TEX_W */

typedef struct hfs_gles_block_texture {
    GLuint tex;
    int rows;        /* allocated rows (grows, never shrinks) */
    size_t bytes;
} hfs_gles_block_texture;

/* Whether n_vec4 vec4 of block data exceed the profile's uniform blocks. */
int hfs_gles_block_too_big(const hfs_gl_caps *c, size_t n_vec4);

/* Uploads n_vec4 vec4 of std140 data (what the block would hold).  Refuses,
 * naming `what` and the limit, when even the texture would exceed the
 * profile's texture size.  scratch: 16 bytes per vec4 (not data). */
int hfs_gles_block_texture_upload(hfs_gles_block_texture *bt, const hfs_gl *gl,
                                  const hfs_gl_caps *c, const float *data, size_t n_vec4,
                                  void *scratch, const char *what, hfs_error *err);
/* The limits check alone (before anything is allocated). */
int hfs_gles_block_texture_check(const hfs_gl_caps *c, size_t n_vec4, const char *what,
                                 hfs_error *err);
void hfs_gles_block_texture_free(hfs_gles_block_texture *bt, const hfs_gl *gl);

#endif /* HFS_GLES_BLOCK_TEXTURE_H */
