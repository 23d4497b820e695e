/*
 * edit_region.c — see edit_region.h.
 */
#include "edit_region.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int row_differs(const float *a, const float *b, int w)
{
    return memcmp(a, b, (size_t)w * sizeof *a) != 0;
}

int hfs_edit_find(const float *a, const float *b, int w, int h, hfs_edit_box *box)
{
    int y0 = 0, y1 = h - 1;
    while (y0 < h && !row_differs(a + (size_t)y0 * w, b + (size_t)y0 * w, w))
        ++y0;
    if (y0 == h)
        return 0;
    while (!row_differs(a + (size_t)y1 * w, b + (size_t)y1 * w, w))
        --y1;
    int x0 = w, x1 = -1;
    for (int y = y0; y <= y1; ++y) {
        const float *ra = a + (size_t)y * w, *rb = b + (size_t)y * w;
        for (int x = 0; x < x0; ++x) /* bits, not values: -0 and 0 differ */
            if (memcmp(&ra[x], &rb[x], sizeof *ra)) {
                x0 = x;
                break;
            }
        for (int x = w - 1; x > x1; --x)
            if (memcmp(&ra[x], &rb[x], sizeof *ra)) {
                x1 = x;
                break;
            }
    }
    *box = (hfs_edit_box){x0, y0, x1, y1};
    return 1;
}

double hfs_edit_top(const hfs_gles_layout *L, const float *a, const float *b, int w,
                    hfs_edit_box box)
{
    double top = -HUGE_VAL;
    for (int y = box.y0; y <= box.y1; ++y)
        for (int x = box.x0; x <= box.x1; ++x) {
            const size_t i = (size_t)y * w + x;
            top = fmax(top, fmax(a[i], b[i]));
        }
    return (top - L->base) / L->hscale + 1e-4;
}

hfs_edit_box hfs_edit_box_grow(hfs_edit_box b, int r, int w, int h)
{
    if (b.x1 < b.x0 || b.y1 < b.y0)
        return b;
    b.x0 = b.x0 - r < 0 ? 0 : b.x0 - r;
    b.y0 = b.y0 - r < 0 ? 0 : b.y0 - r;
    b.x1 = b.x1 + r > w - 1 ? w - 1 : b.x1 + r;
    b.y1 = b.y1 + r > h - 1 ? h - 1 : b.y1 + r;
    return b;
}

int hfs_tiles_init(hfs_tiles *t, int w, int h)
{
    const int tw = (w + HFS_EDIT_TILE - 1) / HFS_EDIT_TILE;
    const int th = (h + HFS_EDIT_TILE - 1) / HFS_EDIT_TILE;
    const size_t n = (size_t)tw * th;
    if (n > t->cap) {
        unsigned char *on = realloc(t->on, n);
        if (!on)
            return -1;
        t->on = on;
        t->cap = n;
    }
    t->w = w, t->h = h, t->tw = tw, t->th = th;
    hfs_tiles_clear(t);
    return 0;
}

void hfs_tiles_free(hfs_tiles *t)
{
    free(t->on);
    memset(t, 0, sizeof *t);
}

void hfs_tiles_clear(hfs_tiles *t)
{
    t->all = 0;
    if (t->on)
        memset(t->on, 0, (size_t)t->tw * t->th);
}

void hfs_tiles_set_all(hfs_tiles *t)
{
    t->all = 1;
}

void hfs_tiles_add_box(hfs_tiles *t, hfs_edit_box b)
{
    b = hfs_edit_box_grow(b, 0, t->w, t->h);
    if (t->all || b.x1 < b.x0 || b.y1 < b.y0)
        return;
    for (int ty = b.y0 / HFS_EDIT_TILE; ty <= b.y1 / HFS_EDIT_TILE; ++ty)
        memset(t->on + (size_t)ty * t->tw + b.x0 / HFS_EDIT_TILE, 1,
               (size_t)(b.x1 / HFS_EDIT_TILE - b.x0 / HFS_EDIT_TILE + 1));
}

void hfs_tiles_add_grown(hfs_tiles *dst, const hfs_tiles *src, int r)
{
    if (src->all) {
        dst->all = 1;
        return;
    }
    for (int ty = 0; ty < src->th; ++ty)
        for (int tx = 0; tx < src->tw; ++tx) {
            if (!src->on[(size_t)ty * src->tw + tx])
                continue;
            const hfs_edit_box b = {tx * HFS_EDIT_TILE - r, ty * HFS_EDIT_TILE - r,
                                    tx * HFS_EDIT_TILE + HFS_EDIT_TILE - 1 + r,
                                    ty * HFS_EDIT_TILE + HFS_EDIT_TILE - 1 + r};
            hfs_tiles_add_box(dst, b);
        }
}

int hfs_tiles_any(const hfs_tiles *t)
{
    if (t->all)
        return 1;
    for (size_t i = 0; i < (size_t)t->tw * t->th; ++i)
        if (t->on[i])
            return 1;
    return 0;
}

int hfs_tiles_rects(const hfs_tiles *t, hfs_edit_rect *out)
{
    if (t->all) {
        out[0] = (hfs_edit_rect){0, 0, t->w, t->h};
        return 1;
    }
    int n = 0;
    for (int ty = 0; ty < t->th; ++ty) {
        const unsigned char *on = t->on + (size_t)ty * t->tw;
        const int y = ty * HFS_EDIT_TILE;
        const int y1 = y + HFS_EDIT_TILE < t->h ? y + HFS_EDIT_TILE : t->h;
        for (int a = 0; a < t->tw;) {
            if (!on[a]) {
                ++a;
                continue;
            }
            int b = a;
            while (b < t->tw && on[b])
                ++b;
            const int x = a * HFS_EDIT_TILE;
            const int x1 = b * HFS_EDIT_TILE < t->w ? b * HFS_EDIT_TILE : t->w;
            /* the same run ending a row up: one taller rectangle */
            int k = 0;
            while (k < n && !(out[k].x == x && out[k].w == x1 - x && out[k].y + out[k].h == y))
                ++k;
            if (k < n)
                out[k].h = y1 - out[k].y;
            else
                out[n++] = (hfs_edit_rect){x, y, x1 - x, y1 - y};
            a = b;
        }
    }
    return n;
}

double hfs_edit_layer_reach(const hfs_gles_layout *L, int layer)
{
    const int level = layer + L->lmin, input = L->n_levels - 1;
    if (level >= input)
        return 1.0; /* the bilinear read's cell */
    /* the level's spacing in input texels, as its size gives it */
    double sum = 0.0, own = 1.0;
    for (int m = level; m <= input; ++m) {
        const double s = fmax((double)L->w / L->lw[m], (double)L->h / L->lh[m]);
        if (m == level)
            own = s;
        else
            sum += s; /* level m - 1 samples level m bilinearly: one of its spacings */
    }
    /* the B-spline's two spacings each side, the read's cell, and a spacing
     * of slack for the texel centres' offsets */
    return 3.0 * own + sum + 2.0;
}

double hfs_edit_env_near_reach(const hfs_gles_layout *L, int coarsest)
{
    const double refine = pow(2.0, 1.0 / L->k);
    double reach = 2.0; /* the receiver's own cell and normal */
    for (int i = coarsest < 0 ? 0 : coarsest; i < L->n_levels; ++i) {
        const double r = L->spacing[i] * refine + hfs_edit_layer_reach(L, L->read_layer[i]);
        reach = fmax(reach, r);
    }
    return reach + 1.0;
}

hfs_edit_box hfs_edit_sweep(hfs_edit_box e, double c, double s, double t_max, int w, int h)
{
    hfs_edit_box b = e;
    if (t_max > 0.0) {
        const double lim = (double)w + h;
        const double t = t_max < lim ? t_max : lim;
        const double dx = -c * t, dy = -s * t;
        b.x0 = (int)floor(fmin(e.x0, e.x0 + dx)) - 1;
        b.x1 = (int)ceil(fmax(e.x1, e.x1 + dx)) + 1;
        b.y0 = (int)floor(fmin(e.y0, e.y0 + dy)) - 1;
        b.y1 = (int)ceil(fmax(e.y1, e.y1 + dy)) + 1;
    }
    return hfs_edit_box_grow(b, 0, w, h);
}

double hfs_edit_reach_above(double top, double vmin, double rise, double slope)
{
    if (!(slope > 0.0))
        return HUGE_VAL;
    return (top - vmin) * rise / slope;
}

double hfs_edit_slope_margin(double slope)
{
    return 1e-3 * (1.0 + fabs(slope));
}
