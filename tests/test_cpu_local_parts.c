/*
 * test_cpu_local_parts.c — the building blocks of the CPU reference's
 * local spherical lights (runtime/cpu/cpu_local.c, core/local_geometry.c,
 * DESIGN.md "Local lights"; the rendered lights: test_cpu_local.c):
 *   1. the closed-form Legendre fold equals hfs_visibility_eval on the same
 *      swath (partial and full, 1e-12); hfs_horizon_point_slopes equals a
 *      plan's hfs_horizon_point bit for bit; the cap window and the entry
 *      distance against brute force; the partial swath spans exactly the
 *      cap's azimuth range.
 */
#include "cpu_horizon.h"
#include "cpu_local.h"
#include "cpu_pyramid.h"
#include "visibility.h"
#include "lights.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define PI 3.14159265358979323846

static int failures;

#define CHECK(cond, ...) do { if (!(cond)) { failures++; printf("FAIL %s:%d: ", __FILE__, __LINE__); \
    printf(__VA_ARGS__); printf("\n"); } } while (0)

static hfs_local_light light(double x, double y, double z, double r, float le)
{
    return (hfs_local_light){.pos = {x, y, z}, .radius = r, .radiance = {le, le, le}};
}

/* The same generator as test_cpu_local.c's (its seeds' cases). */
static double frand(unsigned *s)
{
    *s = *s * 1664525u + 1013904223u;
    return (*s >> 8) / 16777216.0;
}

/* ---- (1) building blocks ---------------------------------------------------------- */

static void test_fold_matches_visibility(void)
{
    double E[HFS_SH_N * HFS_NLP_N];
    hfs_wedge_elevation_moments(E);
    unsigned seed = 7;
    double worst = 0.0;
    for (int trial = 0; trial < 24; ++trial) {
        hfs_swath s;
        const int n = 1 + trial % 9;
        if (trial % 3 == 0) {
            hfs_swath_full(n + 2, &s);
        } else {
            /* A key swath is a partial swath of any phi0, dphi. */
            const double alpha = 0.02 + 0.5 * frand(&seed), elev = 0.8 * frand(&seed);
            hfs_swath_key(2 * PI * frand(&seed), elev, alpha, n, 32, &s);
        }
        s.elev_lo = -0.4 + 0.3 * frand(&seed);
        s.elev_hi = 0.2 + 1.3 * frand(&seed);
        hfs_visibility *v;
        hfs_error err;
        if (hfs_visibility_create(&s, HFS_VIS_LEGENDRE, &v, &err) != HFS_OK) {
            CHECK(0, "visibility: %s", err.msg);
            continue;
        }
        double omega[32], nlp[32 * HFS_NLP_N], va[HFS_SH_N], vb[HFS_SH_N]; /* n <= 2*9+1 */
        for (int k = 0; k < s.n; ++k) {
            omega[k] = -1.5 + 3.0 * frand(&seed);
            hfs_nlp_visible_band(omega[k] > s.elev_lo ? omega[k] : s.elev_lo, s.elev_hi,
                                 nlp + k * HFS_NLP_N);
        }
        hfs_visibility_eval(v, omega, va);
        const hfs_local_swath ls = {.n = s.n, .full = s.full, .phi0 = s.phi0, .dphi = s.dphi};
        hfs_local_legendre_eval(&ls, E, nlp, vb);
        double scale = 0.0, diff = 0.0;
        for (int k = 0; k < HFS_SH_N; ++k) {
            scale = fmax(scale, fabs(va[k]));
            diff = fmax(diff, fabs(va[k] - vb[k]));
        }
        worst = fmax(worst, diff / fmax(scale, 1e-300));
        CHECK(diff <= 1e-12 * fmax(scale, 1e-3), "trial %d (n=%d full=%d dphi=%g): fold differs by %g",
              trial, s.n, s.full, s.dphi, diff);
        hfs_visibility_destroy(v);
    }
    printf("fold: closed-form Legendre swath == hfs_visibility_eval, worst rel %.1e\n", worst);
}

static void test_slopes_match_plan(void)
{
    const int w = 37, h = 29;
    float *z = malloc((size_t)w * h * sizeof *z);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            z[j * w + i] = (float)(3.0 * sin(i * 0.31) * cos(j * 0.23) + 0.1 * i);
    hfs_field f = {.width = w, .height = h, .z = z, .dx = 0.7, .zscale = 1.3};
    hfs_error err;
    hfs_cpu_pyramid *p = NULL;
    const int k = 3, off = 1;
    const int nl = hfs_pyramid_level_count(w, h, k);
    CHECK(hfs_cpu_pyramid_create(&f, k, hfs_pyramid_read_level(nl, k, off, 0), 1, &p, &err) == HFS_OK,
          "pyramid: %s", err.msg);
    const double phis[] = {0.0, PI / 2, PI, 1.5 * PI, 0.3, 2.0, -1.1, 4.0};
    const int nd = (int)(sizeof phis / sizeof phis[0]);
    hfs_horizon_plan *plan = NULL;
    hfs_horizon_scales *hs = NULL;
    CHECK(hfs_horizon_plan_create(p, f.dx, f.zscale, off, phis, nd, &plan, &err) == HFS_OK, "plan");
    CHECK(hfs_horizon_scales_create(p, f.dx, f.zscale, off, &hs, &err) == HFS_OK, "scales");
    long mismatches = 0;
    if (plan && hs) {
        double lv[64], slope[64];
        unsigned char in[64];
        for (int d = 0; d < nd; ++d) {
            double c, s, pc, ps;
            hfs_horizon_snap_dir(phis[d], &c, &s);
            hfs_horizon_plan_dir(plan, d, &pc, &ps);
            mismatches += c != pc || s != ps;
            for (int j = 0; j < h; ++j)
                for (int i = 0; i < w; ++i) {
                    const double fl = -0.25;
                    hfs_horizon_point(plan, d, i, j, fl, NULL, NULL, lv);
                    hfs_horizon_point_slopes(hs, i, j, c, s, 0, slope, in);
                    for (int t = 0; t < nl; ++t)
                        mismatches += (in[t] ? atan(slope[t]) : fl) != lv[t];
                }
        }
    }
    CHECK(mismatches == 0, "point slopes differ from the plan in %ld samples", mismatches);
    printf("slopes: per-receiver directions == plan samples, bit for bit (%d levels)\n", nl);
    hfs_horizon_plan_destroy(plan);
    hfs_horizon_scales_destroy(hs);
    hfs_cpu_pyramid_destroy(p);
    free(z);
}

static void test_geometry(void)
{
    unsigned seed = 3;
    long bad_window = 0, bad_entry = 0, bad_swath = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const hfs_local_light l = light(20 * frand(&seed) - 10, 20 * frand(&seed) - 10,
                                        16 * frand(&seed) - 8, 0.3 + 3 * frand(&seed), 1);
        const double p[3] = {0, 0, 0};
        hfs_local_view lv;
        hfs_local_view_make(&l, p, &lv);
        if (lv.inside)
            continue;
        /* Window: brute force over elevations of a few azimuths. */
        for (int a = 0; a < 6; ++a) {
            const double phi = lv.phi_l + (a - 2.5) * 0.3;
            const double c = cos(phi), s = sin(phi);
            double lo, hi, blo = 10, bhi = -10;
            const int has = hfs_local_cap_window(&lv, c, s, &lo, &hi);
            for (int e = 0; e <= 20000; ++e) {
                const double el = -PI / 2 + PI * e / 20000;
                const double dot = cos(el) * (c * lv.dir[0] + s * lv.dir[1]) + sin(el) * lv.dir[2];
                if (dot >= lv.cos_a) {
                    blo = fmin(blo, el);
                    bhi = fmax(bhi, el);
                }
            }
            const int bhas = blo <= bhi && bhi - blo > 2e-4;
            if (bhas != has && bhi - blo > 2e-4)
                bad_window++;
            else if (has && bhas && (fabs(lo - blo) > 2e-4 || fabs(hi - bhi) > 2e-4))
                bad_window++;
            /* Entry distance against marching the ray. */
            if (has) {
                const double el = 0.5 * (lo + hi);
                const double ce = cos(el), se = sin(el);
                const double t = hfs_local_entry_distance(&lv, c, s, ce, se);
                double tm = -1.0;
                for (int q = 0; q <= 400000; ++q) {
                    const double u = q * 1e-4;
                    const double x = u * ce * c - lv.v[0], y = u * ce * s - lv.v[1], zz = u * se - lv.v[2];
                    if (x * x + y * y + zz * zz <= lv.r * lv.r) {
                        tm = u * ce;
                        break;
                    }
                }
                if (tm < 0.0 || fabs(t - tm) > 2e-4)
                    bad_entry++;
            }
        }
        /* Partial swath: spans phi_L +- asin(r/rho_h). */
        hfs_local_swath sw;
        hfs_local_swath_make(&lv, 16, HFS_LOCAL_SWATH_PARTIAL, HFS_VIS_LEGENDRE, &sw);
        if (lv.surround) {
            bad_swath += !sw.full || sw.n != 16;
        } else {
            const double hw = 0.5 * sw.n * sw.dphi;
            double lo, hi;
            const double e0 = lv.phi_l - hw * (1 - 1e-6), e1 = lv.phi_l + hw * (1 + 1e-6);
            bad_swath += sw.full || sw.n < HFS_LOCAL_PARTIAL_MIN || sw.n > 16 ||
                         fabs(hw - asin(lv.r / lv.rho_h)) > 1e-12 ||
                         !hfs_local_cap_window(&lv, cos(e0), sin(e0), &lo, &hi) ||
                         hfs_local_cap_window(&lv, cos(e1), sin(e1), &lo, &hi);
        }
    }
    CHECK(bad_window == 0, "cap window wrong in %ld cases", bad_window);
    CHECK(bad_entry == 0, "entry distance wrong in %ld cases", bad_entry);
    CHECK(bad_swath == 0, "partial swath wrong in %ld cases", bad_swath);
    printf("geometry: cap windows, entry distances and swath widths match brute force\n");
}

int main(void)
{
    test_fold_matches_visibility();
    test_slopes_match_plan();
    test_geometry();
    if (failures) {
        printf("%d failure(s)\n", failures);
        return 1;
    }
    printf("test_cpu_local_parts: all passed\n");
    return 0;
}
