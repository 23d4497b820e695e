/*
 * cpu_bounce.h — indirect diffuse light in the CPU reference (issue 16;
 * NS09 sections 4-6 with the exact per-slice weights of issue 15).
 *
 * Bounce b at receiver x: along hfs_bounce_dirs(q) azimuth slices (every
 * (nphi_env / that)-th of the environment's directions, lights.h), the
 * horizon is walked outward from the tangent plane: the receiver's own
 * cell (hfs_field_first_cell: lit where the ray meets the bilinear surface,
 * below its near slope by the receiver itself, issue 36), then each scale
 * of the multi-scale horizons (cpu_horizon.h) with q->bounce_refine
 * samples after it towards the next (read as the scale reads), nearest
 * first.  A sample that rises
 * above everything nearer casts the band of elevations between the old top
 * and its own: those directions hit the terrain between the two samples,
 * and the band takes the sample's radiance Lo_{b-1} (NS09's casting set,
 * the occluder's exit radiance for its band); a scale's group of samples
 * casts one band, up to its highest sample and lit at the first one that
 * rose (the samples find the peaks between scales, and each band costs the
 * GLES gather a fetch and an atan).  The band's weight is the
 * clamped cosine's exact integral over it (hfs_slice_cosine), so
 *   Lo_b(x) = rho(x) / pi * sum_j dphi sum_bands Lo_{b-1}(y_i) W(band_i).
 * Lo_{b-1} is read bilinearly at the sample's grid position from the full
 * resolution image (every scale within 2^offset texels reads the heights
 * there too; farther scales read prefiltered heights, the radiance stays a
 * point sample: the approximation for fields above 2^offset + 1).
 * Under an environment on the exact-slice path the bands stop at the
 * slice's horizon as the direct light computes it (refined scales and own
 * cell; lights.h hfs_bounce_capped; with split horizons, each band clipped
 * to each of the slice's sub-horizons and the parts averaged,
 * split_horizon.h hfs_split_band, the far grid computed again as the
 * direct light's): what a receiver gathers and the sky it sees
 * never overlap, so with albedo <= 1 direct + bounces never exceed the
 * unshadowed maximum (without the cap, 3% over in a white furnace).
 * Without an environment there is no sky to overlap, and on the seeds'
 * paths the GLES backend has no per-direction horizon to cap with: there
 * the bands run to the walk's own top (everything the walk sees).
 * Every band weight and radiance is >= 0, so no bounce is negative.
 * Light leaving the field brings nothing.
 */
#ifndef HFS_CPU_BOUNCE_H
#define HFS_CPU_BOUNCE_H

#include "hfshade.h"

/* out (W*H*3) += the `bounces` bounces of lit (W*H*3, the direct exit
 * radiance with the albedo map applied), each gathered from the one
 * before.  rho(x) = l->albedo * l->albedo_map(x).  Returns HFS_OK or
 * HFS_E_NOMEM. */
int hfs_cpu_bounces(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                    int bounces, float *out, hfs_progress_fn progress, void *user,
                    hfs_error *err);

#endif /* HFS_CPU_BOUNCE_H */
