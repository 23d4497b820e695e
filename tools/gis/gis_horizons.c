/*
 * gis_horizons.c — see gis_horizons.h.
 */
#include "gis_horizons.h"

#include "gis_sweep.h"

#include <stdlib.h>

#define HALF_PI 1.5707963267948966

int gis_horizons_get(hfs_renderer *r, int sweep, const hfs_field *field, const hfs_quality *q,
                     const hfs_horizon_desc *desc, float *out, hfs_error *err)
{
    if (!sweep) {
        hfs_error why = {""};
        const int rc = hfs_renderer_horizons(r, field, q, desc, out, &why);
        /* The renderer's refusal of a whole-field search over its texture
         * side (the only unsupported case without a radius), with the
         * commands' own ways out. */
        if (rc == HFS_E_UNSUPPORTED && desc->radius == 0.0)
            return hfs_fail(err, rc, "%s (here: --radius METRES, --method sweep or --backend "
                            "cpu)", why.msg);
        return rc ? hfs_fail(err, rc, "%s", why.msg) : HFS_OK;
    }
    if (desc->radius != 0.0)
        return hfs_fail(err, HFS_E_INVALID, "horizons: the sweep searches the whole field "
                        "(radius %g asked)", desc->radius);
    const int threads = q ? q->threads : 0;
    return desc->window ? gis_sweep_horizons_in(field, desc->azimuth, desc->n_azimuths, threads,
                                                desc->lo, desc->hi, out, err)
                        : gis_sweep_horizons(field, desc->azimuth, desc->n_azimuths, threads, out,
                                             err);
}

int gis_horizons_each(hfs_renderer *r, int sweep, const hfs_field *field, const hfs_quality *q,
                      const double *phi, int n, double radius, double lo, gis_horizon_fn fn,
                      void *user, hfs_error *err)
{
    const size_t texels = (size_t)field->width * (size_t)field->height;
    size_t batch = GIS_HORIZON_BATCH_FLOATS / texels;
    batch = batch < 1 ? 1 : batch > (size_t)HFS_MAX_HORIZON_AZIMUTHS ? HFS_MAX_HORIZON_AZIMUTHS
                                                                      : batch;
    batch = batch > (size_t)n ? (size_t)n : batch;
    float *out = malloc(batch * texels * sizeof *out);
    if (!out)
        return hfs_fail(err, HFS_E_NOMEM, "horizons: out of memory for %zu x %dx%d angles",
                        batch, field->width, field->height);
    int rc = HFS_OK;
    for (int k0 = 0; k0 < n && !rc; k0 += (int)batch) {
        const int m = n - k0 < (int)batch ? n - k0 : (int)batch;
        const hfs_horizon_desc desc = {.n_azimuths = m, .azimuth = phi + k0, .radius = radius,
                                       .window = lo > -HALF_PI, .lo = lo, .hi = HALF_PI};
        rc = gis_horizons_get(r, sweep, field, q, &desc, out, err);
        for (int a = 0; a < m && !rc; ++a)
            rc = fn(user, k0 + a, out + (size_t)a * texels, err);
    }
    free(out);
    return rc;
}
