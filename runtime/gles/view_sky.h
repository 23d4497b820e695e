/*
 * view_sky.h — the GLES 3-D view's background and haze (issue 41): the
 * environment map as a texture for view_sky.frag, and the HfsView fields
 * (u_bg, u_bg_rgb, u_haze, u_haze_in) filled from the camera's look
 * (runtime/core/view_look.h), the same numbers the truth's view reads.
 *
 * The map texture: the caps' RGBA format, the map's values times a power
 * of two that puts its largest |value| at 2^15 (fp16 then keeps 2^-11
 * relative precision over the 29 stops below it, where a sun of 1e5 next
 * to a sky of 1 would otherwise flush the sky to subnormals); a map wider
 * or taller than the caps' texture limit is halved (2 x 2 box means)
 * until it fits.  Rebuilt only when the map's pointer or size or the
 * environment's SH (which follows the map's contents) change; allocated
 * only while a view draws an env_map.
 */
#ifndef HFS_GLES_VIEW_SKY_H
#define HFS_GLES_VIEW_SKY_H

#include "gl_api.h"
#include "gl_caps.h"
#include "hfshade.h"
#include "uniform_blocks.h"
#include "view_camera.h"

typedef struct hfs_gles_view_sky {
    GLuint tex;
    const float *map;          /* what tex holds: the map, its size, its SH */
    int map_w, map_h, fp32;
    double sh[3][HFS_SH_COEFFS];
    double mul;                /* texel -> radiance (1 / the upload's scale) */
    double max;                /* the map's largest |value|                  */
} hfs_gles_view_sky;

/* Whether the view draws l's env_map (cam's background is the sky). */
int hfs_gles_view_sky_wanted(const hfs_camera *cam, const hfs_lighting *l);

/* The texture of l's env_map (hfs_gles_view_sky_wanted), uploaded when it
 * changed. */
int hfs_gles_view_sky_follow(hfs_gles_view_sky *s, const hfs_gl *gl, const hfs_gl_caps *c,
                             const hfs_lighting *l, hfs_error *err);
void hfs_gles_view_sky_free(hfs_gles_view_sky *s, const hfs_gl *gl);

/* The largest radiance the background shows besides the SH sky (the view
 * keeps it within fp16's range): the map's, the studio's top, the colour. */
double hfs_gles_view_look_bound(const hfs_camera *cam, const hfs_gles_view_sky *s, int map);

/* u_bg, u_bg_rgb, u_haze, u_haze_in for view scale `scale`. */
void hfs_gles_view_look_fill(hfs_gles_view_block *b, const hfs_camera *cam,
                             const hfs_lighting *l, const hfs_gles_view_sky *s, int map,
                             double scale);

#endif /* HFS_GLES_VIEW_SKY_H */
