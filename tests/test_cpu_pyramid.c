/*
 * test_cpu_pyramid.c — the height pyramid of DESIGN.md: level count and
 * sizes, exact constants, linear functions reproduced away from the borders,
 * the B-spline weights at a clamped border, box decimation for k = 1, and
 * independence from the thread count.
 */
#include "cpu_pyramid.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures;

#define CHECK(cond, ...) do { if (!(cond)) { failures++; printf("FAIL %s:%d: ", __FILE__, __LINE__); \
    printf(__VA_ARGS__); printf("\n"); } } while (0)

static hfs_cpu_pyramid *build(const float *z, int w, int h, int k, int first, int threads)
{
    hfs_field f = {.width = w, .height = h, .z = z, .dx = 1.0, .zscale = 1.0};
    hfs_cpu_pyramid *p = NULL;
    hfs_error err = {{0}};
    int rc = hfs_cpu_pyramid_create(&f, k, first, threads, &p, &err);
    CHECK(rc == HFS_OK && p, "create %dx%d k=%d failed: %s", w, h, k, err.msg);
    return p;
}

static void test_layout(void)
{
    CHECK(hfs_pyramid_level_count(256, 256, 4) == 33, "N(256, k=4) = %d", hfs_pyramid_level_count(256, 256, 4));
    CHECK(hfs_pyramid_level_count(512, 512, 4) == 37, "N(512, k=4) = %d", hfs_pyramid_level_count(512, 512, 4));
    CHECK(hfs_pyramid_level_count(512, 100, 4) == 37, "N uses max(W, H)");
    CHECK(hfs_pyramid_level_count(256, 256, 1) == 9, "N(256, k=1) = %d", hfs_pyramid_level_count(256, 256, 1));
    CHECK(hfs_pyramid_level_count(2, 2, 4) == 5, "N(2, k=4) = %d", hfs_pyramid_level_count(2, 2, 4));
    /* 37: 4*log2(37) = 20.84 -> 22 */
    CHECK(hfs_pyramid_level_count(37, 20, 4) == 22, "N(37, k=4) = %d", hfs_pyramid_level_count(37, 20, 4));

    int lw, lh;
    hfs_pyramid_level_size(256, 256, 4, 32, &lw, &lh);
    CHECK(lw == 256 && lh == 256, "finest level is the input: %dx%d", lw, lh);
    hfs_pyramid_level_size(256, 256, 4, 28, &lw, &lh);
    CHECK(lw == 128 && lh == 128, "one octave down: %dx%d", lw, lh);
    hfs_pyramid_level_size(256, 256, 4, 0, &lw, &lh);
    CHECK(lw == 1 && lh == 1, "coarsest level: %dx%d", lw, lh);
    hfs_pyramid_level_size(256, 256, 4, 31, &lw, &lh);
    CHECK(lw == 216 && lh == 216, "256/2^(1/4) -> ceil 215.3 = 216: %dx%d", lw, lh);
    CHECK(fabs(hfs_pyramid_spacing(33, 4, 31) - pow(2.0, 0.25)) < 1e-15, "spacing");
    CHECK(hfs_pyramid_spacing(33, 4, 32) == 1.0 && hfs_pyramid_spacing(33, 4, 0) == 256.0, "spacing ends");

    /* Non-square, non-power-of-two: ceil(W/s), ceil(H/s), never below 1,
     * monotone in the level index. */
    const int n = hfs_pyramid_level_count(37, 20, 4);
    int pw = 0, ph = 0;
    for (int i = 0; i < n; ++i) {
        hfs_pyramid_level_size(37, 20, 4, i, &lw, &lh);
        const double s = hfs_pyramid_spacing(n, 4, i);
        int ew = (int)ceil(37.0 / s), eh = (int)ceil(20.0 / s);
        ew = ew < 1 ? 1 : ew;
        eh = eh < 1 ? 1 : eh;
        CHECK(lw == ew && lh == eh, "37x20 level %d: %dx%d, want %dx%d", i, lw, lh, ew, eh);
        CHECK(lw >= pw && lh >= ph, "sizes not monotone at level %d", i);
        pw = lw;
        ph = lh;
    }
    CHECK(pw == 37 && ph == 20, "37x20 finest level %dx%d", pw, ph);

    CHECK(hfs_pyramid_read_level(37, 4, 2, 0) == 8, "read level offset");
    CHECK(hfs_pyramid_read_level(37, 4, 2, 30) == 36, "read level clamped to N-1");
    CHECK(hfs_pyramid_read_level(37, 4, 0, 5) == 5, "read level, no offset");
}

static void test_object_matches_layout(void)
{
    const int w = 45, h = 30;
    float *z = calloc((size_t)w * h, sizeof *z);
    hfs_cpu_pyramid *p = build(z, w, h, 3, 4, 2);
    if (p) {
        const int n = hfs_cpu_pyramid_count(p);
        CHECK(n == hfs_pyramid_level_count(w, h, 3), "count");
        CHECK(hfs_cpu_pyramid_first_full(p) == 4, "first_full");
        CHECK(hfs_cpu_pyramid_full(p, 3) == NULL && hfs_cpu_pyramid_full(p, 4) != NULL,
              "only levels >= first_full are reconstructed");
        CHECK(hfs_cpu_pyramid_stride(p) == w + 1, "stride");
        for (int i = 0; i < n; ++i) {
            int a, b, c, d;
            hfs_cpu_pyramid_size(p, i, &a, &b);
            hfs_pyramid_level_size(w, h, 3, i, &c, &d);
            CHECK(a == c && b == d, "level %d size", i);
            CHECK(hfs_cpu_pyramid_spacing(p, i) == hfs_pyramid_spacing(n, 3, i), "level %d spacing", i);
        }
    }
    hfs_cpu_pyramid_destroy(p);
    hfs_cpu_pyramid_destroy(NULL);
    free(z);
}

static void test_constant(int w, int h, int k)
{
    float *z = malloc((size_t)w * h * sizeof *z);
    for (int q = 0; q < w * h; ++q)
        z[q] = 123.456f;
    const double c = (double)123.456f;
    hfs_cpu_pyramid *p = build(z, w, h, k, 0, 2);
    if (p) {
        const int n = hfs_cpu_pyramid_count(p), stride = hfs_cpu_pyramid_stride(p);
        long bad = 0;
        for (int i = 0; i < n; ++i) {
            int lw, lh;
            hfs_cpu_pyramid_size(p, i, &lw, &lh);
            const double *s = hfs_cpu_pyramid_samples(p, i);
            for (int q = 0; q < lw * lh; ++q)
                bad += s[q] != c;
            const double *r = hfs_cpu_pyramid_full(p, i);
            for (int j = 0; j <= h; ++j)          /* padding included */
                for (int x = 0; x <= w; ++x)
                    bad += r[j * stride + x] != c;
        }
        CHECK(bad == 0, "constant %dx%d k=%d: %ld samples differ from the constant", w, h, k, bad);
    }
    hfs_cpu_pyramid_destroy(p);
    free(z);
}

/* A linear ramp stays a ramp (at grid points and in bilinear reads) away from
 * the borders, where the clamped B-spline flattens it. */
static void test_ramp(int w, int h, int k)
{
    const double a = 0.75, b = -0.5, c0 = 10.0;
    float *z = malloc((size_t)w * h * sizeof *z);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            z[j * w + i] = (float)(c0 + a * i + b * j);   /* exact in float */
    hfs_cpu_pyramid *p = build(z, w, h, k, 0, 1);
    if (p) {
        const int n = hfs_cpu_pyramid_count(p), stride = hfs_cpu_pyramid_stride(p);
        int checked_levels = 0;
        double worst = 0.0;
        for (int i = 0; i < n; ++i) {
            int lw, lh;
            hfs_cpu_pyramid_size(p, i, &lw, &lh);
            /* The clamp reaches 1.5 level texels from the edge; margin 2.5
             * level texels in input texels. */
            const int mx = (int)ceil(2.5 * w / lw), my = (int)ceil(2.5 * h / lh);
            if (2 * mx >= w - 1 || 2 * my >= h - 1)
                continue;
            checked_levels++;
            const double *r = hfs_cpu_pyramid_full(p, i);
            for (int j = my; j < h - my; ++j)
                for (int x = mx; x < w - mx; ++x) {
                    const double e = fabs(r[j * stride + x] - (c0 + a * x + b * j));
                    worst = e > worst ? e : worst;
                }
            const double gx = mx + 0.37, gy = my + 0.81;
            const double e = fabs(hfs_cpu_pyramid_sample(p, i, gx, gy) - (c0 + a * gx + b * gy));
            worst = e > worst ? e : worst;
        }
        /* measured <= 2.8e-14 (double, every build type): ~10x */
        CHECK(worst < 3e-13, "ramp %dx%d k=%d: max deviation %g", w, h, k, worst);
        CHECK(checked_levels >= 3, "ramp %dx%d: only %d levels checked", w, h, checked_levels);
        /* The decimated samples never clamp (levels shrink), so they are the
         * ramp in texture coordinates at every level, borders included. */
        double worst_s = 0.0;
        for (int i = 0; i < n; ++i) {
            int lw, lh;
            hfs_cpu_pyramid_size(p, i, &lw, &lh);
            const double *s = hfs_cpu_pyramid_samples(p, i);
            for (int r = 0; r < lh; ++r)
                for (int t = 0; t < lw; ++t) {
                    const double gx = (t + 0.5) * w / lw - 0.5, gy = (r + 0.5) * h / lh - 0.5;
                    const double e = fabs(s[r * lw + t] - (c0 + a * gx + b * gy));
                    worst_s = e > worst_s ? e : worst_s;
                }
        }
        CHECK(worst_s < 3e-13, "ramp %dx%d k=%d: decimated samples deviate by %g", w, h, k, worst_s);
    }
    hfs_cpu_pyramid_destroy(p);
    free(z);
}

/* 2x2 ramp: level N-2 has the input's size, so its reconstruction shows the
 * bare B-spline weights (1/6, 2/3, 1/6) with the edge clamp:
 * [0, 6] -> [(5*0 + 6)/6, (0 + 5*6)/6] = [1, 5]. */
static void test_bspline_weights(void)
{
    const float z[4] = {0.0f, 6.0f, 0.0f, 6.0f};
    hfs_cpu_pyramid *p = build(z, 2, 2, 4, 0, 1);
    if (p) {
        const int n = hfs_cpu_pyramid_count(p);
        int lw, lh;
        hfs_cpu_pyramid_size(p, n - 2, &lw, &lh);
        CHECK(lw == 2 && lh == 2, "2x2 level N-2 size %dx%d", lw, lh);
        const double *r = hfs_cpu_pyramid_full(p, n - 2);
        const int st = hfs_cpu_pyramid_stride(p);
        CHECK(fabs(r[0] - 1.0) < 1e-14 && fabs(r[1] - 5.0) < 1e-14 &&
              fabs(r[st] - 1.0) < 1e-14 && fabs(r[st + 1] - 5.0) < 1e-14,
              "B-spline of [0,6]: got [%g, %g]", r[0], r[1]);
        const double *top = hfs_cpu_pyramid_full(p, n - 1);
        CHECK(top[0] == 0.0 && top[1] == 6.0, "level N-1 is the input");
        const double *c = hfs_cpu_pyramid_samples(p, 0);
        CHECK(fabs(c[0] - 3.0) < 1e-14, "1x1 coarsest level is the mean: %g", c[0]);
    }
    hfs_cpu_pyramid_destroy(p);
}

/* k = 1 on a power of two: each decimation is an exact 2x2 box average. */
static void test_box_decimation(void)
{
    const int w = 8, h = 8;
    float z[64];
    for (int q = 0; q < 64; ++q)
        z[q] = (float)((q * 37) % 11);
    hfs_cpu_pyramid *p = build(z, w, h, 1, 0, 1);
    if (p) {
        const int n = hfs_cpu_pyramid_count(p);
        CHECK(n == 4, "N(8, k=1) = %d", n);
        const double *s = hfs_cpu_pyramid_samples(p, n - 2);
        double worst = 0.0;
        for (int r = 0; r < 4; ++r)
            for (int t = 0; t < 4; ++t) {
                const double m = (z[(2 * r) * 8 + 2 * t] + z[(2 * r) * 8 + 2 * t + 1] +
                                  z[(2 * r + 1) * 8 + 2 * t] + z[(2 * r + 1) * 8 + 2 * t + 1]) / 4.0;
                const double e = fabs(s[r * 4 + t] - m);
                worst = e > worst ? e : worst;
            }
        CHECK(worst < 1e-14, "k=1 decimation is not a box average: %g", worst);
    }
    hfs_cpu_pyramid_destroy(p);
}

static void test_threads_and_odd_sizes(void)
{
    const int sizes[][2] = {{2, 2}, {3, 2}, {37, 20}, {20, 37}, {64, 64}, {100, 7}};
    for (size_t t = 0; t < sizeof sizes / sizeof sizes[0]; ++t) {
        const int w = sizes[t][0], h = sizes[t][1];
        float *z = malloc((size_t)w * h * sizeof *z);
        for (int q = 0; q < w * h; ++q)
            z[q] = (float)sin(q * 0.7) * 5.0f;
        hfs_cpu_pyramid *a = build(z, w, h, 4, 0, 1);
        hfs_cpu_pyramid *b = build(z, w, h, 4, 0, 3);
        if (a && b) {
            const int n = hfs_cpu_pyramid_count(a);
            const size_t sz = (size_t)(w + 1) * (h + 1) * sizeof(double);
            int same = 1, finite = 1;
            for (int i = 0; i < n; ++i) {
                same &= memcmp(hfs_cpu_pyramid_full(a, i), hfs_cpu_pyramid_full(b, i), sz) == 0;
                const double *r = hfs_cpu_pyramid_full(a, i);
                for (size_t q = 0; q < (size_t)(w + 1) * (h + 1); ++q)
                    finite &= isfinite(r[q]) && fabs(r[q]) <= 5.0 + 1e-12;
            }
            CHECK(same, "%dx%d: result depends on the thread count", w, h);
            CHECK(finite, "%dx%d: non-finite or out-of-range (convex combination) value", w, h);
        }
        hfs_cpu_pyramid_destroy(a);
        hfs_cpu_pyramid_destroy(b);
        free(z);
    }
}

static void test_bad_arguments(void)
{
    float z[4] = {0};
    hfs_field f = {.width = 2, .height = 2, .z = z, .dx = 1.0, .zscale = 1.0};
    hfs_cpu_pyramid *p = (hfs_cpu_pyramid *)&f;
    hfs_error err = {{0}};
    CHECK(hfs_cpu_pyramid_create(&f, 0, 0, 1, &p, &err) == HFS_E_INVALID && !p && err.msg[0],
          "k = 0 accepted");
}

int main(void)
{
    test_layout();
    test_object_matches_layout();
    test_constant(256, 256, 4);
    test_constant(37, 20, 4);
    test_constant(2, 2, 4);
    test_constant(5, 33, 2);
    test_ramp(128, 128, 4);
    test_ramp(97, 61, 4);
    test_ramp(64, 80, 2);
    test_bspline_weights();
    test_box_decimation();
    test_threads_and_odd_sizes();
    test_bad_arguments();
    if (failures) {
        printf("%d failure(s)\n", failures);
        return 1;
    }
    printf("test_cpu_pyramid: all passed\n");
    return 0;
}
