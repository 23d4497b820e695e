/*
 * gles_render_util.h — what the GLES renderer's test programs share
 * (test_gles_render.c, test_gles_fetch.c, test_gles_grid.c,
 * test_gles_limits.c): the pinned quality, the renderer on the test's
 * context, rendering and comparing with SPEC's metrics.  Header-only and static, so each program's CHECKs
 * count into its own check.h counters (include once per program, after
 * check.h's users' includes).
 */
#ifndef HFS_TEST_GLES_RENDER_UTIL_H
#define HFS_TEST_GLES_RENDER_UTIL_H

#include "backends.h"
#include "gl_test.h"
#include "test_gles_scenes.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define PI 3.14159265358979323846

#ifndef HFS_DATA_DIR
#define HFS_DATA_DIR "data"
#endif

#include "check.h"

/* The bounds below were measured at k2 o3 16/3 (the defaults before issue
 * 15's sweep) with one horizon per direction (split 0, before split
 * horizons): pinned, so that a new pick of the defaults does not move
 * them. */
static inline hfs_quality quality(const char *prec, const char *path, int sub)
{
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.k = 2, q.offset = 3, q.nphi_env = 16, q.nphi_key = 3;
    q.split = 0;
    q.precision = prec && !strcmp(prec, "fp32") ? HFS_PRECISION_FP32 : HFS_PRECISION_FP16;
    q.visibility = path && !strcmp(path, "tables") ? HFS_VIS_WEDGE_TABLE : HFS_VIS_LEGENDRE;
    /* "slice": the exact slice path, one horizon per direction; "split":
     * the same with split horizons (the product's default) */
    if (path && (!strcmp(path, "slice") || !strcmp(path, "split"))) {
        q.visibility = HFS_VIS_SLICE;
        q.split = !strcmp(path, "split");
    }
    q.subsample = sub;
    return q;
}

/* Makes a GLES renderer on the test's context, or exits by gl_test.h's rule
 * (77 only when no GLES context of any kind can be made here). */
static const char *test_context; /* NULL: surfaceless */

static inline hfs_renderer *gles_or_skip(const char *profile)
{
    const hfs_renderer_desc d = {.backend = HFS_BACKEND_GLES, .context = test_context,
                                 .gl_profile = profile};
    return gl_test_renderer(&d);
}

static inline int render(hfs_renderer *r, const scene *s, const hfs_lighting *l, const hfs_quality *q,
                         hfs_image *img)
{
    hfs_error err;
    if (!img->rgb && hfs_image_alloc(img, s->f.width, s->f.height, &err)) {
        CHECK(0, "alloc: %s", err.msg);
        return -1;
    }
    int rc = hfs_renderer_render(r, &s->f, l, q, img, NULL, NULL, &err);
    CHECK(rc == 0, "render: %s", err.msg);
    return rc;
}

static inline int cpu_render(const scene *s, const hfs_lighting *l, const hfs_quality *q,
                      hfs_image *img)
{
    hfs_renderer_desc d = {.backend = HFS_BACKEND_CPU};
    hfs_renderer *r = NULL;
    hfs_error err;
    if (hfs_renderer_create(&d, &r, &err))
        return -1;
    int rc = render(r, s, l, q, img);
    hfs_renderer_destroy(r);
    return rc;
}

static inline hfs_metrics compare(const scene *s, const hfs_lighting *l, const hfs_quality *q,
                           const hfs_image *a, const hfs_image *b)
{
    hfs_metrics m;
    memset(&m, 0, sizeof m);
    hfs_image un = {0};
    hfs_error err;
    if (hfs_image_alloc(&un, s->f.width, s->f.height, &err) ||
        hfs_render_unshadowed(&s->f, l, q, &un, &err) ||
        hfs_compare_images(a, b, hfs_image_max(&un), &m, &err))
        CHECK(0, "compare: %s", err.msg);
    hfs_image_free(&un);
    return m;
}

static inline int bitequal(const hfs_image *a, const hfs_image *b)
{
    return a->width == b->width && a->height == b->height &&
           !memcmp(a->rgb, b->rgb, (size_t)a->width * a->height * 3 * sizeof(float));
}

/* Texels where a and b differ by more than bound (of norm) in some channel. */
static inline long count_over(const hfs_image *a, const hfs_image *b, double norm, double bound)
{
    long n = 0;
    for (size_t i = 0; i < (size_t)a->width * a->height; ++i) {
        int over = 0;
        for (int c = 0; c < 3; ++c)
            over |= fabs((double)a->rgb[3 * i + c] - b->rgb[3 * i + c]) > bound * norm;
        n += over;
    }
    return n;
}

/* Texels allowed past the max bound of a GLES-against-CPU comparison: the
 * horizons refined between scales (--refine) pick the scale to refine
 * about by comparing slopes, and where two scales' slopes tie to within
 * float rounding (beyond pyramid_layout.h's tie), float and double can
 * pick differently: a discontinuity of the algorithm, not a difference of
 * implementation.  One texel in 2000 (at least 2); the mean bound and every
 * other texel's stay as measured. */
static inline long tie_allowance(const hfs_image *a)
{
    const long n = (long)a->width * a->height / 2000;
    return n > 2 ? n : 2;
}

/* Texel x lies on the visibility grid of sub-sampling sub (DESIGN.md "GLES
 * path", "Visibility grid": receiver a at min(a sub, W - 1)). */
static inline int on_grid(int x, int w, int sub)
{
    return x % sub == 0 || x == w - 1;
}

#endif /* HFS_TEST_GLES_RENDER_UTIL_H */
