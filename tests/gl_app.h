/*
 * gl_app.h — an application's own EGL context, as an embedding program
 * makes it (surfaceless Mesa, ES 3), and the lit texture of a renderer
 * that shares with it (hfs_renderer_render_texture) read back IN THAT
 * CONTEXT: wait on the renderer's fence, attach the texture to the
 * application's framebuffer, read.  Used by test_gles_embed.c and
 * test_plan_keys.c.
 *
 * Header-only (static inline); link hfs_gl and EGL.
 */
#ifndef HFS_TEST_GL_APP_H
#define HFS_TEST_GL_APP_H

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <stdlib.h>

#include "gl_api.h"
#include "gl_test.h"
#include "gl_util.h"

typedef struct gl_app {
    EGLDisplay dpy;
    EGLContext ctx;
    hfs_gl gl;
    GLuint fbo;
} gl_app;

static inline void *gl_app_proc(void *user, const char *name)
{
    (void)user;
    return (void *)eglGetProcAddress(name);
}

/* The application's context, current; exits 77 where this machine has no
 * GLES context at all (gl_test.h). */
static inline void gl_app_make(gl_app *a)
{
    hfs_error err = {""};
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    a->dpy = get_display ? get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL)
                         : EGL_NO_DISPLAY;
    const EGLint cfg_attr[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_SURFACE_TYPE, 0,
                               EGL_NONE};
    const EGLint ctx_attr[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_NONE};
    EGLConfig cfg = EGL_NO_CONFIG_KHR;
    EGLint n = 0;
    if (a->dpy == EGL_NO_DISPLAY || !eglInitialize(a->dpy, NULL, NULL) ||
        !eglBindAPI(EGL_OPENGL_ES_API) || !eglChooseConfig(a->dpy, cfg_attr, &cfg, 1, &n) ||
        (a->ctx = eglCreateContext(a->dpy, n ? cfg : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT,
                                   ctx_attr)) == EGL_NO_CONTEXT ||
        !eglMakeCurrent(a->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, a->ctx)) {
        hfs_fail(&err, HFS_E_CONTEXT, "EGL error 0x%x", (unsigned)eglGetError());
        gl_test_unavailable("the application's own EGL context", &err);
    }
    if (hfs_gl_load(&a->gl, gl_app_proc, NULL, &err))
        gl_test_unavailable("GL entry points of the application's context", &err);
    a->gl.GenFramebuffers(1, &a->fbo);
}

static inline void gl_app_free(gl_app *a)
{
    a->gl.DeleteFramebuffers(1, &a->fbo);
    eglMakeCurrent(a->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(a->dpy, a->ctx);
}

/* The texture's RGBA as floats (RGBA8: bytes / 255), width x height x 4. */
static inline int gl_app_read(gl_app *a, const hfs_lit_texture *t, float *rgba, hfs_error *err)
{
    const hfs_gl *gl = &a->gl;
    gl->WaitSync((GLsync)t->fence, 0, GL_TIMEOUT_IGNORED);
    gl->BindFramebuffer(GL_FRAMEBUFFER, a->fbo);
    gl->FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t->texture, 0);
    if (t->internal_format == GL_RGBA16F)
        return hfs_gl_read_rgba(gl, a->fbo, 0, 0, t->width, t->height, HFS_GL_READ_AUTO, rgba,
                                NULL, err);
    /* RGBA8: the one pair ES 3.0 guarantees for it */
    const size_t n = (size_t)t->width * t->height * 4;
    unsigned char *b = malloc(n);
    if (!b)
        return hfs_fail(err, HFS_E_NOMEM, "no memory");
    gl->PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl->ReadPixels(0, 0, t->width, t->height, GL_RGBA, GL_UNSIGNED_BYTE, b);
    for (size_t i = 0; i < n; ++i)
        rgba[i] = (float)b[i] / 255.0f;
    free(b);
    return hfs_gl_check(gl, "read RGBA8", err);
}

#endif /* HFS_TEST_GL_APP_H */
