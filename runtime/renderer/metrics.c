/*
 * metrics.c — SPEC.md's error metrics: mean absolute error, RMSE, 99th
 * percentile and maximum absolute error, normalized by the largest unshadowed
 * value, over every texel and channel; non-finite results are counted.
 */
#include "hfshade.h"

#include <math.h>
#include <stdlib.h>

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double hfs_image_max(const hfs_image *img)
{
    double m = 0.0;
    const size_t n = (size_t)img->width * (size_t)img->height * 3;
    for (size_t i = 0; i < n; ++i)
        if (isfinite(img->rgb[i]) && img->rgb[i] > m)
            m = img->rgb[i];
    return m;
}

int hfs_compare_images(const hfs_image *result, const hfs_image *reference,
                       double norm, hfs_metrics *m, hfs_error *err)
{
    if (result->width != reference->width || result->height != reference->height)
        return hfs_fail(err, HFS_E_INVALID, "compare: sizes differ (%dx%d vs %dx%d)",
                        result->width, result->height, reference->width, reference->height);
    if (!(norm > 0.0) || !isfinite(norm))
        return hfs_fail(err, HFS_E_INVALID, "compare: normalizer %g is not positive", norm);
    const size_t n = (size_t)result->width * (size_t)result->height * 3;
    double *diff = malloc(n * sizeof *diff);
    if (!diff)
        return hfs_fail(err, HFS_E_NOMEM, "compare: out of memory");
    long nonfinite = 0;
    double sum = 0.0, sum2 = 0.0, mx = 0.0;
    for (size_t i = 0; i < n; ++i) {
        double d;
        if (!isfinite(result->rgb[i])) {
            nonfinite++;
            d = INFINITY;
        } else {
            d = fabs((double)result->rgb[i] - (double)reference->rgb[i]) / norm;
        }
        diff[i] = d;
        sum += d;
        sum2 += d * d;
        if (d > mx)
            mx = d;
    }
    qsort(diff, n, sizeof *diff, cmp_double);
    /* Nearest-rank percentile. */
    size_t rank = (size_t)ceil(0.99 * (double)n);
    if (rank < 1)
        rank = 1;
    m->p99_abs = diff[rank - 1];
    free(diff);
    m->mean_abs = sum / (double)n;
    m->rmse = sqrt(sum2 / (double)n);
    m->max_abs = mx;
    m->nonfinite = nonfinite;
    m->norm = norm;
    return HFS_OK;
}
