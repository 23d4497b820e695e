/*
 * sh_legendre.c — NS09 section 4: the normalized Legendre polynomial (NLP)
 * basis P^_l(z) = sqrt((2l+1)/2) P_l(z), l = 0..3, orthonormal on [-1, 1],
 * with z = sin(elevation), and the occlusion/visibility vectors of elevation
 * steps and bands in that basis.
 *
 * Invariants: y_l0 = sqrt(1/(2 pi)) P^_l (NS09 eq. 9), so an NLP vector is
 * the elevation profile of one azimuthal slice of an order-4 SH function.
 * (NS09 prints P^_2, P^_3 with 5 sqrt2/4 and 7 sqrt2/4; the normalized values
 * are sqrt(10)/4 and sqrt(14)/4 — its analytic occlusion form, which we use,
 * is consistent with the latter.)
 */
#include "sh.h"

#include <math.h>

#define HALF_PI 1.57079632679489661923

void hfs_nlp_eval(double z, double out[HFS_NLP_N])
{
    out[0] = 0.7071067811865476;                      /* sqrt(1/2)    */
    out[1] = 1.224744871391589 * z;                   /* sqrt(3/2)    */
    out[2] = 0.7905694150420949 * (3.0 * z * z - 1.0); /* sqrt(5/2)/2  */
    out[3] = 0.9354143466934853 * z * (5.0 * z * z - 3.0); /* sqrt(7/2)/2 */
}

/* NS09's analytic order-4 form: integral_{-1}^{sin sigma} P^(z) dz, written
 * with cos^2 sigma so that the vector is accurate near sigma = +-pi/2. */
void hfs_nlp_occlusion(double sigma, double out[HFS_NLP_N])
{
    if (!(sigma > -HALF_PI))
        sigma = -HALF_PI;
    if (sigma > HALF_PI)
        sigma = HALF_PI;
    const double s = sin(sigma), c = cos(sigma), c2 = c * c;
    out[0] = (s + 1.0) * 0.7071067811865476;              /* 1/sqrt(2)        */
    out[1] = -3.0 * c2 * 0.20412414523193154;              /* 1/(2 sqrt 6)     */
    out[2] = -5.0 * s * c2 * 0.15811388300841897;          /* 1/(2 sqrt 10)    */
    out[3] = 7.0 * c2 * (5.0 * c2 - 4.0) * 0.03340765523905305;/* 1/(8 sqrt 14) */
}

void hfs_nlp_visible_band(double lo, double hi, double out[HFS_NLP_N])
{
    if (!(lo > -HALF_PI))
        lo = -HALF_PI;
    if (hi > HALF_PI)
        hi = HALF_PI;
    if (!(lo < hi)) {
        for (int l = 0; l < HFS_NLP_N; ++l)
            out[l] = 0.0;
        return;
    }
    double a[HFS_NLP_N], b[HFS_NLP_N];
    hfs_nlp_occlusion(hi, b);
    hfs_nlp_occlusion(lo, a);
    for (int l = 0; l < HFS_NLP_N; ++l)
        out[l] = b[l] - a[l];
}
