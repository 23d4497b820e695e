/*
 * truth_raycast.h — exact visibility queries against SPEC.md's bilinear
 * height field, for the ground truth (truth.c) and its tests.
 *
 * Geometry: grid point (i, j) sits at grid coordinate (i, j) = world
 * (i*dx, j*dx); heights are world z = zscale*H, bilinear inside each cell
 * [i, i+1] x [j, j+1]; outside [0, W-1] x [0, H-1] there is no terrain.
 *
 * Acceleration: a max-height quadtree ("max mip") over the cells.  Level 0
 * holds, per cell, the maximum of its four corner heights, which bounds the
 * bilinear patch (a convex combination of its corners); level l+1 holds the
 * max of 2x2 nodes of level l.  Stored as float rounded UP, and every test
 * adds a small margin (rounding), so skipping is conservative: the
 * accelerated queries return exactly what the plain ones would (the tests
 * check this bit for bit).
 *
 * Immutable after hfs_truth_grid_init; safe to share between threads.
 */
#ifndef HFS_TRUTH_RAYCAST_H
#define HFS_TRUTH_RAYCAST_H

#include "hfshade.h"

#define HFS_TRUTH_MAX_LEVELS 32

typedef struct hfs_truth_grid {
    const hfs_field *f;            /* not owned; must outlive the grid       */
    int w, h;                      /* field size (grid points)                */
    int n_levels;                  /* levels 0 (cells) .. n_levels-1 (1x1)    */
    int lw[HFS_TRUTH_MAX_LEVELS];  /* nodes per row at each level            */
    int lh[HFS_TRUTH_MAX_LEVELS];
    float *zmax[HFS_TRUTH_MAX_LEVELS]; /* node maxima, world units, owned   */
    double margin;                 /* added to every node max (rounding)      */
    double z_lo, z_hi;             /* min / max world height over the field   */
} hfs_truth_grid;

/* Builds the max mip.  Returns HFS_OK or HFS_E_NOMEM (grid left empty). */
int hfs_truth_grid_init(hfs_truth_grid *g, const hfs_field *f);
void hfs_truth_grid_free(hfs_truth_grid *g);

/* ---- environment horizons ------------------------------------------------- */

/* hfs_truth_horizon: tangent of the horizon seen from grid point (i, j) at
 * world height z0 (the lifted receiver) along the horizontal direction
 * (c, s) (unit, grid axes): the supremum over the ray's points t > 0
 * (texels) of (z(p(t)) - z0) / (t dx), p(t) = (i + t c, j + t s), z the
 * bilinear surface, up to where the ray leaves the grid.  Exact: per
 * crossed cell the surface along the ray is a quadratic in t, and the
 * maximum of that slope is taken in closed form (truth_horizon.c).
 * For callers that do not care about slopes at or below `cutoff` (e.g. the
 * tangent of the tangent-plane elevation, rounded down; -INFINITY for none)
 * it skips what cannot exceed cutoff (the quadtree, early exit) and returns
 * the supremum when that exceeds cutoff, else -INFINITY.  hint (may be
 * NULL): in, a distance (texels) whose cell is examined first (e.g. where
 * the neighbouring azimuth's maximum lay; any value is safe); out, where
 * this maximum lies (0 if none exceeds cutoff).  The hint changes only the
 * speed, never the result. */
double hfs_truth_horizon(const hfs_truth_grid *g, int i, int j, double z0, double c,
                         double s, double cutoff, double *hint);

/* The same supremum over distances t in (0, t_max] texels only (INFINITY:
 * to the edge), no cutoff (-INFINITY when the ray crosses no cell within
 * t_max): the GIS horizons' search radius (hfs_renderer_horizons). */
double hfs_truth_horizon_within(const hfs_truth_grid *g, int i, int j, double z0, double c,
                                double s, double t_max, double *hint);

/* The same supremum, every crossed cell solved (no quadtree, no cutoff;
 * -INFINITY when the ray crosses no cell): for tests. */
double hfs_truth_horizon_plain(const hfs_truth_grid *g, int i, int j, double z0, double c,
                               double s);

/* ---- exact rays ----------------------------------------------------------------- */

/* Does the ray from o (o[0], o[1] in grid coordinates, inside the grid;
 * o[2] world z) along the world unit direction d hit the bilinear surface at
 * a world distance t in [0, tmax] (tmax may be INFINITY)?  "Hit" means the
 * ray is at or below the surface somewhere on that segment inside the grid;
 * the ray stops testing where its xy projection leaves the grid.  Exact:
 * per crossed cell (2D DDA, vertical rays and rays along grid lines
 * included), the ray height minus the bilinear height is a quadratic in t
 * whose minimum over the cell's segment is evaluated in closed form.
 * Uses the quadtree to skip nodes the ray passes above.  Returns 1 or 0. */
int hfs_truth_ray_hits(const hfs_truth_grid *g, const double o[3],
                       const double d[3], double tmax);

/* The same, and where: on a hit *t is the smallest world distance in
 * [0, tmax] at which the ray is at or below the surface (the first
 * crossing cell's quadratic solved in closed form; the bounces' gather
 * reads the previous bounce's radiance there). */
int hfs_truth_ray_first_hit(const hfs_truth_grid *g, const double o[3], const double d[3],
                            double tmax, double *t);

/* The same without the quadtree (every crossed cell is solved): for tests. */
int hfs_truth_ray_hits_plain(const hfs_truth_grid *g, const double o[3],
                             const double d[3], double tmax);

#endif /* HFS_TRUTH_RAYCAST_H */
