/*
 * test_rng.h — the deterministic random numbers of the randomized tests:
 * xorshift64 (Marsaglia 2003), 53-bit doubles.  Each test draws the same
 * sequence on every machine and run, so a failure it prints is reproducible.
 * Define TEST_RNG_SEED (a non-zero 64-bit constant) before including to give
 * a test its own sequence.  Include once per test program.
 *
 *   urand()     uniform in [0, 1)
 *   uni(a, b)   uniform in [a, b)
 */
#ifndef HFS_TEST_RNG_H
#define HFS_TEST_RNG_H

#include <stdint.h>

#ifndef TEST_RNG_SEED
#define TEST_RNG_SEED 0x9e3779b97f4a7c15ull
#endif

static uint64_t rng_state = TEST_RNG_SEED;

static inline double urand(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return (double)(rng_state >> 11) * 0x1p-53;
}

static inline double uni(double a, double b) { return a + (b - a) * urand(); }

#endif /* HFS_TEST_RNG_H */
