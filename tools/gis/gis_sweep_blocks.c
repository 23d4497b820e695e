/*
 * gis_sweep_blocks.c — see gis_sweep_blocks.h.
 */
#include "gis_sweep_blocks.h"

#include "parallel.h"

#include <math.h>
#include <stdlib.h>

/* A block's values: indices into its 6. */
enum { B_ZMIN, B_ZMAX, B_RISE_PX, B_RISE_NX, B_RISE_PY, B_RISE_NY, B_VALUES };

static inline double max2(double a, double b)
{
    return a > b ? a : b;
}

typedef struct blocks_job {
    gis_sweep_blocks *b;
    const hfs_field *f;
} blocks_job;

/* Block row `by` of the field's blocks (parallel.h: each row one
 * worker's).  The heights and differences as gis_sweep.c's band_column
 * takes them (zscale times each height, then the difference): the same
 * numbers, so a block's maximum is at least each band's. */
static void block_row(void *ctx, int by, int worker)
{
    const blocks_job *j = ctx;
    const hfs_field *f = j->f;
    const int w = f->width, h = f->height;
    const double zs = f->zscale;
    (void)worker;
    double *first = j->b->v + (size_t)by * (size_t)j->b->bw * B_VALUES;
    for (int bx = 0; bx < j->b->bw; ++bx) {
        double *o = first + (size_t)bx * B_VALUES;
        o[B_ZMIN] = HUGE_VAL, o[B_ZMAX] = -HUGE_VAL;
        o[B_RISE_PX] = o[B_RISE_NX] = o[B_RISE_PY] = o[B_RISE_NY] = 0.0;
    }
    const int y1 = (by + 1) * GIS_SWEEP_BLOCK < h ? (by + 1) * GIS_SWEEP_BLOCK : h;
    for (int y = by * GIS_SWEEP_BLOCK; y < y1; ++y) {
        const float *row = f->z + (size_t)y * (size_t)w;
        for (int x = 0; x < w; ++x) {
            double *o = first + (size_t)(x / GIS_SWEEP_BLOCK) * B_VALUES;
            const double z = zs * row[x];
            o[B_ZMIN] = z < o[B_ZMIN] ? z : o[B_ZMIN];
            o[B_ZMAX] = z > o[B_ZMAX] ? z : o[B_ZMAX];
            if (x + 1 < w)
                o[B_RISE_PX] = max2(o[B_RISE_PX], zs * row[x + 1] - z);
            if (x >= 1)
                o[B_RISE_NX] = max2(o[B_RISE_NX], zs * row[x - 1] - z);
            if (y + 1 < h)
                o[B_RISE_PY] = max2(o[B_RISE_PY], zs * row[x + w] - z);
            if (y >= 1)
                o[B_RISE_NY] = max2(o[B_RISE_NY], zs * row[(ptrdiff_t)x - w] - z);
        }
    }
}

int gis_sweep_blocks_make(gis_sweep_blocks *b, const hfs_field *f, int threads)
{
    b->bw = (f->width + GIS_SWEEP_BLOCK - 1) / GIS_SWEEP_BLOCK;
    b->bh = (f->height + GIS_SWEEP_BLOCK - 1) / GIS_SWEEP_BLOCK;
    b->v = malloc((size_t)b->bw * (size_t)b->bh * B_VALUES * sizeof *b->v);
    if (!b->v)
        return HFS_E_NOMEM;
    blocks_job j = {b, f};
    hfs_parallel_rows(b->bh, threads, block_row, &j, NULL, NULL);
    return HFS_OK;
}

double gis_sweep_blocks_zabs(const gis_sweep_blocks *b)
{
    double zabs = 0.0;
    for (size_t q = 0; q < (size_t)b->bw * (size_t)b->bh; ++q) {
        const double *o = b->v + q * B_VALUES;
        zabs = max2(zabs, max2(fabs(o[B_ZMIN]), fabs(o[B_ZMAX])));
    }
    return zabs;
}

void gis_sweep_blocks_free(gis_sweep_blocks *b)
{
    free(b->v);
    b->v = NULL;
}

/* The field's index range [*lo, *hi] of frame indices a..b (a <= b) along
 * an axis of n texels walked up (up) or down it. */
static inline void axis_range(int a, int b, int up, int n, int *lo, int *hi)
{
    *lo = up ? a : n - 1 - b;
    *hi = up ? b : n - 1 - a;
}

gis_sweep_extent gis_sweep_blocks_line(const gis_sweep_blocks *b, const gis_sweep_frame *fr,
                                       long k)
{
    gis_sweep_extent e = {HUGE_VAL, -HUGE_VAL, 0.0, 0.0, 0.0};
    /* the rises along u and along v (both ways across v for dv_abs), by
     * the field's axis each frame axis runs along */
    const int du_at = fr->x_major ? (fr->u_up ? B_RISE_PX : B_RISE_NX)
                                  : (fr->u_up ? B_RISE_PY : B_RISE_NY);
    const int dv_at = fr->x_major ? (fr->v_up ? B_RISE_PY : B_RISE_NY)
                                  : (fr->v_up ? B_RISE_PX : B_RISE_NX);
    const int dv_back = fr->x_major ? (fr->v_up ? B_RISE_NY : B_RISE_PY)
                                    : (fr->v_up ? B_RISE_NX : B_RISE_PX);
    for (int u0 = 0; u0 < fr->nu; u0 += GIS_SWEEP_BLOCK) {
        const int u1 = u0 + GIS_SWEEP_BLOCK - 1 < fr->nu ? u0 + GIS_SWEEP_BLOCK - 1 : fr->nu - 1;
        /* band_column's rows over columns u0..u1 (y grows with u: r >= 0) */
        const double y0 = (double)k + fr->r * u0, y1 = (double)k + fr->r * u1;
        if (y1 < -1.5 || y0 > fr->nv + 0.5)
            continue;
        const int f0 = (int)floor(y0), f1 = (int)floor(y1); /* within the rows, give or take 2 */
        const int j0 = f0 - 2 > 0 ? f0 - 2 : 0, j1 = f1 + 3 < fr->nv - 1 ? f1 + 3 : fr->nv - 1;
        if (j0 > j1)
            continue;
        int ulo, uhi, vlo, vhi;
        axis_range(u0, u1, fr->u_up, fr->nu, &ulo, &uhi);
        axis_range(j0, j1, fr->v_up, fr->nv, &vlo, &vhi);
        const int xlo = fr->x_major ? ulo : vlo, xhi = fr->x_major ? uhi : vhi;
        const int ylo = fr->x_major ? vlo : ulo, yhi = fr->x_major ? vhi : uhi;
        for (int by = ylo / GIS_SWEEP_BLOCK; by <= yhi / GIS_SWEEP_BLOCK; ++by)
            for (int bx = xlo / GIS_SWEEP_BLOCK; bx <= xhi / GIS_SWEEP_BLOCK; ++bx) {
                const double *o = b->v + ((size_t)by * (size_t)b->bw + (size_t)bx) * B_VALUES;
                e.zmin = o[B_ZMIN] < e.zmin ? o[B_ZMIN] : e.zmin;
                e.zmax = max2(e.zmax, o[B_ZMAX]);
                e.du = max2(e.du, o[du_at]);
                e.dv = max2(e.dv, o[dv_at]);
                e.dv_abs = max2(e.dv_abs, max2(o[dv_at], o[dv_back]));
            }
    }
    return e;
}
