/*
 * field_geom.h — SPEC.md's height-field geometry, shared by the CPU reference
 * and the ground truth so that both use exactly the same surface: bilinear
 * heights between grid points, central-difference normals, world units.
 */
#ifndef HFS_FIELD_GEOM_H
#define HFS_FIELD_GEOM_H

#include "hfshade.h"

/* World height zscale*H at grid point (i, j); no bounds check. */
static inline double hfs_field_z(const hfs_field *f, int i, int j)
{
    return f->zscale * (double)f->z[(size_t)j * (size_t)f->width + (size_t)i];
}

/* Bilinear world height at grid coordinates (gx, gy) (texel units, grid point
 * (i, j) at (i, j)).  Returns 0 and leaves *z untouched when the point lies
 * outside [0, W-1] x [0, H-1]: outside the grid the terrain does not exist. */
int hfs_field_bilinear(const hfs_field *f, double gx, double gy, double *z);

/* Unit normal at grid point (i, j): central differences of world z (one-sided
 * at the border), N = normalize(-dz/dx, -dz/dy, 1). */
void hfs_field_normal(const hfs_field *f, int i, int j, double n[3]);

/* The smallest and largest height sample (the field's units, before
 * zscale). */
void hfs_field_range(const hfs_field *f, double *lo, double *hi);

/* Direction s(phi, e) = (cos phi cos e, sin phi cos e, sin e). */
void hfs_dir(double phi, double e, double s[3]);

#endif /* HFS_FIELD_GEOM_H */
