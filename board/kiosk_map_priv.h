/*
 * kiosk_map_priv.h — the map's state, shared by kiosk_map.c (the tiles:
 * cache, view, prefetch) and kiosk_map_levels.c (the levels and the
 * windows tiles are lit from).  Private to the map.
 */
#ifndef HFS_KIOSK_MAP_PRIV_H
#define HFS_KIOSK_MAP_PRIV_H

#include <stdint.h>

#include "kiosk_map.h"

/* Levels: a 2^31-texel side halves to one texel in 31 steps. */
#define KIOSK_MAP_MAX_LEVELS 32
/* The blocks a tile's halo is sized from (kiosk_map_tile_halo). */
#define KIOSK_MAP_BLOCK 16

typedef struct kiosk_map_level {
    int w, h;
    float *z;                  /* w*h heights; level 0: the field's (not owned) */
    float *albedo;             /* NULL, or w*h*3; level 0: the lighting's      */
    double dx;                 /* 2^level dx                                   */
    int tile;                  /* T under the current lighting                 */
    int halo;                  /* the level's relief's, aligned (sizes T); -1:
                                  the whole level                              */
    float *bmax, *bmin;        /* bw x bh blocks of KIOSK_MAP_BLOCK texels:
                                  their highest and lowest heights             */
    int bw, bh;
} kiosk_map_level;

typedef struct kiosk_map_tile {
    int level, tx, ty, w, h;
    long wanted;               /* the stamp of the last view that wanted it   */
    float *rgb;                /* w*h*3                                       */
} kiosk_map_tile;

/* A tile a view wants, in the order prefetch renders them. */
typedef struct kiosk_map_want {
    int level, tx, ty;
} kiosk_map_want;

struct kiosk_map {
    int dw, dh, n_levels;
    kiosk_map_level lv[KIOSK_MAP_MAX_LEVELS];
    double zscale;
    uint64_t serial;           /* the heights the levels were built from      */
    const float *z0;
    hfs_lighting lighting;     /* what the tiles were lit with                */
    hfs_quality quality;
    int lit;                   /* lighting, quality and the tiles' sizes set  */
    kiosk_map_tile *tiles;
    int n_tiles, cap_tiles;
    size_t bytes, budget, level_bytes;
    long stamp;                /* counts views                                */
    kiosk_map_want *want;      /* the last view's wants                       */
    int n_want, cap_want, n_visible; /* the first n_visible: the view itself  */
    int view_level;
    double view_x, view_y;
    float *wz, *walb;          /* a window's heights and albedo              */
    hfs_image wimg;            /* its render                                  */
    size_t wcap;
    int rendered, coarse;
    long prefetched;
    double last_tile_ms;
};

/* Levels 1.. of in's field (level 0 is the field) for the map's display. */
int kiosk_map_levels_build(kiosk_map *m, const hfs_scene_inputs *in, hfs_error *err);
void kiosk_map_levels_free(kiosk_map *m);

/* The halo (texels, a multiple of HFS_TILE_ALIGN) the tile [ix, ix + iw)
 * x [iy, iy + ih) of level l needs for terrain beyond it to stay below
 * elevation eps (hfs_tile_eps) over all of the tile's texels; -1: the
 * whole level (eps 0).  From the tile's own lowest height and the highest
 * heights around it, ring by ring: terrain at least d texels away within
 * e = 5d/4 is below eps when (its highest - the tile's lowest) zscale <= d
 * dx tan(eps).  Never wider than the level's halo from its whole relief. */
int kiosk_map_tile_halo(const kiosk_map *m, int l, int ix, int iy, int iw, int ih, double eps);

/* The w x h window at (x0, y0) of level l as a field *f (the map's
 * scratch) with its lighting *wl (lit's, the albedo map and the world
 * positions moved with the window). */
int kiosk_map_window(kiosk_map *m, int l, int x0, int y0, int w, int h,
                     const hfs_lighting *lit, hfs_field *f, hfs_lighting *wl, hfs_error *err);

#endif /* HFS_KIOSK_MAP_PRIV_H */
