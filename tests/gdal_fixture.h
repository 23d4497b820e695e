/*
 * gdal_fixture.h — DEMs the GDAL tests write for themselves (gdal-bin is
 * not installed, so fixtures are made with GDAL's C API): band 1 of a
 * w x h raster of type t (the floats z converted), a nodata value when
 * has_nd, the geotransform gt and the CRS of an EPSG code, through a MEM
 * dataset copied by `driver` ("GTiff", "SRTMHGT", ...) to path.
 * test_gdal_dem.c, test_gis_cli.c.  Static, one translation unit each.
 */
#ifndef HFS_TEST_GDAL_FIXTURE_H
#define HFS_TEST_GDAL_FIXTURE_H

#include <cpl_conv.h>
#include <gdal.h>
#include <ogr_srs_api.h>

/* The WKT of an EPSG code (CPLFree it). */
static inline void gdal_fixture_wkt(int epsg, char **wkt)
{
    OGRSpatialReferenceH s = OSRNewSpatialReference(NULL);
    OSRImportFromEPSG(s, epsg);
    OSRExportToWkt(s, wkt);
    OSRDestroySpatialReference(s);
}

/* 0, or -1 when GDAL could not write it. */
static inline int gdal_fixture_write(const char *driver, const char *path, int w, int h,
                                     const float *z, const double gt[6], int epsg, int has_nd,
                                     double nd, GDALDataType t)
{
    GDALDatasetH mem = GDALCreate(GDALGetDriverByName("MEM"), "", w, h, 1, t, NULL);
    GDALRasterBandH b = GDALGetRasterBand(mem, 1);
    int rc = GDALRasterIO(b, GF_Write, 0, 0, w, h, (void *)z, w, h, GDT_Float32, 0, 0) ==
                     CE_None
                 ? 0
                 : -1;
    if (has_nd)
        GDALSetRasterNoDataValue(b, nd);
    GDALSetGeoTransform(mem, (double *)gt);
    char *wkt = NULL;
    gdal_fixture_wkt(epsg, &wkt);
    GDALSetProjection(mem, wkt);
    CPLFree(wkt);
    GDALDatasetH out = GDALCreateCopy(GDALGetDriverByName(driver), path, mem, 0, NULL, NULL,
                                      NULL);
    if (out)
        GDALClose(out);
    GDALClose(mem);
    return out && !rc ? 0 : -1;
}

#endif /* HFS_TEST_GDAL_FIXTURE_H */
