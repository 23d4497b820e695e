/*
 * gis_raster.c — see gis_raster.h.
 */
#include "gis_raster.h"

#include "geotiff_write.h"

#include <cpl_error.h>
#include <cpl_string.h>
#include <gdal.h>

#include <math.h>
#include <string.h>

/* The first value that is neither finite nor the nodata value, or -1. */
static long bad_value(const gis_raster *r, int *band)
{
    const size_t n = (size_t)r->width * (size_t)r->height;
    for (int b = 0; b < r->n_bands; ++b)
        for (size_t p = 0; p < n; ++p) {
            const float v = r->band[b].v[p];
            if (!isfinite(v) && !(isnan(v) && isnan(r->nodata)) && v != (float)r->nodata) {
                *band = b + 1;
                return (long)p;
            }
        }
    return -1;
}

/* The product as a MEM dataset with its georeferencing and metadata. */
static GDALDatasetH mem_dataset(const gis_raster *r)
{
    GDALDriverH mem = GDALGetDriverByName("MEM");
    GDALDatasetH ds = mem ? GDALCreate(mem, "", r->width, r->height, r->n_bands, GDT_Float32,
                                       NULL)
                          : NULL;
    if (!ds)
        return NULL;
    for (int b = 0; b < r->n_bands; ++b) {
        GDALRasterBandH band = GDALGetRasterBand(ds, b + 1);
        GDALSetDescription(band, r->band[b].description);
        GDALSetRasterUnitType(band, r->band[b].unit);
        GDALSetRasterNoDataValue(band, r->nodata);
        if (GDALRasterIO(band, GF_Write, 0, 0, r->width, r->height, (void *)r->band[b].v,
                         r->width, r->height, GDT_Float32, 0, 0) != CE_None) {
            GDALClose(ds);
            return NULL;
        }
    }
    GDALSetGeoTransform(ds, (double *)r->geotransform);
    if (r->wkt && *r->wkt)
        GDALSetProjection(ds, r->wkt);
    for (int k = 0; k < GIS_RASTER_MAX_META && r->meta[k]; ++k) {
        char *key = NULL;
        const char *value = CPLParseNameValue(r->meta[k], &key);
        if (key && value)
            GDALSetMetadataItem(ds, key, value, NULL);
        CPLFree(key);
    }
    return ds;
}

int gis_raster_write(hfs_outputs *o, const char *path, const gis_raster *r, hfs_error *err)
{
    int band = 0;
    const long p = bad_value(r, &band);
    if (p >= 0)
        return hfs_fail(err, HFS_E_INVALID, "%s: refusing to write a non-finite value (band "
                        "%d, texel %ld, %ld)", path, band, p % r->width, p / r->width);
    static const char *const gtiff[] = {"TILED=YES", "BLOCKXSIZE=256", "BLOCKYSIZE=256",
                                        "COMPRESS=DEFLATE", "PREDICTOR=3", NULL};
    static const char *const cog[] = {"COMPRESS=DEFLATE", "PREDICTOR=YES", "OVERVIEWS=AUTO",
                                      NULL};
    char **opts = CSLDuplicate((char **)(r->cog ? cog : gtiff));
    CPLPushErrorHandler(CPLQuietErrorHandler);
    GDALDatasetH mem = mem_dataset(r);
    const int rc = hfs_gdal_write_copy(o, path, mem, r->cog ? "COG" : "GTiff", opts, err);
    if (mem)
        GDALClose(mem);
    CPLPopErrorHandler();
    CSLDestroy(opts);
    return rc;
}
