/*
 * half.h — IEEE 754 binary16 <-> binary32, inline and branch-free.
 *
 * The host converts every height it uploads and every texel it reads back
 * (two halves a channel: the lit targets' hi and lo) through these, a few
 * million a frame at 1024²; written as selects instead of branches so that
 * the loops over a frame vectorize (issue 37: the host's part of a frame).
 * Exact for every half (subnormals, infinities, NaN payload top bits);
 * float -> half rounds to nearest even and overflows to infinity.  Both
 * need the default floating-point environment (round to nearest, no
 * flush-to-zero): the subnormal halves are rounded by the FPU's own add.
 * tests/test_gl_half.c checks both against the IEEE formulas, and float ->
 * half against a reference with branches over a stride of every float.
 */
#ifndef HFS_GL_HALF_H
#define HFS_GL_HALF_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

static inline float hfs_half_to_float(uint16_t h)
{
    /* Normal halves: exponent and mantissa shifted into a float's place and
     * the exponent rebiased (15 -> 127) in integers.  Subnormal ones: the
     * mantissa times 2^-24, exact and a normal float, so no arithmetic on
     * float subnormals (which costs a microcode assist on x86, 100 cycles:
     * the lit targets' lo halves are mostly subnormal).  Inf/NaN (exponent
     * 31) get a float exponent of all ones. */
    const uint32_t e = h & 0x7c00u, m = h & 0x3ffu;
    const uint32_t normal = ((uint32_t)(h & 0x7fffu) << 13) + ((127u - 15u) << 23);
    const float sub = (float)m * 0x1p-24f;
    uint32_t sb, bits;
    memcpy(&sb, &sub, sizeof sb);
    bits = e == 0 ? sb : (e == 0x7c00u ? 0x7f800000u | (m << 13) : normal);
    bits |= (uint32_t)(h & 0x8000u) << 16;
    float f;
    memcpy(&f, &bits, sizeof f);
    return f;
}

static inline uint16_t hfs_float_to_half(float f)
{
    uint32_t x;
    memcpy(&x, &f, sizeof x);
    const uint32_t sign = (x >> 16) & 0x8000u, ax = x & 0x7fffffffu;
    /* Normal halves: the exponent rebiased (127 -> 15), the 13 dropped
     * mantissa bits rounded to nearest even (0xfff plus the kept part's
     * lowest bit); a carry into the exponent is the right answer, up to
     * 65504's neighbour.  Wraps for small ax, where it is not selected. */
    const uint32_t normal = (ax - ((127u - 15u) << 23) + 0xfffu + ((ax >> 13) & 1u)) >> 13;
    /* Below 2^-14: |f| + 0.5 puts the half's subnormal unit (2^-24) on the
     * float's last mantissa bit, so the add rounds to nearest even and the
     * bits above 0.5's are the half's (1024 = 2^-14 is the smallest normal,
     * encoded the same). */
    float a, s;
    memcpy(&a, &ax, sizeof a);
    s = a + 0.5f;
    uint32_t sb;
    memcpy(&sb, &s, sizeof sb);
    uint32_t h = ax < 0x38800000u ? sb - 0x3f000000u : normal;
    h = ax >= 0x477ff000u ? 0x7c00u : h; /* >= 65520 (and inf) round to inf */
    h = ax > 0x7f800000u ? 0x7e00u | ((ax >> 13) & 0x3ffu) : h; /* quiet NaN, top payload */
    return (uint16_t)(sign | h);
}

/* ---- over a frame (half_bulk.c: vectorized, bit-identical to the loops
 * of the functions above) ---- */

/* v = (z[i] - base) / scale (double) as two halves, hi = v rounded and
 * lo = v - hi rounded, interleaved in rg (2 n halves); returns the largest
 * |hi + lo - v| when `measure`, else 0 (a frame's upload does not read it:
 * a third of the loop's time). */
double hfs_half_split(const float *z, size_t n, double base, double scale, uint16_t *rg,
                      int measure);

/* The caller's image from a lit target's two halves: rgb[3 i + c] =
 * (hi[4 i + c] + lo[4 i + c]) inv summed in double, 0 where that is not
 * finite; hi and lo are RGBA, npx pixels. */
void hfs_half_sum_rgb(const uint16_t *hi, const uint16_t *lo, size_t npx, double inv,
                      float *rgb);

/* out[i] = the least half >= v[i] (v finite and within the halves' range;
 * a bound rounded this way may only err high). */
void hfs_half_round_up(const double *v, size_t n, uint16_t *out);

#endif /* HFS_GL_HALF_H */
