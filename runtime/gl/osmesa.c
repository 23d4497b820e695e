/*
 * osmesa.c — "osmesa" context: Mesa's off-screen renderer (libOSMesa,
 * gallium llvmpipe in Debian 12), used where EGL surfaceless is unavailable.
 *
 * OSMesa makes desktop GL only.  We ask for a core profile >= 3.3 (Mesa
 * returns the highest it has, 4.5 on llvmpipe) and require
 * GL_ARB_ES3_compatibility (core in 4.3), under which the driver compiles the
 * renderer's `#version 300 es` shaders with ES rules.  Differences from a real
 * ES 3.0 context are listed in README.md.
 *
 * Invariants: OSMesa must be bound to a client colour buffer; we give it a
 * 1x1 RGBA8 buffer inside the object (the renderer draws into FBOs, never
 * into it).  Nothing is shared between objects.
 *
 * libOSMesa is loaded at run time (dlopen), not linked: the renderer core
 * links only EGL (and libc/libm), and a machine without libOSMesa still runs
 * every other backend; "osmesa" then reports which library could not be
 * loaded.  Built without the OSMesa headers (HFS_HAVE_OSMESA undefined),
 * create() reports "not built" with HFS_E_UNSUPPORTED.
 */
#include "gl_context_backend.h"

#include <stdlib.h>

#ifdef HFS_HAVE_OSMESA

#include <GL/osmesa.h>
#include <dlfcn.h>

/* Debian 12's libosmesa6 soname; the unversioned name only exists with -dev. */
#define OSMESA_LIBRARY "libOSMesa.so.8"

/* The entry points we use, resolved per context object (no global state). */
typedef struct osmesa_api {
    void *lib;
    OSMesaContext (*CreateContextAttribs)(const int *, OSMesaContext);
    GLboolean (*MakeCurrent)(OSMesaContext, void *, GLenum, GLsizei, GLsizei);
    OSMesaContext (*GetCurrentContext)(void);
    void (*DestroyContext)(OSMesaContext);
    OSMESAproc (*GetProcAddress)(const char *);
} osmesa_api;

typedef struct osmesa_context {
    hfs_gl_context base;
    osmesa_api api;
    OSMesaContext context;
    unsigned char pixel[4]; /* the 1x1 colour buffer OSMesa insists on */
} osmesa_context;

static int api_load(osmesa_api *a, hfs_error *err)
{
    a->lib = dlopen(OSMESA_LIBRARY, RTLD_NOW | RTLD_LOCAL);
    if (!a->lib)
        return hfs_fail(err, HFS_E_CONTEXT, "cannot load %s (%s)", OSMESA_LIBRARY, dlerror());
    /* POSIX: dlsym's void * converts to a function pointer. */
#define RESOLVE(field, sym)                                                             \
    do {                                                                                \
        *(void **)&a->field = dlsym(a->lib, sym);                                       \
        if (!a->field) {                                                                \
            return hfs_fail(err, HFS_E_CONTEXT, "%s lacks %s", OSMESA_LIBRARY, sym);    \
        }                                                                               \
    } while (0)
    RESOLVE(CreateContextAttribs, "OSMesaCreateContextAttribs");
    RESOLVE(MakeCurrent, "OSMesaMakeCurrent");
    RESOLVE(GetCurrentContext, "OSMesaGetCurrentContext");
    RESOLVE(DestroyContext, "OSMesaDestroyContext");
    RESOLVE(GetProcAddress, "OSMesaGetProcAddress");
#undef RESOLVE
    return HFS_OK;
}

static int bind(osmesa_context *c, hfs_error *err)
{
    if (!c->api.MakeCurrent(c->context, c->pixel, GL_UNSIGNED_BYTE, 1, 1))
        return hfs_fail(err, HFS_E_CONTEXT, "OSMesaMakeCurrent failed");
    return HFS_OK;
}

static void osmesa_destroy(hfs_gl_context *base)
{
    osmesa_context *c = (osmesa_context *)base;
    if (c->context) {
        if (c->api.GetCurrentContext() == c->context)
            c->api.MakeCurrent(NULL, NULL, 0, 0, 0);
        c->api.DestroyContext(c->context);
    }
    /* The library handle is deliberately not dlclose'd: Mesa keeps threads
     * and atexit handlers in it, and leak checkers could no longer name its
     * frames (tests/lsan.supp matches libOSMesa).  dlopen reference-counts,
     * so every context shares the one mapping. */
    free(c);
}

static int osmesa_create(hfs_gl_context **out, hfs_error *err)
{
    int rc;
    osmesa_context *c = calloc(1, sizeof *c);
    if (!c)
        return hfs_fail(err, HFS_E_NOMEM, "out of memory");
    c->base.backend = &hfs_gl_backend_osmesa;
    rc = api_load(&c->api, err);
    if (rc)
        goto err_free;

    const int attribs[] = {
        OSMESA_FORMAT, OSMESA_RGBA,
        OSMESA_DEPTH_BITS, 0,
        OSMESA_STENCIL_BITS, 0,
        OSMESA_ACCUM_BITS, 0,
        OSMESA_PROFILE, OSMESA_CORE_PROFILE,
        OSMESA_CONTEXT_MAJOR_VERSION, 3,
        OSMESA_CONTEXT_MINOR_VERSION, 3,
        0
    };
    c->context = c->api.CreateContextAttribs(attribs, NULL);
    if (!c->context) {
        /* OSMesa gives no reason; the usual one is a classic (non-gallium)
         * OSMesa, which has no core profile. */
        rc = hfs_fail(err, HFS_E_CONTEXT,
                      "OSMesaCreateContextAttribs(core profile >= 3.3) failed");
        goto err_free;
    }
    rc = bind(c, err);
    if (rc)
        goto err_context;
    *out = &c->base;
    return HFS_OK;

err_context:
    c->api.DestroyContext(c->context);
err_free:
    free(c);
    return rc;
}

static void *osmesa_proc(const hfs_gl_context *base, const char *name)
{
    const osmesa_context *c = (const osmesa_context *)base;
    /* POSIX lets function pointers round-trip through void * (dlsym). */
    return (void *)c->api.GetProcAddress(name);
}

static int osmesa_make_current(hfs_gl_context *base, hfs_error *err)
{
    return bind((osmesa_context *)base, err);
}

#else /* !HFS_HAVE_OSMESA */

static int osmesa_create(hfs_gl_context **out, hfs_error *err)
{
    (void)out;
    return hfs_fail(err, HFS_E_UNSUPPORTED,
                    "not built (configure with -DHFS_WITH_OSMESA=ON and libosmesa6-dev)");
}

static void osmesa_destroy(hfs_gl_context *base)
{
    free(base);
}

static void *osmesa_proc(const hfs_gl_context *base, const char *name)
{
    (void)base;
    (void)name;
    return NULL;
}

static int osmesa_make_current(hfs_gl_context *base, hfs_error *err)
{
    (void)base;
    return hfs_fail(err, HFS_E_UNSUPPORTED, "not built");
}

#endif /* HFS_HAVE_OSMESA */

const struct hfs_gl_context_backend hfs_gl_backend_osmesa = {
    .name = "osmesa",
    .create = osmesa_create,
    .destroy = osmesa_destroy,
    .proc = osmesa_proc,
    .make_current = osmesa_make_current,
};
