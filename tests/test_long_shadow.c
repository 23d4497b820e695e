/*
 * test_long_shadow.c — narrow features keep their long shadows (issue 36,
 * deliverable 1): a post a few texels wide on a flat field under a small
 * low sun, its umbra and its lit ground told by geometry alone (no truth
 * render): a ground texel is in umbra where every ray to the sun's disk
 * (its centre and both sides, at the disk's top) passes over the post's
 * top square below its height, with a margin; it is lit where every ray
 * misses the post's footprint grown by the one-texel ramp of the bilinear
 * surface, or passes above its height.  Each umbra texel must render below
 * 5% of its unshadowed value at every subsample (run_case), each lit one
 * above 95%.
 *
 * Before the gap search (runtime/core/ray_bound.h) the scales sampled the
 * sun's direction at distances 2^(m/k) and stepped over the post beyond a
 * few times its width: the shadow came out in stripes, lit texels deep in
 * the umbra.  The cases: axis-aligned and oblique suns (3-15 degrees),
 * posts 2-6 texels wide, the post's shadow crossing 100-300 texels.
 *
 *   test_long_shadow cpu [SUBSAMPLE] | gles SUBSAMPLE [fp32]
 */
#include "metamorphic.h" /* mm_main: the backend from the command line */
#include "post_geometry.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

typedef struct post_case {
    int w, h;          /* field */
    int x0, y0, side;  /* the post's grid points [x0, x0 + side - 1]^2 */
    double height;
    double phi, elev, alpha; /* the sun, degrees */
} post_case;

/* 1: umbra, 0: lit, -1: neither (penumbra, the post, its ramp), for the
 * ground point (i, j). */
static int classify(const post_case *pc, double i, double j)
{
    const double a0 = pc->x0, a1 = pc->x0 + pc->side - 1, b0 = pc->y0, b1 = pc->y0 + pc->side - 1;
    if (i >= a0 - 1 && i <= a1 + 1 && j >= b0 - 1 && j <= b1 + 1)
        return -1;
    const double al = pc->alpha * PI / 180.0, e = pc->elev * PI / 180.0;
    const double side = asin(sin(al) / cos(e)); /* the disk's half-width in azimuth */
    int umbra = 1, lit = 1;
    for (int k = -1; k <= 1; ++k) {
        const double phi = pc->phi * PI / 180.0 + k * side;
        const double c = cos(phi), s = sin(phi);
        const double t_in = ray_enter(i, j, c, s, a0, a1, b0, b1);
        /* the whole disk blocked: its top (e + alpha) below the top
         * square's height with a margin, and the sides in the square */
        if (t_in < 0.0 || t_in * tan(e + al) > pc->height - 0.5 ||
            ray_enter(i, j, c, s, a0 + 0.5, a1 - 0.5, b0 + 0.5, b1 - 0.5) < 0.0)
            umbra = 0;
        const double t_ramp = ray_enter(i, j, c, s, a0 - 1.5, a1 + 1.5, b0 - 1.5, b1 + 1.5);
        if (t_ramp >= 0.0 && t_ramp * tan(e - al) < pc->height + 0.5)
            lit = 0;
    }
    return umbra ? 1 : (lit ? 0 : -1);
}

/* Field f under one sun (degrees; radiance 1000) into img and its
 * unshadowed image into un (both allocated here); 0, or the failure
 * counted and reported. */
static int render_sun(hfs_renderer *r, const char *name, const hfs_field *f, double phi,
                      double elev, double alpha, const hfs_quality *q, hfs_image *img,
                      hfs_image *un)
{
    hfs_lighting l;
    hfs_lighting_defaults(&l);
    l.n_key = 1;
    l.key[0] = (hfs_key_light){.phi = phi * PI / 180.0, .elev = elev * PI / 180.0,
                               .alpha = alpha * PI / 180.0, .radiance = {1000, 1000, 1000}};
    hfs_error err = {""};
    if (hfs_image_alloc(img, f->width, f->height, &err) ||
        hfs_image_alloc(un, f->width, f->height, &err) ||
        hfs_renderer_render(r, f, &l, q, img, NULL, NULL, &err) ||
        hfs_render_unshadowed(f, &l, q, un, &err)) {
        fprintf(stderr, "FAIL %s: %s\n", name, err.msg);
        ++failures;
        return 1;
    }
    return 0;
}

/* Umbra texels render below 5% of their unshadowed value, at every
 * subsample: on a sub-sampled grid each texel searches its own rays to the
 * field's end (DESIGN.md "Sharp edges on the grid").  Before (a37b16b) it
 * searched only to where the disk's penumbra is a grid step wide and
 * blended its grid receivers' occluders beyond, and an umbra narrower than
 * the step came out partly lit (case 4 at subsample 2: 4 texels at
 * 19-21%), so the bound there was the "rendered lit", half of the
 * unshadowed value (before the edge search, at subsample 2 one texel of
 * case 2, at subsample 4 18-72 of cases 3-6, above even that). */
static void run_case(hfs_renderer *r, const char *name, const post_case *pc,
                     const hfs_quality *q)
{
    const double umbra_max = 0.05;
    const int w = pc->w, h = pc->h;
    float *z;
    const hfs_field f = post_field(w, h, pc->x0, pc->y0, pc->side, pc->height, &z);
    hfs_image img = {0}, un = {0};
    if (!render_sun(r, name, &f, pc->phi, pc->elev, pc->alpha, q, &img, &un)) {
        long n_umbra = 0, n_lit = 0, bad_umbra = 0, bad_lit = 0;
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) {
                const int k = classify(pc, i, j);
                const size_t t = 3 * ((size_t)j * w + i);
                const double v = img.rgb[t], u = un.rgb[t];
                if (k == 1) {
                    ++n_umbra;
                    bad_umbra += v > umbra_max * u;
                    if (v > umbra_max * u && bad_umbra <= 3)
                        printf("  umbra texel (%d, %d) at %.3f of its unshadowed value\n", i, j,
                               v / u);
                } else if (k == 0) {
                    ++n_lit;
                    bad_lit += v < 0.95 * u;
                }
            }
        printf("%s: post %d wide, %.0f tall, sun %.0f/%.0f: umbra %ld texels, %ld lit; "
               "lit ground %ld texels, %ld shadowed\n", name, pc->side, pc->height, pc->phi,
               pc->elev, n_umbra, bad_umbra, n_lit, bad_lit);
        post_checks(name, 100, n_umbra, bad_umbra, n_lit, bad_lit);
    }
    hfs_image_free(&img);
    hfs_image_free(&un);
    free(z);
}

/* A receiver's own cell shadows it (issue 36): on a checkerboard of
 * heights 0 and 1 (dx 1) the bilinear surface along the diagonal from a 0
 * texel rises as sqrt2 t - t^2, so its slope at the start, sqrt2 (54.7
 * degrees), is the horizon there, and a sun 45 degrees up along the
 * diagonal is hidden from every 0 texel (a ray below that slope meets the
 * surface just past the receiver's lift) while a 1 texel, whose cells
 * along the diagonal never rise above it, sees it.  No scale's sample lies
 * at the cell's near end: before, every one of the 181 0 texels checked was
 * lit at its full unshadowed value (CPU, GLES at subsample 1 and 2). */
static void run_own_cell(hfs_renderer *r, const char *name, const hfs_quality *q)
{
    const int w = 24, h = 24;
    float z[24 * 24];
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            z[j * w + i] = (float)((i + j) % 2);
    const hfs_field f = {.width = w, .height = h, .z = z, .dx = 1.0, .zscale = 1.0};
    hfs_image img = {0}, un = {0};
    if (!render_sun(r, name, &f, 45.0, 45.0, 0.25, q, &img, &un)) {
        long bad_umbra = 0, bad_lit = 0;
        double worst = 0.0;
        /* interior texels whose diagonal stays on the field for a while */
        for (int j = 1; j < h - 4; ++j)
            for (int i = 1; i < w - 4; ++i) {
                const size_t t = 3 * ((size_t)j * w + i);
                const double v = img.rgb[t] / un.rgb[t];
                if ((i + j) % 2 == 0) {
                    bad_umbra += v > 0.05;
                    worst = fmax(worst, v);
                } else {
                    bad_lit += v < 0.95;
                }
            }
        printf("%s: checkerboard, sun 45/45 along the diagonal: 0 texels at most %.3f of "
               "their unshadowed value, %ld lit; 1 texels %ld shadowed\n", name, worst,
               bad_umbra, bad_lit);
        LS_CHECK(bad_umbra == 0, "%s: %ld texels lit through their own cell (up to %.3f)",
                 name, bad_umbra, worst);
        LS_CHECK(bad_lit == 0, "%s: %ld texels on the ridges shadowed", name, bad_lit);
    }
    hfs_image_free(&img);
    hfs_image_free(&un);
}

/* A lone spike of height H at grid point (sx, sy) on a flat field: the
 * bilinear surface is H tent(x - sx) tent(y - sy).  The largest elevation
 * (radians) the ray from (i, j) along (c, s) sees of it, sampled densely
 * over the part of the ray inside the spike's 2x2 cells (`crossings`: only
 * where the ray meets the lines x = integer, or y = integer where |s| >
 * |c|, as a search of the crossings alone would); -1 where it misses them. */
static double spike_elevation(double i, double j, double c, double s, int sx, int sy, double H,
                              int crossings)
{
    const double t_in = ray_enter(i, j, c, s, sx - 1.0, sx + 1.0, sy - 1.0, sy + 1.0);
    if (t_in < 0.0)
        return -1.0;
    const int xm = fabs(c) >= fabs(s);
    const double step = crossings ? 1.0 / fabs(xm ? c : s) : 1e-3;
    double t = crossings ? ceil((xm ? fabs(sx - 1.0 - i) : fabs(sy - 1.0 - j)) - 1e-9) * step
                         : fmax(t_in, 1e-3);
    double best = -1.0;
    for (; t < t_in + 4.0; t += step) {
        const double x = i + t * c, y = j + t * s;
        const double z = H * fmax(0.0, 1.0 - fabs(x - sx)) * fmax(0.0, 1.0 - fabs(y - sy));
        if (t > 0.0 && z > 0.0)
            best = fmax(best, atan(z / t));
    }
    return best;
}

/* Between crossings (issue 36 item 1; hfstress sun_ramp_spike_1e5): a ray
 * that passes a spike's cell near the corner opposite the spike meets the
 * crossings where the spike weighs 0 and the cell's interior where it
 * does not (the surface along the ray is the cell's quadratic, H |r| / 4 at
 * most, r the ray's minor/major ratio).  A texel is umbra where every ray
 * of the disk, at azimuths spanning it with a margin, rises 1 degree above
 * the disk's top, lit where none comes within 1 degree of its bottom.  Before
 * the key lights searched every cell (ray_bound.h "cells") the band of
 * texels whose rays only clip such a corner came out lit (the CPU and GLES
 * alike: 28 of its 116 umbra texels at subsample 1, 13 at 2 and 4). */
static void run_spike_cell(hfs_renderer *r, const char *name, const hfs_quality *q)
{
    const int w = 96, h = 64, sx = 70, sy = 40;
    const double H = 400.0, phi = 336.0, elev = 10.0, alpha = 0.25;
    float *z = calloc((size_t)w * h, sizeof *z);
    z[(size_t)sy * w + sx] = (float)H;
    const hfs_field f = {.width = w, .height = h, .z = z, .dx = 1.0, .zscale = 1.0};
    hfs_image img = {0}, un = {0};
    const double e = elev * PI / 180.0, al = alpha * PI / 180.0, m = PI / 180.0;
    const double side = asin(sin(al) / cos(e)) + 0.05 * m;
    if (!render_sun(r, name, &f, phi, elev, alpha, q, &img, &un)) {
        long n_umbra = 0, n_between = 0, bad_umbra = 0, n_lit = 0, bad_lit = 0;
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) {
                if (abs(i - sx) <= 1 && abs(j - sy) <= 1)
                    continue;
                double lo = HUGE_VAL, hi = -HUGE_VAL, cross = -1.0;
                for (int k = -3; k <= 3; ++k) {
                    const double a = phi * m + k * side / 3.0;
                    const double el = spike_elevation(i, j, cos(a), sin(a), sx, sy, H, 0);
                    lo = fmin(lo, el);
                    hi = fmax(hi, el);
                    if (k == 0)
                        cross = spike_elevation(i, j, cos(a), sin(a), sx, sy, H, 1);
                }
                const size_t t = 3 * ((size_t)j * w + i);
                const double v = img.rgb[t] / un.rgb[t];
                if (lo > e + al + m) {
                    ++n_umbra;
                    n_between += cross < e - al;
                    bad_umbra += v > 0.05;
                    if (v > 0.05 && bad_umbra <= 3)
                        printf("  umbra texel (%d, %d) at %.3f of its unshadowed value\n", i, j,
                               v);
                } else if (hi < e - al - m) {
                    ++n_lit;
                    bad_lit += v < 0.95;
                }
            }
        printf("%s: spike %.0f tall, sun %.0f/%.0f: umbra %ld texels (%ld seen only between "
               "crossings), %ld lit; lit ground %ld texels, %ld shadowed\n", name, H, phi, elev,
               n_umbra, n_between, bad_umbra, n_lit, bad_lit);
        LS_CHECK(n_between >= 10, "%s: only %ld texels between crossings (the case is wrong)",
                 name, n_between);
        LS_CHECK(bad_umbra == 0, "%s: %ld of %ld umbra texels lit", name, bad_umbra, n_umbra);
        LS_CHECK(bad_lit == 0, "%s: %ld of %ld lit texels shadowed", name, bad_lit, n_lit);
    }
    hfs_image_free(&img);
    hfs_image_free(&un);
    free(z);
}

/* Every case with the defaults at subsample sub (fp32 textures on GLES
 * when the test is named so: TEST gles SUB fp32). */
static int fp32;
static void run(hfs_renderer *r, const char *backend, int sub)
{
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.subsample = sub > 0 ? sub : 1;
    if (fp32)
        q.precision = HFS_PRECISION_FP32;
    static const post_case cases[] = {
        {320, 20, 20, 8, 4, 10.0, 180.0, 3.0, 0.25},  /* along -x: 190 texels of umbra */
        {24, 260, 9, 230, 6, 24.0, 90.0, 6.0, 0.25},  /* along +y, towards row 0 */
        {200, 160, 20, 20, 3, 14.0, 213.0, 5.0, 0.25}, /* oblique */
        {160, 160, 140, 140, 3, 12.0, 45.0, 4.0, 0.1}, /* diagonal */
        {300, 40, 30, 18, 5, 40.0, 184.0, 15.0, 0.5}, /* a steeper sun */
        /* as bench_umbra.sh's towers (on the 2x2 grid before its
         * per-texel edge search 17 of 196 and 17 of 1272 umbra texels
         * lit, BENCHMARKS.md "Sharp edges on the grid"): a 5 x 14 post
         * under a 6-degree sun, a 10 x 20 block under 8 degrees */
        {300, 40, 20, 18, 5, 14.0, 180.0, 6.0, 0.25},
        {300, 60, 20, 25, 10, 20.0, 180.0, 8.0, 0.25},
    };
    char name[64];
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        snprintf(name, sizeof name, "%s sub %d case %zu", backend, q.subsample, c);
        run_case(r, name, &cases[c], &q);
    }
    snprintf(name, sizeof name, "%s sub %d own cell", backend, q.subsample);
    run_own_cell(r, name, &q);
    snprintf(name, sizeof name, "%s sub %d spike's cell", backend, q.subsample);
    run_spike_cell(r, name, &q);
}

int main(int argc, char **argv)
{
    fp32 = argc > 3 && !strcmp(argv[3], "fp32");
    return mm_main(argc, argv, "test_long_shadow", run);
}
