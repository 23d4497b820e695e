/*
 * gles_shade.frag - exit radiance at full resolution (DESIGN.md "Shading",
 * "GLES path").  Per texel: the full-resolution normal N and the clamped
 * cosine H(N) as SH;
 *   environment  Lo += rho/pi * (H * V_env) . L_env per channel, V_env =
 *                hemisphere(N) + the grid's V_env - hemisphere(N_receiver)
 *                read bilinearly (exact at grid points), clamped into
 *                [-neg, rho/pi H . L_env + neg] (u_env_neg);
 *   key light    Lo += rho/pi * Le * E_cap(N.d, alpha) * clamp(num/den, 0, 1),
 *                num = V_key . (H * L_key), den = V_open . (H * L_key); the
 *                horizons are floor_j(N) + excess_j, the excess read
 *                bilinearly from the visibility grid, and V_open uses the
 *                floors of this texel's normal (no fetch).
 *   local lights (HFS_LOCAL) Lo += rho/pi * Le * E_cap * ratio, E_cap at
 *                the texel, the ratio read bilinearly from the grid of
 *                gles_local.frag (local_lights below).
 * The products use the generated SH product (sh_product.glsl.inc).
 * Output: linear RGB times a power-of-two scale (u_misc.y, on both
 * precisions) that keeps the frame inside fp16's range, as an fp16 hi + lo
 * pair in two targets (the readback adds them and divides the scale out
 * exactly).
 *
 * HfsKeys holds one record per key light (runtime/gles_setup.h
 * hfs_gles_pack_key), starting at vec4 u_koff[q].
 */
// hfs-variant: HFS_TABLES 1
// hfs-variant: HFS_FP32 1
// hfs-variant: HFS_LOCAL 1
// hfs-variant: HFS_LOCAL 1, HFS_FP32 1

#ifndef HFS_KEY_VEC4
#define HFS_KEY_VEC4 1
#endif
#ifndef HFS_TABLE_N
#define HFS_TABLE_N 257
#endif
#ifndef HFS_HALF_PI
#define HFS_HALF_PI 1.5707963267948966
#endif
#ifndef HFS_PI
#define HFS_PI 3.14159265358979
#endif

precision highp float;
precision highp int;
precision highp sampler2D;
precision highp sampler2DArray;

vec3 hfs_normal(vec4 t);
vec4 hfs_visible(float omega, vec4 win, vec4 occ_top);
void hfs_sh_cosine(vec3 n, out vec4 h[4]);
void hfs_sh_hemisphere(vec3 n, out vec4 h[4]);
float hfs_sh_dot(vec4 a[4], vec4 b[4]);
float hfs_table_coord(float omega, float n);
void hfs_table_add(highp sampler2DArray tab, vec2 uv, float layer0, bool mirror, vec3 c,
                   vec3 s, inout vec4 V[4]);
float hfs_cap_irradiance(float cos_beta, float alpha);
float hfs_cap_irradiance_sc(float cos_beta, float s, float c);
vec4 hfs_f16v(vec4 v);
void hfs_sh_product(in vec4 a[4], in vec4 b[4], out vec4 c[4]);

uniform highp sampler2D u_normals;       /* full resolution */
uniform highp sampler2D u_v0;            /* V_env, visibility grid, LINEAR */
uniform highp sampler2D u_v1;
uniform highp sampler2D u_v2;
uniform highp sampler2D u_v3;
uniform highp sampler2DArray u_keyhz;    /* key horizon excess (hi, lo) x 2, LINEAR */
#ifdef HFS_TABLES
uniform highp sampler2DArray u_ktab;     /* interior tables, 4 layers per set */
uniform highp sampler2DArray u_ktabb;    /* boundary tables (n x 1), 4 per set */
#endif
uniform ivec2 u_size;                    /* W, H */
uniform ivec2 u_vsize;                   /* visibility grid size */
uniform int u_sub;
uniform int u_nkeys;
uniform int u_koff[8];

layout(std140) uniform HfsShade {
    vec4 u_env[12];                      /* L_env, 4 vec4 per channel */
    vec4 u_misc;                         /* (rho/pi, out scale, has env, 0) */
    vec4 u_env_neg;                      /* rho * negative part of L_env per channel */
};
layout(std140) uniform HfsKeys {
    vec4 u_k[HFS_KEY_VEC4];
};

layout(location = 0) out vec4 o_hi;       /* RGB hi (fp16-exact), 1 */
layout(location = 1) out vec4 o_lo;       /* RGB lo: hi + lo = value */

/* Texture coordinate of full-resolution point p on the visibility grid:
 * between receivers a = p / sub and a + 1 (at min((a+1) sub, W-1)). */
vec2 grid_uv(ivec2 p)
{
    ivec2 a = p / u_sub;
    ivec2 x0 = a * u_sub;
    ivec2 x1 = min(x0 + u_sub, u_size - 1);
    vec2 t = vec2(p - x0) / vec2(max(x1 - x0, ivec2(1)));
    return (vec2(a) + t + 0.5) / vec2(u_vsize);
}

#ifdef HFS_TABLES
void tab_add(inout vec4 V[4], float a, float b, bool boundary, int rot, float set)
{
    float n = float(HFS_TABLE_N);
    bool mirror = u_k[rot].w > 0.5;
    if (boundary)
        hfs_table_add(u_ktabb, vec2(hfs_table_coord(a, n), 0.5), 4.0 * set, mirror,
                      u_k[rot].xyz, u_k[rot + 1].xyz, V);
    else
        hfs_table_add(u_ktab, vec2(hfs_table_coord(a, n), hfs_table_coord(b, n)), 4.0 * set,
                      mirror, u_k[rot].xyz, u_k[rot + 1].xyz, V);
}
#endif

/* rho/pi * Le * E_cap * ratio for the key light whose record starts at b. */
vec3 key_light(int b, vec3 n, vec4 H[4], vec2 uv)
{
    vec4 h0 = u_k[b], h1 = u_k[b + 1], h2 = u_k[b + 2];
    float e_cap = hfs_cap_irradiance(dot(n, h1.xyz), h1.w);
    if (!(e_cap > 0.0))
        return vec3(0.0);
    vec4 L[4];
    for (int g = 0; g < 4; ++g)
        L[g] = u_k[b + 3 + g];
    vec4 M[4];
    hfs_sh_product(H, L, M);

    int nd = int(h0.x);
    bool full = h0.y > 0.5;
    float layer0 = h0.z;
    int sw = b + 7;                      /* the light's HfsSwath record */
    vec4 win = u_k[sw], occtop = u_k[sw + 1];
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
     * sum_j |C_j|_F |v_open_j| (u_k[dirs + j].z), so a den that the CPU's
     * test 1e-12 |L| |V_open| calls zero is zero here too. */
    float num = 0.0, den = 0.0, vo_norm = 0.0;
#endif
    vec4 exv = vec4(0.0);
    for (int j = 0; j < nd; ++j) {
        if (j % 2 == 0)
            exv = texture(u_keyhz, vec3(uv, layer0 + float(j / 2)));
        vec4 dj = u_k[dirs + j];
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
        vec4 w = M[0].x * u_k[c] + M[0].y * u_k[c + 1] + M[0].z * u_k[c + 2] +
                 M[0].w * u_k[c + 3] + M[1].x * u_k[c + 4] + M[1].y * u_k[c + 5] +
                 M[1].z * u_k[c + 6] + M[1].w * u_k[c + 7] + M[2].x * u_k[c + 8] +
                 M[2].y * u_k[c + 9] + M[2].z * u_k[c + 10] + M[2].w * u_k[c + 11] +
                 M[3].x * u_k[c + 12] + M[3].y * u_k[c + 13] + M[3].z * u_k[c + 14] +
                 M[3].w * u_k[c + 15];
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
    return u_misc.x * h2.rgb * (e_cap * ratio);
}

#ifdef HFS_LOCAL
/* ---- local spherical lights (DESIGN.md "Local lights", "GLES path"):
 * rho/pi * Le * E_cap * ratio per light, E_cap at this texel's own point
 * (lifted by 1e-4 dx, as the CPU) and normal, the visibility ratio read
 * bilinearly from the grid written by gles_local.frag (two lights per layer
 * as (hi, lo) pairs).  A texel inside the sphere gets rho Le (E = pi). */
#ifndef HFS_NLAYERS
#define HFS_NLAYERS 25
#endif
#ifndef HFS_LOCAL_DIRS
#define HFS_LOCAL_DIRS 16
#endif
#ifndef HFS_LOCAL_MAX
#define HFS_LOCAL_MAX 16
#endif

float hfs_h(vec2 t);

uniform highp sampler2DArray u_levels;
uniform highp sampler2DArray u_localv;  /* ratio (hi, lo) x 2 per layer, LINEAR */
uniform int u_nlocal;

layout(std140) uniform HfsLocal {
    vec4 u_lE[16];
    vec4 u_lg;                           /* (1, base, hscale, zscale/dx): texel units */
    vec4 u_lq;
    vec4 u_lights[2 * HFS_LOCAL_MAX];    /* (centre.xyz, radius), (Le.rgb, 0) */
    vec4 u_ldir[HFS_LOCAL_DIRS];
};

vec3 local_lights(ivec2 p, vec3 n, vec2 uv)
{
    float dx = u_lg.x;
    float z = u_lg.w * (u_lg.y + u_lg.z * hfs_h(texelFetch(u_levels,
                                                           ivec3(p, HFS_NLAYERS - 1), 0).xy));
    vec3 pw = vec3(vec2(p) * dx, z + 1e-4 * dx);
    vec3 sum = vec3(0.0);
    vec4 rv = vec4(0.0);
    for (int q = 0; q < u_nlocal; ++q) {
        if (q % 2 == 0)
            rv = texture(u_localv, vec3(uv, float(q / 2)));
        vec4 l0 = u_lights[2 * q], l1 = u_lights[2 * q + 1];
        vec3 v = l0.xyz - pw;
        float r = l0.w;
        float rho2 = dot(v.xy, v.xy);
        float c_tan = (rho2 - r * r) + v.z * v.z;  /* as gles_local.frag */
        if (!(c_tan > 0.0)) {
            sum += u_misc.x * HFS_PI * l1.rgb;
            continue;
        }
        float d = length(v);
        float e_cap = hfs_cap_irradiance_sc(dot(n, v / d), r / d, sqrt(c_tan) / d);
        if (!(e_cap > 0.0))
            continue;
        float ratio = clamp(q % 2 == 0 ? rv.x + rv.y : rv.z + rv.w, 0.0, 1.0);
        sum += u_misc.x * l1.rgb * (e_cap * ratio);
    }
    return sum;
}
#endif

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 n = hfs_normal(texelFetch(u_normals, p, 0));
    vec4 H[4];
    hfs_sh_cosine(n, H);
    vec2 uv = grid_uv(p);
    vec3 lo = vec3(0.0);
    if (u_misc.z > 0.5) {
        vec4 V[4];
        V[0] = texture(u_v0, uv);
        V[1] = texture(u_v1, uv);
        V[2] = texture(u_v2, uv);
        V[3] = texture(u_v3, uv);
        vec4 hemi[4];
        hfs_sh_hemisphere(n, hemi);
        for (int g = 0; g < 4; ++g)
            V[g] += hemi[g];
        vec4 T[4];
        hfs_sh_product(H, V, T);
        vec4 L[4];
        for (int c = 0; c < 3; ++c) {
            for (int g = 0; g < 4; ++g)
                L[g] = u_env[4 * c + g];
            /* Into [-neg, unshadowed + neg], as cpu_render.c env_clamp: the
             * interval holds the exact value, and sub-sampling (V of other
             * normals) or fp16 storage can step outside it. */
            float open = u_misc.x * hfs_sh_dot(H, L);
            lo[c] += clamp(u_misc.x * hfs_sh_dot(T, L), -u_env_neg[c], open + u_env_neg[c]);
        }
    }
    for (int q = 0; q < u_nkeys; ++q)
        lo += key_light(u_koff[q], n, H, uv);
#ifdef HFS_LOCAL
    lo += local_lights(p, n, uv);
#endif
    vec3 v = lo * u_misc.y;
    /* Never NaN/Inf in the target (fp16 saturates at 65504). */
    v = clamp(v, vec3(-65504.0), vec3(65504.0));
    v = mix(vec3(0.0), v, equal(v, v));
    vec4 hi = hfs_f16v(vec4(v, 1.0));
    o_hi = hi;
    o_lo = hfs_f16v(vec4(v, 1.0) - hi);
}
