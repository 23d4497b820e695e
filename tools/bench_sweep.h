/*
 * bench_sweep.h — the settings hfbench measures: a union of grids, each the
 * Cartesian product of value lists of scene keys (SPEC's flags without
 * "--", runtime/scene/scene.h, so every value is validated exactly as
 * hfshade validates it) plus "backend":
 *
 *     "k=2,4,8 offset=1,2,3 nphi-env=16,32 subsample=1,2,4"
 *     "precision=fp32"          (one point: the defaults at fp32)
 *
 * Keys a grid does not name keep hfs_quality_defaults().  Points that come
 * out equal (from overlapping grids) are measured once.
 */
#ifndef HFS_BENCH_SWEEP_H
#define HFS_BENCH_SWEEP_H

#include "hfshade.h"

typedef struct bench_point {
    hfs_quality q;
    hfs_backend backend;
    int is_default;          /* the library's defaults on the GLES backend */
    char label[192];         /* canonical, e.g. "gles k4 o2 e32 k3 l16 sub2 fp16 leg part" */
} bench_point;

typedef struct bench_sweep {
    bench_point *pts;
    int n, cap;
} bench_sweep;

/* Adds the points of one grid.  One-line errors name the grid and key. */
int bench_sweep_add_grid(bench_sweep *s, const char *grid, hfs_error *err);
void bench_sweep_free(bench_sweep *s);

/* The canonical label of (q, backend). */
void bench_point_label(const hfs_quality *q, hfs_backend backend, char *out, size_t cap);

#endif /* HFS_BENCH_SWEEP_H */
