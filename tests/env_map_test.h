/*
 * env_map_test.h — what the tests of an environment map shaded from the
 * map itself share (test_env_shade.c, test_env_gloss.c): the lighting as
 * the scene layer makes it, one render on a fresh renderer, the map
 * turned by a quarter.  Header-only; the includer has check.h and
 * gl_test.h.
 */
#ifndef HFS_TEST_ENV_MAP_TEST_H
#define HFS_TEST_ENV_MAP_TEST_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "env_open.h"
#include "sh.h"

/* The w x h map's lighting turned by rot, as the scene layer makes it;
 * with_map: env-shade = map (open table, written into open, and the map
 * itself), else its SH only.  Returns 0, or 1 when the table failed. */
static inline int env_map_lighting(hfs_lighting *l, const float *map, int w, int h, double rot,
                                   float *open, int with_map)
{
    hfs_lighting_defaults(l);
    l->has_env = 1;
    hfs_sh_project_equirect(map, w, h, l->env_sh);
    l->env_rotate = rot;
    l->env_map = map;
    l->env_map_width = w, l->env_map_height = h;
    hfs_error err = {""};
    const int rc = hfs_env_open_build(map, w, h, (const double(*)[HFS_SH_COEFFS])l->env_sh, open,
                                      &err);
    CHECK(rc == HFS_OK, "open table: %s", err.msg);
    if (with_map) {
        l->env_open = open;
        l->env_shade_map = map;
    }
    return rc != HFS_OK;
}

/* The defaults, with the truth's 720 azimuths (a map's sharp openings
 * need them). */
static inline hfs_quality env_map_quality(void)
{
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.truth_azimuths = 720;
    return q;
}

/* One frame of backend b on a fresh renderer (GLES: gl_test_gles) into
 * out (allocated here). */
static inline int env_map_render(hfs_backend b, const hfs_field *f, const hfs_lighting *l,
                                 const hfs_quality *q, hfs_image *out)
{
    hfs_renderer_desc d = {.backend = b};
    hfs_renderer *r = b == HFS_BACKEND_GLES ? gl_test_gles() : NULL;
    hfs_error err = {""};
    if (!r && hfs_renderer_create(&d, &r, &err)) {
        CHECK(0, "create: %s", err.msg);
        return -1;
    }
    hfs_image_alloc(out, f->width, f->height, &err);
    const int rc = hfs_renderer_render(r, f, l, q, out, NULL, NULL, &err);
    CHECK(rc == HFS_OK, "render: %s", err.msg);
    hfs_renderer_destroy(r);
    return rc;
}

/* The w x h map rolled by a quarter of its columns (a pixel at phi moves
 * to phi + 90 degrees), malloc'ed. */
static inline float *env_map_rolled(const float *map, int w, int h)
{
    float *rolled = malloc((size_t)w * (size_t)h * 3 * sizeof *rolled);
    for (int v = 0; v < h && rolled; ++v)
        for (int u = 0; u < w; ++u)
            memcpy(rolled + 3 * ((size_t)v * (size_t)w + (size_t)((u + w / 4) % w)),
                   map + 3 * ((size_t)v * (size_t)w + (size_t)u), 3 * sizeof *map);
    return rolled;
}

/* A map's lighting and its open table. */
typedef struct shaded {
    hfs_lighting l;
    float open[HFS_ENV_OPEN_FLOATS];
} shaded;
typedef void (*env_map_make_fn)(shaded *s, const float *map, double rot, int with_map);

/* The CPU frame under the w x h map turned by 90 degrees against the one
 * under the map rolled by a quarter (make: the test's lighting, env-shade
 * = map): the largest |difference| over the second's largest value. */
static inline double env_map_turn_error(const hfs_field *f, const float *map, int w, int h,
                                        env_map_make_fn make, const hfs_quality *q, int *rc)
{
    float *rolled = env_map_rolled(map, w, h);
    shaded a, b;
    make(&a, map, 0.5 * 3.14159265358979323846, 1);
    make(&b, rolled, 0.0, 1);
    hfs_image x = {0}, y = {0};
    *rc = env_map_render(HFS_BACKEND_CPU, f, &a.l, q, &x) |
          env_map_render(HFS_BACKEND_CPU, f, &b.l, q, &y);
    double m = 0.0, norm = 0.0;
    for (size_t i = 0; !*rc && i < (size_t)f->width * (size_t)f->height * 3; ++i) {
        m = fmax(m, fabs((double)x.rgb[i] - y.rgb[i]));
        norm = fmax(norm, y.rgb[i]);
    }
    hfs_image_free(&x), hfs_image_free(&y);
    free(rolled);
    return norm > 0.0 ? m / norm : m;
}

/* The truth of the map (into truth) and the CPU's map-shaded (a) and
 * SH-shaded (b) frames under make's lighting turned by rot. */
static inline int env_map_truth_and_cpu(const hfs_field *f, const float *map, double rot,
                                        env_map_make_fn make, const hfs_quality *q,
                                        hfs_image *truth, hfs_image *a, hfs_image *b)
{
    shaded on, off;
    make(&on, map, rot, 1);
    make(&off, map, rot, 0);
    return env_map_render(HFS_BACKEND_TRUTH, f, &on.l, q, truth) |
           env_map_render(HFS_BACKEND_CPU, f, &on.l, q, a) |
           env_map_render(HFS_BACKEND_CPU, f, &off.l, q, b);
}

/* A kept GLES renderer draws a (its frame into first when non-NULL),
 * then b; the passes b ran go to ran.  Returns 1 when b's frame is bit
 * for bit a fresh renderer's, 0 otherwise (or on a failed render). */
static inline int env_map_kept_is_fresh(const hfs_field *f, const hfs_lighting *a,
                                        const hfs_lighting *b, const hfs_quality *q,
                                        hfs_image *first, char *ran, size_t n_ran)
{
    hfs_renderer *r = gl_test_gles(), *fresh = gl_test_gles();
    hfs_error err = {""};
    hfs_image x = {0}, y = {0};
    hfs_image_alloc(&x, f->width, f->height, &err), hfs_image_alloc(&y, f->width, f->height, &err);
    int rc = hfs_renderer_render(r, f, a, q, &x, NULL, NULL, &err);
    if (first && !rc) {
        hfs_image_alloc(first, f->width, f->height, &err);
        memcpy(first->rgb, x.rgb, sizeof(float) * (size_t)f->width * (size_t)f->height * 3);
    }
    rc |= hfs_renderer_render(r, f, b, q, &x, NULL, NULL, &err);
    gl_test_ran(r, ran, n_ran);
    rc |= hfs_renderer_render(fresh, f, b, q, &y, NULL, NULL, &err);
    CHECK(!rc, "kept renderer: %s", err.msg);
    const int same = !rc && !memcmp(x.rgb, y.rgb,
                                    sizeof(float) * (size_t)f->width * (size_t)f->height * 3);
    hfs_image_free(&x), hfs_image_free(&y);
    hfs_renderer_destroy(r), hfs_renderer_destroy(fresh);
    return same;
}

#endif /* HFS_TEST_ENV_MAP_TEST_H */
