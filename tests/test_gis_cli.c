/*
 * test_gis_cli.c — `hfshade svf | horizon | openness` end to end (issue
 * 39; tools/cli_gis.c, tools/gis/), on DEMs written here with GDAL and
 * outputs read back with GDAL's C API (gdal-bin is not installed):
 *   geo      a 64x48 GeoTIFF in EPSG:4326, 3 arc-second cells at 36 N
 *            (about 75 x 92 m: not square, so computed on 64x59 square
 *            cells and sampled back), hills and a valley, 5 nodata texels
 *            (-32768): every product comes back 64x48 with the input's
 *            geotransform, CRS, nodata (the input's -32768, outside every
 *            product's range), nodata exactly at the holes, the rest
 *            finite and in the product's range, the metadata naming it;
 *   gles ~ truth  the sky-view factor of the GLES renderer (the product,
 *            fp16) against the ground truth's within the bound below;
 *   flat     a flat DEM (UTM, square cells, holes, no declared nodata but
 *            NaN holes): sky-view factor exactly 1, openness 90 / 90, the
 *            nodata value -9999;
 *   conventions  horizon --azimuths 90 --convention compass is the same
 *            raster as --azimuths 0 (ccw-east): both look east; names
 *            PREFIX_000.tif, PREFIX_090.tif, PREFIX_022_5.tif;
 *   orientation  the same ground written south-up or west-running: the
 *            same horizons, on the file's own grid (rows or columns
 *            reversed), looking the same way on the ground;
 *   sweep    --method sweep: the sky-view factor and a horizon on the
 *            input's grid, against the truth's within the bounds below,
 *            metadata HFS_HORIZON_METHOD; refused with a radius, with the
 *            truth, for openness without --radius 0;
 *   files    horizon's 16 files (encoded a few at a time on worker
 *            threads): each its own azimuth's, as a run of that azimuth
 *            alone; a late file that cannot be written leaves none;
 *   --cog    a Cloud Optimized GeoTIFF (GDAL says LAYOUT=COG);
 *   --help   exit 0, "Usage:" on stdout; bad inputs: non-zero, one line on
 *            stderr, no output file.
 * The GLES runs need a GL context: without one (and HFS_REQUIRE_GL unset)
 * the rest still runs and the test exits 77 at the end.
 *
 * gles vs truth, sky-view factor, 16 directions, whole DEM, over the 3067
 * texels with data (RelWithDebInfo, llvmpipe, Mesa 22.3.6): mean 8.41e-6,
 * max 1.76e-4 (the CPU reference: 7.83e-6, 1.75e-4, so nearly all of it is
 * the gap search's, hfshade.h hfs_renderer_horizons, not fp16's); the
 * bounds are 1.2x those.
 */
#define _XOPEN_SOURCE 700 /* realpath */

#include "gdal_fixture.h"
#include "gis_cli_util.h"

#include <gdal.h>
#include <ogr_srs_api.h>

#include <math.h>
#include <unistd.h>

#define W 64
#define H 48
#define ND (-32768.0)
/* GLES against the truth on the geographic DEM: measured 5.76e-7 mean,
 * 1.07e-6 max (the exact supremum on both sides: fp16 hi + lo heights;
 * with the grid lines' crossings alone it was 8.4e-6 and 1.8e-4, docs/GIS.md). */
#define SVF_MEAN_BOUND 6.9e-7
#define SVF_MAX_BOUND 1.3e-6
/* --method sweep against the truth: measured svf mean 1.69e-4, max
 * 1.44e-3, the horizon at 30 degrees mean 0.0325, max 0.678 degrees; the
 * bounds 1.2x those */
#define SWEEP_SVF_MEAN 2.03e-4
#define SWEEP_SVF_MAX 1.73e-3
#define SWEEP_HOR_MEAN 0.039
#define SWEEP_HOR_MAX 0.814

/* ---- files in ------------------------------------------------------------ */

static void write_dem(const char *name, const float *z, const double gt[6], int epsg,
                      int has_nd)
{
    CHECK(gdal_fixture_write("GTiff", tpath(name), W, H, z, gt, epsg, has_nd, ND, GDT_Float32) ==
          0);
}

/* Hills and a north-south valley, metres; holes at five texels. */
static void terrain(float *z, float hole)
{
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            const double a = hypot(i - 18.0, j - 14.0), b = hypot(i - 46.0, j - 32.0);
            z[j * W + i] = (float)(300.0 + 180.0 * exp(-a * a / 60.0) + 140.0 * exp(-b * b / 90.0) +
                                   25.0 * fabs(i - 32.0) / 8.0 + 10.0 * sin(0.4 * j));
        }
    static const int holes[][2] = {{5, 5}, {30, 20}, {31, 20}, {63, 47}, {0, 40}};
    for (int k = 0; k < 5; ++k)
        z[holes[k][1] * W + holes[k][0]] = hole;
}

/* ---- running the tool ---------------------------------------------------- */

/* ---- files out ----------------------------------------------------------- */

/* name: the input's grid, CRS and nodata nd at exactly the holes of z
 * (NaN or -32768), every other value finite and in [lo, hi]. */
static void check_grid(const char *name, const raster *in, const float *z, double nd,
                       double lo, double hi)
{
    raster r;
    REQUIRE(read_raster(name, &r) == 0, "%s does not open", name);
    OGRSpatialReferenceH a = OSRNewSpatialReference(in->wkt), b = OSRNewSpatialReference(r.wkt);
    CHECK(r.w == W && r.h == H && !memcmp(r.gt, in->gt, sizeof r.gt));
    CHECK(a && b && OSRIsSame(a, b));
    OSRDestroySpatialReference(a), OSRDestroySpatialReference(b);
    CHECK(r.has_nd && (r.nd == nd || (isnan(nd) && isnan(r.nd))));
    long wrong = 0;
    for (int band = 0; band < r.bands; ++band)
        for (int p = 0; p < W * H; ++p) {
            const float v = r.v[band * W * H + p];
            const int hole = isnan(z[p]) || z[p] == (float)ND;
            wrong += hole ? v != (float)nd : !(isfinite(v) && v >= lo && v <= hi);
        }
    if (wrong)
        fprintf(stderr, "%s: %ld texels not nodata at a hole or out of [%g, %g]\n", name, wrong,
                lo, hi);
    CHECK(wrong == 0);
    free_raster(&r);
}

/* ---- the checks ---------------------------------------------------------- */

/* `render --geotiff` of the geographic DEM: computed on its square cells,
 * written on the DEM's own grid (64x48, its geotransform, CRS and nodata at
 * the holes: gis_lit.h), 3 bands of radiance; texel (0, 0) is node 0 of
 * both grids, so it equals the PFM's (the square grid's) first texel. */
static void test_render_grid(const raster *in, const float *z)
{
    REQUIRE(run("render --height geo.tif --backend cpu --env-sh "
                "3.5449077,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0 --pfm lit.pfm --geotiff lit.tif") == 0,
            "render --geotiff failed");
    check_grid("lit.tif", in, z, ND, 0.0, 10.0);
    raster r;
    REQUIRE(read_raster("lit.tif", &r) == 0 && r.bands == 3, "lit.tif: not 3 bands");
    CHECK(!strcmp(meta(&r, "HFS_PRODUCT"), "render"));
    size_t n = 0;
    unsigned char *pfm = read_all(tpath("lit.pfm"), &n);
    REQUIRE(pfm && n > 12, "lit.pfm");
    /* the library's PFM: row j = 0 first (SPEC), the data its last bytes */
    int pw = 0, ph = 0;
    REQUIRE(sscanf((const char *)pfm, "PF %d %d", &pw, &ph) == 2 && ph == 59,
            "lit.pfm: not the 64x59 square grid (%dx%d)", pw, ph);
    float first;
    memcpy(&first, pfm + n - (size_t)pw * ph * 12, sizeof first);
    CHECK(fabsf(first - r.v[0]) <= 1e-6f * fabsf(first));
    free(pfm);
    free_raster(&r);
}

/* Sky-view factor, openness and horizons of the geographic DEM on the
 * CPU reference: grid, CRS, nodata, ranges, metadata. */
static void test_products(const raster *in, const float *z)
{
    REQUIRE(run("svf geo.tif -o svf_cpu.tif --backend cpu") == 0, "svf --backend cpu failed");
    check_grid("svf_cpu.tif", in, z, ND, 0.0, 1.0);
    raster r;
    REQUIRE(read_raster("svf_cpu.tif", &r) == 0, "svf_cpu.tif");
    CHECK(!strcmp(meta(&r, "HFS_PRODUCT"), "svf") && !strcmp(meta(&r, "HFS_SVF"), "zaksek"));
    CHECK(!strcmp(meta(&r, "HFS_DIRECTIONS"), "16") && !strcmp(meta(&r, "HFS_RADIUS_M"), "0"));
    CHECK(!strcmp(meta(&r, "HFS_AZIMUTH_CONVENTION"), "ccw-east"));
    CHECK(!strcmp(meta(&r, "HFS_BACKEND"), "cpu"));
    CHECK(encoded_as(&r, "3")); /* smooth values: the floating-point predictor */
    free_raster(&r);

    REQUIRE(run("openness geo.tif -o open.tif --backend cpu --directions 8") == 0,
            "openness failed");
    check_grid("open.tif", in, z, ND, 0.0, 180.0);
    REQUIRE(read_raster("open.tif", &r) == 0 && r.bands == 2, "open.tif: not 2 bands");
    CHECK(!strcmp(meta(&r, "HFS_PRODUCT"), "openness"));
    CHECK(atof(meta(&r, "HFS_RADIUS_M")) > 900.0); /* 10 cells of about 92 m */
    free_raster(&r);

    REQUIRE(run("horizon geo.tif -o hor --step 22.5 --backend cpu --radius 2000") == 0,
            "horizon --step 22.5 failed");
    static const char *const names[] = {"hor_000_0.tif", "hor_022_5.tif", "hor_180_0.tif",
                                        "hor_337_5.tif"};
    for (int k = 0; k < 4; ++k)
        check_grid(names[k], in, z, ND, 0.0, 90.0);
    REQUIRE(read_raster(names[1], &r) == 0, "%s", names[1]);
    CHECK(encoded_as(&r, NULL)); /* angles in runs of 0: no predictor */
    free_raster(&r);
    CHECK(access(tpath("hor_360_0.tif"), F_OK) != 0 && lines_of("err.txt") == 1);
}

/* |g - t| over the truth's texels with data within mean_bound (mean)
 * and max_bound; the measured error printed. */
static void check_error(const char *what, const raster *g, const raster *t, double mean_bound,
                        double max_bound)
{
    double sum = 0.0, max = 0.0;
    int n = 0;
    for (int p = 0; p < W * H; ++p)
        if (t->v[p] != (float)ND) {
            const double e = fabs((double)g->v[p] - t->v[p]);
            sum += e, max = fmax(max, e), ++n;
        }
    printf("%s vs truth: mean %.3g, max %.3g over %d texels (bounds %.3g, %.3g)\n", what,
           sum / n, max, n, mean_bound, max_bound);
    CHECK(sum / n <= mean_bound && max <= max_bound);
}

/* gles against truth on the geographic DEM; the measured error printed. */
static void test_gles_truth(const raster *in, const float *z)
{
    REQUIRE(run("svf geo.tif -o svf_truth.tif --backend truth") == 0, "svf truth failed");
    if (run("svf geo.tif -o svf_gles.tif") != 0) {
        REQUIRE(gles_failed("svf --backend gles"), "svf --backend gles failed");
        return;
    }
    check_grid("svf_gles.tif", in, z, ND, 0.0, 1.0);
    raster g, t;
    REQUIRE(read_raster("svf_gles.tif", &g) == 0 && read_raster("svf_truth.tif", &t) == 0,
            "svf rasters");
    check_error("svf gles", &g, &t, SVF_MEAN_BOUND, SVF_MAX_BOUND);
    CHECK(!strcmp(meta(&g, "HFS_BACKEND"), "gles"));
    free_raster(&g), free_raster(&t);
}

/* --method sweep (gis_sweep.h): on the input's grid, its metadata saying
 * so, the sky-view factor and a horizon against the truth's within the
 * bounds above (no renderer: no GL needed). */
static void test_sweep(const raster *in, const float *z)
{
    REQUIRE(run("svf geo.tif -o svf_truth.tif --backend truth") == 0 &&
                run("svf geo.tif -o svf_sweep.tif --method sweep") == 0 &&
                run("horizon geo.tif -o hsw_tru --azimuths 30 --backend truth") == 0 &&
                run("horizon geo.tif -o hsw --azimuths 30 --method sweep") == 0,
            "svf, horizon --method sweep failed");
    check_grid("svf_sweep.tif", in, z, ND, 0.0, 1.0);
    check_grid("hsw_030.tif", in, z, ND, 0.0, 90.0);
    const char *pairs[2][2] = {{"svf_sweep.tif", "svf_truth.tif"}, {"hsw_030.tif", "hsw_tru_030.tif"}};
    const double bound[2][2] = {{SWEEP_SVF_MEAN, SWEEP_SVF_MAX}, {SWEEP_HOR_MEAN, SWEEP_HOR_MAX}};
    for (int k = 0; k < 2; ++k) {
        raster g, t;
        REQUIRE(read_raster(pairs[k][0], &g) == 0 && read_raster(pairs[k][1], &t) == 0,
                "sweep rasters");
        check_error(pairs[k][0], &g, &t, bound[k][0], bound[k][1]);
        CHECK(!strcmp(meta(&g, "HFS_HORIZON_METHOD"), "sweep") &&
              !strcmp(meta(&t, "HFS_HORIZON_METHOD"), "exact"));
        free_raster(&g), free_raster(&t);
    }
}

/* The horizon command's files, encoded a few at a time on worker threads
 * (gis_horizon_files.h; 16 azimuths are several queues on a machine of
 * up to 7 cores): each file holds its own azimuth's angles, the same
 * values as a run of that azimuth alone; and a file that cannot be
 * written late in the run (a link to /dev/full: a device is written in
 * place, and fails only when written) leaves none of the others behind,
 * with one line of error. */
static void test_horizon_files(void)
{
    REQUIRE(run("horizon geo.tif -o hq --step 22.5 --method sweep") == 0 &&
                run("horizon geo.tif -o h1 --azimuths 157.5,337.5 --method sweep") == 0,
            "horizon --method sweep, 16 and 2 azimuths");
    static const char *const pairs[2][2] = {{"hq_157_5.tif", "h1_157_5.tif"},
                                            {"hq_337_5.tif", "h1_337_5.tif"}};
    raster q, one, east;
    REQUIRE(read_raster("hq_000_0.tif", &east) == 0, "hq_000_0.tif");
    for (int k = 0; k < 2; ++k) {
        REQUIRE(read_raster(pairs[k][0], &q) == 0 && read_raster(pairs[k][1], &one) == 0,
                "%s, %s", pairs[k][0], pairs[k][1]);
        CHECK(!memcmp(q.v, one.v, sizeof(float) * W * H));
        CHECK(memcmp(q.v, east.v, sizeof(float) * W * H) != 0);
        CHECK(!strcmp(meta(&q, "HFS_AZIMUTH"), k ? "337.5" : "157.5"));
        free_raster(&q), free_raster(&one);
    }
    free_raster(&east);
    if (access("/dev/full", W_OK) != 0)
        return; /* no such device here: the rest has run */
    REQUIRE(symlink("/dev/full", tpath("hx_315_0.tif")) == 0, "hx_315_0.tif -> /dev/full");
    const int rc = run("horizon geo.tif -o hx --step 22.5 --method sweep");
    CHECK(rc != 0 && lines_of("err.txt") == 1);
    CHECK(access(tpath("hx_000_0.tif"), F_OK) != 0 && access(tpath("hx_292_5.tif"), F_OK) != 0 &&
          access(tpath("hx_337_5.tif"), F_OK) != 0);
    unlink(tpath("hx_315_0.tif"));
}

/* A flat DEM: sky-view factor exactly 1, openness 90 / 90; NaN holes and
 * no declared nodata: -9999. */
static void test_flat(void)
{
    float z[W * H];
    for (int p = 0; p < W * H; ++p)
        z[p] = p == 7 * W + 9 || p == 40 * W + 50 ? NAN : 250.0f;
    const double gt[6] = {500000.0, 30.0, 0.0, 4000000.0, 0.0, -30.0};
    write_dem("flat.tif", z, gt, 32617, 0);
    raster f;
    REQUIRE(read_raster("flat.tif", &f) == 0, "flat.tif");
    if (run("svf flat.tif -o flat_svf.tif") != 0)
        REQUIRE(gles_failed("svf flat --backend gles"), "svf flat failed");
    else
        check_grid("flat_svf.tif", &f, z, -9999.0, 1.0, 1.0);
    REQUIRE(run("openness flat.tif -o flat_open.tif --backend cpu") == 0, "openness flat");
    check_grid("flat_open.tif", &f, z, -9999.0, 90.0, 90.0);
    free_raster(&f);
}

/* compass 90 and ccw-east 0 are both east: the same raster, named each
 * in its own convention; --cog writes a COG. */
static void test_conventions(void)
{
    REQUIRE(run("horizon geo.tif -o east --azimuths 0 --backend truth") == 0, "east");
    REQUIRE(run("horizon geo.tif -o east --azimuths 90 --convention compass --backend truth "
                "--cog") == 0, "compass east");
    raster a, b;
    REQUIRE(read_raster("east_000.tif", &a) == 0 && read_raster("east_090.tif", &b) == 0,
            "east_000.tif, east_090.tif");
    CHECK(!memcmp(a.v, b.v, sizeof(float) * W * H));
    CHECK(!strcmp(meta(&b, "HFS_AZIMUTH_CONVENTION"), "compass"));
    CHECK(!strcmp(meta(&b, "HFS_AZIMUTH"), "90") && !strcmp(b.layout, "COG"));
    CHECK(strcmp(a.layout, "COG"));
    free_raster(&a), free_raster(&b);
}

/* The same ground in UTM, north-up and south-up (rows from the south
 * edge, a positive row step): the south-up file's horizon raster at
 * ccw-east 30 (north-east) is the north-up one's with its rows reversed,
 * on its own geotransform; a west-running copy (columns east to west)
 * likewise with its columns reversed. */
static void test_orientation(const float *z)
{
    float s[W * H], e[W * H];
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            s[(H - 1 - j) * W + i] = z[j * W + i];
            e[j * W + (W - 1 - i)] = z[j * W + i];
        }
    const double north[6] = {500000.0, 30.0, 0.0, 4000000.0 + 30.0 * H, 0.0, -30.0};
    const double south[6] = {500000.0, 30.0, 0.0, 4000000.0, 0.0, 30.0};
    const double west[6] = {500000.0 + 30.0 * W, -30.0, 0.0, 4000000.0 + 30.0 * H, 0.0, -30.0};
    write_dem("utm_n.tif", z, north, 32617, 1);
    write_dem("utm_s.tif", s, south, 32617, 1);
    write_dem("utm_w.tif", e, west, 32617, 1);
    REQUIRE(run("horizon utm_n.tif -o hn --azimuths 30 --backend cpu") == 0 &&
                run("horizon utm_s.tif -o hs --azimuths 30 --backend cpu") == 0 &&
                run("horizon utm_w.tif -o hw --azimuths 30 --backend cpu") == 0,
            "horizon of utm_[nsw].tif failed");
    raster n, so, w;
    REQUIRE(read_raster("hn_030.tif", &n) == 0 && read_raster("hs_030.tif", &so) == 0 &&
                read_raster("hw_030.tif", &w) == 0, "hn_030.tif, hs_030.tif, hw_030.tif");
    CHECK(!memcmp(so.gt, south, sizeof south) && !memcmp(w.gt, west, sizeof west));
    double ds = 0.0, dw = 0.0, top = 0.0;
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            const float a = n.v[j * W + i];
            ds = fmax(ds, fabs(a - so.v[(H - 1 - j) * W + i]));
            dw = fmax(dw, fabs(a - w.v[j * W + (W - 1 - i)]));
            top = fmax(top, a == (float)ND ? 0.0 : a);
        }
    printf("orientation: south-up off by %.3g deg, west-running by %.3g (horizons to %.3g)\n", ds,
           dw, top);
    CHECK(ds < 1e-4 && dw < 1e-4 && top > 5.0);
    free_raster(&n), free_raster(&so), free_raster(&w);
}

/* A bad command or input: non-zero, one line on stderr, out not there. */
static void bad(const char *out, const char *args)
{
    const int rc = run("%s", args);
    const int lines = lines_of("err.txt");
    if (rc == 0 || lines != 1 || access(tpath(out), F_OK) == 0)
        fprintf(stderr, "hfshade %s: exit %d, %d stderr lines, %s %s\n", args, rc, lines, out,
                access(tpath(out), F_OK) == 0 ? "written" : "not written");
    CHECK(rc != 0 && lines == 1 && access(tpath(out), F_OK) != 0);
}

/* A DEM over the GLES path's texture side, searched whole (no --radius):
 * one line that names the DEM and the command's ways out.  Under the ES 3.0 minimum
 * limits (HFS_GL_STRICT_LIMITS: 2048 texels) a 4 x 2100 DEM is enough. */
static void test_over_limit(void)
{
    enum { LW = 4, LH = 2100 };
    static float z[LW * LH];
    for (int k = 0; k < LW * LH; ++k)
        z[k] = (float)(k % 7);
    const double gt[6] = {500000.0, 30.0, 0.0, 4000000.0, 0.0, -30.0};
    CHECK(gdal_fixture_write("GTiff", tpath("long.tif"), LW, LH, z, gt, 32616, 0, ND,
                             GDT_Float32) == 0);
    const char *was = getenv("HFS_GL_STRICT_LIMITS");
    char *keep = was ? strdup(was) : NULL;
    setenv("HFS_GL_STRICT_LIMITS", "1", 1);
    bad("long_svf.tif", "svf long.tif -o long_svf.tif");
    size_t n = 0;
    char *msg = (char *)read_all(tpath("err.txt"), &n);
    if (!gles_failed("svf over the texture limit"))
        CHECK(msg && strstr(msg, "long.tif: ") && strstr(msg, "texture limit") &&
              strstr(msg, "--method sweep") && strstr(msg, "--radius"));
    free(msg);
    if (keep)
        setenv("HFS_GL_STRICT_LIMITS", keep, 1);
    else
        unsetenv("HFS_GL_STRICT_LIMITS");
    free(keep);
}

static void test_bad_inputs(void)
{
    CHECK(run("svf --help") == 0 && lines_of("err.txt") == 0);
    size_t n = 0;
    unsigned char *text = read_all(tpath("out.txt"), &n);
    CHECK(text && n > 6 && !memcmp(text, "Usage: hfshade svf DEM", 22));
    free(text);
    write_bytes(tpath("notes.txt"), "not a raster\n", 13);
    bad("x.tif", "svf missing.tif -o x.tif");
    bad("x.tif", "svf notes.txt -o x.tif");
    bad("x.tif", "svf geo.tif -o x.tif --directions 0");
    bad("x.tif", "svf geo.tif -o x.tif --radius -5");
    bad("x.tif", "svf geo.tif -o x.tif --backend vulkan");
    bad("x.tif", "svf geo.tif -o x.tif --bogus");
    bad("x.tif", "openness geo.tif -o x.tif --lambertian");
    bad("x.tif", "svf geo.tif");
    size_t n0 = 0, n1 = 0;
    unsigned char *before = read_all(tpath("geo.tif"), &n0);
    bad("geo_svf.tif", "svf geo.tif -o geo.tif"); /* the input named as the output */
    unsigned char *after = read_all(tpath("geo.tif"), &n1);
    CHECK(before && after && n0 == n1 && !memcmp(before, after, n0));
    free(before), free(after);
    bad("x_000.tif", "horizon geo.tif -o x");
    bad("x_000.tif", "horizon geo.tif -o x --azimuths 0,360");
    bad("x_000.tif", "horizon geo.tif -o x --azimuths 0,abc");
    bad("x_000.tif", "horizon geo.tif -o x --step 0");
    bad("x_000.tif", "horizon geo.tif -o x --step 90 --azimuths 10");
    bad("x_000.tif", "horizon geo.tif -o nodir/x --azimuths 0 --backend cpu");
    bad("x.tif", "svf geo.tif -o x.tif --method fast");
    bad("x.tif", "svf geo.tif -o x.tif --method sweep --radius 500");
    bad("x.tif", "svf geo.tif -o x.tif --method sweep --backend truth");
    bad("x.tif", "openness geo.tif -o x.tif --method sweep");
    test_over_limit();
}

int main(int argc, char **argv)
{
    const int begun = gis_cli_begin(argc, argv, "gis_cli");
    if (begun)
        return begun;
    float z[W * H];
    terrain(z, (float)ND);
    const double arc = 3.0 / 3600.0;
    const double gt[6] = {-84.0, arc, 0.0, 36.0 + H * arc, 0.0, -arc};
    write_dem("geo.tif", z, gt, 4326, 1);
    raster in;
    if (read_raster("geo.tif", &in) == 0) {
        test_products(&in, z);
        test_render_grid(&in, z);
        test_gles_truth(&in, z);
        test_sweep(&in, z);
        test_horizon_files();
        test_flat();
        test_conventions();
        test_orientation(z);
        test_bad_inputs();
    } else {
        CHECK(!"geo.tif written and read");
    }
    free_raster(&in);
    return gis_cli_end("test_gis_cli");
}
