/*
 * test_sh_util.h — reference pieces for the SH unit tests, written
 * independently of runtime/sh/ so that the tests compare the library with
 * brute force, not with itself:
 *   - the SPEC.md basis, transcribed from the table with exact constants,
 *   - a Gauss-Legendre rule (Newton on the three-term recurrence),
 *   - Legendre polynomials, a deterministic RNG, a pass/fail tally.
 * Everything is static inline so each test takes only what it uses.
 */
#ifndef HFS_TEST_SH_UTIL_H
#define HFS_TEST_SH_UTIL_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <time.h>

#define T_PI 3.14159265358979323846

/* SPEC.md table, constants written as their exact normalizations. */
static inline void ref_y(double x, double y, double z, double o[16])
{
    const double pi = T_PI;
    o[0] = 0.5 / sqrt(pi);
    o[1] = sqrt(3.0 / (4 * pi)) * y;
    o[2] = sqrt(3.0 / (4 * pi)) * z;
    o[3] = sqrt(3.0 / (4 * pi)) * x;
    o[4] = sqrt(15.0 / (4 * pi)) * x * y;
    o[5] = sqrt(15.0 / (4 * pi)) * y * z;
    o[6] = sqrt(5.0 / (16 * pi)) * (3 * z * z - 1);
    o[7] = sqrt(15.0 / (4 * pi)) * x * z;
    o[8] = sqrt(15.0 / (16 * pi)) * (x * x - y * y);
    o[9] = sqrt(35.0 / (32 * pi)) * y * (3 * x * x - y * y);
    o[10] = sqrt(105.0 / (4 * pi)) * x * y * z;
    o[11] = sqrt(21.0 / (32 * pi)) * y * (5 * z * z - 1);
    o[12] = sqrt(7.0 / (16 * pi)) * z * (5 * z * z - 3);
    o[13] = sqrt(21.0 / (32 * pi)) * x * (5 * z * z - 1);
    o[14] = sqrt(105.0 / (16 * pi)) * z * (x * x - y * y);
    o[15] = sqrt(35.0 / (32 * pi)) * x * (x * x - 3 * y * y);
}

static inline void ref_y_dir(double phi, double e, double o[16])
{
    ref_y(cos(phi) * cos(e), sin(phi) * cos(e), sin(e), o);
}

static inline double ref_eval(const double c[16], double x, double y, double z)
{
    double b[16], s = 0.0;
    ref_y(x, y, z, b);
    for (int k = 0; k < 16; ++k)
        s += c[k] * b[k];
    return s;
}

/* Legendre P_l(t) by recurrence. */
static inline double ref_legendre(int l, double t)
{
    double p0 = 1.0, p1 = t;
    if (l == 0)
        return 1.0;
    for (int k = 2; k <= l; ++k) {
        const double p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
    }
    return p1;
}

/* Gauss-Legendre nodes/weights on [a, b], n <= 128. */
static inline void ref_gauss(int n, double a, double b, double *x, double *w)
{
    for (int i = 0; i < n; ++i) {
        double t = cos(T_PI * (i + 0.75) / (n + 0.5)), d = 0.0;
        for (int it = 0; it < 200; ++it) {
            const double p = ref_legendre(n, t), q = ref_legendre(n - 1, t);
            d = n * (q - t * p) / (1 - t * t);
            const double dt = p / d;
            t -= dt;
            if (fabs(dt) < 1e-16)
                break;
        }
        const double p = ref_legendre(n, t), q = ref_legendre(n - 1, t);
        d = n * (q - t * p) / (1 - t * t);
        x[i] = 0.5 * (a + b) + 0.5 * (b - a) * t;
        w[i] = (b - a) / ((1 - t * t) * d * d);
    }
}

/* max that keeps NaN (fmax drops it, which would hide a broken result). */
static inline double ref_max(double a, double b)
{
    return (b > a || b != b) ? b : a;
}

/* Deterministic xorshift RNG: uniform in [lo, hi). */
typedef struct { uint64_t s; } ref_rng;
static inline double ref_uniform(ref_rng *r, double lo, double hi)
{
    r->s ^= r->s << 13;
    r->s ^= r->s >> 7;
    r->s ^= r->s << 17;
    return lo + (hi - lo) * (double)(r->s >> 11) * (1.0 / 9007199254740992.0);
}

static inline double ref_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* One check: prints what was checked, the max error seen and the tolerance,
 * and counts failures. */
static inline void ref_check(int *fails, const char *what, double err, double tol)
{
    const int ok = err <= tol;   /* NaN fails */
    printf("%-4s %-64s max err %.3e (tol %.1e)\n", ok ? "ok" : "FAIL", what,
           err, tol);
    if (!ok)
        ++*fails;
}

#endif /* HFS_TEST_SH_UTIL_H */
