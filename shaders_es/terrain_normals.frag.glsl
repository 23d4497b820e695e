/*
 * terrain_normals.frag - unit normals at full resolution (SPEC: central
 * differences of world z, one-sided at the border; runtime/core/field_geom.c
 * hfs_field_normal, including its overflow-safe scaling).  Output RGBA:
 * the upper-hemisphere octahedral coordinates p = (nx, ny) / (|nx| + |ny| +
 * nz) as (px hi, px lo, py hi, py lo); hfs_normal (gles_lib) decodes
 * N = normalize(px, py, 1 - |px| - |py|).  Why not (nx, ny) with nz =
 * sqrt(1 - nx^2 - ny^2): on a near-vertical wall (slope 1e4, nz = 1e-4)
 * nx^2 + ny^2 = 1 - 1e-8 is below float's resolution at 1 and nz came back
 * 2-3x wrong (1e-3 of the frame on relief_1e5 of tools/hfstress, on fp16
 * and fp32 alike); 1 - |px| - |py| = nz / (|nx| + |ny| + nz) is an
 * absolute quantity that hi + lo keep to ~2^-22 at every slope.
 *
 * Uniforms: u_height (input level, RG hi+lo, texelFetch), u_size (W, H),
 * u_zfactor = hscale * zscale / dx (world slope per unit of normalized
 * height difference per texel, clamped to 1e30).
 */
// hfs-variant: HFS_FP32 1

precision highp float;
precision highp int;
precision highp sampler2D;

vec2 hfs_split(float v);
float hfs_hdiff(vec2 a, vec2 b);

uniform highp sampler2D u_height;
uniform ivec2 u_size;
uniform float u_zfactor;

layout(location = 0) out vec4 o_n;

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 lo = max(p - 1, ivec2(0)), hi = min(p + 1, u_size - 1);
    vec2 hx0 = texelFetch(u_height, ivec2(lo.x, p.y), 0).xy;
    vec2 hx1 = texelFetch(u_height, ivec2(hi.x, p.y), 0).xy;
    vec2 hy0 = texelFetch(u_height, ivec2(p.x, lo.y), 0).xy;
    vec2 hy1 = texelFetch(u_height, ivec2(p.x, hi.y), 0).xy;
    vec2 span = vec2(max(hi - lo, ivec2(1)));
    float gx = hfs_hdiff(hx1, hx0) * u_zfactor / span.x;
    float gy = hfs_hdiff(hy1, hy0) * u_zfactor / span.y;
    float m = max(1.0, max(abs(gx), abs(gy)));
    vec3 g = vec3(gx / m, gy / m, 1.0 / m);
    /* N is proportional to (-g.x, -g.y, g.z): no normalization needed. */
    vec2 o = -g.xy / (abs(g.x) + abs(g.y) + g.z);
    o_n = vec4(hfs_split(o.x), hfs_split(o.y));
}
