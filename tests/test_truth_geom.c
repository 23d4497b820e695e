/*
 * test_truth_geom.c — the ground truth's geometric kernels against
 * independent brute force:
 *   cap_irradiance     hfs_cap_irradiance vs 2D midpoint quadrature over the cap
 *   ray_vs_march       exact ray / bilinear-surface test vs a dense march
 *   ray_tree_vs_plain  quadtree-accelerated rays == plain DDA, bit for bit
 *   horizon_fast       accelerated horizon march == plain march, bit for bit
 *   horizon_analytic   horizons of a plane and of a wall vs closed forms
 *   first_cell         hfs_field_first_cell_slope vs a dense march over the
 *                      receiver's own cell, and a saddle in closed form
 * Exit 0 on success, 1 on failure (file:line and values printed; a failing
 * check returns from its test at once, leaking that test's buffers).
 */
#include "field_geom.h"
#include "lights.h"
#include "test_util.h"
#include "truth_raycast.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#define PI 3.14159265358979323846

/* Small deterministic RNG for test inputs. */
static uint64_t rng_state = 0x1234567887654321ULL;
static double urand(void)
{
    rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(rng_state >> 11) * (1.0 / 9007199254740992.0);
}

static float *random_heights(int w, int h, double amp)
{
    float *z = malloc((size_t)w * h * sizeof *z);
    for (int k = 0; k < w * h; ++k)
        z[k] = (float)(amp * urand());
    return z;
}

/* ---- cap irradiance ------------------------------------------------------- */

/* integral over the cap (half-angle alpha, axis at angle beta from N) of
 * max(0, N.s): midpoint rule in (theta, psi) around the cap axis. */
static double cap_brute(double beta, double alpha, int n)
{
    double sum = 0.0;
    const double dt = alpha / n, dp = 2.0 * PI / n;
    for (int a = 0; a < n; ++a) {
        const double th = (a + 0.5) * dt;
        const double ct = cos(th), st = sin(th);
        double row = 0.0;
        for (int b = 0; b < n; ++b) {
            const double ns = cos(beta) * ct + sin(beta) * st * cos((b + 0.5) * dp);
            if (ns > 0.0)
                row += ns;
        }
        sum += row * st;
    }
    return sum * dt * dp;
}

static void test_cap_irradiance(void)
{
    const double betas[] = {0.0, 0.3, 0.8, 1.2, 1.45, PI / 2, 1.7, 2.0, 2.6, PI};
    const double alphas[] = {0.01, 0.1, 0.4, 0.9, 1.3, PI / 2, 1.8, 2.4, 3.0, PI};
    /* Midpoint rule, n = 600 per axis: O(h^2) with a first-derivative kink
     * where N.s = 0; the observed worst error is ~1e-5 (absolute, E <= pi).
     * Tolerance 1e-4 absolute + 1e-4 relative. */
    const double tol_abs = 1e-4, tol_rel = 1e-4;
    double worst = 0.0;
    int straddling = 0;
    for (size_t ib = 0; ib < sizeof betas / sizeof *betas; ++ib)
        for (size_t ia = 0; ia < sizeof alphas / sizeof *alphas; ++ia) {
            const double b = betas[ib], a = alphas[ia];
            const double ref = cap_brute(b, a, 600);
            const double got = hfs_cap_irradiance(cos(b), a);
            const double e = fabs(got - ref);
            if (b - a < PI / 2 && b + a > PI / 2)
                ++straddling;
            worst = e > worst ? e : worst;
            REQUIRE(isfinite(got) && e <= tol_abs + tol_rel * fabs(ref),
                    "beta %.4f alpha %.4f: formula %.9f brute %.9f", b, a, got, ref);
        }
    REQUIRE(straddling >= 20, "only %d straddling cases", straddling);
    /* Small caps across the tangent plane, beta = pi/2 + f alpha: a flat
     * disk of radius alpha in the limit, E = alpha^3 g(f) with
     * g(f) = 2/3 (1 - f^2)^(3/2) - f (acos f - f sqrt(1 - f^2)), to
     * O(alpha^2) relative.  The textbook straddling formula cancels two
     * O(alpha) terms here (it returned 0 at alpha = 1e-8). */
    static const double small[] = {1e-3, 1e-5, 1e-8};
    static const double fs[] = {-0.9, -0.5, 0.0, 0.5, 0.9};
    for (size_t ia = 0; ia < sizeof small / sizeof *small; ++ia)
        for (size_t jf = 0; jf < sizeof fs / sizeof *fs; ++jf) {
            const double a = small[ia], f = fs[jf], r = sqrt(1.0 - f * f);
            const double g = 2.0 / 3.0 * r * r * r - f * (acos(f) - f * r);
            const double got = hfs_cap_irradiance(-sin(f * a), a);
            REQUIRE(fabs(got / (a * a * a * g) - 1.0) < 1e-5, "alpha %g f %.1f: %.9g vs %.9g", a,
                    f, got, a * a * a * g);
        }
    /* Limits: the whole sphere, an empty cap, clamped cos(beta). */
    REQUIRE(fabs(hfs_cap_irradiance(0.3, PI) - PI) < 1e-15, "alpha = pi");
    REQUIRE(hfs_cap_irradiance(1.0, 0.0) == 0.0, "alpha = 0");
    REQUIRE(fabs(hfs_cap_irradiance(1.0 + 1e-12, 0.5) - PI * sin(0.5) * sin(0.5)) < 1e-12,
            "cos_beta > 1");
    printf("cap_irradiance: 100 cases (%d straddling), worst |formula - brute| %.2e\n",
           straddling, worst);
}

/* ---- rays -------------------------------------------------------------------- */

/* Dense march along the ray (world step h) over the whole segment, recording
 * the largest depth of the ray below the surface (negative: the closest
 * clearance above it).  Hit iff depth >= 0. */
static double ray_march_depth(const hfs_field *f, const double o[3], const double d[3],
                              double tmax, double h, double zlo, double zhi)
{
    double depth = -INFINITY;
    for (long k = 0;; ++k) {
        const double t = k * h;
        if (t > tmax)
            break;
        const double gx = o[0] + t * d[0] / f->dx, gy = o[1] + t * d[1] / f->dx;
        const double zr = o[2] + t * d[2];
        double zs;
        if (!hfs_field_bilinear(f, gx, gy, &zs))
            break;
        if (zs - zr > depth)
            depth = zs - zr;
        if ((d[2] >= 0.0 && zr > zhi) || zr < zlo - 1.0)
            break; /* above everything, or surely and deeply below */
    }
    return depth;
}

static void random_dir(double d[3], int kind)
{
    switch (kind) {
    case 0: d[0] = 0; d[1] = 0; d[2] = 1; return;            /* vertical up */
    case 1: d[0] = 1; d[1] = 0; d[2] = 0.15; break;          /* along a grid line */
    case 2: d[0] = 0; d[1] = -1; d[2] = 0.3; break;          /* along a grid line */
    case 3: d[0] = -1; d[1] = 1; d[2] = 0.2; break;          /* through cell corners */
    case 4: d[0] = 0; d[1] = 0; d[2] = -1; return;           /* vertical down */
    default: {
        /* uniform over the sphere, biased toward low elevations */
        const double phi = 2 * PI * urand();
        const double e = asin(2 * urand() - 1) * 0.5;
        d[0] = cos(phi) * cos(e);
        d[1] = sin(phi) * cos(e);
        d[2] = sin(e);
        return;
    }
    }
    const double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int k = 0; k < 3; ++k)
        d[k] /= len;
}

static void test_ray_vs_march(void)
{
    int n_rays = 0, n_hit = 0, n_miss = 0, n_grazing = 0;
    for (int field = 0; field < 6; ++field) {
        const int w = 6 + (int)(urand() * 14), h = 5 + (int)(urand() * 14);
        float *z = random_heights(w, h, 1.0);
        const hfs_field f = {w, h, z, 0.5 + 2.0 * urand(), 0.2 + 3.0 * urand()};
        hfs_truth_grid g;
        REQUIRE(hfs_truth_grid_init(&g, &f) == HFS_OK, "grid init");
        /* Ambiguity band for grazing rays: a dense march with world step h
         * can miss a dip below the surface only if the dip is shallower than
         * h times the largest slope difference between ray and surface. */
        const double step = 1e-3 * f.dx;
        const double eps = 2.0 * step * (1.0 + 2.0 * (g.z_hi - g.z_lo) / f.dx);
        for (int r = 0; r < 400; ++r) {
            const int i = (int)(urand() * w), j = (int)(urand() * h);
            double d[3];
            random_dir(d, r < 20 ? r % 5 : 5);
            const double o[3] = {i, j, hfs_field_z(&f, i, j) + 1e-4 * f.dx};
            const double tmax = (r % 3 == 0) ? (0.5 + 4.0 * urand()) * f.dx : INFINITY;
            const int got = hfs_truth_ray_hits(&g, o, d, tmax);
            const double depth = ray_march_depth(&f, o, d, tmax, step, g.z_lo, g.z_hi);
            const int ref = depth >= 0.0;
            ++n_rays;
            if (got != ref && fabs(depth) < eps) {
                ++n_grazing; /* within the march's own resolution */
                continue;
            }
            REQUIRE(got == ref,
                    "field %d %dx%d ray %d from (%d,%d) d=(%.4f,%.4f,%.4f) tmax %g: exact %d march %d "
                    "(depth %.3g, eps %.3g)",
                    field, w, h, r, i, j, d[0], d[1], d[2], tmax, got, ref, depth, eps);
            n_hit += got;
            n_miss += !got;
        }
        hfs_truth_grid_free(&g);
        free(z);
    }
    /* Meaningful only if both outcomes occur often and grazing is rare. */
    REQUIRE(n_hit > n_rays / 10 && n_miss > n_rays / 10 && n_grazing < n_rays / 50,
            "hits %d misses %d grazing %d of %d", n_hit, n_miss, n_grazing, n_rays);
    printf("ray_vs_march: %d rays, %d hit, %d clear, %d grazing (skipped)\n", n_rays, n_hit,
           n_miss, n_grazing);
}

static void test_ray_tree_vs_plain(void)
{
    int n = 0, n_hit = 0;
    for (int field = 0; field < 4; ++field) {
        const int w = 20 + (int)(urand() * 90), h = 20 + (int)(urand() * 90);
        /* Smooth-ish hills plus noise, so nodes are skipped and descended. */
        float *z = malloc((size_t)w * h * sizeof *z);
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i)
                z[j * w + i] = (float)(10.0 * sin(0.13 * i) * cos(0.07 * j + field) +
                                       urand() * 2.0 + (field == 1 ? 3000.0 : 0.0));
        const hfs_field f = {w, h, z, field == 1 ? 0.02 : 1.0, 0.3 + urand()};
        hfs_truth_grid g;
        REQUIRE(hfs_truth_grid_init(&g, &f) == HFS_OK, "grid init");
        int bad = 0;
        for (int r = 0; r < 20000 && !bad; ++r) {
            const int i = (int)(urand() * w), j = (int)(urand() * h);
            double d[3];
            random_dir(d, r < 50 ? r % 5 : 5);
            const double o[3] = {i, j, hfs_field_z(&f, i, j) + 1e-4 * f.dx};
            const double tmax = (r % 4 == 0) ? 30.0 * urand() : INFINITY;
            const int a = hfs_truth_ray_hits(&g, o, d, tmax);
            const int b = hfs_truth_ray_hits_plain(&g, o, d, tmax);
            bad = a != b;
            n_hit += a;
            ++n;
        }
        hfs_truth_grid_free(&g);
        free(z);
        REQUIRE(!bad, "field %d: accelerated and plain ray tests differ", field);
    }
    REQUIRE(n_hit > n / 10 && n_hit < n - n / 10, "hits %d of %d", n_hit, n);
    printf("ray_tree_vs_plain: %d rays identical (%d hit)\n", n, n_hit);
}

/* ---- horizons ------------------------------------------------------------------ */

/* The largest slope over a march of step `step` texels (t = k step, k >= 1,
 * while in the grid): the exact horizon's lower bound, approached as the
 * step shrinks. */
static double march_horizon(const hfs_field *f, int i, int j, double z0, double c, double s,
                            double step)
{
    double m = -INFINITY, z;
    for (long k = 1; hfs_field_bilinear(f, i + k * step * c, j + k * step * s, &z); ++k)
        m = fmax(m, (z - z0) / (k * step * f->dx));
    return m;
}

/* The exact horizon: the accelerated walk equals the plain one bit for bit
 * (any cutoff, any hint), and every march sample lies at or below it while
 * a fine march comes close (it is the supremum, not a sample of it). */
static void test_horizon_exact(void)
{
    long n = 0, n_cut = 0, n_above = 0;
    double worst_gap = 0.0;
    for (int field = 0; field < 5; ++field) {
        const int w = 8 + (int)(urand() * 50), h = 8 + (int)(urand() * 50);
        float *z = malloc((size_t)w * h * sizeof *z);
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i)
                z[j * w + i] = (float)(field == 4 ? 3.0 /* flat */ :
                                       5.0 * sin(0.2 * i + field) * sin(0.17 * j) + urand() +
                                       (field == 2 ? 4000.0 : 0.0));
        /* field 2: high terrain, fine dx (rounding vs the tree's margin) */
        const hfs_field f = {w, h, z, field == 2 ? 0.01 : 0.5 + urand(),
                             field == 3 ? 0.0 : 0.5 + urand()};
        hfs_truth_grid g;
        REQUIRE(hfs_truth_grid_init(&g, &f) == HFS_OK, "grid init");
        int bad = 0;
        for (int r = 0; r < 3000 && !bad; ++r) {
            const int i = (int)(urand() * w), j = (int)(urand() * h);
            /* some exact axis / diagonal directions, the rest random */
            const double phi = r < 16 ? r * PI / 8 : 2 * PI * urand();
            const double c = cos(phi), s = sin(phi);
            const double z0 = hfs_field_z(&f, i, j) + 1e-4 * f.dx;
            const double plain = hfs_truth_horizon_plain(&g, i, j, z0, c, s);
            double hint = 0.0;
            const double fast = hfs_truth_horizon(&g, i, j, z0, c, s, -INFINITY, &hint);
            const double cut = (urand() - 0.5) * 2.0;
            double rnd_hint = urand() * 300.0 - 20.0; /* any hint, even off the grid */
            const double fast_cut = hfs_truth_horizon(&g, i, j, z0, c, s, cut,
                                                      r % 2 ? &rnd_hint : NULL);
            const double want_cut = plain > cut ? plain : -INFINITY;
            if (fast != plain || fast_cut != want_cut) {
                fprintf(stderr, "field %d (%d,%d) phi %.17g: plain %.17g fast %.17g "
                        "cut %.17g fast_cut %.17g\n", field, i, j, phi, plain, fast, cut, fast_cut);
                bad = 1;
            }
            if (r % 10 == 0 && plain > -INFINITY) {
                const double coarse = march_horizon(&f, i, j, z0, c, s, 0.25);
                const double fine = march_horizon(&f, i, j, z0, c, s, 1.0 / 4096);
                const double tol = 1e-12 * (1.0 + fabs(plain));
                if (coarse > plain + tol || fine > plain + tol) {
                    fprintf(stderr, "field %d (%d,%d) phi %.17g: a march sample %.17g / "
                            "%.17g above the exact %.17g\n", field, i, j, phi, coarse, fine,
                            plain);
                    bad = 1;
                }
                worst_gap = fmax(worst_gap, plain - fine);
                n_above += plain > coarse + 1e-9;
            }
            n_cut += plain <= cut;
            ++n;
        }
        hfs_truth_grid_free(&g);
        free(z);
        REQUIRE(!bad, "field %d: the exact horizon fails (above)", field);
    }
    REQUIRE(n_cut > n / 10 && n_cut < n - n / 10, "cutoff cases %ld of %ld", n_cut, n);
    REQUIRE(worst_gap < 6e-3, "a 1/4096-texel march stays %.3g below the exact horizon",
            worst_gap);
    REQUIRE(n_above > 0, "the exact horizon never exceeds a 0.25-texel march");
    printf("horizon_exact: %ld horizons, tree = plain (%ld under the cutoff); above a "
           "0.25 march %ld times, within %.2e of a 1/4096 march\n", n, n_cut, n_above,
           worst_gap);
}

static void test_horizon_analytic(void)
{
    /* (a) a tilted plane z = zs*(a x + b y): along azimuth phi the surface
     * rises linearly, so the supremum is where the ray leaves the grid,
     * t_e: slope = zs (a cos phi + b sin phi) / dx - lift / t_e, exactly. */
    {
        const int w = 41, h = 29;
        const double a = 0.75, b = -0.375, zs = 1.5, dx = 2.0;
        float *z = malloc((size_t)w * h * sizeof *z);
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i)
                z[j * w + i] = (float)(a * i + b * j); /* dyadic: exact in float */
        const hfs_field f = {w, h, z, dx, zs};
        hfs_truth_grid g;
        REQUIRE(hfs_truth_grid_init(&g, &f) == HFS_OK, "grid init");
        double worst = 0.0;
        for (int r = 0; r < 200; ++r) {
            const int i = 3 + r % 30, j = 2 + (r * 7) % 24;
            const double phi = 2 * PI * (r + 0.5) / 200;
            const double c = cos(phi), s = sin(phi);
            const double z0 = hfs_field_z(&f, i, j) + 1e-4 * dx;
            const double m = hfs_truth_horizon(&g, i, j, z0, c, s, -INFINITY, NULL);
            const double te = fmin(c > 0 ? (w - 1 - i) / c : -i / c,
                                   s > 0 ? (h - 1 - j) / s : -j / s);
            const double want = zs * (a * c + b * s) / dx - 1e-4 / te;
            const double e = fabs(atan(m) - atan(want));
            worst = e > worst ? e : worst;
            REQUIRE(e < 1e-9, "plane (%d,%d) phi %.4f: horizon %.12f want %.12f", i, j, phi,
                    atan(m), atan(want));
        }
        hfs_truth_grid_free(&g);
        free(z);
        printf("horizon_analytic: tilted plane, 200 azimuths, worst error %.2e rad\n", worst);
    }
    /* (b) a saddle-twisted cell: z = 1 where i + j is odd, else 0.  Along
     * the diagonal the first cell is z = sqrt2 t - t^2, so from the lifted
     * corner (lift L = 1e-4, dx = 1) the slope sqrt2 - t - L / t peaks
     * inside the cell at t = sqrt L: sqrt2 - 2 sqrt L.  A 0.25-texel march
     * saw sqrt2 - 0.25 - 4 L (50 degrees for 54). */
    {
        const int w = 9, h = 9;
        float *z = malloc((size_t)w * h * sizeof *z);
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i)
                z[j * w + i] = (float)((i + j) % 2);
        const hfs_field f = {w, h, z, 1.0, 1.0};
        hfs_truth_grid g;
        REQUIRE(hfs_truth_grid_init(&g, &f) == HFS_OK, "grid init");
        const double m = hfs_truth_horizon(&g, 0, 0, 1e-4, sqrt(0.5), sqrt(0.5), -INFINITY,
                                           NULL);
        const double want = sqrt(2.0) - 2.0 * sqrt(1e-4);
        REQUIRE(fabs(m - want) < 1e-12, "twisted cell: %.15f want %.15f", m, want);
        hfs_truth_grid_free(&g);
        free(z);
        printf("horizon_analytic: twisted cell's inner maximum %.6f exact\n", m);
    }
    /* (c) a wall: column x = X of height hw on flat ground.  Bilinear makes it
     * a tent from X-1 to X+1; seen from (i, j) with i < X-1 along +x the
     * steepest point is the crest: atan((zs*hw - lift) / ((X - i) dx)). */
    {
        const int w = 40, h = 9, X = 30;
        const double hw = 7.0, zs = 2.0, dx = 0.5;
        float *z = calloc((size_t)w * h, sizeof *z);
        for (int j = 0; j < h; ++j)
            z[j * w + X] = (float)hw;
        const hfs_field f = {w, h, z, dx, zs};
        hfs_truth_grid g;
        REQUIRE(hfs_truth_grid_init(&g, &f) == HFS_OK, "grid init");
        for (int i = 0; i < X - 1; ++i) {
            const double z0 = 1e-4 * dx;
            const double m = hfs_truth_horizon(&g, i, 4, z0, 1.0, 0.0, -INFINITY, NULL);
            const double want = atan((zs * hw - z0) / ((X - i) * dx));
            REQUIRE(fabs(atan(m) - want) < 1e-12, "wall from i=%d: %.15f want %.15f", i,
                    atan(m), want);
            /* looking away (-x): flat ground only, below the lifted receiver */
            const double back = hfs_truth_horizon(&g, i, 4, z0, -1.0, 0.0, -INFINITY, NULL);
            REQUIRE(i == 0 ? back == -INFINITY : back < 0.0, "away from the wall at i=%d: %g",
                    i, back);
        }
        hfs_truth_grid_free(&g);
        free(z);
        printf("horizon_analytic: wall crest exact from %d receivers\n", X - 1);
    }
}

/* The highest slope over t in (0, tcell] by dense march: -DBL_MAX when the
 * cell leaves the grid (its first point off the grid). */
static double first_cell_march(const hfs_field *f, int i, int j, double c, double s)
{
    const double tc = 1.0 / fmax(fabs(c), fabs(s)), z0 = hfs_field_z(f, i, j);
    double m = -DBL_MAX, z;
    for (int k = 0; k <= 4000; ++k) {
        /* the far end a hair inside: i + tc c may round past the border */
        const double t = k == 0 ? 1e-7 : tc * (1.0 - 1e-12) * k / 4000.0;
        if (!hfs_field_bilinear(f, i + t * c, j + t * s, &z))
            return -DBL_MAX;
        m = fmax(m, (z - z0) / (t * f->dx));
    }
    return m;
}

static void test_first_cell(void)
{
    const int w = 6, h = 5;
    float *z = random_heights(w, h, 3.0);
    const hfs_field f = {w, h, z, 0.5, 1.5};
    double worst = 0.0;
    for (int r = 0; r < 600; ++r) {
        const int i = r % w, j = (r / w) % h;
        /* axes, diagonals, then arbitrary azimuths */
        const double phi = r < 240 ? (r % 8) * PI / 4 : 2 * PI * urand();
        double c = cos(phi), s = sin(phi);
        c = fabs(c) < 1e-12 ? 0.0 : c;
        s = fabs(s) < 1e-12 ? 0.0 : s;
        const double got = hfs_field_first_cell_slope(&f, i, j, c, s);
        const double want = first_cell_march(&f, i, j, c, s);
        if (want == -DBL_MAX) {
            REQUIRE(got == -DBL_MAX, "(%d,%d) phi %.4f: cell off the grid, got %g", i, j, phi,
                    got);
            continue;
        }
        /* The march samples the same linear function: it never exceeds the
         * ends and reaches them to its step's rounding. */
        const double e = fabs(got - want) / fmax(1.0, fabs(want));
        worst = e > worst ? e : worst;
        REQUIRE(e < 1e-5, "(%d,%d) phi %.4f: %.12f want %.12f", i, j, phi, got, want);
    }
    free(z);
    /* A saddle: the receiver and the diagonal neighbour low, the two edge
     * neighbours 1 high.  Along 45 degrees the slope falls from sqrt(2)
     * at the receiver to 0 at the far corner: the distance-1 sample sees
     * sqrt(2) - 1, the cell sqrt(2). */
    float sz[4] = {0.0f, 1.0f, 1.0f, 0.0f};
    const hfs_field sf = {2, 2, sz, 1.0, 1.0};
    const double d = sqrt(0.5), got = hfs_field_first_cell_slope(&sf, 0, 0, d, d);
    REQUIRE(fabs(got - sqrt(2.0)) < 1e-12, "saddle: %.15f want sqrt(2)", got);
    printf("first_cell: 600 receivers and azimuths within %.1e of a dense march; saddle exact\n",
           worst);
}

int main(void)
{
    test_cap_irradiance();
    test_ray_vs_march();
    test_ray_tree_vs_plain();
    test_horizon_exact();
    test_horizon_analytic();
    test_first_cell();
    return finish_checks("test_truth_geom");
}
