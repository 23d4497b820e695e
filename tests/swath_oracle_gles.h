/*
 * swath_oracle_gles.h — test_swath_oracle.c's GLES side (runtime/gles/
 * uniform_blocks.c, no driver): hfs_gles_pack_swath / pack_key of the
 * oracle's swaths against the closed form (swath_oracle_def.h): header
 * (elev_lo, elev_hi, n, full) as the float of the closed-form window, the
 * occlusion vector of elev_hi, the sample directions (cos, sin)(k 2 pi / N)
 * within the 64 float ulps uniform_blocks.h allows for its nudge, the wedge
 * placements (cos m a, sin m a, mirror) at the closed-form wedge starts,
 * the key record header.
 *
 * Static functions and their worst cases (printed by the test): include
 * once, after check.h and swath_oracle_def.h.
 */
#ifndef HFS_TEST_SWATH_ORACLE_GLES_H
#define HFS_TEST_SWATH_ORACLE_GLES_H

#include "sh.h"
#include "uniform_blocks.h"
#include "visibility.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static double worst_dir_ulps, worst_place_err, worst_occ_err; /* printed by the test */
static long n_gles;                                          /* blocks checked */

static double ulpf(float f)
{
    const float a = fabsf(f);
    return (double)nextafterf(a, INFINITY) - (double)a;
}

/* The GLES std140 swath block of s against the closed form (k0, N). */
/* A key record's swath block (hfs_gles_pack_key) against the light's own
 * (b, hfs_gles_pack_swath): the same but for the direction matrices, which
 * come folded with the light and the clamped cosine (uniform_blocks.c
 * fold_key_matrices): for normals N, sum_i Y_i(N) A_j[i] must equal
 * C_j^T (H(N) * L), H(N) the clamped cosine about N, as the CPU forms it. */
static void check_key_swath(const float *kb, const float *b, int n, const hfs_gles_key *k,
                            const char *id)
{
    const size_t head = 2 + (size_t)n, mat = 16 * (size_t)n, all = hfs_gles_swath_vec4(n);
    CHECK(!memcmp(kb, b, head * 4 * sizeof *b) &&
              !memcmp(kb + (head + mat) * 4, b + (head + mat) * 4,
                      (all - head - mat) * 4 * sizeof *b),
          "gles: key record's swath block outside its matrices (%s)", id);
    static const double normals[3][3] = {{0.0, 0.0, 1.0}, {0.6, -0.3, 0.74}, {-0.9, 0.1, 0.42}};
    double zc[HFS_ZH_N], worst = 0.0, scale = 0.0;
    hfs_zh_clamped_cosine(zc);
    for (int t = 0; t < 3; ++t) {
        const double *nv = normals[t], len = sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]);
        double h[HFS_SH_N], m[HFS_SH_N], y[HFS_SH_N];
        hfs_sh_rotate_zonal(zc, nv[0] / len, nv[1] / len, nv[2] / len, h);
        hfs_sh_product(h, k->l_sh, m);
        hfs_sh_eval(nv[0] / len, nv[1] / len, nv[2] / len, y);
        for (int j = 0; j < n; ++j)
            for (int q = 0; q < 4; ++q) {
                double want = 0.0, got = 0.0;
                for (int r = 0; r < HFS_SH_N; ++r) {
                    want += b[(head + 16 * j + r) * 4 + q] * m[r];
                    got += kb[(head + 16 * j + r) * 4 + q] * y[r];
                    scale = fmax(scale, fabs(b[(head + 16 * j + r) * 4 + q] * m[r]));
                }
                worst = fmax(worst, fabs(got - want));
            }
    }
    /* float storage of both matrices (2^-24 relative) over 16-term sums */
    CHECK(worst <= 1e-5 * fmax(scale, 1e-30), "gles: key record's folded matrices off by %.3g "
          "(of terms up to %.3g) (%s)", worst, scale, id);
}

static void check_gles_block(const hfs_gles_layout *L, const hfs_swath *s, long long k0, double N,
                             const expect *x_or_null, int is_env, const char *id)
{
    hfs_visibility *v = NULL;
    hfs_error err;
    if (hfs_visibility_create(s, HFS_VIS_LEGENDRE, &v, &err)) {
        CHECK(0, "gles: visibility_create: %s (%s)", err.msg, id);
        return;
    }
    ++n_gles;
    const int n = s->n;
    float *b = calloc(hfs_gles_swath_vec4(n) * 4, sizeof *b);
    hfs_gles_pack_swath(L, v, b);
    const double lo = is_env ? -HALF_PI : x_or_null->lo, hi = is_env ? HALF_PI : x_or_null->hi;
    const int full = is_env ? 1 : x_or_null->full;
    CHECK(b[0] == (float)lo && b[1] == (float)hi, "gles: window (%.9g, %.9g), want (%.9g, %.9g) (%s)", b[0], b[1],
          (float)lo, (float)hi, id);
    CHECK(b[2] == (float)n && (x_or_null && x_or_null->full_ambiguous ? 1 : b[3] == (float)full),
          "gles: header n %g full %g (%s)", b[2], b[3], id);
    double occ[4];
    occ_closed(hi, occ);
    for (int c = 0; c < 4; ++c) {
        const double e = fabs(b[4 + c] - occ[c]);
        worst_occ_err = fmax(worst_occ_err, e);
        /* float rounding of values <= sqrt(2): 1.2e-7; measured 6e-8 */
        CHECK(e <= 3e-7, "gles: occlusion(elev_hi)[%d] = %.9g, closed form %.9g (%s)", c, b[4 + c], occ[c], id);
    }
    /* directions: sample j at lattice point k0 + j */
    for (int j = 0; j < n; ++j) {
        const double m = fmod((double)(k0 + j), N);
        const double ang = TWO_PI * (m < 0 ? m + N : m) / N;
        const double c = cos(ang), sn = sin(ang);
        const float fc = b[(2 + j) * 4], fs = b[(2 + j) * 4 + 1];
        const double uc = (fabs(fc - c) - 0.5 * ulpf((float)c)) / ulpf((float)c);
        const double us = (fabs(fs - sn) - 0.5 * ulpf((float)sn)) / ulpf((float)sn);
        if (fabs(c) >= 1e-12)
            worst_dir_ulps = fmax(worst_dir_ulps, uc);
        if (fabs(sn) >= 1e-12)
            worst_dir_ulps = fmax(worst_dir_ulps, us);
        /* uniform_blocks.h: the float nearest to (cos, sin), or a neighbour
         * within 64 ulps; |c| < 1e-12 is snapped to 0 */
        CHECK((uc <= 64.5 || fabs(c) < 1e-12) && (us <= 64.5 || fabs(sn) < 1e-12),
              "gles: direction %d = (%.9g, %.9g), lattice point %lld of %.0f gives (%.9g, %.9g) (%s)", j, fc, fs,
              (long long)(k0 + j), N, c, sn, id);
    }
    /* wedge placements */
    const float *rot = b + (2 + 17 * (size_t)n) * 4;
    const int n_wedges = full ? n : n + 1;
    for (int w = 0; w < n_wedges; ++w) {
        double kk;
        int mirror = 0;
        if (full)
            kk = w;
        else if (w == 0)
            kk = (double)k0, mirror = 1; /* start boundary: mirrored, placed at its inner end */
        else if (w == n)
            kk = (double)(k0 + n - 1);
        else
            kk = (double)(k0 + w - 1);
        double mm = fmod(kk, N);
        const double a = TWO_PI * (mm < 0 ? mm + N : mm) / N;
        const float *r = rot + 8 * (size_t)w;
        double e = 0.0;
        for (int m = 1; m <= 3; ++m)
            e = fmax(e, fmax(fabs(r[m - 1] - cos(m * a)), fabs(r[4 + m - 1] - sin(m * a))));
        worst_place_err = fmax(worst_place_err, e);
        /* float rounding (6e-8) of cos/sin of an angle computed in double
         * from phi0 + j dphi; measured 6e-8 */
        CHECK(e <= 6e-7 && r[3] == (float)mirror, "gles: wedge %d placement off by %.3g (mirror %g, want %d) (%s)",
              w, e, r[3], mirror, id);
    }
    /* the key record around it */
    if (!is_env) {
        hfs_gles_key k;
        memset(&k, 0, sizeof k);
        k.swath = *s;
        k.alpha = 0.01;
        k.dir[0] = 0.25, k.dir[1] = -0.5, k.dir[2] = 0.75;
        k.le[0] = 1, k.le[1] = 2, k.le[2] = 3;
        for (int i = 0; i < 16; ++i)
            k.l_sh[i] = i - 7.5;
        k.l_norm = 4.5;
        k.hz_layer = 6;
        k.table_set = 2;
        float *kr = calloc(hfs_gles_key_vec4(n) * 4, sizeof *kr);
        hfs_gles_pack_key(L, &k, v, kr);
        CHECK(kr[0] == (float)n && kr[2] == 6.0f && kr[3] == 2.0f &&
                  (x_or_null->full_ambiguous || kr[1] == (float)x_or_null->full),
              "gles: key record header (%g %g %g %g) (%s)", kr[0], kr[1], kr[2], kr[3], id);
        CHECK(kr[4] == 0.25f && kr[5] == -0.5f && kr[6] == 0.75f && kr[7] == 0.01f && kr[8] == 1.0f &&
                  kr[10] == 3.0f && kr[11] == 4.5f && kr[12] == -7.5f && kr[27] == 7.5f,
              "gles: key record body (%s)", id);
        check_key_swath(kr + 7 * 4, b, n, &k, id);
        free(kr);
    }
    free(b);
    hfs_visibility_destroy(v);
}

#endif /* HFS_TEST_SWATH_ORACLE_GLES_H */
