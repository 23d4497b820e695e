/*
 * embed_mesh.c — hfshade embedded in an application's own GL scene, with
 * no read-back (issue 20; docs/DESIGN.md "Embedding without a read-back").
 *
 * The application owns an EGL context (surfaceless here, so that it runs
 * headless; a window's context works the same) and draws its own scene: a
 * terrain mesh under a perspective camera, with a sky behind it.  hfshade
 * lights the height field in a context that shares objects with the
 * application's (hfs_renderer_desc.egl_display / egl_share_context), and
 * hands the exit radiance back as an RGBA16F texture
 * (hfs_renderer_render_texture).  The application's fragment shader
 * samples it, applies its own exposure and tone map and encodes sRGB.
 * Frame after frame the sun turns: the renderer reruns only the passes the
 * change needs, and nothing leaves the GPU until the application reads its
 * own final picture (here, to write it as a PPM).
 *
 * Built against the INSTALLED package (tests/install.sh, with pkg-config
 * and find_package(hfshade)); links libEGL and libGLESv2 itself.
 *
 * Usage: embed_mesh OUT.ppm [FRAMES]   (FRAMES >= 1, default 3: the last
 * frame is written).  Exit 0; 77 when no EGL/GLES context can be made
 * here; 1 with one line on any other failure.
 */
#include <hfshade.h>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl3.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FIELD 128         /* height field W = H, texels */
#define VIEW_W 640        /* the application's picture  */
#define VIEW_H 400
#define PI 3.14159265358979323846

/* ---- the application's context ----------------------------------------- */

typedef struct app {
    EGLDisplay dpy;
    EGLContext ctx;
    GLuint fbo, color, depth;   /* the application's own framebuffer */
    GLuint prog, vao, vbo, ibo;
    GLsizei n_index;
} app;

static int egl_context(app *a)
{
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    if (!get_display)
        return 0;
    a->dpy = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    const EGLint cfg_attr[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_SURFACE_TYPE, 0,
                               EGL_NONE};
    const EGLint ctx_attr[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_NONE};
    EGLConfig cfg = NULL;
    EGLint n = 0;
    if (a->dpy == EGL_NO_DISPLAY || !eglInitialize(a->dpy, NULL, NULL) ||
        !eglBindAPI(EGL_OPENGL_ES_API) || !eglChooseConfig(a->dpy, cfg_attr, &cfg, 1, &n))
        return 0;
    a->ctx = eglCreateContext(a->dpy, n ? cfg : NULL, EGL_NO_CONTEXT, ctx_attr);
    return a->ctx != EGL_NO_CONTEXT &&
           eglMakeCurrent(a->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, a->ctx);
}

/* ---- the application's scene: a mesh and a camera ---------------------- */

static const char *const vert_src =
    "#version 300 es\n"
    "layout(location = 0) in vec3 a_pos;\n"
    "layout(location = 1) in vec2 a_uv;\n"
    "uniform mat4 u_mvp;\n"
    "out vec2 v_uv;\n"
    "void main() { v_uv = a_uv; gl_Position = u_mvp * vec4(a_pos, 1.0); }\n";

/* The lit texture is linear radiance: exposure, Reinhard, sRGB here. */
static const char *const frag_src =
    "#version 300 es\n"
    "precision highp float;\n"
    "uniform sampler2D u_lit;\n"
    "uniform float u_exposure;\n"
    "in vec2 v_uv;\n"
    "out vec4 o_color;\n"
    "void main() {\n"
    "  vec3 x = max(texture(u_lit, v_uv).rgb * u_exposure, 0.0);\n"
    "  x = x / (1.0 + x);\n"
    "  o_color = vec4(pow(x, vec3(1.0 / 2.2)), 1.0);\n"
    "}\n";

static GLuint compile(GLenum stage, const char *src)
{
    GLuint s = glCreateShader(stage);
    glShaderSource(s, 1, &src, NULL);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[512] = "";
        glGetShaderInfoLog(s, sizeof log, NULL, log);
        fprintf(stderr, "embed_mesh: shader: %s\n", log);
    }
    return s;
}

/* One vertex per height texel: world (i dx, j dx, zscale h), and the lit
 * texture's texel centre (i + 0.5) / W, (j + 0.5) / H. */
static int make_mesh(app *a, const hfs_field *f)
{
    const int w = f->width, h = f->height;
    float *v = malloc(sizeof(float) * 5 * (size_t)w * h);
    GLuint *idx = malloc(sizeof(GLuint) * 6 * (size_t)(w - 1) * (h - 1));
    if (!v || !idx) {
        free(v);
        free(idx);
        return 0;
    }
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            float *p = v + 5 * ((size_t)j * w + i);
            p[0] = (float)(i * f->dx), p[1] = (float)(j * f->dx);
            p[2] = (float)(f->zscale * f->z[(size_t)j * w + i]);
            p[3] = (i + 0.5f) / w, p[4] = (j + 0.5f) / h;
        }
    size_t n = 0;
    for (int j = 0; j + 1 < h; ++j)
        for (int i = 0; i + 1 < w; ++i) {
            const GLuint k = (GLuint)(j * w + i);
            const GLuint quad[6] = {k, k + 1, k + (GLuint)w, k + 1, k + (GLuint)w + 1,
                                    k + (GLuint)w};
            memcpy(idx + n, quad, sizeof quad);
            n += 6;
        }
    glGenVertexArrays(1, &a->vao);
    glBindVertexArray(a->vao);
    glGenBuffers(1, &a->vbo);
    glBindBuffer(GL_ARRAY_BUFFER, a->vbo);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(sizeof(float) * 5 * (size_t)w * h), v,
                 GL_STATIC_DRAW);
    glGenBuffers(1, &a->ibo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, a->ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(sizeof(GLuint) * n), idx, GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 5 * sizeof(float), (void *)0);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 5 * sizeof(float),
                          (void *)(3 * sizeof(float)));
    a->n_index = (GLsizei)n;
    free(v);
    free(idx);
    return 1;
}

static int make_scene(app *a, const hfs_field *f)
{
    const GLuint vs = compile(GL_VERTEX_SHADER, vert_src);
    const GLuint fs = compile(GL_FRAGMENT_SHADER, frag_src);
    a->prog = glCreateProgram();
    glAttachShader(a->prog, vs);
    glAttachShader(a->prog, fs);
    glLinkProgram(a->prog);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(a->prog, GL_LINK_STATUS, &ok);
    glGenFramebuffers(1, &a->fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, a->fbo);
    glGenRenderbuffers(1, &a->color);
    glBindRenderbuffer(GL_RENDERBUFFER, a->color);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, VIEW_W, VIEW_H);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, a->color);
    glGenRenderbuffers(1, &a->depth);
    glBindRenderbuffer(GL_RENDERBUFFER, a->depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, VIEW_W, VIEW_H);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, a->depth);
    return ok && glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE &&
           make_mesh(a, f);
}

/* Column-major perspective * look-at, the camera orbiting the field's
 * centre (c) from the south-west, 35 degrees up. */
static void camera(const hfs_field *f, float mvp[16])
{
    const double c[3] = {0.5 * (f->width - 1) * f->dx, 0.5 * (f->height - 1) * f->dx, 0.0};
    const double dist = 1.6 * (f->width - 1) * f->dx, az = -2.2, el = 35.0 * PI / 180.0;
    const double eye[3] = {c[0] + dist * cos(el) * cos(az), c[1] + dist * cos(el) * sin(az),
                           c[2] + dist * sin(el)};
    double fw[3] = {c[0] - eye[0], c[1] - eye[1], c[2] - eye[2]};
    double n = sqrt(fw[0] * fw[0] + fw[1] * fw[1] + fw[2] * fw[2]);
    for (int k = 0; k < 3; ++k)
        fw[k] /= n;
    double rt[3] = {fw[1], -fw[0], 0.0}; /* forward x up(+z) */
    n = sqrt(rt[0] * rt[0] + rt[1] * rt[1]);
    rt[0] /= n, rt[1] /= n;
    const double up[3] = {rt[1] * fw[2] - rt[2] * fw[1], rt[2] * fw[0] - rt[0] * fw[2],
                          rt[0] * fw[1] - rt[1] * fw[0]};
    const double t = 1.0 / tan(0.5 * 40.0 * PI / 180.0), asp = (double)VIEW_W / VIEW_H;
    const double near = 0.05 * dist, far = 4.0 * dist;
    const double rows[4][4] = {
        {t / asp * rt[0], t / asp * rt[1], t / asp * rt[2], 0},
        {t * up[0], t * up[1], t * up[2], 0},
        {(far + near) / (far - near) * fw[0], (far + near) / (far - near) * fw[1],
         (far + near) / (far - near) * fw[2], -2.0 * far * near / (far - near)},
        {fw[0], fw[1], fw[2], 0}};
    /* Rows: right, up and the projection of depth along forward (the view
     * space's -z), acting on p - eye: the translation folds into the last
     * column. */
    for (int r = 0; r < 4; ++r) {
        const double tr = rows[r][3] - (rows[r][0] * eye[0] + rows[r][1] * eye[1] +
                                        rows[r][2] * eye[2]);
        for (int k = 0; k < 3; ++k)
            mvp[4 * k + r] = (float)rows[r][k];
        mvp[12 + r] = (float)tr;
    }
}

static void draw(app *a, const hfs_field *f, const hfs_lit_texture *lit, double exposure)
{
    /* The renderer's frame must be done before the mesh samples it: a
     * GPU-side wait, the CPU goes on. */
    glWaitSync((GLsync)lit->fence, 0, GL_TIMEOUT_IGNORED);
    glBindFramebuffer(GL_FRAMEBUFFER, a->fbo);
    glViewport(0, 0, VIEW_W, VIEW_H);
    glEnable(GL_DEPTH_TEST);
    glClearColor(0.45f, 0.62f, 0.85f, 1.0f); /* the application's own sky */
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(a->prog);
    float mvp[16];
    camera(f, mvp);
    glUniformMatrix4fv(glGetUniformLocation(a->prog, "u_mvp"), 1, GL_FALSE, mvp);
    glUniform1f(glGetUniformLocation(a->prog, "u_exposure"), (float)exposure);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, lit->texture);
    glUniform1i(glGetUniformLocation(a->prog, "u_lit"), 0);
    glBindVertexArray(a->vao);
    glDrawElements(GL_TRIANGLES, a->n_index, GL_UNSIGNED_INT, 0);
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_2D, 0);
    /* The next render_texture writes the texture in place: flush the
     * draws that read it first (hfshade.h hfs_lit_texture). */
    glFlush();
}

/* The application's picture as a binary PPM, top row first. */
static int write_ppm(const char *path, double *mean)
{
    unsigned char *px = malloc((size_t)VIEW_W * VIEW_H * 4);
    FILE *out = px ? fopen(path, "wb") : NULL;
    if (!out) {
        free(px);
        fprintf(stderr, "embed_mesh: %s: cannot write\n", path);
        return 0;
    }
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, VIEW_W, VIEW_H, GL_RGBA, GL_UNSIGNED_BYTE, px);
    fprintf(out, "P6\n%d %d\n255\n", VIEW_W, VIEW_H);
    double sum = 0.0;
    for (int y = VIEW_H - 1; y >= 0; --y)
        for (int x = 0; x < VIEW_W; ++x) {
            const unsigned char *p = px + 4 * ((size_t)y * VIEW_W + x);
            fwrite(p, 1, 3, out);
            sum += p[0] + p[1] + p[2];
        }
    *mean = sum / (3.0 * VIEW_W * VIEW_H);
    free(px);
    return fclose(out) == 0;
}

/* ---- hfshade's part ------------------------------------------------------ */

/* A ridge and a crater on rolling ground, in texels of height. */
static void make_heights(float *z)
{
    for (int j = 0; j < FIELD; ++j)
        for (int i = 0; i < FIELD; ++i) {
            const double x = (double)i / (FIELD - 1), y = (double)j / (FIELD - 1);
            const double ridge = 18.0 * exp(-pow((x - 0.35 - 0.2 * y) / 0.06, 2.0));
            const double r = hypot(x - 0.7, y - 0.65);
            const double crater = 14.0 * exp(-pow((r - 0.12) / 0.04, 2.0)) - 8.0 * exp(-pow(r / 0.08, 2.0));
            z[j * FIELD + i] = (float)(ridge + crater + 3.0 * sin(9.0 * x) * cos(7.0 * y));
        }
}

static void make_lighting(hfs_lighting *l, double sun_azimuth)
{
    hfs_lighting_defaults(l);
    l->has_env = 1; /* a dim blue sky: its constant SH band */
    const double sky[3] = {0.10, 0.14, 0.22};
    for (int c = 0; c < 3; ++c)
        l->env_sh[c][0] = sky[c] * 2.0 * sqrt(PI);
    l->n_key = 1;
    l->key[0] = (hfs_key_light){.phi = sun_azimuth, .elev = 0.35, .alpha = 0.02,
                                .radiance = {2000.0f, 1900.0f, 1700.0f}};
    l->albedo = 0.7;
}

static int fail(const char *what, const hfs_error *err)
{
    fprintf(stderr, "embed_mesh: %s: %s\n", what, err->msg);
    return 1;
}

int main(int argc, char **argv)
{
    const int frames = argc > 2 ? atoi(argv[2]) : 3;
    if (argc < 2 || argc > 3 || frames < 1) {
        fprintf(stderr, "usage: embed_mesh OUT.ppm [FRAMES >= 1]\n");
        return 1;
    }
    app a = {0};
    if (!egl_context(&a)) {
        printf("embed_mesh: skipped: no EGL/GLES 3 context here (EGL 0x%x)\n", eglGetError());
        return 77;
    }
    static float z[FIELD * FIELD];
    make_heights(z);
    const hfs_field field = {FIELD, FIELD, z, 1.0, 1.0};
    if (!make_scene(&a, &field)) {
        fprintf(stderr, "embed_mesh: the application's scene: GL error 0x%x\n", glGetError());
        return 1;
    }
    const hfs_renderer_desc desc = {.backend = HFS_BACKEND_GLES, .egl_display = a.dpy,
                                    .egl_share_context = a.ctx};
    hfs_renderer *r = NULL;
    hfs_error err = {""};
    if (hfs_renderer_create(&desc, &r, &err))
        return fail("renderer", &err);
    hfs_quality q;
    hfs_quality_defaults(&q);
    hfs_lit_texture lit = {0};
    for (int i = 0; i < frames; ++i) {
        hfs_lighting l;
        make_lighting(&l, 200.0 * PI / 180.0 + 0.1 * i); /* the sun turns */
        if (hfs_renderer_render_texture(r, &field, &l, &q, NULL, &lit, &err))
            return fail("render texture", &err);
        /* hfshade gave the application's context back: draw with it. */
        draw(&a, &field, &lit, 2.0);
    }
    double mean = 0.0;
    const int ok = write_ppm(argv[1], &mean);
    printf("embed_mesh: %d frames, lit texture %u (%dx%d RGBA16F) on a %dx%d mesh; %s: mean "
           "%.1f of 255\n", frames, lit.texture, lit.width, lit.height, FIELD, FIELD, argv[1],
           mean);
    hfs_renderer_destroy(r);
    const GLenum gl_err = glGetError();
    if (gl_err != GL_NO_ERROR)
        fprintf(stderr, "embed_mesh: GL error 0x%x\n", gl_err);
    glDeleteProgram(a.prog);
    eglMakeCurrent(a.dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(a.dpy, a.ctx);
    return ok && gl_err == GL_NO_ERROR ? 0 : 1;
}
