/*
 * renderer.c — the public renderer object: validates every input once and
 * dispatches to a backend (backends.h) through one table of backend
 * operations.  Backends may assume valid inputs.
 */
#include "backends.h"

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

static const backend_ops backends[] = {
    [HFS_BACKEND_GLES] = {"gles", gles_create, gles_destroy, gles_render, gles_set_timing,
                          gles_set_amortize, gles_set_timing_finish, gles_timings,
                          gles_invalidate, gles_frame_report},
    [HFS_BACKEND_CPU] = {"cpu", NULL, NULL, cpu_render, NULL, NULL, NULL, NULL, NULL, NULL},
    [HFS_BACKEND_TRUTH] = {"truth", NULL, NULL, truth_render, NULL, NULL, NULL, NULL, NULL, NULL},
};
#define N_BACKENDS ((int)(sizeof backends / sizeof backends[0]))

struct hfs_renderer {
    const backend_ops *ops;
    void *state;             /* the backend's own object (NULL if it has none) */
    int timing;
    hfs_timings timings;     /* backends without timings of their own: the last timed frame */
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
    if (r && r->ops->invalidate)
        r->ops->invalidate(r->state);
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

static int finite3(const float v[3])
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]) && v[0] >= 0 && v[1] >= 0 && v[2] >= 0;
}

int hfs_validate_inputs(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                        hfs_error *err)
{
    const double pi = 3.14159265358979323846;
    if (!f || !l || !q || !f->z)
        return hfs_fail(err, HFS_E_INVALID, "render: missing field, lighting or quality");
    if (f->width < 2 || f->height < 2)
        return hfs_fail(err, HFS_E_INVALID, "height field: %dx%d is smaller than 2x2", f->width, f->height);
    /* Wide but bounded ranges keep every product of heights, scales and
     * spacings far from double overflow/underflow. */
    if (!(f->dx >= 1e-9 && f->dx <= 1e12))
        return hfs_fail(err, HFS_E_INVALID, "dx: %g is out of range [1e-9, 1e12]", f->dx);
    if (!(f->zscale >= 0.0 && f->zscale <= 1e12))
        return hfs_fail(err, HFS_E_INVALID, "zscale: %g is out of range [0, 1e12]", f->zscale);
    const size_t n = (size_t)f->width * (size_t)f->height;
    for (size_t i = 0; i < n; ++i)
        if (!isfinite(f->z[i]))
            return hfs_fail(err, HFS_E_INVALID, "height field: non-finite height at texel %zu "
                            "(holes must be filled before rendering)", i);
    if (!(l->albedo >= 0.0 && l->albedo <= 1.0))
        return hfs_fail(err, HFS_E_INVALID, "albedo: %g is out of range [0, 1]", l->albedo);
    if (l->has_env) {
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < HFS_SH_COEFFS; ++k)
                if (!isfinite(l->env_sh[c][k]))
                    return hfs_fail(err, HFS_E_INVALID, "env-sh: coefficient %d is not finite", k);
        if (!isfinite(l->env_rotate))
            return hfs_fail(err, HFS_E_INVALID, "env-rotate: not finite");
    }
    if (l->n_key < 0 || l->n_key > HFS_MAX_KEY_LIGHTS)
        return hfs_fail(err, HFS_E_INVALID, "key: %d lights (at most %d)", l->n_key, HFS_MAX_KEY_LIGHTS);
    for (int i = 0; i < l->n_key; ++i) {
        const hfs_key_light *k = &l->key[i];
        if (!isfinite(k->phi) || !(k->elev >= -pi / 2 && k->elev <= pi / 2) ||
            !(k->alpha > 0.0 && k->alpha < pi / 2) || !finite3(k->radiance))
            return hfs_fail(err, HFS_E_INVALID, "key light %d: direction, radius or radiance out of range", i + 1);
    }
    if (l->n_local < 0 || l->n_local > HFS_MAX_LOCAL_LIGHTS)
        return hfs_fail(err, HFS_E_INVALID, "local: %d lights (at most %d)", l->n_local, HFS_MAX_LOCAL_LIGHTS);
    for (int i = 0; i < l->n_local; ++i) {
        const hfs_local_light *o = &l->local[i];
        if (!isfinite(o->pos[0]) || !isfinite(o->pos[1]) || !isfinite(o->pos[2]) ||
            !(o->radius >= 0.0) || !isfinite(o->radius) || !finite3(o->radiance))
            return hfs_fail(err, HFS_E_INVALID, "local light %d: position, radius or radiance out of range", i + 1);
    }
    if (q->k < 1 || q->k > 16 || q->offset < 0 || q->offset > 16)
        return hfs_fail(err, HFS_E_INVALID, "quality: k=%d (1..16) or offset=%d (0..16) out of range", q->k, q->offset);
    if (q->nphi_env < 3 || q->nphi_env > 1024 || q->nphi_key < 1 || q->nphi_key > 256 ||
        q->nphi_local < 3 || q->nphi_local > 1024)
        return hfs_fail(err, HFS_E_INVALID, "quality: azimuth sample counts out of range");
    if (q->subsample != 1 && q->subsample != 2 && q->subsample != 4)
        return hfs_fail(err, HFS_E_INVALID, "subsample: %d is not 1, 2 or 4", q->subsample);
    if (q->precision != HFS_PRECISION_FP16 && q->precision != HFS_PRECISION_FP32)
        return hfs_fail(err, HFS_E_INVALID, "precision: unknown value %d", (int)q->precision);
    if (q->local_full_swath != 0 && q->local_full_swath != 1)
        return hfs_fail(err, HFS_E_INVALID, "local-swath: unknown value %d", q->local_full_swath);
    if (q->visibility != HFS_VIS_LEGENDRE && q->visibility != HFS_VIS_WEDGE_TABLE)
        return hfs_fail(err, HFS_E_INVALID, "visibility: unknown value %d", (int)q->visibility);
    if (q->threads < 0 || q->truth_azimuths < 1 || q->truth_elev_order < 1 ||
        q->truth_elev_order > 64 || q->truth_light_samples < 1)
        return hfs_fail(err, HFS_E_INVALID, "quality: thread or ground-truth settings out of range");
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

int hfs_renderer_render(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l,
                        const hfs_quality *q, hfs_image *out, hfs_progress_fn progress,
                        void *user, hfs_error *err)
{
    int rc = hfs_validate_inputs(f, l, q, err);
    if (rc)
        return rc;
    if (!out || !out->rgb || out->width != f->width || out->height != f->height)
        return hfs_fail(err, HFS_E_INVALID, "render: output image is not %dx%d", f->width, f->height);
    const double t0 = wall_ms();
    if ((rc = r->ops->render(r->state, f, l, q, out, progress, user, err)))
        return rc;
    if (r->timing && !r->ops->timings) {
        hfs_timings *t = &r->timings;
        memset(t, 0, sizeof *t);
        t->n_passes = 1;
        snprintf(t->pass[0].name, sizeof t->pass[0].name, "render");
        t->pass[0].ms = t->gpu_ms = t->frame_ms = wall_ms() - t0;
        t->pass[0].fetches = -1.0;
        snprintf(t->method, sizeof t->method, "wall");
        snprintf(t->device, sizeof t->device, "%s", r->ops->name);
    }
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
