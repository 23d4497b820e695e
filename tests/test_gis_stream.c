/*
 * test_gis_stream.c — `hfshade svf | horizon | openness | sun | insolation
 * --tile N` (issue 39 item 1, issue 40; tools/gis/gis_stream.h): a DEM
 * larger than a tile, with a search radius, read, computed and written
 * window by window, against the same command computing it whole (--tile
 * 0):
 *   utm      a 150x110 GeoTIFF in UTM (30 m square cells), hills, holes
 *            (-9999) alone, in pairs, a 3x3 block, on the seams of 64-texel
 *            tiles and at the DEM's edges; --tile 64 makes 3 x 2 windows;
 *   cpu      svf (--radius 600: a halo of 22 texels, windows from 16-texel
 *            multiples), openness (its default radius) and two horizon
 *            azimuths on the CPU reference: the same bits as the
 *            whole run (every search reads only its window; the windows'
 *            hole fill lines up with the whole DEM's), the same grid,
 *            CRS, nodata (at exactly the holes), metadata and band
 *            descriptions; the summary line counts the windows and the
 *            holes; --cog streamed is a COG of the same values;
 *   sun      sun (its halo the reach of the hills' shadows from the whole
 *            DEM's relief) and insolation (--radius 600, and with
 *            --beam-only) on the CPU reference: the whole run's bits;
 *            insolation without a radius is computed whole and says why;
 *   gles     svf, openness and sun on GLES within the bounds below of the
 *            whole run (each window's heights normalized for the GPU by
 *            their own range: fp16's level, no seam larger);
 *   whole    a geographic DEM (non-square cells) over the tile is computed
 *            whole (the same bits as --tile 0) and the summary says why;
 *            so is a UTM DEM without a radius;
 *   failures a DEM of nodata only streamed: one line, exit 1, no file and
 *            no temporary left; bad --tile values: one line, exit 2,
 *            nothing written.
 * The GLES runs need a GL context: without one (and HFS_REQUIRE_GL unset)
 * the rest still runs and the test exits 77 at the end.
 *
 * gles, --tile 64 against --tile 0, over the 16481 texels with data
 * (RelWithDebInfo, llvmpipe, Mesa 22.3.6; the same with
 * MESA_GLES_VERSION_OVERRIDE=3.0, GALLIUM_OVERRIDE_CPU_CAPS=sse4.1 and
 * HFS_GL_STRICT_LIMITS=1): svf --radius 600, 8 directions, max 2.98e-7
 * (a few float32 steps of the sum); openness, 4 directions, its default
 * radius: max 3.05e-5 degrees.  The bounds are 1.2x those.  sun (14.4
 * degrees, 557 texels in shadow, 56 partly): max 0.207 W/m^2 in all four
 * settings, at 2 texels of a shadow's edge (V 0.450 against 0.492: the
 * disk is 0.53 degrees wide, and each window's normalization rounds the
 * fp16 horizon there its own way; GLES against the truth on
 * test_gis_sun.c's hills: 0.528 W/m^2 at most), bound 1.2x.  (It was 0,
 * the same bits, before the sun's azimuth took the grid's convergence,
 * 0.0147 degrees here: a coincidence of that one azimuth.)
 */
#define _XOPEN_SOURCE 700 /* realpath */

#include "gdal_fixture.h"
#include "gis_cli_util.h"

#include <cpl_string.h>

#include <dirent.h>
#include <math.h>

#define W 150
#define H 110
#define ND (-9999.0)
#define SVF_GLES_BOUND 3.58e-7
#define OPEN_GLES_BOUND 3.66e-5
#define SUN_GLES_BOUND 0.25

/* Hills, a valley and a ripple, metres; holes (ND) where is_hole says. */
static int is_hole(int i, int j)
{
    static const int holes[][2] = {{5, 5},   {30, 20},  {31, 20}, {63, 64}, {64, 64},
                                   {64, 30}, {100, 63}, {128, 5}, {149, 109}, {0, 60}};
    for (size_t k = 0; k < sizeof holes / sizeof holes[0]; ++k)
        if (holes[k][0] == i && holes[k][1] == j)
            return 1;
    return i >= 70 && i < 73 && j >= 62 && j < 65; /* a 3x3 block across a seam */
}

static void terrain(float *z)
{
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            const double a = hypot(i - 40.0, j - 30.0), b = hypot(i - 110.0, j - 80.0);
            z[j * W + i] = is_hole(i, j) ? (float)ND
                                         : (float)(300.0 + 180.0 * exp(-a * a / 200.0) +
                                                   140.0 * exp(-b * b / 300.0) +
                                                   2.0 * fabs(i - 75.0) + 10.0 * sin(0.3 * j) +
                                                   5.0 * cos(0.7 * i));
        }
}

static void write_dem(const char *name, const float *z, const double gt[6], int epsg)
{
    CHECK(gdal_fixture_write("GTiff", tpath(name), W, H, z, gt, epsg, 1, ND, GDT_Float32) == 0);
}

/* The summary line (err.txt) holds `what`. */
static int said(const char *what)
{
    size_t n = 0;
    char *t = (char *)read_all(tpath("err.txt"), &n);
    const int yes = t && strstr(t, what);
    if (!yes)
        fprintf(stderr, "err.txt does not say '%s': %s", what, t ? t : "(none)\n");
    free(t);
    return yes;
}

/* No file of the folder is a temporary (".tmp-", ".part") or starts with
 * `stem` (NULL: any name). */
static int left_over(const char *stem)
{
    DIR *dir = opendir(tmpdir);
    int n = 0;
    for (struct dirent *e; dir && (e = readdir(dir));)
        n += strstr(e->d_name, ".tmp-") || strstr(e->d_name, ".part") ||
             (stem && !strncmp(e->d_name, stem, strlen(stem)));
    if (dir)
        closedir(dir);
    return n;
}

/* Streamed `sa` and whole `wa`: the same grid, CRS, nodata, metadata and
 * band descriptions; nodata exactly at the holes, finite elsewhere; the
 * largest difference between them returned (-1: they differ in any of
 * those, or do not open). */
static double compare(const char *sa, const char *wa)
{
    raster s, w;
    if (read_raster(sa, &s) || read_raster(wa, &w)) {
        fprintf(stderr, "%s, %s do not open\n", sa, wa);
        return -1.0;
    }
    int same = s.w == W && s.h == H && w.w == W && w.h == H && s.bands == w.bands &&
               !memcmp(s.gt, w.gt, sizeof s.gt) && !strcmp(s.wkt, w.wkt) && s.has_nd &&
               w.has_nd && s.nd == ND && w.nd == ND && *meta(&s, "HFS_PRODUCT");
    char **ms = GDALGetMetadata(s.ds, NULL), **mw = GDALGetMetadata(w.ds, NULL);
    same &= CSLCount(ms) == CSLCount(mw) && CSLCount(ms) > 8;
    for (int k = 0; same && ms && ms[k]; ++k)
        same &= CSLFindString(mw, ms[k]) >= 0;
    for (int band = 1; same && band <= s.bands; ++band)
        same &= !strcmp(GDALGetDescription(GDALGetRasterBand(s.ds, band)),
                        GDALGetDescription(GDALGetRasterBand(w.ds, band)));
    double max = 0.0;
    long wrong = 0;
    for (int band = 0; band < s.bands; ++band)
        for (int p = 0; p < W * H; ++p) {
            const float x = s.v[band * W * H + p], y = w.v[band * W * H + p];
            wrong += is_hole(p % W, p / W) ? x != (float)ND || y != (float)ND
                                           : !isfinite(x) || x == (float)ND;
            max = fmax(max, fabs((double)x - y));
        }
    if (!same || wrong)
        fprintf(stderr, "%s vs %s: grid, CRS, nodata or metadata differ (%d), %ld texels "
                "not nodata at a hole or not finite elsewhere\n", sa, wa, !same, wrong);
    free_raster(&s), free_raster(&w);
    return same && !wrong ? max : -1.0;
}

/* The CPU reference streamed: the whole run's bits. */
static void test_cpu(void)
{
    REQUIRE(run("svf utm.tif -o svf_w.tif --radius 600 --directions 8 --tile 0 --backend cpu") ==
                    0 &&
                said("svf of 150x110, 8 directions, 19 nodata texels"),
            "svf whole failed");
    REQUIRE(run("svf utm.tif -o svf_s.tif --radius 600 --directions 8 --tile 64 --backend cpu") ==
                0,
            "svf --tile 64 failed");
    CHECK(said("svf of 150x110, 6 windows of at most 64 texels a side (halo 22), 8 directions, "
               "19 nodata texels"));
    CHECK(compare("svf_s.tif", "svf_w.tif") == 0.0);

    REQUIRE(run("openness utm.tif -o open_w.tif --directions 4 --tile 0 --backend cpu") == 0,
            "openness");
    REQUIRE(run("openness utm.tif -o open_s.tif --directions 4 --tile 64 --backend cpu --cog") ==
                    0 &&
                said("6 windows"),
            "openness --tile 64 --cog failed");
    CHECK(compare("open_s.tif", "open_w.tif") == 0.0);
    raster r;
    REQUIRE(read_raster("open_s.tif", &r) == 0, "open_s.tif");
    CHECK(!strcmp(r.layout, "COG") && r.bands == 2);
    free_raster(&r);

    REQUIRE(run("horizon utm.tif -o hw --azimuths 30,200 --radius 450 --tile 0 --backend cpu") ==
                    0 &&
                run("horizon utm.tif -o hs --azimuths 30,200 --radius 450 --tile 64 --backend "
                    "cpu") == 0,
            "horizon failed");
    CHECK(compare("hs_030.tif", "hw_030.tif") == 0.0);
    CHECK(compare("hs_200.tif", "hw_200.tif") == 0.0);
    raster hs;
    REQUIRE(read_raster("hs_030.tif", &hs) == 0, "hs_030.tif");
    CHECK(encoded_as(&hs, NULL)); /* streamed horizons plain too (gis_raster.h) */
    free_raster(&hs);
    CHECK(left_over(NULL) == 0);
}

/* sun and insolation streamed on the CPU reference: the whole run's bits
 * (the sun's halo the reach of the hills' shadows from the whole DEM's
 * relief; insolation's its --radius). */
#define SUN_AT "--datetime 2026-06-21T06:50-04:00"
#define INS_PERIOD "--from 2026-06-21T07:00-04:00 --to 2026-06-21T11:00-04:00 --step 60"
/* insolation with --radius 600 (and extra) on the CPU, whole (NAME_w.tif)
 * and in 64-texel windows (NAME_s.tif): 6 windows, the same bits. */
static void insolation_streamed(const char *name, const char *extra)
{
    REQUIRE(run("insolation utm.tif -o %s_w.tif " INS_PERIOD " --radius 600 --tile 0 %s "
                "--backend cpu", name, extra) == 0 &&
                run("insolation utm.tif -o %s_s.tif " INS_PERIOD " --radius 600 --tile 64 %s "
                    "--backend cpu", name, extra) == 0,
            "insolation %s failed", extra);
    CHECK(said("6 windows of at most 64 texels a side (halo 22)"));
    char s[32], w[32];
    snprintf(s, sizeof s, "%s_s.tif", name);
    snprintf(w, sizeof w, "%s_w.tif", name);
    CHECK(compare(s, w) == 0.0);
}

static void test_sun_cpu(void)
{
    REQUIRE(run("sun utm.tif -o sun_w.tif " SUN_AT " --tile 0 --backend cpu") == 0 &&
                run("sun utm.tif -o sun_s.tif " SUN_AT " --tile 64 --backend cpu") == 0,
            "sun failed");
    CHECK(said("sun of 150x110, 6 windows of at most 64 texels a side (halo "));
    CHECK(compare("sun_s.tif", "sun_w.tif") == 0.0);
    insolation_streamed("ins", "");
    /* the beam alone streams too: one band a window, the whole run's bits */
    insolation_streamed("insb", "--beam-only");
    REQUIRE(run("insolation utm.tif -o ins_all.tif " INS_PERIOD " --tile 64 --backend cpu") == 0,
            "insolation without a radius");
    CHECK(said("whole (over --tile 64, but no --radius"));
    CHECK(left_over(NULL) == 0);
}

/* GLES streamed: within fp16's level of the whole run. */
static void test_gles(void)
{
    if (run("svf utm.tif -o gsvf_w.tif --radius 600 --directions 8 --tile 0") != 0) {
        REQUIRE(gles_failed("svf --backend gles"), "svf --backend gles failed");
        return;
    }
    REQUIRE(run("svf utm.tif -o gsvf_s.tif --radius 600 --directions 8 --tile 64") == 0 &&
                said("6 windows"),
            "svf gles --tile 64 failed");
    REQUIRE(run("openness utm.tif -o gopen_w.tif --directions 4 --tile 0") == 0 &&
                run("openness utm.tif -o gopen_s.tif --directions 4 --tile 64") == 0,
            "openness gles failed");
    REQUIRE(run("sun utm.tif -o gsun_w.tif " SUN_AT " --tile 0") == 0 &&
                run("sun utm.tif -o gsun_s.tif " SUN_AT " --tile 64") == 0,
            "sun gles failed");
    const double svf = compare("gsvf_s.tif", "gsvf_w.tif");
    const double open = compare("gopen_s.tif", "gopen_w.tif");
    const double sun = compare("gsun_s.tif", "gsun_w.tif");
    printf("gles --tile 64 vs --tile 0: svf max %.3g (bound %.3g), openness max %.3g deg "
           "(bound %.3g), sun max %.3g W/m^2 (bound %.3g)\n", svf, SVF_GLES_BOUND, open,
           OPEN_GLES_BOUND, sun, SUN_GLES_BOUND);
    CHECK(svf >= 0.0 && svf <= SVF_GLES_BOUND);
    CHECK(open >= 0.0 && open <= OPEN_GLES_BOUND);
    CHECK(sun >= 0.0 && sun <= SUN_GLES_BOUND);
}

/* Over the tile but computed whole: a geographic DEM, and no radius. */
static void test_whole(const float *z)
{
    const double arc = 3.0 / 3600.0;
    const double gt[6] = {-84.0, arc, 0.0, 36.0 + H * arc, 0.0, -arc};
    write_dem("geo.tif", z, gt, 4326);
    REQUIRE(run("svf geo.tif -o geo_w.tif --radius 900 --directions 4 --tile 0 --backend cpu") ==
                    0 &&
                run("svf geo.tif -o geo_s.tif --radius 900 --directions 4 --tile 64 --backend "
                    "cpu") == 0,
            "svf of geo.tif failed");
    CHECK(said("whole (over --tile 64, but cells not square"));
    CHECK(compare("geo_s.tif", "geo_w.tif") == 0.0);
    REQUIRE(run("svf utm.tif -o all.tif --directions 4 --tile 64 --backend cpu") == 0,
            "svf, no radius");
    CHECK(said("whole (over --tile 64, but no --radius"));
}

/* A bad command or input: exit `want`, one line on stderr, no file
 * starting with stem and no temporary left. */
static void bad(int want, const char *stem, const char *args)
{
    const int rc = run("%s", args);
    const int lines = lines_of("err.txt"), left = left_over(stem);
    if (rc != want || lines != 1 || left)
        fprintf(stderr, "hfshade %s: exit %d, %d stderr lines, %d files left\n", args, rc,
                lines, left);
    CHECK(rc == want && lines == 1 && left == 0);
}

static void test_failures(void)
{
    float z[W * H];
    for (int p = 0; p < W * H; ++p)
        z[p] = (float)ND;
    const double gt[6] = {500000.0, 30.0, 0.0, 4000000.0, 0.0, -30.0};
    write_dem("void.tif", z, gt, 32617);
    bad(1, "x", "svf void.tif -o x.tif --radius 600 --tile 64 --backend cpu --directions 8");
    CHECK(said("no valid heights"));
    bad(2, "x", "svf utm.tif -o x.tif --radius 600 --tile -64 --backend cpu");
    bad(2, "x", "svf utm.tif -o x.tif --radius 600 --tile abc --backend cpu");
    bad(2, "x", "horizon utm.tif -o x --azimuths 0 --tile 8 --backend cpu");
    CHECK(said("--tile: '8' is not 0 or a whole number of texels"));
}

int main(int argc, char **argv)
{
    const int begun = gis_cli_begin(argc, argv, "gis_stream");
    if (begun)
        return begun;
    float z[W * H];
    terrain(z);
    const double gt[6] = {500000.0, 30.0, 0.0, 4000000.0, 0.0, -30.0};
    write_dem("utm.tif", z, gt, 32617);
    test_cpu();
    test_sun_cpu();
    test_gles();
    test_whole(z);
    test_failures();
    return gis_cli_end("test_gis_stream");
}
