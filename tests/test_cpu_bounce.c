/*
 * test_cpu_bounce.c — indirect light in the CPU reference (cpu_bounce.h):
 *   flat      a plane casts no band: bounces = 2 is bounces = 0 bit for bit
 *   wall      a floor beside a long wall of uniform exit radiance Lw (as
 *             test_truth_bounce: the view factor to the wall, the bilinear
 *             ramp subtending a vertical wall at its top edge, the finite
 *             wall by Lambert's polygon formula): the slices' bands within
 *             the bound below of rho Lw F, never above it
 *   pit       a pit a texel wide, dark at its bottom: the bottom gathers
 *             its own walls' light (the walls meet every ray below their
 *             slope at once), not the lit rim's (issue 36)
 *   furnace   a V-groove, albedo 1, sky 1: every bounce >= 0 exactly (band
 *             weights and radiances are >= 0, no order-4 ringing) and
 *             direct + 3 bounces <= 1 + 1e-9
 *   truth     cones 48^2, sky + sun, one bounce: the indirect part's mean
 *             error against the truth's, relative to the truth's largest
 *             indirect value, within the bound below; diffuse, and glossy
 *             (albedo 0.1 + ks 0.9: the receivers' lobe over the bands
 *             against the truth's lobe samples)
 *   furnace   also glossy (albedo 0.6 + ks 0.4, S 8): >= 0 and <= 1 within
 *             the bound below
 */
#include "backends.h"
#include "bounce_scenes.h"
#include "cpu_bounce.h"
#include "lights.h"
#include "test_util.h"

#include <math.h>

#define PI 3.14159265358979323846

typedef int (*hfs_backend_fn)(const hfs_field *, const hfs_lighting *, const hfs_quality *,
                              hfs_image *, hfs_progress_fn, void *, hfs_error *);

static void render(hfs_backend_fn fn, const hfs_field *f, hfs_lighting *l, int bounces,
                   float *out);


static void test_flat(void)
{
    const int w = 12, h = 9;
    float *z = calloc((size_t)w * h, sizeof *z), *a = malloc(sizeof(float) * w * h * 3),
          *b = malloc(sizeof(float) * w * h * 3);
    const hfs_field f = {w, h, z, 1.0, 1.0};
    hfs_lighting l = bounce_uniform_sky();
    render(hfs_cpu_render, &f, &l, 0, a);
    render(hfs_cpu_render, &f, &l, 2, b);
    CHECK(!memcmp(a, b, sizeof(float) * w * h * 3));
    printf("flat: no indirect light, bit for bit\n");
    free(z), free(a), free(b);
}


/* Bound: the bands stop at the direct light's horizons (energy), which
 * sample the distance at the scales refined about their max (k2 o8), and
 * the azimuth at 12 slices (at D = 3 the wall's elevation falls steeply
 * near the azimuth along it).  Since issue 36 they are the direct light's
 * split horizons at the defaults (subsample 2: the near part refined with
 * 2 samples up to 16 texels, the far part on the 8-step grid), as the
 * frame without bounces has them, not one horizon refined with 4: the
 * wall's top just beyond 16 texels comes from far occluders blended
 * between grid receivers 8 apart, seen lower.  Measured, always low:
 * 7.4%, 4.2%, 10.5%, 12.7%, 8.4% of F at D = 3, 5, 9, 17, 41 (one
 * horizon: 7.2%, 4.7%, 1.8%, 8.0%, 9.5%, bound 12%); bound 15%, 1.2x the
 * worst.  (Without the cap the bands reach 0.7-7%, but direct + bounces
 * then exceed 1 by 3% in the furnace below.) */
#define WALL_REL 0.15

static void test_wall(void)
{
    const int w = 120, h = 401, X = 100;
    const double hw = 20.0, lw = 2.0, rho = 0.75;
    float *z, *lo;
    bounce_wall(w, h, X, hw, lw, &z, &lo);
    const hfs_field f = {w, h, z, 1.0, 1.0};
    hfs_lighting l = bounce_uniform_sky();
    l.albedo = rho;
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.subsample = 1; /* the full-resolution reference (cpu_grid.h: 2, 4) */
    float *direct = malloc(sizeof(float) * w * h * 3);
    memcpy(direct, lo, sizeof(float) * w * h * 3);
    hfs_error err = {""};
    REQUIRE(hfs_cpu_bounces(&f, &l, &q, 1, lo, NULL, NULL, &err) == HFS_OK, "%s", err.msg);
    const int jc = h / 2, foot[5] = {2, 4, 8, 16, 40};
    double worst = 0.0;
    for (int k = 0; k < 5; ++k) {
        const int i = X - 1 - foot[k];
        const double D = X - i;
        const double F = bounce_wall_view_factor(i, jc, h, X, hw);
        const size_t p = 3 * ((size_t)jc * w + i);
        const double got = (lo[p] - direct[p]) / (rho * lw);
        printf("wall: D %4.0f  F %.5f  cpu %.5f  (%+.2f%%)\n", D, F, got, 100 * (got / F - 1));
        worst = fmax(worst, fabs(got / F - 1));
        CHECK(got <= F * (1.0 + 1e-6)); /* capped at the direct horizon: never above */
    }
    CHECK(worst <= WALL_REL);
    free(z), free(lo), free(direct);
}

/* A pit a texel wide (its bottom 3 below the flat ground around it), lit
 * 0 at the bottom and 1 everywhere else (the exit radiance given, as the
 * wall's): from the bottom every ray below the pit's walls' slope meets
 * the wall at once (the bilinear surface rises from the receiver at slope
 * 3 along every axis, 3 and 3 / sqrt(2)-ish along the diagonals' near
 * end), where the radiance is the bottom's own, 0; above the walls nothing
 * is seen but the sky.  So the bottom gathers almost nothing (issue 36:
 * the walk lit the wall's band with its far edge, the lit rim, and
 * gathered 0.93 of rho Lw).  Measured 0; bound 1e-3 of rho Lw. */
#define PIT_MAX 1e-3

static void test_pit(void)
{
    const int w = 9, h = 9, c = 4;
    float *z = calloc((size_t)w * h, sizeof *z), *lo = malloc(sizeof(float) * w * h * 3);
    z[c * w + c] = -3.0f;
    for (int p = 0; p < w * h * 3; ++p)
        lo[p] = p / 3 == c * w + c ? 0.0f : 1.0f;
    const hfs_field f = {w, h, z, 1.0, 1.0};
    hfs_lighting l = bounce_uniform_sky();
    l.albedo = 0.5;
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.subsample = 1; /* the full-resolution reference (cpu_grid.h: 2, 4) */
    const size_t p = 3 * ((size_t)c * w + c);
    const double before = lo[p];
    hfs_error err = {""};
    REQUIRE(hfs_cpu_bounces(&f, &l, &q, 1, lo, NULL, NULL, &err) == HFS_OK, "%s", err.msg);
    const double got = (lo[p] - before) / l.albedo;
    printf("pit: the bottom gathers %.2e of rho Lw (bound %.0e)\n", got, PIT_MAX);
    CHECK(got >= 0.0 && got <= PIT_MAX);
    free(z), free(lo);
}

/* Glossy: the sky's lobe is order 4 (hfs_gloss_env, N.R for the cosine),
 * the bands' the exact one (hfs_lobe_slice_band): not a bound by
 * construction as the diffuse walk's, but the energy must still
 * hold.  Measured max 0.9166; bound 1. */
#define GLOSSY_FURNACE_MAX 1.0

static void glossy_surface(hfs_lighting *l, double ks, double s)
{
    l->albedo = 1.0 - ks, l->specular = ks, l->gloss = s;
    l->view_dir[0] = -0.6, l->view_dir[1] = 0.0, l->view_dir[2] = 0.8;
}

static void test_furnace(int glossy)
{
    const int w = 33, h = 48;
    float *z = bounce_groove(w, h);
    const hfs_field f = {w, h, z, 1.0, 1.0};
    hfs_lighting l = bounce_uniform_sky();
    if (glossy)
        glossy_surface(&l, 0.4, 8.0);
    float *lo[4];
    for (int b = 0; b < 4; ++b) {
        lo[b] = malloc(sizeof(float) * w * h * 3);
        render(hfs_cpu_render, &f, &l, b, lo[b]);
    }
    double worst_total, worst_neg;
    bounce_furnace(lo, (size_t)w * h * 3, &worst_neg, &worst_total);
    CHECK(worst_neg >= 0.0 && worst_total <= (glossy ? GLOSSY_FURNACE_MAX : 1.0 + 1e-9));
    printf("furnace%s: every bounce >= 0 (min %.2e), direct + 3 bounces <= %.4f\n",
           glossy ? ", glossy" : "", worst_neg, worst_total);
    for (int b = 0; b < 4; ++b)
        free(lo[b]);
    free(z);
}

/* Bound: measured 1.8% here (2.2% on the benchmark cones at 128^2);
 * bound 5% of the truth's largest indirect value (issue 16 asks 10% at
 * the defaults).  Glossy (albedo 0.1 + ks 0.9, S 8: the lobe's bounce
 * dominates): measured 0.58%; mutant M61 (no glossy bounce) fails the
 * bound; bound 2%. */
#define TRUTH_REL 0.05
#define GLOSSY_TRUTH_REL 0.02

static void test_truth(int glossy)
{
    const int n = 48;
    float *z = malloc((size_t)n * n * sizeof *z);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) { /* two cones */
            const double r1 = hypot(i - 15.0, j - 18.0), r2 = hypot(i - 33.0, j - 28.0);
            z[j * n + i] = (float)fmax(0.0, fmax(12.0 - r1, 9.0 - 0.8 * r2));
        }
    const hfs_field f = {n, n, z, 1.0, 1.0};
    hfs_lighting l = bounce_uniform_sky();
    l.n_key = 1;
    l.key[0] = (hfs_key_light){336 * PI / 180, 15 * PI / 180, 2 * PI / 180, {300, 300, 300}, 0, 0};
    if (glossy)
        glossy_surface(&l, 0.9, 8.0);
    float *c[2], *t[2];
    for (int b = 0; b < 2; ++b) {
        c[b] = malloc(sizeof(float) * n * n * 3), t[b] = malloc(sizeof(float) * n * n * 3);
        render(hfs_cpu_render, &f, &l, b, c[b]);
        render(hfs_truth_render, &f, &l, b, t[b]);
    }
    double sum = 0.0, tmax = 0.0, tsum = 0.0;
    for (int p = 0; p < n * n * 3; ++p) {
        const double ci = c[1][p] - c[0][p], ti = t[1][p] - t[0][p];
        sum += fabs(ci - ti);
        tmax = fmax(tmax, ti);
        tsum += ti;
    }
    const double rel = sum / (n * n * 3) / tmax;
    printf("truth: one bounce on two cones%s: indirect mean %.4f, max %.4f; cpu error %.2f%% of "
           "the max (bound %.0f%%)\n", glossy ? ", glossy" : "", tsum / (n * n * 3), tmax,
           100 * rel, 100 * (glossy ? GLOSSY_TRUTH_REL : TRUTH_REL));
    CHECK(tmax > 0.0 && rel <= (glossy ? GLOSSY_TRUTH_REL : TRUTH_REL));
    for (int b = 0; b < 2; ++b)
        free(c[b]), free(t[b]);
    free(z);
}

static void render(hfs_backend_fn fn, const hfs_field *f, hfs_lighting *l, int bounces,
                   float *out)
{
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.subsample = 1; /* the full-resolution reference (cpu_grid.h: 2, 4) */
    l->bounces = bounces;
    hfs_image img = {f->width, f->height, out};
    hfs_error err = {""};
    if (fn(f, l, &q, &img, NULL, NULL, &err) != HFS_OK) {
        fprintf(stderr, "render: %s\n", err.msg);
        exit(1);
    }
}

/* The bounces' azimuths are the environment's every (nphi_env / n)-th, n
 * the largest divisor of nphi_env not above nphi_bounce: then each has
 * the direct light's horizon to stop at. */
static void test_bounce_dirs(void)
{
    const int cases[][3] = {{12, 12, 12}, {12, 5, 4}, {12, 100, 12}, {32, 12, 8}, {7, 3, 1},
                            {12, 1, 1}, {30, 7, 6}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        hfs_quality q;
        hfs_quality_defaults(&q);
        q.subsample = 1; /* the full-resolution reference (cpu_grid.h: 2, 4) */
        q.nphi_env = cases[k][0], q.nphi_bounce = cases[k][1];
        CHECK(hfs_bounce_dirs(&q) == cases[k][2]);
    }
    printf("bounce azimuths: the largest divisor of nphi-env not above nphi-bounce\n");
}

int main(void)
{
    test_bounce_dirs();
    test_flat();
    test_wall();
    test_pit();
    test_furnace(0);
    test_furnace(1);
    test_truth(0);
    test_truth(1);
    return finish_checks("test_cpu_bounce");
}
