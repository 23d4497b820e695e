/*
 * gl_caps.c — see gl_caps.h.
 */
#include "gl_caps.h"

#include <stdio.h>
#include <string.h>

/* ES 3.0 minimum maximums (OpenGL ES 3.0.6, table 6.28ff): what every
 * conformant ES 3.0 device guarantees, hence the es30 profiles' caps. */
#define ES30_MAX_TEXTURE_SIZE 2048
#define ES30_MAX_ARRAY_TEXTURE_LAYERS 256
#define ES30_MAX_DRAW_BUFFERS 4
#define ES30_MAX_UNIFORM_BLOCK_SIZE 16384
#define ES30_MAX_FRAGMENT_UNIFORM_BLOCKS 12
#define ES30_MAX_UNIFORM_BUFFER_BINDINGS 24
#define ES30_MAX_TEXTURE_IMAGE_UNITS 16
#define ES30_UNIFORM_BUFFER_OFFSET_ALIGNMENT 256 /* the largest allowed value */
#define ES30_MAX_RENDERBUFFER_SIZE 2048
#define ES30_MAX_VERTEX_TEXTURE_IMAGE_UNITS 16
#define VIEW_MAX_SAMPLES 4 /* more costs fill rate for little on a terrain view */

static int geti(const hfs_gl *gl, GLenum pname)
{
    GLint v = 0;
    gl->GetIntegerv(pname, &v);
    return (int)v;
}

void hfs_gl_caps_query(const hfs_gl *gl, hfs_gl_driver *d)
{
    memset(d, 0, sizeof *d);
    d->is_es = gl->is_es;
    d->major = gl->major;
    d->minor = gl->minor;
    if (gl->is_es) {
        const int es32 = gl->major > 3 || (gl->major == 3 && gl->minor >= 2);
        d->color_buffer_float = es32 || hfs_gl_has_extension(gl, "GL_EXT_color_buffer_float");
        d->color_buffer_half_float =
            d->color_buffer_float || hfs_gl_has_extension(gl, "GL_EXT_color_buffer_half_float");
        d->texture_float_linear = hfs_gl_has_extension(gl, "GL_OES_texture_float_linear");
        d->float_blend = hfs_gl_has_extension(gl, "GL_EXT_float_blend");
    } else {
        /* Desktop >= 3.3 core: float formats renderable and filterable. */
        d->color_buffer_float = d->color_buffer_half_float = d->texture_float_linear = 1;
        d->float_blend = 1;
    }
    d->timer_query = gl->timer_query;
    d->max_texture_size = geti(gl, GL_MAX_TEXTURE_SIZE);
    d->max_array_texture_layers = geti(gl, GL_MAX_ARRAY_TEXTURE_LAYERS);
    const int db = geti(gl, GL_MAX_DRAW_BUFFERS), ca = geti(gl, GL_MAX_COLOR_ATTACHMENTS);
    d->max_draw_buffers = db < ca ? db : ca;
    d->max_uniform_block_size = geti(gl, GL_MAX_UNIFORM_BLOCK_SIZE);
    d->max_fragment_uniform_blocks = geti(gl, GL_MAX_FRAGMENT_UNIFORM_BLOCKS);
    d->max_uniform_buffer_bindings = geti(gl, GL_MAX_UNIFORM_BUFFER_BINDINGS);
    d->max_texture_image_units = geti(gl, GL_MAX_TEXTURE_IMAGE_UNITS);
    d->uniform_buffer_offset_alignment = geti(gl, GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT);
    d->max_renderbuffer_size = geti(gl, GL_MAX_RENDERBUFFER_SIZE);
    gl->GetIntegerv(GL_MAX_VIEWPORT_DIMS, d->max_viewport);
    d->max_vertex_texture_image_units = geti(gl, GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS);
    /* Multisampling of the view's RGBA16F target: the format's own answer
     * (ES 3.0 core does not make RGBA16F renderable; the extension may or
     * may not allow samples), never more than GL_MAX_SAMPLES. */
    GLint samples = 0;
    gl->GetInternalformativ(GL_RENDERBUFFER, GL_RGBA16F, GL_SAMPLES, 1, &samples);
    const int max_samples = geti(gl, GL_MAX_SAMPLES);
    d->samples_rgba16f = samples < max_samples ? samples : max_samples;
    for (int i = 0; i < 16 && gl->GetError() != GL_NO_ERROR; ++i)
        ; /* an unknown pname on an odd driver must not leak an error */
}

const char *hfs_gl_profile_names(void)
{
    return "es30-half, es30-float, es32";
}

static int cap(int driver, int profile)
{
    return profile > 0 && driver > profile ? profile : driver;
}

int hfs_gl_caps_select(const hfs_gl_driver *d, const char *profile, int want_fp32,
                       int strict_limits, hfs_gl_caps *c, hfs_error *err)
{
    if (!profile)
        profile = want_fp32 ? "es30-float" : "es30-half";
    int float_profile, es30;
    if (!strcmp(profile, "es30-half"))
        float_profile = 0, es30 = 1;
    else if (!strcmp(profile, "es30-float"))
        float_profile = 1, es30 = 1;
    else if (!strcmp(profile, "es32"))
        float_profile = 0, es30 = 0;
    else
        return hfs_fail(err, HFS_E_INVALID, "profile \"%.40s\": unknown (known: %s)", profile,
                        hfs_gl_profile_names());
    if (want_fp32 && es30 && !float_profile)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "profile es30-half: precision fp32 needs float "
                        "render targets (profile es30-float or es32)");
    const int fp32 = float_profile || want_fp32; /* features the profile must have */

    if (d->is_es && (d->major < 3))
        return hfs_fail(err, HFS_E_UNSUPPORTED, "profile %s: OpenGL ES %d.%d, need 3.0", profile,
                        d->major, d->minor);
    if (!es30 && d->is_es && d->major == 3 && d->minor < 2)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "profile es32: this driver offers OpenGL ES "
                        "%d.%d only", d->major, d->minor);
    if (!d->color_buffer_half_float)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "profile %s: GL_EXT_color_buffer_half_float "
                        "is not offered by this driver (fp16 render targets)", profile);
    if (!es30 && d->is_es && !d->color_buffer_float)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "profile es32: float render targets (core in "
                        "ES 3.2) are not offered by this driver");
    if (fp32 && !d->color_buffer_float)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "profile %s: GL_EXT_color_buffer_float is not "
                        "offered by this driver (fp32 render targets)", profile);
    if (fp32 && !d->texture_float_linear)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "profile %s: GL_OES_texture_float_linear is "
                        "not offered by this driver (fp32 filtering)", profile);

    hfs_gl_caps out;
    memset(&out, 0, sizeof out);
    snprintf(out.profile, sizeof out.profile, "%s", profile);
    out.driver = *d;
    out.fp32 = want_fp32 != 0;
    out.fmt_r = out.fp32 ? GL_R32F : GL_R16F;
    out.fmt_rg = out.fp32 ? GL_RG32F : GL_RG16F;
    out.fmt_rgba = out.fp32 ? GL_RGBA32F : GL_RGBA16F;
    out.fmt_block = GL_RGBA16UI;
    out.type_upload = out.fp32 ? GL_FLOAT : GL_HALF_FLOAT;
    out.bytes_r = out.fp32 ? 4 : 2;
    out.bytes_rg = out.fp32 ? 8 : 4;
    out.bytes_rgba = out.fp32 ? 16 : 8;
    /* Features come from the profile; limits from the driver, unless strict
     * limits ask for the ES 3.0 minimums (what every ES 3.0 device has). */
    const int strict = es30 && strict_limits;
    out.strict_limits = strict;
    out.max_texture_size = cap(d->max_texture_size, strict ? ES30_MAX_TEXTURE_SIZE : 0);
    out.max_array_texture_layers =
        cap(d->max_array_texture_layers, strict ? ES30_MAX_ARRAY_TEXTURE_LAYERS : 0);
    out.max_draw_buffers = cap(d->max_draw_buffers, strict ? ES30_MAX_DRAW_BUFFERS : 0);
    out.max_uniform_block_size =
        cap(d->max_uniform_block_size, strict ? ES30_MAX_UNIFORM_BLOCK_SIZE : 0);
    out.max_fragment_uniform_blocks =
        cap(d->max_fragment_uniform_blocks, strict ? ES30_MAX_FRAGMENT_UNIFORM_BLOCKS : 0);
    out.max_uniform_buffer_bindings =
        cap(d->max_uniform_buffer_bindings, strict ? ES30_MAX_UNIFORM_BUFFER_BINDINGS : 0);
    out.max_texture_image_units =
        cap(d->max_texture_image_units, strict ? ES30_MAX_TEXTURE_IMAGE_UNITS : 0);
    /* Alignment is a minimum the application must honour: the larger of
     * the two is the safe one. */
    out.uniform_buffer_offset_alignment = d->uniform_buffer_offset_alignment;
    if (strict && out.uniform_buffer_offset_alignment < ES30_UNIFORM_BUFFER_OFFSET_ALIGNMENT)
        out.uniform_buffer_offset_alignment = ES30_UNIFORM_BUFFER_OFFSET_ALIGNMENT;
    if (out.uniform_buffer_offset_alignment < 1)
        out.uniform_buffer_offset_alignment = 1;
    out.timer_query = d->timer_query;
    out.max_renderbuffer_size = cap(d->max_renderbuffer_size, strict ? ES30_MAX_RENDERBUFFER_SIZE : 0);
    for (int a = 0; a < 2; ++a) /* the viewport bounds the view too */
        if (d->max_viewport[a] > 0 && d->max_viewport[a] < out.max_renderbuffer_size)
            out.max_renderbuffer_size = d->max_viewport[a];
    out.max_vertex_texture_image_units =
        cap(d->max_vertex_texture_image_units, strict ? ES30_MAX_VERTEX_TEXTURE_IMAGE_UNITS : 0);
    out.view_samples = d->samples_rgba16f < VIEW_MAX_SAMPLES ? d->samples_rgba16f : VIEW_MAX_SAMPLES;
    if (out.view_samples < 1)
        out.view_samples = 1;
    if (out.max_texture_size < 1 || out.max_array_texture_layers < 1 || out.max_draw_buffers < 1 ||
        out.max_uniform_block_size < 1 || out.max_texture_image_units < 1)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "profile %s: the driver reports no usable "
                        "limits (texture %d, layers %d, draw buffers %d, uniform block %d)",
                        profile, out.max_texture_size, out.max_array_texture_layers,
                        out.max_draw_buffers, out.max_uniform_block_size);
    *c = out;
    return HFS_OK;
}

/* "the driver's limit 4096 (GL_MAX_TEXTURE_SIZE)", or under strict limits
 * "the ES 3.0 minimum 2048 (GL_MAX_TEXTURE_SIZE, strict limits; this driver
 * allows 16384)": every refusal names the limit, its value and whose it is. */
static const char *limit_text(const hfs_gl_caps *c, int limit, int driver, const char *name,
                              char *buf, size_t n)
{
    if (c->strict_limits && limit < driver)
        snprintf(buf, n, "the ES 3.0 minimum %d (%s, strict limits; this driver allows %d)", limit,
                 name, driver);
    else
        snprintf(buf, n, "the driver's limit %d (%s)", limit, name);
    return buf;
}

const char *hfs_gl_caps_texture_limit(const hfs_gl_caps *c, char *buf, size_t n)
{
    return limit_text(c, c->max_texture_size, c->driver.max_texture_size, "GL_MAX_TEXTURE_SIZE",
                      buf, n);
}

int hfs_gl_caps_check_texture(const hfs_gl_caps *c, int w, int h, int layers,
                              const char *what, hfs_error *err)
{
    char t[160];
    if (w > c->max_texture_size || h > c->max_texture_size)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "%s: a %dx%d texture exceeds %s", what, w, h,
                        hfs_gl_caps_texture_limit(c, t, sizeof t));
    if (layers > c->max_array_texture_layers)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "%s: %d array layers exceed %s", what, layers,
                        limit_text(c, c->max_array_texture_layers,
                                   c->driver.max_array_texture_layers,
                                   "GL_MAX_ARRAY_TEXTURE_LAYERS", t, sizeof t));
    return HFS_OK;
}

int hfs_gl_caps_check_uniform_block(const hfs_gl_caps *c, size_t bytes, const char *what,
                                    hfs_error *err)
{
    char t[160];
    if (bytes > (size_t)c->max_uniform_block_size)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "%s: needs a %zu-byte uniform block, over %s",
                        what, bytes,
                        limit_text(c, c->max_uniform_block_size,
                                   c->driver.max_uniform_block_size, "GL_MAX_UNIFORM_BLOCK_SIZE",
                                   t, sizeof t));
    return HFS_OK;
}

int hfs_gl_caps_check_draw_buffers(const hfs_gl_caps *c, int n, const char *what,
                                   hfs_error *err)
{
    char t[160];
    if (n > c->max_draw_buffers)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "%s: needs %d draw buffers, over %s", what, n,
                        limit_text(c, c->max_draw_buffers, c->driver.max_draw_buffers,
                                   "GL_MAX_DRAW_BUFFERS", t, sizeof t));
    return HFS_OK;
}

int hfs_gl_caps_check_samplers(const hfs_gl_caps *c, int n, const char *what, hfs_error *err)
{
    char t[160];
    if (n > c->max_texture_image_units)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "%s: needs %d texture units, over %s", what, n,
                        limit_text(c, c->max_texture_image_units,
                                   c->driver.max_texture_image_units,
                                   "GL_MAX_TEXTURE_IMAGE_UNITS", t, sizeof t));
    return HFS_OK;
}

int hfs_gl_caps_check_view(const hfs_gl_caps *c, int w, int h, int vtex, hfs_error *err)
{
    char t[160];
    if (w > c->max_renderbuffer_size || h > c->max_renderbuffer_size)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "view: a %dx%d image exceeds %s", w, h,
                        limit_text(c, c->max_renderbuffer_size, c->driver.max_renderbuffer_size,
                                   "GL_MAX_RENDERBUFFER_SIZE / GL_MAX_VIEWPORT_DIMS", t,
                                   sizeof t));
    if (vtex > c->max_vertex_texture_image_units)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "view: the vertex shader needs %d texture "
                        "units, over %s", vtex,
                        limit_text(c, c->max_vertex_texture_image_units,
                                   c->driver.max_vertex_texture_image_units,
                                   "GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS", t, sizeof t));
    return HFS_OK;
}
