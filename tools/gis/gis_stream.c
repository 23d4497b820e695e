/*
 * gis_stream.c — see gis_stream.h.  Windows in rows from the DEM's first
 * row, each row's windows from its first column; after a row whose last
 * line ends a row of the files' 256 x 256 blocks (or the DEM), the files'
 * blocks and the DEM's are written and freed, so GDAL holds at most about
 * a row of windows of each.
 */
#include "gis_stream.h"

#include "gis_raster_stream.h"
#include "gis_run.h"
#include "tiled_render.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define BLOCK 256 /* the files' blocks (gis_raster_options) */

/* One window: the texels read (x0, y0, w, h) and the output's texels it
 * computes (ix, iy, iw, ih), both in the DEM's grid: the tiles' own
 * (tiled_render.h), GIS_STREAM_ALIGN being HFS_TILE_ALIGN. */
typedef hfs_tile_window window;
_Static_assert(GIS_STREAM_ALIGN == HFS_TILE_ALIGN, "one alignment for every tile");

static int min_i(int a, int b)
{
    return a < b ? a : b;
}

/* The window of tile (tx, ty).  halo <= width + height
 * (gis_stream_choose), so nothing overflows. */
static window window_of(const gis_dem *d, int tile, int halo, int tx, int ty)
{
    return hfs_tile_window_of(d->width, d->height, tile, halo, tx, ty);
}

gis_stream_mode gis_stream_choose(const gis_dem *dem, int tile, double radius, int *halo)
{
    *halo = 0;
    if (tile <= 0 || (dem->width <= tile && dem->height <= tile))
        return GIS_WHOLE;
    if (!(radius > 0.0))
        return GIS_WHOLE_NO_RADIUS;
    if (!dem->square)
        return GIS_WHOLE_NOT_SQUARE;
    const double cells = ceil(radius / dem->d) + 2.0, most = (double)dem->width + dem->height;
    *halo = cells < most ? (int)cells : (int)most;
    const window w = window_of(dem, tile, *halo, 0, 0);
    if (w.w == dem->width && w.h == dem->height)
        return GIS_WHOLE_HALO;
    return GIS_STREAMED;
}

const char *gis_stream_why(gis_stream_mode mode)
{
    switch (mode) {
    case GIS_WHOLE_NO_RADIUS:
        return "no --radius: every horizon may reach the DEM's edge";
    case GIS_WHOLE_NOT_SQUARE:
        return "cells not square: resampled over the whole grid";
    case GIS_WHOLE_HALO:
        return "a window with its halo spans the DEM";
    case GIS_WHOLE_TRUTH:
        return "the truth renders the whole DEM's shadows";
    case GIS_WHOLE_NIGHT:
        return "the sun is below the horizon: the raster is zeros";
    default:
        return "";
    }
}

/* What the windows share. */
typedef struct stream {
    gis_run *r;
    int n_out, n_bands;        /* files (horizon: one an azimuth); bands each */
    gis_raster_stream **out;
    double *phi;               /* horizon: the map azimuths                   */
    window win;                /* the window being computed                   */
    int ox, oy;                /* --job: its inner part's origin in the DEM   */
    double gt[6];              /* --job: the geotransform of that part        */
    float *inner;              /* n_bands x iw x ih: its output               */
} stream;

/* Band planes v of the window (w x h each) cut to its inner part, into
 * s->inner, and written into file k. */
static int write_inner(stream *s, int k, const float *v, hfs_error *err)
{
    const window *w = &s->win;
    const size_t n = (size_t)w->w * (size_t)w->h, m = (size_t)w->iw * (size_t)w->ih;
    for (int b = 0; b < s->n_bands; ++b)
        for (int j = 0; j < w->ih; ++j)
            memcpy(s->inner + (size_t)b * m + (size_t)j * (size_t)w->iw,
                   v + (size_t)b * n + (size_t)(w->iy - w->y0 + j) * (size_t)w->w +
                       (size_t)(w->ix - w->x0),
                   (size_t)w->iw * sizeof *v);
    return gis_raster_stream_write(s->out[k], w->ix - s->ox, w->iy - s->oy, w->iw, w->ih,
                                   s->inner, err);
}

static int write_horizon(void *user, int k, const float *deg, hfs_error *err)
{
    return write_inner(user, k, deg, err);
}

/* The window's product from its heights z and holes (a field of its own,
 * square cells of the DEM's), on the run's renderer, into v (n_bands
 * planes; horizon: written azimuth by azimuth instead). */
static int compute(stream *s, float *z, unsigned char *hole, float *v, hfs_error *err)
{
    const gis_run *r = s->r;
    const gis_args *a = r->a;
    const gis_dem *d = &r->dem;
    const gis_dem wd = {.width = s->win.w, .height = s->win.h, .hole = hole, .cx = d->d,
                        .cy = d->d, .square = 1, .ex = d->ex, .ey = d->ey, .sw = s->win.w,
                        .sh = s->win.h, .sz = z, .d = d->d};
    gis_compute c = r->c;
    c.dem = &wd;
    const size_t n = (size_t)s->win.w * (size_t)s->win.h;
    if (a->product == GIS_HORIZON)
        return gis_product_horizons(&c, s->phi, a->n_azimuths, write_horizon, s, err);
    if (a->product == GIS_SVF)
        return gis_product_svf(&c, a->directions, a->svf, v, err);
    if (a->product == GIS_SUN) /* c.relief: the whole DEM's (gis_run_open) */
        return gis_product_sun(&c, &r->sun, v, v + n, err);
    if (a->product == GIS_INSOLATION) {
        gis_period_stats st;
        const int all = s->n_bands > 1;
        return gis_product_insolation(&c, &r->period, v, all ? v + n : NULL,
                                      all ? v + 2 * n : NULL, &st, err);
    }
    return gis_product_openness(&c, a->directions, v, v + n, err);
}

/* One window: read, filled, computed, its inner part written. */
static int one_window(stream *s, hfs_error *err)
{
    gis_run *r = s->r;
    const window *w = &s->win;
    const size_t n = (size_t)w->w * (size_t)w->h;
    float *z = malloc(n * sizeof *z), *v = malloc((size_t)s->n_bands * n * sizeof *v);
    unsigned char *hole = malloc(n);
    long holes = 0;
    int rc = z && v && hole ? HFS_OK
                            : hfs_fail(err, HFS_E_NOMEM, "%s: out of memory for a window of "
                                       "%dx%d", r->a->dem, w->w, w->h);
    if (!rc)
        rc = gis_dem_read_window(&r->dem, r->a->dem, w->x0, w->y0, w->w, w->h, z, hole, &holes,
                                 err);
    for (int j = 0; !rc && j < w->ih; ++j) /* the DEM's holes: the inner parts' */
        for (int i = 0; i < w->iw; ++i)
            r->dem.holes += hole[(size_t)(w->iy - w->y0 + j) * (size_t)w->w +
                                 (size_t)(w->ix - w->x0 + i)];
    if (!rc && (size_t)holes < n) {
        rc = compute(s, z, hole, v, err);
    } else if (!rc) { /* no valid height: nodata (hfs_height_fill_holes takes none) */
        for (size_t p = 0; p < (size_t)s->n_bands * n; ++p)
            v[p] = r->c.nodata;
        for (int k = 0; k < s->n_out && !rc; ++k)
            rc = write_inner(s, k, v, err);
    }
    if (!rc && r->a->product != GIS_HORIZON && (size_t)holes < n)
        rc = write_inner(s, 0, v, err);
    free(hole);
    free(v);
    free(z);
    return rc;
}

/* The files created (temporaries of the run's outputs), with the azimuths
 * of horizon. */
static int open_files(stream *s, hfs_error *err)
{
    gis_run *r = s->r;
    const gis_args *a = r->a;
    const int horizon = a->product == GIS_HORIZON;
    s->n_out = horizon ? a->n_azimuths : 1;
    s->n_bands = gis_run_bands(r);
    s->out = calloc((size_t)s->n_out, sizeof *s->out);
    s->phi = horizon ? malloc((size_t)a->n_azimuths * sizeof *s->phi) : NULL;
    if (!s->out || (horizon && !s->phi))
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", a->out);
    int rc = HFS_OK;
    for (int k = 0; k < s->n_out && !rc; ++k) {
        const char *path = horizon ? r->names[k] : a->out, *tmp = NULL;
        gis_horizon_text t;
        gis_raster g = horizon ? gis_run_horizon_raster(r, k, NULL, &t)
                               : gis_run_product_raster(r, NULL, 0);
        if (a->job) /* the window's inner part alone, georeferenced where it lies */
            g.width = s->win.iw, g.height = s->win.ih, g.geotransform = s->gt;
        if (horizon)
            s->phi[k] = gis_phi_of(a->azimuth[k], a->convention);
        rc = gis_outputs_temporary(r->outs, path, &tmp, err);
        if (!rc)
            rc = gis_raster_stream_open(&s->out[k], path, tmp, &g, err);
    }
    return rc;
}

/* After a row of windows ending at row `end`: what GDAL holds written and
 * freed, when the row ends a row of the files' blocks. */
static int row_done(stream *s, int end, hfs_error *err)
{
    if (end % BLOCK && end != s->r->dem.height)
        return HFS_OK;
    int rc = HFS_OK;
    for (int k = 0; k < s->n_out && !rc; ++k)
        rc = gis_raster_stream_flush(s->out[k], err);
    gis_dem_drop_cache(&s->r->dem);
    return rc;
}

/* Every window, row by row; with --job only that one. */
static int windows(stream *s, hfs_error *err)
{
    gis_run *r = s->r;
    const int tile = r->a->tile, nx = (r->dem.width + tile - 1) / tile;
    const int ny = (r->dem.height + tile - 1) / tile;
    s->inner = malloc((size_t)s->n_bands * (size_t)min_i(tile, r->dem.width) *
                      (size_t)min_i(tile, r->dem.height) * sizeof *s->inner);
    if (!s->inner)
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", r->a->dem);
    if (r->a->job) { /* s->win: job_window's */
        r->windows = 1;
        return one_window(s, err);
    }
    int rc = HFS_OK;
    for (int ty = 0; ty < ny && !rc; ++ty) {
        for (int tx = 0; tx < nx && !rc; ++tx, ++r->windows) {
            s->win = window_of(&r->dem, tile, r->halo, tx, ty);
            rc = one_window(s, err);
        }
        if (!rc)
            rc = row_done(s, s->win.iy + s->win.ih, err);
    }
    return rc;
}

/* --job K: window K's place (s->win), its origin and geotransform; an
 * error when the DEM has fewer windows. */
static int job_window(stream *s, hfs_error *err)
{
    gis_run *r = s->r;
    const int tile = r->a->tile, nx = (r->dem.width + tile - 1) / tile;
    const int ny = (r->dem.height + tile - 1) / tile, k = r->a->job - 1;
    if (k >= nx * ny)
        return hfs_fail(err, HFS_E_INVALID, "%s: --job %d: the DEM has %d windows of --tile %d",
                        r->a->dem, r->a->job, nx * ny, tile);
    s->win = window_of(&r->dem, tile, r->halo, k % nx, k / nx);
    s->ox = s->win.ix, s->oy = s->win.iy;
    const double *g = r->dem.gt;
    memcpy(s->gt, g, sizeof s->gt);
    s->gt[0] = g[0] + s->ox * g[1] + s->oy * g[2];
    s->gt[3] = g[3] + s->ox * g[4] + s->oy * g[5];
    return HFS_OK;
}

int gis_stream_write(gis_run *r, hfs_error *err)
{
    stream s = {.r = r};
    r->windows = 0, r->dem.holes = 0;
    int rc = r->a->job ? job_window(&s, err) : HFS_OK;
    if (!rc)
        rc = open_files(&s, err);
    if (!rc)
        rc = windows(&s, err);
    const long n = r->a->job ? (long)s.win.iw * s.win.ih : (long)r->dem.width * r->dem.height;
    if (!rc && r->dem.holes == n)
        rc = hfs_fail(err, HFS_E_FORMAT, "%s: no valid heights (all %ld texels are nodata)",
                      r->a->dem, n);
    for (int k = 0; k < s.n_out && s.out; ++k) {
        if (!rc)
            rc = gis_raster_stream_finish(s.out[k], err);
        else
            gis_raster_stream_abort(s.out[k]);
        s.out[k] = NULL;
    }
    free(s.inner);
    free(s.phi);
    free(s.out);
    return rc;
}
