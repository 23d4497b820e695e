/*
 * test_gis_sky_cli.c — `hfshade insolation --sky-map` and `--albedo` end to
 * end (issue 39: "the sky from ... a clear-sky model or a user's env map",
 * "like r.sun's mode 2"; tools/gis/gis_sky_map.h, gis_sun.c,
 * gis_sun_command.c), on 64x48 UTM DEMs (a ridge running east-west with
 * hills on it, an open 20-degree slope) written here with GDAL, and sky
 * maps written here as PFM (top row the zenith):
 *   uniform  a map of one radiance: band 2 is the isotropic sky's (the run
 *            without --sky-map) at every texel, band 1 the same bits; the
 *            metadata names the map and its north;
 *   north    a sky ten times brighter within 45 degrees of north: the
 *            north face's share over the isotropic sky's is above 1, the
 *            south face's below; the same map turned half a turn with
 *            --sky-north 180 is the same sky as its columns rolled by half
 *            the width: the same band 2;
 *   convergence  the ridge 400 km east of the central meridian: the map's
 *            azimuths are true ones, turned onto the grid by the grid
 *            convergence (--sky-north at it gives the meridian's shares);
 *   truth    GLES against the truth's exact horizons, both with the north
 *            sky in 32 azimuths: the share's mean and max difference
 *            within bounds (what remains is the horizons' fp16 search);
 *   albedo   the ground-reflected part, band 3 - band 1 - band 2: on the
 *            open slope albedo G (1 - cos 20) / 2 at every texel (r.sun's
 *            refl_rad), G the clear sky's global horizontal irradiation
 *            (HFS_GLOBAL_HORIZONTAL_WH, checked against the library's sun
 *            and clear sky step by step); on the ridge albedo G (1 - S),
 *            S the isotropic sky's share (band 2 of the run without a map
 *            over its diffuse), with the map too; --albedo 0 the run
 *            without it, bit for bit;
 *   beam     --beam-only: one band, the full run's band 1 bit for bit (the
 *            CPU reference and the sweep), HFS_BANDS=beam and no sky's
 *            metadata;
 *   bad      --sky-north without --sky-map, a missing map, a negative sky,
 *            a black sky, --sky-map on `sun`, an albedo out of [0, 1],
 *            --beam-only with a sky's option or on `sun`: one line,
 *            non-zero, no file.
 * Without a GL context (and HFS_REQUIRE_GL unset) the GLES parts are
 * skipped and the test exits 77 at the end.
 *
 * Measured (RelWithDebInfo and the ASan build alike, llvmpipe): uniform
 * against isotropic, worst relative difference 0 (the same sums, in the same order); north
 * face 1.405, south face 0.635 times the isotropic share (means); the
 * turned map 0; gles - truth with the north sky, 32 azimuths: mean
 * 8.7e-9, max 1.9e-7 of the share (the ridge's horizons are smooth: the
 * hills of test_gis_sun.c pin the GLES horizons); the reflected part
 * within 0.00087 (slope, cpu), 0.0011 (ridge, gles, with and without the
 * map) of albedo G (1 - S), G equal to the library's to the metadata's
 * 3 decimals.  Bounds 1.2x.
 */
#define _XOPEN_SOURCE 700 /* realpath */

#include "clear_sky.h"
#include "gdal_fixture.h"
#include "gis_cli_util.h"
#include "gis_utm_grid.h"
#include "solar_position.h"

#include <math.h>
#include <unistd.h>

#define PI 3.14159265358979323846

#define UNIFORM_TOL 1e-6   /* relative: the same sums, up to rounding     */
#define TRUTH_MEAN 1.05e-8 /* the share, gles - truth, north sky          */
#define TRUTH_MAX 2.3e-7
#define GLOBAL_TOL 1e-9    /* relative: HFS_GLOBAL_HORIZONTAL_WH, %.3f    */
#define REFLECT_TOL 1.4e-3 /* Wh/m^2: the three Float32 bands' rounding at
                            * some 9000 Wh/m^2 (half an ulp, 0.00049, each) */

static const char *day = "--from 2026-06-21T04:00+02:00 --to 2026-06-21T22:00+02:00 --step 60";

/* The ridge: its crest along row 24 (east-west), faces of about 25
 * degrees to the north (rows < 24) and the south, two hills on it. */
static void ridge(float *z)
{
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            const double a = hypot(i - 16.0, j - 30.0), b = hypot(i - 44.0, j - 16.0);
            z[j * W + i] = (float)(600.0 - 14.0 * fabs(j - 24.0) + 60.0 * exp(-a * a / 40.0) +
                                   50.0 * exp(-b * b / 50.0));
        }
}

/* A w x h PFM sky, grey, value f(compass azimuth of the column's centre). */
static void write_sky(const char *name, int w, int h, double (*f)(double compass), float scale)
{
    FILE *fp = fopen(tpath(name), "wb");
    REQUIRE(fp != NULL, "cannot write %s", name);
    fprintf(fp, "PF\n%d %d\n-1.0\n", w, h);
    for (int r = 0; r < h; ++r)
        for (int i = 0; i < w; ++i) {
            const float v = scale * (float)f(360.0 * (i + 0.5) / w);
            const float px[3] = {v, v, v};
            fwrite(px, sizeof px, 1, fp);
        }
    fclose(fp);
}

static double one(double c)
{
    (void)c;
    return 1.0;
}

static double north_bright(double c)
{
    return c < 45.0 || c > 315.0 ? 10.0 : 1.0;
}

static double south_bright(double c)
{
    return north_bright(fmod(c + 180.0, 360.0));
}

/* Runs insolation on ridge.tif into out with extra options; 0 when it ran,
 * 1 when GLES could not (and that may be skipped). */
static int insolation(const char *out, const char *extra)
{
    if (run("insolation ridge.tif %s -o %s %s", day, out, extra) == 0)
        return 0;
    if (!gles_failed(out)) {
        fprintf(stderr, "insolation %s %s failed\n", out, extra);
        CHECK(0);
    }
    return 1;
}

static double share(const raster *r, int p)
{
    const char *v = GDALGetMetadataItem(r->ds, "HFS_DIFFUSE_HORIZONTAL_WH", NULL);
    return r->v[W * H + p] / (v ? atof(v) : NAN);
}

static void test_uniform(void)
{
    if (insolation("iso.tif", "") || insolation("uni.tif", "--sky-map uniform.pfm"))
        return;
    raster a, b;
    REQUIRE(read_raster("iso.tif", &a) == 0 && read_raster("uni.tif", &b) == 0, "rasters");
    double worst = 0.0;
    int beam_same = 1;
    for (int p = 0; p < W * H; ++p) {
        worst = fmax(worst, fabs(b.v[W * H + p] - a.v[W * H + p]) / fabs(a.v[W * H + p]));
        beam_same &= a.v[p] == b.v[p];
    }
    printf("uniform sky map against the isotropic sky: worst relative %.3g\n", worst);
    printf("metadata: HFS_SKY_MAP=%s HFS_SKY_NORTH=%s HFS_DIFFUSE_MODEL=%s\n",
           meta(&b, "HFS_SKY_MAP"), meta(&b, "HFS_SKY_NORTH"), meta(&b, "HFS_DIFFUSE_MODEL"));
    CHECK(worst <= UNIFORM_TOL && beam_same);
    CHECK(!strcmp(meta(&b, "HFS_SKY_MAP"), "uniform.pfm") &&
          atof(meta(&b, "HFS_SKY_NORTH")) == 0.0);
    CHECK(strstr(meta(&b, "HFS_DIFFUSE_MODEL"), "sky map") != NULL);
    free_raster(&a), free_raster(&b);
}

static void test_north(void)
{
    if (insolation("iso.tif", "") || insolation("north.tif", "--sky-map north.pfm") ||
        insolation("turned.tif", "--sky-map south.pfm --sky-north 180"))
        return;
    raster iso, nb, tu;
    REQUIRE(read_raster("iso.tif", &iso) == 0 && read_raster("north.tif", &nb) == 0 &&
            read_raster("turned.tif", &tu) == 0, "rasters");
    double fn = 0.0, fs = 0.0, worst = 0.0;
    int nn = 0, ns = 0;
    for (int j = 2; j < H - 2; ++j)
        for (int i = 2; i < W - 2; ++i) {
            const int p = j * W + i;
            const double ratio = share(&nb, p) / share(&iso, p);
            if (j < 20)
                fn += ratio, ++nn;
            else if (j > 28)
                fs += ratio, ++ns;
        }
    for (int p = 0; p < W * H; ++p)
        worst = fmax(worst, fabs(tu.v[W * H + p] - nb.v[W * H + p]) / nb.v[W * H + p]);
    printf("north sky over the isotropic: north face %.4f, south face %.4f; turned map %.3g\n",
           fn / nn, fs / ns, worst);
    CHECK(fn / nn > 1.05 && fs / ns < 0.95);
    CHECK(worst <= UNIFORM_TOL);
    free_raster(&iso), free_raster(&nb), free_raster(&tu);
}

/* The same ridge 400 km east of the zone's central meridian, where grid
 * north lies about 3.8 degrees east of true north: the map's azimuths are
 * true ones, so its north sky there with --sky-north at the convergence
 * lies on the grid as the same sky does on the meridian with --sky-north
 * 0: the same shares (band 2 over the clear sky's diffuse).  The CPU
 * reference on both, so that nothing but the sky's placement differs. */
static void test_convergence(void)
{
    float z[W * H];
    ridge(z);
    double gt[6];
    memcpy(gt, utm_gt, sizeof gt);
    gt[0] += 400000.0;
    CHECK(gdal_fixture_write("GTiff", tpath("ridge_far.tif"), W, H, z, gt, EPSG_UTM33, 0, 0.0,
                             GDT_Float32) == 0);
    REQUIRE(run("insolation ridge.tif %s -o on.tif --backend cpu --sky-map north.pfm", day) == 0 &&
                run("insolation ridge_far.tif %s -o far0.tif --backend cpu", day) == 0,
            "insolation on and off the meridian");
    raster on, far0, far;
    REQUIRE(read_raster("on.tif", &on) == 0 && read_raster("far0.tif", &far0) == 0, "rasters");
    const double gamma = meta_num(&far0, "HFS_GRID_CONVERGENCE_DEG");
    REQUIRE(run("insolation ridge_far.tif %s -o far.tif --backend cpu --sky-map north.pfm "
                "--sky-north %.9f", day, gamma) == 0, "insolation off the meridian, the map");
    REQUIRE(read_raster("far.tif", &far) == 0, "far.tif");
    double worst = 0.0;
    for (int p = 0; p < W * H; ++p)
        worst = fmax(worst, fabs(share(&far, p) - share(&on, p)) / share(&on, p));
    printf("north sky 400 km off the meridian (convergence %.4f deg), --sky-north at it: the "
           "shares within %.3g of the meridian's\n", gamma, worst);
    CHECK(gamma > 3.0 && meta_num(&on, "HFS_GRID_CONVERGENCE_DEG") == 0.0);
    CHECK(worst <= UNIFORM_TOL);
    free_raster(&on), free_raster(&far0), free_raster(&far);
}

static void test_truth(void)
{
    REQUIRE(run("insolation ridge.tif %s -o t.tif --backend truth --directions 32 --sky-map "
                "north.pfm", day) == 0, "insolation truth");
    if (insolation("g.tif", "--directions 32 --sky-map north.pfm"))
        return;
    raster t, g;
    REQUIRE(read_raster("t.tif", &t) == 0 && read_raster("g.tif", &g) == 0, "rasters");
    double sum = 0.0, max = 0.0;
    for (int p = 0; p < W * H; ++p) {
        const double e = fabs(share(&g, p) - share(&t, p));
        sum += e, max = fmax(max, e);
    }
    printf("north sky, gles against the truth (32 azimuths): mean %.3g max %.3g\n",
           sum / (W * H), max);
    CHECK(sum / (W * H) <= TRUTH_MEAN && max <= TRUTH_MAX);
    free_raster(&t), free_raster(&g);
}

/* ---- the ground's reflection ------------------------------------------- */

static double jd_of(const char *iso)
{
    hfs_solar_time t;
    char msg[200];
    if (hfs_solar_parse_local(iso, NULL, &t, msg, sizeof msg)) {
        fprintf(stderr, "%s: %s\n", iso, msg);
        CHECK(!"a date-time of the run's metadata");
        return 0.0;
    }
    return hfs_solar_julian_day(&t);
}

/* The clear sky's global horizontal irradiation over run r's period at
 * its site, from the library's sun and clear sky step by step: (beam
 * normal sin h0 + diffuse horizontal) hours, h0 the true elevation. */
static double expected_global(const raster *r)
{
    const hfs_solar_site site = {.lat_deg = meta_num(r, "HFS_SITE_LAT"),
                                 .lon_deg = meta_num(r, "HFS_SITE_LON"),
                                 .elevation_m = meta_num(r, "HFS_SITE_ELEVATION_M")};
    const double from = jd_of(meta(r, "HFS_FROM")), to = jd_of(meta(r, "HFS_TO"));
    const double step = meta_num(r, "HFS_STEP_MIN") / 1440.0;
    double g = 0.0;
    for (double t0 = from; t0 < to - 1e-9; t0 += step) {
        const double len = fmin(step, to - t0);
        hfs_solar_angles a;
        double beam = 0.0, diffuse = 0.0;
        CHECK(hfs_solar_position_jd(t0 + 0.5 * len, &site, &a) == 0);
        CHECK(hfs_clear_sky_g0(a.elevation_true_deg, site.elevation_m, meta_num(r, "HFS_LINKE"),
                               HFS_SOLAR_CONSTANT_WM2 * a.distance_factor, &beam, &diffuse) == 0);
        g += (beam * fmax(sin(a.elevation_true_deg * PI / 180.0), 0.0) + diffuse) * 24.0 * len;
    }
    return g;
}

/* The reflected part at texel p: band 3 - band 1 - band 2. */
static double reflected(const raster *r, int p)
{
    return (double)r->v[2 * W * H + p] - r->v[p] - r->v[W * H + p];
}

/* Run `name` (with --albedo rho): its reflected part against rho G (1 -
 * S(p)); S from iso (the isotropic run's band 2 over its diffuse) or,
 * with iso NULL, the open plane's (1 + cos 20) / 2.  The worst |error|. */
static double check_reflected(const char *name, double rho, const raster *iso)
{
    raster r;
    if (read_raster(name, &r) != 0) {
        CHECK(!"a raster of the albedo runs");
        return HUGE_VAL;
    }
    const double g = meta_num(&r, "HFS_GLOBAL_HORIZONTAL_WH"), want_g = expected_global(&r);
    CHECK(fabs(g - want_g) <= GLOBAL_TOL * want_g + 1e-3);
    CHECK(meta_num(&r, "HFS_ALBEDO") == rho);
    double worst = 0.0;
    for (int p = 0; p < W * H; ++p) {
        const double s = iso ? share(iso, p) : 0.5 * (1.0 + cos(20.0 * PI / 180.0));
        worst = fmax(worst, fabs(reflected(&r, p) - rho * g * (1.0 - s)));
    }
    printf("%s: global horizontal %.3f Wh/m^2 (library %.3f), reflected within %.3g\n", name,
           g, want_g, worst);
    free_raster(&r);
    return worst;
}

static void test_albedo(void)
{
    float z[W * H];
    const double t = tan(20.0 * PI / 180.0);
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) /* falls to the south-east */
            z[j * W + i] = (float)(900.0 - t * CELL * (i + j) / sqrt(2.0));
    CHECK(gdal_fixture_write("GTiff", tpath("slope.tif"), W, H, z, utm_gt, EPSG_UTM33, 0, 0.0,
                             GDT_Float32) == 0);
    REQUIRE(run("insolation slope.tif %s -o slope_a3.tif --backend cpu --albedo 0.3", day) == 0,
            "the slope with an albedo");
    CHECK(check_reflected("slope_a3.tif", 0.3, NULL) <= REFLECT_TOL);
    if (insolation("iso.tif", "") || insolation("a0.tif", "--albedo 0") ||
        insolation("a2.tif", "--albedo 0.2") ||
        insolation("a2map.tif", "--albedo 0.2 --sky-map north.pfm"))
        return;
    raster iso, a0;
    REQUIRE(read_raster("iso.tif", &iso) == 0 && read_raster("a0.tif", &a0) == 0, "iso, a0");
    CHECK(!memcmp(iso.v, a0.v, sizeof(float) * 3 * W * H)); /* --albedo 0: the same bands */
    free_raster(&a0);
    CHECK(check_reflected("a2.tif", 0.2, &iso) <= REFLECT_TOL);
    CHECK(check_reflected("a2map.tif", 0.2, &iso) <= REFLECT_TOL);
    free_raster(&iso);
}

/* --beam-only: the beam alone, the full run's band 1 bit for bit, with
 * and without the sweep (the sky's horizons are not searched). */
static void test_beam_only(void)
{
    static const char *const how[] = {"--backend cpu", "--backend cpu --method sweep"};
    for (int k = 0; k < 2; ++k) {
        char full[32], beam[32];
        snprintf(full, sizeof full, "full%d.tif", k);
        snprintf(beam, sizeof beam, "beam%d.tif", k);
        REQUIRE(run("insolation ridge.tif %s -o %s %s", day, full, how[k]) == 0 &&
                    run("insolation ridge.tif %s -o %s %s --beam-only", day, beam, how[k]) == 0,
                "insolation %s", how[k]);
        raster f, b;
        REQUIRE(read_raster(full, &f) == 0 && read_raster(beam, &b) == 0, "%s, %s", full, beam);
        printf("%s --beam-only: %d band(s), band 1 %s the full run's\n", how[k], b.bands,
               b.bands >= 1 && !memcmp(f.v, b.v, sizeof(float) * W * H) ? "equal to" : "not");
        CHECK(f.bands == 3 && b.bands == 1 && !memcmp(f.v, b.v, sizeof(float) * W * H));
        CHECK(!strcmp(meta(&b, "HFS_BANDS"), "beam") && !*meta(&b, "HFS_DIFFUSE_MODEL") &&
              !*meta(&b, "HFS_DIRECTIONS") && *meta(&f, "HFS_DIFFUSE_MODEL"));
        free_raster(&f), free_raster(&b);
    }
}

/* A bad command or input: non-zero, one line on stderr, x.tif not there. */
static void bad(const char *args, const char *says)
{
    const int rc = run("%s", args);
    const int lines = lines_of("err.txt");
    const int left = access(tpath("x.tif"), F_OK) == 0;
    size_t n = 0;
    unsigned char *e = read_all(tpath("err.txt"), &n);
    if (e)
        e[n] = '\0';
    const int named = e && strstr((const char *)e, says) != NULL;
    if (rc == 0 || lines != 1 || left || !named)
        fprintf(stderr, "hfshade %s: exit %d, %d stderr lines, x.tif %s: %s", args, rc, lines,
                left ? "written" : "not written", e ? (const char *)e : "");
    CHECK(rc != 0 && lines == 1 && !left && named);
    free(e);
}

static void test_bad(void)
{
    /* insolation on the ridge with these options, and what its line says */
    static const char *const ins[][2] = {
        {"--sky-north 10", "only with --sky-map"},
        {"--sky-map missing.exr", "missing.exr"},
        {"--sky-map negative.pfm", "negative.pfm"},
        {"--sky-map black.pfm", "black"},
        {"--sky-map north.pfm --sky-north 400", "--sky-north"},
        {"--albedo 1.5", "--albedo"},
        {"--albedo -0.1", "--albedo"},
        {"--beam-only --albedo 0.2", "--albedo: not with --beam-only"},
        {"--directions 8 --beam-only", "--directions: not with --beam-only"},
        {"--beam-only --sky-map north.pfm", "--sky-map: not with --beam-only"},
    };
    for (size_t k = 0; k < sizeof ins / sizeof ins[0]; ++k) {
        char cmd[512];
        snprintf(cmd, sizeof cmd, "insolation ridge.tif -o x.tif --backend cpu %s %s", day,
                 ins[k][0]);
        bad(cmd, ins[k][1]);
    }
    bad("sun ridge.tif -o x.tif --datetime 2026-06-21T08:00Z --sky-map north.pfm", "--sky-map");
    bad("sun ridge.tif -o x.tif --datetime 2026-06-21T08:00Z --beam-only", "--beam-only");
}

int main(int argc, char **argv)
{
    const int begun = gis_cli_begin(argc, argv, "gis_sky_cli");
    if (begun)
        return begun;
    float z[W * H];
    ridge(z);
    CHECK(gdal_fixture_write("GTiff", tpath("ridge.tif"), W, H, z, utm_gt, EPSG_UTM33, 0, 0.0,
                             GDT_Float32) == 0);
    write_sky("uniform.pfm", 48, 24, one, 2.0f);
    write_sky("north.pfm", 64, 32, north_bright, 1.0f);
    write_sky("south.pfm", 64, 32, south_bright, 1.0f);
    write_sky("negative.pfm", 8, 4, one, -1.0f);
    write_sky("black.pfm", 8, 4, one, 0.0f);
    test_uniform();
    test_north();
    test_truth();
    test_convergence();
    test_albedo();
    test_beam_only();
    test_bad();
    return gis_cli_end("test_gis_sky_cli");
}
