/*
 * kiosk_frame.c — one frame: render, picture, overlay, present.
 *
 * The renderer plans each frame (runtime/core/frame_plan.h): after a key-light
 * knob only that light's passes and the shading run; after an overlay
 * toggle none.  So the kiosk simply renders the whole scene every time
 * something changed and lets the planner decide what work that is.
 *
 * Buffers (linear image, RGBA8 picture) are allocated once and reused; a
 * reload to a field of another size reallocates them.
 *
 * Validation: a world's heights are checked once, when it loads; every
 * render names them by the world's serial (hfs_renderer_set_field_serial),
 * so no frame scans them again.
 */
#include "kiosk.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "frame_image.h"
#include "overlay.h"

/* A renderer for the scene; a GLES one shares the display's context when
 * f has the display's handles (f NULL: an off-screen one of its own). */
static int make_renderer(const kiosk_frame *f, const hfs_scene *s, hfs_renderer **out,
                         hfs_error *err)
{
    hfs_renderer_desc desc = {.backend = s->backend,
                              .context = s->context[0] ? s->context : NULL};
    if (f && f->egl_context && (s->backend == HFS_BACKEND_DEFAULT ||
                                s->backend == HFS_BACKEND_GLES)) {
        desc.egl_display = f->egl_display;
        desc.egl_share_context = f->egl_context;
    }
    return hfs_renderer_create(&desc, out, err);
}

static int shares(const kiosk_frame *f, const hfs_scene *s)
{
    return f->egl_context && (s->backend == HFS_BACKEND_DEFAULT || s->backend == HFS_BACKEND_GLES);
}

int kiosk_frame_init(kiosk_frame *f, const hfs_scene *s, double exposure, hfs_display *d,
                     hfs_error *err)
{
    memset(f, 0, sizeof *f);
    f->auto_exposure = !(exposure > 0.0);
    f->exposure = f->auto_exposure ? 1.0 : exposure;
    f->ev = f->target_ev = NAN;
    f->backend = s->backend;
    snprintf(f->context, sizeof f->context, "%s", s->context);
    hfs_display_gl_handles(d, &f->egl_display, &f->egl_context);
    f->shared = shares(f, s);
    return make_renderer(f, s, &f->renderer, err);
}

int kiosk_frame_renderer_for(const kiosk_frame *f, const hfs_scene *s, hfs_renderer **out,
                             hfs_error *err)
{
    *out = NULL;
    if (s->backend == f->backend && !strcmp(s->context, f->context))
        return HFS_OK;
    return make_renderer(f, s, out, err);
}

void kiosk_frame_adopt(kiosk_frame *f, hfs_renderer *r, const hfs_scene *s)
{
    if (!r)
        return;
    hfs_renderer_destroy(f->renderer);
    f->renderer = r;
    hfs_renderer_set_amortize(r, f->amortize);
    f->backend = s->backend;
    snprintf(f->context, sizeof f->context, "%s", s->context);
    f->shared = shares(f, s);
}

int kiosk_frame_admit(hfs_renderer *r, int amortize, const hfs_scene *s,
                      const hfs_scene_inputs *in, hfs_error *err)
{
    hfs_renderer *own = NULL;
    int rc = r ? HFS_OK : make_renderer(NULL, s, &own, err);
    if (rc)
        return rc;
    hfs_renderer *use = r ? r : own;
    hfs_image img = {0};
    hfs_renderer_set_amortize(use, 0); /* the whole frame must work */
    rc = hfs_image_alloc(&img, in->field.width, in->field.height, err);
    hfs_renderer_set_field_serial(use, in->serial);
    if (!rc)
        rc = hfs_renderer_render(use, &in->field, &in->lighting, &in->quality, &img, NULL, NULL,
                                 err);
    if (rc)
        hfs_renderer_invalidate(use);
    if (r)
        hfs_renderer_set_amortize(r, amortize);
    hfs_image_free(&img);
    hfs_renderer_destroy(own);
    return rc;
}

void kiosk_frame_free(kiosk_frame *f)
{
    hfs_renderer_destroy(f->renderer);
    hfs_image_free(&f->img);
    hfs_image_free(&f->small);
    hfs_image_free(&f->lit);
    free(f->rgba);
    kiosk_map_free(f->map);
    f->renderer = NULL;
    f->rgba = NULL;
    f->map = NULL;
}

int kiosk_frame_map(kiosk_frame *f, const hfs_scene_inputs *in, hfs_input_state *st, int dw,
                    int dh, int keep, hfs_error *err)
{
    const int w = in->field.width, h = in->field.height;
    kiosk_map_free(f->map);
    f->map = NULL;
    f->prefetching = 0;
    const int levels = dw > 0 && dh > 0 ? kiosk_map_levels_for(w, h, dw, dh) : 1;
    keep = keep && st->map_levels == levels && st->map_w == w && st->map_h == h;
    st->map_levels = 0;
    if (levels == 1)
        return HFS_OK;
    const int rc = kiosk_map_create(in, dw, dh, &f->map, err);
    if (rc)
        return rc;
    st->map_levels = levels, st->map_w = w, st->map_h = h;
    if (!keep) { /* the whole field, centred */
        st->map_x = 0.5 * w, st->map_y = 0.5 * h;
        st->map_level = levels - 1;
    }
    return HFS_OK;
}

int kiosk_frame_prefetch(kiosk_frame *f, const hfs_scene_inputs *in, hfs_error *err)
{
    if (!f->map || !f->prefetching)
        return HFS_OK;
    hfs_renderer_set_amortize(f->renderer, 0); /* a tile is kept: lit whole */
    const int rc = kiosk_map_prefetch(f->map, f->renderer, in, err);
    hfs_renderer_set_amortize(f->renderer, f->amortize);
    f->prefetching = rc > 0;
    return rc;
}

/* The render (w x h) and the picture: a field larger than any display's
 * side is shown shrunk by an integer factor, averaged in linear light (a
 * 4096^2 DEM is shown at 2048^2 instead of failing its first frame). */
static int ensure_buffers(kiosk_frame *f, int w, int h, hfs_error *err)
{
    if (f->img.rgb && f->img.width == w && f->img.height == h)
        return HFS_OK;
    hfs_image_free(&f->img);
    hfs_image_free(&f->small);
    free(f->rgba);
    f->shrink = hfs_shrink_factor(w, h, HFS_DISPLAY_MAX_SIDE);
    const int pw = (w + f->shrink - 1) / f->shrink, ph = (h + f->shrink - 1) / f->shrink;
    f->rgba = malloc((size_t)pw * (size_t)ph * 4);
    if (!f->rgba)
        return hfs_fail(err, HFS_E_NOMEM, "frame %dx%d: out of memory", w, h);
    int rc = hfs_image_alloc(&f->img, w, h, err);
    if (!rc && f->shrink > 1)
        rc = hfs_image_alloc(&f->small, pw, ph, err);
    if (rc)
        hfs_image_free(&f->img); /* allocated again next time */
    return rc;
}

/* "12.3 ms  3/11 passes  kiosk": the render's wall time and what the
 * planner ran, so an operator sees at once whether a knob costs a full
 * frame or a few passes. */
static void draw_overlay(kiosk_frame *f, const char *preset)
{
    char text[96];
    int n = snprintf(text, sizeof text, "%.1f ms %d/%d passes %s", f->render_ms, f->passes_ran,
                     f->passes_total, preset && preset[0] ? preset : "kiosk");
    if (f->map && n > 0 && (size_t)n < sizeof text) { /* the map's level, tiles lit now */
        kiosk_map_stats ms;
        kiosk_map_stats_get(f->map, &ms);
        snprintf(text + n, sizeof text - (size_t)n, " L%d %d tiles %d coarse", ms.level,
                 ms.rendered, ms.coarse);
    }
    const hfs_image *pic = f->shrink > 1 ? &f->small : &f->img;
    const int w = pic->width, h = pic->height;
    const int scale = w >= 480 ? 2 : 1;
    hfs_overlay_label(f->rgba, w, h, 2, 2, scale, text); /* readable on white and black */
}

hfs_view kiosk_view_camera(const hfs_input_state *st, const hfs_field *field, int w, int h,
                           int panel)
{
    const double deg = 3.14159265358979323846 / 180.0;
    hfs_view v;
    hfs_view_defaults(&v, field);
    v.mode = HFS_VIEW_PERSPECTIVE;
    v.azimuth = st->cam_azimuth * deg;
    v.elevation = st->cam_elevation * deg;
    v.fov = 40.0 * deg;
    v.width = w, v.height = h;
    hfs_view_frame(&v, field);
    v.distance *= st->cam_zoom;
    v.background = panel ? HFS_BACKGROUND_STUDIO : HFS_BACKGROUND_SKY;
    v.haze = panel ? 0.0 : HFS_HAZE_AUTO;
    return v;
}

/* The lit grid the 3-D view and the texture path meter, at the field's
 * size. */
static int fit_lit(kiosk_frame *f, const hfs_field *field, hfs_error *err)
{
    if (f->lit.rgb && f->lit.width == field->width && f->lit.height == field->height)
        return HFS_OK;
    hfs_image_free(&f->lit);
    return hfs_image_alloc(&f->lit, field->width, field->height, err);
}

/* A new target for the automatic exposure: the terrain's median at middle
 * grey (hfs_exposure_auto); the first one is taken at once. */
static void meter(kiosk_frame *f, const hfs_image *terrain)
{
    f->target_ev = log2(hfs_exposure_auto(terrain));
    f->metered_ns = hfs_input_now_ns();
}

/* The exposure this frame is shown at: fixed (--exposure EV), or the
 * smoothed one stepped towards the last target; settling while it is more
 * than 1/64 stop (invisible in 8 bits) away from it. */
static void step_exposure(kiosk_frame *f)
{
    if (!f->auto_exposure || isnan(f->target_ev))
        return;
    const int64_t now = hfs_input_now_ns();
    f->ev = isnan(f->ev) ? f->target_ev
                         : hfs_exposure_smooth(f->ev, f->target_ev, (double)(now - f->ev_ns) / 1e9,
                                               HFS_KIOSK_EXPOSURE_TAU);
    f->ev_ns = now;
    f->settling = fabs(f->target_ev - f->ev) > 1.0 / 64.0;
    f->exposure = exp2(f->ev);
}

/* The frame's image into f->img: the grid dump, or the 3-D view. */
static int render(kiosk_frame *f, const hfs_scene_inputs *in, const hfs_input_state *st,
                  const char *preset, hfs_error *err)
{
    const int view = st->view;
    int w = view ? f->view_w : in->field.width, h = view ? f->view_h : in->field.height;
    if (f->map && !view)
        kiosk_map_view_size(f->map, st->map_level, &w, &h);
    int rc = ensure_buffers(f, w, h, err);
    if (rc)
        return rc;
    /* The world's heights never change after loading: their serial spares
     * the renderer a pass over them every frame (the knobs' lighting and
     * quality were validated by kiosk_world_relight; the renderer checks
     * them again, which costs nothing next to a frame). */
    hfs_renderer_set_field_serial(f->renderer, in->serial);
    if (!view && f->map) { /* the map's view: its tiles, lit ahead or now */
        hfs_renderer_set_amortize(f->renderer, 0); /* a tile is kept: lit whole */
        rc = kiosk_map_frame(f->map, f->renderer, in, st->map_x, st->map_y, st->map_level,
                             &f->img, err);
        hfs_renderer_set_amortize(f->renderer, f->amortize);
        f->prefetching = !rc;
        if (!rc && f->auto_exposure)
            meter(f, &f->img);
        return rc;
    }
    if (!view) {
        rc = hfs_renderer_render(f->renderer, &in->field, &in->lighting, &in->quality, &f->img,
                                 NULL, NULL, err);
        if (!rc && f->auto_exposure)
            meter(f, &f->img); /* the grid is all terrain */
        return rc;
    }
    /* A camera move costs the view pass alone (the lighting is kept; the
     * lit grid metered is the renderer's kept read-back). */
    const hfs_view v = kiosk_view_camera(st, &in->field, w, h,
                                         preset && !strcmp(preset, "panel"));
    hfs_image *lit = NULL;
    if (f->auto_exposure && (rc = fit_lit(f, &in->field, err)))
        return rc;
    if (f->auto_exposure)
        lit = &f->lit;
    rc = hfs_renderer_render_view(f->renderer, &in->field, &in->lighting, &in->quality, &v, lit,
                                  &f->img, err);
    if (!rc && lit)
        meter(f, lit);
    return rc;
}

/* A grid frame on a GL display goes to the screen as the renderer's
 * texture (issue 20): the sRGB picture encoded on the GPU (HFS_LIT_SRGB8:
 * hfs_srgb8_encode's bytes, as hfs_frame_to_rgba8 writes them), no
 * read-back and no upload.  Not the 3-D view (its picture comes back to
 * the CPU), nor the overlay (drawn into the picture on the CPU), nor a
 * field shrunk to fit the display (averaged on the CPU). */
static int texture_path(const kiosk_frame *f, const hfs_scene_inputs *in,
                        const hfs_input_state *st)
{
    return f->shared && !st->view && !st->overlay && !f->map &&
           hfs_shrink_factor(in->field.width, in->field.height, HFS_DISPLAY_MAX_SIDE) == 1;
}

/* The texture path meters by a read-back of the lit grid (the planner
 * then runs only the read-back: the frame is shared with the texture), at
 * most this often: a knob turned continuously costs a read-back 4 times a
 * second, not every frame. */
#define KIOSK_METER_NS 250000000LL

static int render_texture(kiosk_frame *f, const hfs_scene_inputs *in, hfs_lit_texture *t,
                          hfs_error *err)
{
    hfs_renderer_set_field_serial(f->renderer, in->serial);
    if (f->auto_exposure && (isnan(f->target_ev) ||
                             hfs_input_now_ns() - f->metered_ns >= KIOSK_METER_NS)) {
        int rc = fit_lit(f, &in->field, err);
        if (!rc)
            rc = hfs_renderer_render(f->renderer, &in->field, &in->lighting, &in->quality,
                                     &f->lit, NULL, NULL, err);
        if (rc)
            return rc;
        meter(f, &f->lit);
    }
    step_exposure(f);
    const hfs_lit_texture_desc how = {HFS_LIT_SRGB8, f->exposure, HFS_TONEMAP_HUE};
    return hfs_renderer_render_texture(f->renderer, &in->field, &in->lighting, &in->quality,
                                       &how, t, err);
}

/* The render as the display's picture: shrunk, encoded, the overlay. */
static int picture(kiosk_frame *f, const char *preset, const hfs_input_state *st,
                   const hfs_image **pic, hfs_error *err)
{
    step_exposure(f);
    hfs_png_opts po = {.exposure = f->exposure, .tonemap = HFS_TONEMAP_HUE};
    *pic = &f->img;
    if (f->shrink > 1) {
        hfs_image_shrink(&f->img, f->shrink, &f->small);
        *pic = &f->small;
    }
    int rc = hfs_frame_to_rgba8(*pic, &po, f->rgba, err);
    if (!rc && st->overlay)
        draw_overlay(f, preset);
    return rc;
}

int kiosk_frame_show(kiosk_frame *f, const hfs_scene_inputs *in, const hfs_input_state *st,
                     const char *preset, hfs_display *d, hfs_error *err)
{
    const int64_t t0 = hfs_input_now_ns();
    const int textured = texture_path(f, in, st);
    hfs_lit_texture t = {0};
    int rc = textured ? render_texture(f, in, &t, err) : render(f, in, st, preset, err);
    if (rc)
        return rc;
    f->render_ms = (double)(hfs_input_now_ns() - t0) / 1e6;
    hfs_frame_report rep;
    if (hfs_renderer_frame_report(f->renderer, &rep) == HFS_OK) {
        f->passes_ran = rep.n_ran;
        f->passes_total = rep.n_steps;
        f->deferred = rep.n_deferred;
    } else {
        f->passes_ran = f->passes_total = f->deferred = 0;
    }
    if (textured) {
        rc = hfs_display_present_texture(d, t.texture, t.fence, t.width, t.height, err);
    } else {
        const hfs_image *pic;
        if (!(rc = picture(f, preset, st, &pic, err)))
            rc = hfs_display_present(d, f->rgba, pic->width, pic->height, err);
    }
    if (rc)
        return rc;
    f->present_ns = hfs_input_now_ns();
    f->presented++;
    return HFS_OK;
}
