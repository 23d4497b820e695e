/*
 * gl_pattern.h — test helper: render shaders_es/pattern.frag into an RGBA16F
 * target and compare it with the same function computed in C.
 *
 * Tolerance (per channel value v of the C reference, in double):
 *   |got - v| <= ulp16(v) + 1e-6 |v|  (+ 2^-12 for the sin*cos channel)
 * ulp16(v) is the fp16 spacing at |v| (2^(floor(log2|v|) - 10), 2^-24 below
 * 2^-14): one full ulp covers any rounding mode of the float->half store,
 * 1e-6 |v| the fp32 shader arithmetic, 2^-12 the unspecified accuracy of
 * sin/cos in highp.  Values below the smallest normal fp16 (2^-14) may also
 * read back as 0 (GPUs may flush fp16 denormals).
 */
#ifndef HFS_TEST_GL_PATTERN_H
#define HFS_TEST_GL_PATTERN_H

#include "gl_api.h"

#define PATTERN_SIZE 64
#define PATTERN_GAIN 0.01f

/* The C twin of pattern.frag at pixel (i, j), channel c (0..3). */
double pattern_ref(int i, int j, int c, double sign);
double pattern_tolerance(int c, double ref);

/* Builds the program (with "HFS_PATTERN_SIGN -1.0" when sign < 0), renders
 * 64x64 RGBA16F, reads it back with every readback path the GL accepts and
 * compares.  Prints one line per problem (and the first mismatches) to
 * stderr; on a mismatch writes <tag>_actual.pfm, _expected.pfm, _diff.pfm
 * (RGB) into the working directory.  Returns the number of failures. */
int pattern_check(const hfs_gl *gl, double sign, const char *tag);

#endif /* HFS_TEST_GL_PATTERN_H */
