/*
 * kiosk_map.c — the map's tiles: lit, cached, composed into the view and
 * fetched ahead of it (kiosk_map.h).
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */

#include "kiosk_map_priv.h"

#include "tiled_render.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static void size_tiles(kiosk_map *m, const hfs_scene_inputs *in);

static int min_i(int a, int b) { return a < b ? a : b; }
static int max_i(int a, int b) { return a > b ? a : b; }
static int align_up(int v, int a) { return (v + a - 1) / a * a; }

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec / 1e6;
}

int kiosk_map_create(const hfs_scene_inputs *in, int dw, int dh, kiosk_map **out,
                     hfs_error *err)
{
    *out = NULL;
    if (dw < 1 || dh < 1)
        return hfs_fail(err, HFS_E_INVALID, "map: display %dx%d", dw, dh);
    kiosk_map *m = calloc(1, sizeof *m);
    if (!m)
        return hfs_fail(err, HFS_E_NOMEM, "map: out of memory");
    m->dw = dw, m->dh = dh;
    const int rc = kiosk_map_levels_build(m, in, err);
    if (rc) {
        free(m);
        return rc;
    }
    size_tiles(m, in);
    *out = m;
    return HFS_OK;
}

static void drop_tiles(kiosk_map *m)
{
    for (int k = 0; k < m->n_tiles; ++k)
        free(m->tiles[k].rgb);
    m->n_tiles = 0, m->bytes = 0, m->n_want = 0, m->n_visible = 0;
}

void kiosk_map_free(kiosk_map *m)
{
    if (!m)
        return;
    drop_tiles(m);
    kiosk_map_levels_free(m);
    free(m->tiles);
    free(m->want);
    free(m->wz);
    free(m->walb);
    free(m->wimg.rgb);
    free(m);
}

int kiosk_map_levels(const kiosk_map *m)
{
    return m->n_levels;
}

void kiosk_map_view_size(const kiosk_map *m, int level, int *w, int *h)
{
    *w = min_i(m->dw, m->lv[level].w);
    *h = min_i(m->dh, m->lv[level].h);
}

/* Tiles across a view of level l (one more than fit: a view rarely starts
 * on a tile's edge), ring or not. */
static size_t view_bytes(const kiosk_map *m, int l, int ring)
{
    const kiosk_map_level *v = &m->lv[l];
    int vw, vh;
    kiosk_map_view_size(m, l, &vw, &vh);
    const int across = (v->w + v->tile - 1) / v->tile, down = (v->h + v->tile - 1) / v->tile;
    const int nx = min_i(vw / v->tile + 2 + 2 * ring, across);
    const int ny = min_i(vh / v->tile + 2 + 2 * ring, down);
    return (size_t)nx * (size_t)ny * (size_t)v->tile * (size_t)v->tile * 3 * sizeof(float);
}

/* Each level's halo and tile side under in's lighting, and the budget:
 * the view with its ring and the views a level in and out, at the level
 * whose tiles take the most bytes. */
static void size_tiles(kiosk_map *m, const hfs_scene_inputs *in)
{
    m->zscale = in->field.zscale;
    for (int l = 0; l < m->n_levels; ++l) {
        kiosk_map_level *v = &m->lv[l];
        const hfs_field f = {v->w, v->h, v->z, v->dx, m->zscale};
        const int halo = hfs_tile_halo(&f, &in->lighting);
        v->halo = halo < 0 ? -1 : align_up(halo, HFS_TILE_ALIGN);
        v->tile = halo < 0 ? max_i(v->w, v->h)
                           : min_i(KIOSK_MAP_TILE_MAX,
                                   max_i(KIOSK_MAP_TILE, align_up(2 * v->halo, HFS_TILE_ALIGN)));
    }
    m->budget = 0;
    for (int l = 0; l < m->n_levels; ++l) {
        size_t b = view_bytes(m, l, 1);
        if (l > 0)
            b += view_bytes(m, l - 1, 0);
        if (l + 1 < m->n_levels)
            b += view_bytes(m, l + 1, 0);
        m->budget = b > m->budget ? b : m->budget;
    }
    m->lighting = in->lighting;
    m->quality = in->quality;
    m->lit = 1;
}

/* New heights rebuild the levels; a new lighting or quality (or heights)
 * drops every tile and sizes them again. */
static int follow_inputs(kiosk_map *m, const hfs_scene_inputs *in, hfs_error *err)
{
    if (in->serial != m->serial || in->field.z != m->z0 ||
        in->lighting.albedo_map != (const float *)m->lv[0].albedo) {
        drop_tiles(m);
        m->lit = 0;
        const int rc = kiosk_map_levels_build(m, in, err);
        if (rc)
            return rc;
    }
    if (m->lit && !memcmp(&m->lighting, &in->lighting, sizeof m->lighting) &&
        !memcmp(&m->quality, &in->quality, sizeof m->quality) && m->zscale == in->field.zscale)
        return HFS_OK;
    drop_tiles(m);
    size_tiles(m, in);
    return HFS_OK;
}

static kiosk_map_tile *find(kiosk_map *m, int l, int tx, int ty)
{
    for (int k = 0; k < m->n_tiles; ++k)
        if (m->tiles[k].level == l && m->tiles[k].tx == tx && m->tiles[k].ty == ty)
            return &m->tiles[k];
    return NULL;
}

/* Frees tiles no view wants now, the longest unwanted first, until need
 * more bytes fit the budget.  -1 when they cannot. */
static int make_room(kiosk_map *m, size_t need)
{
    while (m->bytes + need > m->budget) {
        int old = -1;
        for (int k = 0; k < m->n_tiles; ++k)
            if (m->tiles[k].wanted != m->stamp &&
                (old < 0 || m->tiles[k].wanted < m->tiles[old].wanted))
                old = k;
        if (old < 0)
            return -1;
        kiosk_map_tile *t = &m->tiles[old];
        m->bytes -= (size_t)t->w * (size_t)t->h * 3 * sizeof(float);
        free(t->rgb);
        *t = m->tiles[--m->n_tiles];
    }
    return 0;
}

/* Renders tile (tx, ty) of level l: the window around it lit, its inner
 * part kept in a new cache entry. */
static int render_tile(kiosk_map *m, hfs_renderer *r, int l, int tx, int ty, hfs_error *err)
{
    const kiosk_map_level *v = &m->lv[l];
    const int ix = tx * v->tile, iy = ty * v->tile;
    const int iw = min_i(v->tile, v->w - ix), ih = min_i(v->tile, v->h - iy);
    const int local = kiosk_map_tile_halo(m, l, ix, iy, iw, ih, hfs_tile_eps(&m->lighting));
    const int halo = local < 0 ? v->w + v->h : local, a = HFS_TILE_ALIGN;
    const int x0 = max_i(0, ix - halo) / a * a, y0 = max_i(0, iy - halo) / a * a;
    const int x1 = min_i(v->w, align_up(ix + iw + halo, a));
    const int y1 = min_i(v->h, align_up(iy + ih + halo, a));
    if (m->n_tiles == m->cap_tiles) {
        const int cap = m->cap_tiles ? 2 * m->cap_tiles : 64;
        kiosk_map_tile *t = realloc(m->tiles, (size_t)cap * sizeof *t);
        if (!t)
            return hfs_fail(err, HFS_E_NOMEM, "map: out of memory");
        m->tiles = t, m->cap_tiles = cap;
    }
    float *rgb = malloc((size_t)iw * (size_t)ih * 3 * sizeof *rgb);
    if (!rgb)
        return hfs_fail(err, HFS_E_NOMEM, "map: out of memory for a tile of %dx%d", iw, ih);
    const double t0 = now_ms();
    hfs_field f;
    hfs_lighting wl;
    int rc = kiosk_map_window(m, l, x0, y0, x1 - x0, y1 - y0, &m->lighting, &f, &wl, err);
    m->wimg.width = f.width, m->wimg.height = f.height;
    hfs_renderer_set_field_serial(r, 0); /* a window's heights: checked each time */
    if (!rc)
        rc = hfs_renderer_render(r, &f, &wl, &m->quality, &m->wimg, NULL, NULL, err);
    if (rc) {
        free(rgb);
        return rc;
    }
    for (int j = 0; j < ih; ++j)
        memcpy(rgb + (size_t)j * iw * 3,
               m->wimg.rgb + ((size_t)(iy - y0 + j) * f.width + (size_t)(ix - x0)) * 3,
               (size_t)iw * 3 * sizeof *rgb);
    m->tiles[m->n_tiles++] = (kiosk_map_tile){l, tx, ty, iw, ih, m->stamp, rgb};
    m->bytes += (size_t)iw * (size_t)ih * 3 * sizeof *rgb;
    m->last_tile_ms = now_ms() - t0;
    return HFS_OK;
}

/* ---- the view and what it wants ------------------------------------------ */

/* The view's origin at level l, centred on (cx, cy) (level-0 texels),
 * kept on the level. */
static void view_origin(const kiosk_map *m, int l, double cx, double cy, int *ox, int *oy)
{
    const kiosk_map_level *v = &m->lv[l];
    int vw, vh;
    kiosk_map_view_size(m, l, &vw, &vh);
    const double s = ldexp(1.0, -l);
    const double x = floor(cx * s - 0.5 * vw + 0.5), y = floor(cy * s - 0.5 * vh + 0.5);
    *ox = (int)fmax(0.0, fmin(x, (double)(v->w - vw)));
    *oy = (int)fmax(0.0, fmin(y, (double)(v->h - vh)));
}

static int push_want(kiosk_map *m, int l, int tx, int ty)
{
    if (m->n_want == m->cap_want) {
        const int cap = m->cap_want ? 2 * m->cap_want : 64;
        kiosk_map_want *w = realloc(m->want, (size_t)cap * sizeof *w);
        if (!w)
            return -1;
        m->want = w, m->cap_want = cap;
    }
    m->want[m->n_want++] = (kiosk_map_want){l, tx, ty};
    kiosk_map_tile *t = find(m, l, tx, ty);
    if (t)
        t->wanted = m->stamp;
    return 0;
}

/* The tiles of level l a view centred on (cx, cy) covers, grown by `ring`
 * tiles; ring 1 adds only the ring's, nearest the centre first. */
static int want_view(kiosk_map *m, int l, double cx, double cy, int ring)
{
    const kiosk_map_level *v = &m->lv[l];
    int ox, oy, vw, vh;
    view_origin(m, l, cx, cy, &ox, &oy);
    kiosk_map_view_size(m, l, &vw, &vh);
    const int t = v->tile, tx0 = ox / t, ty0 = oy / t;
    const int tx1 = (ox + vw - 1) / t, ty1 = (oy + vh - 1) / t;
    const int nx = (v->w + t - 1) / t, ny = (v->h + t - 1) / t;
    const double mx = 0.5 * (tx0 + tx1), my = 0.5 * (ty0 + ty1);
    const int first = m->n_want;
    for (int ty = max_i(0, ty0 - ring); ty <= min_i(ny - 1, ty1 + ring); ++ty)
        for (int tx = max_i(0, tx0 - ring); tx <= min_i(nx - 1, tx1 + ring); ++tx) {
            const int inside = tx >= tx0 && tx <= tx1 && ty >= ty0 && ty <= ty1;
            if (inside == !ring && push_want(m, l, tx, ty))
                return -1;
        }
    for (int i = first + 1; i < m->n_want; ++i) { /* nearest first: insertion sort */
        const kiosk_map_want w = m->want[i];
        const double d = hypot(w.tx - mx, w.ty - my);
        int j = i;
        for (; j > first && hypot(m->want[j - 1].tx - mx, m->want[j - 1].ty - my) > d; --j)
            m->want[j] = m->want[j - 1];
        m->want[j] = w;
    }
    return 0;
}

/* The wants of the view of level l at (cx, cy), in prefetch order. */
static int want(kiosk_map *m, int l, double cx, double cy, hfs_error *err)
{
    ++m->stamp;
    m->n_want = 0;
    int rc = want_view(m, l, cx, cy, 0);
    m->n_visible = m->n_want;
    if (!rc)
        rc = want_view(m, l, cx, cy, 1);
    if (!rc && l > 0)
        rc = want_view(m, l - 1, cx, cy, 0);
    if (!rc && l + 1 < m->n_levels)
        rc = want_view(m, l + 1, cx, cy, 0);
    return rc ? hfs_fail(err, HFS_E_NOMEM, "map: out of memory") : HFS_OK;
}

/* Tile t's part within the view (ox, oy, out's size) into out. */
static void compose(const kiosk_map *m, const kiosk_map_tile *t, int ox, int oy, hfs_image *out)
{
    const int T = m->lv[t->level].tile;
    const int x0 = max_i(t->tx * T, ox), x1 = min_i(t->tx * T + t->w, ox + out->width);
    const int y0 = max_i(t->ty * T, oy), y1 = min_i(t->ty * T + t->h, oy + out->height);
    for (int y = y0; y < y1; ++y)
        memcpy(out->rgb + ((size_t)(y - oy) * out->width + (size_t)(x0 - ox)) * 3,
               t->rgb + ((size_t)(y - t->ty * T) * t->w + (size_t)(x0 - t->tx * T)) * 3,
               (size_t)(x1 - x0) * 3 * sizeof *out->rgb);
}

/* A stand-in for the view's tile (l, tx, ty), not lit yet: the lit tiles of
 * the nearest coarser level that has every one covering it, each of their
 * texels shown on the 2^k x 2^k it covers.  1 when one was found. */
static int compose_coarser(const kiosk_map *m, int l, int tx, int ty, int ox, int oy,
                           hfs_image *out)
{
    enum { MOST = 4 }; /* coarse tiles a side: (1024 >> 1) + 1 texels over tiles >= 256 */
    const kiosk_map_level *v = &m->lv[l];
    const int x0 = max_i(tx * v->tile, ox), x1 = min_i(min_i((tx + 1) * v->tile, v->w),
                                                       ox + out->width);
    const int y0 = max_i(ty * v->tile, oy), y1 = min_i(min_i((ty + 1) * v->tile, v->h),
                                                       oy + out->height);
    for (int k = 1; l + k < m->n_levels; ++k) {
        const int T = m->lv[l + k].tile;
        const int cx0 = (x0 >> k) / T, cy0 = (y0 >> k) / T;
        const int ncx = ((x1 - 1) >> k) / T - cx0 + 1, ncy = ((y1 - 1) >> k) / T - cy0 + 1;
        const kiosk_map_tile *c[MOST][MOST] = {{NULL}};
        int all = ncx <= MOST && ncy <= MOST;
        for (int j = 0; all && j < ncy; ++j)
            for (int i = 0; all && i < ncx; ++i)
                all = (c[j][i] = find((kiosk_map *)m, l + k, cx0 + i, cy0 + j)) != NULL;
        if (!all)
            continue;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                const int px = x >> k, py = y >> k;
                const kiosk_map_tile *t = c[py / T - cy0][px / T - cx0];
                memcpy(out->rgb + ((size_t)(y - oy) * out->width + (size_t)(x - ox)) * 3,
                       t->rgb + ((size_t)(py - t->ty * T) * t->w + (size_t)(px - t->tx * T)) * 3,
                       3 * sizeof *out->rgb);
            }
        return 1;
    }
    return 0;
}

int kiosk_map_frame(kiosk_map *m, hfs_renderer *r, const hfs_scene_inputs *in, double cx,
                    double cy, int level, hfs_image *out, hfs_error *err)
{
    int rc = follow_inputs(m, in, err);
    if (rc)
        return rc;
    level = max_i(0, min_i(level, m->n_levels - 1));
    int vw, vh, ox, oy;
    kiosk_map_view_size(m, level, &vw, &vh);
    if (out->width != vw || out->height != vh)
        return hfs_fail(err, HFS_E_INVALID, "map: a view of %dx%d into an image of %dx%d", vw,
                        vh, out->width, out->height);
    if ((rc = want(m, level, cx, cy, err)))
        return rc;
    m->view_level = level, m->view_x = cx, m->view_y = cy;
    m->rendered = 0, m->coarse = 0;
    view_origin(m, level, cx, cy, &ox, &oy);
    for (int k = 0; k < m->n_visible; ++k) {
        const kiosk_map_want *w = &m->want[k];
        kiosk_map_tile *t = find(m, w->level, w->tx, w->ty);
        if (!t && compose_coarser(m, w->level, w->tx, w->ty, ox, oy, out)) {
            ++m->coarse; /* lit next, by kiosk_map_prefetch */
            continue;
        }
        if (!t) { /* rendered even past the budget (its tiles and the view's fit it) */
            (void)make_room(m, (size_t)m->lv[level].tile * m->lv[level].tile * 3 * sizeof(float));
            if ((rc = render_tile(m, r, w->level, w->tx, w->ty, err)))
                return rc;
            ++m->rendered;
            t = &m->tiles[m->n_tiles - 1];
        }
        compose(m, t, ox, oy, out);
    }
    return HFS_OK;
}

int kiosk_map_prefetch(kiosk_map *m, hfs_renderer *r, const hfs_scene_inputs *in,
                       hfs_error *err)
{
    int rc = follow_inputs(m, in, err); /* a relit world: nothing is wanted until a frame */
    if (rc)
        return rc;
    for (int k = 0; k < m->n_want; ++k) {
        const kiosk_map_want *w = &m->want[k];
        if (find(m, w->level, w->tx, w->ty))
            continue;
        const kiosk_map_level *v = &m->lv[w->level];
        const int tw = min_i(v->tile, v->w - w->tx * v->tile);
        const int th = min_i(v->tile, v->h - w->ty * v->tile);
        if (make_room(m, (size_t)tw * (size_t)th * 3 * sizeof(float)))
            return 0; /* the budget holds no more */
        if ((rc = render_tile(m, r, w->level, w->tx, w->ty, err)))
            return rc;
        ++m->prefetched;
        return k < m->n_visible ? 2 : 1;
    }
    return 0;
}

void kiosk_map_stats_get(const kiosk_map *m, kiosk_map_stats *s)
{
    *s = (kiosk_map_stats){.level = m->view_level,
                           .x = m->view_x,
                           .y = m->view_y,
                           .rendered = m->rendered,
                           .coarse = m->coarse,
                           .cached = m->n_tiles,
                           .bytes = m->bytes,
                           .budget = m->budget,
                           .level_bytes = m->level_bytes,
                           .prefetched = m->prefetched,
                           .last_tile_ms = m->last_tile_ms};
}
