/*
 * test_cpu_render.c — hfs_cpu_render end to end:
 *   1. SPEC must-show: a flat plane under the uniform sky (c0 = sqrt(4 pi),
 *      grey) is 1 at every texel within 1e-4, for several sizes (2x2 and
 *      non-square 37x20 included), dx and zscale, on both visibility paths;
 *   2. a key light on a flat plane gives rho/pi * Le * E_cap exactly
 *      (ratio 1): zenith, straddling and below the horizon, tiny alpha; a
 *      light below the horizontal but above a tilted receiver's tangent
 *      plane keeps a well-defined ratio, one below the tangent plane gives 0;
 *   3. bit-identical output for 1, 2 and 3 threads;
 *   4. a tall wall between receiver and key light darkens the receiver
 *      (ratio < 0.2) while the lit side stays at the unshadowed value;
 *   5. rotating the terrain and every light by 90 degrees about +z rotates
 *      the image (env_rotate's sign and the swath azimuths);
 *   6. no NaN/Inf on hostile inputs; local lights refused; progress reported.
 */
#include "backends.h"
#include "field_geom.h"
#include "lights.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

static int failures;

#define CHECK(cond, ...) do { if (!(cond)) { failures++; printf("FAIL %s:%d: ", __FILE__, __LINE__); \
    printf(__VA_ARGS__); printf("\n"); } } while (0)

static const char *path_name(int path)
{
    return path == HFS_VIS_WEDGE_TABLE ? "tables" : "legendre";
}

static int render(const float *z, int w, int h, double dx, double zscale,
                  const hfs_lighting *l, const hfs_quality *q, hfs_image *img)
{
    hfs_field f = {.width = w, .height = h, .z = z, .dx = dx, .zscale = zscale};
    hfs_error err = {{0}};
    int rc = hfs_image_alloc(img, w, h, &err);
    if (rc == HFS_OK)
        rc = hfs_cpu_render(&f, l, q, img, NULL, NULL, &err);
    CHECK(rc == HFS_OK, "render %dx%d failed: %s", w, h, err.msg);
    return rc;
}

static void uniform_sky(hfs_lighting *l)
{
    hfs_lighting_defaults(l);
    l->has_env = 1;
    for (int c = 0; c < 3; ++c)
        l->env_sh[c][0] = sqrt(4.0 * PI);
}

static float *terrain(int w, int h, double amp)
{
    float *z = malloc((size_t)w * h * sizeof *z);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            z[j * w + i] = (float)(amp * (sin(i * 0.21) * cos(j * 0.17) + 0.5 * sin(i * 0.53 + j * 0.71)));
    return z;
}

static long count_nonfinite(const hfs_image *img)
{
    long n = 0;
    for (size_t i = 0; i < (size_t)img->width * img->height * 3; ++i)
        n += !isfinite(img->rgb[i]);
    return n;
}

static void test_flat_uniform_sky(void)
{
    const int sizes[][2] = {{37, 20}, {16, 16}, {2, 2}, {3, 50}, {64, 33}};
    const double dxs[3] = {1.0, 0.25, 30.0}, zss[3] = {1.0, 0.0, 1000.0};
    hfs_lighting l;
    uniform_sky(&l);
    for (int path = HFS_VIS_LEGENDRE; path <= HFS_VIS_WEDGE_TABLE; ++path)
        for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; ++s)
            for (int p = 0; p < 3; ++p) {
                /* The table path rebuilds its tables per render: one
                 * (dx, zscale) per size keeps the test fast. */
                if (path == HFS_VIS_WEDGE_TABLE && p != (int)(s % 3))
                    continue;
                const int w = sizes[s][0], h = sizes[s][1];
                float *z = malloc((size_t)w * h * sizeof *z);
                for (int q = 0; q < w * h; ++q)
                    z[q] = 7.25f;
                hfs_quality q;
                hfs_quality_defaults(&q);
                q.subsample = 1; /* the full-resolution reference (cpu_grid.h: 2, 4) */
                q.visibility = (hfs_visibility_path)path;
                q.threads = 2;
                hfs_image img;
                if (render(z, w, h, dxs[p], zss[p], &l, &q, &img) == HFS_OK) {
                    double worst = 0.0;
                    for (size_t i = 0; i < (size_t)w * h * 3; ++i)
                        worst = fmax(worst, fabs(img.rgb[i] - 1.0));
                    /* measured 0 (exact) in every case: bound 10 float ulps */
                    CHECK(worst < 1.2e-6, "%s flat %dx%d dx=%g zscale=%g: max |Lo - 1| = %g",
                          path_name(path), w, h, dxs[p], zss[p], worst);
                }
                hfs_image_free(&img);
                free(z);
            }
}

static void test_key_flat(void)
{
    const int w = 23, h = 17;
    float *z = malloc((size_t)w * h * sizeof *z);
    for (int q = 0; q < w * h; ++q)
        z[q] = -3.0f;
    const double lights[][3] = {   /* elev, alpha, phi */
        {0.6, 0.1, 0.7},           /* ordinary */
        {PI / 2, 0.2, 0.0},        /* at the zenith: full swath */
        {1.45, 0.15, 2.0},         /* disk covers the zenith */
        {0.05, 0.1, -1.0},         /* straddles the horizon */
        {-0.05, 0.1, 4.0},         /* centre below the horizon, part above */
        {-0.4, 0.1, 1.0},          /* entirely below: 0 */
        {0.8, 1e-6, 3.0},          /* tiny alpha */
        {0.3, 1.5, 5.0},           /* huge alpha (covers the zenith) */
    };
    for (int path = HFS_VIS_LEGENDRE; path <= HFS_VIS_WEDGE_TABLE; ++path)
        for (size_t t = 0; t < sizeof lights / sizeof lights[0]; ++t) {
            /* Tables are rebuilt per render: a representative subset. */
            if (path == HFS_VIS_WEDGE_TABLE && t != 0 && t != 1 && t != 4 && t != 6)
                continue;
            hfs_lighting l;
            hfs_lighting_defaults(&l);
            l.albedo = 0.8;
            l.n_key = 1;
            l.key[0] = (hfs_key_light){.phi = lights[t][2], .elev = lights[t][0],
                                       .alpha = lights[t][1], .radiance = {1.0f, 2.0f, 3.0f}};
            hfs_quality q;
            hfs_quality_defaults(&q);
            q.subsample = 1; /* the full-resolution reference (cpu_grid.h: 2, 4) */
            q.visibility = (hfs_visibility_path)path;
            hfs_image img;
            if (render(z, w, h, 1.0, 1.0, &l, &q, &img) != HFS_OK)
                continue;
            const double e = hfs_cap_irradiance(sin(lights[t][0]), lights[t][1]);
            double worst = 0.0;
            for (int i = 0; i < w * h; ++i)
                for (int c = 0; c < 3; ++c) {
                    const double want = 0.8 / PI * (c + 1.0) * e;
                    const double got = img.rgb[3 * i + c];
                    worst = fmax(worst, want > 0 ? fabs(got / want - 1.0) : fabs(got));
                }
            CHECK(worst < 1e-6, "%s key elev=%g alpha=%g: worst relative error %g (E_cap %g)",
                  path_name(path), lights[t][0], lights[t][1], worst, e);
            hfs_image_free(&img);
        }
    free(z);
}

/* A plane tilted 0.6435 rad (slope 0.75) down toward -x and a key light
 * from -x BELOW the horizontal plane (elevation -0.15) but above the tangent
 * plane: the unshadowed part is the exact cap irradiance, and the ratio stays
 * well-defined and near 1 (nothing blocks it; the pyramid's clamped borders
 * raise the downhill horizons by a few degrees, hence the 5% margin).  A light
 * below the tangent plane gives exactly 0. */
static void test_key_below_horizon(void)
{
    const int w = 48, h = 24;
    float *z = malloc((size_t)w * h * sizeof *z);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            z[j * w + i] = (float)(0.75 * i);
    for (int path = HFS_VIS_LEGENDRE; path <= HFS_VIS_WEDGE_TABLE; ++path) {
        hfs_lighting l;
        hfs_lighting_defaults(&l);
        l.n_key = 2;
        l.key[0] = (hfs_key_light){.phi = PI, .elev = -0.15, .alpha = 0.1, .radiance = {1, 1, 1}};
        l.key[1] = (hfs_key_light){.phi = PI, .elev = -0.8, .alpha = 0.1, .radiance = {0, 0, 0}};
        hfs_quality q;
        hfs_quality_defaults(&q);
        q.subsample = 1; /* the full-resolution reference (cpu_grid.h: 2, 4) */
        q.visibility = (hfs_visibility_path)path;
        hfs_image img;
        if (render(z, w, h, 1.0, 1.0, &l, &q, &img) == HFS_OK) {
            double n[3], d[3];
            hfs_field f = {.width = w, .height = h, .z = z, .dx = 1, .zscale = 1};
            hfs_field_normal(&f, 24, 12, n);
            hfs_dir(PI, -0.15, d);
            const double e = hfs_cap_irradiance(n[0] * d[0] + n[1] * d[1] + n[2] * d[2], 0.1) / PI;
            CHECK(e > 0.0, "light should be above the tangent plane");
            double lo = 1e9, hi = 0.0;
            for (int j = 4; j < h - 4; ++j)
                for (int i = 4; i < w - 4; ++i) {
                    lo = fmin(lo, img.rgb[3 * (j * w + i)] / e);
                    hi = fmax(hi, img.rgb[3 * (j * w + i)] / e);
                }
            CHECK(lo > 0.95 && hi < 1.0 + 1e-6, "%s: below-horizon key ratio in [%g, %g]", path_name(path), lo, hi);
            CHECK(count_nonfinite(&img) == 0, "non-finite output");
        }
        hfs_image_free(&img);
        /* Below the tangent plane: nothing at all. */
        l.key[0].elev = -0.8;
        if (render(z, w, h, 1.0, 1.0, &l, &q, &img) == HFS_OK) {
            double m = 0.0;
            for (int i = 0; i < w * h * 3; ++i)
                m = fmax(m, fabs(img.rgb[i]));
            CHECK(m == 0.0, "%s: light below the tangent plane gives %g", path_name(path), m);
        }
        hfs_image_free(&img);
    }
    free(z);
}

static void test_determinism(void)
{
    const int w = 45, h = 38;
    float *z = terrain(w, h, 6.0);
    hfs_lighting l;
    uniform_sky(&l);
    l.env_sh[0][2] = 1.5;
    l.env_sh[1][7] = -0.4;
    l.env_rotate = 0.3;
    l.n_key = 2;
    l.key[0] = (hfs_key_light){.phi = 0.4, .elev = 0.5, .alpha = 0.1, .radiance = {2, 2, 2}};
    l.key[1] = (hfs_key_light){.phi = 2.0, .elev = 1.5, .alpha = 0.2, .radiance = {1, 0, 3}};
    for (int path = HFS_VIS_LEGENDRE; path <= HFS_VIS_WEDGE_TABLE; ++path) {
        hfs_image img[3];
        int ok = 1;
        for (int t = 0; t < 3; ++t) {
            hfs_quality q;
            hfs_quality_defaults(&q);
            q.subsample = 1; /* the full-resolution reference (cpu_grid.h: 2, 4) */
            q.visibility = (hfs_visibility_path)path;
            q.threads = t + 1;
            ok &= render(z, w, h, 1.0, 1.0, &l, &q, &img[t]) == HFS_OK;
        }
        if (ok) {
            const size_t bytes = (size_t)w * h * 3 * sizeof(float);
            CHECK(memcmp(img[0].rgb, img[1].rgb, bytes) == 0 && memcmp(img[0].rgb, img[2].rgb, bytes) == 0,
                  "%s: output depends on the thread count", path_name(path));
            CHECK(count_nonfinite(&img[0]) == 0, "non-finite output");
        }
        for (int t = 0; t < 3; ++t)
            hfs_image_free(&img[t]);
    }
    free(z);
}

static void test_wall(void)
{
    const int w = 64, h = 48;
    float *z = calloc((size_t)w * h, sizeof *z);
    for (int j = 0; j < h; ++j)
        for (int i = 30; i <= 37; ++i)
            z[j * w + i] = 40.0f;
    /* Light from +x, 30 degrees up; the wall (70 to 81 degrees seen from
     * i = 16..24) stands between it and the west side.  (The pyramid blurs a
     * wall with distance, by design: from i = 0 it sees 34 of the exact 53
     * degrees, so the test stays within a wall's height of it.) */
    const double elev = PI / 6, alpha = 5.0 * PI / 180;
    for (int path = HFS_VIS_LEGENDRE; path <= HFS_VIS_WEDGE_TABLE; ++path) {
        hfs_lighting l;
        hfs_lighting_defaults(&l);
        l.n_key = 1;
        l.key[0] = (hfs_key_light){.phi = 0.0, .elev = elev, .alpha = alpha, .radiance = {1, 1, 1}};
        hfs_quality q;
        hfs_quality_defaults(&q);
        q.subsample = 1; /* the full-resolution reference (cpu_grid.h: 2, 4) */
        q.visibility = (hfs_visibility_path)path;
        hfs_image img;
        if (render(z, w, h, 1.0, 1.0, &l, &q, &img) != HFS_OK)
            continue;
        const double open = hfs_cap_irradiance(sin(elev), alpha) / PI;
        for (int i = 16; i <= 24; i += 4) {
            const double r = img.rgb[3 * (24 * w + i)] / open;
            CHECK(r < 0.2, "%s: receiver at i=%d behind the wall has ratio %g", path_name(path), i, r);
        }
        for (int i = 44; i <= 60; i += 8) {
            const double r = img.rgb[3 * (24 * w + i)] / open;
            CHECK(r > 0.99 && r < 1.0 + 1e-6, "%s: lit side i=%d has ratio %g", path_name(path), i, r);
        }
        hfs_image_free(&img);
    }
    free(z);
}

static void test_rotation(void)
{
    const int n = 40;
    float *z = terrain(n, n, 5.0), *zr = malloc((size_t)n * n * sizeof *zr);
    /* +90 degrees about +z: (i, j) -> (n-1-j, i). */
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            zr[i * n + (n - 1 - j)] = z[j * n + i];
    hfs_lighting l;
    uniform_sky(&l);
    l.env_sh[0][3] = 1.2;   /* x lobe  */
    l.env_sh[1][1] = -0.7;  /* y lobe  */
    l.env_sh[2][8] = 0.5;   /* x2 - y2 */
    l.env_rotate = 0.2;
    l.n_key = 1;
    l.key[0] = (hfs_key_light){.phi = 0.3, .elev = 0.6, .alpha = 0.15, .radiance = {1, 2, 1}};
    hfs_lighting lr = l;
    lr.env_rotate += PI / 2;
    lr.key[0].phi += PI / 2;
    for (int path = HFS_VIS_LEGENDRE; path <= HFS_VIS_WEDGE_TABLE; ++path) {
        hfs_quality q;
        hfs_quality_defaults(&q);
        q.subsample = 1; /* the full-resolution reference (cpu_grid.h: 2, 4) */
        q.visibility = (hfs_visibility_path)path;
        hfs_image a, b;
        if (render(z, n, n, 1.0, 1.0, &l, &q, &a) == HFS_OK &&
            render(zr, n, n, 1.0, 1.0, &lr, &q, &b) == HFS_OK) {
            double worst = 0.0;
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i)
                    for (int c = 0; c < 3; ++c)
                        worst = fmax(worst, fabs(a.rgb[3 * (j * n + i) + c] -
                                                 b.rgb[3 * (i * n + n - 1 - j) + c]));
            /* measured 0 (exact) on both paths: bound 10 float ulps */
            CHECK(worst < 1.2e-6, "%s: rotated scene differs by %g", path_name(path), worst);
        }
        hfs_image_free(&a);
        hfs_image_free(&b);
    }
    free(z);
    free(zr);
}

typedef struct progress_log {
    int calls;
    double last;
    int monotone;
} progress_log;

static void on_progress(void *user, double fraction)
{
    progress_log *p = user;
    p->monotone &= fraction >= p->last;
    p->last = fraction;
    p->calls++;
}

static void test_hostile_and_api(void)
{
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.subsample = 1; /* the full-resolution reference (cpu_grid.h: 2, 4) */
    hfs_error err = {{0}};
    /* Tall spiky terrain, tiny field, lights at the limits. */
    const int sizes[][2] = {{2, 2}, {2, 9}, {31, 3}};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; ++s) {
        const int w = sizes[s][0], h = sizes[s][1];
        float *z = malloc((size_t)w * h * sizeof *z);
        for (int i = 0; i < w * h; ++i)
            z[i] = (i * 7919 % 13) * 1000.0f - 5000.0f;
        hfs_lighting l;
        uniform_sky(&l);
        l.env_sh[0][5] = 3.0;
        /* zenith, nadir, horizon, just above it with a minute disk, and
         * disks so small their swath width nearly / fully underflows */
        const double el[6] = {PI / 2, -PI / 2, 0.0, 1e-9, 0.5, 0.5};
        const double al[6] = {0.3, 0.3, 0.3, 1e-12, 1e-150, 1e-200};
        l.n_key = 6;
        for (int k = 0; k < 6; ++k)
            l.key[k] = (hfs_key_light){.phi = k, .elev = el[k], .alpha = al[k],
                                       .radiance = {1, 1, 1}};
        for (int path = HFS_VIS_LEGENDRE; path <= (s == 0 ? HFS_VIS_WEDGE_TABLE : HFS_VIS_LEGENDRE); ++path) {
            q.visibility = (hfs_visibility_path)path;
            hfs_image img;
            if (render(z, w, h, 0.01, 1e6, &l, &q, &img) == HFS_OK)
                CHECK(count_nonfinite(&img) == 0, "%dx%d: non-finite output", w, h);
            hfs_image_free(&img);
        }
        free(z);
    }

    float z[16] = {0};
    hfs_field f = {.width = 4, .height = 4, .z = z, .dx = 1, .zscale = 1};
    hfs_image img;
    hfs_image_alloc(&img, 4, 4, &err);
    hfs_lighting l;
    uniform_sky(&l);
    l.n_local = 1;
    l.local[0] = (hfs_local_light){.pos = {1, 1, 5}, .radius = 1, .radiance = {1, 1, 1}};
    int rc = hfs_cpu_render(&f, &l, &q, &img, NULL, NULL, &err);
    int finite = 1;
    for (int k = 0; k < 4 * 4 * 3; ++k)
        finite &= isfinite(img.rgb[k]);
    CHECK(rc == HFS_OK && finite, "local light: rc=%d msg=%s finite=%d", rc, err.msg, finite);
    l.local[0].disabled = 1;
    CHECK(hfs_cpu_render(&f, &l, &q, &img, NULL, NULL, &err) == HFS_OK, "disabled local light refused");
    l.local[0].disabled = 0;
    l.local[0].radiance[0] = l.local[0].radiance[1] = l.local[0].radiance[2] = 0.0f;
    progress_log p = {0, 0.0, 1};
    CHECK(hfs_cpu_render(&f, &l, &q, &img, on_progress, &p, &err) == HFS_OK, "dark local light refused");
    CHECK(p.calls >= 2 && p.last == 1.0 && p.monotone, "progress: %d calls, last %g", p.calls, p.last);
    /* No light at all: black, not an error. */
    hfs_lighting_defaults(&l);
    for (int i = 0; i < 48; ++i)
        img.rgb[i] = 5.0f;
    CHECK(hfs_cpu_render(&f, &l, &q, &img, NULL, NULL, &err) == HFS_OK && img.rgb[0] == 0.0f &&
          img.rgb[47] == 0.0f, "no lights: not black");
    hfs_image_free(&img);
}

int main(void)
{
    test_flat_uniform_sky();
    test_key_flat();
    test_key_below_horizon();
    test_determinism();
    test_wall();
    test_rotation();
    test_hostile_and_api();
    if (failures) {
        printf("%d failure(s)\n", failures);
        return 1;
    }
    printf("test_cpu_render: all passed\n");
    return 0;
}
