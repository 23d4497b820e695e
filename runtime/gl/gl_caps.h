/*
 * gl_caps.h — the capability layer of the GLES renderer: the single gate for
 * every format, filter and limit decision.
 *
 * Drivers are not trusted to enforce a profile (Mesa's llvmpipe offers ES 3.2
 * with desktop-class limits even under MESA_GLES_VERSION_OVERRIDE=3.0), so
 * the renderer never asks the GL what it may do: it asks these caps, which
 * are what the driver offers INTERSECTED with a named target profile.
 *
 * Profiles (the product runs on the first):
 *   "es30-half"   OpenGL ES 3.0 core + GL_EXT_color_buffer_half_float:
 *                 R16F/RG16F/RGBA16F render targets, fp16 linear filtering
 *                 (core ES 3.0).  No float32 texture or render target.
 *                 Limits: the driver's own (a board that holds a 4096^2
 *                 field renders it), or with strict limits (CI) capped at
 *                 the ES 3.0 minimums (texture 2048, 256 array layers, 4
 *                 draw buffers, 16384-byte uniform blocks...).
 *   "es30-float"  the same + GL_EXT_color_buffer_float (32F render targets)
 *                 + GL_OES_texture_float_linear (32F filtering): what
 *                 --precision fp32 runs on.
 *   "es32"        OpenGL ES 3.2 features (float render targets are core),
 *                 the driver's own limits (relaxed); fp32 still needs
 *                 GL_OES_texture_float_linear.
 * The renderer never blends (float_blend is read for information only).
 *
 * A driver that lacks something the profile needs is refused with one line
 * naming it ("profile es30-half: GL_EXT_color_buffer_half_float is not
 * offered by this driver").  Desktop GL (osmesa, >= 3.3 core with
 * GL_ARB_ES3_compatibility) offers every float feature in core.
 *
 * hfs_gl_caps_select and the check functions are pure (no GL calls) so that
 * tests can feed them synthetic drivers.
 */
#ifndef HFS_GL_CAPS_H
#define HFS_GL_CAPS_H

#include <stddef.h>

#include "gl_api.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What the driver offers (hfs_gl_caps_query). */
typedef struct hfs_gl_driver {
    int is_es, major, minor;
    int color_buffer_half_float; /* R16F..RGBA16F colour-renderable        */
    int color_buffer_float;      /* R32F..RGBA32F colour-renderable        */
    int texture_float_linear;    /* 32F textures filterable                */
    int float_blend;             /* 32F targets blendable (not required)   */
    int timer_query;             /* QueryCounter(GL_TIMESTAMP) pairs       */
    int max_texture_size;
    int max_array_texture_layers;
    int max_draw_buffers;        /* min(MAX_DRAW_BUFFERS, MAX_COLOR_ATTACHMENTS) */
    int max_uniform_block_size;  /* bytes                                   */
    int max_fragment_uniform_blocks;
    int max_uniform_buffer_bindings;
    int max_texture_image_units; /* fragment stage                          */
    int uniform_buffer_offset_alignment;
    int max_renderbuffer_size;   /* the 3-D view's targets                  */
    int max_viewport[2];         /* GL_MAX_VIEWPORT_DIMS                    */
    int max_vertex_texture_image_units; /* the view's vertex shader reads heights */
    int samples_rgba16f;         /* most samples of an RGBA16F renderbuffer
                                    (GL_SAMPLES of glGetInternalformativ; 0:
                                    none, e.g. ES 3.0 core without the
                                    extension's multisample support)         */
    int filter_inexact;          /* LINEAR blends off the exact position or
                                    rounded to a half (gl_probe.h; set by the
                                    renderer's setup, not hfs_gl_caps_query)  */
} hfs_gl_driver;

/* The effective capabilities under a profile. */
typedef struct hfs_gl_caps {
    char profile[16];            /* "es30-half", "es30-float", "es32"        */
    hfs_gl_driver driver;        /* what the driver offered                 */
    int fp32;                    /* 1: textures/targets are 32F (fp32 path) */
    /* Formats of the renderer's textures (all colour-renderable and
     * linearly filterable under this caps): */
    GLenum fmt_r;                /* GL_R16F or GL_R32F                       */
    GLenum fmt_rg;               /* GL_RG16F or GL_RG32F                     */
    GLenum fmt_rgba;             /* GL_RGBA16F or GL_RGBA32F                 */
    GLenum type_upload;          /* GL_HALF_FLOAT or GL_FLOAT                */
    GLenum fmt_block;            /* GL_RGBA16UI: uniform data too large for a
                                    block, as 16-bit halves of its float bits
                                    (gles/block_texture.h; core ES 3.0)       */
    int bytes_r, bytes_rg, bytes_rgba; /* per texel                         */
    int strict_limits;           /* limits capped at the ES 3.0 minimums    */
    /* Limits: the driver's, or min(driver, ES 3.0 minimum) when strict. */
    int max_texture_size;
    int max_array_texture_layers;
    int max_draw_buffers;
    int max_uniform_block_size;
    int max_fragment_uniform_blocks;
    int max_uniform_buffer_bindings;
    int max_texture_image_units;
    int uniform_buffer_offset_alignment;
    int timer_query;             /* GPU timestamps usable                   */
    int max_renderbuffer_size;   /* the 3-D view's colour and depth targets */
    int max_vertex_texture_image_units;
    int view_samples;            /* samples of the view's RGBA16F target: the
                                    driver's, at most 4; 1 = no multisampling */
} hfs_gl_caps;

/* Reads what the current context offers (the context gl was loaded from
 * must be current).  Never fails; absent queries read as 0. */
void hfs_gl_caps_query(const hfs_gl *gl, hfs_gl_driver *d);

/* Intersects driver d with the profile named (NULL = "es30-half", or
 * "es30-float" when want_fp32) and picks the texture formats: 16F, or 32F
 * when want_fp32 (refused under es30-half).  HFS_E_INVALID for an unknown
 * name (the message lists the known ones), HFS_E_UNSUPPORTED with one line
 * naming what the driver lacks.  *c is filled on success only. */
int hfs_gl_caps_select(const hfs_gl_driver *d, const char *profile, int want_fp32,
                       int strict_limits, hfs_gl_caps *c, hfs_error *err);

/* "es30-half, es30-float, es32" for help texts. */
const char *hfs_gl_profile_names(void);

/* ---- checks (each returns 0 or HFS_E_UNSUPPORTED with one line) ---------- */

/* A w x h texture with `layers` array layers (1 for a 2D texture). */
/* The texture size limit as the refusals name it: "the driver's limit
 * 16384 (GL_MAX_TEXTURE_SIZE)" or "the ES 3.0 minimum 2048
 * (GL_MAX_TEXTURE_SIZE, strict limits; this driver allows 32768)"; buf. */
const char *hfs_gl_caps_texture_limit(const hfs_gl_caps *c, char *buf, size_t n);
int hfs_gl_caps_check_texture(const hfs_gl_caps *c, int w, int h, int layers,
                              const char *what, hfs_error *err);
/* A uniform block of `bytes` bytes. */
int hfs_gl_caps_check_uniform_block(const hfs_gl_caps *c, size_t bytes, const char *what,
                                    hfs_error *err);
/* n simultaneous colour outputs (MRT). */
int hfs_gl_caps_check_draw_buffers(const hfs_gl_caps *c, int n, const char *what,
                                   hfs_error *err);
/* The 3-D view (runtime/gles/pass_view.c): a w x h RGBA16F colour and
 * depth target (renderbuffer size, viewport) and a vertex shader that
 * reads `vtex` textures. */
int hfs_gl_caps_check_view(const hfs_gl_caps *c, int w, int h, int vtex, hfs_error *err);
/* n samplers in one fragment shader. */
int hfs_gl_caps_check_samplers(const hfs_gl_caps *c, int n, const char *what,
                               hfs_error *err);

#ifdef __cplusplus
}
#endif
#endif /* HFS_GL_CAPS_H */
