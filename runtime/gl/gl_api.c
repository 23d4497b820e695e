/*
 * gl_api.c — fills the hfs_gl function table and reads what the GL can do.
 *
 * Loaders cannot be trusted to return NULL for missing functions (libglvnd
 * and Mesa's glapi hand out dispatch stubs for any "gl*" name), so optional
 * entry points are loaded only when their extension or version is present.
 */
#include "gl_api.h"

#include <stdio.h>
#include <string.h>

static void *load(void *(*proc)(void *, const char *), void *user, const char *name)
{
    return proc(user, name);
}

int hfs_gl_has_extension(const hfs_gl *gl, const char *name)
{
    GLint n = 0;
    gl->GetIntegerv(GL_NUM_EXTENSIONS, &n);
    for (GLint i = 0; i < n; ++i) {
        const GLubyte *e = gl->GetStringi(GL_EXTENSIONS, (GLuint)i);
        if (e && strcmp((const char *)e, name) == 0)
            return 1;
    }
    return 0;
}

static int version_at_least(const hfs_gl *gl, int major, int minor)
{
    return gl->major > major || (gl->major == major && gl->minor >= minor);
}

static int read_version(hfs_gl *gl, hfs_error *err)
{
    const GLubyte *s = gl->GetString(GL_VERSION);
    if (!s)
        return hfs_fail(err, HFS_E_CONTEXT, "gl: glGetString(GL_VERSION) returned NULL "
                        "(no current context?)");
    const char *v = (const char *)s;
    static const char es_prefix[] = "OpenGL ES ";
    gl->is_es = strncmp(v, es_prefix, sizeof es_prefix - 1) == 0;
    if (sscanf(v + (gl->is_es ? sizeof es_prefix - 1 : 0), "%d.%d", &gl->major,
               &gl->minor) != 2)
        return hfs_fail(err, HFS_E_CONTEXT, "gl: unparsable GL_VERSION \"%.200s\"", v);
    if (gl->is_es && !version_at_least(gl, 3, 0))
        return hfs_fail(err, HFS_E_UNSUPPORTED, "gl: OpenGL ES %d.%d, need 3.0", gl->major,
                        gl->minor);
    if (!gl->is_es && !version_at_least(gl, 3, 3))
        return hfs_fail(err, HFS_E_UNSUPPORTED, "gl: OpenGL %d.%d, need 3.3 core", gl->major,
                        gl->minor);
    if (!gl->is_es && !version_at_least(gl, 4, 3) &&
        !hfs_gl_has_extension(gl, "GL_ARB_ES3_compatibility"))
        return hfs_fail(err, HFS_E_UNSUPPORTED, "gl: OpenGL %d.%d without "
                        "GL_ARB_ES3_compatibility", gl->major, gl->minor);
    return HFS_OK;
}

static void read_caps(hfs_gl *gl, void *(*proc)(void *, const char *), void *user)
{
    if (gl->is_es) {
        int cbf = version_at_least(gl, 3, 2) ||
                  hfs_gl_has_extension(gl, "GL_EXT_color_buffer_float");
        gl->render_float = cbf;
        gl->render_half_float = cbf || hfs_gl_has_extension(gl, "GL_EXT_color_buffer_half_float");
        gl->float_linear = hfs_gl_has_extension(gl, "GL_OES_texture_float_linear");
        if (hfs_gl_has_extension(gl, "GL_EXT_disjoint_timer_query")) {
            gl->QueryCounter =
                (PFNGLQUERYCOUNTEREXTPROC)load(proc, user, "glQueryCounterEXT");
            gl->GetQueryObjectui64v =
                (PFNGLGETQUERYOBJECTUI64VEXTPROC)load(proc, user, "glGetQueryObjectui64vEXT");
        }
    } else {
        /* Desktop GL 3.0+: float formats are renderable and filterable. */
        gl->render_float = gl->render_half_float = gl->float_linear = 1;
        if (version_at_least(gl, 3, 3) || hfs_gl_has_extension(gl, "GL_ARB_timer_query")) {
            gl->QueryCounter = (PFNGLQUERYCOUNTEREXTPROC)load(proc, user, "glQueryCounter");
            gl->GetQueryObjectui64v =
                (PFNGLGETQUERYOBJECTUI64VEXTPROC)load(proc, user, "glGetQueryObjectui64v");
        }
    }
    gl->timer_query = gl->QueryCounter && gl->GetQueryObjectui64v;
    if (!gl->timer_query)
        gl->QueryCounter = NULL, gl->GetQueryObjectui64v = NULL;
}

int hfs_gl_load(hfs_gl *gl, void *(*proc)(void *user, const char *name), void *user,
                hfs_error *err)
{
    memset(gl, 0, sizeof *gl);
    if (!proc)
        return hfs_fail(err, HFS_E_INVALID, "gl: no loader");

#define HFS_GL_LOAD_(type, name)                                                   \
    gl->name = (type)load(proc, user, "gl" #name);                                 \
    if (!gl->name) {                                                               \
        memset(gl, 0, sizeof *gl);                                                 \
        return hfs_fail(err, HFS_E_CONTEXT, "gl: gl%s not found", #name);          \
    }
    HFS_GL_FUNCTIONS(HFS_GL_LOAD_)
#undef HFS_GL_LOAD_

    int rc = read_version(gl, err);
    if (rc) {
        memset(gl, 0, sizeof *gl);
        return rc;
    }
    read_caps(gl, proc, user);
    /* Loading must not leave an error behind for the caller to trip on
     * (GetStringi past the end on a broken driver, say). */
    for (int i = 0; i < 8 && gl->GetError() != GL_NO_ERROR; ++i)
        ;
    return HFS_OK;
}

const char *hfs_gl_error_name(GLenum code)
{
    switch (code) {
    case GL_NO_ERROR: return "GL_NO_ERROR";
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case 0x0503: return "GL_STACK_OVERFLOW";
    case 0x0504: return "GL_STACK_UNDERFLOW";
    case 0x0507: return "GL_CONTEXT_LOST";
    default: return "unknown GL error";
    }
}

int hfs_gl_check(const hfs_gl *gl, const char *what, hfs_error *err)
{
    GLenum first = gl->GetError();
    if (first == GL_NO_ERROR)
        return HFS_OK;
    /* Each error flag is reported once; a lost context may report forever,
     * hence the bound. */
    int more = 0;
    while (more < 16 && gl->GetError() != GL_NO_ERROR)
        ++more;
    if (more)
        return hfs_fail(err, HFS_E_GL, "%s: %s (+%d more)", what, hfs_gl_error_name(first),
                        more);
    return hfs_fail(err, HFS_E_GL, "%s: %s", what, hfs_gl_error_name(first));
}
