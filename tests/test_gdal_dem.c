/*
 * test_gdal_dem.c — the tools' GDAL height module (tools/gdal/height_gdal.h,
 * issue 20) through hfs_height_load, on files written here with GDAL's own
 * drivers:
 *   utm        a GeoTIFF in UTM (EPSG:32617), 30 m cells, nodata -9999:
 *              heights as written, the holes filled, cellsize 30
 *   geo        a GeoTIFF in EPSG:4326, 3 arc-second cells at 36 N: the
 *              cells' metres on the WGS84 ellipsoid at the centre latitude
 *              (computed here), non-square, so resampled to square cells of
 *              the smaller size and said in the note; its one nodata
 *              texel filled before the resampling (one hole, not four)
 *   south-up   a positive row step: rows flipped, row 0 the north edge
 *   columns    a UTM GeoTIFF of 30 m x 20 m cells: its columns resampled
 *              (the other tests' cells are narrower than tall, so only
 *              rows are), node 0's centre and the last node's kept, the
 *              heights the ramp at each new column's position
 *   hgt, vrt   an SRTM .hgt (N36W084.hgt, 1201 x 1201) and a VRT of the
 *              UTM GeoTIFF read as the originals
 *   refused    a rotated geotransform: one line; a text file: the usual
 *              "unrecognised format" error (GDAL cannot open it either)
 */
#include "gdal_fixture.h"
#include "geotiff_write.h"
#include "height_gdal.h"
#include "test_util.h"

#include <cpl_conv.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846

static char dir[256];

static const char *path_of(const char *name)
{
    static char p[512];
    snprintf(p, sizeof p, "%s/%s", dir, name);
    return p;
}

/* A w x h raster (gdal_fixture.h) in the test's folder. */
static void write_raster(const char *driver, const char *name, int w, int h, const float *z,
                         const double gt[6], int epsg, int has_nd, double nd, GDALDataType t)
{
    CHECK(gdal_fixture_write(driver, path_of(name), w, h, z, gt, epsg, has_nd, nd, t) == 0);
}

static float *ramp(int w, int h)
{
    float *z = malloc(sizeof(float) * (size_t)w * h);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            z[j * w + i] = (float)(100 + 3 * i + 7 * j);
    return z;
}

/* A lit image of hm's grid written as a GeoTIFF (geotiff_write.h) and read
 * back with GDAL: its bands, geotransform and CRS. */
static void test_write(const hfs_heightmap *hm)
{
    const int w = hm->width, h = hm->height;
    hfs_image img = {.width = w, .height = h, .rgb = malloc(sizeof(float) * 3 * w * h)};
    for (int p = 0; p < w * h * 3; ++p)
        img.rgb[p] = 0.25f * (float)p;
    hfs_error err = {""};
    REQUIRE(hfs_gdal_write_geotiff(NULL, path_of("lit.tif"), &img, hm, &err) == HFS_OK, "%s",
            err.msg);
    GDALDatasetH ds = GDALOpen(path_of("lit.tif"), GA_ReadOnly);
    REQUIRE(ds != NULL, "lit.tif does not open");
    double gt[6];
    int same = GDALGetRasterCount(ds) == 3 && GDALGetRasterXSize(ds) == w &&
               GDALGetRasterYSize(ds) == h && GDALGetGeoTransform(ds, gt) == CE_None &&
               !memcmp(gt, hm->geotransform, sizeof gt);
    OGRSpatialReferenceH a = OSRNewSpatialReference(hm->crs_wkt);
    OGRSpatialReferenceH b = OSRNewSpatialReference(GDALGetProjectionRef(ds));
    same = same && a && b && OSRIsSame(a, b);
    OSRDestroySpatialReference(a), OSRDestroySpatialReference(b);
    float *band = malloc(sizeof(float) * w * h);
    for (int c = 0; c < 3 && same; ++c) {
        same = GDALRasterIO(GDALGetRasterBand(ds, c + 1), GF_Read, 0, 0, w, h, band, w, h,
                            GDT_Float32, 0, 0) == CE_None;
        for (int p = 0; p < w * h && same; ++p)
            same = band[p] == img.rgb[3 * p + c];
    }
    CHECK(same);
    printf("write: a %dx%d lit GeoTIFF with the heights' geotransform and CRS\n", w, h);
    GDALClose(ds);
    /* A PNG of the grid with its world file: GDAL places it the same. */
    REQUIRE(hfs_png_write(path_of("lit.png"), &img, NULL, &err) == HFS_OK &&
            hfs_gdal_write_world_file(NULL, path_of("lit.png"), hm, &err) == HFS_OK, "%s",
            err.msg);
    ds = GDALOpen(path_of("lit.png"), GA_ReadOnly);
    REQUIRE(ds != NULL, "lit.png does not open");
    same = GDALGetGeoTransform(ds, gt) == CE_None;
    for (int k = 0; k < 6 && same; ++k)
        same = fabs(gt[k] - hm->geotransform[k]) <= 1e-9 * (1.0 + fabs(gt[k]));
    CHECK(same);
    printf("world file: lit.png placed at (%.3f, %.3f), %.3f x %.3f a pixel\n", gt[0], gt[3],
           gt[1], gt[5]);
    GDALClose(ds);
    free(band), free(img.rgb);
}

static void test_utm(void)
{
    const int w = 20, h = 12;
    float *z = ramp(w, h);
    z[5 * w + 6] = -9999.0f;
    const double gt[6] = {500000.0, 30.0, 0.0, 4000000.0, 0.0, -30.0};
    write_raster("GTiff", "utm.tif", w, h, z, gt, 32617, 1, -9999.0, GDT_Float32);
    hfs_heightmap hm;
    hfs_error err = {""};
    REQUIRE(hfs_height_load(path_of("utm.tif"), NULL, &hm, &err) == HFS_OK, "%s", err.msg);
    int same = hm.width == w && hm.height == h;
    for (int p = 0; p < w * h && same; ++p)
        same = p == 5 * w + 6 || hm.z[p] == z[p];
    CHECK(same && hm.holes == 1 && fabs(hm.cellsize - 30.0) < 1e-12 && !hm.note[0] &&
          hm.format == HFS_HEIGHT_EXTERNAL && isfinite(hm.z[5 * w + 6]));
    CHECK(hm.has_georef && !memcmp(hm.geotransform, gt, sizeof gt) && strstr(hm.crs_wkt, "UTM"));
    test_write(&hm);
    printf("utm: %dx%d, cell %g m, %ld hole filled (%g)\n", hm.width, hm.height, hm.cellsize,
           hm.holes, hm.z[5 * w + 6]);
    hfs_heightmap_free(&hm);
    /* A VRT of it reads the same. */
    GDALDatasetH src = GDALOpen(path_of("utm.tif"), GA_ReadOnly);
    GDALDatasetH vrt = GDALCreateCopy(GDALGetDriverByName("VRT"), path_of("utm.vrt"), src, 0,
                                      NULL, NULL, NULL);
    GDALClose(vrt), GDALClose(src);
    REQUIRE(hfs_height_load(path_of("utm.vrt"), NULL, &hm, &err) == HFS_OK, "%s", err.msg);
    CHECK(hm.width == w && hm.height == h && hm.z[3] == z[3] && hm.holes == 1);
    printf("vrt: %dx%d as the GeoTIFF\n", hm.width, hm.height);
    hfs_heightmap_free(&hm);
    free(z);
}

/* Metres per degree on WGS84 at latitude lat (degrees): east-west, north-south. */
static void wgs84(double lat, double *ew, double *ns)
{
    const double a = 6378137.0, f = 1.0 / 298.257223563, e2 = f * (2.0 - f);
    const double s = sin(lat * PI / 180.0), w = 1.0 - e2 * s * s;
    *ew = PI / 180.0 * a / sqrt(w) * cos(lat * PI / 180.0);
    *ns = PI / 180.0 * a * (1.0 - e2) / (w * sqrt(w));
}

static void test_geo_and_south(void)
{
    const int w = 16, h = 10;
    float *z = ramp(w, h);
    const double d = 3.0 / 3600.0, top = 36.0 + 0.5 * h * d;
    const double gt[6] = {-84.0, d, 0.0, top, 0.0, -d};
    const float kept = z[4 * w + 9];
    z[4 * w + 9] = -9999.0f; /* one hole: filled before the resampling spreads it */
    write_raster("GTiff", "geo.tif", w, h, z, gt, 4326, 1, -9999.0, GDT_Float32);
    z[4 * w + 9] = kept;
    hfs_heightmap hm;
    hfs_error err = {""};
    REQUIRE(hfs_height_load(path_of("geo.tif"), NULL, &hm, &err) == HFS_OK, "%s", err.msg);
    double ew, ns;
    wgs84(36.0, &ew, &ns);
    const double cx = d * ew, cy = d * ns, cell = fmin(cx, cy);
    const int want_h = (int)lround((h - 1) * cy / cell) + 1;
    CHECK(fabs(hm.cellsize / cell - 1.0) < 1e-9 && hm.width == w && hm.height == want_h &&
          strstr(hm.note, "resampled") && hm.holes == 1);
    /* Its georeferencing: rows closer, node 0's centre where it was. */
    const double *g = hm.geotransform;
    CHECK(hm.has_georef && g[1] == d && fabs(g[5] / (-d * (h - 1.0) / (want_h - 1.0)) - 1.0) < 1e-12 &&
          fabs(g[3] + 0.5 * g[5] - (top - 0.5 * d)) < 1e-12 && fabs(g[0] - gt[0]) < 1e-12);
    /* Resampled rows: the ramp (7 a row) at each new row's position. */
    double worst = 0.0;
    for (int j = 0; j < hm.height; ++j)
        worst = fmax(worst, fabs(hm.z[(size_t)j * w] - (100.0 + 7.0 * fmin(j * cell / cy, h - 1))));
    CHECK(worst < 1e-3);
    printf("geo: cells %.3f x %.3f m -> %dx%d of %.3f m; note: %s\n", cx, cy, hm.width,
           hm.height, hm.cellsize, hm.note);
    hfs_heightmap_free(&hm);
    /* South-up: the same rows stored bottom first read as the original. */
    float *flipped = malloc(sizeof(float) * w * h);
    for (int j = 0; j < h; ++j)
        memcpy(flipped + j * w, z + (h - 1 - j) * w, sizeof(float) * w);
    const double gs[6] = {500000.0, 10.0, 0.0, 4000000.0, 0.0, 10.0};
    write_raster("GTiff", "south.tif", w, h, flipped, gs, 32617, 0, 0.0, GDT_Float32);
    REQUIRE(hfs_height_load(path_of("south.tif"), NULL, &hm, &err) == HFS_OK, "%s", err.msg);
    CHECK(!memcmp(hm.z, z, sizeof(float) * w * h));
    CHECK(hm.geotransform[3] == 4000000.0 + 10.0 * h && hm.geotransform[5] == -10.0);
    printf("south-up: flipped to north-up, its geotransform too\n");
    hfs_heightmap_free(&hm);
    free(flipped), free(z);
}

/* Cells wider than tall: the columns are resampled to the rows' 20 m. */
static void test_columns(void)
{
    const int w = 13, h = 6;
    float *z = ramp(w, h);
    const double gt[6] = {500000.0, 30.0, 0.0, 4000000.0, 0.0, -20.0};
    write_raster("GTiff", "cols.tif", w, h, z, gt, 32617, 0, 0.0, GDT_Float32);
    hfs_heightmap hm;
    hfs_error err = {""};
    REQUIRE(hfs_height_load(path_of("cols.tif"), NULL, &hm, &err) == HFS_OK, "%s", err.msg);
    const int want_w = (int)lround((w - 1) * 30.0 / 20.0) + 1; /* 19 */
    CHECK(hm.width == want_w && hm.height == h && fabs(hm.cellsize - 20.0) < 1e-12 &&
          strstr(hm.note, "resampled"));
    /* Its georeferencing: columns closer, rows as they were, the first and
     * the last node's centres where they were (GDAL places a cell's
     * centre half a cell in from its corner). */
    const double *g = hm.geotransform;
    CHECK(hm.has_georef && fabs(g[1] - 30.0 * (w - 1.0) / (want_w - 1.0)) < 1e-9 &&
          g[3] == gt[3] && g[5] == gt[5] && g[2] == 0.0 && g[4] == 0.0);
    CHECK(fabs(g[0] + 0.5 * g[1] - (gt[0] + 15.0)) < 1e-6 &&
          fabs(g[0] + (want_w - 0.5) * g[1] - (gt[0] + (w - 0.5) * 30.0)) < 1e-6);
    /* Resampled columns: the ramp (3 a column) at each new column's place. */
    double worst = 0.0;
    for (int j = 0; j < hm.height && hm.width == want_w; ++j)
        for (int i = 0; i < hm.width; ++i)
            worst = fmax(worst, fabs(hm.z[(size_t)j * hm.width + i] -
                                     (100.0 + 7.0 * j + 3.0 * fmin(i * 20.0 / 30.0, w - 1))));
    CHECK(worst < 1e-4);
    printf("columns: cells 30 x 20 m -> %dx%d of %.1f m, node 0 at x %.3f; note: %s\n",
           hm.width, hm.height, hm.cellsize, g[0] + 0.5 * g[1], hm.note);
    hfs_heightmap_free(&hm);
    free(z);
}

static void test_hgt_and_refused(void)
{
    const int n = 1201;
    float *z = ramp(n, n);
    const double d = 3.0 / 3600.0;
    const double gt[6] = {-84.0 - 0.5 * d, d, 0.0, 37.0 + 0.5 * d, 0.0, -d};
    write_raster("SRTMHGT", "N36W084.hgt", n, n, z, gt, 4326, 0, 0.0, GDT_Int16);
    hfs_heightmap hm;
    hfs_error err = {""};
    REQUIRE(hfs_height_load(path_of("N36W084.hgt"), NULL, &hm, &err) == HFS_OK, "%s",
            err.msg);
    CHECK(hm.width == n && hm.height > n && hm.z[0] == z[0] && strstr(hm.note, "resampled"));
    printf("hgt: %dx%d of %.2f m\n", hm.width, hm.height, hm.cellsize);
    hfs_heightmap_free(&hm);
    free(z);
    float small[16] = {0};
    const double rot[6] = {0.0, 1.0, 0.2, 0.0, 0.1, -1.0};
    write_raster("GTiff", "rot.tif", 4, 4, small, rot, 32617, 0, 0.0, GDT_Float32);
    CHECK(hfs_height_load(path_of("rot.tif"), NULL, &hm, &err) == HFS_E_INVALID &&
          strstr(err.msg, "not north-up") && !strchr(err.msg, '\n'));
    printf("refused: %s\n", err.msg);
    FILE *f = fopen(path_of("notes.txt"), "w");
    fputs("just some words\n", f);
    fclose(f);
    CHECK(hfs_height_load(path_of("notes.txt"), NULL, &hm, &err) == HFS_E_FORMAT &&
          strstr(err.msg, "unrecognised height field format"));
    printf("refused: %s\n", err.msg);
}

int main(void)
{
    snprintf(dir, sizeof dir, "/tmp/hfs-gdal-XXXXXX");
    if (!mkdtemp(dir))
        return 1;
    hfs_gdal_register();
    test_utm();
    test_geo_and_south();
    test_columns();
    test_hgt_and_refused();
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", dir);
    return finish_checks("test_gdal_dem");
}
