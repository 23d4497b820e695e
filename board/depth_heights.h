/*
 * depth_heights.h — depth frames (16-bit counts) to a height field: no
 * V4L2 here, only numbers (docs/CAPTURE.md "Depth to heights").
 *
 * Per frame:
 *   1. depth d = count * scale metres; 0 (the sensors' "no data") and
 *      anything outside [min_depth, max_depth] is invalid;
 *   2. height above the ground plane, metres: the plane is depth =
 *      a*u + b*v + c over the image's pixel coordinates (u right, v down),
 *      fitted once by least squares on the valid pixels of the first frame
 *      (or configured), height = plane(u, v) - d, so nearer the camera is
 *      higher.  For a camera looking straight down this is the distance to
 *      the plane; a tilted camera's is along its axis (no intrinsics);
 *   3. the region of interest resampled to the grid, area-averaged over
 *      the valid pixels of each cell (a cell no valid pixel falls in is a
 *      hole);
 *   4. the temporal filter, per cell (below);
 *   5. holes filled (hfs_height_fill_holes, push-pull), heights in world
 *      units = metres * zgain.  Never NaN or Inf.
 *
 * The filter (as AR sandboxes do, with a jump rule so a hand is followed):
 * each cell keeps its last `window` valid samples and the height it shows.
 * A sample farther than `jump` from the window's mean restarts the window
 * at that sample and is shown at once (a hand arriving or leaving: no
 * frame of lag).  Otherwise it joins the window; while the window fills
 * the mean is shown; once full, when the window's
 * standard deviation is at most `gate` (the cell is still) and its mean
 * differs from the shown height by more than `hysteresis`, the mean is
 * shown.  So sensor noise (spread below gate, drift below hysteresis)
 * leaves the picture still, and the renderer's planner sees no change.
 */
#ifndef HFS_BOARD_DEPTH_HEIGHTS_H
#define HFS_BOARD_DEPTH_HEIGHTS_H

#include <stddef.h>
#include <stdint.h>

#include "hfshade.h"

#define HFS_DEPTH_WINDOW_MAX 32

typedef struct hfs_depth_params {
    double scale;               /* metres per count (> 0)                      */
    double min_depth, max_depth;/* valid depths, metres; max 0 = no limit      */
    int plane_set;              /* 1: plane below; 0: fitted on the 1st frame  */
    double plane[3];            /* a, b, c: ground depth = a*u + b*v + c       */
    int roi[4];                 /* x, y, w, h in pixels; w == 0: whole frame   */
    int grid_w, grid_h;         /* the height field's size (>= 2 each)         */
    double zgain;               /* world units per metre of height (> 0)       */
    int window;                 /* samples averaged, 1..HFS_DEPTH_WINDOW_MAX;
                                   1 = no filter                               */
    double gate;                /* metres: max spread of a still cell           */
    double hysteresis;          /* metres: min change shown                     */
    double jump;                /* metres: a change this large is followed now  */
} hfs_depth_params;

/* The defaults (docs/CAPTURE.md says how they were measured): scale 0.001,
 * window 8, gate 3 mm, hysteresis 2.5 mm, jump 10 mm, zgain 1. */
void hfs_depth_params_defaults(hfs_depth_params *p);

typedef struct hfs_depth_heights hfs_depth_heights;

/* HFS_E_INVALID for a parameter out of range (one line naming it). */
int hfs_depth_heights_create(const hfs_depth_params *p, hfs_depth_heights **out,
                             hfs_error *err);
void hfs_depth_heights_destroy(hfs_depth_heights *h);   /* NULL ok */

/* Least-squares plane through the valid pixels of the ROI of one frame
 * (stride in bytes).  HFS_E_FORMAT when fewer than 3 are valid or they
 * are collinear. */
int hfs_depth_fit_plane(const hfs_depth_params *p, const uint8_t *depth, int width, int height,
                        int stride, double plane[3], hfs_error *err);

/* One frame of width x height 16-bit little-endian counts.  The ROI must
 * lie inside the frame.  Updates the heights; returns 1 when they changed
 * (some cell's shown height moved), 0 when not, <0 on error (a frame with
 * no valid pixel: HFS_E_FORMAT; the heights stay as they were). */
int hfs_depth_heights_push(hfs_depth_heights *h, const uint8_t *depth, int width, int height,
                           int stride, hfs_error *err);

/* grid_w * grid_h finite heights (world units), row 0 first: all 0 before
 * the first good frame.  Valid until the next push or destroy. */
const float *hfs_depth_heights_z(const hfs_depth_heights *h);
/* The grid's size. */
void hfs_depth_heights_grid(const hfs_depth_heights *h, int *width, int *height);
/* The plane in use (fitted or configured); 0 before one exists. */
int hfs_depth_heights_plane(const hfs_depth_heights *h, double plane[3]);
/* The unfiltered resampled heights of the last frame, metres (NaN = hole):
 * for measurements. */
const float *hfs_depth_heights_raw(const hfs_depth_heights *h);

#endif /* HFS_BOARD_DEPTH_HEIGHTS_H */
