/*
 * field_geom.h — SPEC.md's height-field geometry, shared by the CPU reference
 * and the ground truth so that both use exactly the same surface: bilinear
 * heights between grid points, central-difference normals, world units.
 */
#ifndef HFS_FIELD_GEOM_H
#define HFS_FIELD_GEOM_H

#include "hfshade.h"

#include <math.h>

/* World height zscale*H at grid point (i, j); no bounds check. */
static inline double hfs_field_z(const hfs_field *f, int i, int j)
{
    return f->zscale * (double)f->z[(size_t)j * (size_t)f->width + (size_t)i];
}

/* The receiver's lift (SPEC): a ray from grid point (i, j) starts 1e-4 dx
 * above it (no self-hits). */
#define HFS_FIELD_LIFT 1e-4

/* World height of grid point (i, j) lifted by HFS_FIELD_LIFT dx, or, where
 * that lift is below the height's resolution (dx 1e-9 under heights of
 * 1e6: the lift would round away and every ray would start on the
 * surface, a hit at its first point), the next double above the height:
 * the least lift there is.  Usual fields keep the SPEC's lift exactly. */
static inline double hfs_field_lifted_z(const hfs_field *f, int i, int j)
{
    const double z = hfs_field_z(f, i, j), z0 = z + HFS_FIELD_LIFT * f->dx;
    return z0 > z ? z0 : nextafter(z, HUGE_VAL);
}

/* Bilinear world height at grid coordinates (gx, gy) (texel units, grid point
 * (i, j) at (i, j)).  Returns 0 and leaves *z untouched when the point lies
 * outside [0, W-1] x [0, H-1]: outside the grid the terrain does not exist. */
int hfs_field_bilinear(const hfs_field *f, double gx, double gy, double *z);

/* Unit normal at grid point (i, j): central differences of world z (one-sided
 * at the border), N = normalize(-dz/dx, -dz/dy, 1). */
void hfs_field_normal(const hfs_field *f, int i, int j, double n[3]);

/* The highest slope (tangent of the elevation, world units) of the bilinear
 * surface seen from grid point (i, j) toward unit direction (c, s) within
 * (i, j)'s own cell, the one the ray crosses first (SPEC: the surface
 * includes the receiver's own cells).  Along the ray z(t) - z(0) =
 * t (A + B t) there (A: the one-sided slopes, B: the cell's twist), so the
 * slope A + B t is highest at one end: t -> 0 or the cell's far edge at
 * t = 1 / max(|c|, |s|).  Multi-scale horizons sample distances >= 1 texel
 * only and miss the first (a receiver on a twisted cell, e.g. a saddle,
 * sees its steepest occluder arbitrarily close).  -DBL_MAX when the cell
 * lies off the grid.  c, s with |c| or |s| < 1e-12 count as 0. */
double hfs_field_first_cell_slope(const hfs_field *f, int i, int j, double c, double s);
/* The same, with its two ends: the near end's slope (t -> 0) into *near,
 * the far edge's (z at the far edge over its distance) into *far; the
 * surface along the ray is z(t) - z(0) = t (near + (far - near) t / t_far)
 * (the bounce walk's own cell, issue 36: a ray below the near slope hits
 * the cell at once).  Both -DBL_MAX off the grid. */
double hfs_field_first_cell(const hfs_field *f, int i, int j, double c, double s, double *near,
                            double *far);

/* Bilinear value of a W x H grid of RGB triples (rgb, row-major, row j = 0
 * first) at grid coordinates (gx, gy), clamped into the grid: the exit
 * radiance a bounce reads where a ray or a horizon sample meets the
 * terrain (SPEC "Indirect light"). */
void hfs_rgb_bilinear(const float *rgb, int w, int h, double gx, double gy, double out[3]);

/* The smallest and largest height sample (the field's units, before
 * zscale). */
void hfs_field_range(const hfs_field *f, double *lo, double *hi);

/* Direction s(phi, e) = (cos phi cos e, sin phi cos e, sin e). */
void hfs_dir(double phi, double e, double s[3]);

/* The horizontal direction (cos phi, sin phi) of a GIS horizon
 * (hfs_renderer_horizons), a component under 1e-12 made 0: sin(pi) is
 * 1.2e-16, and a ray from the field's last row at that tilt leaves the grid
 * at once, where the user asked for the row itself. */
void hfs_horizon_dir(double phi, double *c, double *s);

#endif /* HFS_FIELD_GEOM_H */
