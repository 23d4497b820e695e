/*
 * gis_dem.c — see gis_dem.h.
 */
#include "gis_dem.h"

#include "gdal_lazy.h"
#include "height_gdal.h"

#include <cpl_error.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* The file's georeferencing and declared nodata into dem; a DEM with no
 * geotransform is refused (nothing says how large its cells are). */
static int georef(GDALDatasetH ds, const char *path, const hfs_height_load_opts *opts,
                  gis_dem *dem, hfs_error *err)
{
    if (dem->gt[1] == 0.0 || dem->gt[5] == 0.0)
        return hfs_fail(err, HFS_E_INVALID, "%s: no geotransform (the cells' size in metres "
                        "is unknown; the GIS commands need a georeferenced DEM)", path);
    const char *wkt = GDALGetProjectionRef(ds);
    const size_t len = wkt ? strlen(wkt) : 0;
    if (!(dem->wkt = malloc(len + 1)))
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", path);
    memcpy(dem->wkt, wkt ? wkt : "", len + 1);
    int has = 0;
    const double nd = GDALGetRasterNoDataValue(GDALGetRasterBand(ds, 1), &has);
    dem->has_nodata = (opts && opts->has_nodata) || has;
    dem->nodata = opts && opts->has_nodata ? opts->nodata : nd;
    dem->ex = dem->gt[1] > 0.0 ? 1 : -1;
    dem->ey = dem->gt[5] < 0.0 ? 1 : -1;
    hfs_gdal_cell_metres(dem->wkt, dem->gt, dem->height, &dem->cx, &dem->cy);
    if (!(dem->cx > 0.0 && dem->cy > 0.0 && isfinite(dem->cx) && isfinite(dem->cy)))
        return hfs_fail(err, HFS_E_INVALID, "%s: cells of %g x %g m: not a usable size", path,
                        dem->cx, dem->cy);
    /* Square as the render loader judges: then computed on the input's own
     * grid and sampled back 1:1; else make_square's cell, the smaller side. */
    dem->square = fabs(dem->cx - dem->cy) <= 1e-6 * fmax(dem->cx, dem->cy);
    if (dem->square)
        dem->cy = dem->cx;
    dem->d = fmin(dem->cx, dem->cy);
    dem->sw = dem->width, dem->sh = dem->height;
    return HFS_OK;
}

/* z (the file's heights, holes NaN) -> the hole mask, then filled, then
 * made the square grid (z is taken over). */
static int to_field(float *z, const char *path, gis_dem *dem, hfs_error *err)
{
    const size_t n = (size_t)dem->width * (size_t)dem->height;
    if (!(dem->hole = malloc(n))) {
        free(z);
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", path);
    }
    for (size_t p = 0; p < n; ++p)
        dem->hole[p] = !isfinite(z[p]);
    hfs_error ferr;
    int rc = hfs_height_fill_holes(z, dem->width, dem->height, 0, 0.0f, &dem->holes, &ferr);
    if (rc) {
        free(z);
        return hfs_fail(err, rc, "%s: %s", path, ferr.msg);
    }
    dem->centre_z = z[(size_t)(dem->height / 2) * (size_t)dem->width + (size_t)(dem->width / 2)];
    if (!dem->square &&
        (rc = hfs_gdal_make_square(&z, &dem->sw, &dem->sh, dem->cx, dem->cy, &dem->d))) {
        free(z);
        return hfs_fail(err, rc, "%s: out of memory resampling to square cells", path);
    }
    dem->sz = z;
    return HFS_OK;
}

/* GDAL would block on a FIFO and says little of a missing file: both
 * answered here.  GDAL's virtual paths (/vsizip/...) are its own to judge. */
static int check_path(const char *path, hfs_error *err)
{
    struct stat st;
    if (stat(path, &st) != 0)
        return strncmp(path, "/vsi", 4) ? hfs_fail(err, HFS_E_IO, "%s: %s", path,
                                                   strerror(errno))
                                         : HFS_OK;
    if (S_ISREG(st.st_mode) || S_ISDIR(st.st_mode)) /* a folder: GDAL's grid formats */
        return HFS_OK;
    return hfs_fail(err, HFS_E_IO, "%s: not a regular file (a FIFO or a device)", path);
}

int gis_dem_open(const char *path, const hfs_height_load_opts *opts, gis_dem *dem,
                 hfs_error *err)
{
    memset(dem, 0, sizeof *dem);
    int rc = check_path(path, err);
    if (rc || (rc = hfs_gdal_need(path, err)))
        return rc;
    CPLPushErrorHandler(CPLQuietErrorHandler);
    GDALDatasetH ds = GDALOpenEx(path, GDAL_OF_RASTER | GDAL_OF_READONLY, NULL, NULL, NULL);
    const char *why = CPLGetLastErrorMsg();
    rc = ds ? HFS_OK
            : hfs_fail(err, HFS_E_FORMAT, "%s: GDAL cannot open it as a raster%s%s%s", path,
                       *why ? " (" : "", why, *why ? ")" : "");
    dem->ds = ds;
    if (!rc) {
        dem->width = GDALGetRasterXSize(ds), dem->height = GDALGetRasterYSize(ds);
        rc = hfs_gdal_check_dataset(ds, path, opts, dem->gt, err);
    }
    if (!rc)
        rc = georef(ds, path, opts, dem, err);
    CPLPopErrorHandler();
    if (rc)
        gis_dem_free(dem);
    return rc;
}

int gis_dem_load(gis_dem *dem, const char *path, hfs_error *err)
{
    /* the nodata value georef settled (--nodata's, or the band's) */
    const hfs_height_load_opts nd = {.has_nodata = dem->has_nodata, .nodata = (float)dem->nodata};
    float *z = NULL;
    CPLPushErrorHandler(CPLQuietErrorHandler);
    int rc = hfs_gdal_read_heights(dem->ds, path, &nd, &z, err);
    if (!rc)
        rc = to_field(z, path, dem, err);
    GDALClose(dem->ds);
    dem->ds = NULL;
    CPLPopErrorHandler();
    return rc;
}

int gis_dem_read(const char *path, const hfs_height_load_opts *opts, gis_dem *dem,
                 hfs_error *err)
{
    int rc = gis_dem_open(path, opts, dem, err);
    if (!rc && (rc = gis_dem_load(dem, path, err)))
        gis_dem_free(dem);
    return rc;
}

int gis_dem_read_window(const gis_dem *dem, const char *path, int x0, int y0, int w, int h,
                        float *z, unsigned char *hole, long *holes, hfs_error *err)
{
    CPLPushErrorHandler(CPLQuietErrorHandler);
    const CPLErr e = GDALRasterIO(GDALGetRasterBand(dem->ds, 1), GF_Read, x0, y0, w, h, z, w, h,
                                  GDT_Float32, 0, 0);
    CPLPopErrorHandler();
    if (e != CE_None)
        return hfs_fail(err, HFS_E_FORMAT, "%s: GDAL could not read its band 1 at %d,%d "
                        "(%dx%d) (%s)", path, x0, y0, w, h, CPLGetLastErrorMsg());
    const size_t n = (size_t)w * (size_t)h;
    const float nd = (float)dem->nodata;
    *holes = 0;
    for (size_t p = 0; p < n; ++p) {
        if (dem->has_nodata && z[p] == nd)
            z[p] = NAN; /* as hfs_gdal_read_heights marks the whole band's */
        hole[p] = !isfinite(z[p]);
        *holes += hole[p];
    }
    if ((size_t)*holes == n)
        return HFS_OK;
    hfs_error ferr;
    const int rc = hfs_height_fill_holes(z, w, h, 0, 0.0f, NULL, &ferr);
    return rc ? hfs_fail(err, rc, "%s: %s", path, ferr.msg) : HFS_OK;
}

/* From a window of up to 64 x 64 texels around the centre, filled
 * (gis_dem_read_window). */
int gis_dem_scan_centre(gis_dem *dem, const char *path, hfs_error *err)
{
    enum { W = 64 };
    const int cx = dem->width / 2, cy = dem->height / 2;
    const int x0 = cx > W / 2 ? (cx - W / 2) / 16 * 16 : 0, y0 = cy > W / 2 ? (cy - W / 2) / 16 * 16 : 0;
    const int w = dem->width - x0 < W ? dem->width - x0 : W;
    const int h = dem->height - y0 < W ? dem->height - y0 : W;
    float z[W * W];
    unsigned char hole[W * W];
    long holes;
    const int rc = gis_dem_read_window(dem, path, x0, y0, w, h, z, hole, &holes, err);
    if (!rc)
        dem->centre_z = z[(size_t)(cy - y0) * (size_t)w + (size_t)(cx - x0)];
    return rc;
}

int gis_dem_scan(gis_dem *dem, const char *path, double *lo, double *hi, hfs_error *err)
{
    enum { STRIP = 256 };
    float *z = malloc((size_t)dem->width * STRIP * sizeof *z);
    if (!z)
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory for a strip of %d rows", path,
                        STRIP);
    const float nd = (float)dem->nodata;
    float l = INFINITY, u = -INFINITY;
    int rc = HFS_OK;
    for (int y = 0; y < dem->height && !rc; y += STRIP) {
        const int h = dem->height - y < STRIP ? dem->height - y : STRIP;
        CPLPushErrorHandler(CPLQuietErrorHandler);
        const CPLErr e = GDALRasterIO(GDALGetRasterBand(dem->ds, 1), GF_Read, 0, y, dem->width,
                                      h, z, dem->width, h, GDT_Float32, 0, 0);
        CPLPopErrorHandler();
        if (e != CE_None)
            rc = hfs_fail(err, HFS_E_FORMAT, "%s: GDAL could not read its band 1 at row %d (%s)",
                          path, y, CPLGetLastErrorMsg());
        for (size_t p = 0; !rc && p < (size_t)dem->width * (size_t)h; ++p) {
            if (!isfinite(z[p]) || (dem->has_nodata && z[p] == nd))
                continue; /* a hole, as gis_dem_read_window marks them */
            l = fminf(l, z[p]);
            u = fmaxf(u, z[p]);
        }
        gis_dem_drop_cache(dem);
    }
    free(z);
    *lo = l, *hi = u;
    return rc ? rc : gis_dem_scan_centre(dem, path, err);
}

void gis_dem_drop_cache(const gis_dem *dem)
{
    if (dem->ds)
        GDALFlushCache(dem->ds);
}

void gis_dem_free(gis_dem *dem)
{
    if (!dem)
        return;
    if (dem->ds)
        GDALClose(dem->ds);
    free(dem->hole);
    free(dem->wkt);
    free(dem->sz);
    memset(dem, 0, sizeof *dem);
}

/* The grid convergence at (lon, lat) (gis_dem.h): the meridian through
 * it, 0.001 degrees either way, carried by back (WGS84 to the DEM's CRS)
 * into the DEM's pixels, then into the north-up map frame of its cells
 * (x east cx a column, y north cy a row), and the angle of that meridian
 * from the frame's up axis. */
static int convergence_of(const gis_dem *dem, OGRCoordinateTransformationH back, double lon,
                          double lat, double *deg)
{
    const double dlat = fmin(1e-3, 90.0 - fabs(lat));
    double x[2] = {lon, lon}, y[2] = {lat - dlat, lat + dlat}, i[2], j[2], inv[6];
    if (!(dlat > 0.0) || !OCTTransform(back, 2, x, y, NULL) ||
        !GDALInvGeoTransform((double *)dem->gt, inv))
        return 0;
    for (int k = 0; k < 2; ++k) {
        if (!isfinite(x[k]) || !isfinite(y[k]))
            return 0;
        GDALApplyGeoTransform(inv, x[k], y[k], &i[k], &j[k]);
    }
    const double east = dem->ex * (i[1] - i[0]) * dem->cx, north = -dem->ey * (j[1] - j[0]) * dem->cy;
    if (!(hypot(east, north) > 0.0))
        return 0;
    const double d = -atan2(east, north) * (180.0 / 3.14159265358979323846);
    *deg = fabs(d) < 1e-9 ? 0.0 : d; /* no "-0.000000" on a longitude-latitude grid */
    return 1;
}

int gis_dem_lonlat(const gis_dem *dem, const char *path, double *lon, double *lat,
                   double *convergence_deg, hfs_error *err)
{
    if (!dem->wkt || !*dem->wkt)
        return hfs_fail(err, HFS_E_INVALID, "%s: no CRS (the sun's position needs the DEM's "
                        "longitude and latitude; assign one, e.g. gdal_edit.py -a_srs)", path);
    const double *gt = dem->gt, i = 0.5 * dem->width, j = 0.5 * dem->height;
    double x = gt[0] + gt[1] * i + gt[2] * j, y = gt[3] + gt[4] * i + gt[5] * j;
    CPLPushErrorHandler(CPLQuietErrorHandler);
    OGRSpatialReferenceH src = OSRNewSpatialReference(dem->wkt);
    OGRSpatialReferenceH dst = OSRNewSpatialReference(NULL);
    OGRCoordinateTransformationH ct = NULL, back = NULL;
    if (src && dst && OSRSetWellKnownGeogCS(dst, "WGS84") == OGRERR_NONE) {
        OSRSetAxisMappingStrategy(src, OAMS_TRADITIONAL_GIS_ORDER);
        OSRSetAxisMappingStrategy(dst, OAMS_TRADITIONAL_GIS_ORDER);
        ct = OCTNewCoordinateTransformation(src, dst);
        back = convergence_deg ? OCTNewCoordinateTransformation(dst, src) : NULL;
    }
    int ok = ct && OCTTransform(ct, 1, &x, &y, NULL) && isfinite(x) && isfinite(y) &&
             fabs(y) <= 90.0;
    if (ok && convergence_deg)
        ok = back && convergence_of(dem, back, x, y, convergence_deg);
    const char *why = CPLGetLastErrorMsg();
    int rc = ok ? HFS_OK
                : hfs_fail(err, HFS_E_INVALID, "%s: its centre cannot be transformed to WGS84 "
                           "longitude and latitude, or back to find its north%s%s%s", path,
                           *why ? " (" : "", why, *why ? ")" : "");
    if (ct)
        OCTDestroyCoordinateTransformation(ct);
    if (back)
        OCTDestroyCoordinateTransformation(back);
    OSRDestroySpatialReference(src);
    OSRDestroySpatialReference(dst);
    CPLPopErrorHandler();
    if (!rc) {
        *lon = remainder(x, 360.0); /* (-180, 180] up to the sign of 180 */
        *lat = y;
    }
    return rc;
}
