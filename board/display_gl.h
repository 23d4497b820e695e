/*
 * display_gl.h — the EGL + GLES part the "x11" and "kms" displays share
 * (private to board/): an EGL display on a native platform, a window
 * surface, an ES 3.0 context, and the blit that shows an RGBA8 picture
 * fitted in the window (shaders_es/fullscreen.vert + display_blit.frag).
 *
 * The platform code (display_x11.c, display_kms.c) owns the native objects
 * (X Display/Window, GBM device/surface) and must keep them alive until
 * hfs_dgl_close.  GL entry points come from eglGetProcAddress into an
 * hfs_gl table (runtime/gl/gl_api.h), never from a linked libGLESv2.
 *
 * The EGLDisplay is keyed on our own native display (a private X connection
 * or GBM device), so unlike the surfaceless context's it is not shared with
 * anyone and hfs_dgl_close terminates it.
 */
#ifndef HFS_DISPLAY_GL_H
#define HFS_DISPLAY_GL_H

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include "gl_api.h"

typedef struct hfs_display_gl {
    EGLDisplay display;
    EGLConfig config;
    EGLContext context;
    EGLSurface surface;
    PFNEGLCREATEPLATFORMWINDOWSURFACEEXTPROC create_window_surface;
    hfs_gl gl;            /* loaded once the context is current */
    GLuint program, texture, vao;
    int tex_w, tex_h;     /* the shown picture's size, 0 before the first */
    int own_w, own_h;     /* our texture's storage, 0 before the first upload */
    GLuint shown;         /* the texture drawn: ours, or a renderer's that
                             shares our context (hfs_dgl_show_texture) */
    void *fence;          /* GLsync to wait on before drawing `shown`; NULL
                             once waited on */
} hfs_display_gl;

/* Gets and initialises the EGL display of native on platform (needs the
 * client extensions EGL_EXT_platform_base and one of platform_exts, a
 * NULL-terminated list) and binds the ES API.  HFS_E_CONTEXT on failure. */
int hfs_dgl_open(hfs_display_gl *g, EGLenum platform, void *native,
                 const char *const *platform_exts, hfs_error *err);

/* Picks an ES 3 window config with 8-bit red, green, blue, preferring no
 * alpha; with native_visual >= 0 only configs whose EGL_NATIVE_VISUAL_ID is
 * that value (GBM: the scan-out format).  *visual_out (optional) receives
 * the chosen config's EGL_NATIVE_VISUAL_ID (X11: the visual to give the
 * window). */
int hfs_dgl_choose_config(hfs_display_gl *g, EGLint native_visual, EGLint *visual_out,
                          hfs_error *err);

/* Creates the window surface on native_window (X11: a pointer to the
 * Window; GBM: the gbm_surface), an ES 3.0 context, makes them current,
 * loads the GL table, builds the blit program and sets swap interval 1. */
int hfs_dgl_start(hfs_display_gl *g, void *native_window, hfs_error *err);

/* Makes our context and surface current on this thread. */
int hfs_dgl_make_current(hfs_display_gl *g, hfs_error *err);

/* Draws the picture (uploading rgba first unless it is NULL: then the last
 * upload is drawn again) fitted in a dst_w x dst_h surface, black around
 * it.  Does not swap.  Needs a context current (hfs_dgl_make_current). */
int hfs_dgl_draw(hfs_display_gl *g, const uint8_t *rgba, int w, int h, int dst_w, int dst_h,
                 hfs_error *err);

/* The next draws show texture tex (w x h, the same picture layout as an
 * upload: RGBA8 sRGB, row 0 at t = 0; a renderer's lit texture in our
 * share group, hfs_renderer_render_texture) instead of an upload, after a
 * GPU-side wait on fence (a GLsync, or NULL).  An upload (hfs_dgl_draw
 * with rgba) shows ours again. */
void hfs_dgl_show_texture(hfs_display_gl *g, unsigned tex, void *fence, int w, int h);

/* eglSwapBuffers. */
int hfs_dgl_swap(hfs_display_gl *g, hfs_error *err);

/* Releases GL objects, surface and context, terminates the display.  Safe
 * on a zeroed or partly built object. */
void hfs_dgl_close(hfs_display_gl *g);

/* Formats "WHAT failed (EGL_BAD_...)" with eglGetError(); returns code. */
int hfs_dgl_egl_fail(hfs_error *err, int code, const char *what);

#endif /* HFS_DISPLAY_GL_H */
