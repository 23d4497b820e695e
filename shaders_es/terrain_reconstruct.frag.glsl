/*
 * terrain_reconstruct.frag - a pyramid level brought back to the full W x H
 * grid: the uniform cubic B-spline of its samples evaluated at the grid
 * points (DESIGN.md "Height pyramid"), with bilinear fetches instead of
 * taps (Sigg & Hadwiger, GPU Gems 2 ch. 20; SN08 section 6).  Per axis the
 * weights w0..w3 of taps x0-1..x0+2 become two linear fetches at
 * x0 - 1 + w1/(w0+w1) and x0 + 1 + w3/(w2+w3) with weights g0 = w0+w1 and
 * g1 = w2+w3; CLAMP_TO_EDGE makes both fetches read clamped indices, like
 * the CPU's taps (runtime/cpu/cpu_pyramid.c bspline_taps).  Results are
 * combined in difference (lerp) form, exact for a constant level.
 *
 * Default: separable, like the CPU: pass u_axis = 0 takes the level
 * (lw x lh) to W x lh along x, pass u_axis = 1 takes that to W x H along y
 * (2 fetches per output texel and pass: 2 W lh + 2 W H per level).
 * HFS_RECON_V (= 1..4): the y pass of HFS_RECON_V levels at once, one per
 * colour target (u_vsrc[k], u_vsize[k]): fewer draws and fragments.
 * HFS_RECON_2D: one pass, 4 bilinear fetches per grid point (4 W H).
 * Either way the same function; the separable form fetches ~40% less.
 *
 * Uniforms: u_src (LINEAR, CLAMP_TO_EDGE; its own size exactly), u_src_size,
 * u_dst_size, u_axis.
 */
// hfs-variant: HFS_FP32 1
// hfs-variant: HFS_RECON_2D 1
// hfs-variant: HFS_RECON_V 4

precision highp float;
precision highp int;
precision highp sampler2D;

vec2 hfs_split(float v);
vec2 hfs_pair_tex(highp sampler2D t, vec2 uv);
float hfs_h(vec2 t);
float hfs_hdiff(vec2 a, vec2 b);

uniform highp sampler2D u_src;
uniform ivec2 u_src_size;
uniform ivec2 u_dst_size;
uniform int u_axis;

#ifdef HFS_RECON_V
uniform highp sampler2D u_vsrc[HFS_RECON_V];   /* x-pass results, W x lh_k */
uniform ivec2 u_vsize[HFS_RECON_V];            /* (W, lh_k) */
#endif

layout(location = 0) out vec4 o_h;
#if defined(HFS_RECON_V) && HFS_RECON_V > 1
layout(location = 1) out vec4 o_h1;
#endif
#if defined(HFS_RECON_V) && HFS_RECON_V > 2
layout(location = 2) out vec4 o_h2;
#endif
#if defined(HFS_RECON_V) && HFS_RECON_V > 3
layout(location = 3) out vec4 o_h3;
#endif

/* One axis: position x (level texel units, x = (g + 0.5) n / full - 0.5) ->
 * the two fetch positions (normalized by n) and the weight g1 of the second. */
void taps(float x, float n, out float p0, out float p1, out float g1)
{
    float x0 = floor(x);
    float f = x - x0;
    float u = 1.0 - f;
    float w0 = u * u * u * (1.0 / 6.0);
    float w1 = ((3.0 * f - 6.0) * f * f + 4.0) * (1.0 / 6.0);
    float w3 = f * f * f * (1.0 / 6.0);
    float g0 = w0 + w1;
    g1 = 1.0 - g0;
    p0 = (x0 - 0.5 + w1 / g0) / n;       /* (x0 - 1 + w1/g0 + 0.5) / n */
    p1 = (x0 + 1.5 + w3 / g1) / n;       /* (x0 + 1 + w3/g1 + 0.5) / n */
}

#ifdef HFS_RECON_V
/* The y pass of one level: its x-pass result src (W x lh) to row y. */
vec4 vpass(highp sampler2D src, ivec2 size)
{
    float n = float(size.y);
    float y = gl_FragCoord.y * n / float(u_dst_size.y) - 0.5;
    float p0, p1, t;
    taps(y, n, p0, p1, t);
    float cx = gl_FragCoord.x / float(size.x);
    vec2 sa = hfs_pair_tex(src, vec2(cx, p0)), sb = hfs_pair_tex(src, vec2(cx, p1));
    return vec4(hfs_split(hfs_h(sa) + t * hfs_hdiff(sb, sa)), 0.0, 0.0);
}
#endif

void main()
{
#ifdef HFS_RECON_V
    o_h = vpass(u_vsrc[0], u_vsize[0]);
#if HFS_RECON_V > 1
    o_h1 = vpass(u_vsrc[1], u_vsize[1]);
#endif
#if HFS_RECON_V > 2
    o_h2 = vpass(u_vsrc[2], u_vsize[2]);
#endif
#if HFS_RECON_V > 3
    o_h3 = vpass(u_vsrc[3], u_vsize[3]);
#endif
    return;
#endif
    vec2 ls = vec2(u_src_size);
    vec2 x = gl_FragCoord.xy * ls / vec2(u_dst_size) - 0.5;
#ifdef HFS_RECON_2D
    float px0, px1, gx, py0, py1, gy;
    taps(x.x, ls.x, px0, px1, gx);
    taps(x.y, ls.y, py0, py1, gy);
    vec2 s00 = hfs_pair_tex(u_src, vec2(px0, py0));
    vec2 s10 = hfs_pair_tex(u_src, vec2(px1, py0));
    vec2 s01 = hfs_pair_tex(u_src, vec2(px0, py1));
    vec2 s11 = hfs_pair_tex(u_src, vec2(px1, py1));
    float top = hfs_h(s00) + gx * hfs_hdiff(s10, s00);
    float bot = hfs_h(s01) + gx * hfs_hdiff(s11, s01);
    o_h = vec4(hfs_split(top + gy * (bot - top)), 0.0, 0.0);
#else
    /* Along one axis; the other coordinate is this texel's own centre (the
     * source has the destination's size on that axis). */
    vec2 c = gl_FragCoord.xy / ls;
    float p0, p1, t;
    vec2 a, b;
    if (u_axis == 0) {
        taps(x.x, ls.x, p0, p1, t);
        a = vec2(p0, c.y);
        b = vec2(p1, c.y);
    } else {
        taps(x.y, ls.y, p0, p1, t);
        a = vec2(c.x, p0);
        b = vec2(c.x, p1);
    }
    vec2 sa = hfs_pair_tex(u_src, a), sb = hfs_pair_tex(u_src, b);
    o_h = vec4(hfs_split(hfs_h(sa) + t * hfs_hdiff(sb, sa)), 0.0, 0.0);
#endif
}
