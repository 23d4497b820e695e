/*
 * gles_normals.frag - unit normals at full resolution (SPEC: central
 * differences of world z, one-sided at the border; runtime/field_geom.c
 * hfs_field_normal, including its overflow-safe scaling).  Output RGBA:
 * (nx hi, nx lo, ny hi, ny lo); nz = sqrt(1 - nx^2 - ny^2) > 0 is implied.
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
    vec3 n = vec3(-g.x, -g.y, g.z) / length(g);
    o_n = vec4(hfs_split(n.x), hfs_split(n.y));
}
