/*
 * gis_sun_util.h — what the end-to-end tests of `hfshade sun`
 * (test_gis_sun.c) and `hfshade insolation` (test_gis_insolation.c) share:
 * their 64x48 DEMs (a flat UTM one with two holes, hills on a geographic
 * grid), written with GDAL; the expected sun from the library (hfs_solar:
 * NOAA's position, ESRA's clear sky) at the UTM DEMs' centre, on the
 * central meridian of zone 33N.  Include after gis_cli_util.h and
 * gis_utm_grid.h; the test sets lat0 = utm_centre_lat() first.
 */
#ifndef HFS_TEST_GIS_SUN_UTIL_H
#define HFS_TEST_GIS_SUN_UTIL_H

#include "clear_sky.h"
#include "gdal_fixture.h"
#include "gis_cli_util.h"
#include "gis_utm_grid.h"
#include "solar_position.h"

#include <gdal.h>
#include <ogr_srs_api.h>

#include <math.h>

#define PI 3.14159265358979323846
#define RAD (PI / 180.0)
#define LINKE 3.0

/* ---- files in ------------------------------------------------------------ */


static inline void write_dem(const char *name, const float *z, const double gt[6], int epsg)
{
    CHECK(gdal_fixture_write("GTiff", tpath(name), W, H, z, gt, epsg, 0, 0.0, GDT_Float32) == 0);
}

/* ---- running the tool ---------------------------------------------------- */

/* 1 when file name holds needle. */
static inline int holds(const char *name, const char *needle)
{
    size_t n = 0;
    unsigned char *b = read_all(tpath(name), &n);
    if (b)
        b[n] = '\0';
    const int found = b && strstr((const char *)b, needle) != NULL;
    free(b);
    return found;
}

/* ---- files out ----------------------------------------------------------- */

/* An output of the test DEM's size (W x H), read back; -1 otherwise. */
static inline int read_sized(const char *name, raster *r)
{
    return read_raster(name, r) == 0 && r->w == W && r->h == H ? 0 : -1;
}

/* ---- the expected sun ---------------------------------------------------- */

typedef struct sun {
    double az, el, el_true, alpha, beam, diffuse; /* degrees, W/m^2 */
} sun;

/* The sun at Julian day jd over (lat, lon, z) from the library. */
static inline sun sun_at(double jd, double lat, double lon, double z)
{
    const hfs_solar_site site = {.lat_deg = lat, .lon_deg = lon, .elevation_m = z};
    hfs_solar_angles a;
    sun s = {0};
    CHECK(hfs_solar_position_jd(jd, &site, &a) == 0);
    s.az = a.azimuth_deg, s.el = a.elevation_deg, s.el_true = a.elevation_true_deg;
    s.alpha = 959.63 / 3600.0 / a.distance_au;
    CHECK(hfs_clear_sky_g0(a.elevation_true_deg, z, LINKE, 1367.0 * a.distance_factor, &s.beam,
                           &s.diffuse) == 0);
    return s;
}

static inline double jd_of(const char *local)
{
    hfs_solar_time t;
    char msg[200];
    if (hfs_solar_parse_local(local, NULL, &t, msg, sizeof msg)) {
        fprintf(stderr, "%s\n", msg);
        CHECK(!"a date-time of the test");
        return 0.0;
    }
    return hfs_solar_julian_day(&t);
}

/* The WGS84 longitude and latitude of UTM 33N's (x, y), in place. */
static inline void utm_to_lonlat(double *x, double *y)
{
    OGRSpatialReferenceH a = OSRNewSpatialReference(NULL), b = OSRNewSpatialReference(NULL);
    OSRImportFromEPSG(a, EPSG_UTM33);
    OSRImportFromEPSG(b, 4326);
    OSRSetAxisMappingStrategy(a, OAMS_TRADITIONAL_GIS_ORDER);
    OSRSetAxisMappingStrategy(b, OAMS_TRADITIONAL_GIS_ORDER);
    OGRCoordinateTransformationH ct = OCTNewCoordinateTransformation(a, b);
    CHECK(ct && OCTTransform(ct, 1, x, y, NULL));
    OCTDestroyCoordinateTransformation(ct);
    OSRDestroySpatialReference(a), OSRDestroySpatialReference(b);
}

/* The WGS84 latitude of the UTM grid's centre. */
static inline double utm_centre_lat(void)
{
    double x = 500000.0, y = 5200000.0;
    utm_to_lonlat(&x, &y);
    CHECK(fabs(x - 15.0) < 1e-9); /* the zone's central meridian */
    return y;
}

static double lat0;         /* the UTM DEMs' centre */
#define LON0 15.0
#define Z_FLAT 420.0f

/* The flat UTM DEM, flat.tif: Z_FLAT with NaN holes at two texels. */
#define FLAT_HOLE_A (7 * W + 9)
#define FLAT_HOLE_B (40 * W + 50)

static inline void write_flat(void)
{
    float z[W * H];
    for (int p = 0; p < W * H; ++p)
        z[p] = p == FLAT_HOLE_A || p == FLAT_HOLE_B ? NAN : Z_FLAT;
    write_dem("flat.tif", z, utm_gt, EPSG_UTM33);
}

/* Hills on a geographic grid (3" cells at 47 N: 63 x 93 m, not square,
 * computed on 64x70 cells of 63 m), holes at three texels (-32768); the
 * sun at 5 degrees casts their shadows 30 cells long. */
static inline void hills(float *z)
{
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            const double a = hypot(i - 18.0, j - 14.0), b = hypot(i - 46.0, j - 32.0);
            z[j * W + i] = (float)(300.0 + 180.0 * exp(-a * a / 60.0) + 140.0 * exp(-b * b / 90.0) +
                                   25.0 * fabs(i - 32.0) / 8.0 + 10.0 * sin(0.4 * j));
        }
    z[5 * W + 5] = z[20 * W + 30] = z[47 * W + 63] = -32768.0f;
}

/* hills.tif: the hills as a geographic DEM (EPSG:4326, 3" cells about
 * (15 E, 47 N)) with -32768 as nodata. */
static inline void write_hills(void)
{
    float z[W * H];
    hills(z);
    const double arc = 3.0 / 3600.0;
    const double gt[6] = {15.0 - W / 2 * arc, arc, 0.0, 47.0 + H / 2 * arc, 0.0, -arc};
    CHECK(gdal_fixture_write("GTiff", tpath("hills.tif"), W, H, z, gt, 4326, 1, -32768.0,
                             GDT_Float32) == 0);
}

#endif /* HFS_TEST_GIS_SUN_UTIL_H */
