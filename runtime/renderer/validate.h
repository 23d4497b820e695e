/*
 * validate.h — the renderer's input checks (validate.c), inside the
 * library: the public ones are hfshade.h's hfs_validate_*.
 */
#ifndef HFS_VALIDATE_H
#define HFS_VALIDATE_H

#include "hfshade.h"

/* Field, lighting (the environment map's pixels only when scan_map),
 * albedo map and quality, in the order a message should name them; the
 * heights only when `heights` (the renderer scans them once per serial). */
int hfs_validate_frame_inputs(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                              int heights, int scan_map, hfs_error *err);

/* hfs_renderer_horizons' request: 1..HFS_MAX_HORIZON_AZIMUTHS finite
 * azimuths, a finite radius >= 0, an output array. */
int hfs_validate_horizon_desc(const hfs_horizon_desc *d, const float *out, hfs_error *err);

#endif /* HFS_VALIDATE_H */
