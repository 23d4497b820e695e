/*
 * half_bulk.c — the host's loops over a frame's halves (half.h): the
 * heights split into hi + lo halves for upload, the lit targets' hi + lo
 * halves summed into the caller's image.  Each works in blocks, one simple
 * loop per step, so that the compiler vectorizes them; this file alone is
 * built with -O3 -fno-trapping-math (runtime/gl/CMakeLists.txt: GCC keeps
 * the selects of half.h as branches while floating-point traps are
 * honoured, and vectorizes at -O3 only).  Results are bit-identical to the
 * element-by-element forms (tests/test_gl_half.c checks both).
 */
#include "half.h"

#include <math.h>

#define BLOCK 256

double hfs_half_split(const float *z, size_t n, double base, double scale, uint16_t *rg,
                      int measure)
{
    double worst = 0.0;
    for (size_t s = 0; s < n; s += BLOCK) {
        const size_t m = n - s < BLOCK ? n - s : BLOCK;
        double v[BLOCK], hv[BLOCK], e[BLOCK];
        uint16_t hi[BLOCK], lo[BLOCK];
        for (size_t i = 0; i < m; ++i)
            v[i] = ((double)z[s + i] - base) / scale;
        for (size_t i = 0; i < m; ++i)
            hi[i] = hfs_float_to_half((float)v[i]);
        for (size_t i = 0; i < m; ++i)
            hv[i] = hfs_half_to_float(hi[i]);
        for (size_t i = 0; i < m; ++i)
            lo[i] = hfs_float_to_half((float)(v[i] - hv[i]));
        for (size_t i = 0; i < m; ++i) {
            rg[2 * (s + i)] = hi[i];
            rg[2 * (s + i) + 1] = lo[i];
        }
        if (!measure)
            continue;
        for (size_t i = 0; i < m; ++i)
            e[i] = fabs(hv[i] + (double)hfs_half_to_float(lo[i]) - v[i]);
        for (size_t i = 0; i < m; ++i)
            worst = e[i] > worst ? e[i] : worst;
    }
    return worst;
}

void hfs_half_sum_rgb(const uint16_t *hi, const uint16_t *lo, size_t npx, double inv,
                      float *rgb)
{
    for (size_t s = 0; s < npx; s += BLOCK) {
        const size_t m = npx - s < BLOCK ? npx - s : BLOCK;
        float a[4 * BLOCK], b[4 * BLOCK];
        double v[4 * BLOCK];
        for (size_t i = 0; i < 4 * m; ++i)
            a[i] = hfs_half_to_float(hi[4 * s + i]);
        for (size_t i = 0; i < 4 * m; ++i)
            b[i] = hfs_half_to_float(lo[4 * s + i]);
        for (size_t i = 0; i < 4 * m; ++i)
            v[i] = ((double)a[i] + b[i]) * inv;
        for (size_t i = 0; i < 4 * m; ++i)
            a[i] = isfinite(v[i]) ? (float)v[i] : 0.0f;
        for (size_t i = 0; i < m; ++i)
            for (int c = 0; c < 3; ++c)
                rgb[3 * (s + i) + (size_t)c] = a[4 * i + (size_t)c];
    }
}

void hfs_half_round_up(const double *v, size_t n, uint16_t *out)
{
    for (size_t s = 0; s < n; s += BLOCK) {
        const size_t m = n - s < BLOCK ? n - s : BLOCK;
        uint16_t h[BLOCK];
        for (size_t i = 0; i < m; ++i)
            h[i] = hfs_float_to_half((float)v[s + i]);
        /* below v: one pattern further up (half patterns step monotonically
         * in magnitude: away from 0 for positives, towards it for
         * negatives; -0 up to the least positive) */
        for (size_t i = 0; i < m; ++i) {
            const uint16_t up = h[i] == 0x8000u ? (uint16_t)0x0001u
                                : (h[i] & 0x8000u) ? (uint16_t)(h[i] - 1u)
                                                   : (uint16_t)(h[i] + 1u);
            out[s + i] = (double)hfs_half_to_float(h[i]) >= v[s + i] ? h[i] : up;
        }
    }
}
