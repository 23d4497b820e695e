/*
 * kiosk_map_levels.c — the map's levels (kiosk_map.h "Levels"): 2x2 means
 * of the heights and of the albedo map, level after level, and the window
 * of a level a tile is lit from.
 */
#include "kiosk_map_priv.h"

#include "tiled_render.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int kiosk_map_levels_for(int w, int h, int dw, int dh)
{
    int n = 1;
    while ((w > dw || h > dh) && n < KIOSK_MAP_MAX_LEVELS) {
        w = (w + 1) / 2, h = (h + 1) / 2;
        ++n;
    }
    return n;
}

/* dst ((sw + 1) / 2 x (sh + 1) / 2, ch channels) = the means of src's 2x2
 * blocks (sw x sh), of the texels a block has at the far edges. */
static void halve(const float *src, int sw, int sh, int ch, float *dst)
{
    const int dw = (sw + 1) / 2, dh = (sh + 1) / 2;
    for (int j = 0; j < dh; ++j) {
        const int j1 = 2 * j + 1 < sh ? 2 * j + 1 : 2 * j;
        for (int i = 0; i < dw; ++i) {
            const int i1 = 2 * i + 1 < sw ? 2 * i + 1 : 2 * i;
            for (int c = 0; c < ch; ++c) {
                const double sum = (double)src[((size_t)(2 * j) * sw + 2 * i) * ch + c] +
                                   src[((size_t)(2 * j) * sw + i1) * ch + c] +
                                   src[((size_t)j1 * sw + 2 * i) * ch + c] +
                                   src[((size_t)j1 * sw + i1) * ch + c];
                dst[((size_t)j * dw + i) * ch + c] = (float)(0.25 * sum);
            }
        }
    }
}

void kiosk_map_levels_free(kiosk_map *m)
{
    for (int l = 0; l < m->n_levels; ++l) {
        if (l > 0) {
            free(m->lv[l].z);
            free(m->lv[l].albedo);
        }
        free(m->lv[l].bmax);
        free(m->lv[l].bmin);
    }
    memset(m->lv, 0, sizeof m->lv);
    m->level_bytes = 0;
}

/* v's blocks: the highest and lowest height of each. */
static int blocks(kiosk_map_level *v)
{
    enum { B = KIOSK_MAP_BLOCK };
    v->bw = (v->w + B - 1) / B, v->bh = (v->h + B - 1) / B;
    const size_t n = (size_t)v->bw * (size_t)v->bh;
    v->bmax = malloc(n * sizeof *v->bmax);
    v->bmin = malloc(n * sizeof *v->bmin);
    if (!v->bmax || !v->bmin)
        return -1;
    for (size_t b = 0; b < n; ++b)
        v->bmax[b] = -INFINITY, v->bmin[b] = INFINITY;
    for (int j = 0; j < v->h; ++j)
        for (int i = 0; i < v->w; ++i) {
            const size_t b = (size_t)(j / B) * (size_t)v->bw + (size_t)(i / B);
            const float z = v->z[(size_t)j * (size_t)v->w + (size_t)i];
            v->bmax[b] = fmaxf(v->bmax[b], z);
            v->bmin[b] = fminf(v->bmin[b], z);
        }
    return 0;
}

int kiosk_map_levels_build(kiosk_map *m, const hfs_scene_inputs *in, hfs_error *err)
{
    kiosk_map_levels_free(m);
    const hfs_field *f = &in->field;
    m->n_levels = kiosk_map_levels_for(f->width, f->height, m->dw, m->dh);
    m->lv[0] = (kiosk_map_level){.w = f->width, .h = f->height, .z = (float *)f->z,
                                 .albedo = (float *)in->lighting.albedo_map, .dx = f->dx};
    for (int l = 1; l < m->n_levels; ++l) {
        const kiosk_map_level *p = &m->lv[l - 1];
        kiosk_map_level *v = &m->lv[l];
        v->w = (p->w + 1) / 2, v->h = (p->h + 1) / 2, v->dx = 2.0 * p->dx;
        const size_t n = (size_t)v->w * (size_t)v->h;
        v->z = malloc(n * sizeof *v->z);
        v->albedo = p->albedo ? malloc(3 * n * sizeof *v->albedo) : NULL;
        if (!v->z || (p->albedo && !v->albedo)) {
            kiosk_map_levels_free(m);
            return hfs_fail(err, HFS_E_NOMEM, "map: out of memory for level %d (%dx%d)", l,
                            v->w, v->h);
        }
        halve(p->z, p->w, p->h, 1, v->z);
        if (p->albedo)
            halve(p->albedo, p->w, p->h, 3, v->albedo);
        m->level_bytes += n * sizeof(float) * (p->albedo ? 4 : 1);
    }
    for (int l = 0; l < m->n_levels; ++l) {
        if (blocks(&m->lv[l])) {
            kiosk_map_levels_free(m);
            return hfs_fail(err, HFS_E_NOMEM, "map: out of memory for level %d's blocks", l);
        }
        m->level_bytes += (size_t)m->lv[l].bw * (size_t)m->lv[l].bh * 2 * sizeof(float);
    }
    m->serial = in->serial;
    m->z0 = f->z;
    return HFS_OK;
}

/* The highest (hi 1) or lowest height of the blocks meeting [x0, x1) x
 * [y0, y1) cut to the level: a bound on the window's own. */
static double block_bound(const kiosk_map_level *v, int x0, int y0, int x1, int y1, int hi)
{
    enum { B = KIOSK_MAP_BLOCK };
    const int bx0 = x0 < 0 ? 0 : x0 / B, by0 = y0 < 0 ? 0 : y0 / B;
    const int bx1 = x1 >= v->w ? v->bw : (x1 + B - 1) / B;
    const int by1 = y1 >= v->h ? v->bh : (y1 + B - 1) / B;
    double r = hi ? -INFINITY : INFINITY;
    for (int j = by0; j < by1; ++j)
        for (int i = bx0; i < bx1; ++i) {
            const size_t b = (size_t)j * (size_t)v->bw + (size_t)i;
            r = hi ? fmax(r, v->bmax[b]) : fmin(r, v->bmin[b]);
        }
    return r;
}

int kiosk_map_tile_halo(const kiosk_map *m, int l, int ix, int iy, int iw, int ih, double eps)
{
    const kiosk_map_level *v = &m->lv[l];
    if (!(eps > 0.0) || v->halo < 0)
        return -1;
    const int a = HFS_TILE_ALIGN, span = v->w > v->h ? v->w : v->h;
    const double lowest = block_bound(v, ix, iy, ix + iw, iy + ih, 0);
    const double rise = v->dx * tan(eps) / (m->zscale > 0.0 ? m->zscale : 1.0); /* a texel's */
    /* The nearest ring from which every ring out to the level's end is
     * below eps: rings d..e, e = d + max(a, d / 4) (a quarter wider each:
     * a ring's bound is its farthest blocks' highest over its nearest
     * distance), from d = a (within a of the tile is inside every halo). */
    int from = a;
    for (int d = a;;) {
        const int e = d + (d / 4 > a ? d / 4 : a);
        const double top = block_bound(v, ix - e, iy - e, ix + iw + e, iy + ih + e, 1);
        if (m->zscale > 0.0 && (top - lowest) > d * rise)
            from = e; /* this ring may rise above eps: the halo covers it */
        if (e >= span) /* the ring reaches past the level's far side */
            break;
        d = e;
    }
    const int halo = (from + 2 + a - 1) / a * a; /* + 2: hfs_tile_halo's cell reach */
    return halo < v->halo ? halo : v->halo;
}

/* Grows the window scratch to n texels. */
static int scratch(kiosk_map *m, size_t n, hfs_error *err)
{
    if (n <= m->wcap)
        return HFS_OK;
    free(m->wz);
    free(m->walb);
    free(m->wimg.rgb);
    m->wz = malloc(n * sizeof *m->wz);
    m->walb = malloc(3 * n * sizeof *m->walb);
    m->wimg.rgb = malloc(3 * n * sizeof *m->wimg.rgb);
    m->wcap = m->wz && m->walb && m->wimg.rgb ? n : 0;
    return m->wcap ? HFS_OK
                   : hfs_fail(err, HFS_E_NOMEM, "map: out of memory for a window of %zu texels",
                              n);
}

int kiosk_map_window(kiosk_map *m, int l, int x0, int y0, int w, int h,
                     const hfs_lighting *lit, hfs_field *f, hfs_lighting *wl, hfs_error *err)
{
    const kiosk_map_level *v = &m->lv[l];
    const int rc = scratch(m, (size_t)w * (size_t)h, err);
    if (rc)
        return rc;
    /* The level's texel (i, j) stands at (i, j) 2^l dx: world positions
     * (a local light's, a viewer's eye) keep their place on the terrain. */
    const hfs_field level = {v->w, v->h, v->z, v->dx, m->zscale};
    hfs_lighting ll = *lit;
    ll.albedo_map = v->albedo;
    *f = hfs_tile_sub_field(&level, &ll, x0, y0, w, h, m->wz, v->albedo ? m->walb : NULL, wl);
    return HFS_OK;
}
