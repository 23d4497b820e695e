/*
 * gis_horizons.h — horizon elevation angles of a whole field for many
 * azimuths, through hfs_renderer_horizons, a few azimuths at a time so
 * that a large DEM with many directions needs no n x W x H block at once
 * (each call's block is at most GIS_HORIZON_BATCH_FLOATS floats, and at
 * least one azimuth).  Each azimuth's angles go to a callback as they come,
 * in the order given: the products sum them (sky-view factor, openness)
 * or write them (one raster per azimuth).  With `sweep` the angles come
 * from gis_sweep.h's sweep on the host instead of the renderer (the whole
 * field: radius 0 only).  No GDAL.
 */
#ifndef HFS_GIS_HORIZONS_H
#define HFS_GIS_HORIZONS_H

#include "hfshade.h"

#define GIS_HORIZON_BATCH_FLOATS (1 << 26) /* 256 MiB of angles per call */

/* Texels below which the callbacks' per-texel sums stay on the calling
 * thread (above it they run on parallel.h's workers, the same values). */
#define GIS_SUMS_THREADED 16384

/* Azimuth k's angles: gamma (field W x H, radians, signed,
 * HFS_HORIZON_NONE where the ray met no terrain).  0, or an error code
 * with err filled (the run stops). */
typedef int (*gis_horizon_fn)(void *user, int k, const float *gamma, hfs_error *err);

/* hfs_renderer_horizons(r, field, q, desc, out), or with sweep != 0 the
 * sweep's angles (desc->radius must be 0; a window clamps them as the
 * renderer's do, the renderer unused: r may be NULL). */
int gis_horizons_get(hfs_renderer *r, int sweep, const hfs_field *field, const hfs_quality *q,
                     const hfs_horizon_desc *desc, float *out, hfs_error *err);

/* gis_horizons_each's lo for every angle, signed (openness). */
#define GIS_HORIZONS_ALL (-1.5707963267948966)

/* Calls fn for each of the n azimuths phi[k] (the grid's phi, radians)
 * searched up to radius world units (0: the whole field) over field, on
 * renderer r with quality q (NULL: defaults), or by the sweep
 * (gis_horizons_get).  lo: the lowest angle fn tells apart (0 for the
 * products that clamp at the horizontal: every angle below comes back as
 * 0, and the searches skip what stays below it; GIS_HORIZONS_ALL: all,
 * signed, as openness wants them).  0, or the first error. */
int gis_horizons_each(hfs_renderer *r, int sweep, const hfs_field *field, const hfs_quality *q,
                      const double *phi, int n, double radius, double lo, gis_horizon_fn fn,
                      void *user, hfs_error *err);

#endif /* HFS_GIS_HORIZONS_H */
