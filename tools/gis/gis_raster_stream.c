/*
 * gis_raster_stream.c — see gis_raster_stream.h.
 */
#include "gis_raster_stream.h"

#include "gdal_lazy.h"

#include <cpl_error.h>
#include <cpl_string.h>
#include <gdal.h>

#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

struct gis_raster_stream {
    GDALDatasetH ds;
    const char *path, *file;
    char *part;      /* --cog: the GTiff, FILE.part; NULL: the GTiff is FILE */
    int n_bands;
    double nodata;
    int plain; /* no predictor (gis_raster.h) */
};

/* The last GDAL error after a call that reports none itself (GDALClose
 * is void before GDAL 3.8): 0, or an error naming the output. */
static int gdal_failed(const gis_raster_stream *s, const char *what, hfs_error *err)
{
    const CPLErr e = CPLGetLastErrorType();
    if (e != CE_Failure && e != CE_Fatal)
        return HFS_OK;
    return hfs_fail(err, HFS_E_IO, "%s: GDAL could not %s (%s)", s->path, what,
                    CPLGetLastErrorMsg());
}

/* FILE.part, made ours with O_EXCL before GDAL writes over it. */
static int make_part(gis_raster_stream *s, hfs_error *err)
{
    const size_t n = strlen(s->file) + sizeof ".part";
    if (!(s->part = malloc(n)))
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", s->path);
    snprintf(s->part, n, "%s.part", s->file);
    const int fd = open(s->part, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) {
        free(s->part);
        s->part = NULL;
        return hfs_fail(err, HFS_E_IO, "%s: cannot create a temporary file next to it",
                        s->path);
    }
    close(fd);
    return HFS_OK;
}

int gis_raster_stream_open(gis_raster_stream **out, const char *path, const char *file,
                           const gis_raster *r, hfs_error *err)
{
    *out = NULL;
    int rc = hfs_gdal_need(path, err);
    if (rc)
        return rc;
    gis_raster_stream *s = calloc(1, sizeof *s);
    if (!s)
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", path);
    s->path = path, s->file = file, s->n_bands = r->n_bands, s->nodata = r->nodata;
    s->plain = r->plain;
    rc = r->cog ? make_part(s, err) : HFS_OK;
    if (rc) {
        free(s);
        return rc;
    }
    char **opts = gis_raster_options(0, r->plain);
    opts = CSLSetNameValue(opts, "BIGTIFF", "IF_SAFER");
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
    GDALDriverH gtiff = GDALGetDriverByName("GTiff");
    s->ds = gtiff ? GDALCreate(gtiff, s->part ? s->part : file, r->width, r->height,
                               r->n_bands, GDT_Float32, opts)
                  : NULL;
    if (s->ds)
        gis_raster_describe(s->ds, r);
    rc = s->ds ? gdal_failed(s, "describe the GeoTIFF", err)
               : hfs_fail(err, HFS_E_IO, "%s: GDAL could not create the GeoTIFF (%s)", path,
                          CPLGetLastErrorMsg());
    CPLPopErrorHandler();
    CSLDestroy(opts);
    if (rc)
        gis_raster_stream_abort(s);
    else
        *out = s;
    return rc;
}

int gis_raster_stream_write(gis_raster_stream *s, int x0, int y0, int w, int h,
                            const float *v, hfs_error *err)
{
    const size_t n = (size_t)w * (size_t)h;
    const float *plane[GIS_RASTER_MAX_BANDS];
    for (int b = 0; b < s->n_bands; ++b)
        plane[b] = v + (size_t)b * n;
    int band = 0;
    const long p = gis_raster_bad_value(plane, s->n_bands, n, s->nodata, &band);
    if (p >= 0)
        return hfs_fail(err, HFS_E_INVALID, "%s: refusing to write a non-finite value (band "
                        "%d, texel %ld, %ld)", s->path, band, x0 + p % w, y0 + p / w);
    CPLPushErrorHandler(CPLQuietErrorHandler);
    const CPLErr e = GDALDatasetRasterIO(s->ds, GF_Write, x0, y0, w, h, (void *)v, w, h,
                                         GDT_Float32, s->n_bands, NULL, 0, 0, 0);
    CPLPopErrorHandler();
    if (e != CE_None)
        return hfs_fail(err, HFS_E_IO, "%s: GDAL could not write the window at %d,%d (%s)",
                        s->path, x0, y0, CPLGetLastErrorMsg());
    return HFS_OK;
}

int gis_raster_stream_flush(gis_raster_stream *s, hfs_error *err)
{
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
    GDALFlushCache(s->ds); /* void before GDAL 3.7: its errors are the last error */
    const int rc = gdal_failed(s, "write the GeoTIFF", err);
    CPLPopErrorHandler();
    return rc;
}

/* --cog: FILE made from FILE.part by the COG driver. */
static int make_cog(gis_raster_stream *s, hfs_error *err)
{
    GDALDatasetH src = GDALOpenEx(s->part, GDAL_OF_RASTER | GDAL_OF_READONLY, NULL, NULL, NULL);
    GDALDriverH cog = GDALGetDriverByName("COG");
    char **opts = gis_raster_options(1, s->plain);
    CPLErrorReset();
    GDALDatasetH out = src && cog ? GDALCreateCopy(cog, s->file, src, FALSE, opts, NULL, NULL)
                                  : NULL;
    int rc = out ? HFS_OK
                 : hfs_fail(err, HFS_E_IO, "%s: GDAL could not make the COG (%s)", s->path,
                            CPLGetLastErrorMsg());
    if (out) {
        CPLErrorReset();
        GDALClose(out);
        rc = gdal_failed(s, "write the COG", err);
    }
    if (src)
        GDALClose(src);
    CSLDestroy(opts);
    return rc;
}

int gis_raster_stream_finish(gis_raster_stream *s, hfs_error *err)
{
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
    GDALClose(s->ds);
    s->ds = NULL;
    int rc = gdal_failed(s, "write the GeoTIFF", err);
    if (!rc && s->part)
        rc = make_cog(s, err);
    CPLPopErrorHandler();
    gis_raster_stream_abort(s);
    return rc;
}

void gis_raster_stream_abort(gis_raster_stream *s)
{
    if (!s)
        return;
    if (s->ds) {
        CPLPushErrorHandler(CPLQuietErrorHandler);
        GDALClose(s->ds);
        CPLPopErrorHandler();
    }
    if (s->part) {
        unlink(s->part);
        free(s->part);
    }
    free(s);
}
