/*
 * gis_products.c — see gis_products.h.
 */
#include "gis_products.h"

#include "gis_horizons.h"
#include "gis_resample.h"
#include "parallel.h"

#include <stdlib.h>

/* What the horizon callback sums into, on the square grid. */
typedef struct sums {
    gis_svf_kind kind;
    double *acc;
    int *count; /* openness only */
    size_t n;
    const float *gamma; /* the azimuth at hand */
} sums;

/* An azimuth's sums run on all cores, texel ranges apart (parallel.h:
 * each texel its own sum, so the same values for any split). */
static void svf_range(void *ctx, size_t b, size_t e, int chunk)
{
    const sums *s = ctx;
    (void)chunk;
    gis_svf_add(s->acc + b, s->gamma + b, e - b, s->kind);
}

static void openness_range(void *ctx, size_t b, size_t e, int chunk)
{
    const sums *s = ctx;
    (void)chunk;
    gis_openness_add(s->acc + b, s->count + b, s->gamma + b, e - b);
}

static int add_svf(void *user, int k, const float *gamma, hfs_error *err)
{
    sums *s = user;
    (void)k, (void)err;
    s->gamma = gamma;
    hfs_parallel_ranges(s->n, GIS_SUMS_THREADED, svf_range, s);
    return HFS_OK;
}

static int add_openness(void *user, int k, const float *gamma, hfs_error *err)
{
    sums *s = user;
    (void)k, (void)err;
    s->gamma = gamma;
    hfs_parallel_ranges(s->n, GIS_SUMS_THREADED, openness_range, s);
    return HFS_OK;
}

void gis_product_directions(double *phi, int n_dirs)
{
    for (int k = 0; k < n_dirs; ++k)
        phi[k] = gis_phi_of(360.0 * k / n_dirs, GIS_CCW_EAST);
}

/* Horizons of the map azimuths phi over heights z (the square grid), each
 * to fn. */
static int horizons(const gis_compute *c, const float *z, const double *phi, int n, double lo,
                    gis_horizon_fn fn, void *user, hfs_error *err)
{
    const gis_dem *d = c->dem;
    double *grid = malloc((size_t)n * sizeof *grid);
    if (!grid)
        return hfs_fail(err, HFS_E_NOMEM, "horizons: out of memory");
    for (int k = 0; k < n; ++k)
        grid[k] = gis_grid_phi(phi[k], d->ex, d->ey);
    const hfs_field field = {.width = d->sw, .height = d->sh, .z = z, .dx = d->d,
                             .zscale = c->zscale};
    hfs_quality q;
    hfs_quality_defaults(&q);
    const int rc =
        gis_horizons_each(c->r, c->sweep, &field, &q, grid, n, c->radius, lo, fn, user, err);
    free(grid);
    return rc;
}

/* sq (the square grid) onto the input's grid. */
static void back(const gis_compute *c, const float *sq, float *out)
{
    const gis_dem *d = c->dem;
    gis_sample_back(sq, d->sw, d->sh, d->cx / d->d, d->cy / d->d, d->width, d->height, d->hole,
                    c->nodata, out);
}

int gis_product_svf(const gis_compute *c, int n_dirs, gis_svf_kind kind, float *out,
                    hfs_error *err)
{
    const size_t n = (size_t)c->dem->sw * (size_t)c->dem->sh;
    sums s = {.kind = kind, .acc = calloc(n, sizeof(double)), .n = n};
    float *sq = malloc(n * sizeof *sq);
    double *phi = malloc((size_t)n_dirs * sizeof *phi);
    int rc = s.acc && sq && phi ? HFS_OK : hfs_fail(err, HFS_E_NOMEM, "svf: out of memory");
    if (!rc) {
        gis_product_directions(phi, n_dirs);
        rc = horizons(c, c->dem->sz, phi, n_dirs, 0.0, add_svf, &s, err); /* clamps at 0 */
    }
    if (!rc) {
        gis_svf_finish(sq, s.acc, n, n_dirs, kind);
        back(c, sq, out);
    }
    free(phi);
    free(sq);
    free(s.acc);
    return rc;
}

/* One openness (of z, the square grid's heights or their negation) onto
 * the input's grid. */
static int openness(const gis_compute *c, const float *z, const double *phi, int n_dirs,
                    float *sq, float *out, hfs_error *err)
{
    const size_t n = (size_t)c->dem->sw * (size_t)c->dem->sh;
    sums s = {.acc = calloc(n, sizeof(double)), .count = calloc(n, sizeof(int)), .n = n};
    int rc = s.acc && s.count ? horizons(c, z, phi, n_dirs, GIS_HORIZONS_ALL, add_openness, &s, err)
                              : hfs_fail(err, HFS_E_NOMEM, "openness: out of memory");
    if (!rc) {
        gis_openness_finish(sq, s.acc, s.count, n);
        back(c, sq, out);
    }
    free(s.acc);
    free(s.count);
    return rc;
}

int gis_product_openness(const gis_compute *c, int n_dirs, float *pos, float *neg,
                         hfs_error *err)
{
    const size_t n = (size_t)c->dem->sw * (size_t)c->dem->sh;
    float *sq = malloc(n * sizeof *sq), *negz = malloc(n * sizeof *negz);
    double *phi = malloc((size_t)n_dirs * sizeof *phi);
    int rc = sq && negz && phi ? HFS_OK : hfs_fail(err, HFS_E_NOMEM, "openness: out of memory");
    if (!rc) {
        gis_product_directions(phi, n_dirs);
        for (size_t p = 0; p < n; ++p)
            negz[p] = -c->dem->sz[p];
        rc = openness(c, c->dem->sz, phi, n_dirs, sq, pos, err);
    }
    if (!rc)
        rc = openness(c, negz, phi, n_dirs, sq, neg, err);
    free(phi);
    free(negz);
    free(sq);
    return rc;
}

/* Each azimuth's angles to degrees on the input's grid, then to the
 * caller's fn. */
typedef struct per_azimuth {
    const gis_compute *c;
    float *sq, *out;
    gis_raster_fn fn;
    void *user;
} per_azimuth;

static int one_horizon(void *user, int k, const float *gamma, hfs_error *err)
{
    per_azimuth *a = user;
    gis_horizon_degrees(a->sq, gamma, (size_t)a->c->dem->sw * (size_t)a->c->dem->sh);
    back(a->c, a->sq, a->out);
    return a->fn(a->user, k, a->out, err);
}

int gis_product_horizons(const gis_compute *c, const double *phi, int n, gis_raster_fn fn,
                         void *user, hfs_error *err)
{
    per_azimuth a = {.c = c,
                     .sq = malloc((size_t)c->dem->sw * (size_t)c->dem->sh * sizeof(float)),
                     .out = malloc((size_t)c->dem->width * (size_t)c->dem->height *
                                   sizeof(float)),
                     .fn = fn,
                     .user = user};
    int rc = a.sq && a.out ? horizons(c, c->dem->sz, phi, n, 0.0, one_horizon, &a, err)
                           : hfs_fail(err, HFS_E_NOMEM, "horizon: out of memory");
    free(a.sq);
    free(a.out);
    return rc;
}
