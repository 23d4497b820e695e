/*
 * truth_view.h — the ground truth of the 3-D view (issue 16, deliverables
 * 4-5): a camera ray per pixel (view_camera.h) against the bilinear
 * surface with the view's vertical exaggeration (exact first hit,
 * truth_raycast.h), shaded with the lit field's exit radiance read
 * bilinearly at the hit's grid position (diffuse: the radiance does not
 * depend on the view); a ray that misses the field shows the camera's
 * background in its direction (cam->look, view_look.h: the environment
 * map itself or the SH sky, rotated as lit, black without one; a studio
 * grey; a colour), and what it meets is seen through the look's haze.
 * Objects (obj, in the view's world: z times the exaggeration; NULL for
 * none) are boxes in front of whatever lies behind them, shaded with their
 * lit face grids (objects.h).  One sample per pixel, at its centre.
 */
#ifndef HFS_TRUTH_VIEW_H
#define HFS_TRUTH_VIEW_H

#include "hfshade.h"
#include "objects.h"
#include "view_camera.h"

/* view (w*h*3 floats, row 0 at the top) of field f lit as `lit` (its
 * W*H*3 exit radiance) under lighting l (for the background).  Returns
 * HFS_OK or HFS_E_NOMEM. */
int hfs_truth_view(const hfs_field *f, const float *lit, const hfs_lighting *l,
                   const hfs_camera *cam, const hfs_object_set *obj, int w, int h, float *view,
                   int threads, hfs_error *err);

#endif /* HFS_TRUTH_VIEW_H */
