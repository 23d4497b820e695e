/*
 * layout.c — see layout.h.
 */
#include "layout.h"

#include "field_geom.h"
#include "gl_util.h"
#include "parallel.h"
#include "pyramid_layout.h"
#include "split_horizon.h"

#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846

int hfs_gles_layout_init(hfs_gles_layout *L, const hfs_field *f, const hfs_quality *q,
                         hfs_error *err)
{
    memset(L, 0, sizeof *L);
    L->w = f->width;
    L->h = f->height;
    L->k = q->k;
    L->offset = q->offset;
    L->dx = f->dx;
    L->zscale = f->zscale;
    L->n_levels = hfs_pyramid_level_count(L->w, L->h, q->k);
    if (L->n_levels > HFS_GLES_MAX_LEVELS)
        return hfs_fail(err, HFS_E_UNSUPPORTED, "backend gles: %d pyramid levels (k=%d, %dx%d) "
                        "exceed %d", L->n_levels, q->k, L->w, L->h, HFS_GLES_MAX_LEVELS);
    L->lmin = hfs_pyramid_read_level(L->n_levels, q->k, q->offset, 0);
    L->n_layers = L->n_levels - L->lmin;
    L->sub = q->subsample < 1 ? 1 : q->subsample;
    L->vw = hfs_grid_count(L->w, L->sub);
    L->vh = hfs_grid_count(L->h, L->sub);
    for (int i = 0; i < L->n_levels; ++i) {
        hfs_pyramid_level_size(L->w, L->h, q->k, i, &L->lw[i], &L->lh[i]);
        L->spacing[i] = hfs_pyramid_spacing(L->n_levels, q->k, i);
        L->read_layer[i] = hfs_pyramid_read_level(L->n_levels, q->k, q->offset, i) - L->lmin;
    }
    hfs_ray_bound_layout_make(L->w, L->h, &L->rb);
    double lo, hi;
    hfs_field_range(f, &lo, &hi);
    L->base = 0.5 * lo + 0.5 * hi; /* no overflow for any float range */
    L->hscale = 0.5 * hi - 0.5 * lo;
    L->hunit = hfs_split_h_unit(lo, hi, L->zscale, L->dx);
    L->vmax = 1.0;
    if (!(L->hscale > 0.0)) {
        L->hscale = 1.0; /* flat: every v is 0 */
        L->vmax = 0.0;
    }
    return HFS_OK;
}

/* The fp16 split, a frame's largest piece of host work at 1024² (issue
 * 37): on worker threads from 256k texels, each chunk keeping its own
 * largest error (hfs_parallel_ranges: the same bits for any thread count). */
#define SPLIT_THREADED 262144
typedef struct split_job {
    const float *z;
    double base, scale;
    uint16_t *rg;
    int measure;
    double worst[HFS_PARALLEL_CHUNKS];
} split_job;

static void split_range(void *ctx, size_t a, size_t b, int chunk)
{
    split_job *j = ctx;
    j->worst[chunk] =
        hfs_half_split(j->z + a, b - a, j->base, j->scale, j->rg + 2 * a, j->measure);
}

double hfs_gles_split_heights(const hfs_gles_layout *L, const hfs_field *f, int fp32,
                              void *dst, int measure)
{
    const size_t n = (size_t)L->w * (size_t)L->h;
    if (fp32) {
        float *out = dst;
        for (size_t i = 0; i < n; ++i) {
            out[2 * i] = (float)(((double)f->z[i] - L->base) / L->hscale);
            out[2 * i + 1] = 0.0f;
        }
        return 0.0;
    }
    split_job j = {.z = f->z, .base = L->base, .scale = L->hscale, .rg = dst, .measure = measure};
    hfs_parallel_ranges(n, SPLIT_THREADED, split_range, &j);
    double worst = 0.0;
    for (int c = 0; c < HFS_PARALLEL_CHUNKS; ++c)
        worst = j.worst[c] > worst ? j.worst[c] : worst;
    return worst;
}

double hfs_gles_local_max_irradiance(const hfs_gles_layout *L, const hfs_local_light *l)
{
    const double lo[3] = {0.0, 0.0, L->zscale * (L->base - L->hscale)};
    const double hi[3] = {(L->w - 1) * L->dx, (L->h - 1) * L->dx,
                          L->zscale * (L->base + L->hscale) + 1e-4 * L->dx};
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double c = l->pos[k], e = c < lo[k] ? lo[k] - c : (c > hi[k] ? c - hi[k] : 0.0);
        d2 += e * e;
    }
    const double r2 = l->radius * l->radius;
    return d2 <= r2 ? PI : PI * r2 / d2;
}

double hfs_gles_output_scale(double bound)
{
    if (!(bound > 0.0) || !isfinite(bound))
        return 1.0;
    int e = (int)floor(log2(16384.0 / bound));
    e = e < -1000 ? -1000 : (e > 1000 ? 1000 : e); /* double's range */
    return ldexp(1.0, e);
}
