/*
 * kiosk_map.h — the map: a field larger than the display, shown at the
 * display's resolution, panned and zoomed with the knobs (issue 40 item 4;
 * board/KIOSK.md "The map"; the actions map.pan_x, map.pan_y, map.zoom of
 * docs/INPUT.md).
 *
 * Levels.  Level 0 is the field itself, a texel a pixel; level L holds the
 * 2x2 means of level L - 1 (heights, and the albedo map when the scene has
 * one), cells 2^L dx wide, down to the first level that fits the display:
 * the whole field on the screen.  Each level is lit as a field of its own,
 * so at a coarse level shadows and the sky's occlusion come from the
 * terrain at that level's resolution (a map's level of detail).
 *
 * Tiles.  A level is cut into tiles of T x T texels.  A tile is lit by
 * rendering a window of its level around it, grown on every side by the
 * halo that level's relief and the lights need (hfs_tile_halo,
 * runtime/renderer/tiled_render.h: terrain beyond it cannot rise above an
 * elevation the lights care about; the whole level with a local light), so
 * a mountain outside the view still shades it; the tile keeps the window's
 * inner part.  Windows start on multiples of HFS_TILE_ALIGN, so every
 * tile's sub-sampled visibility grid lies on the level's.  T is
 * KIOSK_MAP_TILE, or where the halo is wider twice the halo (at most
 * KIOSK_MAP_TILE_MAX), so that a window costs at most about 4x its tile.
 *
 * The cache.  Lit tiles are kept up to a byte budget set by the display:
 * the tiles of the view and of a ring one tile wide around it, and of the
 * view one level in and one out, at the level whose tiles take the most
 * bytes.  So memory is bounded by the display and the halo, not by the
 * field.  A frame composes the view from the cache; a tile it lacks is
 * shown from the nearest coarser level whose tiles cover it (`coarse`:
 * each of their texels on the 2^k x 2^k texels it covers), or, where no
 * level has it, rendered at once (`rendered`: the one stall, a fresh map's
 * or a relit one's first frame).  kiosk_map_prefetch renders one missing
 * tile a call, in this order: the view's own (each one means the view is
 * to be shown again), the ring around the view (the nearest to its centre
 * first), the view one level in, one level out; so a pan step of up to a
 * tile, or a zoom step, finds its tiles lit, and a longer one shows the
 * coarser level at once and sharpens tile by tile.  A tile the budget
 * needs back is the one wanted longest ago.
 *
 * A change of the lighting or the quality (a knob) drops every tile; new
 * heights (another field, a capture's: the serial) rebuild the levels too.
 */
#ifndef HFS_KIOSK_MAP_H
#define HFS_KIOSK_MAP_H

#include <stddef.h>

#include "scene_load.h"

#define KIOSK_MAP_TILE 256
#define KIOSK_MAP_TILE_MAX 1024

typedef struct kiosk_map kiosk_map;

/* The levels a w x h field needs on a dw x dh display: 1 when it fits
 * (no map), more when it is wider or taller. */
int kiosk_map_levels_for(int w, int h, int dw, int dh);

/* A map of in's field for a display of dw x dh pixels.  0, or an error. */
int kiosk_map_create(const hfs_scene_inputs *in, int dw, int dh, kiosk_map **out,
                     hfs_error *err);
void kiosk_map_free(kiosk_map *m); /* NULL ok */

int kiosk_map_levels(const kiosk_map *m);

/* The size of the view at level: the display's, or the level's where it
 * is smaller. */
void kiosk_map_view_size(const kiosk_map *m, int level, int *w, int *h);

/* The view of level `level` centred on (cx, cy) (texels of level 0; kept
 * so that the view stays on the field) into out, sized by
 * kiosk_map_view_size: linear RGB as hfs_renderer_render writes it.  The
 * tiles missing are rendered now with r. */
int kiosk_map_frame(kiosk_map *m, hfs_renderer *r, const hfs_scene_inputs *in, double cx,
                    double cy, int level, hfs_image *out, hfs_error *err);

/* Renders the first tile the last view wants and lacks (above): 2 when it
 * rendered one of the view's own (show the view again), 1 one ahead of it,
 * 0 when none is wanted (or the budget holds no more). */
int kiosk_map_prefetch(kiosk_map *m, hfs_renderer *r, const hfs_scene_inputs *in,
                       hfs_error *err);

typedef struct kiosk_map_stats {
    int level;             /* of the last frame                            */
    double x, y;           /* its centre, texels of the field (as asked)   */
    int rendered;          /* tiles the last frame rendered itself         */
    int coarse;            /* tiles it showed from a coarser level         */
    int cached;            /* tiles held now                               */
    size_t bytes, budget;  /* the lit tiles' bytes, and the budget          */
    size_t level_bytes;    /* the levels above 0 (heights, albedo)         */
    long prefetched;       /* tiles kiosk_map_prefetch rendered, in all    */
    double last_tile_ms;   /* the last tile's render                        */
} kiosk_map_stats;

void kiosk_map_stats_get(const kiosk_map *m, kiosk_map_stats *s);

#endif /* HFS_KIOSK_MAP_H */
