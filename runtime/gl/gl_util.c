/*
 * gl_util.c — programs from embedded shaders, float render targets, float
 * readback and fp16 conversion (gl_util.h).
 *
 * Shader prefix: "#version 300 es\n", one "#define ..." line per variant
 * define, then "#line 1\n" so that the driver (and glslang at build time,
 * which gets the same prefix) reports lines of the .glsl file.
 */
#include "gl_util.h"
#include "gl_shaders.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define VERSION_LINE "#version 300 es\n"
#define LINE_RESET "#line 1\n"

/* ---- programs ------------------------------------------------------------ */

/* Builds the prefix into a malloc'ed string; NULL with err set on failure. */
static char *make_prefix(const char *const *defines, const char *label, int *rc,
                         hfs_error *err)
{
    size_t size = sizeof VERSION_LINE + sizeof LINE_RESET;
    for (const char *const *d = defines; d && *d; ++d) {
        if (**d == '\0' || strpbrk(*d, "\n\r")) {
            *rc = hfs_fail(err, HFS_E_INVALID, "%s: bad define \"%.60s\"", label, *d);
            return NULL;
        }
        size += sizeof "#define \n" + strlen(*d);
    }
    char *prefix = malloc(size);
    if (!prefix) {
        *rc = hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", label);
        return NULL;
    }
    size_t used = 0;
    used += (size_t)snprintf(prefix + used, size - used, "%s", VERSION_LINE);
    for (const char *const *d = defines; d && *d; ++d)
        used += (size_t)snprintf(prefix + used, size - used, "#define %s\n", *d);
    snprintf(prefix + used, size - used, "%s", LINE_RESET);
    return prefix;
}

/* Copies a multi-line info log into out as "a; b; c" (no trailing
 * separator, blank lines dropped), truncating to size. */
static void fold_log(const char *log, char *out, size_t size)
{
    size_t w = 0;
    int pending = 0; /* a line ended: separator before the next text */
    for (const char *r = log; *r && w + 1 < size; ++r) {
        if (*r == '\r' || *r == '\n') {
            pending = w > 0;
            continue;
        }
        if (pending) {
            if (w + 3 >= size)
                break;
            out[w++] = ';';
            out[w++] = ' ';
            pending = 0;
        }
        out[w++] = *r;
    }
    while (w > 0 && out[w - 1] == ' ')
        --w;
    out[w] = '\0';
}

int hfs_gl_shader_compile(const hfs_gl *gl, GLenum stage, const char *name,
                          const char *src, const char *const *defines, GLuint *out,
                          hfs_error *err)
{
    int rc = HFS_OK;
    *out = 0;
    if (!src)
        return hfs_fail(err, HFS_E_INVALID, "shader %s: no source", name);
    if (stage != GL_VERTEX_SHADER && stage != GL_FRAGMENT_SHADER)
        return hfs_fail(err, HFS_E_INVALID, "shader %s: unknown stage 0x%x", name,
                        (unsigned)stage);
    char *prefix = make_prefix(defines, name, &rc, err);
    if (!prefix)
        return rc;

    GLuint shader = gl->CreateShader(stage);
    if (!shader) {
        rc = hfs_gl_check(gl, "glCreateShader", err);
        if (!rc)
            rc = hfs_fail(err, HFS_E_GL, "shader %s: glCreateShader returned 0", name);
        goto err_prefix;
    }
    const GLchar *parts[2] = { prefix, src };
    gl->ShaderSource(shader, 2, parts, NULL);
    gl->CompileShader(shader);
    GLint ok = GL_FALSE;
    gl->GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[1024] = "", line[512];
        gl->GetShaderInfoLog(shader, sizeof log, NULL, log);
        fold_log(log, line, sizeof line);
        rc = hfs_fail(err, HFS_E_GL, "shader %s: %s", name, line[0] ? line : "compile failed");
        goto err_shader;
    }
    free(prefix);
    *out = shader;
    return HFS_OK;

err_shader:
    gl->DeleteShader(shader);
err_prefix:
    free(prefix);
    return rc;
}

int hfs_gl_program_from_sources(const hfs_gl *gl, const char *vert_name,
                                const char *vert_src, const char *frag_name,
                                const char *frag_src, const char *const *defines,
                                GLuint *out, hfs_error *err)
{
    char label[160];
    snprintf(label, sizeof label, "program %.60s+%.60s", vert_name, frag_name);
    *out = 0;

    hfs_error why;
    GLuint vs = 0, fs = 0, program = 0;
    int rc = hfs_gl_shader_compile(gl, GL_VERTEX_SHADER, vert_name, vert_src, defines, &vs,
                                   &why);
    if (rc)
        goto err_report;
    rc = hfs_gl_shader_compile(gl, GL_FRAGMENT_SHADER, frag_name, frag_src, defines, &fs,
                               &why);
    if (rc)
        goto err_vs;

    program = gl->CreateProgram();
    if (!program) {
        rc = hfs_fail(&why, HFS_E_GL, "glCreateProgram returned 0");
        goto err_fs;
    }
    gl->AttachShader(program, vs);
    gl->AttachShader(program, fs);
    gl->LinkProgram(program);
    GLint ok = GL_FALSE;
    gl->GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[1024] = "", line[512];
        gl->GetProgramInfoLog(program, sizeof log, NULL, log);
        fold_log(log, line, sizeof line);
        rc = hfs_fail(&why, HFS_E_GL, "link: %s", line[0] ? line : "failed");
        goto err_program;
    }
    /* Flagged for deletion now, freed with the program. */
    gl->DetachShader(program, vs);
    gl->DetachShader(program, fs);
    gl->DeleteShader(vs);
    gl->DeleteShader(fs);
    *out = program;
    return HFS_OK;

err_program:
    gl->DeleteProgram(program);
err_fs:
    gl->DeleteShader(fs);
err_vs:
    gl->DeleteShader(vs);
err_report:
    return hfs_fail(err, rc, "%s: %s", label, why.msg);
}

int hfs_gl_program_create(const hfs_gl *gl, const char *vert, const char *frag,
                          const char *const *defines, GLuint *out, hfs_error *err)
{
    const char *vs = hfs_shader_source(vert), *fs = hfs_shader_source(frag);
    *out = 0;
    if (!vs || !fs)
        return hfs_fail(err, HFS_E_INVALID, "program %.60s+%.60s: no embedded shader \"%.60s\"",
                        vert, frag, vs ? frag : vert);
    return hfs_gl_program_from_sources(gl, vert, vs, frag, fs, defines, out, err);
}

/* ---- render targets ------------------------------------------------------ */

typedef struct target_format {
    GLenum internal_format;
    const char *name;
    int needs_half;       /* 1: needs GL_EXT_color_buffer_half_float */
} target_format;

static const target_format target_formats[] = {
    { GL_RGBA16F, "GL_RGBA16F", 1 },
    { GL_RG16F, "GL_RG16F", 1 },
    { GL_R16F, "GL_R16F", 1 },
    { GL_RGBA8, "GL_RGBA8", 0 },
    { GL_RGBA32UI, "GL_RGBA32UI", 0 }, /* floats' bits, read exactly (gl_probe.c) */
};

int hfs_gl_target_create(const hfs_gl *gl, int width, int height, GLenum internal_format,
                         hfs_gl_target *t, hfs_error *err)
{
    int rc;
    memset(t, 0, sizeof *t);
    const target_format *f = NULL;
    for (size_t i = 0; i < sizeof target_formats / sizeof target_formats[0]; ++i)
        if (target_formats[i].internal_format == internal_format)
            f = &target_formats[i];
    if (!f)
        return hfs_fail(err, HFS_E_INVALID, "render target: format 0x%x not supported",
                        (unsigned)internal_format);
    GLint max_size = 0;
    gl->GetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
    if (width < 1 || height < 1 || width > max_size || height > max_size)
        return hfs_fail(err, width < 1 || height < 1 ? HFS_E_INVALID : HFS_E_UNSUPPORTED,
                        "render target: %dx%d outside 1..%d (GL_MAX_TEXTURE_SIZE)",
                        width, height, (int)max_size);
    if (f->needs_half && !gl->render_half_float)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "render target: %s is not colour-renderable "
                        "(needs GL_EXT_color_buffer_half_float)", f->name);
    rc = hfs_gl_check(gl, "render target: pending error", err);
    if (rc)
        return rc;

    gl->GenTextures(1, &t->texture);
    gl->BindTexture(GL_TEXTURE_2D, t->texture);
    gl->TexStorage2D(GL_TEXTURE_2D, 1, internal_format, width, height);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    gl->GenFramebuffers(1, &t->framebuffer);
    gl->BindFramebuffer(GL_FRAMEBUFFER, t->framebuffer);
    gl->FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t->texture, 0);
    rc = hfs_gl_check(gl, "render target", err);
    if (rc)
        goto err_objects;
    GLenum status = gl->CheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        rc = hfs_fail(err, HFS_E_UNSUPPORTED, "render target: %s %dx%d framebuffer "
                      "incomplete (0x%x)", f->name, width, height, (unsigned)status);
        goto err_objects;
    }
    t->internal_format = internal_format;
    t->width = width;
    t->height = height;
    return HFS_OK;

err_objects:
    hfs_gl_target_destroy(gl, t);
    return rc;
}

void hfs_gl_target_destroy(const hfs_gl *gl, hfs_gl_target *t)
{
    if (!t)
        return;
    if (t->framebuffer)
        gl->DeleteFramebuffers(1, &t->framebuffer);
    if (t->texture)
        gl->DeleteTextures(1, &t->texture);
    memset(t, 0, sizeof *t);
}

/* ---- readback ------------------------------------------------------------- */

#define HALF_FLOAT_OES_ 0x8D61 /* what some ES drivers report for 16F buffers */

static const char *type_name(GLenum type)
{
    switch (type) {
    case GL_FLOAT: return "GL_FLOAT";
    case GL_HALF_FLOAT: return "GL_HALF_FLOAT";
    case HALF_FLOAT_OES_: return "GL_HALF_FLOAT_OES";
    default: return "?";
    }
}

int hfs_gl_read_rgba_raw(const hfs_gl *gl, GLuint framebuffer, int x, int y, int w, int h,
                         hfs_gl_read_path path, void *out, hfs_gl_read_path *used,
                         hfs_error *err)
{
    if (!framebuffer || !out || w < 1 || h < 1 || x < 0 || y < 0 ||
        (size_t)w > SIZE_MAX / 4 / sizeof(float) / (size_t)h)
        return hfs_fail(err, HFS_E_INVALID, "readback: bad arguments (framebuffer %u, "
                        "%dx%d at %d,%d)", (unsigned)framebuffer, w, h, x, y);
    int rc = hfs_gl_check(gl, "readback: pending error from an earlier call", err);
    if (rc)
        return rc;

    GLint old_fbo = 0, old_read_buffer = GL_COLOR_ATTACHMENT0, old_pbo = 0;
    GLint old_align = 4, old_row_length = 0, old_skip_rows = 0, old_skip_pixels = 0;
    gl->GetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &old_fbo);
    gl->GetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &old_pbo);
    gl->GetIntegerv(GL_PACK_ALIGNMENT, &old_align);
    gl->GetIntegerv(GL_PACK_ROW_LENGTH, &old_row_length);
    gl->GetIntegerv(GL_PACK_SKIP_ROWS, &old_skip_rows);
    gl->GetIntegerv(GL_PACK_SKIP_PIXELS, &old_skip_pixels);

    gl->BindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    gl->GetIntegerv(GL_READ_BUFFER, &old_read_buffer); /* per-framebuffer state */
    gl->ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl->BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    gl->PixelStorei(GL_PACK_ALIGNMENT, 4);
    gl->PixelStorei(GL_PACK_ROW_LENGTH, 0);
    gl->PixelStorei(GL_PACK_SKIP_ROWS, 0);
    gl->PixelStorei(GL_PACK_SKIP_PIXELS, 0);

    GLenum type = GL_FLOAT;
    if (path == HFS_GL_READ_HALF) {
        type = GL_HALF_FLOAT;
    } else if (path == HFS_GL_READ_AUTO) {
        GLint impl_format = 0, impl_type = 0;
        gl->GetIntegerv(GL_IMPLEMENTATION_COLOR_READ_FORMAT, &impl_format);
        gl->GetIntegerv(GL_IMPLEMENTATION_COLOR_READ_TYPE, &impl_type);
        if (impl_format == GL_RGBA && (impl_type == GL_FLOAT || impl_type == GL_HALF_FLOAT ||
                                       impl_type == HALF_FLOAT_OES_))
            type = (GLenum)impl_type;
    }
    rc = hfs_gl_check(gl, "readback: setup", err);
    if (rc)
        goto out_restore;

    gl->ReadPixels(x, y, w, h, GL_RGBA, type, out);
    if (gl->GetError() != GL_NO_ERROR)
        rc = hfs_fail(err, HFS_E_GL, "readback: glReadPixels(GL_RGBA, %s) rejected",
                      type_name(type));
    if (!rc) {
        char what[96];
        snprintf(what, sizeof what, "readback: glReadPixels(GL_RGBA, %s)", type_name(type));
        rc = hfs_gl_check(gl, what, err);
    }
    if (!rc && used)
        *used = type == GL_FLOAT ? HFS_GL_READ_FLOAT : HFS_GL_READ_HALF;

out_restore:
    for (int i = 0; i < 16 && gl->GetError() != GL_NO_ERROR; ++i) /* reported in rc */
        ;
    gl->ReadBuffer((GLenum)old_read_buffer);
    gl->BindFramebuffer(GL_READ_FRAMEBUFFER, (GLuint)old_fbo);
    gl->BindBuffer(GL_PIXEL_PACK_BUFFER, (GLuint)old_pbo);
    gl->PixelStorei(GL_PACK_ALIGNMENT, old_align);
    gl->PixelStorei(GL_PACK_ROW_LENGTH, old_row_length);
    gl->PixelStorei(GL_PACK_SKIP_ROWS, old_skip_rows);
    gl->PixelStorei(GL_PACK_SKIP_PIXELS, old_skip_pixels);
    return rc;
}

void hfs_gl_widen_halves(float *buf, size_t n)
{
    /* from the end: float i lies at or after every half j <= i */
    const uint16_t *half = (const uint16_t *)(void *)buf;
    for (size_t i = n; i-- > 0;)
        buf[i] = hfs_half_to_float(half[i]);
}

int hfs_gl_read_rgba(const hfs_gl *gl, GLuint framebuffer, int x, int y, int w, int h,
                     hfs_gl_read_path path, float *out, hfs_gl_read_path *used,
                     hfs_error *err)
{
    hfs_gl_read_path took = HFS_GL_READ_FLOAT;
    int rc = hfs_gl_read_rgba_raw(gl, framebuffer, x, y, w, h, path, out, &took, err);
    if (!rc && took == HFS_GL_READ_HALF)
        hfs_gl_widen_halves(out, (size_t)w * (size_t)h * 4);
    if (!rc && used)
        *used = took;
    return rc;
}
