/*
 * test_cpu_horizon.c — multi-scale horizons (DESIGN.md "Horizons"):
 *   - a tilted plane (ramp) gives the exact horizon uphill on both paths and
 *     the exact floor (tangent plane) downhill;
 *   - on a cone, a wall and a bump the pyramid horizon converges toward the
 *     exact horizon of the bilinear surface (dense march) as k and o grow;
 *   - the B-spline max never exceeds the environment path's level max, and
 *     equals it where the per-level angles are flat;
 *   - off-grid directions give exactly the floor; a receiver in the last
 *     column still sees along the column (offset snapping);
 *   - the row form is bit-identical to the point form;
 *   - zscale = 0 gives the floor (flat) everywhere, huge walls stay <= pi/2.
 */
#include "cpu_horizon.h"
#include "field_geom.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

static int failures;

#define CHECK(cond, ...) do { if (!(cond)) { failures++; printf("FAIL %s:%d: ", __FILE__, __LINE__); \
    printf(__VA_ARGS__); printf("\n"); } } while (0)

typedef struct setup {
    hfs_field f;
    hfs_cpu_pyramid *p;
    hfs_horizon_plan *hp;
} setup;

static int make(setup *s, const float *z, int w, int h, double dx, double zscale, int k,
                int o, const double *phi, int n_dirs)
{
    hfs_error err = {{0}};
    s->f = (hfs_field){.width = w, .height = h, .z = z, .dx = dx, .zscale = zscale};
    s->p = NULL;
    s->hp = NULL;
    const int n = hfs_pyramid_level_count(w, h, k);
    int rc = hfs_cpu_pyramid_create(&s->f, k, hfs_pyramid_read_level(n, k, o, 0), 1, &s->p, &err);
    if (rc == HFS_OK)
        rc = hfs_horizon_plan_create(s->p, dx, zscale, o, phi, n_dirs, &s->hp, &err);
    CHECK(rc == HFS_OK, "setup failed: %s", err.msg);
    return rc == HFS_OK;
}

static void unmake(setup *s)
{
    hfs_horizon_plan_destroy(s->hp);
    hfs_cpu_pyramid_destroy(s->p);
}

static double floor_at(const setup *s, int dir, int i, int j)
{
    double n[3], c, sn;
    hfs_field_normal(&s->f, i, j, n);
    hfs_horizon_plan_dir(s->hp, dir, &c, &sn);
    return hfs_horizon_floor(n, c, sn);
}

/* Exact horizon on the bilinear surface: dense march to the grid edge. */
static double exact_horizon(const hfs_field *f, int i, int j, double phi, double fl)
{
    const double z0 = hfs_field_z(f, i, j), c = cos(phi), s = sin(phi);
    double best = -DBL_MAX, z;
    for (double t = 0.02; hfs_field_bilinear(f, i + t * c, j + t * s, &z); t += 0.02) {
        const double d = (z - z0) / (t * f->dx);
        best = d > best ? d : best;
    }
    const double a = atan(best);
    return a > fl ? a : fl;
}

static void test_ramp(void)
{
    const int w = 200, h = 40;
    const double dx = 2.0, zscale = 3.0, g = 0.5; /* slope g*zscale/dx = 0.75 */
    float *z = malloc((size_t)w * h * sizeof *z);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            z[j * w + i] = (float)(g * i);          /* exact in float */
    const double phi[2] = {0.0, PI};
    setup s;
    if (make(&s, z, w, h, dx, zscale, 4, 2, phi, 2)) {
        const double up = atan(g * zscale / dx);
        double worst_up = 0.0, worst_floor = 0.0;
        for (int i = 20; i < 120; i += 7) {
            double env, key;
            hfs_horizon_point(s.hp, 0, i, 20, floor_at(&s, 0, i, 20), &env, &key, NULL);
            worst_up = fmax(worst_up, fmax(fabs(env - up), fabs(key - up)));
            /* Looking down the slope the exact horizon is the tangent plane.
             * (The pyramid reads a surface flattened by the clamped B-spline
             * near the border it looks at, so its horizon may sit above.) */
            const double fl = floor_at(&s, 1, i, 20);
            worst_floor = fmax(worst_floor, fabs(fl + up));
            hfs_horizon_point(s.hp, 1, i, 20, fl, &env, &key, NULL);
            CHECK(env >= fl && key >= fl && env < fl + 0.1, "downhill horizon %g, floor %g", env, fl);
        }
        /* measured 2.7e-15 and 0 (double, every build type): ~10x */
        CHECK(worst_up < 3e-14, "ramp, facing uphill: error %g", worst_up);
        CHECK(worst_floor < 3e-14, "ramp floor: error %g", worst_floor);
        unmake(&s);
    }
    free(z);
}

/* Receivers and directions of the convergence test. */
#define CONV_STEP 6
#define CONV_DIRS 16

static double conv_phi(int d)
{
    return 2.0 * PI * d / CONV_DIRS + 0.1;
}

/* Mean |pyramid - exact| over a grid of receivers and 16 directions; exact
 * holds the exact horizons in the same order (computed once per shape). */
static void convergence_errors(const float *z, int w, int h, int k, int o,
                               const double *exact, double *err_env, double *err_key)
{
    double phi[CONV_DIRS];
    for (int d = 0; d < CONV_DIRS; ++d)
        phi[d] = conv_phi(d);
    setup s;
    *err_env = *err_key = 1e9;
    if (!make(&s, z, w, h, 1.0, 1.0, k, o, phi, CONV_DIRS))
        return;
    double se = 0.0, sk = 0.0;
    int cnt = 0;
    for (int j = 3; j < h; j += CONV_STEP)
        for (int i = 3; i < w; i += CONV_STEP)
            for (int d = 0; d < CONV_DIRS; ++d) {
                double env, key;
                hfs_horizon_point(s.hp, d, i, j, floor_at(&s, d, i, j), &env, &key, NULL);
                se += fabs(env - exact[cnt]);
                sk += fabs(key - exact[cnt]);
                cnt++;
            }
    *err_env = se / cnt;
    *err_key = sk / cnt;
    unmake(&s);
}

static void test_convergence(void)
{
    const int w = 72, h = 72;
    float *z = malloc((size_t)w * h * sizeof *z);
    const char *names[3] = {"cone", "wall", "bump"};
    const int ks[5] = {1, 2, 4, 8, 8}, os[5] = {0, 1, 2, 4, 8};
    const double final_bound[3] = {0.004, 0.02, 0.002};
    for (int shape = 0; shape < 3; ++shape) {
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) {
                const double x = i - 36.0, y = j - 36.0, r = sqrt(x * x + y * y);
                double v = 0.0;
                if (shape == 0)
                    v = r < 16 ? 16 - r : 0;
                else if (shape == 1)
                    v = (i >= 46 && i <= 48) ? 24.0 : 0.0;
                else
                    v = 8.0 * exp(-r * r / 128.0);
                z[j * w + i] = (float)v;
            }
        /* Exact horizons (floors from the field's normals, as the plan's). */
        double exact[(72 / CONV_STEP) * (72 / CONV_STEP) * CONV_DIRS];
        hfs_field f = {.width = w, .height = h, .z = z, .dx = 1.0, .zscale = 1.0};
        int cnt = 0;
        for (int j = 3; j < h; j += CONV_STEP)
            for (int i = 3; i < w; i += CONV_STEP)
                for (int d = 0; d < CONV_DIRS; ++d) {
                    double n[3];
                    hfs_field_normal(&f, i, j, n);
                    const double fl = hfs_horizon_floor(n, cos(conv_phi(d)), sin(conv_phi(d)));
                    exact[cnt++] = exact_horizon(&f, i, j, conv_phi(d), fl);
                }
        double pe = 1e9, pk = 1e9, e, kk;
        for (int q = 0; q < 5; ++q) {
            convergence_errors(z, w, h, ks[q], os[q], exact, &e, &kk);
            CHECK(e < pe && kk < pk, "%s: k=%d o=%d does not improve (env %.5f key %.5f, before %.5f %.5f)",
                  names[shape], ks[q], os[q], e, kk, pe, pk);
            pe = e;
            pk = kk;
        }
        CHECK(pe < final_bound[shape] && pk < 2.0 * final_bound[shape] + 0.01,
              "%s: k=8 o=8 still off by env %.5f key %.5f", names[shape], pe, pk);
    }
    free(z);
}

/* Random smooth-ish terrain for property tests. */
static float *terrain(int w, int h, unsigned seed)
{
    float *z = malloc((size_t)w * h * sizeof *z);
    srand(seed);
    double a[6][3];
    for (int q = 0; q < 6; ++q)
        for (int c = 0; c < 3; ++c)
            a[q][c] = rand() / (double)RAND_MAX;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            double v = 0.0;
            for (int q = 0; q < 6; ++q)
                v += (4.0 / (q + 1)) * sin(a[q][0] * 0.5 * (q + 1) * i + a[q][1] * 0.4 * (q + 1) * j + 6 * a[q][2]);
            z[j * w + i] = (float)v;
        }
    return z;
}

static void test_properties(void)
{
    const int w = 53, h = 41;
    float *z = terrain(w, h, 7);
    enum { ND = 24 };
    double phi[ND];
    for (int d = 0; d < ND; ++d)
        phi[d] = 2.0 * PI * d / ND;
    setup s;
    if (make(&s, z, w, h, 0.7, 1.3, 4, 2, phi, ND)) {
        const int n = hfs_horizon_plan_levels(s.hp);
        double *fl = malloc((size_t)w * sizeof *fl), *maxd = malloc((size_t)w * sizeof *maxd);
        double *om = malloc((size_t)n * w * sizeof *om), *lev = malloc((size_t)n * sizeof *lev);
        long not_identical = 0, above = 0, out_of_range = 0, flat_mismatch = 0, flat_cases = 0;
        for (int d = 0; d < ND; ++d)
            for (int j = 0; j < h; ++j) {
                for (int i = 0; i < w; ++i)
                    fl[i] = floor_at(&s, d, i, j);
                hfs_horizon_row(s.hp, d, j, fl, maxd, om);
                for (int i = 0; i < w; ++i) {
                    double env, key;
                    hfs_horizon_point(s.hp, d, i, j, fl[i], &env, &key, lev);
                    const double env_r = hfs_horizon_env_from_maxd(maxd[i], fl[i]);
                    const double key_r = hfs_horizon_bspline_max(om + i, n, (size_t)w, fl[i]);
                    not_identical += env != env_r || key != key_r;
                    for (int q = 0; q < n; ++q)
                        not_identical += lev[q] != om[(size_t)q * w + i];
                    above += key > env + 1e-15;
                    out_of_range += !(env >= fl[i] && env <= PI / 2 && key >= fl[i] && key <= PI / 2);
                    /* Where the level max is attained by three equal
                     * neighbours (or the floor wins), the B-spline reaches it. */
                    double lmax = fl[i];
                    int arg = -1;
                    for (int q = 0; q < n; ++q)
                        if (lev[q] > lmax) {
                            lmax = lev[q];
                            arg = q;
                        }
                    if (arg < 0) {
                        flat_cases++;
                        flat_mismatch += key != env;
                    }
                }
            }
        CHECK(not_identical == 0, "row and point forms differ in %ld values", not_identical);
        CHECK(above == 0, "B-spline max exceeds the level max at %ld receivers", above);
        CHECK(out_of_range == 0, "%ld horizons outside [floor, pi/2]", out_of_range);
        CHECK(flat_cases > 0 && flat_mismatch == 0, "floor-dominated receivers: %ld of %ld differ",
              flat_mismatch, flat_cases);
        free(fl);
        free(maxd);
        free(om);
        free(lev);
        unmake(&s);
    }
    free(z);
}

static void test_off_grid_and_border(void)
{
    const int w = 40, h = 40;
    float *z = calloc((size_t)w * h, sizeof *z);
    /* A slope in the last columns so the border normals tilt, and a wall
     * across row 30 that the last column must see looking along +y. */
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            z[j * w + i] = (float)(0.3 * i * (j % 3 + 1)) + (j >= 30 && j <= 31 ? 50.0f : 0.0f);
    const double phi[4] = {0.0, PI / 2, PI, 3 * PI / 2};
    setup s;
    if (make(&s, z, w, h, 1.0, 1.0, 4, 2, phi, 4)) {
        for (int j = 0; j < h; ++j) {
            double env, key;
            const double fl = floor_at(&s, 0, w - 1, j);
            hfs_horizon_point(s.hp, 0, w - 1, j, fl, &env, &key, NULL);
            CHECK(env == fl && key == fl, "last column facing +x: env %g key %g floor %g", env, key, fl);
            const double fl2 = floor_at(&s, 2, 0, j);
            hfs_horizon_point(s.hp, 2, 0, j, fl2, &env, &key, NULL);
            CHECK(env == fl2 && key == fl2, "first column facing -x: not the floor");
        }
        double c, sn;
        hfs_horizon_plan_dir(s.hp, 1, &c, &sn);
        CHECK(c == 0.0 && sn == 1.0, "pi/2 not snapped: (%g, %g)", c, sn);
        double env, key;
        hfs_horizon_point(s.hp, 1, w - 1, 20, floor_at(&s, 1, w - 1, 20), &env, &key, NULL);
        CHECK(env > 1.0 && key > 0.8, "last column does not see the wall along +y: env %g key %g", env, key);
        hfs_horizon_point(s.hp, 3, 0, 38, floor_at(&s, 3, 0, 38), &env, &key, NULL);
        CHECK(env > 1.0, "first column does not see the wall along -y: %g", env);
        unmake(&s);
    }
    free(z);
}

static void test_zscale_zero_and_extremes(void)
{
    const int w = 30, h = 17;
    float *z = terrain(w, h, 3);
    double phi[8];
    for (int d = 0; d < 8; ++d)
        phi[d] = 2.0 * PI * d / 8 + 0.3;
    setup s;
    if (make(&s, z, w, h, 1.0, 0.0, 4, 2, phi, 8)) {
        long bad = 0;
        for (int d = 0; d < 8; ++d)
            for (int j = 0; j < h; ++j)
                for (int i = 0; i < w; ++i) {
                    double env, key;
                    const double fl = floor_at(&s, d, i, j);
                    hfs_horizon_point(s.hp, d, i, j, fl, &env, &key, NULL);
                    bad += fl != 0.0 || env != 0.0 || key != 0.0;
                }
        CHECK(bad == 0, "zscale 0: %ld non-zero horizons", bad);
        unmake(&s);
    }
    /* Enormous heights and zscale: still finite and <= pi/2. */
    for (int q = 0; q < w * h; ++q)
        z[q] = (q % 7 == 0) ? 3e38f : -3e38f;
    if (make(&s, z, w, h, 1e-3, 1e30, 4, 2, phi, 8)) {
        long bad = 0;
        for (int d = 0; d < 8; ++d)
            for (int j = 0; j < h; ++j)
                for (int i = 0; i < w; ++i) {
                    double env, key;
                    const double fl = floor_at(&s, d, i, j);
                    hfs_horizon_point(s.hp, d, i, j, fl, &env, &key, NULL);
                    bad += !(isfinite(fl) && env >= -PI / 2 && env <= PI / 2 && key >= -PI / 2 && key <= PI / 2);
                }
        CHECK(bad == 0, "extreme heights: %ld bad horizons", bad);
        unmake(&s);
    }
    free(z);
}

int main(void)
{
    test_ramp();
    test_convergence();
    test_properties();
    test_off_grid_and_border();
    test_zscale_zero_and_extremes();
    if (failures) {
        printf("%d failure(s)\n", failures);
        return 1;
    }
    printf("test_cpu_horizon: all passed\n");
    return 0;
}
