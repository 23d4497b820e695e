/*
 * egl_shared.c — "shared" context (issue 20, embedding): an OpenGL ES 3.x
 * context on the application's EGLDisplay, in the share group of the
 * application's EGLContext, bound with EGL_NO_SURFACE.  What the renderer
 * draws into a texture is then a texture of the application's context
 * too, with no read-back.
 *
 * Why a context of its own rather than the application's: the renderer
 * sets program, framebuffer, vertex array, viewport and texture bindings
 * on every pass; in its own context none of that leaks into the
 * application's GL state, and the application's state cannot break a
 * frame.  Textures and sync objects are what a share group shares.
 *
 * Current context: the renderer's calls make this context current and
 * release() puts back what was current on the thread before (display,
 * draw and read surfaces, context), so the application finds its own
 * context bound after every call.  The display is the application's: never
 * terminated here.
 */
#include "egl_util.h"
#include "gl_context_backend.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <stdlib.h>

typedef struct shared_context {
    hfs_gl_context base;
    EGLDisplay display;
    EGLContext context;
    /* What was current before our make_current, for release(). */
    EGLDisplay prev_display;
    EGLSurface prev_draw, prev_read;
    EGLContext prev_context;
} shared_context;

static int egl_fail(hfs_error *err, const char *what)
{
    return hfs_fail(err, HFS_E_CONTEXT, "%s failed (%s)", what,
                    hfs_egl_error_name(eglGetError()));
}

static void remember_current(shared_context *c)
{
    const EGLContext now = eglGetCurrentContext();
    if (now == c->context) /* already ours (a nested call): keep the earlier record */
        return;
    c->prev_context = now;
    c->prev_display = eglGetCurrentDisplay();
    c->prev_draw = eglGetCurrentSurface(EGL_DRAW);
    c->prev_read = eglGetCurrentSurface(EGL_READ);
}

static void shared_release(hfs_gl_context *base)
{
    shared_context *c = (shared_context *)base;
    if (eglGetCurrentContext() != c->context)
        return;
    if (c->prev_context != EGL_NO_CONTEXT && c->prev_display != EGL_NO_DISPLAY)
        eglMakeCurrent(c->prev_display, c->prev_draw, c->prev_read, c->prev_context);
    else
        eglMakeCurrent(c->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

static void shared_destroy(hfs_gl_context *base)
{
    shared_context *c = (shared_context *)base;
    if (c->context != EGL_NO_CONTEXT) {
        shared_release(base);
        eglDestroyContext(c->display, c->context);
    }
    free(c);
}

static int shared_make_current(hfs_gl_context *base, hfs_error *err)
{
    shared_context *c = (shared_context *)base;
    remember_current(c);
    if (!eglBindAPI(EGL_OPENGL_ES_API))
        return egl_fail(err, "eglBindAPI(EGL_OPENGL_ES_API)");
    if (!eglMakeCurrent(c->display, EGL_NO_SURFACE, EGL_NO_SURFACE, c->context))
        return egl_fail(err, "eglMakeCurrent(EGL_NO_SURFACE)");
    return HFS_OK;
}

/* The application's context's config (sharing needs a compatible one), or
 * EGL_NO_CONFIG_KHR where it was made without one. */
static int share_config(EGLDisplay d, EGLContext share, EGLConfig *config, hfs_error *err)
{
    EGLint id = 0, api = 0, n = 0;
    if (!eglQueryContext(d, share, EGL_CONFIG_ID, &id))
        return egl_fail(err, "eglQueryContext(the application's context)");
    if (eglQueryContext(d, share, EGL_CONTEXT_CLIENT_TYPE, &api) && api != EGL_OPENGL_ES_API)
        return hfs_fail(err, HFS_E_CONTEXT, "the application's context is not OpenGL ES "
                        "(client type 0x%x)", (unsigned)api);
    *config = EGL_NO_CONFIG_KHR;
    const EGLint attribs[] = {EGL_CONFIG_ID, id, EGL_NONE};
    if (id != 0 && !eglChooseConfig(d, attribs, config, 1, &n))
        return egl_fail(err, "eglChooseConfig(EGL_CONFIG_ID)");
    if (n < 1)
        *config = EGL_NO_CONFIG_KHR;
    return HFS_OK;
}

int hfs_gl_shared_create(void *egl_display, void *egl_context, hfs_gl_context **out,
                         hfs_error *err)
{
    if (!egl_display || !egl_context)
        return hfs_fail(err, HFS_E_INVALID, "share: the application's EGL %s is NULL",
                        egl_display ? "context" : "display");
    EGLDisplay d = (EGLDisplay)egl_display;
    const char *exts = eglQueryString(d, EGL_EXTENSIONS);
    if (!exts)
        return egl_fail(err, "eglQueryString(the application's display)");
    if (!hfs_egl_has_word(exts, "EGL_KHR_surfaceless_context"))
        return hfs_fail(err, HFS_E_CONTEXT, "the application's display lacks "
                        "EGL_KHR_surfaceless_context");
    EGLConfig config;
    int rc = share_config(d, (EGLContext)egl_context, &config, err);
    if (rc)
        return rc;
    shared_context *c = calloc(1, sizeof *c);
    if (!c)
        return hfs_fail(err, HFS_E_NOMEM, "out of memory");
    c->base.backend = &hfs_gl_backend_shared;
    c->display = d;
    c->context = EGL_NO_CONTEXT;
    const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0,
                                      EGL_NONE};
    if (!eglBindAPI(EGL_OPENGL_ES_API)) {
        rc = egl_fail(err, "eglBindAPI(EGL_OPENGL_ES_API)");
    } else {
        c->context = eglCreateContext(d, config, (EGLContext)egl_context, context_attribs);
        if (c->context == EGL_NO_CONTEXT)
            rc = egl_fail(err, "eglCreateContext(OpenGL ES 3.0, shared)");
        else
            rc = shared_make_current(&c->base, err);
    }
    if (rc) {
        shared_destroy(&c->base);
        return rc;
    }
    *out = &c->base;
    return HFS_OK;
}

static void *shared_proc(const hfs_gl_context *base, const char *name)
{
    (void)base; /* eglGetProcAddress is context-independent */
    return (void *)eglGetProcAddress(name);
}

/* Not in gl_context.c's list of names: made only by
 * hfs_gl_context_create_shared, which has the application's handles. */
const struct hfs_gl_context_backend hfs_gl_backend_shared = {
    .name = "shared",
    .create = NULL,
    .destroy = shared_destroy,
    .proc = shared_proc,
    .make_current = shared_make_current,
    .release = shared_release,
};
