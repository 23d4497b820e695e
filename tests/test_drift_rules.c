/*
 * test_drift_rules.c — the rules behind split horizons and an environment
 * map's slices, checked directly (issue 35, deliverable 2): bugs there
 * move the CPU reference and GLES alike (both take them from hfs_core), by
 * less than a comparison with the ground truth can tell apart from its own
 * error, so each rule is checked against a closed form written out here
 * (label "unit", no device).
 *
 *   split       (runtime/core/split_horizon.h)
 *     turns     hfs_split_turn: sub-direction h of K sits at the centre of
 *               the h-th of K equal parts of its direction's wedge: evenly
 *               spaced, symmetric, their mean the direction itself;
 *     swath     hfs_split_swath: the far sub-directions as a full swath of
 *               K n, sub-direction h of direction j at phi_j + turn(h) (the
 *               CPU's far grid and the GLES far pass read their azimuths
 *               here, the GLES transfer its turns from hfs_split_turn: the
 *               two must agree);
 *     boundary  hfs_split_near_count, hfs_split_first_far: the near scales
 *               are exactly those at most far-from texels away (counted
 *               here in integers: scale m at 2^(m/k) texels is near iff
 *               2^m <= from^k), the far grid starts at the next one;
 *     make      hfs_split_make: far-from, sub-directions, grid step by
 *               subsample (DESIGN.md "Split horizons": 8/3/2 at 1, 16/2/8
 *               at 2, 16/2/16 at 4), overrides, the near part's refining (2
 *               at most on a sub-sampled grid) and the far part's (refine at
 *               every subsample), on only on the slice path (bounces or
 *               not: their bands are clipped per sub-horizon, issue 36);
 *     far       hfs_split_far_slope (an occluder moved in proportion within
 *               a grid step), hfs_split_above_plane's tie, and hfs_split_band
 *               (bounce bands clipped per sub-horizon tile the occluded part);
 *     snap      hfs_split_far_snap: where a texel reads a grid beside a
 *               wall's top, case by case;
 *   map_slices  (runtime/core/env_map_slices.h) a map lit in one sector of
 *               azimuths: each slice's occluded part under a flat receiver
 *               fully blocked is -dphi/2 times the map's mean over exactly
 *               its wedge [phi_j - dphi/2, phi_j + dphi/2] (turned by the
 *               sky's rotation), which is computed here from the sector.
 *
 *   test_drift_rules split|map_slices
 */
#include "env_map_slices.h"
#include "pyramid_layout.h"
#include "slice_light.h"
#include "split_horizon.h"
#include "visibility.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

#define PI 3.14159265358979323846
#define TOL 1e-12

/* |a - b| as angles (mod 2 pi). */
static double angle_diff(double a, double b)
{
    return fabs(remainder(a - b, 2.0 * PI));
}

static void check_turns(void)
{
    static const int ns[] = {12, 16, 7};
    for (int a = 0; a < 3; ++a)
        for (int k = 1; k <= HFS_SPLIT_MAX_K; ++k) {
            const double dphi = 2.0 * PI / ns[a];
            double sum = 0.0;
            for (int h = 0; h < k; ++h) {
                const double t = hfs_split_turn(h, k, dphi);
                /* the h-th of k equal parts of [-dphi/2, dphi/2] */
                const double lo = -0.5 * dphi + h * dphi / k, hi = lo + dphi / k;
                CHECK(fabs(t - 0.5 * (lo + hi)) <= TOL,
                      "turn %d of %d (dphi %.4f): %.6f, not the centre %.6f of [%.6f, %.6f]", h,
                      k, dphi, t, 0.5 * (lo + hi), lo, hi);
                CHECK(fabs(t + hfs_split_turn(k - 1 - h, k, dphi)) <= TOL,
                      "turns %d and %d of %d not symmetric", h, k - 1 - h, k);
                if (h > 0)
                    CHECK(fabs(t - hfs_split_turn(h - 1, k, dphi) - dphi / k) <= TOL,
                          "turns %d, %d of %d not dphi/%d apart", h - 1, h, k, k);
                sum += t;
            }
            CHECK(fabs(sum) <= TOL * k, "turns of %d: mean %.3e, not the direction", k, sum / k);
        }
}

static void check_swath(void)
{
    static const int ns[] = {12, 16, 7};
    for (int a = 0; a < 3; ++a)
        for (int turned = 0; turned < 2; ++turned)
            for (int k = 1; k <= HFS_SPLIT_MAX_K; ++k) {
                hfs_swath env, far;
                hfs_swath_full(ns[a], &env);
                env.phi0 = turned ? 0.37 : 0.0;
                hfs_split_swath(&env, k, &far);
                CHECK(far.n == ns[a] * k && far.full && fabs(far.dphi - env.dphi / k) <= TOL,
                      "far swath of %d x %d: n %d full %d dphi %.6f", ns[a], k, far.n, far.full,
                      far.dphi);
                for (int j = 0; j < ns[a]; ++j)
                    for (int h = 0; h < k; ++h) {
                        const double phi = hfs_swath_phi(&far, j * k + h);
                        const double want =
                            hfs_swath_phi(&env, j) - 0.5 * env.dphi + (h + 0.5) * env.dphi / k;
                        CHECK(angle_diff(phi, want) <= 1e-11,
                              "sub-direction %d of direction %d (%d x %d, phi0 %.2f): %.6f, want "
                              "%.6f", h, j, ns[a], k, env.phi0, phi, want);
                        CHECK(angle_diff(phi - hfs_swath_phi(&env, j),
                                         hfs_split_turn(h, k, env.dphi)) <= 1e-11,
                              "sub-direction %d of %d: its azimuth and its turn disagree", h, k);
                    }
            }
}

/* Scales near for far-from = num / 2 texels: scale m (m = 0 finest, at
 * 2^(m/k) texels) is near iff 2^(m/k) <= num / 2, i.e. 2^(m + k) <= num^k,
 * in integers (num^k < 2^62 for the cases here). */
static int near_expected(int n_levels, int k, int num)
{
    unsigned long long p = 1;
    for (int i = 0; i < k; ++i)
        p *= (unsigned long long)num;
    int near = 0;
    for (int m = 0; m < n_levels && m + k < 63 && (1ULL << (m + k)) <= p; ++m)
        ++near;
    return near;
}

static void check_boundary(void)
{
    static const int sizes[][2] = {{48, 40}, {257, 100}, {1024, 3}};
    static const int nums[] = {2, 4, 6, 11, 16, 24, 32}; /* far-from 1, 2, 3, 5.5, 8, 12, 16 */
    for (int s = 0; s < 3; ++s)
        for (int k = 1; k <= 12; ++k)
            for (int a = 0; a < 7; ++a) {
                const int n = hfs_pyramid_level_count(sizes[s][0], sizes[s][1], k);
                const double from = nums[a] / 2.0;
                const int near = near_expected(n, k, nums[a]);
                const int first = hfs_split_first_far(n, k, from);
                CHECK(hfs_split_near_count(n, k, from) == near,
                      "%dx%d k %d far-from %g: %d near scales, want %d", sizes[s][0],
                      sizes[s][1], k, from, hfs_split_near_count(n, k, from), near);
                CHECK(first == n - 1 - near, "%dx%d k %d far-from %g: far from scale %d, want %d",
                      sizes[s][0], sizes[s][1], k, from, first, n - 1 - near);
                CHECK(first < 0 || hfs_pyramid_spacing(n, k, first) > from,
                      "k %d far-from %g: the first far scale is %g texels away", k, from,
                      hfs_pyramid_spacing(n, k, first));
                CHECK(first + 1 > n - 1 || hfs_pyramid_spacing(n, k, first + 1) <= from,
                      "k %d far-from %g: the coarsest near scale is %g texels away", k, from,
                      hfs_pyramid_spacing(n, k, first + 1));
            }
    /* The defaults at 48 x 40 (k = 2: 13 scales, 1 .. 64 texels): far-from
     * 8 keeps 1, 1.4, 2, 2.8, 4, 5.7, 8 near, the far grid starts at 11.3
     * (scale index 5); far-from 16 at 22.6 (index 3). */
    CHECK(hfs_pyramid_level_count(48, 40, 2) == 13 && hfs_split_first_far(13, 2, 8.0) == 5 &&
              hfs_split_first_far(13, 2, 16.0) == 3,
          "48x40 k 2: far from scale %d (far-from 8), %d (16), want 5, 3",
          hfs_split_first_far(13, 2, 8.0), hfs_split_first_far(13, 2, 16.0));
}

static void check_make(void)
{
    static const int subs[] = {1, 2, 4}, from[] = {8, 16, 16}, kk[] = {3, 2, 2},
                     step[] = {2, 8, 16};
    static const int refines[] = {0, 1, 2, 3, 4, 16};
    for (int si = 0; si < 3; ++si)
        for (int ri = 0; ri < 6; ++ri)
            for (int v = 0; v < 4; ++v) { /* bounces or not (issue 36) */
                hfs_quality q;
                hfs_quality_defaults(&q);
                q.subsample = subs[si];
                q.refine = refines[ri];
                q.split = !(v & 1);
                q.visibility = v & 2 ? HFS_VIS_LEGENDRE : HFS_VIS_SLICE;
                hfs_split s;
                hfs_split_make(&q, &s);
                const int near = subs[si] == 1 || q.refine < 2 ? q.refine : 2;
                CHECK(s.on == (v == 0), "sub %d split %d vis %d: on %d", subs[si], q.split,
                      (int)q.visibility, s.on);
                CHECK(s.from == from[si] && s.k == kk[si] && s.step == step[si],
                      "sub %d: far-from %g, %d sub-directions, step %d; want %d, %d, %d",
                      subs[si], s.from, s.k, s.step, from[si], kk[si], step[si]);
                CHECK(s.near_refine == near && s.far_refine == q.refine,
                      "sub %d refine %d: near part refined %d times, far part %d; want %d, %d",
                      subs[si], q.refine, s.near_refine, s.far_refine, near, q.refine);
            }
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.far_from = 5, q.far_dirs = HFS_SPLIT_MAX_K, q.far_step = 3, q.subsample = 4;
    hfs_split s;
    hfs_split_make(&q, &s);
    CHECK(s.from == 5.0 && s.k == HFS_SPLIT_MAX_K && s.step == 3,
          "overrides: far-from %g, %d sub-directions, step %d", s.from, s.k, s.step);
}

static void check_far(void)
{
    /* (h + dz min(d / g, 1)) / d */
    CHECK(hfs_split_far_slope(2.0, 4.0, 1.0, 8) == 2.5 / 4.0, "within a grid step: %g",
          hfs_split_far_slope(2.0, 4.0, 1.0, 8));
    CHECK(hfs_split_far_slope(2.0, 16.0, 1.0, 8) == 3.0 / 16.0, "beyond a grid step: %g",
          hfs_split_far_slope(2.0, 16.0, 1.0, 8));
    CHECK(hfs_split_far_slope(2.0, 0.0, 1.0, 8) <= -1e29, "no occluder: %g",
          hfs_split_far_slope(2.0, 0.0, 1.0, 8));
    /* the stored heights' unit: 1 up to 2^14 texels of relief, then the
     * power of two that brings the relief to 2^14 or below, at most 2^64 */
    static const struct {
        double lo, hi, zscale, dx, unit;
    } units[] = {{0.0, 16384.0, 1.0, 1.0, 1.0},     {-1.0, 1.0, 8192.0, 1.0, 1.0},
                 {0.0, 16385.0, 1.0, 1.0, 2.0},     {0.0, 32768.0, 1.0, 1.0, 2.0},
                 {0.0, 32769.0, 1.0, 1.0, 4.0},     {0.0, 1.0, 1e6, 1.0, 64.0},
                 {0.0, 1.0, 1e12, 1e-9, 0x1p56},    {0.0, 3e38, 1e12, 1e-9, 0x1p64},
                 {0.0, 1.0, 0.0, 1.0, 1.0},         {0.0, 1.0, HUGE_VAL, 1.0, 0x1p64},
                 {0.0, 1.0, NAN, 1.0, 1.0},         {5.0, 5.0, 1e12, 1e-9, 1.0}};
    for (size_t i = 0; i < sizeof units / sizeof units[0]; ++i) {
        const double u = hfs_split_h_unit(units[i].lo, units[i].hi, units[i].zscale, units[i].dx);
        CHECK(u == units[i].unit, "height unit %zu: relief (%g - %g) %g / %g: %g, want %g", i,
              units[i].hi, units[i].lo, units[i].zscale, units[i].dx, u, units[i].unit);
    }
    /* above its own sub-direction's tangent plane by more than the tie,
     * 1e-3 (the far pairs' fp16) relative to 1 + |the plane's slope|: on
     * a plane as steep as 1.6 the tie is 2.6e-3 */
    const double n[3] = {0.3, -0.2, 0.932738};
    static const double a_hs[] = {0.25, 0.0, -0.7, 0.8};
    for (int i = 0; i < 4; ++i) {
        const double nz = i == 3 ? 0.5 : n[2], nn[3] = {n[0], n[1], nz};
        const double plane = -a_hs[i] / nz, tie = HFS_SPLIT_PLANE_TIE * (1.0 + fabs(plane));
        CHECK(hfs_split_above_plane(plane + 1.05 * tie, a_hs[i], nn) &&
                  !hfs_split_above_plane(plane + 0.95 * tie, a_hs[i], nn),
              "the plane's tie (plane slope %.3f, tie %.2e): above at 1.05 tie %d, at 0.95 "
              "tie %d", plane, tie, hfs_split_above_plane(plane + 1.05 * tie, a_hs[i], nn),
              hfs_split_above_plane(plane + 0.95 * tie, a_hs[i], nn));
    }
    /* hfs_split_band (issue 36): a bounce slice's bands clipped to each of
     * 3 sub-horizons tile what the direct light takes as occluded, the
     * mean of each sub-horizon's part above the tangent plane, with the
     * last band's fill up to each; no cap (k 0): the band as it is. */
    const double a = 0.3, nz = 0.95, top0 = atan2(-a, nz), caps[3] = {0.2, 0.9, 0.5};
    double s_cap[3], want = 0.0, got = 0.0;
    for (int h = 0; h < 3; ++h) {
        s_cap[h] = hfs_slice_cosine(a, nz, caps[h]);
        want += (hfs_slice_cosine(a, nz, top0) - s_cap[h]) / 3.0;
    }
    const double edge[4] = {top0, 0.1, 0.45, 0.7}; /* the walk's tops, below the highest cap */
    for (int e = 0; e < 3; ++e)
        got += hfs_split_band(s_cap, 3, hfs_slice_cosine(a, nz, edge[e]),
                              hfs_slice_cosine(a, nz, edge[e + 1]));
    got += hfs_split_band(s_cap, 3, hfs_slice_cosine(a, nz, edge[3]), -HUGE_VAL);
    CHECK(fabs(got - want) <= 1e-12 && want > 0.0,
          "clipped bands and the fill %.15f, the sub-horizons' occluded part %.15f", got, want);
    const double s1 = hfs_slice_cosine(a, nz, 0.1), s2 = hfs_slice_cosine(a, nz, 0.45);
    CHECK(hfs_split_band(s_cap, 0, s1, s2) == s1 - s2 &&
              fabs(hfs_split_band(s_cap, 3, s1, s2) -
                   (s1 - s_cap[0] + 2.0 * (s1 - s2)) / 3.0) <= 1e-15,
          "one band: uncapped %g, clipped %g", hfs_split_band(s_cap, 0, s1, s2),
          hfs_split_band(s_cap, 3, s1, s2));
}

/* ---- an environment map's slices ------------------------------------------------ */

#define MW 360 /* a column a degree */
#define MH 90
#define LIT0 40 /* the lit sector: azimuths [40, 75) degrees, radiance (1, 2, 3) */
#define LIT1 75

/* The length (degrees) of [a, b] (b - a < 360) that lies in the sector,
 * turned by any multiple of 360. */
static double lit_overlap(double a, double b)
{
    double s = 0.0;
    for (int r = -2; r <= 2; ++r) {
        const double lo = fmax(a, LIT0 + 360.0 * r), hi = fmin(b, LIT1 + 360.0 * r);
        s += hi > lo ? hi - lo : 0.0;
    }
    return s;
}

static void check_map_slices(void)
{
    float *map = calloc((size_t)MW * MH * 3, sizeof *map);
    if (!map) {
        CHECK(0, "out of memory");
        return;
    }
    for (int v = 0; v < MH; ++v)
        for (int u = LIT0; u < LIT1; ++u)
            for (int c = 0; c < 3; ++c)
                map[3 * ((size_t)v * MW + u) + c] = (float)(c + 1);
    static const int ns[] = {12, 16, 7};
    static const double rots[] = {0.0, 10.0, -23.5}; /* degrees */
    for (int a = 0; a < 3; ++a)
        for (int r = 0; r < 3; ++r) {
            const int n = ns[a];
            const double dphi = 2.0 * PI / n, rot = rots[r] * PI / 180.0;
            double *dir = malloc((size_t)n * 2 * sizeof *dir);
            for (int j = 0; j < n && dir; ++j)
                dir[2 * j] = cos(j * dphi), dir[2 * j + 1] = sin(j * dphi);
            hfs_map_slices ms;
            hfs_error err = {""};
            if (!dir || hfs_map_slices_build(&ms, map, MW, MH, rot, dir, n, dphi, &err)) {
                CHECK(0, "build: %s", err.msg);
                free(dir);
                break;
            }
            /* A flat receiver (tangent plane 0) fully blocked (x = pi/2):
             * dphi (S_j(pi/2) - S_j(0)) = -dphi L_j / 2, L_j the wedge's
             * mean (uniform in elevation). */
            const double nz[3] = {0.0, 0.0, 1.0};
            for (int j = 0; j < n; ++j) {
                const double c = j * 360.0 / n - rots[r], half = 180.0 / n;
                const double mean = lit_overlap(c - half, c + half) / (2.0 * half);
                double e[3] = {0.0, 0.0, 0.0};
                hfs_map_slices_occluded(&ms, j, nz, 0.5 * PI, e);
                for (int ch = 0; ch < 3; ++ch)
                    CHECK(fabs(e[ch] + dphi * 0.5 * mean * (ch + 1)) <= 1e-9,
                          "%d slices, sky turned %g: slice %d (wedge [%g, %g] degrees of the "
                          "map) channel %d occludes %.6f, want %.6f", n, rots[r], j, c - half,
                          c + half, ch, e[ch], -dphi * 0.5 * mean * (ch + 1));
            }
            hfs_map_slices_free(&ms);
            free(dir);
        }
    free(map);
}

/* hfs_split_far_snap's cases, written out: a texel at (tx, ty) between
 * receivers 0..3 with their rises above it (steep 6). */
static void check_snap(void)
{
    static const struct {
        double tx, ty, rise[4], sx, sy;
        const char *what;
    } c[] = {
        {0.25, 0.5, {5.9, 6.0, 0.0, 3.0}, 0.25, 0.5, "none steeper: the texel's own place"},
        {0.5, 0.5, {0.0, 9.0, 0.0, 9.0}, 0.0, 0.5, "a wall's top at x1: edge x0"},
        {0.5, 0.25, {9.0, 9.0, 0.0, 0.0}, 0.5, 1.0, "a wall's top at y0: edge y1"},
        {0.25, 0.5, {0.0, 0.0, 0.0, 9.0}, 0.0, 0.5, "one corner steep: the heavier edge x0"},
        {0.25, 0.25, {0.0, 0.0, 0.0, 9.0}, 0.0, 0.0, "two edges as heavy: their receiver"},
        {0.75, 0.25, {9.0, 0.0, 9.0, 9.0}, 1.0, 0.0, "one receiver passes: it alone"},
        {0.5, 0.5, {9.0, 8.0, 7.0, 10.0}, 0.0, 1.0, "none passes: the least steep"},
        {0.0, 0.5, {0.0, 50.0, 9.0, 50.0}, 0.0, 0.0, "weightless receivers never count"},
        {0.0, 0.0, {0.0, 50.0, 50.0, 50.0}, 0.0, 0.0, "on a receiver: itself"},
    };
    for (size_t k = 0; k < sizeof c / sizeof c[0]; ++k) {
        double sx = -1.0, sy = -1.0;
        hfs_split_far_snap(c[k].tx, c[k].ty, c[k].rise, HFS_SPLIT_STEEP, &sx, &sy);
        CHECK(sx == c[k].sx && sy == c[k].sy, "snap, %s: (%g, %g), want (%g, %g)", c[k].what,
              sx, sy, c[k].sx, c[k].sy);
    }
    CHECK(HFS_SPLIT_STEEP == 6, "the wall's slope %d (DESIGN.md says 6)", HFS_SPLIT_STEEP);
    /* the cell's 8 symmetries (x -> 1 - x, y -> 1 - y, x <-> y) carry the
     * place and the receivers along: a turned or mirrored field reads the
     * turned place (test_metamorphic_turn's relation, cell by cell); places
     * on eighths and integer rises, so that every kind of tie occurs */
    unsigned seed = 12345u;
    for (int n = 0; n < 20000; ++n) {
        double tx, ty, rise[4], sx, sy;
        seed = seed * 1664525u + 1013904223u;
        tx = (seed >> 8) % 9 / 8.0;
        seed = seed * 1664525u + 1013904223u;
        ty = (seed >> 8) % 9 / 8.0;
        for (int r = 0; r < 4; ++r) {
            seed = seed * 1664525u + 1013904223u;
            rise[r] = (double)((seed >> 8) % 10);
        }
        hfs_split_far_snap(tx, ty, rise, HFS_SPLIT_STEEP, &sx, &sy);
        for (int m = 1; m < 8; ++m) {
            const int fx = m & 1, fy = (m >> 1) & 1, sw = m >> 2;
            double u = fx ? 1.0 - tx : tx, v = fy ? 1.0 - ty : ty, r2[4], ux, uy;
            for (int r = 0; r < 4; ++r) {
                int x = (r & 1) ^ fx, y = (r >> 1) ^ fy;
                if (sw) {
                    const int t = x;
                    x = y, y = t;
                }
                r2[x + 2 * y] = rise[r];
            }
            if (sw) {
                const double t = u;
                u = v, v = t;
            }
            hfs_split_far_snap(u, v, r2, HFS_SPLIT_STEEP, &ux, &uy);
            double wx = fx ? 1.0 - sx : sx, wy = fy ? 1.0 - sy : sy;
            if (sw) {
                const double t = wx;
                wx = wy, wy = t;
            }
            CHECK(ux == wx && uy == wy, "snap under symmetry %d of (%g, %g) rises %g %g %g %g: "
                  "(%g, %g), want (%g, %g)", m, tx, ty, rise[0], rise[1], rise[2], rise[3], ux,
                  uy, wx, wy);
        }
    }
}

int main(int argc, char **argv)
{
    if (argc == 2 && !strcmp(argv[1], "split")) {
        check_turns();
        check_swath();
        check_boundary();
        check_make();
        check_far();
        check_snap();
    } else if (argc == 2 && !strcmp(argv[1], "map_slices")) {
        check_map_slices();
    } else {
        fprintf(stderr, "usage: test_drift_rules split|map_slices\n");
        return 2;
    }
    printf("test_drift_rules %s: %ld checks, %s\n", argv[1], checks, failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
