/*
 * egl_surfaceless.c — "surfaceless" context: EGL_MESA_platform_surfaceless,
 * OpenGL ES 3.x, bound with EGL_NO_SURFACE (EGL_KHR_surfaceless_context).
 * There is no default framebuffer: the renderer draws into FBOs.
 *
 * Invariants: everything this backend makes lives in its object; the only
 * shared thing is the EGLDisplay, which EGL keys on (platform, native display)
 * and so hands the same handle to every user in the process.  Terminating it
 * would destroy other contexts (ours or the application's), so we terminate
 * only with EGL_KHR_display_reference, where eglInitialize/eglTerminate are
 * reference counted; without it the display lives until exit (Mesa frees it
 * from its atexit handler).
 *
 * Limits: needs libEGL with EGL_EXT_platform_base + EGL_MESA_platform_surfaceless
 * (Mesa >= 17; libglvnd forwards them) and a display with
 * EGL_KHR_surfaceless_context.  GL function pointers come from
 * eglGetProcAddress (EGL_KHR_get_all_proc_addresses / EGL 1.5).
 */
#include "egl_util.h"
#include "gl_context_backend.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <stdlib.h>
#include <string.h>

typedef struct surfaceless_context {
    hfs_gl_context base;
    EGLDisplay display;
    EGLContext context;
    int terminate_display; /* EGL_KHR_display_reference: ours to release */
} surfaceless_context;

static int egl_fail(hfs_error *err, const char *what)
{
    EGLint code = eglGetError();
    return hfs_fail(err, HFS_E_CONTEXT, "%s failed (%s)", what, hfs_egl_error_name(code));
}

static void surfaceless_destroy(hfs_gl_context *base)
{
    surfaceless_context *c = (surfaceless_context *)base;
    if (c->context != EGL_NO_CONTEXT) {
        if (eglGetCurrentContext() == c->context)
            eglMakeCurrent(c->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(c->display, c->context);
    }
    if (c->terminate_display)
        eglTerminate(c->display);
    free(c);
}

/* The surfaceless platform's display, initialised (its EGL version in
 * *major.*minor).  c->terminate_display says whether it is ours to
 * terminate; on failure there is nothing to release. */
static int open_display(surfaceless_context *c, EGLint *major, EGLint *minor, hfs_error *err)
{
    /* Client extensions: NULL (EGL_BAD_DISPLAY) means EGL_EXT_client_extensions
     * is missing, so no platform extension can be present either. */
    const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!client || !hfs_egl_has_word(client, "EGL_EXT_platform_base") ||
        !hfs_egl_has_word(client, "EGL_MESA_platform_surfaceless"))
        return hfs_fail(err, HFS_E_CONTEXT,
                        "EGL_MESA_platform_surfaceless not offered by this libEGL");
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    if (!get_platform_display)
        return hfs_fail(err, HFS_E_CONTEXT, "eglGetPlatformDisplayEXT not found");
    const EGLint track[] = { EGL_TRACK_REFERENCES_KHR, EGL_TRUE, EGL_NONE };
    c->terminate_display = hfs_egl_has_word(client, "EGL_KHR_display_reference");
    c->display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY,
                                      c->terminate_display ? track : NULL);
    if (c->display == EGL_NO_DISPLAY) {
        c->terminate_display = 0;
        return egl_fail(err, "eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA)");
    }
    if (!eglInitialize(c->display, major, minor)) {
        c->terminate_display = 0;
        return egl_fail(err, "eglInitialize");
    }
    return HFS_OK;
}

/* The display can bind an ES 3 context without a surface (display
 * extensions exts, EGL major.minor): checked, and the ES API bound. */
static int bind_es3_surfaceless(const char *exts, EGLint major, EGLint minor, hfs_error *err)
{
    if (!hfs_egl_has_word(exts, "EGL_KHR_surfaceless_context"))
        return hfs_fail(err, HFS_E_CONTEXT, "EGL_KHR_surfaceless_context missing (EGL %d.%d)",
                        major, minor);
    /* ES 3 needs EGL_OPENGL_ES3_BIT and EGL_CONTEXT_MAJOR_VERSION: EGL 1.5 or
     * EGL_KHR_create_context. */
    if (!(major > 1 || minor >= 5) && !hfs_egl_has_word(exts, "EGL_KHR_create_context"))
        return hfs_fail(err, HFS_E_CONTEXT, "EGL %d.%d without EGL_KHR_create_context "
                        "cannot make an ES 3 context", major, minor);
    if (!eglBindAPI(EGL_OPENGL_ES_API))
        return egl_fail(err, "eglBindAPI(EGL_OPENGL_ES_API)");
    return HFS_OK;
}

/* Any ES3-renderable config: no surface will ever be made from it
 * (EGL_NO_CONFIG_KHR where there is none but the display allows that). */
static int choose_es3_config(const surfaceless_context *c, const char *exts, EGLConfig *config,
                             hfs_error *err)
{
    const EGLint config_attribs[] = {
        EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT,
        EGL_SURFACE_TYPE, 0,
        EGL_NONE
    };
    *config = EGL_NO_CONFIG_KHR;
    EGLint n_configs = 0;
    if (!eglChooseConfig(c->display, config_attribs, config, 1, &n_configs))
        return egl_fail(err, "eglChooseConfig");
    if (n_configs < 1) {
        if (!hfs_egl_has_word(exts, "EGL_KHR_no_config_context"))
            return hfs_fail(err, HFS_E_CONTEXT, "no EGL config with EGL_OPENGL_ES3_BIT");
        *config = EGL_NO_CONFIG_KHR;
    }
    return HFS_OK;
}

/* c->context: an ES 3 context of config, made current without a surface
 * (on failure none is left). */
static int make_es3_context_current(surfaceless_context *c, EGLConfig config, hfs_error *err)
{
    /* Asking for 3.0 gets the highest compatible version (3.2 on Mesa). */
    const EGLint context_attribs[] = {
        EGL_CONTEXT_MAJOR_VERSION, 3,
        EGL_CONTEXT_MINOR_VERSION, 0,
        EGL_NONE
    };
    c->context = eglCreateContext(c->display, config, EGL_NO_CONTEXT, context_attribs);
    if (c->context == EGL_NO_CONTEXT)
        return egl_fail(err, "eglCreateContext(OpenGL ES 3.0)");
    if (!eglMakeCurrent(c->display, EGL_NO_SURFACE, EGL_NO_SURFACE, c->context)) {
        const int rc = egl_fail(err, "eglMakeCurrent(EGL_NO_SURFACE)");
        eglDestroyContext(c->display, c->context);
        c->context = EGL_NO_CONTEXT;
        return rc;
    }
    return HFS_OK;
}

static int surfaceless_create(hfs_gl_context **out, hfs_error *err)
{
    surfaceless_context *c = calloc(1, sizeof *c);
    if (!c)
        return hfs_fail(err, HFS_E_NOMEM, "out of memory");
    c->base.backend = &hfs_gl_backend_surfaceless;
    c->display = EGL_NO_DISPLAY;
    c->context = EGL_NO_CONTEXT;

    EGLint major = 0, minor = 0;
    int rc = open_display(c, &major, &minor, err);
    if (rc) {
        free(c);
        return rc;
    }
    const char *exts = eglQueryString(c->display, EGL_EXTENSIONS);
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if ((rc = bind_es3_surfaceless(exts, major, minor, err)) ||
        (rc = choose_es3_config(c, exts, &config, err)) ||
        (rc = make_es3_context_current(c, config, err))) {
        if (c->terminate_display)
            eglTerminate(c->display);
        free(c);
        return rc;
    }
    *out = &c->base;
    return HFS_OK;
}

static void *surfaceless_proc(const hfs_gl_context *base, const char *name)
{
    (void)base; /* eglGetProcAddress is context-independent */
    /* POSIX lets function pointers round-trip through void * (dlsym). */
    return (void *)eglGetProcAddress(name);
}

static int surfaceless_make_current(hfs_gl_context *base, hfs_error *err)
{
    surfaceless_context *c = (surfaceless_context *)base;
    /* The bound API is per thread: a new thread starts with EGL_OPENGL_ES_API
     * but the application may have changed it. */
    if (!eglBindAPI(EGL_OPENGL_ES_API))
        return egl_fail(err, "eglBindAPI(EGL_OPENGL_ES_API)");
    if (!eglMakeCurrent(c->display, EGL_NO_SURFACE, EGL_NO_SURFACE, c->context))
        return egl_fail(err, "eglMakeCurrent(EGL_NO_SURFACE)");
    return HFS_OK;
}

const struct hfs_gl_context_backend hfs_gl_backend_surfaceless = {
    .name = "surfaceless",
    .create = surfaceless_create,
    .destroy = surfaceless_destroy,
    .proc = surfaceless_proc,
    .make_current = surfaceless_make_current,
};
