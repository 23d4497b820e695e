/*
 * gl_util.h — small GL helpers of the renderer: programs from the embedded
 * shaders, float render targets, float readback, fp16 conversion.
 *
 * All take the hfs_gl table of the context that must be current.  GL state
 * they change is stated per function; nothing is cached between calls.
 * Errors are one line ("program fullscreen.vert+pattern.frag: pattern.frag:
 * 0:12(7): error: ..."); nothing is printed.
 */
#ifndef HFS_GL_UTIL_H
#define HFS_GL_UTIL_H

#include <stddef.h>
#include <stdint.h>

#include "gl_api.h"
#include "half.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- programs ------------------------------------------------------------ */

/* Compiles and links a program from two embedded shaders (gl_shaders.h)
 * named "<stem>.vert" and "<stem>.frag".  defines: NULL, or a NULL-terminated
 * list of "NAME VALUE" strings (or "NAME"), each emitted as "#define NAME
 * VALUE" after "#version 300 es"; they must not contain newlines.
 * On success *out is a program the caller deletes with gl->DeleteProgram;
 * the shader objects are already deleted.  Changes no binding. */
int hfs_gl_program_create(const hfs_gl *gl, const char *vert, const char *frag,
                          const char *const *defines, GLuint *out, hfs_error *err);

/* The same from sources (no #version line); the names only label messages. */
int hfs_gl_program_from_sources(const hfs_gl *gl, const char *vert_name,
                                const char *vert_src, const char *frag_name,
                                const char *frag_src, const char *const *defines,
                                GLuint *out, hfs_error *err);

/* Compiles one shader (stage GL_VERTEX_SHADER or GL_FRAGMENT_SHADER); the
 * caller deletes *out with gl->DeleteShader. */
int hfs_gl_shader_compile(const hfs_gl *gl, GLenum stage, const char *name,
                          const char *src, const char *const *defines, GLuint *out,
                          hfs_error *err);

/* ---- render targets ------------------------------------------------------ */

/* A 2D texture with immutable storage (NEAREST, CLAMP_TO_EDGE, one level)
 * attached as COLOR_ATTACHMENT0 of its own framebuffer. */
typedef struct hfs_gl_target {
    GLuint texture;
    GLuint framebuffer;
    GLenum internal_format;
    int width, height;
} hfs_gl_target;

/* internal_format: GL_RGBA16F, GL_RG16F, GL_R16F (need gl->render_half_float,
 * i.e. GL_EXT_color_buffer_half_float or _float on ES), GL_RGBA8 or
 * GL_RGBA32UI (a shader's floatBitsToUint, read exactly): the product's
 * formats (fp32 targets exist only in the renderer's es30-float
 * comparison profile, chosen by gl_caps.c).  HFS_E_UNSUPPORTED when the
 * format is not renderable here (capability missing or framebuffer
 * incomplete).  Leaves the target's framebuffer bound to GL_FRAMEBUFFER and
 * TEXTURE_2D of the active unit unbound.  *t is zeroed on failure and must
 * be freed with hfs_gl_target_destroy on success. */
int hfs_gl_target_create(const hfs_gl *gl, int width, int height, GLenum internal_format,
                         hfs_gl_target *t, hfs_error *err);

/* Deletes the objects and zeroes *t; a zeroed target is a no-op. */
void hfs_gl_target_destroy(const hfs_gl *gl, hfs_gl_target *t);

/* ---- readback ------------------------------------------------------------- */

typedef enum hfs_gl_read_path {
    /* The pair the implementation reports for the attachment
     * (GL_IMPLEMENTATION_COLOR_READ_FORMAT/TYPE) when it is RGBA with FLOAT or
     * HALF_FLOAT; otherwise RGBA/FLOAT, which GL_EXT_color_buffer_float, ES 3.2
     * and desktop GL guarantee for float buffers.  ES 3.0 with only
     * GL_EXT_color_buffer_half_float guarantees nothing but the reported
     * pair, which is why it comes first. */
    HFS_GL_READ_AUTO = 0,
    HFS_GL_READ_FLOAT,  /* force RGBA/FLOAT                                  */
    HFS_GL_READ_HALF    /* force RGBA/HALF_FLOAT, converted to float in C    */
} hfs_gl_read_path;

/* Reads a w x h rectangle of COLOR_ATTACHMENT0 of framebuffer into out
 * (w*h*4 floats, RGBA, GL row order: y = 0 first).  The READ_FRAMEBUFFER
 * binding, its read buffer, PIXEL_PACK_BUFFER and the pack state are
 * restored.  A rejected format/type gives HFS_E_GL naming the pair.
 * If used is non-NULL it receives the path taken (FLOAT or HALF). */
int hfs_gl_read_rgba(const hfs_gl *gl, GLuint framebuffer, int x, int y, int w, int h,
                     hfs_gl_read_path path, float *out, hfs_gl_read_path *used,
                     hfs_error *err);

/* The same read, left as the driver gave it: w*h*4 floats in out, or with
 * *used HFS_GL_READ_HALF w*h*4 halves (uint16_t, the buffer's first half),
 * for a caller that converts while it combines (pass_readback.c); out must
 * hold w*h*4 floats either way.  used must not be NULL. */
int hfs_gl_read_rgba_raw(const hfs_gl *gl, GLuint framebuffer, int x, int y, int w, int h,
                         hfs_gl_read_path path, void *out, hfs_gl_read_path *used,
                         hfs_error *err);

/* Widens n halves held in buf's first half to n floats, in place. */
void hfs_gl_widen_halves(float *buf, size_t n);

/* fp16 <-> float: half.h (inline, for the loops over a frame). */

#ifdef __cplusplus
}
#endif
#endif /* HFS_GL_UTIL_H */
