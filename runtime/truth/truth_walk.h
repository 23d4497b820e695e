/*
 * truth_walk.h — the cell walk both exact queries share (private to
 * runtime/truth/): a ray's horizontal path through the grid's cells, node by
 * node of the max mip (truth_raycast.h), in order of distance.
 */
#ifndef HFS_TRUTH_WALK_H
#define HFS_TRUTH_WALK_H

#include <math.h>

/* Parameter at which p0 + t*dir leaves [lo, hi] (dir != 0), else +inf. */
static inline double hfs_truth_exit_param(double p0, double dir, double lo, double hi)
{
    if (dir > 0.0)
        return (hi - p0) / dir;
    if (dir < 0.0)
        return (lo - p0) / dir;
    return INFINITY;
}

/* Index of the cell the ray enters at coordinate p moving with sign(dir);
 * a ray along a grid line (dir == 0) may take either neighbour (the bilinear
 * surface agrees on the shared edge), clamped into [0, ncell-1]. */
static inline int hfs_truth_cell_of(double p, double dir, int ncell)
{
    if (p < -2.0)
        p = -2.0;
    if (p > ncell + 2.0)
        p = ncell + 2.0;
    if (dir > 0.0)
        return (int)floor(p);
    if (dir < 0.0)
        return (int)ceil(p) - 1;
    int c = (int)floor(p);
    return c < 0 ? 0 : (c > ncell - 1 ? ncell - 1 : c);
}

/* The max mip's node of `level` holding cell (ci, cj): its index (nx, ny)
 * and the cells it spans, [x0, x1) x [y0, y1), clipped to the ncx x ncy
 * cells. */
typedef struct hfs_truth_node {
    int nx, ny, x0, y0, x1, y1;
} hfs_truth_node;

static inline hfs_truth_node hfs_truth_node_at(int ci, int cj, int level, int ncx, int ncy)
{
    hfs_truth_node n = {ci >> level, cj >> level, 0, 0, 0, 0};
    n.x0 = n.nx << level, n.y0 = n.ny << level;
    n.x1 = n.x0 + (1 << level) < ncx ? n.x0 + (1 << level) : ncx;
    n.y1 = n.y0 + (1 << level) < ncy ? n.y0 + (1 << level) : ncy;
    return n;
}

/* The ray (ox, oy) + t (u, v) leaves node nd at te = min(tx, ty) (its
 * exits along x and y): moves (*ci, *cj) to the cell it enters there (off
 * the grid when it leaves the grid). */
static inline void hfs_truth_walk_step(double ox, double oy, double u, double v, double te,
                                       double tx, double ty, const hfs_truth_node *nd,
                                       int ncx, int ncy, int *ci, int *cj)
{
    const int x0 = nd->x0, x1 = nd->x1, y0 = nd->y0, y1 = nd->y1;
    if (tx <= ty) {
        const int nci = u > 0.0 ? x1 : x0 - 1;
        if (v != 0.0) {
            int c = hfs_truth_cell_of(oy + te * v, v, ncy);
            c = v > 0.0 ? (c > *cj ? c : *cj) : (c < *cj ? c : *cj);
            *cj = c < y0 ? y0 : (c > y1 - 1 ? y1 - 1 : c);
        }
        *ci = nci;
    } else {
        const int ncj = v > 0.0 ? y1 : y0 - 1;
        if (u != 0.0) {
            int c = hfs_truth_cell_of(ox + te * u, u, ncx);
            c = u > 0.0 ? (c > *ci ? c : *ci) : (c < *ci ? c : *ci);
            *ci = c < x0 ? x0 : (c > x1 - 1 ? x1 - 1 : c);
        }
        *cj = ncj;
    }
}

#endif /* HFS_TRUTH_WALK_H */
