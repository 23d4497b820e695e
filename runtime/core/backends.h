/*
 * backends.h — the entry points every rendering backend implements.  All
 * compute SPEC.md's Lo for the same inputs; the renderer object
 * (renderer.c) validates inputs once and dispatches here.
 *
 * Preconditions (checked by renderer.c, assumed here): field valid (W,H >= 2,
 * finite heights, dx > 0, zscale >= 0), lighting values finite and in range,
 * quality filled by hfs_quality_defaults, out allocated to W x H.
 */
#ifndef HFS_BACKENDS_H
#define HFS_BACKENDS_H

#include "hfshade.h"
#include "objects.h"
#include "view_camera.h"

/* CPU reference (cpu_*.c): the GPU algorithm in double precision. */
int hfs_cpu_render(const hfs_field *f, const hfs_lighting *l,
                   const hfs_quality *q, hfs_image *out,
                   hfs_progress_fn progress, void *user, hfs_error *err);

/* Key-light visibility of n points (hfs_renderer_query_points; checked
 * there: finite, over the field): vis[i * n_key + k].  The CPU reference
 * reads shadow height maps (shm.h), the truth casts exact rays. */
int hfs_cpu_query_points(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                         const double *xyz, int n, float *vis, hfs_error *err);
int hfs_truth_query_points(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                           const double *xyz, int n, float *vis, hfs_error *err);
/* One layer of key light k's shadow height map into out (W*H, world z). */
int hfs_cpu_shadow_height_map(const hfs_field *f, const hfs_key_light *k, const hfs_quality *q,
                              int layer, float *out, hfs_error *err);

/* The GIS horizons of every grid point (hfs_renderer_horizons; desc
 * checked there): the CPU reference's gap search (cpu_horizons.c), the
 * truth's exact supremum (truth_horizons.c), the GLES pass
 * (runtime/gles/horizons.c). */
int hfs_cpu_horizons(const hfs_field *f, const hfs_quality *q, const hfs_horizon_desc *d,
                     float *out, hfs_error *err);
int hfs_truth_horizons(const hfs_field *f, const hfs_quality *q, const hfs_horizon_desc *d,
                       float *out, hfs_error *err);

/* Ground truth (truth_*.c): brute force per SPEC. */
int hfs_truth_render(const hfs_field *f, const hfs_lighting *l,
                     const hfs_quality *q, hfs_image *out,
                     hfs_progress_fn progress, void *user, hfs_error *err);

/* GLES renderer (gles_*.c): the product, DESIGN.md "GLES path".  The object
 * owns a GL context (made current on the creating thread and again at each
 * render; one sharing the application's, hfs_gles_create_shared, gives the
 * application's back after each call), every GPU resource and results
 * cached between frames. */
typedef struct hfs_gles hfs_gles;

/* context: gl_context.h name (NULL = surfaceless); profile: gl_caps.h name
 * or NULL (by precision); strict_limits: hfs_renderer_desc.gl_strict_limits.
 * HFS_E_CONTEXT/UNSUPPORTED/INVALID with one line. */
int hfs_gles_create(const char *context, const char *profile, int strict_limits,
                    hfs_gles **out, hfs_error *err);
/* The same in the share group of the application's EGL context
 * (hfs_renderer_desc.egl_share_context; runtime/gl/egl_shared.c). */
int hfs_gles_create_shared(void *egl_display, void *egl_context, const char *profile,
                           int strict_limits, hfs_gles **out, hfs_error *err);
/* After a call that bound the renderer's context: the application's back
 * (a shared renderer; otherwise nothing). */
void hfs_gles_release(hfs_gles *g);
/* The frame with its lit result as a texture of the application's share
 * group (hfs_renderer_render_texture; pass_lit_texture.c). */
int hfs_gles_render_texture(hfs_gles *g, const hfs_field *f, const hfs_lighting *l,
                            const hfs_quality *q, const hfs_lit_texture_desc *how,
                            hfs_lit_texture *out, hfs_error *err);
void hfs_gles_destroy(hfs_gles *g);
/* "surfaceless" or "osmesa"; hfs_gl_context_describe() of the context. */
const char *hfs_gles_context_name(const hfs_gles *g);
const char *hfs_gles_describe(const hfs_gles *g);
int hfs_gles_render(hfs_gles *g, const hfs_field *f, const hfs_lighting *l,
                    const hfs_quality *q, hfs_image *out, hfs_error *err);
/* The same frame and its 3-D view from camera cam into view (w x h RGB,
 * row 0 at the top; runtime/gles/pass_view.c), with the lit objects obj
 * (objects.h, in the view's world; NULL: none). */
int hfs_gles_render_view(hfs_gles *g, const hfs_field *f, const hfs_lighting *l,
                         const hfs_quality *q, const hfs_camera *cam,
                         const hfs_object_set *obj, int w, int h, hfs_image *out, float *view,
                         hfs_error *err);
/* Key-light visibility of points (hfs_renderer_query_points): shadow
 * height maps by doubling passes on the GPU (runtime/gles/shm_query.c). */
int hfs_gles_query_points(hfs_gles *g, const hfs_field *f, const hfs_lighting *l,
                          const hfs_quality *q, const double *xyz, int n, float *vis,
                          hfs_error *err);
/* The largest field side one GLES frame takes: the profile's texture
 * limit at q's precision, at most HFS_GLES_MAX_FRAME_SIDE (a frame's
 * textures grow with the field: an 8192^2 one exceeds llvmpipe's memory for
 * one texture); 0 when no context can be made (the frame then says why).
 * `limit` (n bytes) gets the limit as a refusal names it. */
#define HFS_GLES_MAX_FRAME_SIDE 4096
int hfs_gles_max_side(hfs_gles *g, const hfs_quality *q, char *limit, size_t n);
int hfs_gles_horizons(hfs_gles *g, const hfs_field *f, const hfs_quality *q,
                      const hfs_horizon_desc *d, float *out, hfs_error *err);
/* One layer of key light k's shadow height map into out (W*H, world z). */
int hfs_gles_shadow_height_map(hfs_gles *g, const hfs_field *f, const hfs_key_light *k,
                               const hfs_quality *q, int layer, float *out, hfs_error *err);
void hfs_gles_set_timing(hfs_gles *g, int level);
void hfs_gles_set_amortize(hfs_gles *g, int passes_per_frame); /* hfshade.h */
void hfs_gles_set_timing_finish(hfs_gles *g, int finish);        /* hfshade.h */
void hfs_gles_get_timings(const hfs_gles *g, hfs_timings *t);
void hfs_gles_invalidate(hfs_gles *g);
void hfs_gles_frame_report(const hfs_gles *g, hfs_frame_report *out);

/* Facts about the last GLES frame, for tests and tools. */
typedef struct hfs_gles_stats {
    double height_scale;       /* hscale: normalized units -> height units     */
    long offset_mismatches;    /* (dir, scale) samples whose float offset
                                  classification differs from the CPU's       */
    int terrain_recomputed;    /* pyramid/normals ran this frame              */
    int env_recomputed;        /* env pass ran this frame                     */
    char profile[16];
    int fp32;
} hfs_gles_stats;
void hfs_gles_get_stats(const hfs_gles *g, hfs_gles_stats *s);

/* Exact unshadowed Lo (V = 1 everywhere) of the same scene: the normalizer of
 * SPEC's error metrics.  Environment exactly through SH (band-limited), key and
 * local lights by the exact cap-irradiance formula. */
int hfs_unshadowed_render(const hfs_field *f, const hfs_lighting *l,
                          const hfs_quality *q, hfs_image *out, hfs_error *err);

#endif /* HFS_BACKENDS_H */
