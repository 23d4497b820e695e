/*
 * gl_context.h — headless GL contexts for the renderer, chosen by name.
 *
 * Backends (see README.md in this folder for their limits):
 *   "surfaceless"  EGL_MESA_platform_surfaceless, OpenGL ES 3.x, no surface:
 *                  render into FBOs.  The default (name NULL).
 *   "osmesa"       Mesa's off-screen library: a desktop GL core context that
 *                  compiles the same `#version 300 es` shaders through
 *                  GL_ARB_ES3_compatibility.  "not built" unless the build
 *                  found OSMesa (option HFS_WITH_OSMESA).
 *   "auto"         surfaceless, else osmesa.  The object reports which one it
 *                  is through hfs_gl_context_name(), never "auto".
 *
 * The GL must be called through function pointers obtained from the context
 * (hfs_gl_context_proc, or hfs_gl_load in runtime/gl/gl_api.h with
 * hfs_gl_context_loader): OSMesa is not behind libglvnd's libGLESv2, so
 * linking libGLESv2 and calling glFoo() directly would reach the wrong driver.
 *
 * Threads: a context is made current on the thread that creates it.  GL calls
 * go to the context current on the calling thread; to use a context from
 * another thread, or to switch between contexts, call
 * hfs_gl_context_make_current().  A context must not be current on another
 * thread when it is destroyed.  Several contexts may live in one process.
 *
 * Errors: functions return 0 or a negative hfs_status and fill err with one
 * line naming the backend: "context surfaceless: eglInitialize failed
 * (EGL_NOT_INITIALIZED)".  Nothing is printed.
 */
#ifndef HFS_GL_CONTEXT_H
#define HFS_GL_CONTEXT_H

#include "hfshade.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct hfs_gl_context hfs_gl_context;

/* Creates the context called name (NULL = "surfaceless") and makes it current
 * on the calling thread.  On success *out owns it (free with
 * hfs_gl_context_destroy); on failure *out is NULL and the result is
 *   HFS_E_INVALID      unknown name (the message lists the known ones);
 *   HFS_E_UNSUPPORTED  the backend was not built into this library;
 *   HFS_E_CONTEXT      the backend exists but no usable context could be made
 *                      here (no driver, no ES 3.0, missing extension...);
 *   HFS_E_NOMEM        allocation failed.
 * For "auto" the message gives the reason of each backend tried. */
int hfs_gl_context_create(const char *name, hfs_gl_context **out, hfs_error *err);

/* "shared" (issue 20, embedding): an OpenGL ES 3.x context on the
 * application's EGLDisplay that shares objects (textures, sync objects)
 * with the application's EGLContext egl_context, bound with EGL_NO_SURFACE
 * (needs EGL_KHR_surfaceless_context on that display).  Both arguments are
 * EGL handles passed as void * (hfshade.h includes no EGL header); the
 * display must be initialized and stays the application's (never
 * terminated here).  The context made current by hfs_gl_context_make_current
 * is handed back by hfs_gl_context_release, and destroy leaves the thread
 * with what was current before.  Errors as hfs_gl_context_create, plus
 * HFS_E_INVALID for a NULL handle. */
int hfs_gl_context_create_shared(void *egl_display, void *egl_context, hfs_gl_context **out,
                                 hfs_error *err);

/* Releases the context (and unbinds it if it is current on this thread).
 * NULL is a no-op.  EGL displays are process-wide and shared with other
 * users, so the display is terminated only where EGL can count references
 * (EGL_KHR_display_reference); otherwise it stays until exit. */
void hfs_gl_context_destroy(hfs_gl_context *ctx);

/* The backend that made this context: "surfaceless" or "osmesa".  Static
 * string. */
const char *hfs_gl_context_name(const hfs_gl_context *ctx);

/* Address of a GL function of this context ("glCreateShader"), or NULL.
 * Both backends may return a non-NULL stub for names the driver does not
 * implement, so a function from an extension may be called only when the
 * extension is listed by the context (hfs_gl_has_extension). */
void *hfs_gl_context_proc(const hfs_gl_context *ctx, const char *gl_function_name);

/* The same, with the signature hfs_gl_load() takes:
 *   hfs_gl_load(&gl, hfs_gl_context_loader, ctx, err); */
void *hfs_gl_context_loader(void *ctx, const char *gl_function_name);

/* Makes ctx current on the calling thread. */
int hfs_gl_context_make_current(hfs_gl_context *ctx, hfs_error *err);
/* After a call that made ctx current: a shared context makes current again
 * what was current on this thread before (the application's context, its
 * surfaces); the renderer's own contexts stay current (no-op). */
void hfs_gl_context_release(hfs_gl_context *ctx);

/* Strings read once at creation (owned by ctx, valid until destroy):
 *   GL_VERSION   "OpenGL ES 3.2 Mesa 22.3.6" or "4.5 (Core Profile) Mesa ..."
 *   GL_RENDERER  "llvmpipe (LLVM 15.0.6, 256 bits)"
 *   GL_SHADING_LANGUAGE_VERSION
 * and a one-line summary for tools to print:
 *   "surfaceless: OpenGL ES 3.2 Mesa 22.3.6, llvmpipe (LLVM 15.0.6, 256 bits)" */
const char *hfs_gl_context_gl_version(const hfs_gl_context *ctx);
const char *hfs_gl_context_gl_renderer(const hfs_gl_context *ctx);
const char *hfs_gl_context_glsl_version(const hfs_gl_context *ctx);
const char *hfs_gl_context_describe(const hfs_gl_context *ctx);

/* 1 for an OpenGL ES context, 0 for desktop GL (osmesa). */
int hfs_gl_context_is_es(const hfs_gl_context *ctx);

/* Names accepted by hfs_gl_context_create, for help texts:
 * "surfaceless, osmesa, auto" ("shared" is made only by
 * hfs_gl_context_create_shared). */
const char *hfs_gl_context_names(void);

#ifdef __cplusplus
}
#endif
#endif /* HFS_GL_CONTEXT_H */
