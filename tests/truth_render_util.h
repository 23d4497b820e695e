/*
 * truth_render_util.h — what the truth's render tests (test_truth_render.c,
 * test_truth_local.c) share: default quality and lighting, the uniform sky,
 * rendering a scene with both hfs_truth_render and hfs_unshadowed_render,
 * and the finite check.  Include once per test program, after test_util.h.
 */
#ifndef HFS_TEST_TRUTH_RENDER_UTIL_H
#define HFS_TEST_TRUTH_RENDER_UTIL_H

#include "backends.h"
#include "lights.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>

#define PI 3.14159265358979323846

static uint64_t rng_state = 0x9e3779b97f4a7c15ULL;
static inline double urand(void)
{
    rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(rng_state >> 11) * (1.0 / 9007199254740992.0);
}

static inline hfs_quality default_quality(int threads)
{
    hfs_quality q;
    hfs_quality_defaults(&q); /* sets every field */
    q.threads = threads;
    return q;
}

static inline hfs_lighting no_lights(void)
{
    hfs_lighting l;
    hfs_lighting_defaults(&l); /* no lights, albedo 1 */
    return l;
}

static inline void uniform_sky(hfs_lighting *l, double radiance)
{
    l->has_env = 1;
    for (int c = 0; c < 3; ++c)
        l->env_sh[c][0] = radiance * sqrt(4.0 * PI);
}

/* Renders with both functions; returns 0 on success. */
static inline int render_both(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                       hfs_image *truth, hfs_image *unsh)
{
    hfs_error err = {{0}};
    if (hfs_image_alloc(truth, f->width, f->height, &err) ||
        hfs_image_alloc(unsh, f->width, f->height, &err))
        return -1;
    if (hfs_truth_render(f, l, q, truth, NULL, NULL, &err) != HFS_OK) {
        fprintf(stderr, "truth: %s\n", err.msg);
        return -1;
    }
    if (hfs_unshadowed_render(f, l, q, unsh, &err) != HFS_OK) {
        fprintf(stderr, "unshadowed: %s\n", err.msg);
        return -1;
    }
    return 0;
}

static inline int all_finite(const hfs_image *img)
{
    for (size_t k = 0; k < (size_t)img->width * img->height * 3; ++k)
        if (!isfinite(img->rgb[k]))
            return 0;
    return 1;
}

#endif /* HFS_TEST_TRUTH_RENDER_UTIL_H */
