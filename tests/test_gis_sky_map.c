/*
 * test_gis_sky_map.c — insolation's sky from a map (tools/gis/gis_sky_map.h;
 * `hfshade insolation --sky-map`), no GDAL, no GL:
 *   uniform   a map of one radiance gives the isotropic sky's share
 *             (gis_sky_add) at random normals and horizons, to rounding;
 *             open flat ground gets 1 under any map;
 *   oracle    a sky that varies in azimuth and elevation, at random
 *             normals under random horizons per azimuth: the share against
 *             a brute-force sum over the map's own pixels (each split into
 *             sub-pixels; max(0, n.w) cos e where the direction is above
 *             the horizontal and its sector's horizon), which shares no
 *             code with the closed form;
 *   north     the map's left edge at compass north_deg: a map whose column
 *             i is column i + W/4 of another, with north_deg 90, is the same
 *             sky and gives the same shares; a sky bright in the north gives a north-facing slope
 *             (SPEC phi -90 deg on a north-up grid) more than 1 and a
 *             south-facing one less;
 *   refused   a negative pixel of the upper half, a black upper half (the
 *             lower half is not read: negative there is accepted).
 */
#include "check.h"
#include "gis_math.h"
#include "gis_products.h"
#include "gis_sky_map.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

static double urand(void)
{
    return rand() / (double)RAND_MAX;
}

/* A unit normal tilted by up to max_tilt radians in a random direction. */
static void random_normal(double max_tilt, float n[3])
{
    const double s = urand() * max_tilt, a = urand() * 2.0 * PI;
    n[0] = (float)(sin(s) * cos(a)), n[1] = (float)(sin(s) * sin(a)), n[2] = (float)cos(s);
}

/* The share at one texel: gamma[k] its horizon in azimuth k. */
static double map_share(const gis_sky_map *m, const double *phi, const float n[3],
                        const float *gamma)
{
    double acc = 0.0;
    for (int k = 0; k < m->n_dirs; ++k)
        gis_sky_map_add(m, k, phi[k], &acc, &gamma[k], n, 1);
    float out;
    gis_sky_map_finish(m, &out, &acc, 1);
    return out;
}

static double iso_share(const double *phi, int n_dirs, const float n[3], const float *gamma)
{
    double acc = 0.0;
    for (int k = 0; k < n_dirs; ++k)
        gis_sky_add(&acc, &gamma[k], n, 1, phi[k]);
    float out;
    gis_sky_finish(&out, &acc, 1, n_dirs);
    return out;
}

/* The grid's azimuths of the sky's horizons: the map's own
 * (gis_product_directions; the tests' grid is north-up, east-running). */
static void directions(double *phi, int n)
{
    gis_product_directions(phi, n);
}

static void test_uniform(void)
{
    enum { W = 40, H = 21, K = 24 };
    float *rgb = malloc(sizeof(float) * W * H * 3);
    for (int i = 0; i < W * H * 3; ++i)
        rgb[i] = 0.7f;
    double phi[K];
    directions(phi, K);
    gis_sky_map m;
    hfs_error err = {{0}};
    CHECK(gis_sky_map_make(rgb, W, H, 33.0, K, "uniform", &m, &err) == 0, "%s", err.msg);
    srand(11);
    double worst = 0.0;
    float g[K], flat[3] = {0.0f, 0.0f, 1.0f};
    for (int k = 0; k < K; ++k)
        g[k] = HFS_HORIZON_NONE;
    CHECK(fabs(map_share(&m, phi, flat, g) - 1.0) < 1e-7, "open flat ground: 1");
    for (int t = 0; t < 500; ++t) {
        float n[3];
        random_normal(1.3, n);
        for (int k = 0; k < K; ++k)
            g[k] = (float)((urand() - 0.3) * 0.5 * PI);
        worst = fmax(worst, fabs(map_share(&m, phi, n, g) - iso_share(phi, K, n, g)));
    }
    CHECK(worst < 1e-6, "a uniform map is the isotropic sky: worst %.2e", worst);
    gis_sky_map_free(&m);
    free(rgb);
}

/* The test sky: brighter towards compass 30 degrees and towards the
 * horizon, a bright band at 20-30 degrees of elevation, in RGB. */
static void test_sky(float *rgb, int w, int h)
{
    for (int r = 0; r < h; ++r)
        for (int i = 0; i < w; ++i) {
            const double compass = 360.0 * (i + 0.5) / w, e = 0.5 * PI - PI * (r + 0.5) / h;
            const double az = 1.0 + 3.0 * fmax(0.0, cos((compass - 30.0) * PI / 180.0));
            const double el = 1.0 + 2.0 * cos(e) * cos(e) + (e > 0.35 && e < 0.52 ? 4.0 : 0.0);
            float *p = rgb + 3 * ((size_t)r * (size_t)w + (size_t)i);
            p[0] = (float)(az * el), p[1] = (float)(0.8 * az * el), p[2] = (float)(1.5 * el);
        }
}

/* The brute force's sub-pixels a map pixel: sub_az in azimuth, sub_el in
 * elevation (`test_gis_sky_map fine`: 4x each, to see its own error). */
static int sub_az = 8, sub_el = 64;

/* The brute force: E over the map's pixels above the horizontal, each cut
 * into sub_az x sub_el sub-pixels; a sub-pixel's direction phi (SPEC, the
 * grid's = the map's) falls in the sector of the nearest of the K
 * directions, open when above that sector's horizon. */
static double brute_e(const float *rgb, int w, int h, double north_deg, int K, const double *phi,
                      const float n[3], const float *gamma)
{
    double e_sum = 0.0;
    for (int r = 0; r < (h + 1) / 2; ++r)
        for (int i = 0; i < w; ++i) {
            const float *p = rgb + 3 * ((size_t)r * (size_t)w + (size_t)i);
            const double lum = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
            for (int a = 0; a < sub_az; ++a) {
                const double compass = north_deg + 360.0 * (i + (a + 0.5) / sub_az) / w;
                const double ph = (compass - 90.0) * PI / 180.0;
                const double sector = remainder(phi[1] - phi[0], 2.0 * PI); /* signed */
                int k = (int)floor(remainder(ph - phi[0], 2.0 * PI) / sector + 0.5);
                k = ((k % K) + K) % K;
                for (int b = 0; b < sub_el; ++b) {
                    const double e = 0.5 * PI - PI * (r + (b + 0.5) / sub_el) / h;
                    if (e <= 0.0 || e <= (double)gamma[k])
                        continue;
                    const double d = n[0] * cos(ph) * cos(e) + n[1] * sin(ph) * cos(e) +
                                     n[2] * sin(e);
                    e_sum += lum * fmax(d, 0.0) * cos(e);
                }
            }
        }
    return e_sum;
}

static void test_oracle(void)
{
    enum { W = 96, H = 48, K = 96 };
    float *rgb = malloc(sizeof(float) * W * H * 3);
    test_sky(rgb, W, H);
    double phi[K];
    directions(phi, K);
    const double north = 17.0;
    gis_sky_map m;
    hfs_error err = {{0}};
    CHECK(gis_sky_map_make(rgb, W, H, north, K, "test sky", &m, &err) == 0, "%s", err.msg);
    float g[K], up[3] = {0.0f, 0.0f, 1.0f};
    for (int k = 0; k < K; ++k)
        g[k] = HFS_HORIZON_NONE;
    const double open = brute_e(rgb, W, H, north, K, phi, up, g);
    srand(5);
    double worst = 0.0, mean = 0.0;
    const int trials = 24;
    for (int t = 0; t < trials; ++t) {
        float n[3];
        random_normal(1.2, n);
        const double base = (urand() - 0.2) * 0.6;
        for (int k = 0; k < K; ++k)
            g[k] = (float)(base + 0.3 * sin(3.0 * phi[k] + t) * urand());
        const double want = brute_e(rgb, W, H, north, K, phi, n, g) / open;
        const double got = map_share(&m, phi, n, g), d = fabs(got - want);
        worst = fmax(worst, d), mean += d / trials;
    }
    /* measured 3.04e-4 worst, 7.05e-5 mean, mostly the brute force's own
     * midpoint rule where a horizon or the tangent plane cuts a pixel: at
     * 32 x 256 sub-pixels (`test_gis_sky_map fine`) it is 6.7e-5 / 1.9e-5,
     * what remains being the sector's one azimuth for n.w across its width
     * (3.75 degrees) */
    printf("the map's sky against the brute force (%d x %d sub-pixels): worst %.2e, mean "
           "%.2e\n", sub_az, sub_el, worst, mean);
    CHECK(worst < 3.65e-4 && mean < 8.5e-5, "the map's sky against the brute force: worst %.2e, "
          "mean %.2e", worst, mean);
    gis_sky_map_free(&m);
    free(rgb);
}

static void test_north(void)
{
    enum { W = 64, H = 32, K = 16 };
    float *rgb = malloc(sizeof(float) * W * H * 3), *turned = malloc(sizeof(float) * W * H * 3);
    test_sky(rgb, W, H);
    /* turned: column i of it is column i + W/4 of rgb (90 degrees on) */
    for (int r = 0; r < H; ++r)
        for (int i = 0; i < W; ++i)
            memcpy(turned + 3 * (r * W + i), rgb + 3 * (r * W + (i + W / 4) % W),
                   3 * sizeof(float));
    double phi[K];
    directions(phi, K);
    gis_sky_map a, b;
    hfs_error err = {{0}};
    CHECK(gis_sky_map_make(rgb, W, H, 0.0, K, "a", &a, &err) == 0, "%s", err.msg);
    CHECK(gis_sky_map_make(turned, W, H, 90.0, K, "b", &b, &err) == 0, "%s", err.msg);
    srand(3);
    double worst = 0.0;
    float g[K];
    for (int t = 0; t < 100; ++t) {
        float n[3];
        random_normal(1.2, n);
        for (int k = 0; k < K; ++k)
            g[k] = (float)((urand() - 0.3) * 0.8);
        worst = fmax(worst, fabs(map_share(&a, phi, n, g) - map_share(&b, phi, n, g)));
    }
    CHECK(worst < 1e-6, "a map turned a quarter, its north with it: worst %.2e", worst);
    gis_sky_map_free(&a);
    gis_sky_map_free(&b);
    /* a sky bright in the north: 10 within 45 degrees of north, 1 elsewhere */
    for (int r = 0; r < H; ++r)
        for (int i = 0; i < W; ++i) {
            const double c = 360.0 * (i + 0.5) / W;
            for (int ch = 0; ch < 3; ++ch)
                rgb[3 * (r * W + i) + ch] = c < 45.0 || c > 315.0 ? 10.0f : 1.0f;
        }
    CHECK(gis_sky_map_make(rgb, W, H, 0.0, K, "north", &a, &err) == 0, "%s", err.msg);
    for (int k = 0; k < K; ++k)
        g[k] = HFS_HORIZON_NONE;
    const double s = 0.5; /* slopes of 0.5 rad facing north (phi -90 deg) and south */
    const float fn[3] = {0.0f, (float)-sin(s), (float)cos(s)};
    const float fs[3] = {0.0f, (float)sin(s), (float)cos(s)};
    const double north = map_share(&a, phi, fn, g), south = map_share(&a, phi, fs, g);
    CHECK(north > 1.0 && south < (1.0 + cos(s)) / 2.0, "north-facing %.4f > 1, south-facing "
          "%.4f < the isotropic %.4f", north, south, (1.0 + cos(s)) / 2.0);
    gis_sky_map_free(&a);
    free(turned);
    free(rgb);
}

static void test_refused(void)
{
    enum { W = 8, H = 6, K = 4 };
    float rgb[W * H * 3];
    double phi[K];
    directions(phi, K);
    gis_sky_map m;
    hfs_error err = {{0}};
    for (int i = 0; i < W * H * 3; ++i)
        rgb[i] = i < W * (H / 2) * 3 ? 0.0f : -1.0f; /* black sky, negative ground */
    CHECK(gis_sky_map_make(rgb, W, H, 0.0, K, "dark.exr", &m, &err) != 0 &&
          strstr(err.msg, "dark.exr") && strstr(err.msg, "black"), "a black sky: %s", err.msg);
    rgb[3 * (W + 2) + 1] = 1.0f;
    CHECK(gis_sky_map_make(rgb, W, H, 0.0, K, "g.exr", &m, &err) == 0,
          "the lower half is not read: %s", err.msg);
    gis_sky_map_free(&m);
    rgb[3 * (2 * W + 5)] = -0.5f;
    CHECK(gis_sky_map_make(rgb, W, H, 0.0, K, "neg.exr", &m, &err) != 0 &&
          strstr(err.msg, "neg.exr") && strstr(err.msg, "(5, 2)") &&
          strstr(err.msg, "negative"), "a negative pixel: %s", err.msg);
}

int main(int argc, char **argv)
{
    if (argc > 1 && !strcmp(argv[1], "fine"))
        sub_az *= 4, sub_el *= 4;
    test_uniform();
    test_oracle();
    test_north();
    test_refused();
    if (failures) {
        fprintf(stderr, "test_gis_sky_map: %d of %ld checks failed\n", failures, checks);
        return 1;
    }
    printf("test_gis_sky_map: %ld checks passed\n", checks);
    return 0;
}
