/*
 * cpu_horizons.c — the GIS horizons on the CPU reference
 * (hfs_renderer_horizons): each grid point's gap search
 * (runtime/core/ray_bound.h, the search the key lights' and the far
 * grid's horizons make, and the GLES pass of the same name) over every
 * crossing within the radius, the near end of the point's own cell
 * (hfs_field_first_cell_slope), the point where the ray leaves the grid
 * and the one where it reaches the radius, from the point's own height, in
 * double precision.  Rows in parallel, each writing its own texels.
 */
#include "backends.h"
#include "field_geom.h"
#include "parallel.h"
#include "ray_bound.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>

typedef struct horizon_rows {
    const hfs_field *f;
    const hfs_horizon_desc *d;
    const hfs_ray_bound_layout *L;
    const double *atlas, *z;
    double t_last; /* texels */
    double floor;  /* the slope the search starts from: tan(lo) in a window */
    float *out;
} horizon_rows;

/* Where the ray leaves the grid through a side parallel to its major axis
 * (between two crossings, where the search does not look), the surface's
 * slope there: the last cell's far end, as crossing 1 is the first cell's
 * (shaders_es/horizons.frag exit_slope, the same steps).  -DBL_MAX when
 * the ray leaves at a crossing or past t_last (texels). */
static double exit_slope(const hfs_field *f, int i, int j, double c, double s, double t_last)
{
    const int xm = fabs(c) >= fabs(s);
    const double ma = xm ? c : s, mi = xm ? s : c;
    const int p = xm ? i : j, q = xm ? j : i;
    const int np = xm ? f->width : f->height, nq = xm ? f->height : f->width;
    const double t = mi != 0.0 ? ((mi > 0.0 ? nq - 1 : 0) - q) / mi : -1.0;
    const double pm = p + t * ma; /* the major coordinate there */
    if (!(t > 0.0 && t <= t_last && pm >= 0.0 && pm <= np - 1) || pm == floor(pm))
        return -DBL_MAX;
    const int a = (int)floor(pm), e = mi > 0.0 ? nq - 1 : 0;
    const double fr = pm - a;
    const double za = xm ? hfs_field_z(f, a, e) : hfs_field_z(f, e, a);
    const double zb = xm ? hfs_field_z(f, a + 1, e) : hfs_field_z(f, e, a + 1);
    return (za + fr * (zb - za) - hfs_field_z(f, i, j)) / (t * f->dx);
}

/* The surface where the ray reaches the radius (t_last texels, finite),
 * the last cell's far end within it: -DBL_MAX past the grid or with no
 * radius (horizons.frag end_slope, the same). */
static double end_slope(const hfs_field *f, int i, int j, double c, double s, double t_last)
{
    double z;
    if (!(t_last < HUGE_VAL) || !hfs_field_bilinear(f, i + t_last * c, j + t_last * s, &z))
        return -DBL_MAX;
    return (z - hfs_field_z(f, i, j)) / (t_last * f->dx);
}

static void horizon_row(void *ctx, int j, int worker)
{
    (void)worker;
    const horizon_rows *h = ctx;
    const hfs_field *f = h->f;
    const size_t w = (size_t)f->width, plane = w * (size_t)f->height;
    const double zs = f->zscale / f->dx;
    for (int a = 0; a < h->d->n_azimuths; ++a) {
        double c, s;
        hfs_horizon_dir(h->d->azimuth[a], &c, &s);
        float *row = h->out + plane * (size_t)a + (size_t)j * w;
        for (int i = 0; i < f->width; ++i) {
            /* the own cell's near end (its far end is crossing 1: the
             * surface may fall away from its steepest start), the exit
             * through a side and the end at the radius */
            double dist = 0.0;
            const double near = fmax(fmax(hfs_field_first_cell_slope(f, i, j, c, s), h->floor),
                                     fmax(exit_slope(f, i, j, c, s, h->t_last),
                                          end_slope(f, i, j, c, s, h->t_last)));
            const double m = hfs_ray_bound_search_cells(h->L, h->atlas, h->z, w, i, j, c, s,
                                                        0.0, h->t_last, zs, 0.0, near, &dist,
                                                        NULL);
            row[i] = m > -DBL_MAX ? (float)atan(m) : HFS_HORIZON_NONE;
        }
    }
}

int hfs_cpu_horizons(const hfs_field *f, const hfs_quality *q, const hfs_horizon_desc *d,
                     float *out, hfs_error *err)
{
    hfs_ray_bound_layout L;
    hfs_ray_bound_layout_make(f->width, f->height, &L);
    const size_t n = (size_t)f->width * (size_t)f->height;
    double *atlas = malloc((size_t)L.aw * (size_t)L.ah * sizeof *atlas);
    double *z = malloc(n * sizeof *z), *scratch = malloc(n * sizeof *scratch);
    int rc = HFS_OK;
    if (!atlas || !z || !scratch) {
        rc = hfs_fail(err, HFS_E_NOMEM, "horizons: out of memory for a %dx%d field's bounds",
                      f->width, f->height);
    } else {
        for (size_t k = 0; k < n; ++k)
            z[k] = f->z[k];
        hfs_ray_bound_build(&L, f->z, 0.0, 1.0, -HUGE_VAL, atlas, scratch);
        horizon_rows h = {f, d, &L, atlas, z, d->radius > 0.0 ? d->radius / f->dx : HUGE_VAL,
                          d->window ? tan(d->lo) : -DBL_MAX, out};
        hfs_parallel_rows(f->height, q ? q->threads : 0, horizon_row, &h, NULL, NULL);
    }
    free(atlas);
    free(z);
    free(scratch);
    return rc;
}
