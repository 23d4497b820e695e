/*
 * cpu_local_grid.c — local lights on a sub-sampled visibility grid
 * (subsample 2, 4; issue 36 item 5, cpu_grid.h): as the GLES path
 * (local_visibility.frag, shade.frag local_lights), each light's visible
 * fraction at the grid's receivers (cpu_local.c reads it bilinearly per
 * texel; E_cap, the inside test and the glossy lobe stay per texel).
 * Above cpu_local.c: it calls cpu_local.c's ratio, never the reverse.
 */
#include "cpu_local_priv.h"

#include "field_geom.h"
#include "lights.h"
#include "parallel.h"
#include "pyramid_layout.h"

#include <math.h>
#include <stdlib.h>

/* Light src's visible fraction at grid receiver (x, y) of normal n, as
 * local_visibility.frag's local_ratio: 1 inside the sphere (and for a
 * light nothing can shadow); where the cap lies wholly below the
 * receiver's tangent plane, the fraction for the plane facing the light
 * (tilted up to at least 0.05 in z), so that the texels between it and
 * lit receivers interpolate toward the terrain's occlusion alone. */
static double grid_ratio(const hfs_cpu_local *lc, local_scratch *s, const local_src *src, int x,
                         int y, const double n[3])
{
    const hfs_field *f = lc->f;
    const double p[3] = {x * f->dx, y * f->dx, hfs_field_lifted_z(f, x, y)};
    hfs_local_view lv;
    hfs_local_view_make(&src->light, p, &lv);
    if (lv.inside || src->open)
        return 1.0;
    double nn[3] = {n[0], n[1], n[2]}, hn[HFS_SH_N];
    if (!(hfs_cap_irradiance(n[0] * lv.dir[0] + n[1] * lv.dir[1] + n[2] * lv.dir[2], lv.alpha) >
          0.0)) {
        const double fz = fmax(lv.dir[2], 0.05);
        const double len = sqrt(lv.dir[0] * lv.dir[0] + lv.dir[1] * lv.dir[1] + fz * fz);
        nn[0] = lv.dir[0] / len, nn[1] = lv.dir[1] / len, nn[2] = fz / len;
    }
    hfs_sh_rotate_zonal(lc->h_zonal, nn[0], nn[1], nn[2], hn);
    return hfs_cpu_local_cap_ratio(lc, s, &lv, x, y, nn, hn, 0);
}

/* Grid row b: every light's fraction at its receivers. */
static void grid_row(void *ctx, int b, int worker)
{
    const hfs_cpu_local *lc = ctx;
    const int y = b * lc->sub < lc->h - 1 ? b * lc->sub : lc->h - 1;
    for (int a = 0; a < lc->gw; ++a) {
        const int x = a * lc->sub < lc->w - 1 ? a * lc->sub : lc->w - 1;
        double n[3];
        hfs_field_normal(lc->f, x, y, n);
        for (int q = 0; q < lc->n_src; ++q)
            lc->grid[((size_t)q * lc->gh + (size_t)b) * lc->gw + (size_t)a] =
                grid_ratio(lc, &lc->scratch[worker], &lc->src[q], x, y, n);
    }
}

int hfs_cpu_local_grid_build(hfs_cpu_local *lc, int sub, int threads, hfs_error *err)
{
    if (!lc)
        return HFS_OK;
    lc->sub = sub;
    lc->gw = hfs_grid_count(lc->w, sub);
    lc->gh = hfs_grid_count(lc->h, sub);
    lc->grid = malloc((size_t)lc->n_src * lc->gw * lc->gh * sizeof *lc->grid);
    if (!lc->grid)
        return hfs_fail(err, HFS_E_NOMEM, "backend cpu: out of memory for the local grid");
    hfs_parallel_rows(lc->gh, threads, grid_row, lc, NULL, NULL);
    return HFS_OK;
}
