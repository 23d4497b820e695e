/*
 * test_sky.h — the order-4 sky of the tests against the ground truth
 * (test_cpu_truth.c, test_drift.c): 0.6 sqrt(4 pi) + 1.4 lobe(50, 25) +
 * 0.6 lobe(205, 8) (clamped-cosine ZH rotated to those azimuths /
 * elevations, in degrees) + 0.06 y9 - 0.05 y10 + 0.04 y11 - 0.03 y13 +
 * 0.07 y15, written out so that no library function under test makes the
 * test's input.  Min 0.48, max 2.05 over the sphere, not rotationally
 * symmetric, and not symmetric under x -> -x or y -> -y (|L(phi) - L(pi -
 * phi)| and |L(phi) - L(-phi)| reach 0.94 and 1.33 at elevation 15
 * degrees), so a sign error in a rotation or an azimuth moves its bright
 * side.
 */
#ifndef HFS_TEST_SKY_H
#define HFS_TEST_SKY_H

#include "hfshade.h"

static const double test_sky_sh[HFS_SH_COEFFS] = {
    3.899398, 0.737693, 0.690919, 0.283560, 0.679263, 0.322494, -0.300963, 0.231459,
    0.076591, 0.060000, -0.050000, 0.040000, 0.000000, -0.030000, 0.000000, 0.070000};

#endif
