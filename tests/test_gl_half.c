/*
 * test_gl_half.c — the fp16 conversions readback relies on (gl_util.h),
 * exhaustively, no driver needed:
 *   every non-NaN half survives half -> float -> half;
 *   half -> float matches the IEEE formula (sign, subnormals, inf);
 *   float -> half rounds to nearest even: every midpoint between neighbours
 *   goes to the even one, and a float ulp either side to the nearer one;
 *   overflow: 65504 stays, 65519.99 -> 65504, 65520 -> inf; NaN stays NaN.
 */
#include "gl_util.h"

#include <math.h>
#include <stdio.h>

#define CHECK_MAX_MESSAGES 20
#include "check.h"

static double half_formula(unsigned h)
{
    int sign = (h >> 15) & 1, exp = (h >> 10) & 31, mant = h & 1023;
    double v = exp == 0 ? ldexp(mant, -24) : exp == 31 ? INFINITY
                                                      : ldexp(1024 + mant, exp - 25);
    return sign ? -v : v;
}

int main(void)
{
    setvbuf(stdout, NULL, _IONBF, 0); /* keep order with stderr in logs */
    for (unsigned h = 0; h < 65536; ++h) {
        float f = hfs_half_to_float((uint16_t)h);
        int nan = ((h >> 10) & 31) == 31 && (h & 1023);
        if (nan) {
            CHECK(isnan(f), "half 0x%04x not NaN", h);
            CHECK(isnan(hfs_half_to_float(hfs_float_to_half(f))), "NaN 0x%04x lost", h);
            continue;
        }
        CHECK((double)f == half_formula(h), "half 0x%04x -> %.9g, want %.9g", h, f,
              half_formula(h));
        CHECK(hfs_float_to_half(f) == h, "round trip 0x%04x -> 0x%04x", h,
              hfs_float_to_half(f));
    }

    /* Midpoints between positive neighbours a < b (exact in float: 12 bits). */
    for (unsigned a = 0; a < 0x7bff; ++a) {
        unsigned b = a + 1;
        float fa = hfs_half_to_float((uint16_t)a), fb = hfs_half_to_float((uint16_t)b);
        float mid = (float)(((double)fa + (double)fb) / 2.0);
        unsigned even = (a & 1) ? b : a;
        CHECK(hfs_float_to_half(mid) == even, "midpoint 0x%04x/0x%04x -> 0x%04x", a, b,
              hfs_float_to_half(mid));
        CHECK(hfs_float_to_half(nextafterf(mid, 0.0f)) == a, "below midpoint 0x%04x", a);
        CHECK(hfs_float_to_half(nextafterf(mid, INFINITY)) == b, "above midpoint 0x%04x", a);
        CHECK(hfs_float_to_half(-mid) == (even | 0x8000), "negative midpoint 0x%04x", a);
    }

    CHECK(hfs_float_to_half(65504.0f) == 0x7bff, "max half");
    CHECK(hfs_float_to_half(65519.99f) == 0x7bff, "just below overflow");
    CHECK(hfs_float_to_half(65520.0f) == 0x7c00, "overflow to inf");
    CHECK(hfs_float_to_half(-1e30f) == 0xfc00, "-overflow");
    CHECK(hfs_float_to_half(INFINITY) == 0x7c00, "inf");
    CHECK(hfs_float_to_half(0x1p-25f) == 0x0000, "2^-25 ties to 0");
    CHECK(hfs_float_to_half(nextafterf(0x1p-25f, 1.0f)) == 0x0001, "above 2^-25");
    CHECK(hfs_float_to_half(1e-30f) == 0x0000, "tiny");
    CHECK(hfs_float_to_half(-0.0f) == 0x8000, "-0");
    CHECK(hfs_float_to_half(0x1p-149f) == 0x0000, "float denormal");
    CHECK(isnan(hfs_half_to_float(hfs_float_to_half(NAN))), "NaN");

    if (failures) {
        printf("FAIL: %d check(s) failed\n", failures);
        return 1;
    }
    printf("PASS\n");
    return 0;
}
