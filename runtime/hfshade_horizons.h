/*
 * hfshade_horizons.h — horizons: the rasters terrain analysts use (issue
 * 39).  The horizon elevation angles of every grid point along a set of
 * azimuths, on any backend; the GIS products (sky-view factor, openness,
 * the sun and insolation: hfshade_gis.h) are built on them.  Part of the
 * public interface: hfshade.h includes it after the renderer, and users
 * include <hfshade.h> (the conventions stated there, radians and world
 * units, hold here too).
 */
#ifndef HFSHADE_HORIZONS_H
#define HFSHADE_HORIZONS_H

#ifndef HFSHADE_H
#error "include <hfshade.h>, which includes hfshade_horizons.h"
#endif

/* What hfs_renderer_horizons searches: n_azimuths directions (radians,
 * SPEC's azimuth phi, from +x towards +y; for a north-up DEM +x is east
 * and +y south, so phi runs clockwise from east), each up to `radius`
 * world units of horizontal distance (0: to the field's edge). */
#define HFS_MAX_HORIZON_AZIMUTHS 1024
typedef struct hfs_horizon_desc {
    int n_azimuths;          /* 1..HFS_MAX_HORIZON_AZIMUTHS                  */
    const double *azimuth;   /* n_azimuths finite angles, radians            */
    double radius;           /* world units, >= 0 (0: the whole field)       */
    /* window = 1: only angles in [lo, hi] (radians, -pi/2 <= lo <= hi <=
     * pi/2) are wanted, and each result comes back as clamp(gamma, lo,
     * hi), lo where the ray meets no terrain.  The searches start from lo
     * (a run of the ray whose bound stays below it is skipped at once) and
     * GLES stops at hi: a sun's disk needs only [elevation - alpha,
     * elevation + alpha], and a high sun's search ends within a few cells.
     * window = 0 (zero-initialized): every angle, as below. */
    int window;
    double lo, hi;
} hfs_horizon_desc;

/* The value of a direction whose ray meets no terrain within the radius
 * (a texel on the field's border looking outwards): -pi/2. */
#define HFS_HORIZON_NONE (-1.5707963267948966f)

/* Horizon elevation angles of every grid point: out[(a H + j) W + i] (n_azimuths
 * x H x W floats, the caller's) is, in radians, the elevation above the
 * horizontal plane of the highest terrain seen from grid point (i, j)'s
 * own surface point (x = i dx, y = j dx, z = zscale h, no lift) along
 * azimuth a, over horizontal distances t in (0, radius]:
 *     atan(max_t (zscale h(p(t)) - zscale h(i, j)) / t),
 * signed (negative where all the terrain in reach lies below the texel:
 * a peak's), HFS_HORIZON_NONE where the ray meets none.  SPEC's GIS
 * definitions (sky-view factor, openness) are built on these.
 *   - truth: the exact supremum over SPEC's bilinear surface (each crossed
 *     cell in closed form; double precision);
 *   - CPU reference and GLES: the gap search of the key lights with
 *     every cell solved (runtime/core/ray_bound.h "cells"): the max-pyramid
 *     skips the runs of the ray that cannot beat the best, and each cell
 *     it does not skip is solved in closed form (the surface along the ray
 *     is a quadratic there), so the result is the same supremum; the CPU
 *     in double precision (equal to the truth to rounding), GLES on the
 *     fp16 (hi, lo) heights, its angles returned as fp16 hi + lo (about
 *     1e-5 rad; BENCHMARKS.md "Every cell solved").
 * quality: NULL or filled by hfs_quality_defaults; only precision (GLES)
 * and threads (CPU, truth) are read.  Errors (one line): a bad desc, a
 * field over the backend's texture limit (GLES: the limit named). */
HFS_API int hfs_renderer_horizons(hfs_renderer *r, const hfs_field *field,
                                  const hfs_quality *quality, const hfs_horizon_desc *desc,
                                  float *out, hfs_error *err);

#endif /* HFSHADE_HORIZONS_H */
