/*
 * height_gdal.c — see height_gdal.h.
 */
#include "height_gdal.h"

#include "gdal_lazy.h"

#include <cpl_error.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

void hfs_gdal_cell_metres(const char *wkt, const double gt[6], int h, double *cx, double *cy)
{
    *cx = fabs(gt[1]), *cy = fabs(gt[5]);
    if (!wkt || !*wkt)
        return; /* no CRS: the geotransform's own units */
    OGRSpatialReferenceH srs = OSRNewSpatialReference(wkt);
    if (!srs)
        return;
    if (OSRIsGeographic(srs)) {
        OGRErr e1 = OGRERR_NONE, e2 = OGRERR_NONE;
        const double a = OSRGetSemiMajor(srs, &e1), inv_f = OSRGetInvFlattening(srs, &e2);
        const double f = inv_f > 0.0 ? 1.0 / inv_f : 0.0, e2sq = f * (2.0 - f);
        const double lat = (gt[3] + gt[5] * 0.5 * h) * PI / 180.0, s = sin(lat);
        const double w = 1.0 - e2sq * s * s;
        const double n_rad = a / sqrt(w), m_rad = a * (1.0 - e2sq) / (w * sqrt(w));
        *cx *= PI / 180.0 * n_rad * cos(lat);
        *cy *= PI / 180.0 * m_rad;
    } else {
        const double unit = OSRGetLinearUnits(srs, NULL); /* metres per unit */
        *cx *= unit > 0.0 ? unit : 1.0;
        *cy *= unit > 0.0 ? unit : 1.0;
    }
    OSRDestroySpatialReference(srs);
}

int hfs_gdal_make_square(float **z, int *w, int *h, double cx, double cy, double *cell)
{
    const double d = cx < cy ? cx : cy;
    const int nw = (int)lround((*w - 1) * cx / d) + 1, nh = (int)lround((*h - 1) * cy / d) + 1;
    float *out = malloc((size_t)nw * (size_t)nh * sizeof *out);
    if (!out)
        return HFS_E_NOMEM;
    for (int j = 0; j < nh; ++j)
        for (int i = 0; i < nw; ++i) {
            const double gx = fmin(i * d / cx, *w - 1.0), gy = fmin(j * d / cy, *h - 1.0);
            const int i0 = gx >= *w - 1 ? *w - 2 : (int)gx, j0 = gy >= *h - 1 ? *h - 2 : (int)gy;
            const double fx = gx - i0, fy = gy - j0;
            const float *r0 = *z + (size_t)j0 * (size_t)*w + (size_t)i0, *r1 = r0 + *w;
            const double a = r0[0] + fx * ((double)r0[1] - r0[0]);
            const double b = r1[0] + fx * ((double)r1[1] - r1[0]);
            out[(size_t)j * (size_t)nw + (size_t)i] = (float)(a + fy * (b - a));
        }
    free(*z);
    *z = out, *w = nw, *h = nh, *cell = d;
    return HFS_OK;
}

int hfs_gdal_read_heights(GDALDatasetH ds, const char *path, const hfs_height_load_opts *opts,
                          float **z, hfs_error *err)
{
    const int w = GDALGetRasterXSize(ds), h = GDALGetRasterYSize(ds);
    GDALRasterBandH band = GDALGetRasterBand(ds, 1);
    *z = malloc((size_t)w * (size_t)h * sizeof **z);
    if (!*z)
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory for %dx%d heights", path, w, h);
    if (GDALRasterIO(band, GF_Read, 0, 0, w, h, *z, w, h, GDT_Float32, 0, 0) != CE_None) {
        free(*z);
        *z = NULL;
        return hfs_fail(err, HFS_E_FORMAT, "%s: GDAL could not read its band 1 (%s)", path,
                        CPLGetLastErrorMsg());
    }
    int has_nd = 0;
    const double nd = GDALGetRasterNoDataValue(band, &has_nd);
    const int use_opts = opts && opts->has_nodata;
    const float hole = use_opts ? opts->nodata : (float)nd;
    const size_t n = (size_t)w * (size_t)h;
    for (size_t p = 0; p < n; ++p)
        if ((use_opts || has_nd) && (*z)[p] == hole)
            (*z)[p] = NAN; /* a hole for hfs_height_fill_holes */
    return HFS_OK;
}

/* A south-up grid's rows flipped: row 0 becomes the north edge. */
static void flip_rows(float *z, int w, int h)
{
    for (int j = 0; j < h / 2; ++j)
        for (int i = 0; i < w; ++i) {
            float *a = z + (size_t)j * w + i, *b = z + (size_t)(h - 1 - j) * w + i;
            const float t = *a;
            *a = *b, *b = t;
        }
}

int hfs_gdal_check_dataset(GDALDatasetH ds, const char *path, const hfs_height_load_opts *opts,
                           double gt[6], hfs_error *err)
{
    const int w = GDALGetRasterXSize(ds), h = GDALGetRasterYSize(ds);
    const int maxw = opts && opts->max_width ? opts->max_width : HFS_HEIGHT_MAX_DIM;
    const int maxh = opts && opts->max_height ? opts->max_height : HFS_HEIGHT_MAX_DIM;
    if (GDALGetRasterCount(ds) < 1)
        return hfs_fail(err, HFS_E_FORMAT, "%s: GDAL opens it but it has no raster band", path);
    if (w < 2 || h < 2 || w > maxw || h > maxh || (long long)w * h > HFS_HEIGHT_MAX_TEXELS)
        return hfs_fail(err, HFS_E_FORMAT, "%s: %dx%d heights (2..%dx%d allowed)", path, w, h,
                        maxw, maxh);
    if (GDALGetGeoTransform(ds, gt) != CE_None) {
        const double id[6] = {0.0, 1.0, 0.0, 0.0, 0.0, -1.0};
        memcpy(gt, id, sizeof id);
        gt[1] = 0.0; /* no cell size known */
    } else if (gt[2] != 0.0 || gt[4] != 0.0) {
        return hfs_fail(err, HFS_E_INVALID, "%s: a rotated or sheared grid (geotransform "
                        "terms %g, %g): not north-up", path, gt[2], gt[4]);
    }
    return HFS_OK;
}

/* out's georeferencing: the file's geotransform, made north-up (a south-up
 * grid's rows were flipped) and scaled to the resampled cells (node 0
 * stays where it was: make_square samples node-aligned), and its CRS. */
static void georef(GDALDatasetH ds, const double gt[6], int w0, int h0, hfs_heightmap *out)
{
    double g[6];
    memcpy(g, gt, sizeof g);
    if (g[5] > 0.0) { /* south-up: the last row's far edge is the north one */
        g[3] += g[5] * h0;
        g[5] = -g[5];
    }
    /* (a loaded grid is at least 2 x 2, hfs_gdal_check_dataset; guarded all the same) */
    const double sx = out->width > 1 ? (w0 - 1.0) / (out->width - 1.0) : 1.0;
    const double sy = out->height > 1 ? (h0 - 1.0) / (out->height - 1.0) : 1.0;
    g[0] += 0.5 * g[1] * (1.0 - sx), g[1] *= sx;
    g[3] += 0.5 * g[5] * (1.0 - sy), g[5] *= sy;
    memcpy(out->geotransform, g, sizeof g);
    out->has_georef = 1;
    const char *wkt = GDALGetProjectionRef(ds);
    if (wkt && strlen(wkt) < sizeof out->crs_wkt) {
        snprintf(out->crs_wkt, sizeof out->crs_wkt, "%s", wkt);
    } else if (wkt) { /* too long to keep: say so (hfs_io.h) */
        const size_t n = strlen(out->note);
        snprintf(out->note + n, sizeof out->note - n, "%sCRS dropped (WKT of %zu bytes)",
                 n ? "; " : "", strlen(wkt));
    }
}

int hfs_gdal_height_load(const char *path, const hfs_height_load_opts *opts,
                         hfs_heightmap *out, hfs_error *err)
{
    memset(out, 0, sizeof *out);
    int rc = hfs_gdal_need(path, err); /* not HFS_E_UNSUPPORTED: the file may be GDAL's */
    if (rc)
        return rc;
    CPLPushErrorHandler(CPLQuietErrorHandler);
    GDALDatasetH ds = GDALOpenEx(path, GDAL_OF_RASTER | GDAL_OF_READONLY, NULL, NULL, NULL);
    if (!ds) {
        CPLPopErrorHandler();
        return hfs_fail(err, HFS_E_UNSUPPORTED, "%s: GDAL cannot open it as a raster", path);
    }
    double gt[6];
    float *z = NULL;
    int w = GDALGetRasterXSize(ds), h = GDALGetRasterYSize(ds);
    rc = hfs_gdal_check_dataset(ds, path, opts, gt, err);
    if (!rc && !(rc = hfs_gdal_read_heights(ds, path, opts, &z, err)) && gt[5] > 0.0)
        flip_rows(z, w, h);
    /* Holes filled on the file's own grid, before any resampling spreads them. */
    long holes = 0;
    hfs_error ferr;
    int frc;
    if (!rc && (frc = hfs_height_fill_holes(z, w, h, 0, 0.0f, &holes, &ferr)))
        rc = hfs_fail(err, frc, "%s: %s", path, ferr.msg);
    double cx = 0.0, cy = 0.0, cell = 0.0;
    if (!rc && gt[1] != 0.0) {
        hfs_gdal_cell_metres(GDALGetProjectionRef(ds), gt, h, &cx, &cy);
        cell = cx;
        if (fabs(cx - cy) > 1e-6 * fmax(cx, cy)) {
            const int w0 = w, h0 = h;
            if ((rc = hfs_gdal_make_square(&z, &w, &h, cx, cy, &cell)))
                rc = hfs_fail(err, rc, "%s: out of memory resampling to square cells", path);
            else
                snprintf(out->note, sizeof out->note, "%s: resampled %dx%d cells of %.4g x "
                         "%.4g m to %dx%d square cells of %.4g m", path, w0, h0, cx, cy, w, h,
                         cell);
        }
    }
    if (!rc) {
        out->width = w, out->height = h, out->z = z, out->holes = holes;
        out->cellsize = cell;
        out->format = HFS_HEIGHT_EXTERNAL;
        if (gt[1] != 0.0) /* a geotransform was there */
            georef(ds, gt, GDALGetRasterXSize(ds), GDALGetRasterYSize(ds), out);
    }
    GDALClose(ds);
    CPLPopErrorHandler();
    if (rc) {
        free(z);
        return rc;
    }
    return HFS_OK;
}

void hfs_gdal_register(void)
{
    /* GDAL itself is loaded by the first file only the extra loader reads
     * (gdal_lazy.h), and registers its drivers then. */
    hfs_height_set_extra_loader(hfs_gdal_height_load);
}
