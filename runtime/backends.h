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

/* CPU reference (cpu_*.c): the GPU algorithm in double precision. */
int hfs_cpu_render(const hfs_field *f, const hfs_lighting *l,
                   const hfs_quality *q, hfs_image *out,
                   hfs_progress_fn progress, void *user, hfs_error *err);

/* Ground truth (truth_*.c): brute force per SPEC. */
int hfs_truth_render(const hfs_field *f, const hfs_lighting *l,
                     const hfs_quality *q, hfs_image *out,
                     hfs_progress_fn progress, void *user, hfs_error *err);

/* Exact unshadowed Lo (V = 1 everywhere) of the same scene: the normalizer of
 * SPEC's error metrics.  Environment exactly through SH (band-limited), key and
 * local lights by the exact cap-irradiance formula. */
int hfs_unshadowed_render(const hfs_field *f, const hfs_lighting *l,
                          const hfs_quality *q, hfs_image *out, hfs_error *err);

#endif /* HFS_BACKENDS_H */
