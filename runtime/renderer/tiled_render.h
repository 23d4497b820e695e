/*
 * tiled_render.h — a lit frame of a field larger than the backend can hold
 * at once, rendered in tiles (issue 39 item 1; DESIGN.md "GIS horizons",
 * "Tiles").  Each tile's inner part is rendered with a halo of heights
 * around it and kept; the halo is sized from the field's relief and the
 * lights, so that what lies beyond it cannot rise above an elevation the
 * scene cares about:
 *   - a key light of elevation e and radius a: nothing below e - a can
 *     shadow it (exactly);
 *   - the environment (and the light bounced from it): terrain below
 *     HFS_TILE_SKY_EPS (1.27 deg: sin^2 of it is 2^-11, fp16's step) above
 *     a receiver's horizontal takes less than that share of a horizontal
 *     receiver's sky;
 *   - the halo is then zscale (zmax - zmin) / (dx tan eps) texels (+ 2),
 *     the farthest terrain can stand and still rise eps above the lowest
 *     receiver.
 * Local lights need the terrain between receiver and light, anywhere: a
 * frame with one is not tiled (one line, the way out).  Origins are
 * aligned to HFS_TILE_ALIGN texels so that every tile's sub-sampled grids
 * fall on the whole field's.
 */
#ifndef HFS_TILED_RENDER_H
#define HFS_TILED_RENDER_H

#include "hfshade.h"

#define HFS_TILE_SKY_EPS 0.02216 /* radians: asin(sqrt(2^-11)) */
#define HFS_TILE_ALIGN 16
/* The side every backend renders in one frame (ES 3.0's minimum texture
 * size): below it no backend is asked for its limit. */
#define HFS_TILE_MIN_SIDE 2048

/* Renders field f into out (W x H) tile by tile through render (the
 * backend's frame of a sub-field, its own lighting), tiles of at most
 * max_side texels a side (`limit`: the backend's limit as a refusal names
 * it).  0, or an error (one line): the halo needed leaves no room in such
 * tiles, a local light, or the frame's own. */
typedef int (*hfs_tile_frame_fn)(void *ctx, const hfs_field *f, const hfs_lighting *l,
                                 hfs_image *out, hfs_error *err);
int hfs_tiled_render(const hfs_field *f, const hfs_lighting *l, int max_side, const char *limit,
                     hfs_tile_frame_fn render, void *ctx, hfs_image *out, hfs_error *err);

/* The sub-field [x0, x0 + w) x [y0, y0 + h) of f with its heights copied
 * into z (w*h) and, when l has an albedo map, its albedo into alb
 * (w*h*3; NULL without one); *sl = l with world positions (local lights,
 * a viewer's eye) moved with the window and albedo_map = alb.  Also the
 * kiosk's map (board/kiosk_map.h) cuts its tiles' windows with it. */
hfs_field hfs_tile_sub_field(const hfs_field *f, const hfs_lighting *l, int x0, int y0, int w,
                             int h, float *z, float *alb, hfs_lighting *sl);

/* Tile (tx, ty) of a width x height grid cut into tiles of `tile` texels,
 * row by row: its part (ix, iy, iw x ih) and the window read for it: the
 * part grown by halo texels on every side, widened outwards to multiples
 * of HFS_TILE_ALIGN (so that sub-sampled and hole-filling grids fall on
 * the whole grid's), cut to the grid.  The jobs of `hfshade tiles` and
 * the GIS commands' streamed windows (tools/gis/gis_stream.h) are these. */
typedef struct hfs_tile_window {
    int x0, y0, w, h;     /* the window read                              */
    int ix, iy, iw, ih;   /* the part kept                                */
} hfs_tile_window;
hfs_tile_window hfs_tile_window_of(int width, int height, int tile, int halo, int tx, int ty);

/* The lowest elevation (radians) terrain must rise to for lighting l to
 * see it, as above (the environment's eps, each key light's e - a); 0
 * when terrain at any elevation matters (a local light, a key light at or
 * below its own radius). */
double hfs_tile_eps(const hfs_lighting *l);

/* The halo (texels) f's relief needs under lighting l, as above; -1 when
 * no halo short of the whole field is enough (a key light at or below
 * its own radius, a local light). */
int hfs_tile_halo(const hfs_field *f, const hfs_lighting *l);

#endif /* HFS_TILED_RENDER_H */
