/*
 * test_metrics.c — SPEC.md's error metrics (runtime/renderer/metrics.c) against values
 * worked out by hand: every bound in the suite is a bound on these numbers,
 * so a wrong percentile or normalization would loosen all of them at once.
 */
#include "hfshade.h"
#include "test_util.h"

#include <math.h>
#include <stdio.h>

static int near(double a, double b) { return fabs(a - b) <= 1e-12 * (1.0 + fabs(b)); }

/* 10x10 texels, 300 channel values: result = reference + k / 300 for the
 * k-th value (k = 1..300) in a scrambled order, normalized by 2.  Nearest
 * rank: p99 is the ceil(0.99 * 300) = 297th smallest difference. */
static void known_distribution(void)
{
    hfs_image res = {0}, ref = {0};
    hfs_error err = {0};
    REQUIRE(hfs_image_alloc(&res, 10, 10, &err) == HFS_OK &&
                hfs_image_alloc(&ref, 10, 10, &err) == HFS_OK,
            "alloc: %s", err.msg);
    const int n = 300;
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < n; ++i) {
        const int k = (i * 7) % n + 1; /* 7 is prime to 300: a permutation */
        ref.rgb[i] = (float)(0.25 * (i % 5));
        res.rgb[i] = ref.rgb[i] + (float)k / 300.0f;
        const double d = fabs((double)res.rgb[i] - (double)ref.rgb[i]) / 2.0;
        sum += d;
        sum2 += d * d;
    }
    hfs_metrics m;
    CHECK(hfs_compare_images(&res, &ref, 2.0, &m, &err) == HFS_OK);
    CHECK(near(m.mean_abs, sum / n));
    CHECK(near(m.rmse, sqrt(sum2 / n)));
    /* The differences are k/300/2 up to float rounding of the sums. */
    CHECK(fabs(m.p99_abs - 297.0 / 600.0) < 1e-6);
    CHECK(fabs(m.max_abs - 300.0 / 600.0) < 1e-6);
    CHECK(fabs(m.mean_abs - 150.5 / 300.0 / 2.0) < 1e-6);
    CHECK(m.nonfinite == 0 && m.norm == 2.0);

    /* One non-finite value: counted, and it is the maximum. */
    res.rgb[17] = NAN;
    CHECK(hfs_compare_images(&res, &ref, 2.0, &m, &err) == HFS_OK);
    CHECK(m.nonfinite == 1 && isinf(m.max_abs));
    hfs_image_free(&res);
    hfs_image_free(&ref);
}

/* Of 300 channel values, p99 (rank 297) ignores one outlier and reaches four:
 * the percentile is taken from the top, not the bottom. */
static void outliers(void)
{
    hfs_image res = {0}, ref = {0};
    hfs_error err = {0};
    REQUIRE(hfs_image_alloc(&res, 10, 10, &err) == HFS_OK &&
                hfs_image_alloc(&ref, 10, 10, &err) == HFS_OK,
            "alloc: %s", err.msg);
    for (int i = 0; i < 300; ++i) {
        ref.rgb[i] = 1.0f;
        res.rgb[i] = 1.0f + (i % 3 == 0 ? 0.001f : 0.0f);
    }
    res.rgb[5] = 2.0f;
    hfs_metrics m;
    CHECK(hfs_compare_images(&res, &ref, 1.0, &m, &err) == HFS_OK);
    CHECK(fabs(m.p99_abs - 0.001) < 1e-6 && fabs(m.max_abs - 1.0) < 1e-6);
    res.rgb[8] = 2.0f;
    res.rgb[11] = 2.0f;
    res.rgb[14] = 2.0f; /* four outliers: rank 297 of 300 is the 4th largest */
    CHECK(hfs_compare_images(&res, &ref, 1.0, &m, &err) == HFS_OK);
    CHECK(fabs(m.p99_abs - 1.0) < 1e-6);
    hfs_image_free(&res);
    hfs_image_free(&ref);
}

static void refusals(void)
{
    hfs_image a = {0}, b = {0};
    hfs_error err = {0};
    REQUIRE(hfs_image_alloc(&a, 4, 3, &err) == HFS_OK &&
                hfs_image_alloc(&b, 3, 4, &err) == HFS_OK,
            "alloc: %s", err.msg);
    hfs_metrics m;
    CHECK(hfs_compare_images(&a, &b, 1.0, &m, &err) == HFS_E_INVALID);
    CHECK(hfs_compare_images(&a, &a, 0.0, &m, &err) == HFS_E_INVALID);
    CHECK(hfs_compare_images(&a, &a, NAN, &m, &err) == HFS_E_INVALID);
    CHECK(hfs_compare_images(&a, &a, INFINITY, &m, &err) == HFS_E_INVALID);
    for (int i = 0; i < 36; ++i)
        a.rgb[i] = (float)i;
    CHECK(fabs(hfs_image_max(&a) - 35.0) < 1e-12);
    a.rgb[3] = INFINITY; /* non-finite values are not the maximum */
    CHECK(fabs(hfs_image_max(&a) - 35.0) < 1e-12);
    hfs_image_free(&a);
    hfs_image_free(&b);
}

int main(void)
{
    known_distribution();
    outliers();
    refusals();
    return finish_checks("test_metrics");
}
