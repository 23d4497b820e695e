/*
 * test_gdal_jacksboro.c — issue 20's must-show: the demo's Jacksboro DEM
 * (data/jacksboro.png, USGS 3 arc-second cells, read with dx 83: the
 * geometric mean of its cells' sides) written here as GeoTIFFs in a
 * geographic CRS (EPSG:4326) at its place (about 36.25 N, 84.25 W) and
 * read back through the tools' GDAL module, rendered on the CPU reference
 * (a sky and the demo's sun, zscale 2) against the PNG's render:
 *   square   cells of 83 m on both sides at the centre latitude (degrees
 *            chosen for it): no resampling, the picture equals the PNG's
 *            bit for bit (dx from the geotransform);
 *   3 arc-s  the true cells, 74.9 m east-west by 92.5 m north-south,
 *            resampled to square cells of 74.9 m (424 rows; the log says
 *            so): sampled back at the PNG's texels, the picture differs by
 *            what the PNG's one square dx gets wrong (slopes 10% too gentle
 *            east-west, 11% too steep north-south), stated and bounded
 *            below.
 *   usage: test_gdal_jacksboro DATA_DIR
 */
#include "height_gdal.h"
#include "hfshade.h"
#include "test_util.h"

#include <cpl_conv.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

static char dir[256];

/* WGS84 metres per degree at latitude lat: east-west, north-south. */
static void wgs84(double lat, double *ew, double *ns)
{
    const double a = 6378137.0, f = 1.0 / 298.257223563, e2 = f * (2.0 - f);
    const double s = sin(lat * PI / 180.0), w = 1.0 - e2 * s * s;
    *ew = PI / 180.0 * a / sqrt(w) * cos(lat * PI / 180.0);
    *ns = PI / 180.0 * a * (1.0 - e2) / (w * sqrt(w));
}

static void write_geo(const char *path, const hfs_heightmap *hm, double dlon, double dlat)
{
    const double lat_c = 36.25;
    const double gt[6] = {-84.25 - 0.5 * hm->width * dlon, dlon, 0.0,
                          lat_c + 0.5 * hm->height * dlat, 0.0, -dlat};
    GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), path, hm->width, hm->height, 1,
                                 GDT_Float32, NULL);
    CHECK(GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, hm->width, hm->height, hm->z,
                       hm->width, hm->height, GDT_Float32, 0, 0) == CE_None);
    GDALSetGeoTransform(ds, (double *)gt);
    OGRSpatialReferenceH s = OSRNewSpatialReference(NULL);
    OSRImportFromEPSG(s, 4326);
    char *wkt = NULL;
    OSRExportToWkt(s, &wkt);
    GDALSetProjection(ds, wkt);
    CPLFree(wkt);
    OSRDestroySpatialReference(s);
    GDALClose(ds);
}

/* The field lit by a sky and the demo's sun on the CPU reference. */
static void render(const hfs_heightmap *hm, double dx, hfs_image *out)
{
    const hfs_field f = {.width = hm->width, .height = hm->height, .z = hm->z, .dx = dx,
                         .zscale = 2.0};
    hfs_lighting l;
    hfs_lighting_defaults(&l);
    l.has_env = 1;
    for (int c = 0; c < 3; ++c)
        l.env_sh[c][0] = sqrt(4.0 * PI), l.env_sh[c][2] = 1.0;
    l.n_key = 1;
    l.key[0] = (hfs_key_light){.phi = 336.0 * PI / 180.0, .elev = 15.0 * PI / 180.0,
                               .alpha = 2.0 * PI / 180.0, .radiance = {1500, 1500, 1500}};
    l.albedo = 0.35;
    hfs_quality q;
    hfs_quality_defaults(&q);
    hfs_renderer_desc d = {.backend = HFS_BACKEND_CPU};
    hfs_renderer *r = NULL;
    hfs_error err = {""};
    REQUIRE(hfs_renderer_create(&d, &r, &err) == HFS_OK &&
            hfs_image_alloc(out, f.width, f.height, &err) == HFS_OK &&
            hfs_renderer_render(r, &f, &l, &q, out, NULL, NULL, &err) == HFS_OK, "%s", err.msg);
    hfs_renderer_destroy(r);
}

/* Mean |a(i, j * sy) - b(i, j)| over b's max, a read bilinearly along y. */
static double mean_diff(const hfs_image *a, const hfs_image *b, double sy)
{
    double s = 0.0, m = 0.0;
    for (int j = 0; j < b->height; ++j) {
        const double y = fmin(j * sy, a->height - 1.0);
        const int j0 = y >= a->height - 1 ? a->height - 2 : (int)y;
        const double t = y - j0;
        for (int i = 0; i < b->width * 3; ++i) {
            const double v = (1.0 - t) * a->rgb[(size_t)j0 * a->width * 3 + i] +
                             t * a->rgb[(size_t)(j0 + 1) * a->width * 3 + i];
            s += fabs(v - b->rgb[(size_t)j * b->width * 3 + i]);
            m = fmax(m, b->rgb[(size_t)j * b->width * 3 + i]);
        }
    }
    return s / ((double)b->width * b->height * 3) / m;
}

static void run(const char *data)
{
    char png[512], sq[300], geo[300];
    snprintf(png, sizeof png, "%s/jacksboro.png", data);
    snprintf(sq, sizeof sq, "%s/square.tif", dir);
    snprintf(geo, sizeof geo, "%s/geo.tif", dir);
    hfs_heightmap p, a, b;
    hfs_error err = {""};
    REQUIRE(hfs_height_load(png, NULL, &p, &err) == HFS_OK, "%s", err.msg);
    double ew, ns;
    wgs84(36.25, &ew, &ns);
    write_geo(sq, &p, 83.0 / ew, 83.0 / ns);
    write_geo(geo, &p, 3.0 / 3600.0, 3.0 / 3600.0);
    REQUIRE(hfs_height_load(sq, NULL, &a, &err) == HFS_OK, "%s", err.msg);
    REQUIRE(hfs_height_load(geo, NULL, &b, &err) == HFS_OK, "%s", err.msg);
    hfs_image ip, ia, ib;
    render(&p, 83.0, &ip);
    render(&a, a.cellsize, &ia);
    render(&b, b.cellsize, &ib);
    const double d_sq = mean_diff(&ia, &ip, 1.0);
    const double d_geo = mean_diff(&ib, &ip, (b.height - 1.0) / (p.height - 1.0));
    /* Square: measured 0 (bit for bit).  3 arc-s: measured 2.05e-2 of the
     * max; bound 1.5x. */
    CHECK(a.width == p.width && a.height == p.height && fabs(a.cellsize - 83.0) < 1e-6 &&
          !a.note[0] && d_sq <= 1e-6);
    CHECK(b.width == p.width && b.height > p.height && strstr(b.note, "resampled") &&
          d_geo <= 3.1e-2);
    printf("square: %dx%d of %.9f m, mean difference from the PNG's render %.2e\n", a.width,
           a.height, a.cellsize, d_sq);
    printf("3 arc-s: %dx%d of %.3f m (%s), mean difference %.2e of the max\n", b.width,
           b.height, b.cellsize, b.note, d_geo);
    hfs_image_free(&ip), hfs_image_free(&ia), hfs_image_free(&ib);
    hfs_heightmap_free(&p), hfs_heightmap_free(&a), hfs_heightmap_free(&b);
}

int main(int argc, char **argv)
{
    if (argc < 2)
        return 2;
    snprintf(dir, sizeof dir, "/tmp/hfs-jacksboro-XXXXXX");
    if (!mkdtemp(dir))
        return 1;
    hfs_gdal_register();
    run(argv[1]);
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", dir);
    return finish_checks("test_gdal_jacksboro");
}
