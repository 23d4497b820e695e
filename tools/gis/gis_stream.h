/*
 * gis_stream.h — the GIS products of a DEM larger than a tile,
 * window by window, so that memory stays bounded (issue 39 item 1): the
 * whole-DEM path (gis_command.c) holds the DEM, the product and its
 * encoded file at once (3.0 GB of RSS for an 8192x6144 sky-view factor).
 *
 * When: --tile N > 0 and the DEM wider or taller than N; a search radius
 * (--radius, or openness's default; sun: the reach of its shadows, cut by
 * --radius; insolation: --radius, for its sky); square cells (gis_dem.h
 * `square`: a projected CRS's); not sun or insolation on the truth (it
 * renders the whole DEM); and a window smaller than the DEM (a halo can
 * span it).  Otherwise the DEM is
 * computed whole, and gis_stream_choose says why (the summary line):
 *   - without a radius every horizon may reach the DEM's edge: no halo
 *     short of the whole DEM is enough;
 *   - non-square cells are resampled to square ones node-aligned over the
 *     whole grid (hfs_gdal_make_square), which windows cannot reproduce.
 *
 * How: output windows of at most N x N texels, row by row; each is read
 * grown by a halo of ceil(radius / cell) + 2 texels (DESIGN.md "GIS
 * horizons", Tiles: a search within the radius reads nothing farther),
 * then widened outwards to multiples of GIS_STREAM_ALIGN texels, cut to
 * the DEM.  The window is read with GDAL's windowed RasterIO, its holes
 * filled within it (gis_dem_read_window), its product computed as the
 * whole DEM's is (gis_products.h, the same hfs_renderer_horizons calls
 * with the same radius, on the run's one renderer), and the inner part
 * written into the output (gis_raster_stream.h: a GTiff created up front
 * as a temporary of the run's outputs, renamed into place when every
 * window is written; --cog made from it at the end).
 *
 * What equals the whole-DEM run: every texel's search reads only its own
 * window's heights, so the CPU reference and the truth give the same
 * bits; the GLES path normalizes each field it uploads by its own height
 * range, so its windows differ at fp16's level (no seam larger than that).
 * The hole fill (push-pull, hfs_height_fill_holes) is the one step that
 * sees past the radius: its 2x2 blocks line up with the whole DEM's
 * because a window starts and ends on multiples of GIS_STREAM_ALIGN (or
 * on the DEM's edge), so a hole that the fill's first log2(ALIGN) levels
 * close (up to about ALIGN / 2 texels across) away from the window's own
 * edge fills exactly as in the whole DEM.  A larger hole may fill
 * differently; its texels are nodata either way, only its neighbours'
 * horizons can change.
 */
#ifndef HFS_GIS_STREAM_H
#define HFS_GIS_STREAM_H

#include "gis_dem.h"

/* Windows start and end on multiples of this many texels (or the DEM's
 * edge): the hole fill's blocks (above). */
#define GIS_STREAM_ALIGN 16

typedef enum gis_stream_mode {
    GIS_WHOLE = 0,         /* the DEM fits a tile (or --tile 0)              */
    GIS_WHOLE_NO_RADIUS,   /* over a tile, but no radius                     */
    GIS_WHOLE_NOT_SQUARE,  /* over a tile, but its cells are not square      */
    GIS_WHOLE_HALO,        /* over a tile, but a window and its halo span it */
    GIS_WHOLE_TRUTH,       /* sun, insolation on the truth: it renders the
                              whole DEM's exact shadows                      */
    GIS_WHOLE_NIGHT,       /* sun below the horizon: zeros, nothing searched */
    GIS_STREAMED           /* window by window                               */
} gis_stream_mode;

/* How dem is computed with tiles of `tile` texels a side (0: never
 * windows) and a search radius of `radius` metres (0: the whole DEM; sun
 * and insolation: gis_sun_choose's); *halo the halo in texels when
 * streamed. */
gis_stream_mode gis_stream_choose(const gis_dem *dem, int tile, double radius, int *halo);

/* The summary line's words for mode ("" for GIS_WHOLE; "windows" for
 * GIS_STREAMED is the caller's, with the count). */
const char *gis_stream_why(gis_stream_mode mode);

struct gis_run;

/* Computes and writes the run's product window by window (the run's dem
 * opened with gis_dem_open, described, its renderer made; its outputs
 * added): r->windows the windows computed, r->dem.holes the DEM's holes.
 * 0, or an error (the run's outputs then hold only temporaries). */
int gis_stream_write(struct gis_run *r, hfs_error *err);

#endif /* HFS_GIS_STREAM_H */
