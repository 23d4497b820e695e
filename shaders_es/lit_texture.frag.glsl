/*
 * lit_texture.frag - the frame's lit result (the shading or bounce pass's
 * fp16 hi + lo pair, RGB times the frame's output scale, pass_shade.c) as
 * the application's texture (pass_lit_texture.c, hfshade.h
 * hfs_lit_encoding), drawn with fullscreen.vert over the field's size:
 *   u_encoding 0: linear radiance (hi + lo) * u_inv_scale into RGBA16F,
 *                 clamped to fp16's +-65504 (the target would round beyond
 *                 it to infinity);
 *   u_encoding 1: the kiosk's picture, hfs_srgb8_encode_rgb (runtime/io/
 *                 tonemap.c, hfs_io.h "Display mapping"): tonemap(u_exposure
 *                 v) (0 clamp, 1 Reinhard, 2 max-RGB extended Reinhard: the
 *                 SAME curve as hfs_tonemap_rgb, test_gles_embed compares
 *                 the bytes), the sRGB OETF, into RGBA8 (the target rounds
 *                 x 255).
 * u_inv_scale is 1 / scale clamped to float's range in C: beyond it the
 * radiance is beyond fp16's either way.  Texel (i, j) reads texel (i, j):
 * no flip, row j = 0 stays at t near 0.
 */
precision highp float;

uniform highp sampler2D u_hi;
uniform highp sampler2D u_lo;
uniform float u_inv_scale;
uniform int u_encoding;
uniform int u_tonemap;
uniform float u_exposure;

layout(location = 0) out vec4 o_color;

vec3 srgb_oetf(vec3 x)
{
    vec3 lo = 12.92 * x;
    vec3 hi = 1.055 * pow(x, vec3(1.0 / 2.4)) - 0.055;
    return mix(hi, lo, lessThan(x, vec3(0.0031308)));
}

/* hfs_tonemap_rgb's HFS_TONEMAP_HUE: the largest channel through the
 * extended Reinhard shoulder (white point 16), all three scaled by the same
 * factor so their ratios (hue, saturation) are kept. */
vec3 tonemap_hue(vec3 x)
{
    const float white = 16.0;
    x = max(x, 0.0);
    float n = max(max(x.r, x.g), x.b);
    float r = n >= white ? 1.0 : n * (1.0 + n / (white * white)) / (1.0 + n);
    return n > 0.0 ? x * (r / n) : vec3(0.0);
}

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 v = (texelFetch(u_hi, p, 0).rgb + texelFetch(u_lo, p, 0).rgb) * u_inv_scale;
    if (u_encoding == 0) {
        o_color = vec4(clamp(v, -65504.0, 65504.0), 1.0);
        return;
    }
    vec3 x = u_exposure * v;
    if (u_tonemap == 2)
        x = tonemap_hue(x);
    else
        x = u_tonemap == 1 ? max(x, 0.0) / (1.0 + max(x, 0.0)) : clamp(x, 0.0, 1.0);
    o_color = vec4(srgb_oetf(x), 1.0);
}
