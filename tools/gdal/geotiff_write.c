/*
 * geotiff_write.c — see geotiff_write.h.
 */
#include "geotiff_write.h"

#include "gdal_lazy.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_string.h>
#include <cpl_vsi.h>
#include <gdal.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The image as a MEM dataset with hm's georeferencing; NULL on failure. */
static GDALDatasetH mem_dataset(const hfs_image *img, const hfs_heightmap *hm)
{
    GDALDriverH mem = GDALGetDriverByName("MEM");
    GDALDatasetH ds = mem ? GDALCreate(mem, "", img->width, img->height, 3, GDT_Float32, NULL)
                          : NULL;
    if (!ds)
        return NULL;
    static const GDALColorInterp ci[3] = {GCI_RedBand, GCI_GreenBand, GCI_BlueBand};
    for (int c = 0; c < 3; ++c) { /* band c: every third float, from channel c */
        GDALRasterBandH b = GDALGetRasterBand(ds, c + 1);
        GDALSetRasterColorInterpretation(b, ci[c]);
        if (GDALRasterIO(b, GF_Write, 0, 0, img->width, img->height, img->rgb + c, img->width,
                         img->height, GDT_Float32, 3 * (GSpacing)sizeof(float),
                         3 * (GSpacing)sizeof(float) * img->width) != CE_None) {
            GDALClose(ds);
            return NULL;
        }
    }
    if (hm && hm->has_georef) {
        GDALSetGeoTransform(ds, (double *)hm->geotransform);
        if (hm->crs_wkt[0])
            GDALSetProjection(ds, hm->crs_wkt);
    }
    return ds;
}

int hfs_gdal_encode_copy(const char *path, GDALDatasetH src, const char *driver, char **opts,
                         void **bytes, size_t *len, hfs_error *err)
{
    *bytes = NULL, *len = 0;
    char name[64]; /* a memory file of this call's own */
    snprintf(name, sizeof name, "/vsimem/hfshade-%p.tif", (void *)src);
    CPLPushErrorHandler(CPLQuietErrorHandler);
    GDALDriverH drv = GDALGetDriverByName(driver);
    GDALDatasetH out = src && drv ? GDALCreateCopy(drv, name, src, FALSE, opts, NULL, NULL) : NULL;
    int ok = out != NULL;
    if (out) { /* GDALClose writes the rest (void before GDAL 3.8): errors are logged */
        CPLErrorReset();
        GDALClose(out);
        ok &= CPLGetLastErrorType() != CE_Failure && CPLGetLastErrorType() != CE_Fatal;
    }
    vsi_l_offset n = 0;
    GByte *b = VSIGetMemFileBuffer(name, &n, TRUE); /* ours now */
    CPLPopErrorHandler();
    if (ok && b && n > 0) {
        *bytes = b, *len = (size_t)n;
        return HFS_OK;
    }
    VSIFree(b);
    return hfs_fail(err, HFS_E_IO, "%s: GDAL could not encode the %s (%s)", path,
                    !strcmp(driver, "GTiff") ? "GeoTIFF" : driver, CPLGetLastErrorMsg());
}

int hfs_gdal_write_copy(hfs_outputs *o, const char *path, GDALDatasetH src, const char *driver,
                        char **opts, hfs_error *err)
{
    void *bytes;
    size_t len;
    int rc = hfs_gdal_encode_copy(path, src, driver, opts, &bytes, &len, err);
    if (!rc)
        rc = hfs_bytes_write_to(o, path, bytes, len, err);
    VSIFree(bytes);
    return rc;
}

int hfs_gdal_write_geotiff(hfs_outputs *o, const char *path, const hfs_image *img,
                           const hfs_heightmap *hm, hfs_error *err)
{
    if (!img || !img->rgb || img->width < 1 || img->height < 1)
        return hfs_fail(err, HFS_E_INVALID, "%s: nothing to write (empty image)", path);
    for (size_t k = 0, n = (size_t)img->width * (size_t)img->height * 3; k < n; ++k)
        if (!isfinite(img->rgb[k]))
            return hfs_fail(err, HFS_E_INVALID, "%s: refusing to write a non-finite value",
                            path);
    int rc = hfs_gdal_need(path, err);
    if (rc)
        return rc;
    CPLPushErrorHandler(CPLQuietErrorHandler);
    GDALDatasetH mem = mem_dataset(img, hm);
    char **opts = CSLSetNameValue(NULL, "COMPRESS", "DEFLATE");
    rc = hfs_gdal_write_copy(o, path, mem, "GTiff", opts, err);
    CSLDestroy(opts);
    if (mem)
        GDALClose(mem);
    CPLPopErrorHandler();
    return rc;
}

int hfs_gdal_write_world_file(hfs_outputs *o, const char *path, const hfs_heightmap *hm,
                              hfs_error *err)
{
    if (!hm || !hm->has_georef)
        return HFS_OK;
    char wpath[4096];
    if (snprintf(wpath, sizeof wpath, "%sw", path) >= (int)sizeof wpath)
        return hfs_fail(err, HFS_E_INVALID, "%s: path too long for its world file", path);
    const double *g = hm->geotransform;
    char text[256];
    const int n = snprintf(text, sizeof text, "%.17g\n%.17g\n%.17g\n%.17g\n%.17g\n%.17g\n",
                           g[1], g[4], g[2], g[5], g[0] + 0.5 * g[1] + 0.5 * g[2],
                           g[3] + 0.5 * g[4] + 0.5 * g[5]);
    int rc = o ? hfs_outputs_add(o, wpath, err) : HFS_OK;
    return rc ? rc : hfs_bytes_write_to(o, wpath, text, (size_t)n, err);
}
