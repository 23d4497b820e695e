/*
 * gl_context.c — picks a context backend by name and does what all share:
 * the "context NAME:" error prefix, reading GL_VERSION/RENDERER/GLSL strings
 * once, and refusing a GL that cannot run `#version 300 es` shaders (ES < 3.0,
 * or desktop GL without GL_ARB_ES3_compatibility).
 */
#include "gl_context_backend.h"

#ifndef GL_GLES_PROTOTYPES
#define GL_GLES_PROTOTYPES 0
#endif
#include <GLES3/gl3.h>

#include <stdio.h>
#include <string.h>

static const struct hfs_gl_context_backend *const backends[] = {
    &hfs_gl_backend_surfaceless,
    &hfs_gl_backend_osmesa,
};
#define N_BACKENDS (sizeof backends / sizeof backends[0])

const char *hfs_gl_context_names(void)
{
    return "surfaceless, osmesa, auto";
}

static void copy_string(char *dst, size_t size, const GLubyte *src)
{
    snprintf(dst, size, "%s", src ? (const char *)src : "");
}

static int has_gl_extension(const hfs_gl_context *ctx, const char *name)
{
    PFNGLGETINTEGERVPROC get_integerv =
        (PFNGLGETINTEGERVPROC)hfs_gl_context_proc(ctx, "glGetIntegerv");
    PFNGLGETSTRINGIPROC get_stringi =
        (PFNGLGETSTRINGIPROC)hfs_gl_context_proc(ctx, "glGetStringi");
    if (!get_integerv || !get_stringi)
        return 0;
    GLint n = 0;
    get_integerv(GL_NUM_EXTENSIONS, &n);
    for (GLint i = 0; i < n; ++i) {
        const GLubyte *e = get_stringi(GL_EXTENSIONS, (GLuint)i);
        if (e && strcmp((const char *)e, name) == 0)
            return 1;
    }
    return 0;
}

/* Reads the strings and checks the GL can run the renderer's shaders.
 * Messages without prefix, like a backend's. */
static int finish_create(hfs_gl_context *ctx, hfs_error *err)
{
    PFNGLGETSTRINGPROC get_string =
        (PFNGLGETSTRINGPROC)hfs_gl_context_proc(ctx, "glGetString");
    if (!get_string)
        return hfs_fail(err, HFS_E_CONTEXT, "glGetString not found");
    const GLubyte *version = get_string(GL_VERSION);
    if (!version)
        return hfs_fail(err, HFS_E_CONTEXT, "glGetString(GL_VERSION) returned NULL");
    copy_string(ctx->gl_version, sizeof ctx->gl_version, version);
    copy_string(ctx->gl_renderer, sizeof ctx->gl_renderer, get_string(GL_RENDERER));
    copy_string(ctx->glsl_version, sizeof ctx->glsl_version,
                get_string(GL_SHADING_LANGUAGE_VERSION));

    static const char es_prefix[] = "OpenGL ES ";
    int major = 0, minor = 0;
    ctx->is_es = strncmp(ctx->gl_version, es_prefix, sizeof es_prefix - 1) == 0;
    const char *number = ctx->gl_version + (ctx->is_es ? sizeof es_prefix - 1 : 0);
    if (sscanf(number, "%d.%d", &major, &minor) != 2)
        return hfs_fail(err, HFS_E_CONTEXT, "unparsable GL_VERSION \"%s\"", ctx->gl_version);
    if (ctx->is_es && major < 3)
        return hfs_fail(err, HFS_E_CONTEXT, "OpenGL ES %d.%d, need 3.0", major, minor);
    if (!ctx->is_es && (major < 3 || (major == 3 && minor < 3)))
        return hfs_fail(err, HFS_E_CONTEXT, "OpenGL %d.%d, need 3.3 core", major, minor);
    if (!ctx->is_es && !(major > 4 || (major == 4 && minor >= 3)) &&
        !has_gl_extension(ctx, "GL_ARB_ES3_compatibility"))
        return hfs_fail(err, HFS_E_CONTEXT, "OpenGL %d.%d without GL_ARB_ES3_compatibility "
                        "cannot compile #version 300 es", major, minor);

    snprintf(ctx->describe, sizeof ctx->describe, "%s: %s, %s", ctx->backend->name,
             ctx->gl_version, ctx->gl_renderer);
    return HFS_OK;
}

static int create_one(const struct hfs_gl_context_backend *b, hfs_gl_context **out,
                      hfs_error *err)
{
    hfs_gl_context *ctx = NULL;
    int rc = b->create(&ctx, err);
    if (rc)
        return rc;
    rc = finish_create(ctx, err);
    if (rc) {
        b->destroy(ctx);
        return rc;
    }
    *out = ctx;
    return HFS_OK;
}

/* Which of two failures to report for "auto": a backend that exists but
 * failed here says more than one that was not built. */
static int worse(int a, int b)
{
    if (a == HFS_E_NOMEM || b == HFS_E_NOMEM)
        return HFS_E_NOMEM;
    if (a == HFS_E_CONTEXT || b == HFS_E_CONTEXT)
        return HFS_E_CONTEXT;
    return a ? a : b;
}

int hfs_gl_context_create(const char *name, hfs_gl_context **out, hfs_error *err)
{
    if (!out)
        return hfs_fail(err, HFS_E_INVALID, "context: no output pointer");
    *out = NULL;
    if (!name)
        name = "surfaceless";

    if (strcmp(name, "auto") == 0) {
        char reasons[sizeof err->msg] = "";
        size_t used = 0;
        int rc = HFS_OK;
        for (size_t i = 0; i < N_BACKENDS; ++i) {
            hfs_error why = { "" };
            int r = create_one(backends[i], out, &why);
            if (r == HFS_OK)
                return HFS_OK;
            rc = worse(rc, r);
            int n = snprintf(reasons + used, sizeof reasons - used, "%s%s: %s",
                             i ? "; " : "", backends[i]->name, why.msg);
            if (n > 0)
                used += (size_t)n < sizeof reasons - used ? (size_t)n : sizeof reasons - used - 1;
        }
        return hfs_fail(err, rc, "context auto: %s", reasons);
    }

    for (size_t i = 0; i < N_BACKENDS; ++i) {
        if (strcmp(name, backends[i]->name) != 0)
            continue;
        hfs_error why;
        int rc = create_one(backends[i], out, &why);
        if (rc)
            return hfs_fail(err, rc, "context %s: %s", name, why.msg);
        return HFS_OK;
    }
    return hfs_fail(err, HFS_E_INVALID, "context \"%.64s\": unknown (known: %s)", name,
                    hfs_gl_context_names());
}

int hfs_gl_context_create_shared(void *egl_display, void *egl_context, hfs_gl_context **out,
                                 hfs_error *err)
{
    if (!out)
        return hfs_fail(err, HFS_E_INVALID, "context: no output pointer");
    *out = NULL;
    hfs_gl_context *ctx = NULL;
    hfs_error why;
    int rc = hfs_gl_shared_create(egl_display, egl_context, &ctx, &why);
    if (!rc && (rc = finish_create(ctx, &why)))
        hfs_gl_backend_shared.destroy(ctx);
    if (rc)
        return hfs_fail(err, rc, "context shared: %s", why.msg);
    *out = ctx;
    return HFS_OK;
}

void hfs_gl_context_destroy(hfs_gl_context *ctx)
{
    if (ctx)
        ctx->backend->destroy(ctx);
}

const char *hfs_gl_context_name(const hfs_gl_context *ctx)
{
    return ctx->backend->name;
}

void *hfs_gl_context_proc(const hfs_gl_context *ctx, const char *gl_function_name)
{
    return ctx->backend->proc(ctx, gl_function_name);
}

void *hfs_gl_context_loader(void *ctx, const char *gl_function_name)
{
    return hfs_gl_context_proc(ctx, gl_function_name);
}

int hfs_gl_context_make_current(hfs_gl_context *ctx, hfs_error *err)
{
    hfs_error why;
    int rc = ctx->backend->make_current(ctx, &why);
    if (rc)
        return hfs_fail(err, rc, "context %s: %s", ctx->backend->name, why.msg);
    return HFS_OK;
}

void hfs_gl_context_release(hfs_gl_context *ctx)
{
    if (ctx && ctx->backend->release)
        ctx->backend->release(ctx);
}

const char *hfs_gl_context_gl_version(const hfs_gl_context *ctx)
{
    return ctx->gl_version;
}

const char *hfs_gl_context_gl_renderer(const hfs_gl_context *ctx)
{
    return ctx->gl_renderer;
}

const char *hfs_gl_context_glsl_version(const hfs_gl_context *ctx)
{
    return ctx->glsl_version;
}

const char *hfs_gl_context_describe(const hfs_gl_context *ctx)
{
    return ctx->describe;
}

int hfs_gl_context_is_es(const hfs_gl_context *ctx)
{
    return ctx->is_es;
}
