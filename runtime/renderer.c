/*
 * renderer.c — the public renderer object: validates every input and
 * dispatches to a backend (backends.h) through one table of backend
 * operations.  Backends may assume valid inputs.  Ranges come from the
 * table of scene keys (scene_keys.h); the heights are scanned once per
 * change when the caller names their changes (hfs_renderer_set_field_serial).
 */
#include "albedo.h"
#include "backends.h"
#include "scene_keys.h"
#include "truth_view.h"
#include "view_params.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* ---- backends as a table (like board/display_backend.h) ---------------------------
 * Every backend is one row: its name, how it is made and destroyed, how it
 * renders, and the GLES-only controls (NULL where a backend has none: the
 * CPU reference and the ground truth render every frame from scratch and
 * are timed here by wall clock). */
typedef struct backend_ops {
    const char *name;
    int (*create)(const hfs_renderer_desc *d, void **state, hfs_error *err); /* NULL: none */
    void (*destroy)(void *state);
    int (*render)(void *state, const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                  hfs_image *out, hfs_progress_fn progress, void *user, hfs_error *err);
    void (*set_timing)(void *state, int level);
    void (*set_amortize)(void *state, int passes_per_frame);
    void (*set_timing_finish)(void *state, int finish);
    void (*timings)(const void *state, hfs_timings *out);
    void (*invalidate)(void *state);
    void (*frame_report)(const void *state, hfs_frame_report *out);
    /* The lit frame and its 3-D view in one go (NULL: the lit image's
     * ray-cast view, hfs_truth_view). */
    int (*render_view)(void *state, const hfs_field *f, const hfs_lighting *l,
                       const hfs_quality *q, const hfs_camera *cam, int w, int h,
                       hfs_image *lit, float *view, hfs_error *err);
    /* Key-light visibility of points (NULL: not yet on this backend). */
    int (*query_points)(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                        const double *xyz, int n, float *vis, hfs_error *err);
} backend_ops;

static int cpu_render(void *state, const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                      hfs_image *out, hfs_progress_fn progress, void *user, hfs_error *err)
{
    (void)state;
    return hfs_cpu_render(f, l, q, out, progress, user, err);
}

static int truth_render(void *state, const hfs_field *f, const hfs_lighting *l,
                        const hfs_quality *q, hfs_image *out, hfs_progress_fn progress, void *user,
                        hfs_error *err)
{
    (void)state;
    return hfs_truth_render(f, l, q, out, progress, user, err);
}

static int gles_create(const hfs_renderer_desc *d, void **state, hfs_error *err)
{
    const char *env = getenv("HFS_GL_STRICT_LIMITS");
    const int strict = (d && d->gl_strict_limits) || (env && !strcmp(env, "1"));
    hfs_gles *g = NULL;
    const int rc = hfs_gles_create(d ? d->context : NULL, d ? d->gl_profile : NULL, strict, &g, err);
    *state = g;
    return rc;
}
static void gles_destroy(void *state) { hfs_gles_destroy(state); }
static int gles_render(void *state, const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                       hfs_image *out, hfs_progress_fn progress, void *user, hfs_error *err)
{
    const int rc = hfs_gles_render(state, f, l, q, out, err);
    if (!rc && progress)
        progress(user, 1.0); /* one GPU frame: no finer progress to report */
    return rc;
}
static void gles_set_timing(void *state, int level) { hfs_gles_set_timing(state, level); }
static void gles_set_amortize(void *state, int n) { hfs_gles_set_amortize(state, n); }
static void gles_set_timing_finish(void *state, int f) { hfs_gles_set_timing_finish(state, f); }
static void gles_timings(const void *state, hfs_timings *out) { hfs_gles_get_timings(state, out); }
static void gles_invalidate(void *state) { hfs_gles_invalidate(state); }
static void gles_frame_report(const void *state, hfs_frame_report *out)
{
    hfs_gles_frame_report(state, out);
}
static int gles_render_view(void *state, const hfs_field *f, const hfs_lighting *l,
                            const hfs_quality *q, const hfs_camera *cam, int w, int h,
                            hfs_image *lit, float *view, hfs_error *err)
{
    return hfs_gles_render_view(state, f, l, q, cam, w, h, lit, view, err);
}

static const backend_ops backends[] = {
    [HFS_BACKEND_GLES] = {"gles", gles_create, gles_destroy, gles_render, gles_set_timing,
                          gles_set_amortize, gles_set_timing_finish, gles_timings,
                          gles_invalidate, gles_frame_report, gles_render_view},
    [HFS_BACKEND_CPU] = {"cpu", NULL, NULL, cpu_render, NULL, NULL, NULL, NULL, NULL, NULL,
                         NULL, hfs_cpu_query_points},
    [HFS_BACKEND_TRUTH] = {"truth", NULL, NULL, truth_render, NULL, NULL, NULL, NULL, NULL,
                           NULL, NULL, hfs_truth_query_points},
};
#define N_BACKENDS ((int)(sizeof backends / sizeof backends[0]))

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
    if ((int)b < 0 || (int)b >= N_BACKENDS || !backends[b].render)
        return hfs_fail(err, HFS_E_INVALID, "backend %d: unknown", (int)b);
    hfs_renderer *r = calloc(1, sizeof *r);
    if (!r)
        return hfs_fail(err, HFS_E_NOMEM, "renderer: out of memory");
    r->ops = &backends[b];
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

/* ---- validation -------------------------------------------------------------------
 * Every range is the table of scene keys' (scene_keys.h), in library units:
 * a value the scene parser accepts passes here, one just outside fails both.
 * Fields without a scene key (counts of lights, enumerations, the truth's
 * elevation order) are checked here alone. */

#define CHECK_LIB(id, i, x, who) hfs_scene_key_check_lib((id), (i), (x), (who), err)

static int check_radiance(hfs_scene_key_id id, int i, const float v[3], const char *who,
                          hfs_error *err)
{
    int rc = HFS_OK;
    for (int c = 0; c < 3 && !rc; ++c)
        rc = CHECK_LIB(id, i, (double)v[c], who);
    return rc;
}

/* Everything about the field but its heights: O(1). */
static int check_field_params(const hfs_field *f, hfs_error *err)
{
    if (!f || !f->z)
        return hfs_fail(err, HFS_E_INVALID, "render: missing field, lighting or quality");
    const hfs_key_range side = hfs_scene_key_lib_range(HFS_SK_SIZE, 0);
    if (f->width < side.lo || f->height < side.lo)
        return hfs_fail(err, HFS_E_INVALID, "height field: %dx%d is smaller than %.0fx%.0f",
                        f->width, f->height, side.lo, side.lo);
    if (f->width > side.hi || f->height > side.hi)
        return hfs_fail(err, HFS_E_INVALID, "height field: %dx%d is larger than %.0fx%.0f",
                        f->width, f->height, side.hi, side.hi);
    int rc = CHECK_LIB(HFS_SK_DX, 0, f->dx, "dx");
    return rc ? rc : CHECK_LIB(HFS_SK_ZSCALE, 0, f->zscale, "zscale");
}

/* The heights: a pass over the whole field. */
static int check_heights(const hfs_field *f, hfs_error *err)
{
    const size_t n = (size_t)f->width * (size_t)f->height;
    for (size_t i = 0; i < n; ++i)
        if (!isfinite(f->z[i]))
            return hfs_fail(err, HFS_E_INVALID, "height field: non-finite height at texel %zu "
                            "(holes must be filled before rendering)", i);
    return HFS_OK;
}

int hfs_validate_field(const hfs_field *f, hfs_error *err)
{
    const int rc = check_field_params(f, err);
    return rc ? rc : check_heights(f, err);
}

static int check_lights(const hfs_lighting *l, hfs_error *err)
{
    char who[32];
    int rc = HFS_OK;
    if (l->n_key < 0 || l->n_key > HFS_MAX_KEY_LIGHTS)
        return hfs_fail(err, HFS_E_INVALID, "key: %d lights (at most %d)", l->n_key, HFS_MAX_KEY_LIGHTS);
    for (int i = 0; i < l->n_key && !rc; ++i) {
        const hfs_key_light *k = &l->key[i];
        snprintf(who, sizeof who, "key light %d", i + 1);
        const double angle[3] = {k->phi, k->elev, k->alpha};
        for (int j = 0; j < 3 && !rc; ++j)
            rc = CHECK_LIB(HFS_SK_KEY, j, angle[j], who);
        if (!rc)
            rc = check_radiance(HFS_SK_KEY, 3, k->radiance, who, err);
    }
    if (!rc && (l->n_local < 0 || l->n_local > HFS_MAX_LOCAL_LIGHTS))
        return hfs_fail(err, HFS_E_INVALID, "local: %d lights (at most %d)", l->n_local, HFS_MAX_LOCAL_LIGHTS);
    for (int i = 0; i < l->n_local && !rc; ++i) {
        const hfs_local_light *o = &l->local[i];
        snprintf(who, sizeof who, "local light %d", i + 1);
        for (int j = 0; j < 3 && !rc; ++j)
            rc = CHECK_LIB(HFS_SK_LOCAL, j, o->pos[j], who);
        if (!rc)
            rc = CHECK_LIB(HFS_SK_LOCAL, 3, o->radius, who);
        if (!rc)
            rc = check_radiance(HFS_SK_LOCAL, 4, o->radiance, who, err);
    }
    return rc;
}

/* Glossy surfaces: specular and gloss in their keys' ranges, albedo +
 * specular <= 1 (the lobe and the Lambertian term share the energy), a
 * unit view direction above the horizon.  gloss and view_dir are checked
 * only when specular > 0: a lighting zeroed by its caller (no
 * hfs_lighting_defaults) stays the valid diffuse one it was. */
static int check_gloss(const hfs_lighting *l, hfs_error *err)
{
    int rc = CHECK_LIB(HFS_SK_SPECULAR, 0, l->specular, "specular");
    if (rc || l->specular == 0.0)
        return rc;
    if (!rc)
        rc = CHECK_LIB(HFS_SK_GLOSS, 0, l->gloss, "gloss");
    if (!rc && !(l->albedo + l->specular <= 1.0 + 1e-12))
        return hfs_fail(err, HFS_E_INVALID, "albedo %g + specular %g is above 1 (energy)",
                        l->albedo, l->specular);
    const double *v = l->view_dir;
    const double len2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    if (!rc && !(fabs(len2 - 1.0) <= 1e-9 && v[2] > 0.0))
        return hfs_fail(err, HFS_E_INVALID, "view-dir: (%g, %g, %g) is not a unit vector above "
                        "the horizon (elevation in (0, 90] degrees)", v[0], v[1], v[2]);
    const double *e = l->view_eye;
    if (!rc && l->view_from_eye && !(isfinite(e[0]) && isfinite(e[1]) && isfinite(e[2])))
        return hfs_fail(err, HFS_E_INVALID, "view eye: (%g, %g, %g) is not a finite point",
                        e[0], e[1], e[2]);
    return rc;
}

/* The environment map (hfshade.h): only with has_env (env_sh is its
 * projection, what every backend but the truth renders), sane sizes,
 * finite values (hfs_envmap_load keeps negative ones).  A pass over the map. */
static int check_env_map(const hfs_lighting *l, hfs_error *err)
{
    if (!l->env_map)
        return HFS_OK;
    const int w = l->env_map_width, h = l->env_map_height;
    if (!l->has_env)
        return hfs_fail(err, HFS_E_INVALID, "env-map: given without has_env (env_sh must hold "
                        "the map's SH projection)");
    if (w < 1 || h < 1 || w > 65536 || h > 65536 || (long long)w * h > (1ll << 28))
        return hfs_fail(err, HFS_E_INVALID, "env-map: size %dx%d out of range (1..65536 per "
                        "side, at most 2^28 pixels)", w, h);
    const size_t n = (size_t)w * (size_t)h * 3;
    for (size_t i = 0; i < n; ++i)
        if (!(fabsf(l->env_map[i]) <= FLT_MAX))
            return hfs_fail(err, HFS_E_INVALID, "env-map: pixel (%zu, %zu) channel %zu is %g "
                            "(must be finite)", i / 3 % (size_t)w, i / 3 / (size_t)w,
                            i % 3, (double)l->env_map[i]);
    return HFS_OK;
}

int hfs_validate_lighting(const hfs_lighting *l, hfs_error *err)
{
    if (!l)
        return hfs_fail(err, HFS_E_INVALID, "render: missing field, lighting or quality");
    int rc = CHECK_LIB(HFS_SK_ALBEDO, 0, l->albedo, "albedo");
    if (!rc)
        rc = CHECK_LIB(HFS_SK_BOUNCES, 0, l->bounces, "bounces");
    for (int c = 0; c < 3 && l->has_env && !rc; ++c)
        for (int k = 0; k < HFS_SH_COEFFS && !rc; ++k)
            rc = CHECK_LIB(HFS_SK_ENV_SH, k, l->env_sh[c][k], "env-sh");
    if (!rc && l->has_env)
        rc = CHECK_LIB(HFS_SK_ENV_ROTATE, 0, l->env_rotate, "env-rotate");
    if (!rc)
        rc = check_env_map(l, err);
    if (!rc)
        rc = check_gloss(l, err);
    return rc ? rc : check_lights(l, err);
}

int hfs_validate_quality(const hfs_quality *q, hfs_error *err)
{
    if (!q)
        return hfs_fail(err, HFS_E_INVALID, "render: missing field, lighting or quality");
    const struct { hfs_scene_key_id id; int value; } counts[] = {
        {HFS_SK_K, q->k}, {HFS_SK_OFFSET, q->offset}, {HFS_SK_NPHI_ENV, q->nphi_env},
        {HFS_SK_NPHI_KEY, q->nphi_key}, {HFS_SK_REFINE, q->refine},
        {HFS_SK_NPHI_BOUNCE, q->nphi_bounce}, {HFS_SK_BOUNCE_REFINE, q->bounce_refine},
        {HFS_SK_BOUNCE_SUBSAMPLE, q->bounce_subsample},
        {HFS_SK_NPHI_LOCAL, q->nphi_local},
        {HFS_SK_SUBSAMPLE, q->subsample}, {HFS_SK_THREADS, q->threads},
        {HFS_SK_TRUTH_AZIMUTHS, q->truth_azimuths}, {HFS_SK_TRUTH_SAMPLES, q->truth_light_samples},
    };
    for (size_t i = 0; i < sizeof counts / sizeof counts[0]; ++i) {
        const hfs_scene_key *k = hfs_scene_key_get(counts[i].id);
        const int rc = CHECK_LIB(counts[i].id, 0, counts[i].value, k->name);
        if (rc)
            return rc;
        if (!hfs_scene_key_int_allowed(k, counts[i].value)) {
            char allowed[64];
            hfs_scene_key_allowed_text(k, allowed, sizeof allowed);
            return hfs_fail(err, HFS_E_INVALID, "%s: %d is not one of %s", k->name,
                            counts[i].value, allowed);
        }
    }
    if (q->precision != HFS_PRECISION_FP16 && q->precision != HFS_PRECISION_FP32)
        return hfs_fail(err, HFS_E_INVALID, "precision: unknown value %d", (int)q->precision);
    if (q->local_full_swath != 0 && q->local_full_swath != 1)
        return hfs_fail(err, HFS_E_INVALID, "local-swath: unknown value %d", q->local_full_swath);
    if (q->visibility != HFS_VIS_LEGENDRE && q->visibility != HFS_VIS_WEDGE_TABLE &&
        q->visibility != HFS_VIS_SLICE)
        return hfs_fail(err, HFS_E_INVALID, "visibility: unknown value %d", (int)q->visibility);
    if (q->truth_elev_order < 1 || q->truth_elev_order > 64)
        return hfs_fail(err, HFS_E_INVALID, "quality: truth_elev_order %d is out of range [1, 64]",
                        q->truth_elev_order);
    return HFS_OK;
}

#undef CHECK_LIB

/* Inputs in the order a message should name them; the heights only when
 * `heights` (the renderer scans them once per serial). */
static int validate(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q, int heights,
                    hfs_error *err)
{
    if (!f || !l || !q || !f->z)
        return hfs_fail(err, HFS_E_INVALID, "render: missing field, lighting or quality");
    int rc = check_field_params(f, err);
    if (!rc && heights)
        rc = check_heights(f, err);
    if (!rc)
        rc = hfs_validate_lighting(l, err);
    if (!rc)
        rc = hfs_albedo_map_check(l->albedo_map, f->width, f->height, err);
    return rc ? rc : hfs_validate_quality(q, err);
}

int hfs_validate_inputs(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                        hfs_error *err)
{
    return validate(f, l, q, 1, err);
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
    const int rc = validate(f, l, q, !known, err);
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
    if ((rc = r->ops->render(r->state, f, l, q, out, progress, user, err)))
        return rc;
    if (r->timing && !r->ops->timings)
        wall_timings(r, "render", t0);
    return check_output(out, r->ops->name, err);
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

/* The view of the lit image: the backend's own, or the ray-cast one. */
static int render_view(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l,
                       const hfs_quality *q, const hfs_camera *cam, const hfs_view *v,
                       hfs_image *lit, hfs_image *out, hfs_error *err)
{
    if (r->ops->render_view)
        return r->ops->render_view(r->state, f, l, q, cam, v->width, v->height, lit, out->rgb,
                                   err);
    int rc = r->ops->render(r->state, f, l, q, lit, NULL, NULL, err);
    if (!rc)
        rc = check_output(lit, r->ops->name, err);
    return rc ? rc : hfs_truth_view(f, lit->rgb, l, cam, v->width, v->height, out->rgb,
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
    hfs_lighting seen = *l;
    if (l->specular > 0.0)
        glossy_viewer(&cam, &seen);
    const double t0 = wall_ms();
    rc = render_view(r, f, &seen, q, &cam, v, lit ? lit : &own, out, err);
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
    if (!r->ops->query_points)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "query: the %s backend does not answer point "
                        "queries yet (use the cpu or truth backend)", r->ops->name);
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
    return n > 0 && l->n_key > 0 ? r->ops->query_points(f, l, q, xyz, n, vis, err) : HFS_OK;
}
