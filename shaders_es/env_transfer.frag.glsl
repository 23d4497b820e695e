/*
 * env_transfer.frag - the occluded part of the environment's per-texel
 * transfer vector (DESIGN.md "Shading", "Frame planner").  The transfer is
 * T = H * V with H = the clamped cosine of the full-resolution normal N as
 * SH and V = hemisphere(N) + D, D = the grid's V_env - hemisphere(N_receiver)
 * read bilinearly (exact at grid points).  T = H * hemisphere(N) + H * D:
 * the first term is zonal about N and the shading pass evaluates it
 * exactly from N; this pass stores T_occ = H * D, which is 0 wherever
 * nothing occludes, so fp16 storage costs nothing there and elsewhere only
 * a fraction of the occluded part.  T does not depend on the environment's
 * radiance or rotation, so it is kept while only those change: a turned or
 * re-tinted environment costs the shading pass's dots (shade.frag),
 * not this product.
 * Output: T_occ's 16 coefficients in 4 RGBA targets, rounded to fp16 in the
 * shader (HFS_FP32: kept as is) so the stored value does not depend on how a
 * driver converts float to half.
 */
// hfs-variant: HFS_FP32 1

precision highp float;
precision highp int;
precision highp sampler2D;

vec3 hfs_normal_at(highp sampler2DArray h, ivec2 p, ivec2 size, float zf);
void hfs_sh_cosine(vec3 n, out vec4 h[4]);
vec4 hfs_f16v(vec4 v);
vec2 hfs_grid_uv(ivec2 p, int sub, ivec2 size, ivec2 vsize);
void hfs_sh_product(in vec4 a[4], in vec4 b[4], out vec4 c[4]);

uniform highp sampler2DArray u_height;   /* the heights (hi, lo): normals (hfs_normal_at) */
uniform float u_zf;                      /* hscale zscale / dx, clamped to 1e30 */
uniform highp sampler2D u_v0;            /* D = V_env - hemisphere, grid, LINEAR */
uniform highp sampler2D u_v1;
uniform highp sampler2D u_v2;
uniform highp sampler2D u_v3;
uniform ivec2 u_size;                    /* W, H */
uniform ivec2 u_vsize;                   /* visibility grid size */
uniform int u_sub;

layout(location = 0) out vec4 o_t0;
layout(location = 1) out vec4 o_t1;
layout(location = 2) out vec4 o_t2;
layout(location = 3) out vec4 o_t3;

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 n = hfs_normal_at(u_height, p, u_size, u_zf);
    vec4 H[4];
    hfs_sh_cosine(n, H);
    vec2 uv = hfs_grid_uv(p, u_sub, u_size, u_vsize);
    vec4 V[4];
    V[0] = texture(u_v0, uv);
    V[1] = texture(u_v1, uv);
    V[2] = texture(u_v2, uv);
    V[3] = texture(u_v3, uv);
    vec4 T[4];
    hfs_sh_product(H, V, T);
    o_t0 = hfs_f16v(T[0]);
    o_t1 = hfs_f16v(T[1]);
    o_t2 = hfs_f16v(T[2]);
    o_t3 = hfs_f16v(T[3]);
}
