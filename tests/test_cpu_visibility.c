/*
 * test_visibility.c — swaths and horizons -> SH visibility, against
 * brute-force integration over the sphere:
 *   - swath layouts (full, partial, pole-covering key lights, tiny alpha);
 *   - full swath with a constant horizon omega: V is the exact SH projection
 *     of "visible above omega", for both paths;
 *   - random horizons on full and partial swaths: each path equals the
 *     projection of the function it defines (Legendre: NLP profiles blended
 *     linearly in azimuth, zero at the swath edges; tables: indicator above a
 *     horizon linear in azimuth, rising to pi/2 over the boundary wedges);
 *   - partial swath with every horizon at the (flat) floor: the swath window;
 *   - the fast form equals the wedge-by-wedge reference.
 */
#include "visibility.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define HALF_PI 1.57079632679489661923

static int failures;

#define CHECK(cond, ...) do { if (!(cond)) { failures++; printf("FAIL %s:%d: ", __FILE__, __LINE__); \
    printf(__VA_ARGS__); printf("\n"); } } while (0)

static double maxdiff(const double *a, const double *b, int n)
{
    double m = 0.0;
    for (int k = 0; k < n; ++k)
        m = fmax(m, fabs(a[k] - b[k]));
    return m;
}

/* ---- brute force --------------------------------------------------------------- */

#define NE 24          /* Gauss nodes in elevation */
#define NPHI_PER_RAD 2000

/* Position of azimuth phi inside the swath: the horizon (tables) or the NLP
 * blend weights (Legendre) there.  Returns 0 outside the swath. */
typedef struct where {
    int a, b;      /* samples at wedge start / end (-1 blocked) */
    double u;      /* fraction across the wedge */
} where;

static int locate(const hfs_swath *s, double phi, where *o)
{
    const int nw = hfs_swath_wedge_count(s);
    for (int w = 0; w < nw; ++w) {
        hfs_swath_wedge wd;
        hfs_swath_get_wedge(s, w, &wd);
        double t = phi - wd.start;
        t -= 2.0 * PI * floor(t / (2.0 * PI));
        if (t < wd.extent) {
            o->a = wd.a;
            o->b = wd.b;
            o->u = t / wd.extent;
            return 1;
        }
    }
    return 0;
}

/* Projection of the function a path defines, by quadrature: midpoint rule in
 * azimuth over the swath, Gauss-Legendre in elevation. */
static void brute(const hfs_swath *s, hfs_visibility_path path, const double *omega,
                  double V[HFS_SH_N])
{
    double gx[NE], gw[NE];
    hfs_gauss_legendre(NE, gx, gw);
    memset(V, 0, HFS_SH_N * sizeof *V);
    const double lo = s->full ? 0.0 : s->phi0 - 0.5 * s->dphi;
    const double span = s->full ? 2.0 * PI : s->n * s->dphi;
    const int nphi = (int)(span * NPHI_PER_RAD) + 64;
    for (int p = 0; p < nphi; ++p) {
        const double phi = lo + span * (p + 0.5) / nphi, dphi = span / nphi;
        where wh;
        if (!locate(s, phi, &wh))
            continue;
        if (path == HFS_VIS_WEDGE_TABLE) {
            const double ha = wh.a < 0 ? HALF_PI : omega[wh.a];
            const double hb = wh.b < 0 ? HALF_PI : omega[wh.b];
            const double h = ha + (hb - ha) * wh.u;
            for (int q = 0; q < NE; ++q) {     /* e in [h, pi/2] */
                const double e = h + (HALF_PI - h) * 0.5 * (gx[q] + 1.0);
                const double wt = dphi * (HALF_PI - h) * 0.5 * gw[q] * cos(e);
                double y[HFS_SH_N];
                hfs_sh_eval_dir(phi, e, y);
                for (int k = 0; k < HFS_SH_N; ++k)
                    V[k] += wt * y[k];
            }
        } else {
            double va[HFS_NLP_N] = {0}, vb[HFS_NLP_N] = {0};
            /* The Legendre path's function: the visible band clipped to the
             * light's elevation window (NS09 section 6). */
            if (wh.a >= 0)
                hfs_nlp_visible_band(fmax(omega[wh.a], s->elev_lo), s->elev_hi, va);
            if (wh.b >= 0)
                hfs_nlp_visible_band(fmax(omega[wh.b], s->elev_lo), s->elev_hi, vb);
            for (int q = 0; q < NE; ++q) {     /* e in [-pi/2, pi/2] */
                const double e = HALF_PI * gx[q];
                double pl[HFS_NLP_N], y[HFS_SH_N];
                hfs_nlp_eval(sin(e), pl);
                double f = 0.0;
                for (int c = 0; c < HFS_NLP_N; ++c)
                    f += ((1.0 - wh.u) * va[c] + wh.u * vb[c]) * pl[c];
                const double wt = dphi * HALF_PI * gw[q] * cos(e) * f;
                hfs_sh_eval_dir(phi, e, y);
                for (int k = 0; k < HFS_SH_N; ++k)
                    V[k] += wt * y[k];
            }
        }
    }
}

/* Exact projection of "visible above a constant omega" over the full circle:
 * only m = 0 survives; Gauss in elevation over [omega, pi/2]. */
static void exact_constant(double omega, double V[HFS_SH_N])
{
    double gx[NE], gw[NE];
    hfs_gauss_legendre(NE, gx, gw);
    memset(V, 0, HFS_SH_N * sizeof *V);
    for (int q = 0; q < NE; ++q) {
        const double e = omega + (HALF_PI - omega) * 0.5 * (gx[q] + 1.0);
        const double wt = 2.0 * PI * (HALF_PI - omega) * 0.5 * gw[q] * cos(e);
        double y[HFS_SH_N];
        hfs_sh_eval_dir(0.0, e, y);
        for (int k = 0; k < HFS_SH_N; ++k)
            if (hfs_sh_order(k) == 0)
                V[k] += wt * y[k];
    }
}

static hfs_visibility *make(const hfs_swath *s, hfs_visibility_path path)
{
    hfs_visibility *v = NULL;
    hfs_error err = {{0}};
    int rc = hfs_visibility_create(s, path, &v, &err);
    CHECK(rc == HFS_OK && v, "visibility create failed: %s", err.msg);
    return v;
}

/* ---- tests ------------------------------------------------------------------------ */

static void test_swaths(void)
{
    hfs_swath s;
    hfs_swath_full(32, &s);
    CHECK(s.full && s.n == 32 && hfs_swath_wedge_count(&s) == 32, "full swath");
    double total = 0.0;
    for (int w = 0; w < 32; ++w) {
        hfs_swath_wedge wd;
        hfs_swath_get_wedge(&s, w, &wd);
        total += wd.extent;
        CHECK(wd.a == w && wd.b == (w + 1) % 32, "full wedge %d samples", w);
        CHECK(fabs(wd.start - 2 * PI * w / 32) < 1e-14, "full wedge %d start", w);
    }
    CHECK(fabs(total - 2 * PI) < 1e-12, "full wedges cover %g", total);

    /* Partial: phi 1.0, elev 0.5, alpha 0.2 -> h = asin(sin .2 / cos .5):
     * samples on a lattice 2 pi / N (N = 4..7 times a power of two), the
     * finest not finer than 2h / 3, whose wedges cover [1 - h, 1 + h]. */
    const double h = asin(sin(0.2) / cos(0.5));
    hfs_swath_key(1.0, 0.5, 0.2, 3, 32, &s);
    const double lat_n = 2 * PI / s.dphi;
    CHECK(!s.full && fabs(lat_n - floor(lat_n + 0.5)) < 1e-9 && s.dphi >= 2 * h / 3 &&
              s.dphi <= 1.25 * (2 * h / 3),
          "partial swath spacing %g (h %g)", s.dphi, h);
    CHECK(s.n >= 2 && s.n <= 4 && hfs_swath_wedge_count(&s) == s.n + 1, "partial swath n=%d",
          s.n);
    /* Over many lights, the lattice spacing stays within 1.25x of 2h / n
     * (where the circle allows: at most 2 pi), with 0.8 n to n + 1
     * samples. */
    for (int t = 0; t < 2000; ++t) {
        const double al = 1e-6 + 0.3 * (t % 97) / 97.0, el = 1.2 * (t % 89) / 89.0;
        const int nk = 1 + t % 9;
        hfs_swath w;
        hfs_swath_key(0.37 * t, el, al, nk, 16, &w);
        if (w.full)
            continue;
        const double hh = asin(sin(al) / cos(el)), want = 2 * hh / nk;
        const int within = w.dphi >= want * (1 - 1e-12) &&
                           (w.dphi <= 1.25 * want * (1 + 1e-12) || w.dphi == 2 * PI);
        CHECK(within && w.n >= (int)(0.8 * nk) && w.n <= nk + 1,
              "light %d: spacing %g for %g, n %d for %d", t, w.dphi, want, w.n, nk);
    }
    CHECK(fabs(s.phi0 / s.dphi - floor(s.phi0 / s.dphi + 0.5)) < 1e-9, "samples on the lattice");
    hfs_swath_wedge first, last;
    hfs_swath_get_wedge(&s, 0, &first);
    hfs_swath_get_wedge(&s, s.n, &last);
    CHECK(first.a == -1 && first.b == 0 && first.start <= 1.0 - h &&
          first.start > 1.0 - h - s.dphi && fabs(first.extent - s.dphi / 2) < 1e-15,
          "start boundary wedge at %g for %g", first.start, 1.0 - h);
    CHECK(last.a == s.n - 1 && last.b == -1 && last.start + last.extent >= 1.0 + h &&
              last.start + last.extent < 1.0 + h + s.dphi,
          "end boundary wedge ends at %g for %g", last.start + last.extent, 1.0 + h);
    /* A light moved within its sampled swath keeps it; one that leaves it
     * gets another (the frame planner reuses the horizons only then). */
    hfs_swath moved;
    /* Moved left by half the smaller distance from either end of the disk
     * to the left edge of the wedge holding it: both ends stay in their
     * wedges. */
    const double room = fmin((1.0 - h) - first.start, (1.0 + h) - (last.start + last.extent - s.dphi));
    CHECK(room > 0.0, "no room to move (%g)", room);
    hfs_swath_key(1.0 - 0.5 * room, 0.5, 0.2, 3, 32, &moved);
    CHECK(moved.n == s.n && moved.phi0 == s.phi0 && moved.dphi == s.dphi,
          "a small move changed the swath");
    hfs_swath_key(1.0 + 1.5 * s.dphi, 0.5, 0.2, 3, 32, &moved);
    CHECK(moved.phi0 != s.phi0, "a move of 1.5 samples kept the swath");
    /* Azimuths a turn apart give the same swath. */
    hfs_swath_key(1.0 + 2 * PI, 0.5, 0.2, 3, 32, &moved);
    CHECK(moved.n == s.n && fabs(moved.phi0 - s.phi0) < 1e-12, "phi + 2 pi: another swath");

    /* Disk covering the zenith or the nadir: full swath, max(nkey, nenv). */
    hfs_swath_key(0.3, 1.45, 0.2, 3, 32, &s);
    CHECK(s.full && s.n == 32, "zenith-covering key light: full=%d n=%d", s.full, s.n);
    hfs_swath_key(0.3, HALF_PI, 0.01, 40, 32, &s);
    CHECK(s.full && s.n == 40, "key light at the zenith: n=%d", s.n);
    hfs_swath_key(0.3, -1.45, 0.2, 3, 16, &s);
    CHECK(s.full && s.n == 16, "nadir-covering key light: full=%d n=%d", s.full, s.n);
    hfs_swath_key(0.3, -HALF_PI, 0.2, 3, 16, &s);
    CHECK(s.full && s.n == 16 && isfinite(s.dphi), "key light at the nadir");
    /* Tiny alpha: the swath of a disk of HFS_MIN_VIS_ALPHA (lights.h):
     * h ~ 1.005e-6 at elev 0.1, 2h/3 <= dphi <= 1.25 * 2h/3. */
    hfs_swath_key(2.0, 0.1, 1e-9, 3, 32, &s);
    CHECK(!s.full && s.dphi >= 6.6e-7 && s.dphi < 8.4e-7 && isfinite(s.phi0) && s.elev_lo == 0.1 - 1e-6,
          "tiny alpha swath: dphi %g, window from %.17g", s.dphi, s.elev_lo);
}

static void test_constant_full(void)
{
    const int ns[3] = {32, 7, 3};
    const double omegas[6] = {-0.6, -0.2, 0.0, 0.3, 0.9, 1.4};
    for (int path = HFS_VIS_LEGENDRE; path <= HFS_VIS_WEDGE_TABLE; ++path)
        for (int q = 0; q < 3; ++q) {
            hfs_swath s;
            hfs_swath_full(ns[q], &s);
            hfs_visibility *v = make(&s, (hfs_visibility_path)path);
            if (!v)
                continue;
            for (int t = 0; t < 6; ++t) {
                double om[32], V[HFS_SH_N], E[HFS_SH_N];
                for (int j = 0; j < ns[q]; ++j)
                    om[j] = omegas[t];
                hfs_visibility_eval(v, om, V);
                exact_constant(omegas[t], E);
                /* Tables: bilinear interpolation between entries pi/256
                 * apart (exact at the node omega = 0). */
                /* measured 1.6e-15 (Legendre), 1.0e-15 (tables at omega 0),
                 * 6.2e-5 (tables elsewhere: interpolation): ~10x, 2e-4 kept */
                const double tol = path == HFS_VIS_LEGENDRE ? 1.6e-14 : (omegas[t] == 0.0 ? 1e-14 : 2e-4);
                const double d = maxdiff(V, E, HFS_SH_N);
                CHECK(d < tol, "%s n=%d omega=%g: |V - exact| = %g",
                      path == HFS_VIS_LEGENDRE ? "legendre" : "tables", ns[q], omegas[t], d);
            }
            hfs_visibility_destroy(v);
        }
}

static unsigned rng_state = 12345u;
static double urand(void)
{
    rng_state = rng_state * 1664525u + 1013904223u;
    return (rng_state >> 8) / 16777216.0;
}

static void test_random_horizons(void)
{
    hfs_swath swaths[4];
    hfs_swath_full(5, &swaths[0]);
    hfs_swath_key(0.7, 0.4, 0.3, 3, 32, &swaths[1]);
    hfs_swath_key(-2.5, -0.2, 0.5, 4, 32, &swaths[2]);
    hfs_swath_key(3.0, 0.9, 0.1, 1, 32, &swaths[3]);
    for (int path = HFS_VIS_LEGENDRE; path <= HFS_VIS_WEDGE_TABLE; ++path)
        for (int q = 0; q < 4; ++q) {
            hfs_visibility *v = make(&swaths[q], (hfs_visibility_path)path);
            if (!v)
                continue;
            for (int t = 0; t < 3; ++t) {
                double om[8], V[HFS_SH_N], R[HFS_SH_N], B[HFS_SH_N];
                for (int j = 0; j < swaths[q].n; ++j)
                    om[j] = -0.8 + 2.2 * urand();
                hfs_visibility_eval(v, om, V);
                hfs_visibility_eval_reference(v, om, R);
                brute(&swaths[q], (hfs_visibility_path)path, om, B);
                const double tol = path == HFS_VIS_LEGENDRE ? 1e-6 : 2e-4;
                CHECK(maxdiff(V, R, HFS_SH_N) < 1e-13, "path %d swath %d: fast != reference (%g)",
                      path, q, maxdiff(V, R, HFS_SH_N));
                CHECK(maxdiff(V, B, HFS_SH_N) < tol, "path %d swath %d: |V - brute| = %g",
                      path, q, maxdiff(V, B, HFS_SH_N));
            }
            hfs_visibility_destroy(v);
        }
}

/* Flat receiver, partial swath, every horizon at the floor (0): the swath
 * window above the horizontal plane.  For the tables that is the region
 * phi in [phi_L - h, phi_L + h], e > 0 with the boundary horizons rising to
 * pi/2; check it directly against an independent window description. */
static void test_window(void)
{
    hfs_swath s;
    const double phil = 2.2, el = 0.35, alpha = 0.25;
    hfs_swath_key(phil, el, alpha, 3, 32, &s);
    /* The swath spans [A, B] (its wedges; samples on a lattice around the
     * disk's phil +- h), with half-wedge ramps at both ends. */
    hfs_swath_wedge w0, w1;
    hfs_swath_get_wedge(&s, 0, &w0);
    hfs_swath_get_wedge(&s, s.n, &w1);
    const double A = w0.start, B = w1.start + w1.extent, h = 0.5 * (B - A), mid = 0.5 * (A + B);
    for (int path = HFS_VIS_LEGENDRE; path <= HFS_VIS_WEDGE_TABLE; ++path) {
        hfs_visibility *v = make(&s, (hfs_visibility_path)path);
        if (!v)
            continue;
        double om[64] = {0.0}; /* horizons at 0 (s.n <= 2 * 3 + 1) */
        double V[HFS_SH_N], W[HFS_SH_N] = {0};
        hfs_visibility_eval(v, om, V);
        double gx[NE], gw[NE];
        hfs_gauss_legendre(NE, gx, gw);
        const int nphi = 20000;
        const double b = s.dphi / 2; /* boundary width */
        for (int p = 0; p < nphi; ++p) {
            const double t = -h + 2 * h * (p + 0.5) / nphi, dphi = 2 * h / nphi;
            const double edge = fmin(t + h, h - t); /* distance to the swath edge */
            const double ramp = edge >= b ? 1.0 : edge / b;
            /* Legendre: the visible band, clipped to the light's elevation
             * window [el - alpha, el + alpha], faded by ramp; tables: horizon
             * at (1 - ramp) * pi/2, no elevation window. */
            const double lo = path == HFS_VIS_LEGENDRE ? fmax(0.0, el - alpha) : (1.0 - ramp) * HALF_PI;
            const double hi = path == HFS_VIS_LEGENDRE ? el + alpha : HALF_PI;
            const double scale = path == HFS_VIS_LEGENDRE ? ramp : 1.0;
            for (int q = 0; q < NE; ++q) {
                const double e = lo + (hi - lo) * 0.5 * (gx[q] + 1.0);
                const double wt = scale * dphi * (hi - lo) * 0.5 * gw[q] * cos(e);
                double y[HFS_SH_N];
                hfs_sh_eval_dir(mid + t, e, y);
                for (int k = 0; k < HFS_SH_N; ++k)
                    W[k] += wt * y[k];
            }
        }
        /* Legendre visibility above 0 is the NLP truncation of the step, whose
         * m = 0 projections are exact but whose m != 0 ones are not: compare
         * m = 0 tightly for Legendre and everything for the tables. */
        double d = 0.0;
        for (int k = 0; k < HFS_SH_N; ++k)
            if (path == HFS_VIS_WEDGE_TABLE || hfs_sh_order(k) == 0)
                d = fmax(d, fabs(V[k] - W[k]));
        CHECK(d < 1e-8, "%s: window differs by %g", path == HFS_VIS_LEGENDRE ? "legendre" : "tables", d);
        hfs_visibility_destroy(v);
    }
}

static void test_sample_matrices(void)
{
    hfs_swath s;
    hfs_swath_full(8, &s);
    hfs_visibility *v = make(&s, HFS_VIS_LEGENDRE);
    if (v) {
        CHECK(hfs_visibility_sample_matrix(v, 0) && hfs_visibility_sample_matrix(v, 7) &&
              !hfs_visibility_sample_matrix(v, 8), "legendre sample matrices");
        CHECK(hfs_visibility_get_path(v) == HFS_VIS_LEGENDRE, "path");
    }
    hfs_visibility_destroy(v);
    v = make(&s, HFS_VIS_WEDGE_TABLE);
    if (v)
        CHECK(!hfs_visibility_sample_matrix(v, 0), "tables have no sample matrices");
    hfs_visibility_destroy(v);
    hfs_visibility_destroy(NULL);
}

int main(void)
{
    test_swaths();
    test_constant_full();
    test_random_horizons();
    test_window();
    test_sample_matrices();
    if (failures) {
        printf("%d failure(s)\n", failures);
        return 1;
    }
    printf("test_cpu_visibility: all passed\n");
    return 0;
}
