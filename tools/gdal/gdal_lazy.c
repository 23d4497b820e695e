/*
 * gdal_lazy.c — the GDAL functions of gdal_functions.def as forwarders into
 * libgdal, loaded on the first call (gdal_lazy.h says why).
 */
#define _GNU_SOURCE /* program_invocation_short_name */
#include "gdal_lazy.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_string.h>
#include <cpl_vsi.h>
#include <gdal.h>
#include <gdal_utils.h>
#include <ogr_srs_api.h>

#include <dlfcn.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef HFS_GDAL_SONAME
#error "HFS_GDAL_SONAME: the build names GDAL's library (tools/gdal.cmake)"
#endif

/* The library's own functions, once loaded. */
static struct {
#define HFS_GDAL_FN(ret, name, params, args) ret(*name) params;
#define HFS_GDAL_VOID(name, params, args) void(*name) params;
#include "gdal_functions.def"
#undef HFS_GDAL_FN
#undef HFS_GDAL_VOID
} gdal;

static pthread_once_t load_once = PTHREAD_ONCE_INIT;
/* Set (release) once every pointer above is: the forwarders' fast path.
 * It is set before GDALAllRegister runs, so a call back into a forwarder
 * from inside the registration does not wait on load_once. */
static atomic_int loaded;
static char load_error[320];

static void load(void)
{
    const char *library = getenv("HFS_GDAL_LIBRARY");
    if (!library || !*library)
        library = HFS_GDAL_SONAME;
    void *lib = dlopen(library, RTLD_NOW | RTLD_LOCAL);
    if (!lib) {
        const char *why = dlerror();
        snprintf(load_error, sizeof load_error, "GDAL (%s) cannot be loaded: %s", library,
                 why ? why : "unknown error");
        return;
    }
    void *f;
    /* memcpy: ISO C has no conversion from void * to a function pointer. */
#define HFS_GDAL_RESOLVE(name)                                                                 \
    if (!(f = dlsym(lib, #name))) {                                                            \
        snprintf(load_error, sizeof load_error, "GDAL (%s) cannot be loaded: it has no %s",   \
                 library, #name);                                                              \
        dlclose(lib);                                                                          \
        return;                                                                                \
    }                                                                                          \
    memcpy(&gdal.name, &f, sizeof f);
#define HFS_GDAL_FN(ret, name, params, args) HFS_GDAL_RESOLVE(name)
#define HFS_GDAL_VOID(name, params, args) HFS_GDAL_RESOLVE(name)
#include "gdal_functions.def"
#undef HFS_GDAL_FN
#undef HFS_GDAL_VOID
#undef HFS_GDAL_RESOLVE
    atomic_store_explicit(&loaded, 1, memory_order_release);
    gdal.GDALAllRegister();
}

/* 1 once the library is loaded (loading it on the first call), else 0
 * with the reason in load_error. */
static int gdal_loaded(void)
{
    if (!atomic_load_explicit(&loaded, memory_order_acquire))
        pthread_once(&load_once, load);
    return atomic_load_explicit(&loaded, memory_order_acquire);
}

int hfs_gdal_need(const char *path, hfs_error *err)
{
    return gdal_loaded() ? HFS_OK : hfs_fail(err, HFS_E_IO, "%s: %s", path, load_error);
}

/* A forwarder's way in: the library, or the one-line error and exit 1
 * (the doors call hfs_gdal_need first; this is for a call past them). */
static void need_gdal(void)
{
    if (!gdal_loaded()) {
        fprintf(stderr, "%s: %s\n", program_invocation_short_name, load_error);
        exit(1);
    }
}

#define HFS_GDAL_FN(ret, name, params, args)                                                   \
    ret name params                                                                            \
    {                                                                                          \
        need_gdal();                                                                           \
        return gdal.name args;                                                                 \
    }
#define HFS_GDAL_VOID(name, params, args)                                                      \
    void name params                                                                           \
    {                                                                                          \
        need_gdal();                                                                           \
        gdal.name args;                                                                        \
    }
#include "gdal_functions.def"
#undef HFS_GDAL_FN
#undef HFS_GDAL_VOID
