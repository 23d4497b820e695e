/*
 * gis_cli_util.h — what the GIS commands' end-to-end tests share
 * (test_gis_cli.c, test_gis_sun.c): running `hfshade` in the test's
 * directory, reading its outputs back through GDAL's C API (gdal-bin is
 * not installed), and the rule for GLES runs that fail for want of a GL
 * context.  Include once per test, after test_util.h (tmpdir, tpath,
 * read_all); the test sets `hfshade` to the tool's path.
 */
#ifndef HFS_TEST_GIS_CLI_UTIL_H
#define HFS_TEST_GIS_CLI_UTIL_H

#include "gl_require.h"
#include "test_util.h"

#include <gdal.h>
#include <math.h>

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

static const char *hfshade;
static int gl_missing;

/* The test's start: hfshade = argv[1] made absolute (the runs start in
 * the temporary folder), GDAL's drivers, the temporary folder
 * (make_tmpdir); 0, or the exit status the test returns.  realpath needs
 * _XOPEN_SOURCE 700, defined by the test before any include. */
static int gis_cli_begin(int argc, char **argv, const char *name)
{
    static char exe[4096];
    if (argc < 2) {
        fprintf(stderr, "usage: test_%s HFSHADE\n", name);
        return 2;
    }
    if (!realpath(argv[1], exe)) {
        perror(argv[1]);
        return 1;
    }
    hfshade = exe;
    GDALAllRegister();
    return make_tmpdir(name) ? 1 : 0;
}

/* The test's end: the temporary folder removed (kept, and named, with
 * HFS_TEST_KEEP set), 77 when only the GLES parts could not run, else the
 * checks' verdict. */
static int gis_cli_end(const char *name)
{
    if (!getenv("HFS_TEST_KEEP"))
        rm_tmpdir();
    else
        printf("kept %s\n", tmpdir);
    if (!failures && gl_missing)
        return 77;
    return finish_checks(name);
}

/* Runs `hfshade ARGS` in tmpdir, stdout and stderr to out.txt and err.txt;
 * its exit status (128: it did not exit). */
static int run(const char *fmt, ...)
{
    char args[2048], cmd[4096];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(args, sizeof args, fmt, ap);
    va_end(ap);
    snprintf(cmd, sizeof cmd, "cd %s && %s %s >out.txt 2>err.txt", tmpdir, hfshade, args);
    const int st = system(cmd);
    return WIFEXITED(st) ? WEXITSTATUS(st) : 128;
}

/* The lines of a file (0 when it cannot be read). */
static int lines_of(const char *name)
{
    size_t n = 0;
    unsigned char *b = read_all(tpath(name), &n);
    int lines = 0;
    for (size_t k = 0; b && k < n; ++k)
        lines += b[k] == '\n';
    free(b);
    return lines;
}

/* A GLES run that failed: a skip when no GL context can be made here. */
static int gles_failed(const char *what)
{
    hfs_error why = {""};
    if (hfs_gl_missing_device(&why)) {
        printf("SKIP (gles parts): %s: %s\n", what, why.msg);
        gl_missing = 1;
        return 1;
    }
    return 0;
}

/* An output read back: every band as Float32, the grid, band 1's nodata
 * (has_nd: every band declares the same), the COG layout. */
typedef struct raster {
    int w, h, bands, has_nd;
    double nd, gt[6];
    float *v;
    char wkt[4096], layout[32];
    GDALDatasetH ds;
} raster;

static int read_raster(const char *name, raster *r)
{
    memset(r, 0, sizeof *r);
    if (!(r->ds = GDALOpen(tpath(name), GA_ReadOnly)))
        return -1;
    r->w = GDALGetRasterXSize(r->ds), r->h = GDALGetRasterYSize(r->ds);
    r->bands = GDALGetRasterCount(r->ds);
    GDALGetGeoTransform(r->ds, r->gt);
    snprintf(r->wkt, sizeof r->wkt, "%s", GDALGetProjectionRef(r->ds));
    const char *layout = GDALGetMetadataItem(r->ds, "LAYOUT", "IMAGE_STRUCTURE");
    snprintf(r->layout, sizeof r->layout, "%s", layout ? layout : "");
    r->v = malloc(sizeof(float) * (size_t)r->w * r->h * r->bands);
    for (int b = 0; b < r->bands; ++b) {
        GDALRasterBandH band = GDALGetRasterBand(r->ds, b + 1);
        int has = 0;
        const double nd = GDALGetRasterNoDataValue(band, &has);
        r->has_nd = b ? r->has_nd && has && nd == r->nd : has;
        r->nd = nd;
        if (GDALRasterIO(band, GF_Read, 0, 0, r->w, r->h, r->v + (size_t)b * r->w * r->h, r->w,
                         r->h, GDT_Float32, 0, 0) != CE_None)
            return -1;
    }
    return 0;
}

static void free_raster(raster *r)
{
    if (r->ds)
        GDALClose(r->ds);
    free(r->v);
}

/* Metadata item key of the dataset ("" when absent). */
static const char *meta(const raster *r, const char *key)
{
    const char *v = GDALGetMetadataItem(r->ds, key, NULL);
    return v ? v : "";
}

/* Whether r is encoded as gis_raster.h writes a GTiff: Float32 in 256 x
 * 256 tiles, DEFLATE, with the floating-point predictor (predictor "3")
 * or none (NULL: a plain raster, horizon angles). */
static inline int encoded_as(const raster *r, const char *predictor)
{
    GDALRasterBandH b = GDALGetRasterBand(r->ds, 1);
    int bx = 0, by = 0;
    GDALGetBlockSize(b, &bx, &by);
    const char *c = GDALGetMetadataItem(r->ds, "COMPRESSION", "IMAGE_STRUCTURE");
    const char *p = GDALGetMetadataItem(r->ds, "PREDICTOR", "IMAGE_STRUCTURE");
    const int pred_ok = predictor ? p && !strcmp(p, predictor) : !p || !strcmp(p, "1");
    return GDALGetRasterDataType(b) == GDT_Float32 && bx == 256 && by == 256 && c &&
           !strcmp(c, "DEFLATE") && pred_ok;
}

/* The same as a number (NaN when absent). */
static inline double meta_num(const raster *r, const char *key)
{
    const char *v = GDALGetMetadataItem(r->ds, key, NULL);
    return v ? atof(v) : NAN;
}

#endif /* HFS_TEST_GIS_CLI_UTIL_H */
