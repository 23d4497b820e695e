/*
 * gles_backend.c — the GLES renderer backend (backends.h, DESIGN.md "GLES
 * path"): the CPU reference's algorithm on OpenGL ES 3.0 with fp16
 * textures.  This file holds the object (context, GL table, buffers,
 * caches) and turns a lighting into a frame's lights; gles_frame.c runs
 * the frame over the pass table (pass.h).
 *
 * Every format/limit decision goes through gl_caps.h; every GL call through
 * the hfs_gl table of the renderer's own context, which is made current at
 * each call.  Nothing is printed; nothing is global.
 */
#include "gles_backend.h"

#include "gl_probe.h"
#include "gl_util.h"
#include "key_setup.h"
#include "lights.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

/* Timing slots: the stages of the table's passes, in order. */
static void name_slots(hfs_gles *g)
{
    int n = 0;
    for (int p = 0; p < HFS_PASS_COUNT; ++p) {
        const hfs_gles_pass *pass = hfs_gles_pass_table[p];
        g->stage_slot[p] = n;
        for (int s = 0; s < HFS_PASS_MAX_STAGES && pass->stages[s]; ++s)
            g->timing.name[n++] = pass->stages[s];
    }
    g->timing.n_slots = n;
}

/* Everything after the context: the GL table, the driver's caps, the
 * profile (refused now, not at the first frame), the shared objects. */
static int setup(hfs_gles *g, const char *profile, int strict_limits, hfs_error *err)
{
    int rc;
    if ((rc = hfs_gl_load(&g->gl, hfs_gl_context_loader, g->ctx, err)))
        return rc;
    hfs_gl_caps_query(&g->gl, &g->driver);
    g->driver.filter_inexact = hfs_gl_probe_filter_inexact(&g->gl);
    g->programs.pair_fetch = g->driver.filter_inexact;
    g->strict_limits = strict_limits != 0;
    if (profile) {
        hfs_gl_caps c;
        if ((rc = hfs_gl_caps_select(&g->driver, profile, !strcmp(profile, "es30-float"),
                                     strict_limits, &c, err)))
            return rc;
        snprintf(g->profile, sizeof g->profile, "%s", profile);
    }
    const hfs_gl *gl = &g->gl;
    gl->GenVertexArrays(1, &g->vao);
    gl->BindVertexArray(g->vao);
    gl->GenBuffers(HFS_UBO_COUNT, g->ubo);
    hfs_gles_timing_init(&g->timing, gl, g->driver.timer_query);
    name_slots(g);
    gl->Disable(GL_BLEND);
    gl->Disable(GL_DEPTH_TEST);
    gl->Disable(GL_SCISSOR_TEST);
    if ((rc = hfs_gl_check(gl, "backend gles: setup", err)))
        return rc;
    return hfs_gles_plan_init(&g->plan, err);
}

/* The context made (own, or shared with the application's), the rest. */
static int create(const char *context, void *egl_display, void *egl_context, const char *profile,
                  int strict_limits, hfs_gles **out, hfs_error *err)
{
    *out = NULL;
    hfs_gles *g = calloc(1, sizeof *g);
    if (!g)
        return hfs_fail(err, HFS_E_NOMEM, "backend gles: out of memory");
    g->shared = egl_context != NULL;
    int rc = g->shared ? hfs_gl_context_create_shared(egl_display, egl_context, &g->ctx, err)
                       : hfs_gl_context_create(context, &g->ctx, err);
    if (!rc)
        rc = setup(g, profile, strict_limits, err);
    if (rc) {
        hfs_gles_destroy(g);
        return rc;
    }
    hfs_gles_release(g);
    *out = g;
    return HFS_OK;
}

int hfs_gles_create(const char *context, const char *profile, int strict_limits, hfs_gles **out,
                    hfs_error *err)
{
    return create(context, NULL, NULL, profile, strict_limits, out, err);
}

int hfs_gles_create_shared(void *egl_display, void *egl_context, const char *profile,
                           int strict_limits, hfs_gles **out, hfs_error *err)
{
    if (!egl_display || !egl_context)
        return hfs_fail(err, HFS_E_INVALID, "renderer desc: egl_display and egl_share_context "
                        "go together (%s is NULL)", egl_display ? "egl_share_context"
                                                                : "egl_display");
    return create(NULL, egl_display, egl_context, profile, strict_limits, out, err);
}

void hfs_gles_release(hfs_gles *g)
{
    if (g && g->ctx)
        hfs_gl_context_release(g->ctx);
}

void hfs_gles_destroy(hfs_gles *g)
{
    if (!g)
        return;
    const hfs_gl *gl = NULL;
    if (g->ctx && g->gl.GetError && !hfs_gl_context_make_current(g->ctx, NULL)) {
        gl = &g->gl;
        hfs_gles_resources_free(&g->r, gl);
        hfs_gles_programs_free(&g->programs, gl);
        if (g->vao)
            gl->DeleteVertexArrays(1, &g->vao);
        gl->DeleteBuffers(HFS_UBO_COUNT, g->ubo);
        hfs_gles_timing_free(&g->timing, gl);
        hfs_gles_block_texture_free(&g->env_swath_tex, gl);
        hfs_gles_block_texture_free(&g->key_swath_tex, gl);
        hfs_gles_block_texture_free(&g->keys_tex, gl);
        hfs_gles_block_texture_free(&g->local_tex, gl);
        hfs_gles_block_texture_free(&g->far_swath_tex, gl);
        hfs_gles_view_free(g);
        hfs_gles_lit_texture_free(g);
    }
    hfs_gles_wedge_textures_free(&g->wedge, gl);
    hfs_gles_albedo_texture_free(&g->albedo, gl);
    hfs_gles_bounce_targets_free(&g->bounce, gl);
    hfs_gles_env_map_textures_free(&g->envmap, gl);
    hfs_visibility_destroy(g->env_vis);
    hfs_slice_table_free(&g->env_slices);
    hfs_gl_context_destroy(g->ctx);
    free(g->terrain_z);
    hfs_gles_edit_free(&g->edit);
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
    g->timing.finish = finish != 0;
}

void hfs_gles_set_amortize(hfs_gles *g, int passes_per_frame)
{
    g->plan.amortize = passes_per_frame;
}

void hfs_gles_set_timing(hfs_gles *g, int level)
{
    g->timing.level = level < 0 ? 0 : (level > 2 ? 2 : level);
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

/* The frame's lights: those that contribute, exactly as cpu_render.c. */
static void frame_lights(const hfs_lighting *l, const hfs_quality *q, hfs_gles_frame *fr)
{
    fr->has_env = hfs_env_contributes(l);
    for (int i = 0; i < l->n_key && i < HFS_MAX_KEY_LIGHTS; ++i) {
        if (!hfs_key_light_contributes(&l->key[i], l->albedo + l->specular))
            continue;
        hfs_gles_key *k = &fr->keys[fr->n_keys++].k;
        hfs_key_setup ks;
        hfs_key_setup_make(&l->key[i], q, &ks);
        k->swath = ks.swath;
        memcpy(k->dir, ks.dir, sizeof k->dir);
        k->alpha = ks.alpha;
        memcpy(k->le, ks.le, sizeof k->le);
        memcpy(k->l_sh, ks.l_sh, sizeof k->l_sh);
        k->l_norm = ks.l_norm;
    }
    for (int i = 0; i < l->n_local && i < HFS_MAX_LOCAL_LIGHTS; ++i)
        if (hfs_local_light_contributes(&l->local[i]))
            fr->local[fr->n_local++] = l->local[i];
    fr->rho_pi = l->albedo / PI;
    fr->bounces = l->bounces;
    fr->capped = hfs_bounce_capped(l, q);
    fr->albedo = l->albedo_map;
    hfs_gloss_make(l, &fr->gloss);
    fr->l = l;
    if (fr->has_env) {
        hfs_env_rotated(l, fr->l_env);
        fr->env_map = !l->env_open ? 0 : q->visibility == HFS_VIS_SLICE && l->env_shade_map ? 2 : 1;
        fr->gloss_map = fr->gloss.on && fr->env_map > 0 && l->env_shade_map != NULL;
    }
}

static void frame_free(hfs_gles_frame *fr)
{
    for (int q = 0; q < fr->n_keys; ++q)
        hfs_visibility_destroy(fr->keys[q].vis);
    fr->n_keys = 0;
}

static void report_timings(hfs_gles *g, double t_start)
{
    hfs_timings *t = &g->last;
    hfs_gles_timing_report(&g->timing, t);
    t->texture_bytes = hfs_gles_resources_bytes(&g->r) + g->wedge.bytes +
                       g->env_swath_tex.bytes + g->key_swath_tex.bytes + g->keys_tex.bytes +
                       g->local_tex.bytes + g->albedo.bytes + g->bounce.bytes +
                       g->envmap.bytes;
    snprintf(t->method, sizeof t->method, "%s",
             g->timing.use_queries ? "timer-query" : "finish-clock");
    snprintf(t->device, sizeof t->device, "%s (%s)", hfs_gl_context_describe(g->ctx),
             g->caps.profile);
    t->frame_ms = hfs_gles_now_ms() - t_start;
}

/* backends.h */
int hfs_gles_max_side(hfs_gles *g, const hfs_quality *q, char *limit, size_t n)
{
    hfs_error ignored;
    if (hfs_gles_select_caps(g, q, &ignored))
        return 0;
    const int m = g->caps.max_texture_size;
    if (m < HFS_GLES_MAX_FRAME_SIDE) {
        hfs_gl_caps_texture_limit(&g->caps, limit, n);
        return m;
    }
    snprintf(limit, n, "the GLES frame's limit %d (its textures grow with the field)",
             HFS_GLES_MAX_FRAME_SIDE);
    return HFS_GLES_MAX_FRAME_SIDE;
}

/* A frame the device cannot hold: for a field past the ES 3.0 minimum
 * (2048 texels, what every device renders), the message says the way
 * out. */
static int way_out(const hfs_field *f, hfs_error *err)
{
    if (err && (f->width > 2048 || f->height > 2048)) {
        const size_t n = strlen(err->msg);
        snprintf(err->msg + n, sizeof err->msg - n, " (a %dx%d field: the cpu backend renders "
                 "any size; the GIS rasters come in tiles)", f->width, f->height);
    }
    return HFS_E_UNSUPPORTED;
}

/* One frame, with a view from cam when cam is not NULL, into the lit
 * texture instead of out when lit is not NULL. */
static int render_frame(hfs_gles *g, const hfs_field *f, const hfs_lighting *l,
                        const hfs_quality *q, hfs_image *out, const hfs_camera *cam,
                        const hfs_object_set *obj, int w, int h, float *view,
                        const hfs_lit_texture_desc *lit, hfs_error *err)
{
    const double t_start = hfs_gles_now_ms();
    int rc = hfs_gl_context_make_current(g->ctx, err);
    if (rc)
        return rc;
    hfs_gles_timing_reset(&g->timing);
    memset(&g->last, 0, sizeof g->last);
    g->stats.terrain_recomputed = 0;
    g->stats.env_recomputed = 0;

    static const hfs_gles_frame empty;
    hfs_gles_frame fr = empty;
    fr.f = f, fr.q = q, fr.out = out;
    fr.cam = cam, fr.view_w = w, fr.view_h = h, fr.view_rgb = view, fr.objects = obj;
    fr.lit = lit;
    frame_lights(l, q, &fr);
    /* A black field still has a view (its sky): that frame runs. */
    if (!cam && ((!fr.has_env && fr.n_keys == 0 && fr.n_local == 0) || !(l->albedo > 0.0 || fr.gloss.on))) {
        /* Black without a pass; the planner keeps the last lit frame's state
         * (its image is still right for that scene). */
        g->plan.black = 1;
        if (lit) /* but not its texture, which is now black */
            return hfs_gles_lit_texture_black(g, f->width, f->height, lit, err);
        memset(out->rgb, 0, (size_t)out->width * out->height * 3 * sizeof *out->rgb);
        return HFS_OK;
    }
    rc = hfs_gles_frame_render(g, &fr, err);
    frame_free(&fr);
    if (rc) {
        /* A failed frame may have left partial results: recompute next time. */
        g->terrain_valid = 0;
        hfs_gles_plan_drop_all(&g->plan);
        for (int i = 0; i < 16 && g->gl.GetError() != GL_NO_ERROR; ++i)
            ;
        return rc == HFS_E_UNSUPPORTED ? way_out(f, err) : rc;
    }
    hfs_gles_timing_collect(&g->timing, &g->gl);
    snprintf(g->stats.profile, sizeof g->stats.profile, "%s", g->caps.profile);
    g->stats.fp32 = g->caps.fp32;
    if (g->timing.level)
        report_timings(g, t_start);
    return HFS_OK;
}

int hfs_gles_render(hfs_gles *g, const hfs_field *f, const hfs_lighting *l,
                    const hfs_quality *q, hfs_image *out, hfs_error *err)
{
    return render_frame(g, f, l, q, out, NULL, NULL, 0, 0, NULL, NULL, err);
}

int hfs_gles_render_texture(hfs_gles *g, const hfs_field *f, const hfs_lighting *l,
                            const hfs_quality *q, const hfs_lit_texture_desc *how,
                            hfs_lit_texture *out, hfs_error *err)
{
    if (!g->shared)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "render texture: the renderer was made "
                        "without egl_share_context (its texture would be in no context of "
                        "the application's)");
    int rc = render_frame(g, f, l, q, NULL, NULL, NULL, 0, 0, NULL, how, err);
    return rc ? rc : hfs_gles_lit_texture_hand_out(g, out, err);
}

int hfs_gles_render_view(hfs_gles *g, const hfs_field *f, const hfs_lighting *l,
                         const hfs_quality *q, const hfs_camera *cam,
                         const hfs_object_set *obj, int w, int h, hfs_image *out, float *view,
                         hfs_error *err)
{
    return render_frame(g, f, l, q, out, cam, obj, w, h, view, NULL, err);
}
