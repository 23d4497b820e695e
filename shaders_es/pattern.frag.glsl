/*
 * pattern.frag - a known analytic pattern of gl_FragCoord, for the context
 * tests (tests/test_gl_context.c computes the same function in C).
 *
 * Channels cover what an fp16 target must hold: negative values, values
 * above 1, a smooth transcendental and small values near the bottom of the
 * normal fp16 range.  HFS_PATTERN_SIGN (a variant define, default 1.0)
 * flips the sign of every channel, to test the #define prefix.
 *
 *   x, y = gl_FragCoord.xy (pixel centres: i + 0.5, j + 0.5)
 *   r = (x - 32) / 4                     in [-8, 8]
 *   g = y * y / 64                       in [0, 64]
 *   b = sin(x / 8) * cos(y / 16)         in [-1, 1]
 *   a = u_gain * (x + 2y) / 1024         (u_gain = 0.01: ~1e-5 .. 2e-3)
 */
// hfs-variant: HFS_PATTERN_SIGN -1.0

#ifndef HFS_PATTERN_SIGN
#define HFS_PATTERN_SIGN 1.0
#endif

precision highp float;

uniform float u_gain;

in highp vec2 v_uv;
layout(location = 0) out vec4 o_color;

void main()
{
    vec2 p = gl_FragCoord.xy;
    vec4 c = vec4((p.x - 32.0) * 0.25,
                  p.y * p.y * (1.0 / 64.0),
                  sin(p.x * 0.125) * cos(p.y * 0.0625),
                  u_gain * (p.x + 2.0 * p.y) * (1.0 / 1024.0));
    o_color = HFS_PATTERN_SIGN * c;
}
