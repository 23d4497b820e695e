/*
 * gl_context_backend.h — what a context backend implements (private to
 * runtime/gl/).  gl_context.c picks a backend by name and does everything common:
 * error prefixes, reading the GL strings, checking the GL is ES 3.0-capable.
 *
 * A backend object embeds struct hfs_gl_context as its first member, so the
 * backend casts between the two.  Tables are const: no mutable globals.
 */
#ifndef HFS_GL_CONTEXT_BACKEND_H
#define HFS_GL_CONTEXT_BACKEND_H

#include "gl_context.h"

struct hfs_gl_context_backend {
    const char *name;
    /* Makes a context, current on the calling thread.  Messages carry no
     * "context NAME:" prefix (the caller adds it). */
    int (*create)(hfs_gl_context **out, hfs_error *err);
    /* Unbinds (if current on this thread) and frees; never NULL. */
    void (*destroy)(hfs_gl_context *ctx);
    void *(*proc)(const hfs_gl_context *ctx, const char *name);
    int (*make_current)(hfs_gl_context *ctx, hfs_error *err);
    /* Makes current again what was current before make_current (NULL: the
     * context stays current, as the renderer's own contexts do). */
    void (*release)(hfs_gl_context *ctx);
};

struct hfs_gl_context {
    const struct hfs_gl_context_backend *backend;
    int is_es;
    char gl_version[128];
    char gl_renderer[128];
    char glsl_version[128];
    char describe[320];
};

extern const struct hfs_gl_context_backend hfs_gl_backend_surfaceless;
extern const struct hfs_gl_context_backend hfs_gl_backend_osmesa;
extern const struct hfs_gl_context_backend hfs_gl_backend_shared;

/* egl_shared.c: a context sharing objects with the application's
 * (hfs_gl_context_create_shared), current on return. */
int hfs_gl_shared_create(void *egl_display, void *egl_context, hfs_gl_context **out,
                         hfs_error *err);

#endif /* HFS_GL_CONTEXT_BACKEND_H */
