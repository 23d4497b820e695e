/*
 * test_gis_tiles.c — `hfshade tiles plan | run | merge` (issue 40 item 1,
 * tools/gis/gis_tiles.h) on a 150x110 UTM DEM with holes (the terrain of
 * test_gis_stream.c), svf and horizon on the CPU reference, tiles of 64
 * texels (3 x 2 jobs):
 *   plan     the manifest and one line a job (K IX IY IW IH HALO tiles/K);
 *            a second plan into the same directory, a DEM that does not
 *            stream (no radius) and a product that does not tile are
 *            refused in one line;
 *   run      each job by its whole line of jobs (as GNU parallel passes
 *            it); a finished job is not redone; a job killed while
 *            writing (its temporary left behind) runs again and finishes;
 *            a job number out of range is refused;
 *   merge    refused while jobs are missing (naming them); then the
 *            mosaic holds the streamed command's values bit for bit
 *            (`hfshade svf --tile 64`), its grid, CRS and nodata; horizon
 *            merges one file an azimuth;
 *   sun      sun (a morning sun: its halo the reach of the hills' shadows)
 *            and insolation (--radius 450) planned, run and merged: the
 *            whole run's (--tile 0) values bit for bit, shadows included;
 *            insolation without a radius and the truth's sun refused;
 *   render   the lit render (sky + a 3-degree sun, --zscale 0.25, --dx 60:
 *            a halo of 53 texels) planned, run, merged: within RENDER_BOUND
 *            of the whole render, holes nodata in both; its jobs run in
 *            reverse merge to the same bytes; a local light and a DEM that
 *            fits one tile refused;
 *   vrt      the DEM as a VRT of two GeoTIFF halves: the same mosaic;
 *   parallel the same plan run by GNU parallel on 2 cores, and once more
 *            stopped after 2 jobs and resumed with --resume-failed: each
 *            mosaic byte for byte the sequential run's.
 */
#define _XOPEN_SOURCE 700 /* realpath */

#include "gdal_fixture.h"
#include "gis_cli_util.h"

#include <gdal_utils.h>

#include <math.h>
#include <sys/stat.h>

#define W 150
#define H 110
#define ND (-9999.0)
#define SVF_ARGS "--backend cpu --radius 600 --directions 8"
#define RENDER_BOUND 3.6e-5 /* 1.2x the 2.97e-5 measured (values about 1.02) */

/* CHECK with a message: EXPECT(cond) or EXPECT(cond, "fmt", ...). */
#define EXPECT(cond, ...) expect_at(__FILE__, __LINE__, (cond), #cond, "" __VA_ARGS__)
static void expect_at(const char *file, int line, int ok, const char *what, const char *fmt, ...)
{
    if (ok)
        return;
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "%s:%d: CHECK failed: %s: ", file, line, what);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    ++failures;
}

static void terrain(float *z)
{
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            const double a = hypot(i - 40.0, j - 30.0), b = hypot(i - 110.0, j - 80.0);
            const int hole = (i == 64 && j == 64) || (i == 5 && j == 5) ||
                             (i >= 70 && i < 73 && j >= 62 && j < 65);
            z[j * W + i] = hole ? (float)ND
                                : (float)(300.0 + 180.0 * exp(-a * a / 200.0) +
                                          140.0 * exp(-b * b / 300.0) + 2.0 * fabs(i - 75.0) +
                                          10.0 * sin(0.3 * j));
        }
}

/* 1 when err.txt (the last run's stderr) holds s. */
static int said(const char *s)
{
    size_t n = 0;
    char *b = (char *)read_all(tpath("err.txt"), &n);
    const int yes = b && strstr(b, s) != NULL;
    if (!yes)
        printf("err.txt: %s\n", b ? b : "(none)");
    free(b);
    return yes;
}

/* Runs jobs first..last of plan dir one by one, each by its line. */
static int run_jobs(const char *dir, int first, int last)
{
    char jobs[64];
    snprintf(jobs, sizeof jobs, "%s/jobs", dir);
    size_t n = 0;
    char *b = (char *)read_all(tpath(jobs), &n), *save = NULL;
    int rc = b ? 0 : -1, k = 0;
    for (char *line = b ? strtok_r(b, "\n", &save) : NULL; line && !rc;
         line = strtok_r(NULL, "\n", &save))
        if (++k >= first && k <= last)
            rc = run("tiles run %s/manifest '%s'", dir, line);
    free(b);
    return rc;
}

/* The bytes of two files equal. */
static int same_bytes(const char *a, const char *b)
{
    size_t na = 0, nb = 0;
    unsigned char *x = read_all(tpath(a), &na), *y = read_all(tpath(b), &nb);
    const int same = x && y && na == nb && !memcmp(x, y, na);
    free(x);
    free(y);
    return same;
}

static void test_plan(void)
{
    EXPECT(run("tiles plan dem.tif --product svf --tile 64 -o A " SVF_ARGS) == 0);
    EXPECT(lines_of("A/jobs") == 6, "6 jobs: %d", lines_of("A/jobs"));
    size_t n = 0;
    char *jobs = (char *)read_all(tpath("A/jobs"), &n);
    EXPECT(jobs && !strncmp(jobs, "1 0 0 64 64 22 tiles/1\n", 23), "job 1: %.30s",
          jobs ? jobs : "");
    EXPECT(jobs && strstr(jobs, "\n6 128 64 22 46 22 tiles/6\n"), "job 6");
    free(jobs);
    EXPECT(run("tiles plan dem.tif --product svf --tile 64 -o A " SVF_ARGS) == 1 &&
          said("a plan is there already"));
    EXPECT(run("tiles plan dem.tif --product svf --tile 64 -o X --backend cpu") == 1 &&
          said("no tiles to plan: no --radius"));
    EXPECT(run("tiles plan dem.tif --product hillshade --tile 64 -o X") == 2 &&
          said("is not render, svf, horizon, openness, sun or insolation"));
    EXPECT(run("tiles plan dem.tif --product insolation --tile 64 -o X --backend cpu "
               "--from 2026-06-21T05:00Z --to 2026-06-21T06:00Z") == 1 &&
          said("no tiles to plan: no --radius"));
    EXPECT(run("tiles plan dem.tif --product sun --tile 64 -o X --backend truth "
               "--datetime 2026-06-21T06:30Z") == 1 &&
          said("no tiles to plan: the truth renders the whole DEM's shadows"));
    EXPECT(run("tiles plan dem.tif --product sun --tile 64 -o X --backend cpu "
               "--datetime 2026-06-21T01:00Z") == 1 &&
          said("no tiles to plan: the sun is below the horizon: the raster is zeros"));
    EXPECT(access(tpath("X"), F_OK) != 0, "a refused plan left its directory");
}

static void test_run_merge(void)
{
    EXPECT(run_jobs("A", 1, 3) == 0);
    EXPECT(run("tiles merge A -o early.tif") == 1 && said("3 of 6 jobs have no tiles/N.tif: 4, "
                                                           "5, 6"));
    EXPECT(access(tpath("early.tif"), F_OK) != 0, "a refused merge wrote its output");
    /* job 4 killed while writing: its temporary, no file */
    FILE *f = fopen(tpath("A/tiles/4.tif.tmp-abcdef"), "w");
    EXPECT(f && fputs("half a GeoTIFF", f) >= 0 && fclose(f) == 0);
    EXPECT(run_jobs("A", 4, 6) == 0);
    struct stat before, after;
    EXPECT(stat(tpath("A/tiles/2.tif"), &before) == 0);
    EXPECT(run("tiles run A/manifest 2") == 0 && said("job 2 done already"));
    EXPECT(stat(tpath("A/tiles/2.tif"), &after) == 0 &&
          before.st_mtim.tv_nsec == after.st_mtim.tv_nsec &&
          before.st_mtim.tv_sec == after.st_mtim.tv_sec, "a finished job was redone");
    EXPECT(run("tiles run A/manifest 7") == 1 && said("job '7' is not one of 1..6"));
    EXPECT(run("tiles merge A -o a.tif") == 0);
    EXPECT(run("svf dem.tif " SVF_ARGS " --tile 64 -o streamed.tif") == 0);
    raster m, s;
    EXPECT(read_raster("a.tif", &m) == 0 && read_raster("streamed.tif", &s) == 0);
    EXPECT(m.w == W && m.h == H && m.has_nd && m.nd == ND && !memcmp(m.gt, s.gt, sizeof m.gt) &&
          !strcmp(m.wkt, s.wkt), "the mosaic's grid");
    long off = 0;
    for (size_t p = 0; m.v && s.v && p < (size_t)W * H; ++p)
        off += memcmp(&m.v[p], &s.v[p], sizeof(float)) != 0;
    EXPECT(off == 0, "%ld texels of the mosaic differ from the streamed run", off);
    EXPECT(!strcmp(meta(&m, "HFS_PRODUCT"), "svf"), "metadata: %s", meta(&m, "HFS_PRODUCT"));
    EXPECT(encoded_as(&m, "3"), "a.tif: not DEFLATE tiles of 256 with the predictor, as its tiles");
    free_raster(&m), free_raster(&s);
}

static void test_horizon(void)
{
    EXPECT(run("tiles plan dem.tif --product horizon --tile 64 -o B --backend cpu --radius 600 "
              "--azimuths 0,135") == 0);
    EXPECT(run_jobs("B", 1, 6) == 0);
    EXPECT(run("tiles merge B -o hm") == 0);
    EXPECT(run("horizon dem.tif --backend cpu --radius 600 --azimuths 0,135 --tile 64 -o hs") == 0);
    for (int k = 0; k < 2; ++k) {
        raster m, s;
        const char *a = k ? "hm_135.tif" : "hm_000.tif", *b = k ? "hs_135.tif" : "hs_000.tif";
        EXPECT(read_raster(a, &m) == 0 && read_raster(b, &s) == 0, "%s", a);
        EXPECT(m.v && s.v && !memcmp(m.v, s.v, sizeof(float) * W * H), "%s differs from %s", a, b);
        EXPECT(encoded_as(&m, NULL), "%s: not plain DEFLATE tiles of 256", a); /* as the tiles */
        free_raster(&m), free_raster(&s);
    }
}

/* Mosaic a and whole run b: the same bands, bit for bit; *shade the
 * texels of band `band` below 0.5 (the sun's shadows). */
static long same_values(const char *a, const char *b, int bands, int band, long *shade)
{
    raster m, w;
    EXPECT(read_raster(a, &m) == 0 && read_raster(b, &w) == 0, "%s, %s", a, b);
    long off = m.v && w.v && m.bands == bands && w.bands == bands ? 0 : -1;
    *shade = 0;
    for (size_t p = 0; off >= 0 && p < (size_t)bands * W * H; ++p)
        off += memcmp(&m.v[p], &w.v[p], sizeof(float)) != 0;
    for (size_t p = 0; off >= 0 && p < (size_t)W * H; ++p)
        *shade += m.v[(size_t)band * W * H + p] < 0.5f && m.v[p] != (float)ND;
    EXPECT(off == 0, "%s: %ld values differ from %s", a, off, b);
    EXPECT(!strcmp(meta(&m, "HFS_PRODUCT"), meta(&w, "HFS_PRODUCT")), "%s: metadata", a);
    free_raster(&m), free_raster(&w);
    return off;
}

/* dem.tif's plan of `product` with args in tiles of 64 (6 jobs) into
 * dir, each job run, merged into out: 1 when all of it succeeded. */
static int plan_run_merge(const char *dir, const char *product, const char *args,
                          const char *out)
{
    return run("tiles plan dem.tif --product %s --tile 64 -o %s %s", product, dir, args) == 0 &&
           run_jobs(dir, 1, 6) == 0 && run("tiles merge %s -o %s", dir, out) == 0;
}

/* sun (its halo the shadows' reach from the DEM's relief, no radius) and
 * insolation (--radius) in tiles: the mosaic is the whole run's, bit for
 * bit, shadows and all. */
#define SUN_ARGS "--backend cpu --datetime 2026-06-21T04:30Z"
#define INS_ARGS "--backend cpu --radius 450 --from 2026-06-21T04:00Z --to 2026-06-21T08:00Z " \
                 "--step 60"
static void test_sun(void)
{
    EXPECT(plan_run_merge("S", "sun", SUN_ARGS, "sm.tif"));
    size_t n = 0;
    char *manifest = (char *)read_all(tpath("S/manifest"), &n);
    EXPECT(manifest && strstr(manifest, "\narg = --relief\narg = "),
           "the plan gives its jobs the relief it read");
    free(manifest);
    EXPECT(run("sun dem.tif " SUN_ARGS " --tile 0 -o sw.tif") == 0);
    long shade;
    EXPECT(same_values("sm.tif", "sw.tif", 2, 1, &shade) == 0);
    EXPECT(shade > 1000, "%ld texels in the hills' shadows (V < 0.5)", shade);
    EXPECT(plan_run_merge("I", "insolation", INS_ARGS, "im.tif"));
    EXPECT(run("insolation dem.tif " INS_ARGS " --tile 0 -o iw.tif") == 0);
    EXPECT(same_values("im.tif", "iw.tif", 3, 0, &shade) == 0);
}

/* The lit render in tiles (tools/cli_render_job.h): each job renders its
 * part with a halo from the relief and the lights; the mosaic is within
 * RENDER_BOUND of the whole render (the CPU reference; its search stops
 * at a window's edge instead of the field's), holes nodata in both, and
 * the same plan run in another order merges to the same bytes. */
#define RENDER_ARGS "--backend cpu --dx 60 --zscale 0.25 " \
                    "--env-sh 3.5449,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0 --key 40,3,0.5,5000"
static void test_render(void)
{
    EXPECT(plan_run_merge("R", "render", RENDER_ARGS, "rm.tif"));
    EXPECT(run("render --height dem.tif " RENDER_ARGS " --geotiff rw.tif") == 0);
    raster m, w;
    EXPECT(read_raster("rm.tif", &m) == 0 && read_raster("rw.tif", &w) == 0);
    EXPECT(m.v && w.v && m.bands == 3 && w.bands == 3 && m.w == W && m.h == H &&
               !memcmp(m.gt, w.gt, sizeof m.gt) && !strcmp(m.wkt, w.wkt) && m.nd == w.nd,
           "the render mosaic's grid");
    double worst = 0.0, seam = 0.0; /* seam: within 2 texels of a tile's inner edge */
    long holes = 0, shade = 0;
    for (size_t p = 0; w.v && p < (size_t)W * H; ++p) /* red: the key light's shadows */
        shade += w.v[p] != (float)w.nd && w.v[p] < 1.01f;
    for (size_t p = 0; m.v && w.v && p < (size_t)3 * W * H; ++p) {
        if (w.v[p] == (float)w.nd) {
            holes += m.v[p] == (float)m.nd;
            continue;
        }
        const int i = (int)(p % ((size_t)W * H) % W), j = (int)(p % ((size_t)W * H) / W);
        const int near = (i % 64 < 2 && i >= 64) || (i % 64 >= 62 && i < W - 2) ||
                         (j % 64 < 2 && j >= 64) || (j % 64 >= 62 && j < H - 2);
        worst = fmax(worst, fabs((double)m.v[p] - w.v[p]));
        seam = near ? fmax(seam, fabs((double)m.v[p] - w.v[p])) : seam;
    }
    printf("render in 6 tiles against the whole render: max %.3g (bound %.3g), %.3g within 2 "
           "texels of a tile's edge, %ld hole values nodata in both\n", worst, RENDER_BOUND,
           seam, holes);
    EXPECT(worst <= RENDER_BOUND && holes == 3 * 11, "max %.3g, %ld holes", worst, holes);
    EXPECT(shade > 300, "%ld texels in the key light's shadows", shade);
    free_raster(&m), free_raster(&w);
    EXPECT(run("tiles plan dem.tif --product render --tile 64 -o Q " RENDER_ARGS) == 0);
    for (int k = 6; k >= 1; --k)
        EXPECT(run("tiles run Q/manifest %d", k) == 0);
    EXPECT(run("tiles merge Q -o qm.tif") == 0 && same_bytes("rm.tif", "qm.tif"),
           "the render mosaic of jobs run in another order differs");
    EXPECT(run("tiles plan dem.tif --product render --tile 64 -o X " RENDER_ARGS
               " --local 600,600,300,20,1") == 1 && said("no halo short of the whole field"));
    /* a file-valued key is made absolute in the manifest, as the DEM is,
     * so that a job finds it from any folder */
    FILE *f = fopen(tpath("sky.pfm"), "wb");
    if (f) {
        const float grey[2 * 4 * 3] = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1,
                                       1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
        fprintf(f, "PF\n4 2\n-1.0\n");
        fwrite(grey, sizeof grey, 1, f);
        fclose(f);
    }
    char sky[PATH_MAX], want[PATH_MAX + 16];
    EXPECT(f && realpath(tpath("sky.pfm"), sky));
    snprintf(want, sizeof want, "arg = %s\n", sky);
    EXPECT(run("tiles plan dem.tif --product render --tile 64 -o RM --backend cpu --dx 60 "
               "--zscale 0.25 --env-map sky.pfm --key 40,3,0.5,5000") == 0);
    size_t n = 0;
    unsigned char *manifest = read_all(tpath("RM/manifest"), &n);
    if (manifest)
        manifest[n] = '\0';
    EXPECT(manifest && strstr((const char *)manifest, want), "the manifest has no '%s'", sky);
    free(manifest);
    EXPECT(run("tiles plan dem.tif --product insolation --tile 64 -o IM --backend cpu "
               "--from 2026-06-21T10:00Z --to 2026-06-21T11:00Z --radius 200 "
               "--sky-map sky.pfm") == 0);
    manifest = read_all(tpath("IM/manifest"), &n);
    if (manifest)
        manifest[n] = '\0';
    EXPECT(manifest && strstr((const char *)manifest, want), "insolation: no '%s'", sky);
    free(manifest);
    EXPECT(run("tiles plan dem.tif --product render --tile 256 -o X " RENDER_ARGS) == 1 &&
           said("fits one tile"));
    EXPECT(access(tpath("X"), F_OK) != 0, "a refused plan left its directory");
}

/* A VRT of the DEM's two halves (two GeoTIFFs, GDALBuildVRT) plans and
 * runs as the DEM itself: its mosaic holds a.tif's values bit for bit. */
static void test_vrt(const float *z, const double gt[6])
{
    enum { HW = W / 2 };
    static float half[HW * H];
    const char *names[2] = {"west.tif", "east.tif"};
    char *paths[2];
    for (int k = 0; k < 2; ++k) {
        for (int j = 0; j < H; ++j)
            memcpy(half + (size_t)j * HW, z + (size_t)j * W + (size_t)k * HW, sizeof(float) * HW);
        const double g[6] = {gt[0] + k * HW * gt[1], gt[1], gt[2], gt[3], gt[4], gt[5]};
        EXPECT(gdal_fixture_write("GTiff", tpath(names[k]), HW, H, half, g, 32633, 1, ND,
                                  GDT_Float32) == 0);
        paths[k] = strdup(tpath(names[k]));
    }
    int bad = 0;
    GDALDatasetH v = GDALBuildVRT(tpath("dem.vrt"), 2, NULL, (const char *const *)paths, NULL,
                                  &bad);
    EXPECT(v && !bad, "GDALBuildVRT");
    if (v)
        GDALClose(v);
    free(paths[0]), free(paths[1]);
    EXPECT(run("tiles plan dem.vrt --product svf --tile 64 -o V " SVF_ARGS) == 0);
    EXPECT(run_jobs("V", 1, 6) == 0 && run("tiles merge V -o v.tif") == 0);
    long shade;
    EXPECT(same_values("v.tif", "a.tif", 1, 0, &shade) == 0);
}

/* GNU parallel runs the jobs: the mosaic is the sequential run's, bytes
 * and all; stopped after 2 jobs and resumed, the same. */
static void test_parallel(void)
{
    if (system("command -v parallel >/dev/null 2>&1")) {
        EXPECT(0, "GNU parallel is not installed (tools/install-deps.sh installs it)");
        return;
    }
    EXPECT(run("tiles plan dem.tif --product svf --tile 64 -o C " SVF_ARGS) == 0);
    char cmd[8192];
    snprintf(cmd, sizeof cmd, "cd %s && parallel -j2 --joblog C/log %s tiles run C/manifest {} "
             ":::: C/jobs >out.txt 2>err.txt", tmpdir, hfshade);
    EXPECT(system(cmd) == 0, "parallel");
    EXPECT(run("tiles merge C -o c.tif") == 0 && same_bytes("a.tif", "c.tif"),
          "GNU parallel's mosaic is not the sequential run's, byte for byte");
    EXPECT(run("tiles plan dem.tif --product svf --tile 64 -o D " SVF_ARGS) == 0);
    snprintf(cmd, sizeof cmd, "cd %s && head -2 D/jobs | parallel -j2 --joblog D/log %s tiles "
             "run D/manifest {} >out.txt 2>err.txt && parallel -j2 --resume-failed --joblog "
             "D/log %s tiles run D/manifest {} :::: D/jobs >>out.txt 2>>err.txt", tmpdir,
             hfshade, hfshade);
    EXPECT(system(cmd) == 0, "parallel --resume-failed");
    EXPECT(lines_of("D/log") == 7, "the joblog: a header and 6 jobs (%d lines)", lines_of("D/log"));
    EXPECT(run("tiles merge D -o d.tif") == 0 && same_bytes("a.tif", "d.tif"),
          "the resumed mosaic is not the sequential run's, byte for byte");
}

int main(int argc, char **argv)
{
    int rc = gis_cli_begin(argc, argv, "gis_tiles");
    if (rc)
        return rc;
    float z[W * H];
    terrain(z);
    const double gt[6] = {500000.0, 30.0, 0.0, 4100000.0, 0.0, -30.0};
    EXPECT(gdal_fixture_write("GTiff", tpath("dem.tif"), W, H, z, gt, 32633, 1, ND,
                             GDT_Float32) == 0);
    test_plan();
    test_run_merge();
    test_horizon();
    test_sun();
    test_render();
    test_vrt(z, gt);
    test_parallel();
    (void)gles_failed; /* the CPU reference only: no GL context needed */
    return gis_cli_end("gis_tiles");
}
