/*
 * test_gis_sky_cli.c — `hfshade insolation --sky-map` end to end (issue 39:
 * "the sky from ... a clear-sky model or a user's env map"; tools/gis/
 * gis_sky_map.h, gis_sun_command.c), on a 64x48 UTM DEM of a ridge running
 * east-west with hills on it, written here with GDAL, and sky maps written
 * here as PFM (top row the zenith):
 *   uniform  a map of one radiance: band 2 is the isotropic sky's (the run
 *            without --sky-map) at every texel, band 1 the same bits; the
 *            metadata names the map and its north;
 *   north    a sky ten times brighter within 45 degrees of north: the
 *            north face's share over the isotropic sky's is above 1, the
 *            south face's below; the same map turned half a turn with
 *            --sky-north 180 is the same sky as its columns rolled by half
 *            the width: the same band 2;
 *   truth    GLES against the truth's exact horizons, both with the north
 *            sky in 32 azimuths: the share's mean and max difference
 *            within bounds (what remains is the horizons' fp16 search);
 *   bad      --sky-north without --sky-map, a missing map, a negative sky,
 *            a black sky, --sky-map on `sun`: one line, non-zero, no file.
 * Without a GL context (and HFS_REQUIRE_GL unset) the GLES parts are
 * skipped and the test exits 77 at the end.
 *
 * Measured (RelWithDebInfo and the ASan build alike, llvmpipe): uniform
 * against isotropic, worst relative difference 0 (the same sums, in the same order); north
 * face 1.405, south face 0.635 times the isotropic share (means); the
 * turned map 0; gles - truth with the north sky, 32 azimuths: mean
 * 8.7e-9, max 1.9e-7 of the share (the ridge's horizons are smooth: the
 * hills of test_gis_sun.c pin the GLES horizons).  Bounds 1.2x.
 */
#define _XOPEN_SOURCE 700 /* realpath */

#include "gdal_fixture.h"
#include "gis_cli_util.h"

#include <math.h>
#include <unistd.h>

#define W 64
#define H 48
#define CELL 30.0
#define EPSG_UTM33 32633
#define PI 3.14159265358979323846

#define UNIFORM_TOL 1e-6   /* relative: the same sums, up to rounding     */
#define TRUTH_MEAN 1.05e-8 /* the share, gles - truth, north sky          */
#define TRUTH_MAX 2.3e-7

static const double utm_gt[6] = {500000.0 - CELL * W / 2, CELL, 0.0, 5200000.0 + CELL * H / 2,
                                 0.0, -CELL};
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
    CHECK(strstr(meta(&b, "HFS_DIFFUSE_MODEL"), "sky map") != NULL &&
          strstr(meta(&b, "HFS_DIFFUSE_MODEL"), "no ground reflection") != NULL);
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
    char cmd[512];
    const char *base = "insolation ridge.tif -o x.tif --backend cpu";
    snprintf(cmd, sizeof cmd, "%s %s --sky-north 10", base, day);
    bad(cmd, "only with --sky-map");
    snprintf(cmd, sizeof cmd, "%s %s --sky-map missing.exr", base, day);
    bad(cmd, "missing.exr");
    snprintf(cmd, sizeof cmd, "%s %s --sky-map negative.pfm", base, day);
    bad(cmd, "negative.pfm");
    snprintf(cmd, sizeof cmd, "%s %s --sky-map black.pfm", base, day);
    bad(cmd, "black");
    snprintf(cmd, sizeof cmd, "%s %s --sky-map north.pfm --sky-north 400", base, day);
    bad(cmd, "--sky-north");
    bad("sun ridge.tif -o x.tif --datetime 2026-06-21T08:00Z --sky-map north.pfm", "--sky-map");
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
    test_bad();
    return gis_cli_end("test_gis_sky_cli");
}
