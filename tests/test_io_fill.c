/*
 * test_io_fill.c — hfs_height_fill_holes() (push-pull): exact cases (a hole in
 * a constant field gets the constant), the hole count, valid texels never
 * change, every output finite and inside the range of the valid inputs,
 * determinism, odd and degenerate sizes, nodata value vs NaN/Inf, the
 * all-holes error, and that z is untouched on error; and the values the
 * method gives on ramps with a missing border line or corner, at every
 * border, odd and even sizes (test_ramp_*: derivation there).
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

/* ---- ramps with a missing border line or corner ------------------------------- */

/* What push-pull gives on a ramp z = a i + b j, derived from the method (not
 * from a run):
 *   - Every fill is a mean of valid heights, so it never extrapolates: a
 *     ramp is NOT reproduced across a missing border line.  (A bug report
 *     expected 6 for a 7-wide ramp z = i missing its last column: that is
 *     above every valid height, 0..5.  The old code gave 4.5.)
 *   - With one border line missing, every level-1 texel still has a valid
 *     child, and the mean of a ramp over texels is the ramp at their
 *     centroid: a level-1 texel on the missing line holds the ramp at the
 *     next line in (its block's other texels; on an odd level, whose last
 *     block is the last line alone, that line is all holes and the texel
 *     takes the next line), and along the border at its block's centre:
 *     2X + 0.5, or n - 1 for the last texel of an odd n (its one child).
 *   - A hole on the line lies at or beyond the level-1 centres across the
 *     border, so it reads the border texels alone, and along the border it
 *     interpolates them linearly: exact for a ramp between the first and
 *     last centre, clamped beyond.  So the missing last column gets
 *       z(W-1, j) = a (W - 2) + b clamp(j, lo(H), hi(H)),
 *     the first column a + b clamp(j, lo(H), hi(H)), and the rows likewise,
 *     with lo(n) = 0.5 (the centre of texels 0 and 1; 0 when n = 1) and
 *     hi(n) = n - 1.5 for even n, n - 1 for odd n.  For the 7-wide ramp:
 *     5, the next column's height, as the first column gets 1. */
static double line_lo(int n)
{
    return n == 1 ? 0.0 : 0.5;
}

static double line_hi(int n)
{
    return n % 2 ? n - 1.0 : n - 1.5;
}

static double clampd(double v, double lo, double hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

static int near(double got, double want)
{
    return fabs(got - want) <= 1e-5 * (1.0 + fabs(want));
}

/* side: 0 first column, 1 last column, 2 first row, 3 last row. */
static const char *side_name[4] = {"first column", "last column", "first row", "last row"};

static void check_ramp_line(int w, int h, double a, double b, int side)
{
    const size_t n = (size_t)w * (size_t)h;
    float *z = malloc(n * sizeof *z);
    long holes = 0, expect = 0, wrong = 0;
    double worst_got = 0.0, worst_want = 0.0;
    int worst_i = -1, worst_j = -1;
    hfs_error err;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const int hole = (side == 0 && i == 0) || (side == 1 && i == w - 1) ||
                             (side == 2 && j == 0) || (side == 3 && j == h - 1);
            z[(size_t)j * w + i] = hole ? NAN : (float)(a * i + b * j);
            expect += hole;
        }
    CHECK(hfs_height_fill_holes(z, w, h, 0, 0.0f, &holes, &err) == 0);
    CHECK(holes == expect);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            double want = a * i + b * j; /* valid texels never change */
            if (side == 0 && i == 0)
                want = a * 1 + b * clampd(j, line_lo(h), line_hi(h));
            else if (side == 1 && i == w - 1)
                want = a * (w - 2) + b * clampd(j, line_lo(h), line_hi(h));
            else if (side == 2 && j == 0)
                want = a * clampd(i, line_lo(w), line_hi(w)) + b * 1;
            else if (side == 3 && j == h - 1)
                want = a * clampd(i, line_lo(w), line_hi(w)) + b * (h - 2);
            const double got = z[(size_t)j * w + i];
            if (!near(got, want)) {
                if (!wrong++ || fabs(got - want) > fabs(worst_got - worst_want)) {
                    worst_got = got, worst_want = want;
                    worst_i = i, worst_j = j;
                }
            }
        }
    if (wrong) {
        fprintf(stderr, "%s:%d: ramp %gi+%gj %dx%d, %s missing: %ld texel(s) wrong, worst (%d,%d) "
                "= %.6g, derived %.6g\n", __FILE__, __LINE__, a, b, w, h, side_name[side], wrong,
                worst_i, worst_j, worst_got, worst_want);
        ++failures;
    }
    free(z);
}

static void test_ramp_border_lines(void)
{
    /* Odd and even sides, both orders, 1-wide fields, and odd sizes whose
     * halvings stay odd for a few levels (5, 9, 13: the old code's worst). */
    static const int sizes[][2] = {{6, 6}, {7, 7}, {6, 7}, {7, 6}, {8, 3}, {9, 5}, {5, 9},
                                   {13, 11}, {2, 2}, {3, 3}, {2, 3}, {7, 1}, {1, 7}};
    static const double ramps[][2] = {{1, 0}, {0, 1}, {1, 2}};
    for (size_t t = 0; t < sizeof sizes / sizeof sizes[0]; ++t)
        for (size_t r = 0; r < sizeof ramps / sizeof ramps[0]; ++r)
            for (int side = 0; side < 4; ++side) {
                const int w = sizes[t][0], h = sizes[t][1];
                if ((side < 2 && w == 1) || (side >= 2 && h == 1))
                    continue; /* the line is the whole field */
                check_ramp_line(w, h, ramps[r][0], ramps[r][1], side);
            }

    /* The bug report's field, spelled out: 0 1 2 3 4 5 NaN -> 5. */
    float z[7] = {0, 1, 2, 3, 4, 5, NAN};
    long holes = 0;
    hfs_error err;
    CHECK(hfs_height_fill_holes(z, 7, 1, 0, 0.0f, &holes, &err) == 0);
    CHECK(holes == 1 && z[6] == 5.0f);
}

/* One missing corner texel: its level-1 parent holds the mean of the
 * corner's valid block-mates (the other texels of its 2x2 block; on an odd
 * side the last block is the last line alone, and when that leaves the
 * corner no block-mate at all, odd x odd, the parent takes the corner's row
 * and column neighbours), and the corner, at or beyond that parent's centre
 * on both axes, reads it alone.  On a ramp, e.g. at (W-1, H-1): even x even
 * a (W - 5/3) + b (H - 5/3); odd x even a (W - 1) + b (H - 2); odd x odd
 * a (W - 3/2) + b (H - 3/2); at (0, 0) always 2/3 (a + b). */
static void block_range(int c, int n, int *lo, int *hi)
{
    const int first = c - c % 2; /* the block starts at an even index */
    *lo = first;
    *hi = first + 1 < n ? first + 1 : first;
}

static void test_ramp_corners(void)
{
    static const int sizes[][2] = {{6, 6}, {7, 7}, {6, 7}, {7, 6}, {9, 5}, {2, 2}, {3, 3},
                                   {2, 3}, {13, 11}};
    static const double ramps[][2] = {{1, 0}, {0, 1}, {1, 2}};
    for (size_t t = 0; t < sizeof sizes / sizeof sizes[0]; ++t)
        for (size_t r = 0; r < sizeof ramps / sizeof ramps[0]; ++r)
            for (int corner = 0; corner < 4; ++corner) {
                const int w = sizes[t][0], h = sizes[t][1];
                const double a = ramps[r][0], b = ramps[r][1];
                const int ci = corner & 1 ? w - 1 : 0, cj = corner & 2 ? h - 1 : 0;
                const size_t n = (size_t)w * (size_t)h;
                float *z = malloc(n * sizeof *z);
                long holes = 0;
                hfs_error err;
                for (int j = 0; j < h; ++j)
                    for (int i = 0; i < w; ++i)
                        z[(size_t)j * w + i] = (float)(a * i + b * j);
                z[(size_t)cj * w + ci] = NAN;
                CHECK(hfs_height_fill_holes(z, w, h, 0, 0.0f, &holes, &err) == 0);
                CHECK(holes == 1);
                int x0, x1, y0, y1, count = 0;
                double sum = 0.0;
                block_range(ci, w, &x0, &x1);
                block_range(cj, h, &y0, &y1);
                for (int j = y0; j <= y1; ++j)
                    for (int i = x0; i <= x1; ++i)
                        if (i != ci || j != cj)
                            sum += a * i + b * j, ++count;
                if (!count) /* odd x odd, high corner */
                    sum = a * (ci - 1) + b * cj + a * ci + b * (cj - 1), count = 2;
                const double want = sum / count, got = z[(size_t)cj * w + ci];
                if (!near(got, want)) {
                    fprintf(stderr, "%s:%d: ramp %gi+%gj %dx%d, corner (%d,%d) missing: %.6g, "
                            "derived %.6g\n", __FILE__, __LINE__, a, b, w, h, ci, cj, got, want);
                    ++failures;
                }
                free(z);
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
    test_ramp_border_lines();
    test_ramp_corners();
    test_errors();
    return finish_checks("test_io_fill");
}
