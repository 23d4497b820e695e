/*
 * programs.c — see programs.h.
 */
#include "programs.h"

#include "gl_shaders.h"
#include "gl_util.h"
#include "layout.h"
#include "split_horizon.h"
#include "visibility.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The generated GLSL SH product (runtime/gles/CMakeLists.txt embeds sh_product.glsl.inc),
 * NUL-terminated. */
extern const char hfs_gles_sh_product_src[];

typedef struct program_row {
    const char *shader;   /* "env_horizons.frag" */
    const char *vert;     /* "fullscreen.vert", or the row's own (HFS_PROGRAM_VS) */
    int product;
    const char *samplers; /* space-separated, unit = position */
    const char *blocks;
} program_row;

static const program_row rows[HFS_PROG_COUNT] = {
#define HFS_PROGRAM(id, shader, product, samplers, blocks) \
    [id] = {#shader ".frag", "fullscreen.vert", product, samplers, blocks},
#define HFS_PROGRAM_VS(id, vert, shader, product, samplers, blocks) \
    [id] = {#shader ".frag", #vert ".vert", product, samplers, blocks},
#include "programs.def"
#undef HFS_PROGRAM
#undef HFS_PROGRAM_VS
};

static const char *const block_names[HFS_BLOCK_COUNT] = {
    [HFS_BLOCK_SCALES] = "HfsScales", [HFS_BLOCK_SWATH] = "HfsSwath",
    [HFS_BLOCK_SHADE] = "HfsShade", [HFS_BLOCK_KEYS] = "HfsKeys", [HFS_BLOCK_LOCAL] = "HfsLocal",
    [HFS_BLOCK_BOUNCE] = "HfsBounce",
    [HFS_BLOCK_VIEW] = "HfsView"};

const char *hfs_gles_program_shader(hfs_gles_program_id id)
{
    return rows[id].shader;
}

int hfs_gles_program_has_product(hfs_gles_program_id id)
{
    return rows[id].product;
}

void hfs_gles_variant_defines(const hfs_gles_variant *v, int pair_fetch, char bufs[][32],
                              const char *defs[HFS_GLES_MAX_DEFINES + 1])
{
    const struct { const char *name; int value; } all[] = {
        {"HFS_SCALES_MAX", HFS_GLES_MAX_LEVELS}, {"HFS_NLAYERS", v->n_layers},
        {"HFS_NOUT", v->n_out},        {"HFS_NDIR", v->n_dir},
        {"HFS_RECON_V", v->recon_v},   {"HFS_KEY_VEC4", v->key_vec4},
        {"HFS_NKEYS", v->n_keys},      {"HFS_ENV", v->env},
        {"HFS_LOCAL", v->local},       {"HFS_LOCAL_DIRS", v->local_dirs},
        {"HFS_NLOCAL", v->n_local},    {"HFS_TABLES", v->tables},
        {"HFS_TABLE_N", v->tables ? HFS_VIS_TABLE_SIZE : 0},
        {"HFS_FP32", v->fp32},         {"HFS_COUNT", v->count},
        {"HFS_SWATH_TEX", v->swath_tex}, {"HFS_KEYS_TEX", v->keys_tex},
        {"HFS_LOCAL_TEX", v->local_tex}, {"HFS_SLICE", v->slice},
        {"HFS_ALBEDO_MAP", v->albedo_map}, {"HFS_NBDIR", v->n_bdir},
        {"HFS_GLOSSY", v->glossy},     {"HFS_ENV_MAP", v->env_map},
        {"HFS_ENV_DOT", v->env_dot},   {"HFS_ENV_OCC", v->env_occ},
        {"HFS_PAIRS", v->pairs},       {"HFS_FARK", v->far_k},
        {"HFS_FARH", v->far_h > 1 ? v->far_h : 0},
        {"HFS_FAR_ATLAS", v->far_atlas}, {"HFS_GLOSS_MAP", v->gloss_map},
        {"HFS_NEAR", v->near},         {"HFS_CELLS", v->cells},
        {"HFS_SRC_LAYERS", v->src_layers},
        {"HFS_PAIR_FETCH", pair_fetch}, {"HFS_FAR_STEEP", HFS_SPLIT_STEEP}};
    _Static_assert(sizeof all / sizeof all[0] <= HFS_GLES_MAX_DEFINES, "defines");
    int n = 0;
    for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i)
        if (all[i].value) {
            snprintf(bufs[n], 32, "%s %d", all[i].name, all[i].value);
            defs[n] = bufs[n];
            ++n;
        }
    defs[n] = NULL;
}

/* Unit of `sampler` in the row's list, or -1. */
static int sampler_unit(const program_row *row, const char *sampler)
{
    const size_t len = strlen(sampler);
    int unit = 0;
    for (const char *s = row->samplers; *s;) {
        const size_t w = strcspn(s, " ");
        if (w == len && !strncmp(s, sampler, len))
            return unit;
        s += w;
        s += strspn(s, " ");
        ++unit;
    }
    return -1;
}

static int is_sampler(GLenum type)
{
    static const GLenum types[] = {
        GL_SAMPLER_2D, GL_SAMPLER_3D, GL_SAMPLER_CUBE, GL_SAMPLER_2D_SHADOW,
        GL_SAMPLER_2D_ARRAY, GL_SAMPLER_2D_ARRAY_SHADOW, GL_SAMPLER_CUBE_SHADOW,
        GL_INT_SAMPLER_2D, GL_INT_SAMPLER_3D, GL_INT_SAMPLER_CUBE, GL_INT_SAMPLER_2D_ARRAY,
        GL_UNSIGNED_INT_SAMPLER_2D, GL_UNSIGNED_INT_SAMPLER_3D, GL_UNSIGNED_INT_SAMPLER_CUBE,
        GL_UNSIGNED_INT_SAMPLER_2D_ARRAY};
    for (size_t i = 0; i < sizeof types / sizeof types[0]; ++i)
        if (type == types[i])
            return 1;
    return 0;
}

/* Sets every sampler's unit and every block's binding from the row, and
 * refuses samplers or blocks the row does not list. */
static int bind_interface(const hfs_gl *gl, GLuint id, const program_row *row, hfs_error *err)
{
    GLint n_uniforms = 0, n_blocks = 0;
    gl->GetProgramiv(id, GL_ACTIVE_UNIFORMS, &n_uniforms);
    for (GLint i = 0; i < n_uniforms; ++i) {
        char name[64];
        GLint size = 0;
        GLenum type = 0;
        gl->GetActiveUniform(id, (GLuint)i, sizeof name, NULL, &size, &type, name);
        if (!is_sampler(type))
            continue;
        char *bracket = strstr(name, "[0]"); /* an array reports its first element */
        for (GLint k = 0; k < size; ++k) {
            char el[72];
            if (bracket)
                snprintf(el, sizeof el, "%.*s[%d]", (int)(bracket - name), name, (int)k);
            else
                snprintf(el, sizeof el, "%s", name);
            const int unit = sampler_unit(row, el);
            if (unit < 0)
                return hfs_fail(err, HFS_E_INVALID, "backend gles: %s samples %s, which its "
                                "row of programs.def does not list", row->shader, el);
            gl->Uniform1i(gl->GetUniformLocation(id, el), unit);
        }
    }
    int found = 0;
    for (int b = 0; b < HFS_BLOCK_COUNT; ++b) {
        const GLuint idx = gl->GetUniformBlockIndex(id, block_names[b]);
        if (idx == GL_INVALID_INDEX)
            continue;
        if (!strstr(row->blocks, block_names[b]))
            return hfs_fail(err, HFS_E_INVALID, "backend gles: %s reads block %s, which its "
                            "row of programs.def does not list", row->shader, block_names[b]);
        gl->UniformBlockBinding(id, idx, (GLuint)b);
        ++found;
    }
    gl->GetProgramiv(id, GL_ACTIVE_UNIFORM_BLOCKS, &n_blocks);
    if (n_blocks != found)
        return hfs_fail(err, HFS_E_INVALID, "backend gles: %s reads a uniform block that "
                        "programs.h does not know", row->shader);
    return HFS_OK;
}

/* "gles_pairs + gles_lib + gles_ray + gles_view + [product] + pass", linked
 * with the row's vertex shader (source strings 5, 1, 3, 4, 2, 0 in driver
 * messages). */
static int build(const hfs_gl *gl, const program_row *row, const hfs_gles_variant *v,
                 int pair_fetch, GLuint *out, hfs_error *err)
{
    const char *pairs = hfs_shader_source("gles_pairs.frag");
    const char *lib = hfs_shader_source("gles_lib.frag");
    const char *ray = hfs_shader_source("gles_ray.frag");
    const char *look = hfs_shader_source("gles_view.frag");
    const char *pass = hfs_shader_source(row->shader);
    const char *vert = hfs_shader_source(row->vert);
    if (!pairs || !lib || !ray || !look || !pass || !vert)
        return hfs_fail(err, HFS_E_INVALID, "backend gles: shader %s not embedded", row->shader);
    const char *prod = row->product ? hfs_gles_sh_product_src : "";
    const size_t size = strlen(pairs) + strlen(lib) + strlen(ray) + strlen(look) + strlen(prod) +
                        strlen(pass) + 120;
    char *src = malloc(size);
    if (!src)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory");
    snprintf(src, size,
             "#line 1 5\n%s\n#line 1 1\n%s\n#line 1 3\n%s\n#line 1 4\n%s\n#line 1 2\n%s\n"
             "#line 1 0\n%s",
             pairs, lib, ray, look, prod, pass);
    /* The generated product carries UTF-8 in a comment; GLSL ES 3.00 knows
     * ASCII only. */
    for (char *c = src; *c; ++c)
        if ((unsigned char)*c >= 0x80)
            *c = ' ';
    char bufs[HFS_GLES_MAX_DEFINES][32];
    const char *defs[HFS_GLES_MAX_DEFINES + 1];
    hfs_gles_variant_defines(v, pair_fetch, bufs, defs);
    int rc = hfs_gl_program_from_sources(gl, row->vert, vert, row->shader, src, defs,
                                         out, err);
    free(src);
    if (rc)
        return rc;
    gl->UseProgram(*out);
    rc = bind_interface(gl, *out, row, err);
    gl->UseProgram(0);
    if (!rc)
        rc = hfs_gl_check(gl, row->shader, err);
    if (rc)
        gl->DeleteProgram(*out);
    return rc;
}

int hfs_gles_program_use(hfs_gles_programs *c, const hfs_gl *gl, hfs_gles_program_id id,
                         const hfs_gles_variant *v, const hfs_gles_program **out,
                         hfs_error *err)
{
    hfs_gles_program *p = NULL;
    for (int i = 0; i < c->n && !p; ++i)
        if (c->prog[i].id == id && !memcmp(&c->prog[i].variant, v, sizeof *v))
            p = &c->prog[i];
    if (!p) {
        if (c->n == HFS_GLES_MAX_PROGRAMS) /* a pathological sequence of settings */
            hfs_gles_programs_free(c, gl);
        GLuint name = 0;
        int rc = build(gl, &rows[id], v, c->pair_fetch, &name, err);
        if (rc)
            return rc;
        p = &c->prog[c->n++];
        p->id = id;
        p->variant = *v;
        p->name = name;
    }
    gl->UseProgram(p->name);
    *out = p;
    return HFS_OK;
}

void hfs_gles_programs_free(hfs_gles_programs *c, const hfs_gl *gl)
{
    for (int i = 0; i < c->n; ++i)
        gl->DeleteProgram(c->prog[i].name);
    c->n = 0;
}

int hfs_gles_program_texture(const hfs_gl *gl, const hfs_gles_program *p, const char *sampler,
                             GLenum target, GLuint t, hfs_error *err)
{
    const int unit = sampler_unit(&rows[p->id], sampler);
    if (unit < 0)
        return hfs_fail(err, HFS_E_INVALID, "backend gles: %s has no sampler %s in "
                        "programs.def", rows[p->id].shader, sampler);
    gl->ActiveTexture(GL_TEXTURE0 + (GLenum)unit);
    gl->BindTexture(target, t);
    return HFS_OK;
}

void hfs_gles_set_i1(const hfs_gl *gl, const hfs_gles_program *p, const char *name, int a)
{
    GLint loc = gl->GetUniformLocation(p->name, name);
    if (loc >= 0)
        gl->Uniform1i(loc, a);
}

void hfs_gles_set_i2(const hfs_gl *gl, const hfs_gles_program *p, const char *name, int a,
                     int b)
{
    GLint loc = gl->GetUniformLocation(p->name, name);
    if (loc >= 0)
        gl->Uniform2i(loc, a, b);
}

void hfs_gles_set_f1(const hfs_gl *gl, const hfs_gles_program *p, const char *name, float a)
{
    GLint loc = gl->GetUniformLocation(p->name, name);
    if (loc >= 0)
        gl->Uniform1f(loc, a);
}

void hfs_gles_set_f2(const hfs_gl *gl, const hfs_gles_program *p, const char *name, float a,
                     float b)
{
    GLint loc = gl->GetUniformLocation(p->name, name);
    if (loc >= 0)
        gl->Uniform2f(loc, a, b);
}

void hfs_gles_set_f4(const hfs_gl *gl, const hfs_gles_program *p, const char *name,
                     const double v[4])
{
    GLint loc = gl->GetUniformLocation(p->name, name);
    if (loc >= 0)
        gl->Uniform4f(loc, (float)v[0], (float)v[1], (float)v[2], (float)v[3]);
}
