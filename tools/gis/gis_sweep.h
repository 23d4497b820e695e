/*
 * gis_sweep.h — horizon angles of a whole field by a sweep (`--method
 * sweep` of the GIS commands, docs/GIS.md "The sweep"): an approximation
 * of hfs_renderer_horizons' exact supremum at a fraction of its cost, by a
 * line sweep with upper convex hulls (the way Timonen and Westerholm 2010,
 * "Scalable Height Field Self-Shadowing", find horizons).  No GDAL, no GL.
 *
 * Per azimuth the grid is swept along the parallel lines one texel apart
 * (across the azimuth's minor axis) that the azimuth's rays follow.  Each
 * texel's horizon is the larger of
 *   - the bilinear surface along its own ray over its first `near` columns,
 *     exactly (each cell's piece in closed form, the surface's slope as it
 *     leaves the texel included), and
 *   - beyond them, the tangent from the texel to the upper convex hull of
 *     the surface points of the line nearest its own ray (at most half a
 *     texel aside): its crossings with the columns and rows, and the top of
 *     each cell's piece that bulges above its chord (a twisted cell), kept
 *     as the sweep walks the line towards its start (each point enters the
 *     hull once; a texel's query is a binary search).
 * So a texel costs `near` cells and a search of a hull, whatever the
 * field's size, where the exact search reads on to the field's end.  What
 * it gives up, beyond `near` columns: the terrain read up to half a texel
 * aside of the ray, and a bulging piece taken at its top, not at the
 * tangent's own point (measured against the exact horizons in
 * BENCHMARKS.md "GIS rasters").
 */
#ifndef HFS_GIS_SWEEP_H
#define HFS_GIS_SWEEP_H

#include "hfshade.h"

/* The columns each texel reads exactly along its own ray before its line
 * takes over (more: less error, more time; BENCHMARKS.md "The sweep"). */
#define GIS_SWEEP_NEAR 4

/* Horizon angles of field f for the n azimuths phi[k] (SPEC's phi,
 * radians), as hfs_renderer_horizons gives them for a radius of 0 (the
 * whole field) and no window: out[(k H + j) W + i], radians, signed,
 * HFS_HORIZON_NONE where the texel's ray leaves the field at once.  The
 * azimuths are shared among `threads` workers (0: the machine's cores;
 * runtime/core/parallel.h), each computed by one, or, with fewer azimuths
 * than workers (a sun's one), each azimuth's lines in parts: every texel
 * is its nearest line's, so the result does not depend on the count.  0, or
 * HFS_E_NOMEM / HFS_E_INVALID with err filled. */
int gis_sweep_horizons(const hfs_field *f, const double *phi, int n, int threads, float *out,
                       hfs_error *err);

/* The same for the angles in [lo, hi] only (radians, -pi/2 <= lo <= hi <=
 * pi/2; hfs_horizon_desc's window): each result clamp(gamma, lo, hi), lo
 * where the ray meets no terrain.  A texel whose line's hull already rises
 * above hi skips its own columns, and one outside the window its
 * arctangent (a sun's disk wants 0.53 degrees of them).  With lo > 0 (a
 * sun above the horizontal) a line whose relief, or whose steepest rise
 * along the azimuth (with its offset from its texels' rays), stays below
 * lo skips its hull, or its texels' own columns, or both (a high sun's
 * lines do), and a texel whose own columns cannot rise to lo skips them:
 * the same values, from bounds that cannot miss (gis_sweep.c's
 * line_bounds, after the field's blocks: gis_sweep_blocks.h).  [-pi/2,
 * pi/2] is gis_sweep_horizons. */
int gis_sweep_horizons_in(const hfs_field *f, const double *phi, int n, int threads, double lo,
                          double hi, float *out, hfs_error *err);

#endif /* HFS_GIS_SWEEP_H */
