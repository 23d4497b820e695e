/*
 * shade.frag - exit radiance at full resolution from the kept per-texel
 * products (DESIGN.md "Shading", "GLES path", "Frame planner"):
 *   environment  Lo += rho/pi * T . L_env per channel, T = H * V_env = the
 *                open part H * hemisphere(N), zonal about N and evaluated
 *                here as k_l Y_lm(N) (u_topen), plus the occluded part
 *                T_occ (env_transfer.frag, env_slices.frag) dotted with
 *                the sky on its own (hfs_env_occ, times u_occs); clamped
 *                into [-neg, rho/pi H . L_env + neg] (u_env_neg) with H =
 *                the clamped cosine of this texel's normal.  HFS_SLICE (the
 *                exact slice path): the open part is H itself, rho/pi
 *                H . L_env.  HFS_ENV_OCC: the occluded part's dot was
 *                taken by the sky occlusion pass (u_socc, u_socclo;
 *                pass_env_sky_occlusion.c), the same bits;
 *   key light q  Lo += rho/pi * Le E_max * f_q, f_q = E_cap ratio / E_max
 *                from key_visibility.frag (one layer per light, (hi, lo));
 *   local lights (HFS_LOCAL) Lo += rho/pi * Le * E_cap * ratio, E_cap at
 *                the texel, the ratio read bilinearly from the grid of
 *                local_visibility.frag (local_lights below).
 *   glossy (HFS_GLOSSY, runtime/core/gloss.h; DESIGN.md "Glossy surfaces") the
 *                Phong lobe about R = 2 (N.V) N - V, added after the albedo
 *                map: each key/local light's lobe at its centre times its
 *                factor E_cap ratio, the environment's ks (N.R) v L*lobe(R)
 *                with v = clamp(T.Q / H.Q, 0, 1), Q the lobe's ZH at R.
 *                HFS_GLOSSY 2: a viewer at a point (a perspective camera),
 *                V towards it from the texel's own point.
 *                Without it the program is the diffuse one, unchanged.
 *   env-shade = map (HFS_ENV_MAP; DESIGN.md "Shading from the map
 *                itself") the diffuse environment's open part is the map's
 *                own irradiance: H . L_env plus the table D(N') (u_eopen,
 *                runtime/core/env_open.h, N' = N turned by -rotate); with
 *                HFS_ENV_MAP 2 its occluded part is the map's too (u_mocc,
 *                pass_env_map_slices.c) instead of T . L_env's; the glossy
 *                lobe still reads T.  HFS_GLOSS_MAP (glossy): the lobe's
 *                radiance is the map's own, L*lobe(R) plus the table D_g(R')
 *                (u_egloss, runtime/core/env_gloss.h, R' = R turned by
 *                -rotate), its visible fraction v as above.
 * Everything that depends on the visibility was computed by those passes,
 * so this pass is what a turned or re-tinted environment or a change of
 * radiance costs.
 * Output: linear RGB times a power-of-two scale (folded into every radiance, on both
 * precisions) that keeps the frame inside fp16's range, as an fp16 hi + lo
 * pair in two targets (the readback adds them and divides the scale out
 * exactly).
 */
// hfs-variant: HFS_ENV 1
// hfs-variant: HFS_ENV 1, HFS_FP32 1
// hfs-variant: HFS_ENV 1, HFS_NKEYS 2
// hfs-variant: HFS_NKEYS 2
// hfs-variant: HFS_LOCAL 1
// hfs-variant: HFS_ENV 1, HFS_LOCAL 1, HFS_FP32 1
// hfs-variant: HFS_ENV 1, HFS_NKEYS 1, HFS_ALBEDO_MAP 1
// hfs-variant: HFS_ENV 1, HFS_NKEYS 2, HFS_LOCAL 1, HFS_GLOSSY 1
// hfs-variant: HFS_ENV 1, HFS_NKEYS 1, HFS_ALBEDO_MAP 1, HFS_GLOSSY 1, HFS_FP32 1
// hfs-variant: HFS_ENV 1, HFS_NKEYS 1, HFS_GLOSSY 2
// hfs-variant: HFS_NKEYS 1, HFS_LOCAL 1, HFS_GLOSSY 2
// hfs-variant: HFS_ENV 1, HFS_SLICE 1
// hfs-variant: HFS_ENV 1, HFS_SLICE 1, HFS_NKEYS 1, HFS_GLOSSY 1
// hfs-variant: HFS_ENV 1, HFS_SLICE 1, HFS_ENV_OCC 1
// hfs-variant: HFS_ENV 1, HFS_SLICE 1, HFS_ENV_OCC 1, HFS_NKEYS 1, HFS_FP32 1
// hfs-variant: HFS_ENV 1, HFS_SLICE 1, HFS_ENV_OCC 1, HFS_ENV_MAP 1, HFS_NKEYS 2, HFS_LOCAL 1
// hfs-variant: HFS_ENV 1, HFS_ENV_MAP 1
// hfs-variant: HFS_ENV 1, HFS_ENV_MAP 2, HFS_NKEYS 1
// hfs-variant: HFS_ENV 1, HFS_ENV_MAP 2, HFS_GLOSSY 1, HFS_FP32 1
// hfs-variant: HFS_ENV 1, HFS_ENV_MAP 2, HFS_GLOSSY 1, HFS_GLOSS_MAP 1
// hfs-variant: HFS_ENV 1, HFS_ENV_MAP 1, HFS_GLOSSY 2, HFS_GLOSS_MAP 1, HFS_FP32 1

#ifndef HFS_PI
#define HFS_PI 3.14159265358979
#endif

precision highp float;
precision highp int;
precision highp sampler2D;
precision highp sampler2DArray;

vec3 hfs_normal_at(highp sampler2DArray h, ivec2 p, ivec2 size, float zf);
void hfs_sh_cosine(vec3 n, out vec4 h[4]);
float hfs_sh_dot(vec4 a[4], vec4 b[4]);
void hfs_env_occ(vec4 t[4], vec4 l[12], out vec4 a, out vec2 b);
vec3 hfs_env_occ_sum(vec4 a, vec2 b);
float hfs_cap_irradiance_sc(float cos_beta, float s, float c);
vec2 hfs_split(float v);
vec4 hfs_pair_tex4_layer(highp sampler2DArray t, vec3 uvl);
void hfs_sh_basis(vec3 d, out vec4 y[4]);
vec2 hfs_grid_uv(ivec2 p, int sub, ivec2 size, ivec2 vsize);
vec2 hfs_height_at(highp sampler2DArray h, ivec2 p);

uniform highp sampler2DArray u_height;   /* the heights (hi, lo): normals (hfs_normal_at) */
uniform float u_zf;                      /* hscale zscale / dx, clamped to 1e30 */
#ifdef HFS_ENV_OCC
uniform highp sampler2D u_socc;          /* hfs_env_occ(T_occ, u_envo): (hi, lo_r), */
uniform highp sampler2D u_socclo;        /* (lo_g, lo_b), full resolution */
#else
uniform highp sampler2D u_t0;            /* T_occ, full resolution */
uniform highp sampler2D u_t1;
uniform highp sampler2D u_t2;
uniform highp sampler2D u_t3;
#endif
uniform highp sampler2DArray u_kf;       /* key factors f / E_max (hi, lo), a layer each */
uniform ivec2 u_size;                    /* W, H */
uniform ivec2 u_vsize;                   /* visibility grid size */
uniform int u_sub;
#ifdef HFS_ALBEDO_MAP
uniform highp sampler2D u_albedo;        /* albedo map (RGB in [0, 1]), full resolution */
#endif
#ifndef HFS_NKEYS
#define HFS_NKEYS 0
#endif
#ifndef HFS_ENV_MAP
#define HFS_ENV_MAP 0
#endif
#if HFS_ENV_MAP > 0
uniform highp sampler2D u_eopen;         /* D(N) / D_max, 33 x 33, LINEAR */
#endif
#if HFS_ENV_MAP == 2
uniform highp sampler2D u_mocc;          /* the map's occluded light / (F_max dphi) */
#endif
#ifdef HFS_GLOSS_MAP
uniform highp sampler2D u_egloss;        /* D_g(R) / D_g max, 129 x 65, LINEAR */
#endif
#if defined(HFS_ENV_OCC) && defined(HFS_GLOSSY)
#error "the glossy lobe reads all of T: no sky occlusion (gles_frame.c env_fold)"
#endif
#ifdef HFS_GLOSSY
#if HFS_GLOSSY == 2
#define HFS_GLOSS_EYE 1                  /* each texel's own view vector */
#endif
#endif
#if defined(HFS_LOCAL) || defined(HFS_GLOSS_EYE)
/* A texel's own height: u_height's layer u_hlayer (hfs_height_at), a
 * uniform and not the level count compiled in, so that a field of another
 * size or pyramid reuses this program. */
float hfs_h(vec2 t);
#endif

layout(std140) uniform HfsShade {
    vec4 u_env[12];                      /* L_env, 4 vec4 per channel */
    vec4 u_misc;                         /* (rho/pi, 1, has env, 0) */
    vec4 u_env_neg;                      /* rho * negative part of L_env per channel */
    vec4 u_kle[8];                       /* per key light: rho/pi Le E_max (rgb) */
    vec4 u_topen[4];                     /* k_l per coefficient: H * hemisphere(N)
                                            = k_l Y_lm(N) */
    vec4 u_lle[16];                      /* per local light: Le (rgb) */
    vec4 u_emap;                         /* HFS_ENV_MAP: (rho/pi D_max, cos rotate,
                                            sin rotate, rho/pi F_max dphi) */
    vec4 u_envo[12];                     /* L_c / m_c, m_c = sum_k |L_ck|: T_occ's sky */
    vec4 u_occs;                         /* rho/pi m_c s: the occluded light's scale */
#ifdef HFS_GLOSSY
    vec4 u_gview;                        /* (V towards the viewer, ks) */
    vec4 u_gpar;                         /* (S, ks (S+2)/(2 pi), D_g max, 0) */
    vec4 u_gzh[4];                       /* the lobe's g_l per coefficient */
    vec4 u_kspec[8];                     /* per key light: ks (S+2)/(2 pi) Le E_max */
    vec4 u_kdir[8];                      /* per key light: unit direction */
    vec4 u_geye;                         /* HFS_GLOSSY 2: the eye, texel units */
    vec4 u_ghgt;                         /* (base, hscale, zscale / dx, 0) */
#endif
};
/* Every radiance above (u_env, u_env_neg, u_kle, u_lle) comes multiplied by
 * the frame's power-of-two output scale (runtime/gles/pass_shade.c): no product here
 * can overflow fp16 or fp32 for any finite scene. */

layout(location = 0) out vec4 o_hi;       /* RGB hi (fp16-exact), 1 */
layout(location = 1) out vec4 o_lo;       /* RGB lo: hi + lo = value */

#ifdef HFS_GLOSSY
vec3 g_r;                                /* R = 2 (N.V) N - V (gloss.h hfs_gloss_reflect) */
float g_nr;                              /* N.R; 0: no glossy term at this texel */
vec3 g_spec;                             /* the glossy term, not the albedo map's */

/* max(0, R.d)^S: the lobe over its peak (S+2)/(2 pi), in u_gpar.y. */
float gloss_lobe(vec3 d)
{
    float c = dot(g_r, d);
    return c > 0.0 && g_nr > 0.0 ? pow(c, u_gpar.x) : 0.0; /* 0 where N.V <= 0 */
}
#endif

#if HFS_ENV_MAP > 0
/* rho/pi D at normal n (runtime/core/env_open.c hfs_env_open_uv, lookup): n
 * turned by -rotate, azimuthal equidistant, node i at texel centre i. */
vec3 env_open(vec3 n)
{
    vec2 xy = vec2(u_emap.y * n.x + u_emap.z * n.y, u_emap.y * n.y - u_emap.z * n.x);
    float rxy = length(xy);
    float r = acos(clamp(n.z, 0.0, 1.0)) / (0.5 * HFS_PI);
    vec2 uv = rxy > 0.0 ? (r / rxy) * xy : vec2(0.0);
    return u_emap.x * texture(u_eopen, ((uv + 1.0) * 16.0 + 0.5) / 33.0).rgb;
}
#endif

#ifdef HFS_GLOSS_MAP
/* D_g at R (runtime/core/env_gloss.c hfs_env_gloss_xy, lookup): R turned by
 * -rotate, equirect, node (i, j) at texel centre (i, j), column 128 = 0. */
vec3 env_gloss(vec3 r)
{
    vec2 xy = vec2(u_emap.y * r.x + u_emap.z * r.y, u_emap.y * r.y - u_emap.z * r.x);
    float phi = atan(xy.y, xy.x);
    phi = phi < 0.0 ? phi + 2.0 * HFS_PI : phi;
    float e = asin(clamp(r.z, -1.0, 1.0));
    vec2 f = vec2(phi / (2.0 * HFS_PI) * 128.0, (0.5 * HFS_PI - e) / HFS_PI * 64.0);
    return u_gpar.z * texture(u_egloss, (f + 0.5) / vec2(129.0, 65.0)).rgb;
}
#endif

#ifdef HFS_LOCAL
/* ---- local spherical lights (DESIGN.md "Local lights", "GLES path"):
 * rho/pi * Le * E_cap * ratio per light, E_cap at this texel's own point
 * (lifted by 1e-4 dx, as the CPU) and normal, the visibility ratio read
 * bilinearly from the grid written by local_visibility.frag (two lights per layer
 * as (hi, lo) pairs).  A texel inside the sphere gets rho Le (E = pi). */
#ifndef HFS_LOCAL_DIRS
#define HFS_LOCAL_DIRS 16
#endif
#ifndef HFS_LOCAL_MAX
#define HFS_LOCAL_MAX 16
#endif

uniform highp sampler2DArray u_localv;  /* ratio (hi, lo) x 2 per layer, LINEAR */
#ifndef HFS_NLOCAL
#define HFS_NLOCAL 1
#endif

layout(std140) uniform HfsLocal {
    vec4 u_lE[16];
    vec4 u_lg;                           /* (1, base, hscale, zscale/dx): texel units */
    vec4 u_lq;
    vec4 u_lights[2 * HFS_LOCAL_MAX];    /* (centre.xyz, radius), (-, open): Le is u_lle */
};                                       /* (a prefix: the swath that follows is not read here) */

vec3 local_lights(ivec2 p, vec3 n, vec2 uv)
{
    float dx = u_lg.x;
    float z = u_lg.w * (u_lg.y + u_lg.z * hfs_h(hfs_height_at(u_height, p)));
    vec3 pw = vec3(vec2(p) * dx, z + 1e-4 * dx);
    vec3 sum = vec3(0.0);
    vec4 rv = vec4(0.0);
    for (int q = 0; q < HFS_NLOCAL; ++q) { /* compiled in, as HFS_NKEYS */
        if (q % 2 == 0)
            rv = hfs_pair_tex4_layer(u_localv, vec3(uv, float(q / 2)));
        vec4 l0 = u_lights[2 * q], l1 = u_lights[2 * q + 1];
        vec3 v = l0.xyz - pw;
        float r = l0.w;
        float rho2 = dot(v.xy, v.xy);
        float c_tan = (rho2 - r * r) + v.z * v.z;  /* as local_visibility.frag */
        if (!(c_tan > 0.0)) {
            sum += u_misc.x * HFS_PI * u_lle[q].rgb;
#ifdef HFS_GLOSSY
            g_spec += g_nr > 0.0 ? u_gview.w * u_lle[q].rgb : vec3(0.0); /* as cpu_local.c */
#endif
            continue;
        }
        float d = length(v);
        float e_cap = hfs_cap_irradiance_sc(dot(n, v / d), r / d, sqrt(c_tan) / d);
        if (!(e_cap > 0.0))
            continue;
        /* l1.w: the terrain cannot shadow this light (ratio 1, none stored). */
        float ratio = l1.w > 0.5 ? 1.0 : clamp(q % 2 == 0 ? rv.x + rv.y : rv.z + rv.w, 0.0, 1.0);
        sum += u_misc.x * u_lle[q].rgb * (e_cap * ratio);
#ifdef HFS_GLOSSY
        g_spec += u_gpar.y * u_lle[q].rgb * (e_cap * ratio * gloss_lobe(v / d));
#endif
    }
    return sum;
}
#endif

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 n = hfs_normal_at(u_height, p, u_size, u_zf);
    vec3 lo = vec3(0.0);
#ifdef HFS_GLOSSY
    {
        vec3 view = u_gview.xyz;
#ifdef HFS_GLOSS_EYE
        /* gloss.h hfs_gloss_view_at, in texel units (the texel's point as
         * the heights give it; straight up at the eye itself). */
        float z = u_ghgt.z * (u_ghgt.x + u_ghgt.y * hfs_h(hfs_height_at(u_height, p)));
        vec3 d = u_geye.xyz - vec3(vec2(p), z);
        float len = length(d);
        view = len > 0.0 ? d / len : vec3(0.0, 0.0, 1.0);
#endif
        float nv = dot(n, view);
        g_nr = max(nv, 0.0);
        g_r = nv > 0.0 ? 2.0 * nv * n - view : n;
        g_spec = vec3(0.0);
    }
#endif
#ifdef HFS_ENV
    /* Compiled in only when the scene has an environment: llvmpipe pays
     * for this block even behind a uniform branch that skips it (the 512^2
     * shading pass of a scene without a sky: 15.4 ms behind the branch,
     * 3.5 ms without the block; BENCHMARKS.md "Frame planner"). */
    {
        vec4 H[4];
        hfs_sh_cosine(n, H);
        /* T's open part, then (glossy) all of T.  On the exact slice path
         * (HFS_SLICE) the open part is H(N) itself: the diffuse term takes
         * H . L, which the clamp needs anyway. */
        vec4 T[4];
#if !defined(HFS_SLICE) || defined(HFS_GLOSSY)
        hfs_sh_basis(n, T);
        for (int g = 0; g < 4; ++g)
            T[g] *= u_topen[g];
#endif
        vec3 occ;                        /* the occluded light, <= 0 */
#if HFS_ENV_MAP == 2
        occ = u_emap.w * texelFetch(u_mocc, p, 0).rgb;
#elif defined(HFS_ENV_OCC)
        occ = u_occs.rgb * hfs_env_occ_sum(texelFetch(u_socc, p, 0),
                                           texelFetch(u_socclo, p, 0).xy);
#endif
#if !defined(HFS_ENV_OCC) && (HFS_ENV_MAP != 2 || defined(HFS_GLOSSY))
        vec4 To[4];
        To[0] = texelFetch(u_t0, p, 0);
        To[1] = texelFetch(u_t1, p, 0);
        To[2] = texelFetch(u_t2, p, 0);
        To[3] = texelFetch(u_t3, p, 0);
#if HFS_ENV_MAP != 2
        vec4 oa;
        vec2 ob;
        hfs_env_occ(To, u_envo, oa, ob);
        occ = u_occs.rgb * hfs_env_occ_sum(oa, ob);
#endif
#endif
        vec3 dmap = vec3(0.0);
#if HFS_ENV_MAP > 0
        dmap = env_open(n);
#endif
        vec4 L[4];
        for (int c = 0; c < 3; ++c) {
            for (int g = 0; g < 4; ++g)
                L[g] = u_env[4 * c + g];
            /* Into [-neg, unshadowed + neg], as cpu_render.c env_clamp: the
             * interval holds the exact value, and sub-sampling (V of other
             * normals) or fp16 storage can step outside it. */
            float open = u_misc.x * hfs_sh_dot(H, L) + dmap[c];
#if HFS_ENV_MAP == 2 || defined(HFS_SLICE)
            float v = open + occ[c];
#else
            float v = u_misc.x * hfs_sh_dot(T, L) + dmap[c] + occ[c];
#endif
            lo[c] += clamp(v, -u_env_neg[c], open + u_env_neg[c]);
        }
#ifdef HFS_GLOSSY
        /* gloss.c hfs_gloss_env: the lobe's order-4 visible fraction v. */
        for (int g = 0; g < 4; ++g) /* all of T: the lobe's visible part */
            T[g] += To[g];
        if (g_nr > 0.0) {
            vec4 Q[4];
            hfs_sh_basis(g_r, Q);
            for (int g = 0; g < 4; ++g)
                Q[g] *= u_gzh[g];
            float num = hfs_sh_dot(T, Q), den = hfs_sh_dot(H, Q);
            float v = den > 1e-9 * sqrt(hfs_sh_dot(H, H) * hfs_sh_dot(Q, Q))
                          ? clamp(num / den, 0.0, 1.0) : 0.0;
            vec3 dg = vec3(0.0);
#ifdef HFS_GLOSS_MAP
            dg = env_gloss(g_r);
#endif
            for (int c = 0; c < 3; ++c) {
                for (int g = 0; g < 4; ++g)
                    L[g] = u_env[4 * c + g];
                g_spec[c] += u_gview.w * g_nr * v * (hfs_sh_dot(L, Q) + dg[c]);
            }
        }
#endif
    }
#endif
    /* The frame's key-light count is compiled in: llvmpipe runs a loop
     * with a uniform bound as a masked loop, several times slower. */
    for (int q = 0; q < HFS_NKEYS; ++q) {
        vec4 f = texelFetch(u_kf, ivec3(p, q), 0);
        lo += u_kle[q].rgb * (f.x + f.y);
#ifdef HFS_GLOSSY
        g_spec += u_kspec[q].rgb * ((f.x + f.y) * gloss_lobe(u_kdir[q].xyz));
#endif
    }
#ifdef HFS_LOCAL
    vec2 uv = hfs_grid_uv(p, u_sub, u_size, u_vsize);
    lo += local_lights(p, n, uv);
#endif
#ifdef HFS_ALBEDO_MAP
    lo *= texelFetch(u_albedo, p, 0).rgb; /* in [0, 1]: bounds and clamps still hold */
#endif
#ifdef HFS_GLOSSY
    lo += g_spec; /* after the map: the lobe is not the albedo's */
#endif
    vec3 v = lo * u_misc.y;
    /* Never NaN/Inf in the target (fp16 saturates at 65504). */
    v = clamp(v, vec3(-65504.0), vec3(65504.0));
    v = mix(vec3(0.0), v, equal(v, v));
    /* hi exactly representable, lo = the rest (hfs_split: one rounding a
     * channel; lo's own rounding in the target costs 2^-21 of v). */
    vec2 r = hfs_split(v.r), g = hfs_split(v.g), b = hfs_split(v.b);
    o_hi = vec4(r.x, g.x, b.x, 1.0);
    o_lo = vec4(r.y, g.y, b.y, 0.0);
}
