/*
 * renderer.c — the public renderer object: validates every input once and
 * dispatches to a backend (backends.h).  Backends may assume valid inputs.
 */
#include "backends.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

struct hfs_renderer {
    hfs_backend backend;
    hfs_gles *gles;          /* HFS_BACKEND_GLES only */
    int timing;
    hfs_timings timings;     /* CPU backends: the last timed frame */
};

static double wall_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

static const char *backend_name(hfs_backend b)
{
    switch (b) {
    case HFS_BACKEND_GLES: return "gles";
    case HFS_BACKEND_CPU: return "cpu";
    case HFS_BACKEND_TRUTH: return "truth";
    default: return "default";
    }
}

int hfs_renderer_create(const hfs_renderer_desc *desc, hfs_renderer **out, hfs_error *err)
{
    *out = NULL;
    hfs_backend b = desc ? desc->backend : HFS_BACKEND_DEFAULT;
    if (b == HFS_BACKEND_DEFAULT)
        b = HFS_BACKEND_GLES; /* the product */
    if (b != HFS_BACKEND_CPU && b != HFS_BACKEND_TRUTH && b != HFS_BACKEND_GLES)
        return hfs_fail(err, HFS_E_INVALID, "backend %d: unknown", (int)b);
    hfs_renderer *r = calloc(1, sizeof *r);
    if (!r)
        return hfs_fail(err, HFS_E_NOMEM, "renderer: out of memory");
    r->backend = b;
    if (b == HFS_BACKEND_GLES) {
        const char *env = getenv("HFS_GL_STRICT_LIMITS");
        const int strict = (desc && desc->gl_strict_limits) || (env && !strcmp(env, "1"));
        int rc = hfs_gles_create(desc ? desc->context : NULL, desc ? desc->gl_profile : NULL,
                                 strict, &r->gles, err);
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
    hfs_gles_destroy(r->gles);
    free(r);
}

const char *hfs_renderer_backend_name(const hfs_renderer *r)
{
    return backend_name(r->backend);
}

int hfs_renderer_set_timing(hfs_renderer *r, int level)
{
    if (!r || level < 0 || level > 2)
        return HFS_E_INVALID;
    r->timing = level;
    if (r->gles)
        hfs_gles_set_timing(r->gles, level);
    return HFS_OK;
}

int hfs_renderer_set_amortize(hfs_renderer *r, int passes_per_frame)
{
    if (!r || passes_per_frame < 0)
        return HFS_E_INVALID;
    if (r->gles)
        hfs_gles_set_amortize(r->gles, passes_per_frame);
    return HFS_OK;
}

int hfs_renderer_set_timing_finish(hfs_renderer *r, int finish)
{
    if (!r || finish < 0 || finish > 1)
        return HFS_E_INVALID;
    if (r->gles)
        hfs_gles_set_timing_finish(r->gles, finish);
    return HFS_OK;
}

int hfs_renderer_timings(const hfs_renderer *r, hfs_timings *out)
{
    if (!r || !out)
        return HFS_E_INVALID;
    if (r->gles)
        hfs_gles_get_timings(r->gles, out);
    else
        *out = r->timings;
    return HFS_OK;
}

void hfs_renderer_invalidate(hfs_renderer *r)
{
    if (r && r->gles)
        hfs_gles_invalidate(r->gles);
}

int hfs_renderer_frame_report(const hfs_renderer *r, hfs_frame_report *out)
{
    if (!r || !out)
        return HFS_E_INVALID;
    if (r->gles) {
        hfs_gles_frame_report(r->gles, out);
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
    switch (r->backend) {
    case HFS_BACKEND_CPU:
        rc = hfs_cpu_render(f, l, q, out, progress, user, err);
        break;
    case HFS_BACKEND_TRUTH:
        rc = hfs_truth_render(f, l, q, out, progress, user, err);
        break;
    case HFS_BACKEND_GLES:
        rc = hfs_gles_render(r->gles, f, l, q, out, err);
        if (!rc && progress)
            progress(user, 1.0);
        break;
    default:
        return hfs_fail(err, HFS_E_UNSUPPORTED, "backend %s: not available", backend_name(r->backend));
    }
    if (rc)
        return rc;
    if (r->timing && !r->gles) {
        hfs_timings *t = &r->timings;
        memset(t, 0, sizeof *t);
        t->n_passes = 1;
        snprintf(t->pass[0].name, sizeof t->pass[0].name, "render");
        t->pass[0].ms = t->gpu_ms = t->frame_ms = wall_ms() - t0;
        t->pass[0].fetches = -1.0;
        snprintf(t->method, sizeof t->method, "wall");
        snprintf(t->device, sizeof t->device, "%s", backend_name(r->backend));
    }
    return check_output(out, backend_name(r->backend), err);
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
