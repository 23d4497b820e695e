/*
 * cli_picture.h — what hfshade render does to its PNG only (display
 * options; the linear outputs, PFM and GeoTIFF, keep SPEC's Lo):
 * --colormap terrain.  The exposure and the tone curve are hfs_io.h's
 * (hfs_exposure_auto, HFS_TONEMAP_HUE).
 */
#ifndef HFS_CLI_PICTURE_H
#define HFS_CLI_PICTURE_H

#include "hfs_io.h"

/* --colormap terrain: multiplies img (the lit grid of hm) by a colour of
 * the normalized height, lowland green to summit white. */
void cli_terrain_colormap(hfs_image *img, const hfs_heightmap *hm);

#endif /* HFS_CLI_PICTURE_H */
