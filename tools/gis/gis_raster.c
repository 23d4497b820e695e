/*
 * gis_raster.c — see gis_raster.h.
 */
#include "gis_raster.h"

#include "gdal_lazy.h"
#include "geotiff_write.h"

#include <cpl_error.h>
#include <cpl_string.h>
#include <cpl_vsi.h>
#include <gdal.h>

#include <math.h>
#include <string.h>

/* DEFLATE at level 1: float angles and irradiances behind the floating-
 * point predictor shrink about as much at level 1 as at GDAL's default 6
 * (the Jacksboro DEM's 16 horizon files 1.75% larger), and libdeflate's
 * share of the horizon command's CPU falls from 18% to 10%
 * (BENCHMARKS.md "GIS rasters").  The predictor helps smooth values (the
 * sky-view factor, irradiation: smaller files) and hurts values in
 * runs: horizon angles, 0 wherever the sky is open, are 13.9% smaller
 * without it (the Jacksboro DEM's 16 files) and cheaper to encode
 * (BENCHMARKS.md "Each point once, and plain horizon files"). */
static const char *const gtiff_options[] = {"TILED=YES", "BLOCKXSIZE=256", "BLOCKYSIZE=256",
                                            "COMPRESS=DEFLATE", "PREDICTOR=3", "ZLEVEL=1",
                                            NULL};
static const char *const cog_options[] = {"COMPRESS=DEFLATE", "PREDICTOR=YES",
                                          "OVERVIEWS=AUTO", NULL};

char **gis_raster_options(int cog, int plain)
{
    char **o = CSLDuplicate((char **)(cog ? cog_options : gtiff_options));
    return plain ? CSLSetNameValue(o, "PREDICTOR", cog ? "NO" : "1") : o;
}

long gis_raster_bad_value(const float *const *v, int n_bands, size_t n, double nodata,
                          int *band)
{
    for (int b = 0; b < n_bands; ++b)
        for (size_t p = 0; p < n; ++p) {
            const float x = v[b][p];
            if (!isfinite(x) && !(isnan(x) && isnan(nodata)) && x != (float)nodata) {
                *band = b + 1;
                return (long)p;
            }
        }
    return -1;
}

void gis_raster_describe(GDALDatasetH ds, const gis_raster *r)
{
    for (int b = 0; b < r->n_bands; ++b) {
        GDALRasterBandH band = GDALGetRasterBand(ds, b + 1);
        GDALSetDescription(band, r->band[b].description);
        GDALSetRasterUnitType(band, r->band[b].unit);
        GDALSetRasterNoDataValue(band, r->nodata);
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
    gis_raster_describe(ds, r);
    for (int b = 0; b < r->n_bands; ++b)
        if (GDALRasterIO(GDALGetRasterBand(ds, b + 1), GF_Write, 0, 0, r->width, r->height,
                         (void *)r->band[b].v, r->width, r->height, GDT_Float32, 0,
                         0) != CE_None) {
            GDALClose(ds);
            return NULL;
        }
    return ds;
}

int gis_raster_encode(const char *path, const gis_raster *r, void **bytes, size_t *len,
                      hfs_error *err)
{
    *bytes = NULL, *len = 0;
    int band = 0;
    const float *v[GIS_RASTER_MAX_BANDS];
    for (int b = 0; b < r->n_bands; ++b)
        v[b] = r->band[b].v;
    const long p = gis_raster_bad_value(v, r->n_bands, (size_t)r->width * (size_t)r->height,
                                        r->nodata, &band);
    if (p >= 0)
        return hfs_fail(err, HFS_E_INVALID, "%s: refusing to write a non-finite value (band "
                        "%d, texel %ld, %ld)", path, band, p % r->width, p / r->width);
    int rc = hfs_gdal_need(path, err);
    if (rc)
        return rc;
    char **opts = gis_raster_options(r->cog, r->plain);
    CPLPushErrorHandler(CPLQuietErrorHandler);
    GDALDatasetH mem = mem_dataset(r);
    rc = hfs_gdal_encode_copy(path, mem, r->cog ? "COG" : "GTiff", opts, bytes, len, err);
    if (mem)
        GDALClose(mem);
    CPLPopErrorHandler();
    CSLDestroy(opts);
    return rc;
}

int gis_raster_write(hfs_outputs *o, const char *path, const gis_raster *r, hfs_error *err)
{
    void *bytes;
    size_t len;
    int rc = gis_raster_encode(path, r, &bytes, &len, err);
    if (!rc)
        rc = hfs_bytes_write_to(o, path, bytes, len, err);
    VSIFree(bytes);
    return rc;
}
