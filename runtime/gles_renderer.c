/*
 * gles_renderer.c — the GLES renderer backend (backends.h), DESIGN.md "GLES
 * path": the algorithm of the CPU reference (cpu_*.c) on OpenGL ES 3.0 with
 * fp16 textures.
 *
 * A frame, pass by pass (each a small shader of shaders_es/, drawn as one
 * fullscreen triangle into a framebuffer object):
 *   upload       normalized heights as fp16 hi+lo pairs (gles_setup.c) into
 *                the input texture and the last layer of the level array;
 *   normals      full resolution, RGBA (px hi/lo, py hi/lo): octahedral;
 *   decimate     levels N-2 .. lmin, each from the next finer (bilinear);
 *   reconstruct  levels lmin .. N-2 to the full grid (B-spline, 4 fetches),
 *                layers of one RG 2D array texture;
 *   env          horizons + SH visibility on the visibility grid, 4 RGBA MRT;
 *   key          per key light, horizon excess per swath direction;
 *   local        local lights' visibility ratios on the visibility grid,
 *                up to 8 lights per draw (uniform block HfsLocal,
 *                local_upload);
 *   shade        full resolution: H(N), products, lights -> RGB (local
 *                lights: E_cap per texel times the interpolated ratio);
 *   readback     RGBA -> hfs_image (the power-of-two output scale divided out).
 * upload..env depend only on the terrain and the settings: they are skipped
 * while those do not change (the heights are compared with a kept copy).
 *
 * Every format/limit decision goes through gl_caps.h; every GL call through
 * the hfs_gl table of the renderer's own context, which is made current at
 * each call.  Nothing is printed; nothing is global.
 */
#include "backends.h"
#include "cpu_local.h"
#include "visibility.h"
#include "field_geom.h"
#include "gl_caps.h"
#include "gl_context.h"
#include "gl_shaders.h"
#include "gl_util.h"
#include "gles_plan.h"
#include "gles_setup.h"
#include "lights.h"
#include "sh.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* The generated GLSL SH product (runtime/gles.cmake embeds
 * sh_product.glsl.inc), NUL-terminated. */
extern const char hfs_gles_sh_product_src[];

#define PI 3.14159265358979323846
#define MAX_PROGRAMS 64
#define MAX_TABLE_CACHE 12
#define TABLE_N HFS_VIS_TABLE_SIZE
#define MAX_KEYS HFS_MAX_KEY_LIGHTS
#define DIRS_PER_KEY_PASS 8 /* 4 RGBA targets (ES 3.0's minimum) x 2 (hi, lo) pairs */

#define LIGHTS_PER_LOCAL_PASS 8 /* 4 RGBA targets x 2 (hi, lo) ratio pairs */

enum pass_id { P_UPLOAD, P_NORMALS, P_DECIMATE, P_RECON, P_ENV, P_KEY, P_LOCAL, P_TRANSFER,
               P_KFACTOR, P_SHADE, P_READBACK, P_COUNT };
static const char *const pass_names[P_COUNT] = {"upload", "normals", "decimate", "reconstruct",
                                                "env", "key", "local", "transfer",
                                                "keyfactor", "shade", "readback"};

/* Texture units and uniform-block bindings shared by all passes. */
enum { U_LEVELS = 0, U_NORMALS = 1, U_TAB = 2, U_V0 = 2, U_KEYHZ = 6, U_KTAB = 7, U_KTABB = 8,
       U_LOCALV = 9, U_T0 = 2, U_KF = 6, U_SRC = 0, U_VSRC = 4 };
#define RECON_MRT 4 /* levels per y pass: ES 3.0's minimum draw buffers */
enum { B_SCALES = 0, B_SWATH = 1, B_SHADE = 2, B_KEYS = 3, B_LOCAL = 4 };
enum { UBO_SCALES, UBO_ENV, UBO_KEYSWATH, UBO_SHADE, UBO_KEYS, UBO_LOCAL, UBO_COUNT };

typedef struct program {
    char key[224];
    GLuint id;
} program;

typedef struct table_entry {
    double dphi;
    hfs_wedge_tables *t;
    unsigned long used;
} table_entry;

/* GPU resources for one configuration (field size, levels, grid, precision). */
typedef struct resources {
    int valid;
    int w, h, n_levels, lmin, n_layers, vw, vh, fp32;
    GLuint input;
    GLuint lev[HFS_GLES_MAX_LEVELS], lev_fbo[HFS_GLES_MAX_LEVELS];
    GLuint half[HFS_GLES_MAX_LEVELS], half_fbo[HFS_GLES_MAX_LEVELS]; /* W x lh */
    GLuint arr, arr_fbo[HFS_GLES_MAX_LEVELS];
    GLuint arr_mrt_fbo[HFS_GLES_MAX_LEVELS]; /* layers 4g..4g+3 as 4 targets */
    GLuint normals, normals_fbo;
    GLuint venv[4], venv_fbo;
    GLuint keyhz, keyhz_fbo;
    int keyhz_layers;
    GLuint localv, localv_fbo; /* local-light ratios, 2 lights per layer */
    int localv_layers;
    GLuint transfer[4], transfer_fbo; /* T = H * V_env per texel (gles_transfer.frag) */
    GLuint kf, kf_fbo;      /* key factors f / E_max (hi, lo), a layer per key light */
    int kf_layers;
    GLuint out[2], out_fbo; /* RGB hi, lo: drawn together */
    GLuint out_lo_fbo;      /* lo alone as attachment 0, for the readback */
    size_t bytes, keyhz_bytes, localv_bytes, kf_bytes;
    unsigned grid_gen, keyhz_gen, localv_gen, kf_gen; /* bumped when reallocated */
} resources;

/* One key light of the frame. */
typedef struct frame_key {
    hfs_gles_key k;
    hfs_visibility *vis;
    size_t swath_off;  /* bytes into UBO_KEYSWATH */
    size_t swath_size; /* bytes */
    int rec_off;       /* vec4 into HfsKeys */
} frame_key;

struct hfs_gles {
    hfs_gl_context *ctx;
    hfs_gl gl;
    hfs_gl_driver driver;
    hfs_gl_caps caps;
    char profile[16]; /* "" = by precision */
    int strict_limits; /* ES 3.0 minimums instead of the driver's limits */
    GLuint vao;
    GLuint ubo[UBO_COUNT];
    GLuint queries[2 * P_COUNT];
    int have_queries;
    program progs[MAX_PROGRAMS];
    int n_progs;
    resources r;

    /* Terrain cache: what upload..reconstruct were computed from. */
    int terrain_valid;
    float *terrain_z;
    size_t terrain_cap;
    int t_w, t_h, t_k, t_offset, t_fp32;
    double t_dx, t_zscale;

    /* The frame planner (gles_plan.h): which passes a frame runs. */
    hfs_gles_plan plan;
    hfs_field_extent extent;              /* of the kept terrain (lights.h) */
    int key_stride;                       /* horizon layers per key slot */
    int extent_valid;
    float *last_img;                      /* the last image read back, RGB */
    size_t last_img_cap;
    hfs_visibility *env_vis;
    int env_vis_n;

    /* Wedge tables (CPU, cached by dphi) and their textures. */
    table_entry tables[MAX_TABLE_CACHE];
    unsigned long table_clock;
    GLuint env_tab;
    double env_tab_dphi;
    GLuint ktab, ktabb;
    int ktab_sets;
    GLuint loc_tab;        /* local lights' interior table (full local swath) */
    double loc_tab_dphi;
    double ktab_dphi[MAX_KEYS];
    size_t table_bytes;
    int tab_fp32;          /* format of env_tab/ktab/ktabb */

    /* Timing. */
    int timing;
    int timing_finish;     /* glFinish + clock even where timer queries exist */
    double pass_ms[P_COUNT], pass_fetch[P_COUNT];
    int pass_ran[P_COUNT], pass_cached[P_COUNT];
    double pass_t0[P_COUNT];
    hfs_timings last;
    hfs_gles_stats stats;
    char *scratch;
    size_t scratch_cap;
};

/* ---- small helpers ------------------------------------------------------------ */

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

static void *scratch(hfs_gles *g, size_t bytes)
{
    if (bytes > g->scratch_cap) {
        char *p = realloc(g->scratch, bytes);
        if (!p)
            return NULL;
        g->scratch = p;
        g->scratch_cap = bytes;
    }
    return g->scratch;
}


/* ---- timing --------------------------------------------------------------------- */

static int use_queries(const hfs_gles *g)
{
    return g->have_queries && g->caps.timer_query && !g->timing_finish;
}

static void pass_begin(hfs_gles *g, int p)
{
    g->pass_ran[p] = 1;
    if (!g->timing)
        return;
    if (use_queries(g)) {
        g->gl.QueryCounter(g->queries[2 * p], GL_TIMESTAMP_EXT);
    } else {
        g->gl.Finish();
        g->pass_t0[p] = now_ms();
    }
}

static void pass_end(hfs_gles *g, int p)
{
    if (!g->timing)
        return;
    if (use_queries(g)) {
        g->gl.QueryCounter(g->queries[2 * p + 1], GL_TIMESTAMP_EXT);
    } else {
        g->gl.Finish();
        g->pass_ms[p] += now_ms() - g->pass_t0[p];
    }
}

static void collect_queries(hfs_gles *g)
{
    if (!g->timing || !use_queries(g))
        return;
    const hfs_gl *gl = &g->gl;
    for (int p = 0; p < P_COUNT; ++p) {
        if (!g->pass_ran[p])
            continue;
        GLuint64 t0 = 0, t1 = 0;
        gl->GetQueryObjectui64v(g->queries[2 * p], GL_QUERY_RESULT, &t0);
        gl->GetQueryObjectui64v(g->queries[2 * p + 1], GL_QUERY_RESULT, &t1);
        g->pass_ms[p] = t1 > t0 ? (double)(t1 - t0) * 1e-6 : 0.0;
    }
    if (g->gl.is_es) {
        GLint disjoint = 0;
        gl->GetIntegerv(GL_GPU_DISJOINT_EXT, &disjoint);
        if (disjoint)
            for (int p = 0; p < P_COUNT; ++p)
                g->pass_ms[p] = -1.0; /* unreliable: the GPU was disjoint */
    }
    for (int i = 0; i < 8 && gl->GetError() != GL_NO_ERROR; ++i)
        ;
}

/* ---- programs --------------------------------------------------------------------- */

/* Builds "gles_lib + [product] + pass" and links it with fullscreen.vert. */
static int program_get(hfs_gles *g, const char *frag, const char *const *defines,
                       GLuint *out, hfs_error *err)
{
    char key[224];
    size_t used = (size_t)snprintf(key, sizeof key, "%s", frag);
    for (const char *const *d = defines; d && *d && used < sizeof key; ++d)
        used += (size_t)snprintf(key + used, sizeof key - used, "|%s", *d);
    if (used >= sizeof key)
        return hfs_fail(err, HFS_E_INVALID, "backend gles: program key too long (%s)", frag);
    for (int i = 0; i < g->n_progs; ++i)
        if (!strcmp(g->progs[i].key, key)) {
            *out = g->progs[i].id;
            return HFS_OK;
        }
    if (g->n_progs == MAX_PROGRAMS) { /* a pathological sequence of settings */
        for (int i = 0; i < g->n_progs; ++i)
            g->gl.DeleteProgram(g->progs[i].id);
        g->n_progs = 0;
    }

    const char *lib = hfs_shader_source("gles_lib.frag");
    const char *pass = hfs_shader_source(frag);
    const char *vert = hfs_shader_source("fullscreen.vert");
    if (!lib || !pass || !vert)
        return hfs_fail(err, HFS_E_INVALID, "backend gles: shader %s not embedded", frag);
    /* The passes that multiply SH vectors get the generated product. */
    const int with_product = !strcmp(frag, "gles_transfer.frag") ||
                             !strcmp(frag, "gles_keyfactor.frag") || !strcmp(frag, "gles_local.frag");
    const char *prod = with_product ? hfs_gles_sh_product_src : "";
    const size_t size = strlen(lib) + strlen(prod) + strlen(pass) + 64;
    char *src = malloc(size);
    if (!src)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory");
    snprintf(src, size, "#line 1 1\n%s\n#line 1 2\n%s\n#line 1 0\n%s", lib, prod, pass);
    /* The generated product carries UTF-8 in a comment; GLSL ES 3.00 knows
     * ASCII only. */
    for (char *c = src; *c; ++c)
        if ((unsigned char)*c >= 0x80)
            *c = ' ';
    GLuint id = 0;
    int rc = hfs_gl_program_from_sources(&g->gl, "fullscreen.vert", vert, frag, src, defines,
                                         &id, err);
    free(src);
    if (rc)
        return rc;

    /* Fixed sampler units and block bindings (names absent from a program
     * are simply not found). */
    const hfs_gl *gl = &g->gl;
    gl->UseProgram(id);
    static const struct { const char *name; int unit; } samplers[] = {
        {"u_levels", U_LEVELS}, {"u_normals", U_NORMALS}, {"u_tab", U_TAB},
        {"u_src", U_SRC}, {"u_height", U_SRC}, {"u_v0", U_V0}, {"u_v1", U_V0 + 1},
        {"u_v2", U_V0 + 2}, {"u_v3", U_V0 + 3}, {"u_keyhz", U_KEYHZ}, {"u_ktab", U_KTAB},
        {"u_ktabb", U_KTABB}, {"u_localv", U_LOCALV}, {"u_vsrc[0]", U_VSRC}, {"u_vsrc[1]", U_VSRC + 1},
        {"u_vsrc[2]", U_VSRC + 2}, {"u_vsrc[3]", U_VSRC + 3}, {"u_t0", U_T0},
        {"u_t1", U_T0 + 1}, {"u_t2", U_T0 + 2}, {"u_t3", U_T0 + 3}, {"u_kf", U_KF}};
    for (size_t i = 0; i < sizeof samplers / sizeof samplers[0]; ++i) {
        GLint loc = gl->GetUniformLocation(id, samplers[i].name);
        if (loc >= 0)
            gl->Uniform1i(loc, samplers[i].unit);
    }
    static const struct { const char *name; GLuint binding; } blocks[] = {
        {"HfsScales", B_SCALES}, {"HfsSwath", B_SWATH}, {"HfsShade", B_SHADE},
        {"HfsKeys", B_KEYS}, {"HfsLocal", B_LOCAL}};
    for (size_t i = 0; i < sizeof blocks / sizeof blocks[0]; ++i) {
        GLuint idx = gl->GetUniformBlockIndex(id, blocks[i].name);
        if (idx != GL_INVALID_INDEX)
            gl->UniformBlockBinding(id, idx, blocks[i].binding);
    }
    gl->UseProgram(0);
    rc = hfs_gl_check(gl, frag, err);
    if (rc) {
        gl->DeleteProgram(id);
        return rc;
    }
    snprintf(g->progs[g->n_progs].key, sizeof g->progs[g->n_progs].key, "%s", key);
    g->progs[g->n_progs++].id = id;
    *out = id;
    return HFS_OK;
}

static void set_i2(const hfs_gl *gl, GLuint p, const char *name, int a, int b)
{
    GLint loc = gl->GetUniformLocation(p, name);
    if (loc >= 0)
        gl->Uniform2i(loc, a, b);
}

static void set_i1(const hfs_gl *gl, GLuint p, const char *name, int a)
{
    GLint loc = gl->GetUniformLocation(p, name);
    if (loc >= 0)
        gl->Uniform1i(loc, a);
}

static void set_f1(const hfs_gl *gl, GLuint p, const char *name, float a)
{
    GLint loc = gl->GetUniformLocation(p, name);
    if (loc >= 0)
        gl->Uniform1f(loc, a);
}

/* ---- textures and framebuffers ------------------------------------------------------ */

static GLuint tex_new(const hfs_gl *gl, GLenum target, GLenum fmt, int w, int h, int layers,
                      int linear)
{
    GLuint t = 0;
    gl->GenTextures(1, &t);
    gl->BindTexture(target, t);
    if (target == GL_TEXTURE_2D_ARRAY)
        gl->TexStorage3D(target, 1, fmt, w, h, layers);
    else
        gl->TexStorage2D(target, 1, fmt, w, h);
    const GLint f = linear ? GL_LINEAR : GL_NEAREST;
    gl->TexParameteri(target, GL_TEXTURE_MIN_FILTER, f);
    gl->TexParameteri(target, GL_TEXTURE_MAG_FILTER, f);
    gl->TexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl->TexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl->BindTexture(target, 0);
    return t;
}

/* A framebuffer with n colour attachments: 2D textures (layer < 0) or
 * layers of array textures. */
static int fbo_new(const hfs_gl *gl, GLuint *fbo, int n, const GLuint *tex, const int *layer,
                   const char *what, hfs_error *err)
{
    gl->GenFramebuffers(1, fbo);
    gl->BindFramebuffer(GL_FRAMEBUFFER, *fbo);
    GLenum bufs[4];
    for (int i = 0; i < n; ++i) {
        if (layer && layer[i] >= 0)
            gl->FramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + (GLenum)i, tex[i],
                                        0, layer[i]);
        else
            gl->FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + (GLenum)i,
                                     GL_TEXTURE_2D, tex[i], 0);
        bufs[i] = GL_COLOR_ATTACHMENT0 + (GLenum)i;
    }
    gl->DrawBuffers(n, bufs);
    GLenum status = gl->CheckFramebufferStatus(GL_FRAMEBUFFER);
    gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "backend gles: %s framebuffer incomplete "
                        "(0x%x)", what, (unsigned)status);
    return hfs_gl_check(gl, what, err);
}

static void del_tex(const hfs_gl *gl, GLuint *t)
{
    if (*t)
        gl->DeleteTextures(1, t);
    *t = 0;
}

static void del_fbo(const hfs_gl *gl, GLuint *f)
{
    if (*f)
        gl->DeleteFramebuffers(1, f);
    *f = 0;
}

static void grid_free(hfs_gles *g)
{
    const hfs_gl *gl = &g->gl;
    resources *r = &g->r;
    for (int i = 0; i < 4; ++i)
        del_tex(gl, &r->venv[i]);
    del_fbo(gl, &r->venv_fbo);
    del_tex(gl, &r->keyhz);
    r->keyhz_layers = 0;
    r->keyhz_bytes = 0;
    del_tex(gl, &r->localv);
    r->localv_layers = 0;
    r->localv_bytes = 0;
    r->vw = r->vh = 0;
}

static void resources_free(hfs_gles *g)
{
    const hfs_gl *gl = &g->gl;
    resources *r = &g->r;
    grid_free(g);
    del_tex(gl, &r->input);
    for (int i = 0; i < HFS_GLES_MAX_LEVELS; ++i) {
        del_tex(gl, &r->lev[i]);
        del_fbo(gl, &r->lev_fbo[i]);
        del_tex(gl, &r->half[i]);
        del_fbo(gl, &r->half_fbo[i]);
        del_fbo(gl, &r->arr_fbo[i]);
        del_fbo(gl, &r->arr_mrt_fbo[i]);
    }
    del_tex(gl, &r->arr);
    del_tex(gl, &r->normals);
    del_fbo(gl, &r->normals_fbo);
    del_tex(gl, &r->out[0]);
    del_tex(gl, &r->out[1]);
    del_fbo(gl, &r->out_fbo);
    del_fbo(gl, &r->out_lo_fbo);
    del_fbo(gl, &r->keyhz_fbo);
    del_fbo(gl, &r->localv_fbo);
    for (int i = 0; i < 4; ++i)
        del_tex(gl, &r->transfer[i]);
    del_fbo(gl, &r->transfer_fbo);
    del_tex(gl, &r->kf);
    del_fbo(gl, &r->kf_fbo);
    const unsigned gen[4] = {r->grid_gen, r->keyhz_gen, r->localv_gen, r->kf_gen};
    memset(r, 0, sizeof *r);
    r->grid_gen = gen[0] + 1, r->keyhz_gen = gen[1] + 1, r->localv_gen = gen[2] + 1;
    r->kf_gen = gen[3] + 1;
    g->terrain_valid = 0;
}

/* Terrain-sized resources (levels, normals, output) follow the field size,
 * level layout and precision; grid-sized ones (visibility, key horizons)
 * also follow the sub-sampling, without touching the terrain's. */
static int resources_ensure(hfs_gles *g, const hfs_gles_layout *L, int key_layers,
                            int local_layers, int n_keys, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    const hfs_gl_caps *c = &g->caps;
    resources *r = &g->r;
    int rc;
    if (key_layers < 1)
        key_layers = 1;
    if (!(r->valid && r->w == L->w && r->h == L->h && r->n_levels == L->n_levels &&
          r->lmin == L->lmin && r->fp32 == c->fp32)) {
        resources_free(g);
        rc = hfs_gl_check(gl, "backend gles: pending error", err);
        if (rc)
            return rc;
        r->w = L->w, r->h = L->h, r->n_levels = L->n_levels, r->lmin = L->lmin;
        r->n_layers = L->n_layers, r->fp32 = c->fp32;
        const int w = L->w, h = L->h;
        r->input = tex_new(gl, GL_TEXTURE_2D, c->fmt_rg, w, h, 1, 1);
        r->bytes += (size_t)w * h * c->bytes_rg;
        for (int l = L->lmin; l < L->n_levels - 1; ++l) {
            r->lev[l] = tex_new(gl, GL_TEXTURE_2D, c->fmt_rg, L->lw[l], L->lh[l], 1, 1);
            r->bytes += (size_t)L->lw[l] * L->lh[l] * c->bytes_rg;
            if ((rc = fbo_new(gl, &r->lev_fbo[l], 1, &r->lev[l], NULL, "level", err)))
                return rc;
            /* The separable reconstruction's intermediate, its own size so
             * that CLAMP_TO_EDGE clamps at the level's last row. */
            r->half[l] = tex_new(gl, GL_TEXTURE_2D, c->fmt_rg, w, L->lh[l], 1, 1);
            r->bytes += (size_t)w * L->lh[l] * c->bytes_rg;
            if ((rc = fbo_new(gl, &r->half_fbo[l], 1, &r->half[l], NULL, "level", err)))
                return rc;
        }
        r->arr = tex_new(gl, GL_TEXTURE_2D_ARRAY, c->fmt_rg, w, h, L->n_layers, 1);
        r->bytes += (size_t)w * h * L->n_layers * c->bytes_rg;
        for (int i = 0; i < L->n_layers - 1; ++i)
            if ((rc = fbo_new(gl, &r->arr_fbo[i], 1, &r->arr, &i, "level layer", err)))
                return rc;
        for (int i = 0; i < L->n_layers - 1; i += RECON_MRT) {
            const int n = L->n_layers - 1 - i < RECON_MRT ? L->n_layers - 1 - i : RECON_MRT;
            const GLuint att[RECON_MRT] = {r->arr, r->arr, r->arr, r->arr};
            const int lay[RECON_MRT] = {i, i + 1, i + 2, i + 3};
            if ((rc = fbo_new(gl, &r->arr_mrt_fbo[i / RECON_MRT], n, att, lay, "level layers",
                              err)))
                return rc;
        }
        r->normals = tex_new(gl, GL_TEXTURE_2D, c->fmt_rgba, w, h, 1, 0);
        r->bytes += (size_t)w * h * c->bytes_rgba;
        if ((rc = fbo_new(gl, &r->normals_fbo, 1, &r->normals, NULL, "normals", err)))
            return rc;
        r->out[0] = tex_new(gl, GL_TEXTURE_2D, c->fmt_rgba, w, h, 1, 0);
        r->out[1] = tex_new(gl, GL_TEXTURE_2D, c->fmt_rgba, w, h, 1, 0);
        r->bytes += (size_t)2 * w * h * c->bytes_rgba;
        if ((rc = fbo_new(gl, &r->out_fbo, 2, r->out, NULL, "output", err)) ||
            (rc = fbo_new(gl, &r->out_lo_fbo, 1, &r->out[1], NULL, "output", err)))
            return rc;
        for (int i = 0; i < 4; ++i)
            r->transfer[i] = tex_new(gl, GL_TEXTURE_2D, c->fmt_rgba, w, h, 1, 0);
        r->bytes += (size_t)4 * w * h * c->bytes_rgba;
        if ((rc = fbo_new(gl, &r->transfer_fbo, 4, r->transfer, NULL, "env transfer", err)))
            return rc;
        gl->GenFramebuffers(1, &r->kf_fbo);
        gl->GenFramebuffers(1, &r->keyhz_fbo);
        gl->GenFramebuffers(1, &r->localv_fbo);
        r->valid = 1;
    }
    if (r->vw != L->vw || r->vh != L->vh || !r->venv_fbo) {
        grid_free(g);
        r->vw = L->vw, r->vh = L->vh;
        ++r->grid_gen, ++r->keyhz_gen, ++r->localv_gen;
        for (int i = 0; i < 4; ++i)
            r->venv[i] = tex_new(gl, GL_TEXTURE_2D, c->fmt_rgba, L->vw, L->vh, 1, 1);
        if ((rc = fbo_new(gl, &r->venv_fbo, 4, r->venv, NULL, "visibility", err)))
            return rc;
    }
    if (r->keyhz_layers < key_layers) {
        del_tex(gl, &r->keyhz);
        r->keyhz = tex_new(gl, GL_TEXTURE_2D_ARRAY, c->fmt_rgba, L->vw, L->vh, key_layers, 1);
        r->keyhz_layers = key_layers;
        ++r->keyhz_gen;
        r->keyhz_bytes = (size_t)L->vw * L->vh * key_layers * c->bytes_rgba;
    }
    if (n_keys > 0 && r->kf_layers < n_keys) {
        del_tex(gl, &r->kf);
        r->kf = tex_new(gl, GL_TEXTURE_2D_ARRAY, c->fmt_rg, L->w, L->h, n_keys, 0);
        r->kf_layers = n_keys;
        ++r->kf_gen;
        r->kf_bytes = (size_t)L->w * L->h * n_keys * c->bytes_rg;
    }
    if (local_layers > 0 && r->localv_layers < local_layers) {
        del_tex(gl, &r->localv);
        r->localv = tex_new(gl, GL_TEXTURE_2D_ARRAY, c->fmt_rgba, L->vw, L->vh, local_layers, 1);
        r->localv_layers = local_layers;
        ++r->localv_gen;
        r->localv_bytes = (size_t)L->vw * L->vh * local_layers * c->bytes_rgba;
    }
    return hfs_gl_check(gl, "backend gles: allocating textures", err);
}

static size_t resources_bytes(const hfs_gles *g)
{
    const resources *r = &g->r;
    return r->bytes + (size_t)4 * r->vw * r->vh * g->caps.bytes_rgba + r->keyhz_bytes +
           r->localv_bytes + r->kf_bytes;
}

static void bind_tex(const hfs_gl *gl, int unit, GLenum target, GLuint t)
{
    gl->ActiveTexture(GL_TEXTURE0 + (GLenum)unit);
    gl->BindTexture(target, t);
}

static void draw(const hfs_gl *gl, GLuint fbo, int w, int h)
{
    gl->BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl->Viewport(0, 0, w, h);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
}

static void ubo_upload(const hfs_gl *gl, GLuint ubo, const void *data, size_t bytes)
{
    gl->BindBuffer(GL_UNIFORM_BUFFER, ubo);
    gl->BufferData(GL_UNIFORM_BUFFER, (GLsizeiptr)(bytes ? bytes : 16), data, GL_DYNAMIC_DRAW);
    gl->BindBuffer(GL_UNIFORM_BUFFER, 0);
}

/* ---- wedge tables --------------------------------------------------------------------- */

/* Tables of extent dphi (boundary dphi/2), cached (visibility.c builds
 * exactly these: hfs_wedge_tables_create_ext(dphi, dphi/2, 257)). */
static hfs_wedge_tables *tables_get(hfs_gles *g, double dphi, hfs_error *err)
{
    ++g->table_clock;
    int victim = 0;
    for (int i = 0; i < MAX_TABLE_CACHE; ++i) {
        if (g->tables[i].t && g->tables[i].dphi == dphi) {
            g->tables[i].used = g->table_clock;
            return g->tables[i].t;
        }
        if (!g->tables[i].t || g->tables[i].used < g->tables[victim].used)
            victim = i;
        if (!g->tables[i].t)
            break;
    }
    hfs_wedge_tables *t = hfs_wedge_tables_create_ext(dphi, 0.5 * dphi, TABLE_N);
    if (!t) {
        hfs_fail(err, HFS_E_NOMEM, "backend gles: cannot build wedge tables for dphi = %g", dphi);
        return NULL;
    }
    hfs_wedge_tables_destroy(g->tables[victim].t);
    g->tables[victim].t = t;
    g->tables[victim].dphi = dphi;
    g->tables[victim].used = g->table_clock;
    return t;
}

/* Uploads interior (and boundary) tables as set `set` of 4 layers
 * (coefficients 4g..4g+3 in layer 4*set + g). */
static int tables_upload(hfs_gles *g, const hfs_wedge_tables *t, GLuint tab, GLuint tabb, int set,
                         hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    const int n = hfs_wedge_tables_size(t), fp32 = g->caps.fp32;
    const size_t esz = fp32 ? sizeof(float) : sizeof(uint16_t);
    void *buf = scratch(g, (size_t)n * n * 4 * esz);
    if (!buf)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for wedge tables");
    for (int pass = 0; pass < 2; ++pass) {
        GLuint tex = pass ? tabb : tab;
        if (!tex)
            continue;
        const double *src = pass ? hfs_wedge_boundary_data(t) : hfs_wedge_interior_data(t);
        const size_t rows = pass ? 1 : (size_t)n;
        for (int grp = 0; grp < 4; ++grp) {
            for (size_t e = 0; e < rows * (size_t)n; ++e)
                for (int c = 0; c < 4; ++c) {
                    const double v = src[e * 16 + (size_t)(4 * grp + c)];
                    if (fp32)
                        ((float *)buf)[e * 4 + (size_t)c] = (float)v;
                    else
                        ((uint16_t *)buf)[e * 4 + (size_t)c] = hfs_float_to_half((float)v);
                }
            gl->BindTexture(GL_TEXTURE_2D_ARRAY, tex);
            gl->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
            gl->TexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, 4 * set + grp, n, (GLsizei)rows, 1,
                              GL_RGBA, g->caps.type_upload, buf);
            gl->PixelStorei(GL_UNPACK_ALIGNMENT, 4);
        }
    }
    gl->BindTexture(GL_TEXTURE_2D_ARRAY, 0);
    return hfs_gl_check(gl, "backend gles: wedge table upload", err);
}

/* ---- object ------------------------------------------------------------------------------ */

int hfs_gles_create(const char *context, const char *profile, int strict_limits, hfs_gles **out,
                    hfs_error *err)
{
    *out = NULL;
    hfs_gles *g = calloc(1, sizeof *g);
    if (!g)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory");
    int rc = hfs_gl_context_create(context, &g->ctx, err);
    if (rc)
        goto fail;
    if ((rc = hfs_gl_load(&g->gl, hfs_gl_context_loader, g->ctx, err)))
        goto fail;
    hfs_gl_caps_query(&g->gl, &g->driver);
    g->strict_limits = strict_limits != 0;
    if (profile) {
        /* Refuse a bad name or an impossible profile now, not at the first
         * frame. */
        hfs_gl_caps c;
        if ((rc = hfs_gl_caps_select(&g->driver, profile, !strcmp(profile, "es30-float"),
                                     strict_limits, &c, err)))
            goto fail;
        snprintf(g->profile, sizeof g->profile, "%s", profile);
    }
    const hfs_gl *gl = &g->gl;
    gl->GenVertexArrays(1, &g->vao);
    gl->BindVertexArray(g->vao);
    gl->GenBuffers(UBO_COUNT, g->ubo);
    if (g->driver.timer_query) {
        gl->GenQueries(2 * P_COUNT, g->queries);
        g->have_queries = 1;
    }
    gl->Disable(GL_BLEND);
    gl->Disable(GL_DEPTH_TEST);
    gl->Disable(GL_SCISSOR_TEST);
    if ((rc = hfs_gl_check(gl, "backend gles: setup", err)))
        goto fail;
    hfs_gles_plan_init(&g->plan);
    *out = g;
    return HFS_OK;

fail:
    hfs_gles_destroy(g);
    return rc;
}

void hfs_gles_destroy(hfs_gles *g)
{
    if (!g)
        return;
    if (g->ctx && g->gl.GetError && !hfs_gl_context_make_current(g->ctx, NULL)) {
        const hfs_gl *gl = &g->gl;
        resources_free(g);
        for (int i = 0; i < g->n_progs; ++i)
            gl->DeleteProgram(g->progs[i].id);
        if (g->vao)
            gl->DeleteVertexArrays(1, &g->vao);
        gl->DeleteBuffers(UBO_COUNT, g->ubo);
        if (g->have_queries)
            gl->DeleteQueries(2 * P_COUNT, g->queries);
        del_tex(gl, &g->env_tab);
        del_tex(gl, &g->ktab);
        del_tex(gl, &g->ktabb);
        del_tex(gl, &g->loc_tab);
    }
    for (int i = 0; i < MAX_TABLE_CACHE; ++i)
        hfs_wedge_tables_destroy(g->tables[i].t);
    hfs_visibility_destroy(g->env_vis);
    hfs_gl_context_destroy(g->ctx);
    free(g->terrain_z);
    free(g->last_img);
    free(g->scratch);
    free(g);
}

const char *hfs_gles_context_name(const hfs_gles *g)
{
    return hfs_gl_context_name(g->ctx);
}

const char *hfs_gles_describe(const hfs_gles *g)
{
    return hfs_gl_context_describe(g->ctx);
}

void hfs_gles_set_timing_finish(hfs_gles *g, int finish)
{
    g->timing_finish = finish != 0;
}

void hfs_gles_set_amortize(hfs_gles *g, int passes_per_frame)
{
    g->plan.amortize = passes_per_frame;
}

void hfs_gles_set_timing(hfs_gles *g, int level)
{
    g->timing = level < 0 ? 0 : (level > 2 ? 2 : level);
}

void hfs_gles_get_timings(const hfs_gles *g, hfs_timings *t)
{
    *t = g->last;
}

void hfs_gles_invalidate(hfs_gles *g)
{
    g->terrain_valid = 0;
    hfs_gles_plan_drop_all(&g->plan);
}

void hfs_gles_frame_report(const hfs_gles *g, hfs_frame_report *out)
{
    hfs_gles_plan_report(&g->plan, out);
}

void hfs_gles_get_stats(const hfs_gles *g, hfs_gles_stats *s)
{
    *s = g->stats;
}

/* ---- passes --------------------------------------------------------------------------------- */

/* Why the terrain passes must run again, or NULL when what they computed
 * still holds (the heights are compared with the kept copy). */
static const char *terrain_change(const hfs_gles *g, const hfs_field *f, const hfs_quality *q)
{
    const size_t n = (size_t)f->width * (size_t)f->height;
    if (!g->terrain_valid)
        return "terrain not computed yet";
    if (g->t_w != f->width || g->t_h != f->height)
        return "field size changed";
    if (g->t_k != q->k || g->t_offset != q->offset)
        return "pyramid settings (k, offset) changed";
    if (g->t_fp32 != g->caps.fp32)
        return "precision changed";
    if (g->t_dx != f->dx || g->t_zscale != f->zscale)
        return "dx or zscale changed";
    if (memcmp(g->terrain_z, f->z, n * sizeof *f->z))
        return "heights changed";
    return NULL;
}

static int terrain_remember(hfs_gles *g, const hfs_field *f, const hfs_quality *q)
{
    const size_t n = (size_t)f->width * (size_t)f->height;
    if (n > g->terrain_cap) {
        float *z = realloc(g->terrain_z, n * sizeof *z);
        if (!z)
            return 0;
        g->terrain_z = z;
        g->terrain_cap = n;
    }
    memcpy(g->terrain_z, f->z, n * sizeof *f->z);
    g->t_w = f->width, g->t_h = f->height, g->t_k = q->k, g->t_offset = q->offset;
    g->t_fp32 = g->caps.fp32, g->t_dx = f->dx, g->t_zscale = f->zscale;
    return 1;
}

/* upload, normals, decimate, reconstruct. */
static int run_terrain(hfs_gles *g, const hfs_field *f, const hfs_gles_layout *L, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    resources *r = &g->r;
    const int fp32 = g->caps.fp32, w = L->w, h = L->h;
    const char *fpdef = fp32 ? "HFS_FP32 1" : NULL;
    int rc;

    pass_begin(g, P_UPLOAD);
    void *buf = scratch(g, (size_t)w * h * 2 * (fp32 ? 4 : 2));
    if (!buf)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for a %dx%d upload", w, h);
    g->stats.height_split_err = hfs_gles_split_heights(L, f, fp32, buf);
    g->stats.height_scale = L->hscale;
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 4);
    gl->BindTexture(GL_TEXTURE_2D, r->input);
    gl->TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RG, g->caps.type_upload, buf);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    gl->BindTexture(GL_TEXTURE_2D_ARRAY, r->arr);
    gl->TexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, L->n_layers - 1, w, h, 1, GL_RG,
                      g->caps.type_upload, buf);
    gl->BindTexture(GL_TEXTURE_2D_ARRAY, 0);
    pass_end(g, P_UPLOAD);
    if ((rc = hfs_gl_check(gl, "backend gles: upload", err)))
        return rc;

    const char *defs[2] = {fpdef, NULL};
    GLuint prog;
    if ((rc = program_get(g, "gles_normals.frag", defs, &prog, err)))
        return rc;
    pass_begin(g, P_NORMALS);
    gl->UseProgram(prog);
    bind_tex(gl, U_SRC, GL_TEXTURE_2D, r->input);
    set_i2(gl, prog, "u_size", w, h);
    double zf = L->hscale * L->zscale / L->dx;
    set_f1(gl, prog, "u_zfactor", (float)(zf < 1e30 ? zf : 1e30));
    draw(gl, r->normals_fbo, w, h);
    pass_end(g, P_NORMALS);
    g->pass_fetch[P_NORMALS] += 4.0 * w * h;

    if ((rc = program_get(g, "gles_decimate.frag", defs, &prog, err)))
        return rc;
    pass_begin(g, P_DECIMATE);
    gl->UseProgram(prog);
    for (int l = L->n_levels - 2; l >= L->lmin; --l) {
        bind_tex(gl, U_SRC, GL_TEXTURE_2D, l == L->n_levels - 2 ? r->input : r->lev[l + 1]);
        set_i2(gl, prog, "u_dsize", L->lw[l], L->lh[l]);
        draw(gl, r->lev_fbo[l], L->lw[l], L->lh[l]);
        g->pass_fetch[P_DECIMATE] += (double)L->lw[l] * L->lh[l];
    }
    pass_end(g, P_DECIMATE);

    if ((rc = program_get(g, "gles_reconstruct.frag", defs, &prog, err)))
        return rc;
    pass_begin(g, P_RECON);
    gl->UseProgram(prog);
    /* x passes, one per level (the results differ in height)... */
    set_i1(gl, prog, "u_axis", 0);
    for (int l = L->lmin; l < L->n_levels - 1; ++l) {
        bind_tex(gl, U_SRC, GL_TEXTURE_2D, r->lev[l]);
        set_i2(gl, prog, "u_src_size", L->lw[l], L->lh[l]);
        set_i2(gl, prog, "u_dst_size", w, L->lh[l]);
        draw(gl, r->half_fbo[l], w, L->lh[l]);
        g->pass_fetch[P_RECON] += 2.0 * w * L->lh[l] + 2.0 * w * h;
    }
    /* ... then the y passes, RECON_MRT levels per draw. */
    for (int i = 0; i < L->n_layers - 1; i += RECON_MRT) {
        const int n = L->n_layers - 1 - i < RECON_MRT ? L->n_layers - 1 - i : RECON_MRT;
        char vdef[24];
        snprintf(vdef, sizeof vdef, "HFS_RECON_V %d", n);
        const char *vdefs[3] = {vdef, fpdef, NULL};
        GLuint vprog;
        if ((rc = program_get(g, "gles_reconstruct.frag", vdefs, &vprog, err)))
            return rc;
        gl->UseProgram(vprog);
        set_i2(gl, vprog, "u_dst_size", w, h);
        for (int k = 0; k < n; ++k) {
            const int l = L->lmin + i + k;
            char name[16];
            bind_tex(gl, U_VSRC + k, GL_TEXTURE_2D, r->half[l]);
            snprintf(name, sizeof name, "u_vsize[%d]", k);
            set_i2(gl, vprog, name, w, L->lh[l]);
        }
        draw(gl, r->arr_mrt_fbo[i / RECON_MRT], w, h);
    }
    pass_end(g, P_RECON);
    gl->UseProgram(0);
    return hfs_gl_check(gl, "backend gles: pyramid", err);
}

static void level_defines(const hfs_gles_layout *L, char *nlev, char *nlay, size_t size)
{
    snprintf(nlev, size, "HFS_NLEV %d", L->n_levels);
    snprintf(nlay, size, "HFS_NLAYERS %d", L->n_layers);
}


/* The env pass (or its counting twin) into the V targets. */
static int run_env(hfs_gles *g, const hfs_gles_layout *L, int tables, int count, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    resources *r = &g->r;
    char nlev[32], nlay[32], ndir[32], tabn[32];
    level_defines(L, nlev, nlay, sizeof nlev);
    snprintf(ndir, sizeof ndir, "HFS_NDIR %d", g->env_vis_n);
    snprintf(tabn, sizeof tabn, "HFS_TABLE_N %d", TABLE_N);
    const char *defs[9];
    int nd = 0;
    defs[nd++] = nlev;
    defs[nd++] = nlay;
    defs[nd++] = ndir;
    if (tables) {
        defs[nd++] = "HFS_TABLES 1";
        defs[nd++] = tabn;
    }
    if (g->caps.fp32)
        defs[nd++] = "HFS_FP32 1";
    if (count)
        defs[nd++] = "HFS_COUNT 1";
    defs[nd] = NULL;
    GLuint prog;
    int rc = program_get(g, "gles_env.frag", defs, &prog, err);
    if (rc)
        return rc;
    gl->UseProgram(prog);
    bind_tex(gl, U_LEVELS, GL_TEXTURE_2D_ARRAY, r->arr);
    bind_tex(gl, U_NORMALS, GL_TEXTURE_2D, r->normals);
    if (tables)
        bind_tex(gl, U_TAB, GL_TEXTURE_2D_ARRAY, g->env_tab);
    set_i2(gl, prog, "u_size", L->w, L->h);
    set_i1(gl, prog, "u_sub", L->sub);
    /* A hair above the largest height: rounding in the pyramid's hi+lo
     * pairs and the bilinear filter must never make the bound too tight. */
    set_f1(gl, prog, "u_vmax", (float)(L->vmax + 1e-5));
    gl->BindBufferBase(GL_UNIFORM_BUFFER, B_SCALES, g->ubo[UBO_SCALES]);
    gl->BindBufferBase(GL_UNIFORM_BUFFER, B_SWATH, g->ubo[UBO_ENV]);
    draw(gl, r->venv_fbo, L->vw, L->vh);
    gl->UseProgram(0);
    return hfs_gl_check(gl, "backend gles: env pass", err);
}

/* Draws the bound program over the visibility grid into `outs` consecutive
 * layers of the array texture `tex` from `layer0` (through `fbo`); with
 * fetch_sum, adds the fetch counts the HFS_COUNT twin wrote to target 0. */
static int draw_grid_layers(hfs_gles *g, const hfs_gles_layout *L, GLuint fbo, GLuint tex,
                            int layer0, int outs, const char *what, double *fetch_sum,
                            hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    gl->BindFramebuffer(GL_FRAMEBUFFER, fbo);
    GLenum bufs[4];
    for (int o = 0; o < 4; ++o) {
        gl->FramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + (GLenum)o,
                                    o < outs ? tex : 0, 0, o < outs ? layer0 + o : 0);
        bufs[o] = GL_COLOR_ATTACHMENT0 + (GLenum)o;
    }
    gl->DrawBuffers(outs, bufs);
    GLenum status = gl->CheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "backend gles: %s framebuffer incomplete (0x%x)",
                        what, (unsigned)status);
    draw(gl, fbo, L->vw, L->vh);
    if (fetch_sum) {
        float *px = scratch(g, (size_t)L->vw * L->vh * 4 * sizeof(float));
        if (!px)
            return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory");
        int rc = hfs_gl_read_rgba(gl, fbo, 0, 0, L->vw, L->vh, HFS_GL_READ_AUTO, px, NULL, err);
        if (rc)
            return rc;
        for (size_t i = 0; i < (size_t)L->vw * L->vh; ++i)
            *fetch_sum += px[4 * i] + 1024.0 * px[4 * i + 1];
    }
    return HFS_OK;
}

/* Program `frag` of a grid pass with `outs` targets (HFS_NOUT), the level
 * defines, up to three more (`extra`, NULL-terminated) and the precision/count
 * variants, made current with the pyramid, normals, grid size and per-scale
 * constants bound. */
static int grid_program(hfs_gles *g, const hfs_gles_layout *L, const char *frag,
                        const char *const *extra, int outs, int count, GLuint *prog,
                        hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    char nlev[32], nlay[32], nout[32];
    level_defines(L, nlev, nlay, sizeof nlev);
    snprintf(nout, sizeof nout, "HFS_NOUT %d", outs);
    const char *defs[9] = {nlev, nlay, nout, NULL, NULL, NULL, NULL, NULL, NULL};
    int nd = 3;
    for (int i = 0; i < 3 && extra[i]; ++i)
        defs[nd++] = extra[i];
    if (g->caps.fp32)
        defs[nd++] = "HFS_FP32 1";
    if (count)
        defs[nd++] = "HFS_COUNT 1";
    int rc = program_get(g, frag, defs, prog, err);
    if (rc)
        return rc;
    gl->UseProgram(*prog);
    bind_tex(gl, U_LEVELS, GL_TEXTURE_2D_ARRAY, g->r.arr);
    bind_tex(gl, U_NORMALS, GL_TEXTURE_2D, g->r.normals);
    set_i2(gl, *prog, "u_size", L->w, L->h);
    set_i1(gl, *prog, "u_sub", L->sub);
    gl->BindBufferBase(GL_UNIFORM_BUFFER, B_SCALES, g->ubo[UBO_SCALES]);
    return HFS_OK;
}

/* Key-light passes (or their counting twins) into the horizon excess array:
 * the keys q with which[q] set (which = NULL: all). */
static int run_keys(hfs_gles *g, const hfs_gles_layout *L, const frame_key *keys, int n_keys,
                    const int *which, int count, double *fetch_sum, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    resources *r = &g->r;
    char ndir[32];
    int rc;
    for (int q = 0; q < n_keys; ++q) {
        if (which && !which[q])
            continue;
        const int n = keys[q].k.swath.n;
        snprintf(ndir, sizeof ndir, "HFS_NDIR %d", n);
        for (int d0 = 0; d0 < n; d0 += DIRS_PER_KEY_PASS) {
            const int cnt = n - d0 < DIRS_PER_KEY_PASS ? n - d0 : DIRS_PER_KEY_PASS;
            const int outs = (cnt + 1) / 2;
            GLuint prog;
            const char *extra[2] = {ndir, NULL};
            if ((rc = grid_program(g, L, "gles_key.frag", extra, outs, count, &prog, err)))
                return rc;
            set_i1(gl, prog, "u_dir0", d0);
            set_i1(gl, prog, "u_ndir", cnt);
            gl->BindBufferRange(GL_UNIFORM_BUFFER, B_SWATH, g->ubo[UBO_KEYSWATH],
                                (GLintptr)keys[q].swath_off, (GLsizeiptr)keys[q].swath_size);
            if ((rc = draw_grid_layers(g, L, r->keyhz_fbo, r->keyhz, keys[q].k.hz_layer + d0 / 2,
                                       outs, "key", count ? fetch_sum : NULL, err)))
                return rc;
            if ((rc = hfs_gl_check(gl, "backend gles: key pass", err)))
                return rc;
        }
    }
    gl->UseProgram(0);
    return HFS_OK;
}

/* Local-light passes (or their counting twins) into the ratio array, light
 * i in layer i / 2 (channels RG for even i, BA for odd).  which[i] set: the
 * light's ratios are computed (which = NULL: all lights).  Layers whose
 * lights are all wanted (or absent) are drawn 4 at a time (8 lights per
 * draw); a layer with one wanted and one kept light is drawn alone with a
 * colour mask that protects the kept light's channels (ES 3.0 has no
 * per-target mask) and computes only the wanted one (u_lmask).  HfsLocal
 * must be uploaded. */
static int run_local(hfs_gles *g, const hfs_gles_layout *L, const hfs_quality *q, int n_local,
                     const int *which, int count, double *fetch_sum, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    resources *r = &g->r;
    const int tables = q->visibility == HFS_VIS_WEDGE_TABLE;
    char ldirs[40], tabn[32];
    snprintf(ldirs, sizeof ldirs, "HFS_LOCAL_DIRS %d", q->nphi_local);
    snprintf(tabn, sizeof tabn, "HFS_TABLE_N %d", TABLE_N);
    const char *extra[4] = {ldirs, tables ? "HFS_TABLES 1" : NULL, tabn, NULL};
    const int n_layers = (n_local + 1) / 2;
    int rc = HFS_OK;
    for (int k = 0; k < n_layers;) {
        /* Wanted lights of layer k: bit 0 = light 2k, bit 1 = light 2k + 1. */
        int want = 0;
        for (int b = 0; b < 2 && 2 * k + b < n_local; ++b)
            want |= (!which || which[2 * k + b]) << b;
        const int both = 2 * k + 1 < n_local ? 3 : 1;
        if (!want) {
            ++k;
            continue;
        }
        int layers = 1, mask = want;
        if (want == both) { /* extend over the following whole layers */
            while (layers < 4 && k + layers < n_layers) {
                int w2 = 0;
                for (int b = 0; b < 2 && 2 * (k + layers) + b < n_local; ++b)
                    w2 |= (!which || which[2 * (k + layers) + b]) << b;
                if (w2 != (2 * (k + layers) + 1 < n_local ? 3 : 1))
                    break;
                mask |= w2 << (2 * layers);
                ++layers;
            }
        }
        const int l0 = 2 * k, cnt = 2 * (k + layers) < n_local ? 2 * layers : n_local - l0;
        GLuint prog;
        if ((rc = grid_program(g, L, "gles_local.frag", extra, layers, count, &prog, err)))
            break;
        set_i1(gl, prog, "u_light0", l0);
        set_i1(gl, prog, "u_nl", cnt);
        set_i1(gl, prog, "u_lmask", mask);
        if (tables)
            bind_tex(gl, U_TAB, GL_TEXTURE_2D_ARRAY, g->loc_tab);
        gl->BindBufferBase(GL_UNIFORM_BUFFER, B_LOCAL, g->ubo[UBO_LOCAL]);
        const int partial = layers == 1 && want != both && !count;
        if (partial)
            gl->ColorMask(want & 1, want & 1, (want >> 1) & 1, (want >> 1) & 1);
        rc = draw_grid_layers(g, L, r->localv_fbo, r->localv, k, layers, "local-light",
                              count ? fetch_sum : NULL, err);
        if (partial)
            gl->ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        if (rc || (rc = hfs_gl_check(gl, "backend gles: local-light pass", err)))
            break;
        k += layers;
    }
    gl->UseProgram(0);
    return rc;
}

/* ---- frame ------------------------------------------------------------------------------------ */

typedef struct frame {
    int has_env, n_keys;
    frame_key keys[MAX_KEYS];
    double l_env[3][HFS_SH_N];
    double rho_pi;
    int key_layers;
    int n_local;                          /* contributing local lights (issue 4) */
    hfs_local_light local[HFS_MAX_LOCAL_LIGHTS];
    int local_open[HFS_MAX_LOCAL_LIGHTS]; /* beyond the shadow range: ratio 1 */
} frame;

static void frame_free(frame *fr)
{
    for (int q = 0; q < fr->n_keys; ++q)
        hfs_visibility_destroy(fr->keys[q].vis);
    fr->n_keys = 0;
}

static size_t align_up(size_t v, size_t a)
{
    return (v + a - 1) / a * a;
}

/* HfsLocal (gles_local.frag; gles_shade.frag reads a prefix): elevation
 * moments E (16 vec4), (1, base, hscale, zscale/dx), (nphi_local, forced full
 * swath, 0, 0), two vec4 per light ((centre, radius), (Le, 0)), the full
 * swath's directions (the robust floats of hfs_gles_swath_float_dirs), one
 * vec4 each, then per wedge of the full swath its z-rotation for the wedge
 * tables, (cos m a), (sin m a) for m = 1..3 (as hfs_gles_pack_swath). */
static int local_upload(hfs_gles *g, const hfs_gles_layout *L, const hfs_quality *q,
                        const frame *fr, hfs_error *err)
{
    const int nphi = q->nphi_local;
    const size_t n4 = sizeof(hfs_gles_local_block) / 16 + 3 * (size_t)nphi;
    int rc;
    if ((rc = hfs_gl_caps_check_uniform_block(&g->caps, n4 * 16,
                                              "local lights (--nphi-local)", err)))
        return rc;
    float *u = scratch(g, n4 * 16 + (size_t)nphi * 2 * sizeof(float));
    if (!u)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory");
    memset(u, 0, n4 * 16);
    hfs_gles_local_block *lb = (hfs_gles_local_block *)u;
    double E[HFS_SH_N * HFS_NLP_N];
    _Static_assert(HFS_SH_N * HFS_NLP_N == 16 * 4, "u_lE[16]");
    hfs_wedge_elevation_moments(E);
    for (int i = 0; i < HFS_SH_N * HFS_NLP_N; ++i)
        lb->moments[i / 4][i % 4] = (float)E[i];
    /* Lengths in texel units (dx = 1): the shaders' float arithmetic is then
     * the same for a scene scaled as a whole (dx, zscale and the lights
     * together), so knife-edge decisions (a scale exactly at a light's
     * entry distance) fall the same way at every scale. */
    const double inv_dx = 1.0 / L->dx;
    lb->geom[0] = 1.0f;
    lb->geom[1] = (float)L->base;
    lb->geom[2] = (float)L->hscale;
    lb->geom[3] = (float)(L->zscale * inv_dx);
    lb->swath[0] = (float)nphi;
    lb->swath[1] = q->local_full_swath ? 1.0f : 0.0f;
    for (int i = 0; i < fr->n_local; ++i) {
        for (int c = 0; c < 3; ++c)
            lb->lights[i][0][c] = (float)(fr->local[i].pos[c] * inv_dx);
        lb->lights[i][0][3] = (float)(fr->local[i].radius * inv_dx);
        /* Le is the shading block's (u_lle, scaled); here only whether
         * the terrain can shadow the light at all (ratio 1, none stored). */
        lb->lights[i][1][3] = fr->local_open[i] ? 1.0f : 0.0f;
    }
    hfs_swath sw;
    hfs_swath_full(nphi, &sw);
    float *cs = u + n4 * 4;
    hfs_gles_swath_float_dirs(L, &sw, cs);
    float *dirs = u + sizeof(hfs_gles_local_block) / sizeof(float); /* u_ldir */
    for (int k = 0; k < nphi; ++k) {
        dirs[4 * k] = cs[2 * k];
        dirs[4 * k + 1] = cs[2 * k + 1];
    }
    float *rot = dirs + 4 * (size_t)nphi;
    for (int w = 0; w < hfs_swath_wedge_count(&sw) && w < nphi; ++w) {
        hfs_swath_wedge wd;
        hfs_swath_get_wedge(&sw, w, &wd); /* interior wedges: no mirror */
        for (int m = 1; m <= 3; ++m) {
            rot[8 * w + m - 1] = (float)cos(m * wd.start);
            rot[8 * w + 4 + m - 1] = (float)sin(m * wd.start);
        }
    }
    ubo_upload(&g->gl, g->ubo[UBO_LOCAL], u, n4 * 16);
    g->stats.offset_mismatches += hfs_gles_offset_mismatches(L, &sw);
    return HFS_OK;
}

/* What this frame's passes are computed from, for the planner. */
static void frame_signature(const frame *fr, const hfs_quality *q, const hfs_gles_layout *L,
                            hfs_gles_frame_sig *s)
{
    memset(s, 0, sizeof *s);
    s->sub = L->sub, s->vw = L->vw, s->vh = L->vh;
    s->has_env = fr->has_env;
    s->nphi_env = q->nphi_env;
    s->vis_path = (int)q->visibility;
    if (fr->has_env)
        memcpy(s->l_env, fr->l_env, sizeof s->l_env);
    s->rho_pi = fr->rho_pi;
    s->n_keys = fr->n_keys;
    for (int i = 0; i < fr->n_keys && i < HFS_GLES_PLAN_KEYS; ++i) {
        const hfs_gles_key *k = &fr->keys[i].k;
        s->key[i].swath = k->swath;
        s->key[i].hz_layer = k->hz_layer;
        memcpy(s->key[i].dir, k->dir, sizeof k->dir);
        s->key[i].alpha = k->alpha;
        memcpy(s->key[i].le, k->le, sizeof k->le);
    }
    s->n_local = fr->n_local;
    s->nphi_local = q->nphi_local;
    s->local_full = q->local_full_swath;
    for (int i = 0; i < fr->n_local; ++i) {
        memcpy(s->local[i].pos, fr->local[i].pos, sizeof fr->local[i].pos);
        s->local[i].radius = fr->local[i].radius;
        memcpy(s->local[i].le, fr->local[i].radiance, sizeof fr->local[i].radiance);
        s->local[i].open = fr->local_open[i];
    }
}

/* The environment's transfer vectors T = H * V_env at full resolution
 * (gles_transfer.frag): kept while only the environment's radiance or
 * rotation changes. */
static int run_transfer(hfs_gles *g, const hfs_gles_layout *L, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    resources *r = &g->r;
    const char *defs[2] = {g->caps.fp32 ? "HFS_FP32 1" : NULL, NULL};
    GLuint prog;
    int rc = program_get(g, "gles_transfer.frag", defs, &prog, err);
    if (rc)
        return rc;
    gl->UseProgram(prog);
    bind_tex(gl, U_NORMALS, GL_TEXTURE_2D, r->normals);
    for (int i = 0; i < 4; ++i)
        bind_tex(gl, U_V0 + i, GL_TEXTURE_2D, r->venv[i]);
    set_i2(gl, prog, "u_size", L->w, L->h);
    set_i2(gl, prog, "u_vsize", L->vw, L->vh);
    set_i1(gl, prog, "u_sub", L->sub);
    draw(gl, r->transfer_fbo, L->w, L->h);
    gl->UseProgram(0);
    g->pass_fetch[P_TRANSFER] = (double)L->w * L->h * 5;
    return hfs_gl_check(gl, "backend gles: transfer pass", err);
}

/* A key light's irradiance at normal incidence, pi sin^2 alpha: the
 * largest value of its factor E_cap * ratio, by which the factor pass
 * divides and the shading multiplies (never 0 in float). */
static double key_emax(const hfs_gles_key *k)
{
    return fmax(hfs_cap_irradiance(1.0, k->alpha), (double)FLT_MIN);
}

/* Each key light q with which[q] set: its factor E_cap * ratio / E_max at
 * full resolution into layer q of the factor array (gles_keyfactor.frag).
 * HfsKeys (rec vec4) must be uploaded. */
static int run_kfactor(hfs_gles *g, const hfs_gles_layout *L, const frame_key *keys,
                       int n_keys, int rec, int tables, const int *which, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    resources *r = &g->r;
    char kvec[32], tabn[32];
    snprintf(kvec, sizeof kvec, "HFS_KEY_VEC4 %d", rec > 0 ? rec : 1);
    snprintf(tabn, sizeof tabn, "HFS_TABLE_N %d", TABLE_N);
    const char *defs[5] = {kvec, NULL, NULL, NULL, NULL};
    int nd = 1;
    if (tables) {
        defs[nd++] = "HFS_TABLES 1";
        defs[nd++] = tabn;
    }
    if (g->caps.fp32)
        defs[nd++] = "HFS_FP32 1";
    GLuint prog;
    int rc = program_get(g, "gles_keyfactor.frag", defs, &prog, err);
    if (rc)
        return rc;
    gl->UseProgram(prog);
    bind_tex(gl, U_NORMALS, GL_TEXTURE_2D, r->normals);
    bind_tex(gl, U_KEYHZ, GL_TEXTURE_2D_ARRAY, r->keyhz);
    if (tables) {
        bind_tex(gl, U_KTAB, GL_TEXTURE_2D_ARRAY, g->ktab);
        bind_tex(gl, U_KTABB, GL_TEXTURE_2D_ARRAY, g->ktabb);
    }
    set_i2(gl, prog, "u_size", L->w, L->h);
    set_i2(gl, prog, "u_vsize", L->vw, L->vh);
    set_i1(gl, prog, "u_sub", L->sub);
    gl->BindBufferBase(GL_UNIFORM_BUFFER, B_KEYS, g->ubo[UBO_KEYS]);
    for (int q = 0; q < n_keys; ++q) {
        if (!which[q])
            continue;
        set_i1(gl, prog, "u_kb", keys[q].rec_off);
        set_f1(gl, prog, "u_emax", (float)key_emax(&keys[q].k));
        gl->BindFramebuffer(GL_FRAMEBUFFER, r->kf_fbo);
        gl->FramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, r->kf, 0, q);
        const GLenum buf = GL_COLOR_ATTACHMENT0;
        gl->DrawBuffers(1, &buf);
        GLenum status = gl->CheckFramebufferStatus(GL_FRAMEBUFFER);
        if (status != GL_FRAMEBUFFER_COMPLETE)
            return hfs_fail(err, HFS_E_UNSUPPORTED,
                            "backend gles: key factor framebuffer incomplete (0x%x)",
                            (unsigned)status);
        draw(gl, r->kf_fbo, L->w, L->h);
        g->pass_fetch[P_KFACTOR] += (double)L->w * L->h * (1 + (keys[q].k.swath.n + 1) / 2);
        if ((rc = hfs_gl_check(gl, "backend gles: key factor pass", err)))
            return rc;
    }
    gl->UseProgram(0);
    return HFS_OK;
}

static int render_frame(hfs_gles *g, const hfs_field *f, const hfs_quality *q, hfs_image *out, frame *fr, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    int rc;
    const int fp32 = q->precision == HFS_PRECISION_FP32;
    if ((rc = hfs_gl_caps_select(&g->driver, g->profile[0] ? g->profile : NULL, fp32,
                                 g->strict_limits, &g->caps, err)))
        return rc;
    const hfs_gl_caps *caps = &g->caps;
    hfs_gles_layout L;
    if ((rc = hfs_gles_layout_init(&L, f, q, err)))
        return rc;
    const int tables = q->visibility == HFS_VIS_WEDGE_TABLE;

    /* Limits, all through the caps layer. */
    if ((rc = hfs_gl_caps_check_texture(caps, L.w, L.h, L.n_layers, "height levels (the field's size)", err)) ||
        (rc = hfs_gl_caps_check_texture(caps, TABLE_N, TABLE_N, 4 * (MAX_KEYS + 1),
                                        "wedge tables", err)) ||
        (rc = hfs_gl_caps_check_draw_buffers(caps, 4, "SH visibility (16 coefficients)", err)) ||
        (rc = hfs_gl_caps_check_samplers(caps, 10, "shading pass", err)) ||
        (rc = hfs_gl_caps_check_uniform_block(caps, hfs_gles_scales_vec4(&L) * 16,
                                              "per-scale constants", err)))
        return rc;
    if (fr->has_env &&
        (rc = hfs_gl_caps_check_uniform_block(caps, hfs_gles_swath_vec4(q->nphi_env) * 16,
                                              "environment swath (--nphi-env)", err)))
        return rc;

    /* Key lights: swaths, visibility objects, records. */
    size_t keyswath_bytes = 0;
    int rec = 0;
    const size_t align = (size_t)caps->uniform_buffer_offset_alignment;
    /* Each key slot owns a run of g->key_stride horizon layers, the most any
     * key swath of this renderer has needed (a high-water mark, from room
     * for a partial swath's nphi_key + 1 samples): a light whose swath
     * grows or shrinks within it does not move the other lights' horizons,
     * and the texture is not reallocated.  When the mark rises (a light
     * covering the zenith takes the full swath) every slot moves: the
     * planner sees new layers (hz_layer is in the signature). */
    if (g->key_stride < (q->nphi_key + 2) / 2)
        g->key_stride = (q->nphi_key + 2) / 2;
    for (int i = 0; i < fr->n_keys; ++i)
        if (g->key_stride < (fr->keys[i].k.swath.n + 1) / 2)
            g->key_stride = (fr->keys[i].k.swath.n + 1) / 2;
    for (int i = 0; i < fr->n_keys; ++i) {
        frame_key *k = &fr->keys[i];
        k->k.hz_layer = i * g->key_stride;
        fr->key_layers = (i + 1) * g->key_stride;
        if ((rc = hfs_visibility_create(&k->k.swath, HFS_VIS_LEGENDRE, &k->vis, err)))
            return rc;
        k->swath_off = keyswath_bytes;
        k->swath_size = hfs_gles_swath_vec4(k->k.swath.n) * 16;
        keyswath_bytes = align_up(keyswath_bytes + k->swath_size, align);
        k->rec_off = rec;
        rec += (int)hfs_gles_key_vec4(k->k.swath.n);
        if ((rc = hfs_gl_caps_check_uniform_block(caps, k->swath_size,
                                                   "key-light swath (lower --nphi-key)", err)))
            return rc;
    }
    /* The records' declared size (HFS_KEY_VEC4) goes in size classes, so
     * that a swath gaining or losing a sample as its light moves does not
     * recompile the factor pass (a 100-400 ms hitch on llvmpipe): the next
     * power of two from 64 vec4, or the exact size where that would not
     * fit the block limit.  The buffer is uploaded at that size. */
    int rec_block = 64;
    while (rec_block < rec)
        rec_block *= 2;
    if ((size_t)rec_block * 16 > (size_t)caps->max_uniform_block_size)
        rec_block = rec > 0 ? rec : 1;
    if ((rc = hfs_gl_caps_check_uniform_block(caps, (size_t)rec_block * 16,
                                              "key-light records (fewer keys or --nphi-key)", err)) ||
        (rc = hfs_gl_caps_check_texture(caps, L.vw, L.vh, fr->key_layers,
                                        "key-light horizons", err)))
        return rc;
    const int local_layers = (fr->n_local + 1) / 2;
    if ((rc = hfs_gl_caps_check_texture(caps, L.vw, L.vh, local_layers > 0 ? local_layers : 1,
                                        "local-light visibility", err)))
        return rc;

    /* Textures follow the frame's sizes; what a reallocated texture held is
     * lost, and the planner is told so before it plans. */
    const resources *rs = &g->r;
    const unsigned gens[4] = {rs->grid_gen, rs->keyhz_gen, rs->localv_gen, rs->kf_gen};
    if ((rc = resources_ensure(g, &L, fr->key_layers, local_layers, fr->n_keys, err)))
        return rc;
    hfs_gles_plan_lost(&g->plan, rs->grid_gen != gens[0], rs->keyhz_gen != gens[1],
                       rs->localv_gen != gens[2], rs->kf_gen != gens[3]);

    /* Plan: which passes this frame needs (gles_plan.h). */
    const size_t n_img = (size_t)L.w * L.h * 3;
    const char *terrain_why = terrain_change(g, f, q);
    if (terrain_why) {
        g->terrain_valid = 0;
        g->extent_valid = 0;
    }
    /* Local lights the terrain cannot shadow need no ratios (lights.h). */
    if (fr->n_local > 0 && !g->extent_valid) {
        hfs_field_extent_make(f, &g->extent);
        g->extent_valid = 1;
    }
    for (int i = 0; i < fr->n_local; ++i)
        fr->local_open[i] = hfs_local_light_open(&g->extent, &fr->local[i]);
    hfs_gles_frame_sig sig;
    frame_signature(fr, q, &L, &sig);
    if (hfs_gles_plan_frame(&g->plan, &sig, terrain_why) == 0 && g->last_img &&
        g->last_img_cap >= n_img) {
        /* Nothing changed: no pass; the last image again. */
        memcpy(out->rgb, g->last_img, n_img * sizeof *out->rgb);
        for (int p = 0; p < P_COUNT; ++p)
            g->pass_cached[p] = 1;
        return HFS_OK;
    }
    int *run = g->plan.run;
    /* The readback needs this frame's output scale, and a shaded frame is
     * read back: the two go together (as does a frame without a kept
     * image, e.g. the first after a failure). */
    if (run[GP_SHADE] || run[GP_READBACK] || !(g->last_img && g->last_img_cap >= n_img))
        run[GP_SHADE] = run[GP_READBACK] = 1;

    /* Terrain: upload, normals, pyramid. */
    if (run[GP_TERRAIN]) {
        g->terrain_valid = 0;
        float *sc = scratch(g, hfs_gles_scales_vec4(&L) * 16);
        if (!sc)
            return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory");
        hfs_gles_pack_scales(&L, sc);
        ubo_upload(gl, g->ubo[UBO_SCALES], sc, hfs_gles_scales_vec4(&L) * 16);
        if ((rc = run_terrain(g, f, &L, err)))
            return rc;
        g->terrain_valid = terrain_remember(g, f, q);
        g->stats.terrain_recomputed = 1;
        hfs_gles_plan_done(&g->plan, GP_TERRAIN);
    } else {
        for (int p = P_UPLOAD; p <= P_RECON; ++p)
            g->pass_cached[p] = 1;
    }

    /* Table textures follow the precision. */
    if ((g->env_tab || g->ktab || g->loc_tab) && g->tab_fp32 != caps->fp32) {
        del_tex(gl, &g->env_tab);
        del_tex(gl, &g->ktab);
        del_tex(gl, &g->ktabb);
        del_tex(gl, &g->loc_tab);
        g->ktab_sets = 0;
        g->table_bytes = 0;
    }
    g->tab_fp32 = caps->fp32;

    /* Environment (cached with the terrain). */
    long mismatches = 0;
    if (fr->has_env) {
        if (!g->env_vis || g->env_vis_n != q->nphi_env) {
            hfs_visibility_destroy(g->env_vis);
            g->env_vis = NULL;
            hfs_swath s;
            hfs_swath_full(q->nphi_env, &s);
            if ((rc = hfs_visibility_create(&s, HFS_VIS_LEGENDRE, &g->env_vis, err)))
                return rc;
            g->env_vis_n = q->nphi_env;
        }
        mismatches += hfs_gles_offset_mismatches(&L, hfs_visibility_swath(g->env_vis));
        if (run[GP_ENV]) {
            const size_t bytes = hfs_gles_swath_vec4(q->nphi_env) * 16;
            float *sw = scratch(g, bytes);
            if (!sw)
                return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory");
            hfs_gles_pack_swath(&L, g->env_vis, sw);
            ubo_upload(gl, g->ubo[UBO_ENV], sw, bytes);
            if (tables) {
                const double dphi = hfs_visibility_swath(g->env_vis)->dphi;
                if (!g->env_tab || g->env_tab_dphi != dphi) {
                    hfs_wedge_tables *t = tables_get(g, dphi, err);
                    if (!t)
                        return HFS_E_NOMEM;
                    if (!g->env_tab) {
                        g->env_tab = tex_new(gl, GL_TEXTURE_2D_ARRAY, caps->fmt_rgba, TABLE_N,
                                             TABLE_N, 4, 1);
                        g->table_bytes += (size_t)TABLE_N * TABLE_N * 4 * caps->bytes_rgba;
                    }
                    if ((rc = tables_upload(g, t, g->env_tab, 0, 0, err)))
                        return rc;
                    g->env_tab_dphi = dphi;
                }
            }
            pass_begin(g, P_ENV);
            if ((rc = run_env(g, &L, tables, 0, err)))
                return rc;
            pass_end(g, P_ENV);
            g->stats.env_recomputed = 1;
            hfs_gles_plan_done(&g->plan, GP_ENV);
        } else {
            g->pass_cached[P_ENV] = 1;
        }
    }

    /* Key lights: uniform data, tables, horizon passes. */
    float *keys_rec = NULL;
    if (fr->n_keys > 0) {
        float *ks = scratch(g, keyswath_bytes + (size_t)rec_block * 16);
        if (!ks)
            return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory");
        memset(ks, 0, keyswath_bytes + (size_t)rec_block * 16);
        keys_rec = ks + keyswath_bytes / sizeof(float);
        int n_sets = 0;
        double set_dphi[MAX_KEYS];
        for (int i = 0; i < fr->n_keys; ++i) {
            frame_key *k = &fr->keys[i];
            mismatches += hfs_gles_offset_mismatches(&L, &k->k.swath);
            hfs_gles_pack_swath(&L, k->vis, ks + k->swath_off / sizeof(float));
            k->k.table_set = 0;
            if (tables) {
                int s = 0;
                while (s < n_sets && set_dphi[s] != k->k.swath.dphi)
                    ++s;
                if (s == n_sets)
                    set_dphi[n_sets++] = k->k.swath.dphi;
                k->k.table_set = s;
            }
            hfs_gles_pack_key(&L, &k->k, k->vis, keys_rec + (size_t)k->rec_off * 4);
        }
        ubo_upload(gl, g->ubo[UBO_KEYSWATH], ks, keyswath_bytes);
        ubo_upload(gl, g->ubo[UBO_KEYS], keys_rec, (size_t)rec_block * 16);
        if (tables) {
            int same = g->ktab && g->ktab_sets >= n_sets;
            for (int s = 0; s < n_sets && same; ++s)
                same = g->ktab_dphi[s] == set_dphi[s];
            if (!same) {
                if (g->ktab_sets < n_sets) {
                    if (g->ktab)
                        g->table_bytes -= (size_t)TABLE_N * (TABLE_N + 1) * 4 * g->ktab_sets *
                                          caps->bytes_rgba;
                    del_tex(gl, &g->ktab);
                    del_tex(gl, &g->ktabb);
                    g->ktab = tex_new(gl, GL_TEXTURE_2D_ARRAY, caps->fmt_rgba, TABLE_N, TABLE_N,
                                      4 * n_sets, 1);
                    g->ktabb = tex_new(gl, GL_TEXTURE_2D_ARRAY, caps->fmt_rgba, TABLE_N, 1,
                                       4 * n_sets, 1);
                    g->ktab_sets = n_sets;
                    g->table_bytes += (size_t)TABLE_N * (TABLE_N + 1) * 4 * n_sets *
                                      caps->bytes_rgba;
                }
                for (int s = 0; s < n_sets; ++s) {
                    hfs_wedge_tables *t = tables_get(g, set_dphi[s], err);
                    if (!t)
                        return HFS_E_NOMEM;
                    if ((rc = tables_upload(g, t, g->ktab, g->ktabb, s, err)))
                        return rc;
                    g->ktab_dphi[s] = set_dphi[s];
                }
            }
        }
        int any = 0;
        for (int i = 0; i < fr->n_keys; ++i)
            any |= run[GP_KEY0 + i];
        if (any) {
            pass_begin(g, P_KEY);
            if ((rc = run_keys(g, &L, fr->keys, fr->n_keys, run + GP_KEY0, 0, NULL, err)))
                return rc;
            pass_end(g, P_KEY);
            for (int i = 0; i < fr->n_keys; ++i)
                if (run[GP_KEY0 + i])
                    hfs_gles_plan_done(&g->plan, GP_KEY0 + i);
        } else {
            g->pass_cached[P_KEY] = 1;
        }
    }
    g->stats.offset_mismatches = mismatches;

    /* Local lights: visibility ratios on the grid. */
    int any_local = 0;
    for (int i = 0; i < fr->n_local; ++i)
        any_local |= run[GP_LOCAL0 + i];
    if (fr->n_local > 0 && (any_local || run[GP_SHADE]) &&
        (rc = local_upload(g, &L, q, fr, err)))
        return rc;
    if (fr->n_local > 0 && !any_local)
        g->pass_cached[P_LOCAL] = 1;
    if (fr->n_local > 0 && any_local) {
        const double dphi = 2.0 * PI / q->nphi_local;
        if (tables && (!g->loc_tab || g->loc_tab_dphi != dphi)) {
            hfs_wedge_tables *t = tables_get(g, dphi, err);
            if (!t)
                return HFS_E_NOMEM;
            if (!g->loc_tab) {
                g->loc_tab = tex_new(gl, GL_TEXTURE_2D_ARRAY, caps->fmt_rgba, TABLE_N, TABLE_N,
                                     4, 1);
                g->table_bytes += (size_t)TABLE_N * TABLE_N * 4 * caps->bytes_rgba;
            }
            if ((rc = tables_upload(g, t, g->loc_tab, 0, 0, err)))
                return rc;
            g->loc_tab_dphi = dphi;
        }
        pass_begin(g, P_LOCAL);
        if ((rc = run_local(g, &L, q, fr->n_local, run + GP_LOCAL0, 0, NULL, err)))
            return rc;
        pass_end(g, P_LOCAL);
        for (int i = 0; i < fr->n_local; ++i)
            if (run[GP_LOCAL0 + i])
                hfs_gles_plan_done(&g->plan, GP_LOCAL0 + i);
    }
    /* Full-resolution products of the visibility: the environment's
     * transfer vectors and each key light's factor. */
    if (fr->has_env && run[GP_TRANSFER]) {
        pass_begin(g, P_TRANSFER);
        if ((rc = run_transfer(g, &L, err)))
            return rc;
        pass_end(g, P_TRANSFER);
        hfs_gles_plan_done(&g->plan, GP_TRANSFER);
    } else if (fr->has_env) {
        g->pass_cached[P_TRANSFER] = 1;
    }
    if (fr->n_keys > 0) {
        int any = 0;
        for (int i = 0; i < fr->n_keys; ++i)
            any |= run[GP_KFACTOR0 + i];
        if (any) {
            pass_begin(g, P_KFACTOR);
            if ((rc = run_kfactor(g, &L, fr->keys, fr->n_keys, rec_block, tables, run + GP_KFACTOR0,
                                  err)))
                return rc;
            pass_end(g, P_KFACTOR);
            for (int i = 0; i < fr->n_keys; ++i)
                if (run[GP_KFACTOR0 + i])
                    hfs_gles_plan_done(&g->plan, GP_KFACTOR0 + i);
        } else {
            g->pass_cached[P_KFACTOR] = 1;
        }
    }
    if (!run[GP_SHADE] && !run[GP_READBACK]) {
        memcpy(out->rgb, g->last_img, n_img * sizeof *out->rgb);
        g->pass_cached[P_SHADE] = g->pass_cached[P_READBACK] = 1;
        return HFS_OK;
    }

    /* Shading. */
    double bound = 0.0;
    hfs_gles_shade_block sb;
    memset(&sb, 0, sizeof sb);
    if (fr->has_env) {
        double m = 0.0;
        for (int c = 0; c < 3; ++c) {
            double s = 0.0;
            for (int k = 0; k < HFS_SH_N; ++k)
                s += fabs(fr->l_env[c][k]);
            m = s > m ? s : m;
        }
        bound += 4.0 * m;
    }
    bound *= PI;
    /* Lights by the irradiance they can actually give (not pi): a bound
     * loose by Le * pi / E_max pushes the frame's values into fp16's
     * subnormals, where hi + lo keep only ~3e-8 of the scale (a 1e-5 rad sun
     * of radiance 3e9 lost 0.7% that way). */
    for (int i = 0; i < fr->n_keys; ++i) /* pi sin^2 alpha, at normal incidence */
        bound += fmax(fr->keys[i].k.le[0], fmax(fr->keys[i].k.le[1], fr->keys[i].k.le[2])) *
                 hfs_cap_irradiance(1.0, fr->keys[i].k.alpha);
    for (int i = 0; i < fr->n_local; ++i)
        bound += fmax(fr->local[i].radiance[0],
                      fmax(fr->local[i].radiance[1], fr->local[i].radiance[2])) *
                 hfs_gles_local_max_irradiance(&L, &fr->local[i]);
    bound *= fr->rho_pi;
    /* Every radiance reaches the shader already multiplied by a power of
     * two that puts the frame's largest possible value near 16384: fp16
     * (and fp32: the shader clamps to fp16's range on either path) then
     * never saturates and never sinks into subnormals, for any finite
     * scene (a sky of radiance 1e38 read back as 8.3e34 when only the
     * output was scaled: the products overflowed first).  A power of two
     * is exact: the frame's bits are those of an unscaled computation
     * wherever that one neither overflowed nor underflowed. */
    if (!isfinite(bound))
        return hfs_fail(err, HFS_E_INVALID, "backend gles: the scene's radiance (bound %g) is "
                        "beyond what double precision carries", bound);
    const double out_scale = hfs_gles_output_scale(bound);
    for (int c = 0; c < 3 && fr->has_env; ++c)
        for (int k = 0; k < HFS_SH_N; ++k)
            sb.env[c][k] = (float)(fr->l_env[c][k] * out_scale);
    sb.misc[0] = (float)fr->rho_pi;
    sb.misc[1] = 1.0f; /* the scale is in the radiances */
    sb.misc[2] = fr->has_env ? 1.0f : 0.0f;
    for (int c = 0; c < 3 && fr->has_env; ++c) /* cpu_render.c env_clamp */
        sb.env_neg[c] =
            (float)(fr->rho_pi * PI * hfs_sh_negative_bound(fr->l_env[c]) * out_scale);
    for (int i = 0; i < fr->n_keys; ++i) /* rho/pi Le E_max: the factor's scale */
        for (int c = 0; c < 3; ++c)
            sb.kle[i][c] = (float)(fr->rho_pi * fr->keys[i].k.le[c] *
                                   key_emax(&fr->keys[i].k) * out_scale);
    hfs_gles_open_transfer(sb.topen);
    for (int i = 0; i < fr->n_local; ++i)
        for (int c = 0; c < 3; ++c)
            sb.lle[i][c] = (float)(fr->local[i].radiance[c] * out_scale);
    ubo_upload(gl, g->ubo[UBO_SHADE], &sb, sizeof sb);

    char nkeys[32];
    snprintf(nkeys, sizeof nkeys, "HFS_NKEYS %d", fr->n_keys);
    const char *defs[8] = {nkeys, NULL, NULL, NULL, NULL, NULL, NULL, NULL};
    int nd = 1;
    if (fr->has_env)
        defs[nd++] = "HFS_ENV 1";
    char nlev[32], nlay[32], ldirs[40], nlocal[32];
    if (fr->n_local > 0) {
        level_defines(&L, nlev, nlay, sizeof nlev);
        snprintf(ldirs, sizeof ldirs, "HFS_LOCAL_DIRS %d", q->nphi_local);
        snprintf(nlocal, sizeof nlocal, "HFS_NLOCAL %d", fr->n_local);
        defs[nd++] = "HFS_LOCAL 1";
        defs[nd++] = nlay;
        defs[nd++] = ldirs;
        defs[nd++] = nlocal;
    }
    if (caps->fp32)
        defs[nd++] = "HFS_FP32 1";
    GLuint prog;
    if ((rc = program_get(g, "gles_shade.frag", defs, &prog, err)))
        return rc;
    resources *r = &g->r;
    pass_begin(g, P_SHADE);
    gl->UseProgram(prog);
    bind_tex(gl, U_NORMALS, GL_TEXTURE_2D, r->normals);
    for (int i = 0; i < 4; ++i)
        bind_tex(gl, U_T0 + i, GL_TEXTURE_2D, r->transfer[i]);
    bind_tex(gl, U_KF, GL_TEXTURE_2D_ARRAY, r->kf);
    if (fr->n_local > 0) {
        bind_tex(gl, U_LEVELS, GL_TEXTURE_2D_ARRAY, r->arr);
        bind_tex(gl, U_LOCALV, GL_TEXTURE_2D_ARRAY, r->localv);
        gl->BindBufferBase(GL_UNIFORM_BUFFER, B_LOCAL, g->ubo[UBO_LOCAL]);
    }
    set_i2(gl, prog, "u_size", L.w, L.h);
    set_i2(gl, prog, "u_vsize", L.vw, L.vh);
    set_i1(gl, prog, "u_sub", L.sub);
    gl->BindBufferBase(GL_UNIFORM_BUFFER, B_SHADE, g->ubo[UBO_SHADE]);
    draw(gl, r->out_fbo, L.w, L.h);
    gl->UseProgram(0);
    pass_end(g, P_SHADE);
    g->pass_fetch[P_SHADE] = (double)L.w * L.h * (1 + 4 * fr->has_env + fr->n_keys);
    if (fr->n_local > 0) /* the texel's height, one ratio layer per two lights */
        g->pass_fetch[P_SHADE] += (double)L.w * L.h * (1 + (fr->n_local + 1) / 2);
    if ((rc = hfs_gl_check(gl, "backend gles: shading pass", err)))
        return rc;

    /* Readback. */
    pass_begin(g, P_READBACK);
    const size_t npx = (size_t)L.w * L.h;
    float *px = scratch(g, npx * 8 * sizeof(float));
    if (!px)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for the readback");
    float *lo = px + npx * 4;
    if ((rc = hfs_gl_read_rgba(gl, r->out_fbo, 0, 0, L.w, L.h, HFS_GL_READ_AUTO, px, NULL, err)) ||
        (rc = hfs_gl_read_rgba(gl, r->out_lo_fbo, 0, 0, L.w, L.h, HFS_GL_READ_AUTO, lo, NULL,
                               err)))
        return rc;
    const double inv = 1.0 / out_scale;
    for (size_t i = 0; i < npx; ++i)
        for (int c = 0; c < 3; ++c) {
            const double v = ((double)px[4 * i + (size_t)c] + lo[4 * i + (size_t)c]) * inv;
            out->rgb[3 * i + (size_t)c] = isfinite(v) ? (float)v : 0.0f;
        }
    pass_end(g, P_READBACK);
    if (g->last_img_cap < n_img) {
        float *k = realloc(g->last_img, n_img * sizeof *k);
        if (!k)
            return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for the kept image");
        g->last_img = k;
        g->last_img_cap = n_img;
    }
    memcpy(g->last_img, out->rgb, n_img * sizeof *out->rgb);
    hfs_gles_plan_done(&g->plan, GP_SHADE);
    hfs_gles_plan_done(&g->plan, GP_READBACK);

    /* Counting twins of the horizon passes (timing level 2). */
    if (g->timing >= 2) {
        g->pass_fetch[P_ENV] = 0.0;
        g->pass_fetch[P_KEY] = 0.0;
        g->pass_fetch[P_LOCAL] = 0.0;
        if (fr->has_env) {
            if ((rc = run_env(g, &L, tables, 1, err)))
                return rc;
            /* the targets now hold counts: hfs_gles_plan_drop_grids below */
            float *cnt = scratch(g, (size_t)L.vw * L.vh * 4 * sizeof(float));
            if (!cnt)
                return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory");
            if ((rc = hfs_gl_read_rgba(gl, r->venv_fbo, 0, 0, L.vw, L.vh, HFS_GL_READ_AUTO, cnt,
                                       NULL, err)))
                return rc;
            for (size_t i = 0; i < (size_t)L.vw * L.vh; ++i)
                g->pass_fetch[P_ENV] += cnt[4 * i] + 1024.0 * cnt[4 * i + 1];
        }
        if (fr->n_keys > 0 &&
            (rc = run_keys(g, &L, fr->keys, fr->n_keys, NULL, 1, &g->pass_fetch[P_KEY], err)))
            return rc;
        if (fr->n_local > 0 &&
            (rc = run_local(g, &L, q, fr->n_local, NULL, 1, &g->pass_fetch[P_LOCAL], err)))
            return rc;
        hfs_gles_plan_drop_grids(&g->plan); /* their targets now hold counts */
    } else {
        g->pass_fetch[P_ENV] = -1.0;
        g->pass_fetch[P_KEY] = -1.0;
        g->pass_fetch[P_LOCAL] = -1.0;
    }
    return HFS_OK;
}

int hfs_gles_render(hfs_gles *g, const hfs_field *f, const hfs_lighting *l,
                    const hfs_quality *q, hfs_image *out, hfs_error *err)
{
    const double t_start = now_ms();
    int rc = hfs_gl_context_make_current(g->ctx, err);
    if (rc)
        return rc;
    memset(g->pass_ms, 0, sizeof g->pass_ms);
    memset(g->pass_fetch, 0, sizeof g->pass_fetch);
    memset(g->pass_ran, 0, sizeof g->pass_ran);
    memset(g->pass_cached, 0, sizeof g->pass_cached);
    memset(&g->last, 0, sizeof g->last);
    g->stats.terrain_recomputed = 0;
    g->stats.env_recomputed = 0;

    /* Which lights contribute (exactly as cpu_render.c). */
    frame fr;
    memset(&fr, 0, sizeof fr);
    if (l->has_env)
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < HFS_SH_COEFFS; ++k)
                fr.has_env |= l->env_sh[c][k] != 0.0;
    for (int i = 0; i < l->n_key && i < HFS_MAX_KEY_LIGHTS; ++i) {
        const hfs_key_light *k = &l->key[i];
        if (!hfs_key_light_contributes(k, l->albedo))
            continue;
        frame_key *fk = &fr.keys[fr.n_keys++];
        /* The visible fraction comes from the swath's elevation window
         * e +- alpha and its half-width, angles the shaders difference in
         * float: below ~1e-7 rad they collapse (a 1e-8 rad sun came out
         * black on an open plane).  A disk that small is a point at any
         * terrain scale: its fraction is taken from a disk of
         * HFS_MIN_VIS_ALPHA (lights.h) about the same centre; E_cap keeps
         * alpha. */
        const double a_vis = hfs_key_vis_alpha(k->alpha);
        hfs_swath_key(k->phi, k->elev, a_vis, q->nphi_key, q->nphi_env, &fk->k.swath);
        hfs_dir(k->phi, k->elev, fk->k.dir);
        fk->k.alpha = k->alpha;
        for (int c = 0; c < 3; ++c)
            fk->k.le[c] = k->radiance[c];
        double zh[HFS_ZH_N];
        hfs_zh_cap(a_vis, zh);
        hfs_sh_rotate_zonal(zh, fk->k.dir[0], fk->k.dir[1], fk->k.dir[2], fk->k.l_sh);
        fk->k.l_norm = sqrt(hfs_sh_dot(fk->k.l_sh, fk->k.l_sh));
    }
    for (int i = 0; i < l->n_local && i < HFS_MAX_LOCAL_LIGHTS; ++i)
        if (hfs_local_light_contributes(&l->local[i]))
            fr.local[fr.n_local++] = l->local[i];
    fr.rho_pi = l->albedo / PI;
    if ((!fr.has_env && fr.n_keys == 0 && fr.n_local == 0) || !(l->albedo > 0.0)) {
        /* Black without a pass; the planner keeps the last lit frame's state
         * (its image is still right for that scene). */
        memset(out->rgb, 0, (size_t)out->width * out->height * 3 * sizeof *out->rgb);
        g->plan.black = 1;
        return HFS_OK;
    }
    if (fr.has_env)
        for (int c = 0; c < 3; ++c)
            hfs_sh_rotate_z(l->env_sh[c], l->env_rotate, fr.l_env[c]);

    rc = render_frame(g, f, q, out, &fr, err);
    frame_free(&fr);
    if (rc) {
        /* A failed frame may have left partial results: recompute next time. */
        g->terrain_valid = 0;
        hfs_gles_plan_drop_all(&g->plan);
        for (int i = 0; i < 16 && g->gl.GetError() != GL_NO_ERROR; ++i)
            ;
        return rc;
    }
    collect_queries(g);
    snprintf(g->stats.profile, sizeof g->stats.profile, "%s", g->caps.profile);
    g->stats.fp32 = g->caps.fp32;

    if (g->timing) {
        hfs_timings *t = &g->last;
        for (int p = 0; p < P_COUNT; ++p) {
            if (!g->pass_ran[p] && !g->pass_cached[p])
                continue;
            hfs_pass_time *pt = &t->pass[t->n_passes++];
            snprintf(pt->name, sizeof pt->name, "%s", pass_names[p]);
            pt->ms = g->pass_ran[p] ? g->pass_ms[p] : 0.0;
            pt->fetches = g->pass_ran[p] ? g->pass_fetch[p] : 0.0;
            pt->cached = !g->pass_ran[p];
            t->gpu_ms += pt->ms > 0.0 ? pt->ms : 0.0;
        }
        t->texture_bytes = resources_bytes(g) + g->table_bytes;
        snprintf(t->method, sizeof t->method, "%s", use_queries(g) ? "timer-query" : "finish-clock");
        snprintf(t->device, sizeof t->device, "%s (%s)", hfs_gl_context_describe(g->ctx),
                 g->caps.profile);
        t->frame_ms = now_ms() - t_start;
    }
    return HFS_OK;
}
