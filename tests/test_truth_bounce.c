/*
 * test_truth_bounce.c — indirect light in the ground truth (truth_bounce.h)
 * and the first-hit rays it casts, against independent answers:
 *   first_hit   hfs_truth_ray_first_hit: hits exactly when
 *               hfs_truth_ray_hits does, the ray at or below the surface at
 *               t (or starting below it), above it at 400 samples before t
 *   flat        a plane gets no indirect light: bounces = 2 is bounces = 0
 *               bit for bit
 *   wall        a floor beside a long wall of uniform exit radiance Lw:
 *               Lo_1 = rho Lw F, F the view factor from the floor point to
 *               the wall.  Infinite wall at distance D, height Hw:
 *               F = (1 - D / sqrt(D^2 + Hw^2)) / 2 (2-D: the strings rule,
 *               F = (sin b2 - sin b1) / 2 with b the angles from the
 *               normal to the wall's foot (90 degrees) and top).  The
 *               bilinear step makes the wall a ramp one texel wide from
 *               the last floor texel to the first wall texel; its foot lies
 *               in the receiver's horizontal plane like a vertical wall's,
 *               so it subtends exactly a vertical wall at the TOP edge's
 *               distance: D = that distance (one texel more than the
 *               foot's).  The finite grid shortens the wall: the expected
 *               value is the view factor to the finite rectangle (Lambert's
 *               polygon formula, computed here), printed beside the
 *               infinite one.  Bound: 2 sigma of an unstratified estimate
 *               (the stratified one measures within 0.2 sigma).
 *   furnace     a closed V-groove, albedo 1 under a uniform sky of 1:
 *               every bounce >= 0 and direct + 3 bounces <= 1 + the
 *               sampling error (below) at every texel
 */
#include "backends.h"
#include "bounce_scenes.h"
#include "field_geom.h"
#include "test_util.h"
#include "truth_bounce.h"
#include "truth_raycast.h"

#include <float.h>
#include <math.h>

#define PI 3.14159265358979323846

static uint64_t seed = 0x2545f4914f6cdd1dULL;
static double urand(void)
{
    seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(seed >> 11) * (1.0 / 9007199254740992.0);
}

static double ray_minus_surface(const hfs_field *f, const double o[3], const double d[3], double t)
{
    double z;
    if (!hfs_field_bilinear(f, o[0] + t * d[0] / f->dx, o[1] + t * d[1] / f->dx, &z))
        return INFINITY;
    return o[2] + t * d[2] - z;
}

static void test_first_hit(void)
{
    const int w = 24, h = 20;
    float *z = malloc((size_t)w * h * sizeof *z);
    for (int k = 0; k < w * h; ++k)
        z[k] = (float)(4.0 * urand());
    const hfs_field f = {w, h, z, 0.5, 1.0};
    hfs_truth_grid g;
    REQUIRE(hfs_truth_grid_init(&g, &f) == HFS_OK, "grid");
    int hits = 0;
    for (int r = 0; r < 3000; ++r) {
        const double o[3] = {1 + (w - 3) * urand(), 1 + (h - 3) * urand(), 4.5 * urand()};
        const double e = (urand() - 0.3) * PI / 2, a = 2 * PI * urand();
        const double d[3] = {cos(e) * cos(a), cos(e) * sin(a), sin(e)};
        double t = -1.0;
        const int hit = hfs_truth_ray_first_hit(&g, o, d, INFINITY, &t);
        REQUIRE(hit == hfs_truth_ray_hits(&g, o, d, INFINITY), "ray %d: first_hit %d", r, hit);
        if (!hit)
            continue;
        ++hits;
        REQUIRE(t >= 0.0 && ray_minus_surface(&f, o, d, t) <= 1e-9, "ray %d: above at t %.9g", r,
                t);
        for (int k = 0; k < 400 && t > 0.0; ++k) {
            const double tk = t * k / 400.0;
            REQUIRE(ray_minus_surface(&f, o, d, tk) > -1e-9, "ray %d: below at %.9g < t %.9g", r,
                    tk, t);
        }
    }
    hfs_truth_grid_free(&g);
    free(z);
    printf("first_hit: 3000 rays, %d hits, each the first crossing\n", hits);
}

/* Render through the truth backend with `bounces`. */
static void render(const hfs_field *f, hfs_lighting *l, int bounces, int samples, float *out)
{
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.truth_light_samples = samples;
    l->bounces = bounces;
    hfs_image img = {f->width, f->height, out};
    hfs_error err = {""};
    if (hfs_truth_render(f, l, &q, &img, NULL, NULL, &err) != HFS_OK) {
        fprintf(stderr, "truth: %s\n", err.msg);
        exit(1);
    }
}


static void test_flat(void)
{
    const int w = 12, h = 9;
    float *z = calloc((size_t)w * h, sizeof *z), *a = malloc(sizeof(float) * w * h * 3),
          *b = malloc(sizeof(float) * w * h * 3);
    const hfs_field f = {w, h, z, 1.0, 1.0};
    hfs_lighting l = bounce_uniform_sky();
    render(&f, &l, 0, 16, a);
    render(&f, &l, 2, 16, b);
    CHECK(!memcmp(a, b, sizeof(float) * w * h * 3));
    printf("flat: no indirect light, bit for bit\n");
    free(z), free(a), free(b);
}


static void test_wall(void)
{
    const int w = 120, h = 401, X = 100; /* wall texels x >= X, height Hw */
    const double hw = 20.0, lw = 2.0, rho = 0.75;
    float *z, *prev;
    bounce_wall(w, h, X, hw, lw, &z, &prev);
    const hfs_field f = {w, h, z, 1.0, 1.0};
    hfs_truth_grid g;
    REQUIRE(hfs_truth_grid_init(&g, &f) == HFS_OK, "grid");
    const int samples = 128 * 128, jc = h / 2;
    const hfs_truth_bounce_in in = {&g, prev, rho, NULL, samples, 1, 1, NULL};
    const int foot[5] = {2, 4, 8, 16, 40};
    for (int k = 0; k < 5; ++k) {
        const int i = X - 1 - foot[k];
        const double D = X - i;
        const double F = bounce_wall_view_factor(i, jc, h, X, hw);
        const double F_inf = 0.5 * (1.0 - D / sqrt(D * D + hw * hw));
        double lo[3];
        hfs_truth_bounce_at(&in, i, jc, lo);
        const double got = lo[0] / (rho * lw), sigma = sqrt(F * (1.0 - F) / samples);
        printf("wall: D %4.0f  F %.5f (infinite wall %.5f)  truth %.5f  (%+.1f sigma)\n", D, F,
               F_inf, got, (got - F) / sigma);
        CHECK(fabs(got - F) <= 2.0 * sigma && lo[0] == lo[1] && lo[1] == lo[2]);
    }
    hfs_truth_grid_free(&g);
    free(z), free(prev);
}

static void test_furnace(void)
{
    const int w = 33, h = 48, samples = 256;
    float *z = bounce_groove(w, h);
    const hfs_field f = {w, h, z, 1.0, 1.0};
    hfs_lighting l = bounce_uniform_sky();
    float *lo[4];
    for (int b = 0; b < 4; ++b) {
        lo[b] = malloc(sizeof(float) * w * h * 3);
        render(&f, &l, b, samples, lo[b]);
    }
    /* The direct part comes from exact horizons, each bounce's hit fraction
     * from its own stratified rays: an indicator with a smooth boundary
     * sampled on a k x k grid errs by about N^(-3/4), and three bounces add
     * three such errors (measured: 1.0101 at the grid's rim, where the
     * one-sided normal tilts the lobe past the border). */
    const double tol = 3.0 * pow((double)samples, -0.75);
    double worst_total, worst_neg;
    bounce_furnace(lo, (size_t)w * h * 3, &worst_neg, &worst_total);
    CHECK(worst_neg >= 0.0);
    CHECK(worst_total <= 1.0 + tol);
    printf("furnace: V-groove, albedo 1, sky 1: every bounce >= 0 (min %.2e), "
           "direct + 3 bounces <= %.4f (bound 1 + %.3f)\n", worst_neg, worst_total, tol);
    for (int b = 0; b < 4; ++b)
        free(lo[b]);
    free(z);
}

int main(void)
{
    test_first_hit();
    test_flat();
    test_wall();
    test_furnace();
    return finish_checks("test_truth_bounce");
}
