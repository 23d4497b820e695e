/*
 * test_gl_half.c — the fp16 conversions readback relies on (gl_util.h),
 * exhaustively, no driver needed:
 *   every non-NaN half survives half -> float -> half;
 *   half -> float matches the IEEE formula (sign, subnormals, inf);
 *   float -> half rounds to nearest even: every midpoint between neighbours
 *   goes to the even one, and a float ulp either side to the nearer one;
 *   overflow: 65504 stays, 65519.99 -> 65504, 65520 -> inf; NaN stays NaN;
 *   the branch-free float -> half (half.h) equals a reference written with
 *   branches on a stride through every float and on every float within
 *   2^14 ulps of each exponent boundary the halves span;
 *   the frame loops (hfs_half_split, hfs_half_sum_rgb, hfs_half_round_up:
 *   vectorized) equal
 *   their element-by-element forms bit for bit, odd lengths, infinities
 *   and NaN halves included.
 */
#include "gl_util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CHECK_MAX_MESSAGES 20
#include "check.h"

static double half_formula(unsigned h)
{
    int sign = (h >> 15) & 1, exp = (h >> 10) & 31, mant = h & 1023;
    double v = exp == 0 ? ldexp(mant, -24) : exp == 31 ? INFINITY
                                                      : ldexp(1024 + mant, exp - 25);
    return sign ? -v : v;
}

/* float -> half as the renderer wrote it before half.h (branches; the
 * subnormal halves rounded in integers). */
static unsigned ref_float_to_half(float f)
{
    uint32_t x;
    memcpy(&x, &f, sizeof x);
    unsigned sign = (x >> 16) & 0x8000u;
    uint32_t ax = x & 0x7fffffffu;
    if (ax > 0x7f800000u)
        return sign | 0x7e00u | ((ax >> 13) & 0x3ffu);
    if (ax >= 0x477ff000u)
        return sign | 0x7c00u;
    if (ax < 0x38800000u) {
        int shift = 126 - (int)(ax >> 23);
        if (shift > 24)
            return sign;
        uint32_t m = (ax & 0x7fffffu) | 0x800000u;
        uint32_t q = m >> shift, r = m & ((1u << shift) - 1), half = 1u << (shift - 1);
        if (r > half || (r == half && (q & 1u)))
            ++q;
        return sign | q;
    }
    uint32_t h = ((ax >> 23) - 127 + 15) << 10 | ((ax & 0x7fffffu) >> 13);
    uint32_t r = ax & 0x1fffu;
    if (r > 0x1000u || (r == 0x1000u && (h & 1u)))
        ++h;
    return sign | h;
}

static void check_against_reference(uint32_t bits)
{
    float f;
    memcpy(&f, &bits, sizeof f);
    unsigned want = ref_float_to_half(f), got = hfs_float_to_half(f);
    CHECK(got == want, "float 0x%08x -> 0x%04x, want 0x%04x", (unsigned)bits, got, want);
}

/* A fixed pseudo-random sequence (xorshift32). */
static uint32_t next(uint32_t *x)
{
    *x ^= *x << 13;
    *x ^= *x >> 17;
    *x ^= *x << 5;
    return *x;
}

static void check_bulk(void)
{
    enum { N = 1003 }; /* not a multiple of the block or of a vector */
    static float z[N];
    static uint16_t rg[2 * N], hi[4 * N], lo[4 * N];
    static float rgb[3 * N];
    uint32_t x = 12345;
    for (int i = 0; i < N; ++i)
        z[i] = (float)((double)next(&x) / 4294967296.0 * 3000.0 - 500.0);
    z[7] = 1e30f; /* beyond the halves' range */
    const double base = 1000.0, scale = 1500.0;
    double worst = 0.0;
    static uint16_t rg_unmeasured[2 * N];
    const double none = hfs_half_split(z, N, base, scale, rg_unmeasured, 0);
    const double got_worst = hfs_half_split(z, N, base, scale, rg, 1);
    CHECK(none == 0.0 && memcmp(rg, rg_unmeasured, sizeof rg) == 0,
          "split without its error: other halves, or an error %g", none);
    for (int i = 0; i < N; ++i) {
        const double v = ((double)z[i] - base) / scale;
        const uint16_t h = hfs_float_to_half((float)v);
        const double hv = hfs_half_to_float(h);
        const uint16_t l = hfs_float_to_half((float)(v - hv));
        const double e = fabs(hv + (double)hfs_half_to_float(l) - v);
        worst = e > worst ? e : worst;
        CHECK(rg[2 * i] == h && rg[2 * i + 1] == l, "split %d: 0x%04x 0x%04x, want 0x%04x 0x%04x",
              i, rg[2 * i], rg[2 * i + 1], h, l);
    }
    CHECK(memcmp(&got_worst, &worst, sizeof worst) == 0, "split error %g, want %g", got_worst,
          worst);
    for (int i = 0; i < 4 * N; ++i) {
        hi[i] = (uint16_t)next(&x);
        lo[i] = (uint16_t)(next(&x) & 0x87ffu); /* mostly small, as a remainder is */
    }
    /* round up: v exactly on halves (kept), between them (the next up), on
     * both sides of 0 */
    static double vu[N];
    static uint16_t up[N];
    for (int i = 0; i < N; ++i) {
        const uint16_t h = (uint16_t)(next(&x) & 0xfbffu); /* finite */
        const double hv = hfs_half_to_float(h);
        vu[i] = i % 3 == 0 ? hv : hv * (1.0 + ((double)next(&x) / 4294967296.0 - 0.5) * 1e-3);
    }
    vu[0] = -0.0, vu[1] = 0.0, vu[2] = -1e-30, vu[3] = 1e-30, vu[4] = 65504.0;
    hfs_half_round_up(vu, N, up);
    for (int i = 0; i < N; ++i) {
        uint16_t h = hfs_float_to_half((float)vu[i]);
        if (!((double)hfs_half_to_float(h) >= vu[i]))
            h = h == 0x8000u ? 0x0001u : (h & 0x8000u) ? (uint16_t)(h - 1u) : (uint16_t)(h + 1u);
        CHECK(up[i] == h, "round up %d (%.9g): 0x%04x, want 0x%04x", i, vu[i], up[i], h);
        CHECK((double)hfs_half_to_float(up[i]) >= vu[i], "round up %d below %.9g", i, vu[i]);
    }
    hi[5] = 0x7c00u, hi[9] = 0xfe01u, lo[10] = 0x7bffu, hi[10] = 0x7bffu;
    const double inv = 1.0 / 3.7;
    hfs_half_sum_rgb(hi, lo, N, inv, rgb);
    for (int i = 0; i < N; ++i)
        for (int c = 0; c < 3; ++c) {
            const int k = 4 * i + c;
            const double v = ((double)hfs_half_to_float(hi[k]) + hfs_half_to_float(lo[k])) * inv;
            const float want = isfinite(v) ? (float)v : 0.0f;
            CHECK(memcmp(&rgb[3 * i + c], &want, sizeof want) == 0, "sum %d.%d: %g, want %g",
                  i, c, rgb[3 * i + c], want);
        }
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

    /* The branch-free conversion against the reference: a stride through
     * every float (a prime, so every mantissa pattern's low bits turn up),
     * then each exponent boundary from 2^-26 to 2^17 and the infinities,
     * 2^14 floats either side, both signs. */
    for (uint64_t b = 0; b <= 0xffffffffu; b += 4093)
        check_against_reference((uint32_t)b);
    for (uint32_t e = 101; e <= 144 || e == 255; e = e == 144 ? 255 : e + 1)
        for (uint32_t d = 0; d < 1u << 15; ++d) {
            uint32_t b = (e << 23) - (1u << 14) + d;
            check_against_reference(b);
            check_against_reference(b | 0x80000000u);
        }

    check_bulk();

    if (failures) {
        printf("FAIL: %d check(s) failed\n", failures);
        return 1;
    }
    printf("PASS\n");
    return 0;
}
