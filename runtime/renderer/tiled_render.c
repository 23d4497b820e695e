/*
 * tiled_render.c — see tiled_render.h.
 */
#include "tiled_render.h"

#include "field_geom.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

double hfs_tile_eps(const hfs_lighting *l)
{
    double eps = l->has_env ? HFS_TILE_SKY_EPS : 1.5707963267948966;
    for (int k = 0; k < l->n_key; ++k)
        if (!l->key[k].disabled)
            eps = fmin(eps, l->key[k].elev - l->key[k].alpha);
    for (int k = 0; k < l->n_local; ++k)
        if (!l->local[k].disabled)
            return 0.0;
    return eps > 0.0 ? eps : 0.0;
}

static int min_side(int a, int b)
{
    return a < b ? a : b;
}

hfs_tile_window hfs_tile_window_of(int width, int height, int tile, int halo, int tx, int ty)
{
    enum { A = HFS_TILE_ALIGN };
    hfs_tile_window v;
    v.ix = tx * tile, v.iy = ty * tile;
    v.iw = min_side(tile, width - v.ix), v.ih = min_side(tile, height - v.iy);
    v.x0 = v.ix > halo ? (v.ix - halo) / A * A : 0;
    v.y0 = v.iy > halo ? (v.iy - halo) / A * A : 0;
    v.w = min_side((v.ix + v.iw + halo + A - 1) / A * A, width) - v.x0;
    v.h = min_side((v.iy + v.ih + halo + A - 1) / A * A, height) - v.y0;
    return v;
}

int hfs_tile_halo(const hfs_field *f, const hfs_lighting *l)
{
    const double eps = hfs_tile_eps(l);
    if (!(eps > 0.0))
        return -1;
    double lo, hi;
    hfs_field_range(f, &lo, &hi);
    const double reach = f->zscale * (hi - lo) / (f->dx * tan(eps));
    return reach < 1e9 ? (int)ceil(reach) + 2 : -1;
}

hfs_field hfs_tile_sub_field(const hfs_field *f, const hfs_lighting *l, int x0, int y0, int w,
                             int h, float *z, float *alb, hfs_lighting *sl)
{
    for (int j = 0; j < h; ++j) {
        const size_t src = (size_t)(y0 + j) * (size_t)f->width + (size_t)x0;
        memcpy(z + (size_t)j * (size_t)w, f->z + src, (size_t)w * sizeof *z);
        if (alb)
            memcpy(alb + (size_t)j * (size_t)w * 3, l->albedo_map + 3 * src,
                   (size_t)w * 3 * sizeof *alb);
    }
    *sl = *l;
    sl->albedo_map = alb;
    for (int k = 0; k < sl->n_local; ++k) {
        sl->local[k].pos[0] -= x0 * f->dx;
        sl->local[k].pos[1] -= y0 * f->dx;
    }
    sl->view_eye[0] -= x0 * f->dx;
    sl->view_eye[1] -= y0 * f->dx;
    return (hfs_field){w, h, z, f->dx, f->zscale};
}

int hfs_tiled_render(const hfs_field *f, const hfs_lighting *l, int max_side, const char *limit,
                     hfs_tile_frame_fn render, void *ctx, hfs_image *out, hfs_error *err)
{
    const int halo0 = hfs_tile_halo(f, l);
    const int a = HFS_TILE_ALIGN, halo = halo0 < 0 ? -1 : (halo0 + a - 1) / a * a;
    const int inner = halo < 0 ? 0 : (max_side - 2 * halo) / a * a;
    if (inner < 4 * a)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "render: a %dx%d field exceeds %s, and tiles "
                        "cannot help: %s; the cpu backend renders any size",
                        f->width, f->height, limit,
                        halo < 0 ? "its lights see terrain at any distance (a local light, or "
                                   "a key light at or below its own radius)"
                                 : "its relief needs halos too wide for them");
    const int side = inner + 2 * halo;
    float *z = malloc((size_t)side * (size_t)side * sizeof *z);
    float *alb = l->albedo_map ? malloc((size_t)side * (size_t)side * 3 * sizeof *alb) : NULL;
    hfs_image tile = {0};
    int rc = z && (alb || !l->albedo_map) ? hfs_image_alloc(&tile, side, side, err)
                                          : hfs_fail(err, HFS_E_NOMEM, "render: out of memory "
                                                     "for a %d-texel tile", side);
    for (int ty = 0; ty < f->height && !rc; ty += inner)
        for (int tx = 0; tx < f->width && !rc; tx += inner) {
            const int x0 = tx > halo ? tx - halo : 0, y0 = ty > halo ? ty - halo : 0;
            const int x1 = tx + inner + halo < f->width ? tx + inner + halo : f->width;
            const int y1 = ty + inner + halo < f->height ? ty + inner + halo : f->height;
            hfs_lighting sl;
            const hfs_field sf = hfs_tile_sub_field(f, l, x0, y0, x1 - x0, y1 - y0, z, alb, &sl);
            tile.width = sf.width, tile.height = sf.height;
            if ((rc = render(ctx, &sf, &sl, &tile, err)))
                break;
            const int iw = tx + inner < f->width ? inner : f->width - tx;
            const int ih = ty + inner < f->height ? inner : f->height - ty;
            for (int j = 0; j < ih; ++j)
                memcpy(out->rgb + 3 * ((size_t)(ty + j) * (size_t)f->width + (size_t)tx),
                       tile.rgb + 3 * ((size_t)(ty - y0 + j) * (size_t)sf.width +
                                       (size_t)(tx - x0)),
                       (size_t)iw * 3 * sizeof *out->rgb);
        }
    free(z);
    free(alb);
    hfs_image_free(&tile);
    return rc;
}
