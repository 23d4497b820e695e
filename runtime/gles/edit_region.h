/*
 * edit_region.h — where an edit of the heights can change a GLES frame
 * (issue 38; DESIGN.md "Local edits"): pure functions, no GL, unit-tested
 * without a driver (tests/test_edit_region.c).
 *
 * A frame after an edit recomputes, pass by pass, only the texels whose
 * inputs may have changed, and keeps the others as the last frame left
 * them; the result equals a cold frame bit for bit because each texel is
 * computed by the same shader from the same inputs either way.  So every
 * region here must be CONSERVATIVE: it may hold texels that turn out
 * unchanged (they are recomputed to the same bits), never miss one that
 * changes.
 *
 *   box     the texels whose heights changed (hfs_edit_find), and the
 *           highest normalized height any of them had before or has now
 *           (hfs_edit_top: what the edit could raise a horizon to);
 *   tiles   a mask of HFS_EDIT_TILE^2 texel tiles, the form every pass's
 *           region takes: grown by a reach (hfs_tiles_grow), united, and
 *           drawn as scissor rectangles (hfs_tiles_rects);
 *   reach   how far a change travels through the pyramid's levels
 *           (hfs_edit_layer_reach) and through the environment's near
 *           search (hfs_edit_env_near_reach);
 *   sweep   the texels whose rays toward a key light can meet the box
 *           above the light's window (hfs_edit_sweep).
 */
#ifndef HFS_EDIT_REGION_H
#define HFS_EDIT_REGION_H

#include "layout.h"

#include <stddef.h>

#define HFS_EDIT_TILE 16

/* Texels [x0, x1] x [y0, y1], inclusive; empty when x1 < x0. */
typedef struct hfs_edit_box {
    int x0, y0, x1, y1;
} hfs_edit_box;

/* A w x h field's tiles (tw x th); `all`: every tile, whatever `on` says. */
typedef struct hfs_tiles {
    int w, h, tw, th;
    int all;
    unsigned char *on; /* tw * th */
    size_t cap;
} hfs_tiles;

/* A scissor rectangle in texels: [x, x + w) x [y, y + h). */
typedef struct hfs_edit_rect {
    int x, y, w, h;
} hfs_edit_rect;

/* The box of texels whose values differ bit for bit between a and b (w x h,
 * row-major); 0 when none does. */
int hfs_edit_find(const float *a, const float *b, int w, int h, hfs_edit_box *box);

/* The highest normalized height (layout.h: (z - base) / hscale) in the box
 * of either field, rounded up by 1e-4 (more than the fp16 hi + lo pairs'
 * and the bilinear filter's rounding). */
double hfs_edit_top(const hfs_gles_layout *L, const float *a, const float *b, int w,
                    hfs_edit_box box);

/* Box b grown by r texels on every side, clipped to w x h. */
hfs_edit_box hfs_edit_box_grow(hfs_edit_box b, int r, int w, int h);

/* 0, or -1 when out of memory; the mask starts empty. */
int hfs_tiles_init(hfs_tiles *t, int w, int h);
void hfs_tiles_free(hfs_tiles *t);
void hfs_tiles_clear(hfs_tiles *t);
void hfs_tiles_set_all(hfs_tiles *t);
/* Marks the tiles box b (clipped) touches. */
void hfs_tiles_add_box(hfs_tiles *t, hfs_edit_box b);
/* dst |= src's texels grown by r texels (dst and src of one size). */
void hfs_tiles_add_grown(hfs_tiles *dst, const hfs_tiles *src, int r);
/* Whether any tile is marked (all counts). */
int hfs_tiles_any(const hfs_tiles *t);
/* The marked tiles as rectangles in texels (runs along a row, merged with
 * the same run in the rows below), clipped to the field; at most
 * tw * th of them.  Returns how many it wrote to out. */
int hfs_tiles_rects(const hfs_tiles *t, hfs_edit_rect *out);

/* How far (texels) from a changed height a bilinear read of reconstructed
 * layer `layer` (layout.h read_layer: 0 the coarsest read, n_layers - 1 the
 * input) can change: the read's own cell, and for a filtered level its
 * decimation chain (each level samples the finer one bilinearly) and its
 * B-spline reconstruction (two of its spacings each side). */
double hfs_edit_layer_reach(const hfs_gles_layout *L, int layer);

/* How far the environment's near search on the grid reads (texels): the
 * scales from index `coarsest` to the finest, each refined up to 2^(1/k)
 * of its distance, plus the reach of the layer it reads. */
double hfs_edit_env_near_reach(const hfs_gles_layout *L, int coarsest);

/* The texels p whose ray p + t (cos, sin) for 0 <= t <= t_max meets box e
 * (in texels, continuous): the box e swept backwards by t_max, as a box
 * clipped to w x h (t_max <= 0: e itself). */
hfs_edit_box hfs_edit_sweep(hfs_edit_box e, double c, double s, double t_max, int w, int h);

/* The largest distance at which an occluder as high as `top` (normalized)
 * can rise above slope `slope` (tan of the light's lowest elevation, in the
 * units of rise = hscale zscale / dx per normalized height) seen from any
 * texel of the field (none lower than vmin): (top - vmin) rise / slope,
 * or HUGE_VAL where the slope is not above 0. */
double hfs_edit_reach_above(double top, double vmin, double rise, double slope);

/* The margin the key factor's test (key_visibility.frag edit_reaches)
 * allows below a light's lowest slope: a bound within it counts. */
double hfs_edit_slope_margin(double slope);

#endif /* HFS_EDIT_REGION_H */
