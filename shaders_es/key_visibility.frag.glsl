/*
 * key_visibility.frag - one key light's per-texel factor at full resolution
 * (DESIGN.md "Shading", "GLES path", "Frame planner"):
 *   f = E_cap(N.d, alpha) * clamp(num/den, 0, 1),
 *   num = V_key . (H * L_key), den = V_open . (H * L_key); the horizons are
 *   floor_j(N) + excess_j, the excess read bilinearly from the visibility
 *   grid (key_horizons.frag), and V_open uses the floors of this texel's normal.
 * The shading pass multiplies f by rho/pi Le: a re-tinted or dimmed key
 * light, or any change of the other lights, keeps f.  Stored as f / E_max
 * (u_emax = pi sin^2 alpha, f's largest value, so the stored value is in
 * [0, 1] whatever the disk's size: a 1e-7 rad sun's E_cap is far below
 * fp16's range) as an fp16 (hi, lo) pair in one layer of an RG array.
 * HfsKeys holds one record per key light (runtime/gles/uniform_blocks.h
 * hfs_gles_pack_key), this light's from vec4 u_k[u_kb].
 */
// hfs-variant: HFS_TABLES 1
// hfs-variant: HFS_FP32 1
// hfs-variant: HFS_KEYS_TEX 1
// hfs-variant: HFS_KEYS_TEX 1, HFS_TABLES 1

#ifndef HFS_KEY_VEC4
#define HFS_KEY_VEC4 1
#endif
#ifndef HFS_TABLE_N
#define HFS_TABLE_N 257
#endif
#ifndef HFS_HALF_PI
#define HFS_HALF_PI 1.5707963267948966
#endif

precision highp float;
precision highp int;
precision highp sampler2D;
precision highp sampler2DArray;

vec3 hfs_normal(vec4 t);
vec4 hfs_visible(float omega, vec4 win, vec4 occ_top);
void hfs_sh_cosine(vec3 n, out vec4 h[4]);
float hfs_sh_dot(vec4 a[4], vec4 b[4]);
float hfs_table_coord(float omega, float n);
void hfs_table_add(highp sampler2DArray tab, vec2 uv, float layer0, bool mirror, vec3 c,
                   vec3 s, inout vec4 V[4]);
float hfs_cap_irradiance(float cos_beta, float alpha);
vec2 hfs_split(float v);
vec2 hfs_grid_uv(ivec2 p, int sub, ivec2 size, ivec2 vsize);
void hfs_sh_product(in vec4 a[4], in vec4 b[4], out vec4 c[4]);

uniform highp sampler2D u_normals;       /* full resolution */
uniform highp sampler2DArray u_keyhz;    /* key horizon excess (hi, lo) x 2, LINEAR */
#ifdef HFS_TABLES
uniform highp sampler2DArray u_ktab;     /* interior tables, 4 layers per set */
uniform highp sampler2DArray u_ktabb;    /* boundary tables (n x 1), 4 per set */
#endif
uniform ivec2 u_size;                    /* W, H */
uniform ivec2 u_vsize;                   /* visibility grid size */
uniform int u_sub;
uniform int u_kb;                        /* this light's record in u_k */
uniform float u_emax;                    /* pi sin^2 alpha */

#ifdef HFS_KEYS_TEX
/* The records from a texture (too large for a uniform block). */
vec4 hfs_block_vec4(highp usampler2D t, int i);
uniform highp usampler2D u_keys_tex;
#define KREC(i) hfs_block_vec4(u_keys_tex, (i))
#else
layout(std140) uniform HfsKeys {
    vec4 u_k[HFS_KEY_VEC4];
};
#define KREC(i) u_k[i]
#endif

layout(location = 0) out vec4 o_f;       /* (f / E_max hi, lo, 0, 1) */

#ifdef HFS_TABLES
void tab_add(inout vec4 V[4], float a, float b, bool boundary, int rot, float set)
{
    float n = float(HFS_TABLE_N);
    bool mirror = KREC(rot).w > 0.5;
    if (boundary)
        hfs_table_add(u_ktabb, vec2(hfs_table_coord(a, n), 0.5), 4.0 * set, mirror,
                      KREC(rot).xyz, KREC(rot + 1).xyz, V);
    else
        hfs_table_add(u_ktab, vec2(hfs_table_coord(a, n), hfs_table_coord(b, n)), 4.0 * set,
                      mirror, KREC(rot).xyz, KREC(rot + 1).xyz, V);
}
#endif

/* E_cap * ratio for the key light whose record starts at b. */
float key_factor(int b, vec3 n, vec4 H[4], vec2 uv)
{
    vec4 h0 = KREC(b), h1 = KREC(b + 1), h2 = KREC(b + 2);
    float e_cap = hfs_cap_irradiance(dot(n, h1.xyz), h1.w);
    if (!(e_cap > 0.0))
        return 0.0;
    vec4 L[4];
    for (int g = 0; g < 4; ++g)
        L[g] = KREC(b + 3 + g);
    vec4 M[4];
    hfs_sh_product(H, L, M);

    int nd = int(h0.x);
    bool full = h0.y > 0.5;
    float layer0 = h0.z;
    int sw = b + 7;                      /* the light's HfsSwath record */
    vec4 win = KREC(sw), occtop = KREC(sw + 1);
    int dirs = sw + 2, cm = sw + 2 + nd, rot = sw + 2 + 17 * nd;
#ifdef HFS_TABLES
    vec4 Vk[4], Vo[4];
    for (int g = 0; g < 4; ++g) {
        Vk[g] = vec4(0.0);
        Vo[g] = vec4(0.0);
    }
    float om_prev = 0.0, fl_prev = 0.0, om_first = 0.0, fl_first = 0.0;
#else
    /* V.M = sum_j v_j . (C_j^T M): one 16x4 product per direction serves
     * num and den.  |V_open| (the threshold's scale) is bounded by
     * sum_j |C_j|_F |v_open_j| (KREC(dirs + j).z), so a den that the CPU's
     * test 1e-12 |L| |V_open| calls zero is zero here too. */
    float num = 0.0, den = 0.0, vo_norm = 0.0;
#endif
    vec4 exv = vec4(0.0);
    for (int j = 0; j < nd; ++j) {
        if (j % 2 == 0)
            exv = texture(u_keyhz, vec3(uv, layer0 + float(j / 2)));
        vec4 dj = KREC(dirs + j);
        float fl = atan(-(n.x * dj.x + n.y * dj.y), n.z);
        float ex = j % 2 == 0 ? exv.x + exv.y : exv.z + exv.w;
        float om = min(fl + ex, HFS_HALF_PI);
#ifdef HFS_TABLES
        if (j == 0) {
            om_first = om;
            fl_first = fl;
            if (!full) {
                tab_add(Vk, om, 0.0, true, rot, h0.w);
                tab_add(Vo, fl, 0.0, true, rot, h0.w);
            }
        } else {
            int w = full ? j - 1 : j;
            tab_add(Vk, om_prev, om, false, rot + 2 * w, h0.w);
            tab_add(Vo, fl_prev, fl, false, rot + 2 * w, h0.w);
        }
        om_prev = om;
        fl_prev = fl;
#else
        int c = cm + 16 * j;
        vec4 w = M[0].x * KREC(c) + M[0].y * KREC(c + 1) + M[0].z * KREC(c + 2) +
                 M[0].w * KREC(c + 3) + M[1].x * KREC(c + 4) + M[1].y * KREC(c + 5) +
                 M[1].z * KREC(c + 6) + M[1].w * KREC(c + 7) + M[2].x * KREC(c + 8) +
                 M[2].y * KREC(c + 9) + M[2].z * KREC(c + 10) + M[2].w * KREC(c + 11) +
                 M[3].x * KREC(c + 12) + M[3].y * KREC(c + 13) + M[3].z * KREC(c + 14) +
                 M[3].w * KREC(c + 15);
        vec4 vo = hfs_visible(fl, win, occtop);
        num += dot(hfs_visible(om, win, occtop), w);
        den += dot(vo, w);
        vo_norm += dj.z * length(vo);
#endif
    }
#ifdef HFS_TABLES
    if (full) {
        tab_add(Vk, om_prev, om_first, false, rot + 2 * (nd - 1), h0.w);
        tab_add(Vo, fl_prev, fl_first, false, rot + 2 * (nd - 1), h0.w);
    } else {
        tab_add(Vk, om_prev, 0.0, true, rot + 2 * nd, h0.w);
        tab_add(Vo, fl_prev, 0.0, true, rot + 2 * nd, h0.w);
    }
    float num = hfs_sh_dot(Vk, M), den = hfs_sh_dot(Vo, M);
    float vo_norm = sqrt(hfs_sh_dot(Vo, Vo));
#endif
    float ratio = 0.0;
    if (den > 1e-12 * h2.w * vo_norm)
        ratio = clamp(num / den, 0.0, 1.0);
    return e_cap * ratio;
}


void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 n = hfs_normal(texelFetch(u_normals, p, 0));
    vec4 H[4];
    hfs_sh_cosine(n, H);
    vec2 uv = hfs_grid_uv(p, u_sub, u_size, u_vsize);
    float f = clamp(key_factor(u_kb, n, H, uv) / u_emax, 0.0, 1.0);
    o_f = vec4(hfs_split(f), 0.0, 1.0);
}
