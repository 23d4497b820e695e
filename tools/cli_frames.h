/*
 * cli_frames.h — the render command's frames: one frame of a scene's
 * inputs (the lit grid, and its 3-D view when there is one), and --time's
 * timed frames with their per-pass medians.
 */
#ifndef HFS_CLI_FRAMES_H
#define HFS_CLI_FRAMES_H

#include "scene_load.h"

/* One frame: the lit grid into img, and with a view (v not NULL) its view
 * into vimg too; progress as hfs_renderer_render takes it (NULL: none). */
int cli_render_once(hfs_renderer *r, const hfs_scene_inputs *in, const hfs_view *v,
                    hfs_image *img, hfs_image *vimg, hfs_progress_fn progress, void *user,
                    hfs_error *err);

/* --time N: one warm-up frame, then n full frames (caches invalidated so
 * every pass runs), per-pass medians, the GPU's and the frame's, and the
 * texture memory on stdout.  img (and vimg) hold the last frame. */
int cli_time_frames(int n, hfs_renderer *r, const hfs_scene_inputs *in, const hfs_view *v,
                    hfs_image *img, hfs_image *vimg, hfs_error *err);

#endif /* HFS_CLI_FRAMES_H */
