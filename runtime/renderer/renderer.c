/*
 * renderer.c — the public renderer object: validates every input
 * (validate.c) and dispatches to a backend (backends.h) through one table
 * of backend operations.  Backends may assume valid inputs.  The heights
 * are scanned once per change when the caller names their changes
 * (hfs_renderer_set_field_serial); an environment map's pixels only for
 * the backend that reads them (the truth).
 */
#include "backend_ops.h"
#include "tiled_render.h"
#include "truth_view.h"
#include "validate.h"
#include "view_params.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>


/* The heights last found finite, under the caller's serial (see
 * hfs_renderer_set_field_serial): the same pointer, size and serial are the
 * same heights, so their scan is not repeated. */
typedef struct checked_heights {
    const float *z;
    int width, height;
    uint64_t serial;         /* 0: none checked */
} checked_heights;

struct hfs_renderer {
    const backend_ops *ops;
    void *state;             /* the backend's own object (NULL if it has none) */
    int timing;
    hfs_timings timings;     /* backends without timings of their own: the last timed frame */
    uint64_t field_serial;   /* the caller's serial of the heights; 0: unknown */
    checked_heights checked;
};

static double wall_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

int hfs_renderer_create(const hfs_renderer_desc *desc, hfs_renderer **out, hfs_error *err)
{
    *out = NULL;
    hfs_backend b = desc ? desc->backend : HFS_BACKEND_DEFAULT;
    if (b == HFS_BACKEND_DEFAULT)
        b = HFS_BACKEND_GLES; /* the product */
    if (!hfs_backend_ops(b))
        return hfs_fail(err, HFS_E_INVALID, "backend %d: unknown", (int)b);
    hfs_renderer *r = calloc(1, sizeof *r);
    if (!r)
        return hfs_fail(err, HFS_E_NOMEM, "renderer: out of memory");
    r->ops = hfs_backend_ops(b);
    if (r->ops->create) {
        const int rc = r->ops->create(desc, &r->state, err);
        if (rc) {
            free(r);
            return rc;
        }
    }
    *out = r;
    return HFS_OK;
}

void hfs_renderer_destroy(hfs_renderer *r)
{
    if (!r)
        return;
    if (r->ops->destroy)
        r->ops->destroy(r->state);
    free(r);
}

const char *hfs_renderer_backend_name(const hfs_renderer *r)
{
    return r->ops->name;
}

int hfs_renderer_set_timing(hfs_renderer *r, int level)
{
    if (!r || level < 0 || level > 2)
        return HFS_E_INVALID;
    r->timing = level;
    if (r->ops->set_timing)
        r->ops->set_timing(r->state, level);
    return HFS_OK;
}

int hfs_renderer_set_amortize(hfs_renderer *r, int passes_per_frame)
{
    if (!r || passes_per_frame < 0)
        return HFS_E_INVALID;
    if (r->ops->set_amortize)
        r->ops->set_amortize(r->state, passes_per_frame);
    return HFS_OK;
}

int hfs_renderer_set_timing_finish(hfs_renderer *r, int finish)
{
    if (!r || finish < 0 || finish > 1)
        return HFS_E_INVALID;
    if (r->ops->set_timing_finish)
        r->ops->set_timing_finish(r->state, finish);
    return HFS_OK;
}

int hfs_renderer_timings(const hfs_renderer *r, hfs_timings *out)
{
    if (!r || !out)
        return HFS_E_INVALID;
    if (r->ops->timings)
        r->ops->timings(r->state, out);
    else
        *out = r->timings;
    return HFS_OK;
}

void hfs_renderer_invalidate(hfs_renderer *r)
{
    if (!r)
        return;
    r->checked = (checked_heights){0};
    if (r->ops->invalidate)
        r->ops->invalidate(r->state);
}

void hfs_renderer_set_field_serial(hfs_renderer *r, uint64_t serial)
{
    if (r)
        r->field_serial = serial;
}

int hfs_renderer_frame_report(const hfs_renderer *r, hfs_frame_report *out)
{
    if (!r || !out)
        return HFS_E_INVALID;
    if (r->ops->frame_report) {
        r->ops->frame_report(r->state, out);
        return HFS_OK;
    }
    memset(out, 0, sizeof *out);
    out->n_steps = out->n_ran = 1;
    snprintf(out->step[0].pass, sizeof out->step[0].pass, "render");
    out->step[0].ran = 1;
    snprintf(out->step[0].reason, sizeof out->step[0].reason,
             "%s backend: every frame from scratch", hfs_renderer_backend_name(r));
    return HFS_OK;
}

/* Defence in depth: a backend bug must never leak NaN/Inf to an output. */
static int check_output(const hfs_image *out, const char *who, hfs_error *err)
{
    const size_t n = (size_t)out->width * (size_t)out->height * 3;
    for (size_t i = 0; i < n; ++i)
        if (!isfinite(out->rgb[i]))
            return hfs_fail(err, HFS_E_INVALID, "backend %s: produced a non-finite value at %zu (bug)", who, i / 3);
    return HFS_OK;
}

/* Validates a frame's inputs; the heights only when they are not the ones
 * last found finite under the current serial. */
static int validate_frame(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l,
                          const hfs_quality *q, hfs_error *err)
{
    const checked_heights now = {f ? f->z : NULL, f ? f->width : 0, f ? f->height : 0,
                                 r->field_serial};
    const int known = now.serial != 0 && now.z == r->checked.z && now.width == r->checked.width &&
                      now.height == r->checked.height && now.serial == r->checked.serial;
    const int rc = hfs_validate_frame_inputs(f, l, q, !known, r->ops->reads_env_map, err);
    if (!rc && !known && now.serial != 0)
        r->checked = now;
    return rc;
}

/* A backend without its own timings is timed as one pass by the wall
 * clock, from t0 (ms). */
static void wall_timings(hfs_renderer *r, const char *pass, double t0)
{
    hfs_timings *t = &r->timings;
    memset(t, 0, sizeof *t);
    t->n_passes = 1;
    snprintf(t->pass[0].name, sizeof t->pass[0].name, "%s", pass);
    t->pass[0].ms = t->gpu_ms = t->frame_ms = wall_ms() - t0;
    t->pass[0].fetches = -1.0;
    snprintf(t->method, sizeof t->method, "wall");
    snprintf(t->device, sizeof t->device, "%s", r->ops->name);
}

/* One tile's frame (tiled_render.h): the backend's own, its inputs valid
 * as the whole field's were. */
typedef struct tile_frame_ctx {
    hfs_renderer *r;
    const hfs_quality *q;
} tile_frame_ctx;

static int tile_frame(void *ctx, const hfs_field *f, const hfs_lighting *l, hfs_image *out,
                      hfs_error *err)
{
    const tile_frame_ctx *c = ctx;
    return c->r->ops->render(c->r->state, f, l, c->q, out, NULL, NULL, err);
}

int hfs_renderer_render(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l,
                        const hfs_quality *q, hfs_image *out, hfs_progress_fn progress,
                        void *user, hfs_error *err)
{
    int rc = validate_frame(r, f, l, q, err);
    if (rc)
        return rc;
    if (!out || !out->rgb || out->width != f->width || out->height != f->height)
        return hfs_fail(err, HFS_E_INVALID, "render: output image is not %dx%d", f->width, f->height);
    const double t0 = wall_ms();
    /* Every ES 3.0 device holds a 2048-texel frame: only a larger field asks
     * the backend (a context bound, its caps selected), off the kiosk's
     * per-frame path. */
    char limit[200] = "";
    const int side = r->ops->max_side && (f->width > HFS_TILE_MIN_SIDE ||
                                          f->height > HFS_TILE_MIN_SIDE)
                         ? r->ops->max_side(r->state, q, limit, sizeof limit)
                         : 0;
    if (side > 0 && (f->width > side || f->height > side)) {
        tile_frame_ctx ctx = {r, q};
        rc = hfs_tiled_render(f, l, side, limit, tile_frame, &ctx, out, err);
        if (!rc && progress)
            progress(user, 1.0);
    } else {
        rc = r->ops->render(r->state, f, l, q, out, progress, user, err);
    }
    if (rc)
        return rc;
    if (r->timing && !r->ops->timings)
        wall_timings(r, "render", t0);
    return check_output(out, r->ops->name, err);
}

/* The encoding asked for, checked, with its defaults filled in. */
static int lit_desc(const hfs_lit_texture_desc *how, hfs_lit_texture_desc *d, hfs_error *err)
{
    *d = how ? *how : (hfs_lit_texture_desc){HFS_LIT_RADIANCE, 0.0, 0};
    if (d->encoding != HFS_LIT_RADIANCE && d->encoding != HFS_LIT_SRGB8)
        return hfs_fail(err, HFS_E_INVALID, "render texture: encoding %d is unknown (0 "
                        "radiance, 1 srgb8)", (int)d->encoding);
    if (d->exposure == 0.0)
        d->exposure = 1.0;
    if (!(d->exposure > 0.0) || !isfinite(d->exposure))
        return hfs_fail(err, HFS_E_INVALID, "render texture: exposure %g must be positive "
                        "and finite", d->exposure);
    if (d->tonemap < 0 || d->tonemap > 2)
        return hfs_fail(err, HFS_E_INVALID, "render texture: tonemap %d is unknown (0 clamp, "
                        "1 reinhard, 2 hue)", d->tonemap);
    return HFS_OK;
}

int hfs_renderer_render_texture(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l,
                                const hfs_quality *q, const hfs_lit_texture_desc *how,
                                hfs_lit_texture *out, hfs_error *err)
{
    if (!r || !out)
        return hfs_fail(err, HFS_E_INVALID, "render texture: no %s", r ? "output" : "renderer");
    *out = (hfs_lit_texture){0};
    hfs_lit_texture_desc d;
    int rc = validate_frame(r, f, l, q, err);
    if (rc || (rc = lit_desc(how, &d, err)))
        return rc;
    if (!r->ops->render_texture)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "render texture: the %s backend has no GL "
                        "texture (GLES only)", r->ops->name);
    rc = r->ops->render_texture(r->state, f, l, q, &d, out, err);
    if (rc)
        *out = (hfs_lit_texture){0};
    return rc;
}

int hfs_render_unshadowed(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                          hfs_image *out, hfs_error *err)
{
    int rc = hfs_validate_inputs(f, l, q, err);
    if (rc)
        return rc;
    if (!out || !out->rgb || out->width != f->width || out->height != f->height)
        return hfs_fail(err, HFS_E_INVALID, "render: output image is not %dx%d", f->width, f->height);
    rc = hfs_unshadowed_render(f, l, q, out, err);
    if (rc)
        return rc;
    return check_output(out, "unshadowed", err);
}

/* The view's objects lit (objects.h): key lights through shadow height
 * maps (exact rays on the truth), then their boxes moved into the view's
 * world (z times the exaggeration, as the terrain's). */
static int light_objects(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l,
                         const hfs_quality *q, const hfs_view *v, hfs_object_set *s,
                         hfs_error *err)
{
    int rc = hfs_objects_check(f, v->objects, v->n_objects, err);
    if (rc || (rc = hfs_objects_make(f, v->objects, v->n_objects, s, err)))
        return rc;
    const size_t n = (size_t)s->n * 6 * HFS_OBJ_VERTS;
    double *xyz = malloc(n * 3 * sizeof *xyz);
    float *vis = malloc((n * (size_t)l->n_key + 1) * sizeof *vis);
    if (!xyz || !vis)
        rc = hfs_fail(err, HFS_E_NOMEM, "objects: out of memory");
    if (!rc && l->n_key > 0) {
        hfs_objects_query_points(s, f, xyz);
        /* The truth's exact rays; else the shadow height maps built on the
         * CPU, O(W H) a layer: for a few thousand vertices cheaper than
         * the GPU's passes and their read-back (the same maps to fp16's
         * hi + lo: BENCHMARKS.md "Shadow height maps"). */
        rc = !strcmp(r->ops->name, "truth") ? r->ops->query_points(r->state, f, l, q, xyz, (int)n, vis, err)
                                            : hfs_cpu_query_points(f, l, q, xyz, (int)n, vis, err);
    }
    if (!rc)
        rc = hfs_objects_light(s, f, l, q, vis, err);
    for (int b = 0; b < s->n && !rc; ++b)
        s->box[b][2] *= v->exaggeration, s->box[b][5] *= v->exaggeration;
    free(xyz);
    free(vis);
    if (rc)
        hfs_objects_free(s);
    return rc;
}

/* The view of the lit image: the backend's own, or the ray-cast one. */
static int render_view(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l,
                       const hfs_quality *q, const hfs_camera *cam, const hfs_view *v,
                       const hfs_object_set *obj, hfs_image *lit, hfs_image *out,
                       hfs_error *err)
{
    if (r->ops->render_view)
        return r->ops->render_view(r->state, f, l, q, cam, obj, v->width, v->height, lit,
                                   out->rgb, err);
    int rc = r->ops->render(r->state, f, l, q, lit, NULL, NULL, err);
    if (!rc)
        rc = check_output(lit, r->ops->name, err);
    return rc ? rc : hfs_truth_view(f, lit->rgb, l, cam, obj, v->width, v->height, out->rgb,
                                    q->threads, err);
}

/* Glossy surfaces are seen from the camera: an ortho view's direction
 * towards it for every texel, a perspective view's eye for each texel's
 * own view vector (the lighting products stay on the grid; the view
 * resamples them).  The view's exaggeration scales z for display only, so
 * the viewer is mapped back into the lighting's space, z / exaggeration
 * (an affine map of the whole scene: the surface the lighting sees, looked
 * at from where the camera stands in it). */
static void glossy_viewer(const hfs_camera *cam, hfs_lighting *seen)
{
    hfs_camera_frame fr;
    hfs_camera_frame_make(cam, &fr);
    if (cam->ortho) {
        const double d[3] = {-fr.forward[0], -fr.forward[1], -fr.forward[2] / cam->exaggeration};
        const double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (int k = 0; k < 3; ++k)
            seen->view_dir[k] = d[k] / len;
        return;
    }
    seen->view_from_eye = 1;
    seen->view_eye[0] = fr.eye[0];
    seen->view_eye[1] = fr.eye[1];
    seen->view_eye[2] = fr.eye[2] / cam->exaggeration;
}

int hfs_renderer_render_view(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l,
                             const hfs_quality *q, const hfs_view *v, hfs_image *lit,
                             hfs_image *out, hfs_error *err)
{
    int rc = validate_frame(r, f, l, q, err);
    if (rc || (rc = hfs_view_check(v, err)))
        return rc;
    if (!out || !out->rgb || out->width != v->width || out->height != v->height)
        return hfs_fail(err, HFS_E_INVALID, "render: view image is not %dx%d", v->width,
                        v->height);
    if (lit && (!lit->rgb || lit->width != f->width || lit->height != f->height))
        return hfs_fail(err, HFS_E_INVALID, "render: output image is not %dx%d", f->width,
                        f->height);
    hfs_image own = {0};
    if (!lit && (rc = hfs_image_alloc(&own, f->width, f->height, err)))
        return rc;
    hfs_camera cam;
    hfs_view_camera(v, &cam);
    hfs_view_look_make(v, f, l, &cam.look);
    hfs_lighting seen = *l;
    if (l->specular > 0.0)
        glossy_viewer(&cam, &seen);
    const double t0 = wall_ms();
    hfs_object_set obj = {0};
    if (v->n_objects != 0)
        rc = light_objects(r, f, l, q, v, &obj, err);
    if (!rc)
        rc = render_view(r, f, &seen, q, &cam, v, obj.n > 0 ? &obj : NULL, lit ? lit : &own, out,
                         err);
    hfs_objects_free(&obj);
    if (!rc && r->timing && !r->ops->timings)
        wall_timings(r, "render+view", t0);
    if (!rc)
        rc = check_output(lit ? lit : &own, r->ops->name, err);
    if (!rc)
        rc = check_output(out, r->ops->name, err);
    hfs_image_free(&own);
    return rc;
}

int hfs_renderer_query_points(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l,
                              const hfs_quality *q, const double *xyz, int n, float *vis,
                              hfs_error *err)
{
    int rc = validate_frame(r, f, l, q, err);
    if (rc)
        return rc;
    if (n < 0 || (n > 0 && (!xyz || !vis)))
        return hfs_fail(err, HFS_E_INVALID, "query: %d points without their arrays", n);
    const double xmax = (f->width - 1) * f->dx, ymax = (f->height - 1) * f->dx;
    for (int i = 0; i < n; ++i) {
        const double *p = xyz + 3 * (size_t)i;
        if (!(isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2])))
            return hfs_fail(err, HFS_E_INVALID, "query: point %d is not finite", i + 1);
        if (!(p[0] >= 0.0 && p[0] <= xmax && p[1] >= 0.0 && p[1] <= ymax))
            return hfs_fail(err, HFS_E_INVALID, "query: point %d (%g, %g) is not over the field "
                            "([0, %g] x [0, %g])", i + 1, p[0], p[1], xmax, ymax);
    }
    return n > 0 && l->n_key > 0 ? r->ops->query_points(r->state, f, l, q, xyz, n, vis, err)
                                 : HFS_OK;
}

int hfs_renderer_shadow_height_map(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l,
                                   const hfs_quality *q, int key, int layer, float *out,
                                   hfs_error *err)
{
    int rc = validate_frame(r, f, l, q, err);
    if (rc)
        return rc;
    if (key < 0 || key >= l->n_key || layer < 0 || layer >= HFS_SHM_LAYERS || !out)
        return hfs_fail(err, HFS_E_INVALID, "shadow height map: key light %d of %d, layer %d "
                        "of %d%s", key + 1, l->n_key, layer, HFS_SHM_LAYERS,
                        out ? "" : ", no output array");
    if (!r->ops->shadow_map)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "shadow height map: the %s backend has none "
                        "(it answers points by exact rays)", r->ops->name);
    return r->ops->shadow_map(r->state, f, &l->key[key], q, layer, out, err);
}

/* out[k] = clamp(out[k], lo, hi) (a ray that met no terrain,
 * HFS_HORIZON_NONE = -pi/2, becomes lo): the same numbers from every
 * backend, whichever part of the search it skipped. */
static void clamp_to_window(const hfs_horizon_desc *d, float *out, size_t n)
{
    const float lo = (float)d->lo, hi = (float)d->hi;
    for (size_t k = 0; k < n; ++k)
        out[k] = fminf(fmaxf(out[k], lo), hi);
}

int hfs_renderer_horizons(hfs_renderer *r, const hfs_field *f, const hfs_quality *q,
                          const hfs_horizon_desc *d, float *out, hfs_error *err)
{
    hfs_lighting none;
    hfs_lighting_defaults(&none);
    hfs_quality own;
    if (!q)
        hfs_quality_defaults(&own);
    int rc = validate_frame(r, f, &none, q ? q : &own, err);
    if (!rc)
        rc = hfs_validate_horizon_desc(d, out, err);
    if (!rc)
        rc = r->ops->horizons(r->state, f, q ? q : &own, d, out, err);
    if (!rc && d->window) /* the backends only skip what the window leaves out */
        clamp_to_window(d, out, (size_t)d->n_azimuths * (size_t)f->width * (size_t)f->height);
    return rc;
}
