/*
 * view_params.h — the public hfs_view (hfshade.h) checked and turned into
 * the neutral camera (view_camera.h) every backend's view is built from.
 */
#ifndef HFS_VIEW_PARAMS_H
#define HFS_VIEW_PARAMS_H

#include "hfshade.h"
#include "view_camera.h"

#define HFS_VIEW_MAX_SIZE 8192

/* One-line HFS_E_INVALID naming the field and its range, or HFS_OK. */
int hfs_view_check(const hfs_view *v, hfs_error *err);
void hfs_view_camera(const hfs_view *v, hfs_camera *cam);

#endif /* HFS_VIEW_PARAMS_H */
