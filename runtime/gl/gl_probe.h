/*
 * gl_probe.h — what a driver does that no query says, measured once per
 * context by a one-pixel draw.
 *
 * Filtering: GL ES leaves the precision of LINEAR filtering to the
 * implementation.  Mesa's llvmpipe blends in float at the exact position.
 * NVIDIA's hardware (seen on an H200, driver 580.159) keeps 8 bits of the
 * texel fraction (a blend up to 2^-9 of a texel off) and rounds a 16F
 * texture's blend to a half.  The renderer keeps heights, normals and
 * light ratios as (hi, lo) pairs of halves whose sum carries ~22 bits, or
 * as floats at fp32: such a filter rounds hi's blend to 11 bits (lo cannot
 * restore them) and moves every sample along its ray.  Measured on the
 * H200 against the CPU reference (256^2, sky + sun): p99 3.1e-4, max 6.0e-3
 * of the maximum at fp16, against 5.4e-5 and 2.7e-4 with the texels
 * blended by the shaders (BENCHMARKS.md "On a real GPU").  Where the
 * probe sees an inexact filter, the shaders fetch the four texels and
 * blend them in float (HFS_PAIR_FETCH, gles_lib.frag hfs_pair_tex).
 */
#ifndef HFS_GL_PROBE_H
#define HFS_GL_PROBE_H

#include "gl_api.h"

/* 1 when LINEAR filtering is inexact: an R16F blend of two adjacent
 * halves rounded (off by more than 1/64 of their step), or a blend's
 * position off by more than 2^-14 of a texel; also when the probe could
 * not run (the safe answer).  0 otherwise.  HFS_GL_PAIR_FETCH=1 in the
 * environment answers 1 without a probe (tests of the shaders' blend on a
 * driver that does not need it), =0 answers 0 (to measure what it costs
 * and buys on one that does).  The context gl was loaded from must be
 * current; leaves no binding changed (framebuffer, program, texture 0). */
int hfs_gl_probe_filter_inexact(const hfs_gl *gl);

#endif /* HFS_GL_PROBE_H */
