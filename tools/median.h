/*
 * median.h — the median of timing samples, as every benchmark in tools/ and
 * tests/ quotes it (BENCHMARKS.md: medians, not means, on shared machines).
 * Sorts v in place.
 */
#ifndef HFS_MEDIAN_H
#define HFS_MEDIAN_H

#include <stdlib.h>

static inline int hfs_cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static inline double hfs_median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, hfs_cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

#endif /* HFS_MEDIAN_H */
