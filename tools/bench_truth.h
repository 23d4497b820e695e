/*
 * bench_truth.h — ground-truth images for hfbench, cached on disk by a hash
 * of everything the truth depends on (heights, dx, zscale, lighting, truth
 * settings), because the truth costs seconds to minutes and the sweep
 * compares hundreds of settings against the same one.
 */
#ifndef HFS_BENCH_TRUTH_H
#define HFS_BENCH_TRUTH_H

#include "hfshade.h"

/* 64-bit FNV-1a over the truth's inputs (the field's bytes, its size and
 * spacing, the lighting struct's fields one by one and the truth settings of
 * q), stable across runs and machines of the same endianness. */
unsigned long long bench_truth_hash(const hfs_field *f, const hfs_lighting *l,
                                    const hfs_quality *q);

/* The truth image of (f, l, q's truth settings): read from
 * cache_dir/truth-<hash>.pfm, or rendered with the truth backend and written
 * there.  *cached tells which.  `out` is allocated here. */
int bench_truth_get(const char *cache_dir, const hfs_field *f, const hfs_lighting *l,
                    const hfs_quality *q, hfs_image *out, int *cached, double *seconds,
                    hfs_error *err);

#endif /* HFS_BENCH_TRUTH_H */
