/*
 * truth_sampling.h — the ground truth's deterministic jitter and frames,
 * shared by the direct light (truth.c) and the bounces (truth_bounce.c):
 * splitmix64 streams seeded by a hash of (receiver, slot), so every
 * receiver's samples are its own and the output is bit identical for any
 * thread count.
 */
#ifndef HFS_TRUTH_SAMPLING_H
#define HFS_TRUTH_SAMPLING_H

#include <math.h>
#include <stdint.h>

static inline uint64_t mix64(uint64_t x)
{
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ULL;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebULL;
    x ^= x >> 31;
    return x;
}

/* splitmix64 stream seeded by (receiver, light slot). */
static inline uint64_t rng_seed(uint64_t receiver, int slot)
{
    return mix64(receiver * 0x9e3779b97f4a7c15ULL + (uint64_t)slot * 0xd1b54a32d192ed03ULL + 1);
}

static inline double rng_uniform(uint64_t *state)
{
    *state += 0x9e3779b97f4a7c15ULL;
    return (double)(mix64(*state) >> 11) * (1.0 / 9007199254740992.0); /* [0, 1) */
}

/* An orthonormal frame (t1, t2) about unit d. */
static inline void frame_around(const double d[3], double t1[3], double t2[3])
{
    /* Helper axis least aligned with d. */
    const double h[3] = {fabs(d[2]) < 0.9 ? 0.0 : 1.0, 0.0, fabs(d[2]) < 0.9 ? 1.0 : 0.0};
    double a[3] = {h[1] * d[2] - h[2] * d[1], h[2] * d[0] - h[0] * d[2], h[0] * d[1] - h[1] * d[0]};
    const double len = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    for (int k = 0; k < 3; ++k)
        t1[k] = a[k] / len;
    t2[0] = d[1] * t1[2] - d[2] * t1[1];
    t2[1] = d[2] * t1[0] - d[0] * t1[2];
    t2[2] = d[0] * t1[1] - d[1] * t1[0];
}

/* The direction of the Phong lobe about unit r (frame t1, t2) at (u1, u2)
 * in [0, 1)^2: the inverse CDF of (S+1) cos^S theta sin theta, 1 -
 * cos^(S+1) theta = u1 (inv_s1 = 1/(S+1)), and psi = 2 pi u2. */
static inline void lobe_direction(const double r[3], const double t1[3], const double t2[3],
                                  double inv_s1, double u1, double u2, double s[3])
{
    const double ct = pow(1.0 - u1, inv_s1);
    const double st = sqrt(fmax(0.0, 1.0 - ct * ct));
    const double psi = 2.0 * 3.14159265358979323846 * u2, cp = cos(psi), sp = sin(psi);
    for (int q = 0; q < 3; ++q)
        s[q] = ct * r[q] + st * (cp * t1[q] + sp * t2[q]);
}

#endif /* HFS_TRUTH_SAMPLING_H */
