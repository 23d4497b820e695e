/*
 * truth_horizons.c — the GIS horizons in the ground truth
 * (hfs_renderer_horizons): for every grid point and azimuth, the exact
 * supremum of the slope to SPEC's bilinear surface within the radius
 * (hfs_truth_horizon_within: each crossed cell in closed form), from the
 * point's own surface height, as an elevation angle.  Rows in parallel;
 * each row writes only its own texels, so the result does not depend on
 * the thread count.
 */
#include "backends.h"
#include "field_geom.h"
#include "parallel.h"
#include "truth_raycast.h"

#include <math.h>
#include <stdlib.h>

typedef struct horizon_rows {
    const hfs_truth_grid *g;
    const hfs_horizon_desc *d;
    double t_max; /* texels */
    float *out;
} horizon_rows;

static void horizon_row(void *ctx, int j, int worker)
{
    (void)worker;
    const horizon_rows *h = ctx;
    const hfs_field *f = h->g->f;
    const size_t plane = (size_t)f->width * (size_t)f->height;
    for (int a = 0; a < h->d->n_azimuths; ++a) {
        double c, s;
        hfs_horizon_dir(h->d->azimuth[a], &c, &s);
        float *row = h->out + plane * (size_t)a + (size_t)j * (size_t)f->width;
        double hint = 0.0; /* the neighbour's maximum: looked at first, a speed-up only */
        for (int i = 0; i < f->width; ++i) {
            const double z0 = f->zscale * f->z[(size_t)j * (size_t)f->width + (size_t)i];
            const double m = hfs_truth_horizon_within(h->g, i, j, z0, c, s, h->t_max, &hint);
            row[i] = m > -INFINITY ? (float)atan(m) : HFS_HORIZON_NONE;
        }
    }
}

int hfs_truth_horizons(const hfs_field *f, const hfs_quality *q, const hfs_horizon_desc *d,
                       float *out, hfs_error *err)
{
    hfs_truth_grid g;
    if (hfs_truth_grid_init(&g, f))
        return hfs_fail(err, HFS_E_NOMEM, "horizons: out of memory for the truth's max mip");
    horizon_rows h = {&g, d, d->radius > 0.0 ? d->radius / f->dx : INFINITY, out};
    hfs_parallel_rows(f->height, q ? q->threads : 0, horizon_row, &h, NULL, NULL);
    hfs_truth_grid_free(&g);
    return HFS_OK;
}
