/*
 * test_io_fill.c — hfs_height_fill_holes() (push-pull): exact cases (a hole in
 * a constant field gets the constant), the hole count, valid texels never
 * change, every output finite and inside the range of the valid inputs,
 * determinism, odd and degenerate sizes, nodata value vs NaN/Inf, the
 * all-holes error, and that z is untouched on error.
 */
#include "hfs_io.h"
#include "test_util.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint32_t rng(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

static void test_single_hole_constant(void)
{
    float z[25];
    long holes = -1;
    hfs_error err;
    for (int k = 0; k < 25; ++k)
        z[k] = 7.25f;
    z[12] = NAN;
    CHECK(hfs_height_fill_holes(z, 5, 5, 0, 0.0f, &holes, &err) == 0);
    CHECK(holes == 1);
    CHECK(z[12] == 7.25f);

    /* Holes on the border and in the corners too. */
    for (int k = 0; k < 25; ++k)
        z[k] = -3.0f;
    z[0] = NAN;
    z[4] = INFINITY;
    z[20] = -INFINITY;
    z[24] = NAN;
    z[2] = NAN;
    CHECK(hfs_height_fill_holes(z, 5, 5, 0, 0.0f, &holes, &err) == 0);
    CHECK(holes == 5);
    for (int k = 0; k < 25; ++k)
        CHECK(z[k] == -3.0f);
}

static void test_nodata_value(void)
{
    float z[6] = {1, 1, -9999, 1, 1, 1};
    long holes = 0;
    hfs_error err;
    /* Without has_nodata, -9999 is a height. */
    CHECK(hfs_height_fill_holes(z, 3, 2, 0, -9999.0f, &holes, &err) == 0);
    CHECK(holes == 0 && z[2] == -9999.0f);
    CHECK(hfs_height_fill_holes(z, 3, 2, 1, -9999.0f, &holes, &err) == 0);
    CHECK(holes == 1 && z[2] == 1.0f);
    /* The count pointer is optional. */
    z[1] = NAN;
    CHECK(hfs_height_fill_holes(z, 3, 2, 0, 0.0f, NULL, &err) == 0);
    CHECK(z[1] == 1.0f);
}

static void test_two_values(void)
{
    /* Left half 0, right half 10, a hole column in between: filled values
     * lie between, and the fill is symmetric in this symmetric setup. */
    enum { W = 9, H = 4 };
    float z[W * H];
    long holes;
    hfs_error err;
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i)
            z[j * W + i] = i < 4 ? 0.0f : i > 4 ? 10.0f : NAN;
    CHECK(hfs_height_fill_holes(z, W, H, 0, 0.0f, &holes, &err) == 0);
    CHECK(holes == H);
    for (int j = 0; j < H; ++j) {
        CHECK(z[j * W + 4] > 0.0f && z[j * W + 4] < 10.0f);
        CHECK(z[j * W + 4] == z[4]); /* same in every row */
    }
}

static void test_random(void)
{
    static const int sizes[][2] = {{1, 1}, {1, 17}, {17, 1}, {2, 2}, {3, 5}, {7, 3},
                                   {31, 33}, {64, 64}, {100, 37}, {257, 129}};
    uint32_t s = 12345;
    for (size_t t = 0; t < sizeof sizes / sizeof sizes[0]; ++t) {
        for (int density = 1; density <= 99; density += 49) {
            int w = sizes[t][0], h = sizes[t][1];
            size_t n = (size_t)w * (size_t)h;
            float *z = malloc(n * sizeof *z), *orig = malloc(n * sizeof *z),
                  *again = malloc(n * sizeof *z);
            float lo = INFINITY, hi = -INFINITY;
            long holes = 0, expect = 0, holes2 = 0;
            hfs_error err;
            for (size_t k = 0; k < n; ++k) {
                if ((int)(rng(&s) % 100) < density && k != n / 2) {
                    z[k] = (rng(&s) & 1) ? NAN : INFINITY;
                    ++expect;
                } else {
                    z[k] = (float)(rng(&s) % 20000) * 0.05f - 300.0f;
                    lo = fminf(lo, z[k]);
                    hi = fmaxf(hi, z[k]);
                }
            }
            memcpy(orig, z, n * sizeof *z);
            memcpy(again, z, n * sizeof *z);
            CHECK(hfs_height_fill_holes(z, w, h, 0, 0.0f, &holes, &err) == 0);
            CHECK(holes == expect);
            for (size_t k = 0; k < n; ++k) {
                CHECK(isfinite(z[k]));
                CHECK(z[k] >= lo && z[k] <= hi);
                if (isfinite(orig[k]))
                    CHECK(z[k] == orig[k]);
            }
            CHECK(hfs_height_fill_holes(again, w, h, 0, 0.0f, &holes2, &err) == 0);
            CHECK(memcmp(z, again, n * sizeof *z) == 0); /* deterministic */
            free(z);
            free(orig);
            free(again);
        }
    }
}

static void test_errors(void)
{
    float z[4] = {NAN, INFINITY, -INFINITY, 3.0f};
    float copy[4];
    long holes = 99;
    hfs_error err;
    memcpy(copy, z, sizeof z);
    /* Nodata makes the last texel a hole too: nothing valid left. */
    CHECK(hfs_height_fill_holes(z, 2, 2, 1, 3.0f, &holes, &err) == HFS_E_FORMAT);
    CHECK(strstr(err.msg, "no valid heights") != NULL);
    CHECK(holes == 0);
    CHECK(memcmp(z, copy, sizeof z) == 0); /* untouched on error */
    CHECK(hfs_height_fill_holes(NULL, 2, 2, 0, 0.0f, NULL, &err) == HFS_E_INVALID);
    CHECK(hfs_height_fill_holes(z, 0, 2, 0, 0.0f, NULL, &err) == HFS_E_INVALID);
    CHECK(hfs_height_fill_holes(z, 2, -1, 0, 0.0f, NULL, NULL) == HFS_E_INVALID);
}

int main(void)
{
    test_single_hole_constant();
    test_nodata_value();
    test_two_values();
    test_random();
    test_errors();
    return finish_checks("test_io_fill");
}
