/*
 * view.frag - the 3-D view's surface (runtime/gles/pass_view.c): the lit
 * exit radiance at the fragment's grid position, bilinear between the four
 * grid points of its cell exactly as the truth's view reads it
 * (hfs_rgb_bilinear: clamped to the grid, the last row and column read
 * from the cell before them).  The four texels are fetched and weighted in
 * highp here rather than by the texture unit, whose weights may be 8-bit
 * fixed point on some GPUs; the radiance is the shading pass's fp16
 * (hi, lo) pair.  A diffuse surface looks the same from everywhere, so the
 * view only resamples the lighting; a glossy one was shaded for this
 * camera (renderer.c glossy_viewer: an ortho view's direction, or each
 * texel's own vector towards a perspective eye), so its highlight is
 * resampled as well: exact at the texels, bilinear between them.
 * Output: RGB times the view's power-of-two scale (u_zmap.w converts the
 * lit textures' scale into it), which keeps sky and terrain in fp16's
 * range; the read-back divides it out.  Seen through the view's haze
 * (gles_view.frag hfs_haze, view_look.h) when it has one.
 */
precision highp float;
precision highp int;
precision highp sampler2D;

uniform highp sampler2D u_lit_hi;       /* exit radiance, RGB hi, W x H */
uniform highp sampler2D u_lit_lo;       /* RGB lo: hi + lo = value */

layout(std140) uniform HfsView {
    mat4 u_mvp;
    vec4 u_eye;
    vec4 u_zmap;
    vec4 u_sizes;
    vec4 u_fwd;                         /* forward, the side walls' bottom z */
    vec4 u_right;
    vec4 u_up;
    vec4 u_env[12];
    vec4 u_bg;                          /* (mode, map scale, env_rotate, 0): view_sky.c */
    vec4 u_bg_rgb;                      /* studio level or colour, times the scale */
    vec4 u_haze;                        /* (sigma, z0, scale height, 0); 0: no haze */
    vec4 u_haze_in;                     /* in-scattered radiance, times the scale */
};

in highp vec2 v_grid;
in highp vec3 v_rel;

vec3 hfs_haze(vec3 rgb, vec4 haze, vec3 lin, vec3 rel, vec3 eye, vec3 fwd, bool ortho);

layout(location = 0) out vec4 o_color;

vec3 lit_at(ivec2 p)
{
    return texelFetch(u_lit_hi, p, 0).rgb + texelFetch(u_lit_lo, p, 0).rgb;
}

void main()
{
    vec2 last = u_sizes.xy - 1.0;
    vec2 g = clamp(v_grid, vec2(0.0), last);
    ivec2 c = min(ivec2(g), ivec2(last) - 1);
    vec2 f = g - vec2(c);
    vec3 a = lit_at(c) * (1.0 - f.x) + lit_at(c + ivec2(1, 0)) * f.x;
    vec3 b = lit_at(c + ivec2(0, 1)) * (1.0 - f.x) + lit_at(c + ivec2(1, 1)) * f.x;
    vec3 rgb = (a * (1.0 - f.y) + b * f.y) * u_zmap.w;
    if (u_haze.x > 0.0) /* off: the view without haze, bit for bit */
        rgb = hfs_haze(rgb, u_haze, u_haze_in.rgb, v_rel, u_eye.xyz, u_fwd.xyz, u_eye.w > 0.5);
    o_color = vec4(rgb, 1.0);
}
