/*
 * backend_ops.h — the renderer's backends as a table (renderer.c uses it,
 * backend_ops.c fills it), like board/display_backend.h: every backend is
 * one row: its name, how it is made and destroyed, how it renders, and the
 * GLES-only controls (NULL where a backend has none: the CPU reference and
 * the ground truth render every frame from scratch and are timed by the
 * renderer's wall clock).
 */
#ifndef HFS_BACKEND_OPS_H
#define HFS_BACKEND_OPS_H

#include "backends.h"

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
                       const hfs_quality *q, const hfs_camera *cam,
                       const hfs_object_set *obj, int w, int h, hfs_image *lit, float *view,
                       hfs_error *err);
    /* Reads hfs_lighting.env_map (the truth): its pixels are checked for
     * it alone, the others' frames skip the scan. */
    int reads_env_map;
    /* Key-light visibility of points. */
    int (*query_points)(void *state, const hfs_field *f, const hfs_lighting *l,
                        const hfs_quality *q, const double *xyz, int n, float *vis,
                        hfs_error *err);
    /* One layer of a key light's shadow height map (NULL: none). */
    int (*shadow_map)(void *state, const hfs_field *f, const hfs_key_light *k,
                      const hfs_quality *q, int layer, float *out, hfs_error *err);
    /* The lit result as a texture of the application's context (NULL:
     * none, the CPU backends have no GL). */
    int (*render_texture)(void *state, const hfs_field *f, const hfs_lighting *l,
                          const hfs_quality *q, const hfs_lit_texture_desc *how,
                          hfs_lit_texture *out, hfs_error *err);
    /* The GIS horizons of every grid point. */
    int (*horizons)(void *state, const hfs_field *f, const hfs_quality *q,
                    const hfs_horizon_desc *d, float *out, hfs_error *err);
    /* The largest field side one frame may have (a larger field is
     * rendered in tiles, tiled_render.h); NULL or 0: any. */
    int (*max_side)(void *state, const hfs_quality *q, char *limit, size_t n);
} backend_ops;

/* The row of backend b (hfs_backend), or NULL when there is none. */
const backend_ops *hfs_backend_ops(hfs_backend b);

#endif /* HFS_BACKEND_OPS_H */
