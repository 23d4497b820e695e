/*
 * swath_oracle_def.h — the swath layout of DESIGN.md "Azimuth swaths" written
 * out for test_swath_oracle.c, without the code under test: the round
 * counts of the lattice, the NLP occlusion vector from the Legendre
 * polynomials, and what the definition fixes for a light (closed_form).
 * Static functions: include once, in that test program.
 */
#ifndef HFS_TEST_SWATH_ORACLE_DEF_H
#define HFS_TEST_SWATH_ORACLE_DEF_H

#include "lights.h"        /* HFS_MIN_VIS_ALPHA */
#include "test_sh_util.h" /* ref_legendre */

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define HALF_PI 1.57079632679489661923
#define TWO_PI 6.28318530717958647692

/* Round counts: 1, 2, 3, then m * 2^p for m = 4..7, p >= 0, ascending. */
#define N_ROUND 256
static double round_count[N_ROUND];
static int n_round;

static void init_round_counts(void)
{
    double r[N_ROUND];
    int n = 0;
    r[n++] = 1, r[n++] = 2, r[n++] = 3;
    for (int p = 0; p < 60; ++p)
        for (int m = 4; m <= 7; ++m)
            r[n++] = m * ldexp(1.0, p);
    /* already ascending: 4..7 * 2^p < 8 * 2^p = 4 * 2^(p+1) */
    for (int i = 1; i < n; ++i)
        if (!(r[i] > r[i - 1]))
            abort();
    memcpy(round_count, r, sizeof r);
    n_round = n;
}

/* Index of N among the round counts, or -1. */
static int round_index(double N)
{
    for (int i = 0; i < n_round; ++i)
        if (round_count[i] == N)
            return i;
    return -1;
}

/* x reduced to [0, 2 pi). */
static double wrap_2pi(double x)
{
    double r = fmod(x, TWO_PI);
    if (r < 0)
        r += TWO_PI;
    return r;
}

/* Distance of x from the nearest integer. */
static double frac_dist(double x) { return fabs(x - nearbyint(x)); }

/* The NLP occlusion vector occ_l(sigma) = integral_{-1}^{sin sigma} P^_l,
 * P^_l = sqrt((2l+1)/2) P_l, from int P_l = (P_{l+1} - P_{l-1}) / (2l+1). */
static void occ_closed(double sigma, double out[4])
{
    if (sigma < -HALF_PI)
        sigma = -HALF_PI;
    if (sigma > HALF_PI)
        sigma = HALF_PI;
    const double t = sin(sigma);
    out[0] = sqrt(0.5) * (t + 1.0);
    for (int l = 1; l < 4; ++l)
        out[l] = sqrt((2 * l + 1) / 2.0) * (ref_legendre(l + 1, t) - ref_legendre(l - 1, t)) / (2 * l + 1);
}

/* What the definition fixes for a light; "ambiguous" marks the measure-zero
 * ties (|e| + alpha within 1e-12 of pi/2; n_max within 1e-12 of a round
 * count) where either choice is accepted. */
typedef struct expect {
    int full, full_ambiguous;
    double h;           /* partial only */
    double n_max;       /* pi nphi_key / h: 2 pi over the disk's own spacing */
    double lo, hi;
} expect;

static void closed_form(double phi, double elev, double alpha, int nk, expect *x)
{
    (void)phi;
    if (alpha < HFS_MIN_VIS_ALPHA) /* the documented floor (lights.h) */
        alpha = HFS_MIN_VIS_ALPHA;
    const double margin = fabs(elev) + alpha - HALF_PI;
    x->full = margin >= 0.0;
    x->full_ambiguous = fabs(margin) < 1e-12;
    x->h = x->full ? NAN : asin(sin(alpha) / cos(elev));
    x->n_max = x->full ? NAN : PI * (nk < 1 ? 1 : nk) / x->h;
    x->lo = elev - alpha < -HALF_PI ? -HALF_PI : elev - alpha;
    x->hi = elev + alpha > HALF_PI ? HALF_PI : elev + alpha;
}

#endif /* HFS_TEST_SWATH_ORACLE_DEF_H */
