/*
 * pass_view.c — the 3-D view (issue 16, deliverable 4): the lit field seen
 * from an hfs_camera (view_camera.h, the basis the truth's ray-cast view
 * uses), drawn as a triangle mesh over its background, read back as RGB.
 *
 *   sky    view_sky.frag over the whole view: the camera's background in
 *          each pixel centre's ray direction (view_sky.c, core view_look.h:
 *          the environment map, its SH, zero without an environment, a
 *          studio grey, a colour); the mesh and the objects are seen
 *          through the look's haze (gles_view.frag);
 *   mesh   view.vert + view.frag: W x H grid points, two triangles a cell
 *          (strips, one instance per row of cells: no vertex or index
 *          buffer), heights from the level array's last layer (u_hlayer), the lit
 *          exit radiance (hfs_gles_lit_targets) bilinear at each fragment's
 *          grid position; depth-tested; then the four side walls down to
 *          the field's lowest height (the truth's rays start testing where
 *          they enter the grid above that height, so one entering under
 *          the surface hits there: the field is a solid block down to its
 *          lowest point, its walls showing their edge's radiance; below
 *          it the sky);
 *   target RGBA16F + 24-bit depth, multisampled with the capability
 *          layer's sample count (the format's own GL_SAMPLES, at most 4;
 *          1 where the driver offers none) and resolved by a blit;
 *   read   the resolved image, flipped to row 0 at the top, the view's
 *          scale divided out, non-finite values written as 0.
 *
 * Values: the lit textures hold radiance times the frame's output scale
 * (pass_shade.c); the view multiplies them into its own power of two,
 * min(lit scale, the scale of the sky's bound), so neither a bright sky
 * nor a bright field leaves fp16's range.
 *
 * The planner runs this pass when the camera, the view size, the lit
 * output, the heights or the sky change: a camera move costs this pass
 * alone (plan.h).  Differences from the truth (one exact ray per pixel
 * centre over the bilinear surface): the mesh is the grid's triangles,
 * not its bilinear patches (within a cell the surface differs by up to a
 * quarter of the cell's twist), edges are antialiased, and a perspective
 * camera inside the field's box loses what lies nearer than 1e-4 of the
 * far plane.
 */
#include "gles_backend.h"

#include "gl_util.h"
#include "view_sky.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct hfs_gles_view_state {
    int w, h, samples;
    GLuint fbo, rb[2];       /* resolved colour (RGBA16F), depth when samples == 1 */
    GLuint ms_fbo, ms_rb[2]; /* multisampled colour and depth */
    float *kept;             /* the last view image, RGB */
    size_t kept_cap;
    int kept_w, kept_h;
    hfs_gles_view_sky sky;   /* the environment map behind the terrain */
};

static void free_targets(const hfs_gl *gl, hfs_gles_view_state *v)
{
    if (v->fbo)
        gl->DeleteFramebuffers(1, &v->fbo);
    if (v->ms_fbo)
        gl->DeleteFramebuffers(1, &v->ms_fbo);
    gl->DeleteRenderbuffers(2, v->rb);
    gl->DeleteRenderbuffers(2, v->ms_rb);
    v->fbo = v->ms_fbo = v->rb[0] = v->rb[1] = v->ms_rb[0] = v->ms_rb[1] = 0;
    v->w = v->h = v->samples = 0;
}

void hfs_gles_view_free(hfs_gles *g)
{
    if (!g->view)
        return;
    free_targets(&g->gl, g->view);
    hfs_gles_view_sky_free(&g->view->sky, &g->gl);
    free(g->view->kept);
    free(g->view);
    g->view = NULL;
}

int hfs_gles_view_copy_kept(const hfs_gles *g, hfs_gles_frame *fr)
{
    const hfs_gles_view_state *v = g->view;
    if (!v || !v->kept || v->kept_w != fr->view_w || v->kept_h != fr->view_h)
        return 0;
    memcpy(fr->view_rgb, v->kept, (size_t)v->kept_w * v->kept_h * 3 * sizeof *v->kept);
    return 1;
}

/* A framebuffer of a colour and a depth renderbuffer (samples > 1:
 * multisampled); 0 when the driver refuses it. */
static int make_fbo(const hfs_gl *gl, int samples, int w, int h, int depth, GLuint *fbo,
                    GLuint rb[2])
{
    const GLenum fmt[2] = {GL_RGBA16F, GL_DEPTH_COMPONENT24};
    const GLenum at[2] = {GL_COLOR_ATTACHMENT0, GL_DEPTH_ATTACHMENT};
    gl->GenFramebuffers(1, fbo);
    gl->BindFramebuffer(GL_FRAMEBUFFER, *fbo);
    gl->GenRenderbuffers(1 + depth, rb);
    for (int k = 0; k < 1 + depth; ++k) {
        gl->BindRenderbuffer(GL_RENDERBUFFER, rb[k]);
        if (samples > 1)
            gl->RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, fmt[k], w, h);
        else
            gl->RenderbufferStorage(GL_RENDERBUFFER, fmt[k], w, h);
        gl->FramebufferRenderbuffer(GL_FRAMEBUFFER, at[k], GL_RENDERBUFFER, rb[k]);
    }
    const GLenum buf = GL_COLOR_ATTACHMENT0;
    gl->DrawBuffers(1, &buf);
    const GLenum status = gl->CheckFramebufferStatus(GL_FRAMEBUFFER);
    gl->BindRenderbuffer(GL_RENDERBUFFER, 0);
    gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
    return status == GL_FRAMEBUFFER_COMPLETE && gl->GetError() == GL_NO_ERROR;
}

/* The view's targets at w x h: multisampled where the capability layer
 * allows, else (or if the driver refuses the multisampled pair) one
 * sample with its depth on the resolved framebuffer. */
static int ensure_targets(hfs_gles *g, int w, int h, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    if (!g->view && !(g->view = calloc(1, sizeof *g->view)))
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for the view");
    hfs_gles_view_state *v = g->view;
    const int want = g->caps.view_samples > 1 ? g->caps.view_samples : 1;
    if (v->fbo && v->w == w && v->h == h && (v->samples == want || v->samples == 1))
        return HFS_OK;
    free_targets(gl, v);
    v->samples = want;
    if (want > 1 && (!make_fbo(gl, want, w, h, 1, &v->ms_fbo, v->ms_rb) ||
                     !make_fbo(gl, 1, w, h, 0, &v->fbo, v->rb))) {
        free_targets(gl, v); /* the multisampled RGBA16F pair refused: one sample */
        v->samples = 1;
    }
    if (v->samples == 1 && !make_fbo(gl, 1, w, h, 1, &v->fbo, v->rb)) {
        free_targets(gl, v);
        return hfs_fail(err, HFS_E_UNSUPPORTED, "view: an RGBA16F + DEPTH_COMPONENT24 "
                        "framebuffer of %dx%d is incomplete on this driver", w, h);
    }
    v->w = w, v->h = h;
    return hfs_gl_check(gl, "backend gles: view targets", err);
}

/* The side walls' bottom: the field's lowest height (the block the
 * truth's view shows, truth_view.c; below it the sky). */
static double wall_bottom(const hfs_gles_frame *fr, const hfs_camera_frame *cf)
{
    (void)cf;
    const hfs_gles_layout *L = &fr->L;
    return L->zscale * fr->cam->exaggeration * (L->base - L->hscale);
}

/* Near and far planes around the field's box (exaggerated heights, down
 * to the walls' bottom) and the objects' as seen along the camera's
 * forward axis. */
static void depth_range(const hfs_gles_frame *fr, const hfs_camera_frame *cf, double *n,
                        double *f)
{
    const hfs_gles_layout *L = &fr->L;
    const double zs = L->zscale * fr->cam->exaggeration;
    double box[2][3] = {{0.0, 0.0, wall_bottom(fr, cf)},
                        {(L->w - 1) * L->dx, (L->h - 1) * L->dx, zs * (L->base + L->hscale)}};
    for (int b = 0; fr->objects && b < fr->objects->n; ++b) /* and the objects' boxes */
        for (int k = 0; k < 3; ++k) {
            box[0][k] = fmin(box[0][k], fr->objects->box[b][k]);
            box[1][k] = fmax(box[1][k], fr->objects->box[b][k + 3]);
        }
    double lo = INFINITY, hi = -INFINITY;
    for (int c = 0; c < 8; ++c) {
        double d = 0.0;
        for (int k = 0; k < 3; ++k)
            d += (box[(c >> k) & 1][k] - cf->eye[k]) * cf->forward[k];
        lo = fmin(lo, d), hi = fmax(hi, d);
    }
    const double margin = 1e-3 * (hi - lo) + 1e-9 * (fabs(hi) + 1.0);
    if (cf->ortho) { /* nothing behind the eye's plane, as the truth's rays */
        *n = fmax(lo - margin, 0.0);
        *f = fmax(hi + margin, *n + 1.0);
    } else {
        *f = hi > 0.0 ? hi + margin : 1.0;
        *n = fmax(lo - margin, 1e-4 * *f);
    }
}

/* u_mvp: eye-relative world -> clip, column-major; GL's y up is the
 * image's up (the read-back flips rows). */
static void projection(const hfs_camera_frame *cf, double aspect, double n, double f,
                       float m[16])
{
    double row[4][4] = {{0}};
    const double sy = cf->ortho ? cf->half_height : cf->tan_half, sx = sy * aspect;
    for (int k = 0; k < 3; ++k) {
        row[0][k] = cf->right[k] / sx;
        row[1][k] = cf->up[k] / sy;
    }
    if (cf->ortho) {
        for (int k = 0; k < 3; ++k)
            row[2][k] = 2.0 * cf->forward[k] / (f - n);
        row[2][3] = -(f + n) / (f - n);
        row[3][3] = 1.0;
    } else {
        for (int k = 0; k < 3; ++k) {
            row[2][k] = (f + n) / (f - n) * cf->forward[k];
            row[3][k] = cf->forward[k];
        }
        row[2][3] = -2.0 * f * n / (f - n);
    }
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            m[4 * c + r] = (float)row[r][c];
}

/* HfsView; returns the view's scale (radiance -> stored value).  map: the
 * background is the environment map (g->view->sky). */
static double fill_block(const hfs_gles *g, const hfs_gles_frame *fr, int map,
                         hfs_gles_view_block *b)
{
    memset(b, 0, sizeof *b);
    const hfs_gles_layout *L = &fr->L;
    hfs_camera_frame cf;
    hfs_camera_frame_make(fr->cam, &cf);
    const double aspect = (double)fr->view_w / (double)fr->view_h;
    double n, f;
    depth_range(fr, &cf, &n, &f);
    projection(&cf, aspect, n, f, b->mvp);
    const double sy = cf.tan_half, sx = sy * aspect;
    for (int k = 0; k < 3; ++k) {
        b->eye[k] = (float)cf.eye[k];
        b->fwd[k] = (float)cf.forward[k];
        b->right[k] = (float)(cf.right[k] * sx);
        b->up[k] = (float)(cf.up[k] * sy);
    }
    b->eye[3] = cf.ortho ? 1.0f : 0.0f;
    b->fwd[3] = (float)wall_bottom(fr, &cf);
    double sky = 0.0; /* |SH basis| <= 1 for l <= 3: the sky's bound */
    for (int c = 0; c < 3 && fr->has_env; ++c) {
        double s = 0.0;
        for (int k = 0; k < HFS_SH_N; ++k)
            s += fabs(fr->l_env[c][k]);
        sky = fmax(sky, s);
    }
    sky = fmax(sky, hfs_gles_view_look_bound(fr->cam, &g->view->sky, map));
    const double lit = g->lit_scale > 0.0 ? g->lit_scale : 1.0;
    const double scale = fmin(lit, hfs_gles_output_scale(sky));
    const double zs = L->zscale * fr->cam->exaggeration;
    b->zmap[0] = (float)(zs * L->hscale);
    b->zmap[1] = (float)(zs * L->base);
    b->zmap[2] = (float)L->dx;
    b->zmap[3] = (float)(scale / lit); /* a power of two: exact (0 if it underflows) */
    b->sizes[0] = (float)L->w, b->sizes[1] = (float)L->h;
    b->sizes[2] = (float)fr->view_w, b->sizes[3] = (float)fr->view_h;
    for (int c = 0; c < 3 && fr->has_env; ++c)
        for (int k = 0; k < HFS_SH_N; ++k)
            b->env[c][k] = (float)(fr->l_env[c][k] * scale);
    hfs_gles_view_look_fill(b, fr->cam, fr->l, &g->view->sky, map, scale);
    return scale;
}

/* The objects' lit faces (objects.h; bottoms left out) as triangles:
 * per vertex its position relative to the eye and its radiance times the
 * view's scale, 6 floats.  Returns the vertex count, 0 without objects,
 * -1 out of memory. */
static int object_triangles(const hfs_gles_frame *fr, double scale, const double eye[3],
                            float **out)
{
    const hfs_object_set *s = fr->objects;
    *out = NULL;
    if (!s || s->n == 0)
        return 0;
    static const int faces[5] = {0, 1, 2, 3, 5};
    static const int corner[6][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
    const int g = HFS_OBJ_GRID, per_box = 5 * g * g * 6;
    float *v = malloc((size_t)s->n * (size_t)per_box * 6 * sizeof *v), *w = v;
    if (!v)
        return -1;
    for (int b = 0; b < s->n; ++b)
        for (int fi = 0; fi < 5; ++fi)
            for (int q = 0; q < g * g; ++q)
                for (int k = 0; k < 6; ++k) {
                    const int vi = (q / g + corner[k][1]) * (g + 1) + q % g + corner[k][0];
                    double p[3];
                    hfs_objects_vertex(s, b, faces[fi], vi, p);
                    const float *rgb = s->rgb + 3 * (((size_t)b * 6 + (size_t)faces[fi]) *
                                                         HFS_OBJ_VERTS + (size_t)vi);
                    for (int c = 0; c < 3; ++c) {
                        w[c] = (float)(p[c] - eye[c]);
                        w[3 + c] = (float)(rgb[c] * scale);
                    }
                    w += 6;
                }
    *out = v;
    return s->n * per_box;
}

/* Draws the objects into the bound target, depth-tested with the mesh. */
static int draw_objects(hfs_gles *g, const hfs_gles_frame *fr, double scale, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    hfs_camera_frame cf;
    hfs_camera_frame_make(fr->cam, &cf);
    float *tri;
    const int n = object_triangles(fr, scale, cf.eye, &tri);
    if (n <= 0)
        return n < 0 ? hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for the "
                                "objects") : HFS_OK;
    const hfs_gles_variant var = {0};
    const hfs_gles_program *prog;
    int rc = hfs_gles_program_use(&g->programs, gl, HFS_PROG_VIEW_OBJECTS, &var, &prog, err);
    if (rc) {
        free(tri);
        return rc;
    }
    GLuint vbo = 0;
    gl->GenBuffers(1, &vbo);
    gl->BindBuffer(GL_ARRAY_BUFFER, vbo);
    gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)((size_t)n * 6 * sizeof *tri), tri,
                   GL_STREAM_DRAW);
    free(tri);
    gl->EnableVertexAttribArray(0);
    gl->EnableVertexAttribArray(1);
    gl->VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (const void *)0);
    gl->VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float),
                            (const void *)(3 * sizeof(float)));
    gl->DrawArrays(GL_TRIANGLES, 0, n);
    gl->DisableVertexAttribArray(0);
    gl->DisableVertexAttribArray(1);
    gl->BindBuffer(GL_ARRAY_BUFFER, 0);
    gl->DeleteBuffers(1, &vbo);
    return hfs_gl_check(gl, "backend gles: view objects", err);
}

/* Sky, then the mesh and the objects, into the (multisampled) target;
 * resolved. */
static int draw(hfs_gles *g, const hfs_gles_frame *fr, double scale, hfs_error *err)
{
    const hfs_gl *gl = &g->gl;
    const hfs_gles_view_state *v = g->view;
    const hfs_gles_variant var = {0};
    const hfs_gles_program *prog;
    const GLuint target = v->samples > 1 ? v->ms_fbo : v->fbo;
    int rc = hfs_gles_program_use(&g->programs, gl, HFS_PROG_VIEW_SKY, &var, &prog, err);
    if (!rc)
        rc = hfs_gles_program_texture(gl, prog, "u_sky", GL_TEXTURE_2D, v->sky.tex, err);
    if (rc)
        return rc;
    gl->BindBufferBase(GL_UNIFORM_BUFFER, HFS_BLOCK_VIEW, g->ubo[HFS_UBO_VIEW]);
    hfs_gles_draw(gl, target, fr->view_w, fr->view_h); /* every pixel: no colour clear */
    GLuint lit[2];
    hfs_gles_lit_targets(g, fr, lit);
    if ((rc = hfs_gles_program_use(&g->programs, gl, HFS_PROG_VIEW, &var, &prog, err)) ||
        (rc = hfs_gles_program_texture(gl, prog, "u_height", GL_TEXTURE_2D_ARRAY, g->r.arr, err)) ||
        (rc = hfs_gles_program_texture(gl, prog, "u_lit_hi", GL_TEXTURE_2D, lit[0], err)) ||
        (rc = hfs_gles_program_texture(gl, prog, "u_lit_lo", GL_TEXTURE_2D, lit[1], err)))
        return rc;
    const GLfloat far_depth = 1.0f;
    gl->ClearBufferfv(GL_DEPTH, 0, &far_depth);
    gl->Enable(GL_DEPTH_TEST);
    gl->DepthFunc(GL_LESS);
    hfs_gles_set_i1(gl, prog, "u_hlayer", fr->L.n_layers - 1);
    hfs_gles_set_i1(gl, prog, "u_skirt", 0);
    gl->DrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 2 * fr->L.w, fr->L.h - 1);
    hfs_gles_set_i1(gl, prog, "u_skirt", 1); /* the four walls, an instance each */
    gl->DrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 2 * (fr->L.w > fr->L.h ? fr->L.w : fr->L.h), 4);
    if ((rc = draw_objects(g, fr, scale, err)))
        return rc;
    gl->Disable(GL_DEPTH_TEST);
    gl->UseProgram(0);
    if (v->samples > 1) {
        gl->BindFramebuffer(GL_READ_FRAMEBUFFER, v->ms_fbo);
        gl->BindFramebuffer(GL_DRAW_FRAMEBUFFER, v->fbo);
        gl->BlitFramebuffer(0, 0, fr->view_w, fr->view_h, 0, 0, fr->view_w, fr->view_h,
                            GL_COLOR_BUFFER_BIT, GL_NEAREST);
        gl->BindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    hfs_gles_stage_fetches(g, HFS_PASS_VIEW, 0,
                           (double)fr->L.w * fr->L.h + 8.0 * fr->view_w * fr->view_h);
    return hfs_gl_check(gl, "backend gles: view pass", err);
}

/* The resolved image into fr->view_rgb (row 0 at the top) and the kept copy. */
static int read_view(hfs_gles *g, hfs_gles_frame *fr, double scale, hfs_error *err)
{
    hfs_gles_view_state *v = g->view;
    const int w = fr->view_w, h = fr->view_h;
    const size_t n = (size_t)w * h * 3;
    float *px = hfs_gles_scratch(g, (size_t)w * h * 4 * sizeof(float));
    if (!px)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for the view");
    int rc = hfs_gl_read_rgba(&g->gl, v->fbo, 0, 0, w, h, HFS_GL_READ_AUTO, px, NULL, err);
    if (rc)
        return rc;
    const double inv = 1.0 / scale;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) {
                const double val = px[4 * ((size_t)(h - 1 - y) * w + x) + (size_t)c] * inv;
                fr->view_rgb[3 * ((size_t)y * w + x) + (size_t)c] = isfinite(val) ? (float)val : 0.0f;
            }
    if (v->kept_cap < n) {
        float *k = realloc(v->kept, n * sizeof *k);
        if (!k)
            return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory for the kept view");
        v->kept = k, v->kept_cap = n;
    }
    memcpy(v->kept, fr->view_rgb, n * sizeof *v->kept);
    v->kept_w = w, v->kept_h = h;
    return HFS_OK;
}

static int present(const hfs_gles_frame *fr)
{
    return fr->cam != NULL;
}

static int layout(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err)
{
    int rc = hfs_gl_caps_check_view(&g->caps, fr->view_w, fr->view_h, 1, err);
    if (!rc)
        rc = hfs_gl_caps_check_samplers(&g->caps, 2, "view pass", err);
    return rc ? rc : hfs_gl_caps_check_uniform_block(&g->caps, sizeof(hfs_gles_view_block),
                                                     "view camera", err);
}

static int run(hfs_gles *g, hfs_gles_frame *fr, const int *which, hfs_error *err)
{
    (void)which;
    hfs_gles_stage_begin(g, HFS_PASS_VIEW, 0);
    int rc = ensure_targets(g, fr->view_w, fr->view_h, err);
    if (rc)
        return rc;
    /* The map's texture only while a view draws it. */
    const int map = hfs_gles_view_sky_wanted(fr->cam, fr->l);
    if (map && (rc = hfs_gles_view_sky_follow(&g->view->sky, &g->gl, &g->caps, fr->l, err)))
        return rc;
    if (!map)
        hfs_gles_view_sky_free(&g->view->sky, &g->gl);
    hfs_gles_view_block b;
    const double scale = fill_block(g, fr, map, &b);
    hfs_gles_ubo_upload(&g->gl, g->ubo[HFS_UBO_VIEW], &b, sizeof b);
    if ((rc = draw(g, fr, scale, err)))
        return rc;
    hfs_gles_stage_end(g, HFS_PASS_VIEW, 0);
    hfs_gles_stage_begin(g, HFS_PASS_VIEW, 1);
    rc = read_view(g, fr, scale, err);
    hfs_gles_stage_end(g, HFS_PASS_VIEW, 1);
    return rc;
}

const hfs_gles_pass hfs_pass_view = {
    .id = HFS_PASS_VIEW,
    .plan_name = "view",
    .scope = HFS_SCOPE_FRAME,
    /* And the bounced targets when the frame has bounces (plan.c). */
    .reads = {"pyramid", "output targets", "env light", "light set", "camera"},
    .writes = {"view image"},
    .stages = {"view", "viewread"},
    .present = present,
    .layout = layout,
    .run = run,
};
