/*
 * backend_ops.c — the table of backend_ops.h: each backend's entry points
 * wrapped to one signature (the GLES calls that bind the renderer's
 * context give the application's back before returning).
 */
#include "backend_ops.h"

#include <stdlib.h>
#include <string.h>


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

/* The GLES calls that bind the renderer's context give the application's
 * back before returning (hfs_gles_release: a shared renderer's). */
static int gles_create(const hfs_renderer_desc *d, void **state, hfs_error *err)
{
    const char *env = getenv("HFS_GL_STRICT_LIMITS");
    const int strict = (d && d->gl_strict_limits) || (env && !strcmp(env, "1"));
    const char *profile = d ? d->gl_profile : NULL;
    hfs_gles *g = NULL;
    const int rc = d && (d->egl_display || d->egl_share_context)
                       ? hfs_gles_create_shared(d->egl_display, d->egl_share_context, profile,
                                                strict, &g, err)
                       : hfs_gles_create(d ? d->context : NULL, profile, strict, &g, err);
    *state = g;
    return rc;
}
static void gles_destroy(void *state) { hfs_gles_destroy(state); }
static int gles_render(void *state, const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                       hfs_image *out, hfs_progress_fn progress, void *user, hfs_error *err)
{
    const int rc = hfs_gles_render(state, f, l, q, out, err);
    hfs_gles_release(state);
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
                            const hfs_quality *q, const hfs_camera *cam,
                            const hfs_object_set *obj, int w, int h, hfs_image *lit,
                            float *view, hfs_error *err)
{
    const int rc = hfs_gles_render_view(state, f, l, q, cam, obj, w, h, lit, view, err);
    hfs_gles_release(state);
    return rc;
}
static int gles_render_texture(void *state, const hfs_field *f, const hfs_lighting *l,
                               const hfs_quality *q, const hfs_lit_texture_desc *how,
                               hfs_lit_texture *out, hfs_error *err)
{
    const int rc = hfs_gles_render_texture(state, f, l, q, how, out, err);
    hfs_gles_release(state);
    return rc;
}

static int cpu_query(void *state, const hfs_field *f, const hfs_lighting *l,
                     const hfs_quality *q, const double *xyz, int n, float *vis, hfs_error *err)
{
    (void)state;
    return hfs_cpu_query_points(f, l, q, xyz, n, vis, err);
}
static int truth_query(void *state, const hfs_field *f, const hfs_lighting *l,
                       const hfs_quality *q, const double *xyz, int n, float *vis,
                       hfs_error *err)
{
    (void)state;
    return hfs_truth_query_points(f, l, q, xyz, n, vis, err);
}
static int gles_query(void *state, const hfs_field *f, const hfs_lighting *l,
                      const hfs_quality *q, const double *xyz, int n, float *vis, hfs_error *err)
{
    const int rc = hfs_gles_query_points(state, f, l, q, xyz, n, vis, err);
    hfs_gles_release(state);
    return rc;
}

static int cpu_shadow_map(void *state, const hfs_field *f, const hfs_key_light *k,
                          const hfs_quality *q, int layer, float *out, hfs_error *err)
{
    (void)state;
    return hfs_cpu_shadow_height_map(f, k, q, layer, out, err);
}
static int gles_shadow_map(void *state, const hfs_field *f, const hfs_key_light *k,
                           const hfs_quality *q, int layer, float *out, hfs_error *err)
{
    const int rc = hfs_gles_shadow_height_map(state, f, k, q, layer, out, err);
    hfs_gles_release(state);
    return rc;
}

static int cpu_horizons(void *state, const hfs_field *f, const hfs_quality *q,
                        const hfs_horizon_desc *d, float *out, hfs_error *err)
{
    (void)state;
    return hfs_cpu_horizons(f, q, d, out, err);
}
static int truth_horizons(void *state, const hfs_field *f, const hfs_quality *q,
                          const hfs_horizon_desc *d, float *out, hfs_error *err)
{
    (void)state;
    return hfs_truth_horizons(f, q, d, out, err);
}
static int gles_horizons(void *state, const hfs_field *f, const hfs_quality *q,
                         const hfs_horizon_desc *d, float *out, hfs_error *err)
{
    const int rc = hfs_gles_horizons(state, f, q, d, out, err);
    hfs_gles_release(state);
    return rc;
}

static int gles_max_side(void *state, const hfs_quality *q, char *limit, size_t n)
{
    const int side = hfs_gles_max_side(state, q, limit, n);
    hfs_gles_release(state);
    return side;
}

static const backend_ops backends[] = {
    [HFS_BACKEND_GLES] = {"gles", gles_create, gles_destroy, gles_render, gles_set_timing,
                          gles_set_amortize, gles_set_timing_finish, gles_timings,
                          gles_invalidate, gles_frame_report, gles_render_view, 0, gles_query,
                          gles_shadow_map, gles_render_texture, gles_horizons, gles_max_side},
    [HFS_BACKEND_CPU] = {"cpu", NULL, NULL, cpu_render, NULL, NULL, NULL, NULL, NULL, NULL,
                         NULL, 0, cpu_query, cpu_shadow_map, NULL, cpu_horizons, NULL},
    [HFS_BACKEND_TRUTH] = {"truth", NULL, NULL, truth_render, NULL, NULL, NULL, NULL, NULL,
                           NULL, NULL, 1, truth_query, NULL, NULL, truth_horizons, NULL},
};
#define N_BACKENDS ((int)(sizeof backends / sizeof backends[0]))

const backend_ops *hfs_backend_ops(hfs_backend b)
{
    return (int)b >= 0 && (int)b < N_BACKENDS && backends[b].render ? &backends[b] : NULL;
}
