/*
 * gis_api.c — libhfshade_gis (hfshade_gis.h): the GIS products of a DEM in
 * memory, through the commands' own plumbing (gis_products.h) on a
 * gis_dem made as gis_dem_read makes one from a north-up, square-celled
 * file: the hole mask, the holes filled by push-pull, the grid the
 * renderer takes the input's own (sampled back 1:1).
 */
#include "hfshade_gis.h"

#include "gis_products.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Each product's largest value (gis_command.c describe). */
static const double product_hi[] = {1.0, 90.0, 180.0};

float hfs_gis_nodata(const hfs_gis_dem *dem, hfs_gis_product product)
{
    const int p = product >= HFS_GIS_SVF && product <= HFS_GIS_OPENNESS ? (int)product : 0;
    const float v = dem ? gis_nodata_for(dem->has_nodata, dem->nodata, 0.0, product_hi[p])
                        : GIS_NODATA;
    return isfinite(v) ? v : GIS_NODATA; /* a NaN nodata is not written: outputs are finite */
}

static int check_dem(const hfs_gis_dem *dem, hfs_error *err)
{
    if (!dem || !dem->z)
        return hfs_fail(err, HFS_E_INVALID, "dem: no heights given");
    if (dem->width < 2 || dem->height < 2 || dem->width > HFS_HEIGHT_MAX_DIM ||
        dem->height > HFS_HEIGHT_MAX_DIM ||
        (long long)dem->width * dem->height > HFS_HEIGHT_MAX_TEXELS)
        return hfs_fail(err, HFS_E_INVALID, "dem: %dx%d heights (2..%dx%d allowed)", dem->width,
                        dem->height, HFS_HEIGHT_MAX_DIM, HFS_HEIGHT_MAX_DIM);
    if (!(dem->cell > 0.0 && dem->cell <= DBL_MAX))
        return hfs_fail(err, HFS_E_INVALID, "cell_size: %g metres is not a finite size above 0",
                        dem->cell);
    if (!(dem->zscale >= 1e-9 && dem->zscale <= 1e6))
        return hfs_fail(err, HFS_E_INVALID, "zscale: %g is not a number in [1e-9, 1e6]",
                        dem->zscale);
    return HFS_OK;
}

static int check_radius(double radius, hfs_error *err)
{
    if (radius == HFS_GIS_RADIUS_DEFAULT || (radius >= 0.0 && radius <= 1e9))
        return HFS_OK;
    return hfs_fail(err, HFS_E_INVALID, "radius: %g is not a distance in [0, 1e9] metres",
                    radius);
}

static int check_directions(int n, hfs_error *err)
{
    if (n >= 1 && n <= HFS_MAX_HORIZON_AZIMUTHS)
        return HFS_OK;
    return hfs_fail(err, HFS_E_INVALID, "directions: %d is not a whole number in [1, %d]", n,
                    HFS_MAX_HORIZON_AZIMUTHS);
}

/* The commands' gis_dem of dem (gis_dem.c georef + to_field on a square,
 * north-up grid): the holes marked and filled.  Freed by gis_dem_free's
 * GDAL-free part: free(hole), free(sz). */
static int make_dem(const hfs_gis_dem *dem, gis_dem *d, hfs_error *err)
{
    memset(d, 0, sizeof *d);
    const size_t n = (size_t)dem->width * (size_t)dem->height;
    d->width = d->sw = dem->width;
    d->height = d->sh = dem->height;
    d->cx = d->cy = d->d = dem->cell;
    d->square = 1;
    d->ex = d->ey = 1;
    d->has_nodata = dem->has_nodata;
    d->nodata = dem->nodata;
    d->hole = malloc(n);
    d->sz = malloc(n * sizeof *d->sz);
    if (!d->hole || !d->sz)
        return hfs_fail(err, HFS_E_NOMEM, "dem: out of memory for %dx%d heights", dem->width,
                        dem->height);
    const float nd = (float)dem->nodata;
    for (size_t p = 0; p < n; ++p) {
        float z = dem->z[p];
        if ((dem->has_nodata && z == nd) || (dem->hole && dem->hole[p]))
            z = NAN; /* a hole, as hfs_gdal_read_heights marks them */
        d->hole[p] = !isfinite(z);
        d->sz[p] = z;
    }
    hfs_error ferr;
    const int rc = hfs_height_fill_holes(d->sz, d->width, d->height, 0, 0.0f, &d->holes, &ferr);
    if (rc)
        return hfs_fail(err, rc, "dem: %s", ferr.msg);
    d->centre_z = d->sz[(size_t)(d->height / 2) * (size_t)d->width + (size_t)(d->width / 2)];
    return HFS_OK;
}

static void free_dem(gis_dem *d)
{
    free(d->hole);
    free(d->sz);
    memset(d, 0, sizeof *d);
}

/* Checks, the gis_dem and the compute of product p (radius resolved as
 * gis_command_radius: openness's default 10 cells). */
static int begin(hfs_renderer *r, const hfs_gis_dem *dem, hfs_gis_product p, double radius,
                 gis_dem *d, gis_compute *c, hfs_error *err)
{
    memset(d, 0, sizeof *d);
    if (!r)
        return hfs_fail(err, HFS_E_INVALID, "renderer: none given");
    int rc = check_dem(dem, err);
    if (!rc)
        rc = check_radius(radius, err);
    if (!rc)
        rc = make_dem(dem, d, err);
    if (rc)
        return rc;
    if (radius == HFS_GIS_RADIUS_DEFAULT)
        radius = p == HFS_GIS_OPENNESS ? GIS_OPENNESS_DEFAULT_CELLS * fmax(d->cx, d->cy) : 0.0;
    *c = (gis_compute){.r = r, .dem = d, .zscale = dem->zscale, .radius = radius,
                       .nodata = hfs_gis_nodata(dem, p)};
    return HFS_OK;
}

int hfs_gis_svf(hfs_renderer *r, const hfs_gis_dem *dem, int directions, int lambertian,
                double radius, float *out, hfs_error *err)
{
    gis_dem d;
    gis_compute c;
    int rc = check_directions(directions, err);
    if (!rc && !out)
        rc = hfs_fail(err, HFS_E_INVALID, "out: no output given");
    if (!rc)
        rc = begin(r, dem, HFS_GIS_SVF, radius, &d, &c, err);
    if (!rc)
        rc = gis_product_svf(&c, directions, lambertian ? GIS_SVF_LAMBERTIAN : GIS_SVF_ZAKSEK,
                             out, err);
    free_dem(&d);
    return rc;
}

/* The one azimuth's raster into out (the callback's user). */
typedef struct horizon_out {
    float *out;
    size_t n;
} horizon_out;

static int take_horizon(void *user, int k, const float *deg, hfs_error *err)
{
    horizon_out *h = user;
    (void)k, (void)err;
    memcpy(h->out, deg, h->n * sizeof *deg);
    return HFS_OK;
}

int hfs_gis_horizon(hfs_renderer *r, const hfs_gis_dem *dem, double azimuth, int compass,
                    double radius, float *out, hfs_error *err)
{
    gis_dem d;
    gis_compute c;
    int rc = azimuth >= -1e6 && azimuth <= 1e6
                 ? HFS_OK
                 : hfs_fail(err, HFS_E_INVALID, "azimuth: %g is not an angle in [-1e6, 1e6] "
                            "degrees", azimuth);
    if (!rc && !out)
        rc = hfs_fail(err, HFS_E_INVALID, "out: no output given");
    if (!rc)
        rc = begin(r, dem, HFS_GIS_HORIZON, radius, &d, &c, err);
    if (!rc) {
        const double phi = gis_phi_of(azimuth, compass ? GIS_COMPASS : GIS_CCW_EAST);
        horizon_out h = {.out = out, .n = (size_t)d.width * (size_t)d.height};
        rc = gis_product_horizons(&c, &phi, 1, take_horizon, &h, err);
    }
    free_dem(&d);
    return rc;
}

int hfs_gis_openness(hfs_renderer *r, const hfs_gis_dem *dem, int directions, double radius,
                     float *positive, float *negative, hfs_error *err)
{
    gis_dem d;
    gis_compute c;
    int rc = check_directions(directions, err);
    if (!rc && (!positive || !negative))
        rc = hfs_fail(err, HFS_E_INVALID, "out: no output given");
    if (!rc)
        rc = begin(r, dem, HFS_GIS_OPENNESS, radius, &d, &c, err);
    if (!rc)
        rc = gis_product_openness(&c, directions, positive, negative, err);
    free_dem(&d);
    return rc;
}
