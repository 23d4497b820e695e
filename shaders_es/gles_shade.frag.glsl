/*
 * gles_shade.frag - exit radiance at full resolution (DESIGN.md "Shading",
 * "GLES path").  Per texel: the full-resolution normal N and the clamped
 * cosine H(N) as SH;
 *   environment  Lo += rho/pi * (H * V_env) . L_env per channel, V_env =
 *                hemisphere(N) + the grid's V_env - hemisphere(N_receiver)
 *                read bilinearly (exact at grid points);
 *   key light    Lo += rho/pi * Le * E_cap(N.d, alpha) * clamp(num/den, 0, 1),
 *                num = V_key . (H * L_key), den = V_open . (H * L_key); the
 *                horizons are floor_j(N) + excess_j, the excess read
 *                bilinearly from the visibility grid, and V_open uses the
 *                floors of this texel's normal (no fetch).
 *   local lights (HFS_LOCAL) Lo += rho/pi * Le * E_cap * clamp(num/den, 0, 1)
 *                per texel with its own swath, windows and light-cut
 *                horizons (local_lights below; DESIGN.md "Local lights").
 * The products use the generated SH product (sh_product.glsl.inc).
 * Output: linear RGB times a power-of-two scale (u_misc.y) that keeps the
 * frame inside fp16's range, as an fp16 hi + lo pair in two targets (the
 * readback adds them and divides the scale out exactly).
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
void hfs_sh_rotz(inout vec4 t[4], vec3 c, vec3 s);
void hfs_sh_mirror_y(inout vec4 t[4]);
float hfs_table_coord(float omega, float n);
float hfs_cap_irradiance(float cos_beta, float alpha);
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
    vec4 t[4];
    float n = float(HFS_TABLE_N);
    if (boundary) {
        vec2 uv = vec2(hfs_table_coord(a, n), 0.5);
        for (int g = 0; g < 4; ++g)
            t[g] = texture(u_ktabb, vec3(uv, 4.0 * set + float(g)));
    } else {
        vec2 uv = vec2(hfs_table_coord(a, n), hfs_table_coord(b, n));
        for (int g = 0; g < 4; ++g)
            t[g] = texture(u_ktab, vec3(uv, 4.0 * set + float(g)));
    }
    if (u_k[rot].w > 0.5)
        hfs_sh_mirror_y(t);
    hfs_sh_rotz(t, u_k[rot].xyz, u_k[rot + 1].xyz);
    for (int g = 0; g < 4; ++g)
        V[g] += t[g];
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
/* ---- local spherical lights (DESIGN.md "Local lights", mirroring
 * runtime/cpu_local.c shade() for the Legendre path).  Per texel (the
 * receiver point lifted by 1e-4 dx) and light: the partial swath around the
 * light's azimuth (or the full swath of nphi_local), exact per-sample cap
 * windows, horizons cut at the light's entry distance, the B-spline max over
 * scale (as gles_key.frag), closed-form hat weights A_k and the constant
 * elevation moments E, num/den as 4-dots with the NLP bands.  Computed at
 * full resolution: the CPU reference evaluates local lights at every texel
 * whatever the sub-sampling. */
#ifndef HFS_NLEV
#define HFS_NLEV 33
#endif
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
vec4 hfs_nlp_occ(float sigma);
void hfs_receiver_heights(highp sampler2DArray levels, ivec2 g, out vec2 hx[HFS_NLAYERS]);
float hfs_floor(vec3 n, vec2 cs);
bool hfs_scale_offset(ivec2 g, ivec2 size, float d, vec2 cs, out vec2 o);
float hfs_scale_slope(highp sampler2DArray levels, ivec2 g, ivec2 size, vec2 o, vec4 sc, vec2 h);
void hfs_bspline_push(inout float best, inout vec4 w, float a, int i);
float hfs_bspline_close(float best, vec4 w);

uniform highp sampler2DArray u_levels;
uniform int u_nlocal;

layout(std140) uniform HfsScales {
    vec4 u_scale[HFS_NLEV];              /* (d_i, inv_run_i, read layer, 0) */
};
layout(std140) uniform HfsLocal {
    vec4 u_lE[16];                       /* elevation moments, row r = E[r][0..3] */
    vec4 u_lg;                           /* (dx, base, hscale, zscale) */
    vec4 u_lq;                           /* (nphi_local, forced full swath, 0, 0) */
    vec4 u_lights[2 * HFS_LOCAL_MAX];    /* (centre.xyz, radius), (Le.rgb, 0) */
    vec4 u_ldir[HFS_LOCAL_DIRS];         /* full swath: (cos, sin) of 2 pi k/n */
};

/* integral_0^w (1 - u/w) cos(m u) du and ... sin(m u) du for m = 0..3
 * (cpu_local.c tri_cos / tri_sin; the sin series up to x = 0.5 in float). */
vec4 local_tri_cos(float w)
{
    if (!(w > 0.0))
        return vec4(0.0);
    vec4 m = vec4(1.0, 1.0, 2.0, 3.0);
    vec4 x = m * w, hs = sin(0.5 * x);
    vec4 r = 2.0 * hs * hs / (m * x);
    r.x = 0.5 * w;
    return r;
}

vec4 local_tri_sin(float w)
{
    if (!(w > 0.0))
        return vec4(0.0);
    vec4 m = vec4(1.0, 1.0, 2.0, 3.0);
    vec4 x = m * w, x2 = x * x;
    vec4 ser = x2 * (1.0 / 6.0 - x2 * (1.0 / 120.0 - x2 * (1.0 / 5040.0 - x2 / 362880.0))) / m;
    vec4 r = mix((x - sin(x)) / (m * x), ser, lessThan(x, vec4(0.5)));
    r.x = 0.0;
    return r;
}

/* A[r] of a hat (moments gc, gs) centred at azimuth (c, s), SH order of r:
 * 0: gc0; m > 0: cos(m phi) gc_m - sin(m phi) gs_m; m < 0: sin gc + cos gs. */
void local_weights(vec2 cs, vec4 gc, vec4 gs, out vec4 A[4])
{
    vec4 cm, sm;
    cm.x = 1.0;
    sm.x = 0.0;
    cm.y = cs.x;
    sm.y = cs.y;
    cm.z = cm.y * cs.x - sm.y * cs.y;
    sm.z = sm.y * cs.x + cm.y * cs.y;
    cm.w = cm.z * cs.x - sm.z * cs.y;
    sm.w = sm.z * cs.x + cm.z * cs.y;
    vec4 ap = cm * gc - sm * gs, an = sm * gc + cm * gs;
    A[0] = vec4(gc.x, an.y, gc.x, ap.y);
    A[1] = vec4(an.z, an.y, gc.x, ap.y);
    A[2] = vec4(ap.z, an.w, an.z, an.y);
    A[3] = vec4(gc.x, ap.y, ap.z, ap.w);
}

/* SH of a uniform cap of half-angle alpha about unit d (hfs_zh_cap rotated:
 * band factors 4 pi sin^2(a/2), pi s^2, pi c s^2, pi/4 s^2 (5c^2 - 1)). */
void local_cap_sh(float alpha, vec3 d, out vec4 L[4])
{
    float c = cos(alpha), s = sin(alpha), s2 = s * s, h = sin(0.5 * alpha);
    float f0 = 12.566370614359172 * h * h, f1 = 3.141592653589793 * s2;
    float f2 = f1 * c, f3 = 0.7853981633974483 * s2 * (5.0 * c * c - 1.0);
    float x = d.x, y = d.y, z = d.z;
    float a1 = f1 * 0.4886025119029199;
    L[0] = vec4(f0 * 0.28209479177387814, a1 * y, a1 * z, a1 * x);
    L[1] = vec4(f2 * 1.0925484305920792 * x * y, f2 * 1.0925484305920792 * y * z,
                f2 * 0.31539156525252005 * (3.0 * z * z - 1.0), f2 * 1.0925484305920792 * x * z);
    L[2] = vec4(f2 * 0.5462742152960396 * (x * x - y * y),
                f3 * 0.5900435899266435 * y * (3.0 * x * x - y * y),
                f3 * 2.890611442640554 * x * y * z,
                f3 * 0.4570457994644658 * y * (5.0 * z * z - 1.0));
    L[3] = vec4(f3 * 0.3731763325901154 * z * (5.0 * z * z - 3.0),
                f3 * 0.4570457994644658 * x * (5.0 * z * z - 1.0),
                f3 * 1.445305721320277 * z * (x * x - y * y),
                f3 * 0.5900435899266435 * x * (x * x - 3.0 * y * y));
}

/* Horizontal distance at which the ray (azimuth cs, elevation (ce, se))
 * enters the sphere; its closest approach where it misses. */
float local_entry(vec3 v, float c_tan, vec2 cs, float ce, float se)
{
    float b = ce * dot(cs, v.xy) + se * v.z;
    float disc = b * b - c_tan;
    float t = (b > 0.0 && disc >= 0.0) ? c_tan / (b + sqrt(disc)) : max(b, 0.0);
    return max(t * ce, 0.0);
}

vec3 local_lights(ivec2 p, vec3 n, vec4 H[4])
{
    vec2 hx[HFS_NLAYERS];
    hfs_receiver_heights(u_levels, p, hx);
    float dx = u_lg.x;
    float z = u_lg.w * (u_lg.y + u_lg.z * hfs_h(hx[HFS_NLAYERS - 1]));
    vec3 pw = vec3(vec2(p) * dx, z + 1e-4 * dx);
    int nphi = int(u_lq.x);
    vec3 sum = vec3(0.0);
    for (int q = 0; q < u_nlocal; ++q) {
        vec4 l0 = u_lights[2 * q], l1 = u_lights[2 * q + 1];
        vec3 v = l0.xyz - pw;
        float r = l0.w;
        /* (d - r)(d + r) as (rho_h^2 - r^2) + v_z^2: a receiver on the
         * sphere's horizontal great circle (integer centre and radius) is
         * decided by the 1e-4 dx lift alone, which d in float cannot see. */
        float rho2 = dot(v.xy, v.xy);
        float c_tan = (rho2 - r * r) + v.z * v.z;
        if (!(c_tan > 0.0)) {            /* inside: E = pi, nothing in between */
            sum += u_misc.x * HFS_PI * l1.rgb;
            continue;
        }
        float d = length(v);
        vec3 dir = v / d;
        float rho_h = sqrt(rho2);
        float sin_a = r / d, cos_a = sqrt(c_tan) / d;
        float alpha = atan(sin_a, cos_a);
        float e_cap = hfs_cap_irradiance(dot(n, dir), alpha);
        if (!(e_cap > 0.0))
            continue;
        vec4 L[4], M[4];
        local_cap_sh(alpha, dir, L);
        hfs_sh_product(H, L, M);

        bool surround = r >= rho_h;
        bool full = u_lq.y > 0.5 || surround;
        bool exact = !full || surround;
        int ns;
        float dphi, phi0, bw;
        if (full) {
            ns = nphi;
            dphi = 2.0 * HFS_PI / float(nphi);
            phi0 = 0.0;
            bw = dphi;
        } else {
            float h = asin(r / rho_h);
            ns = min(max(int(ceil(float(nphi) * h / HFS_PI)), 3), nphi);
            dphi = 2.0 * h / float(ns);
            phi0 = atan(v.y, v.x) - h + 0.5 * dphi;
            bw = 0.5 * dphi;
        }
        float elev_l = atan(v.z, rho_h);
        float glo = max(elev_l - alpha, -HFS_HALF_PI), ghi = min(elev_l + alpha, HFS_HALF_PI);
        float reach = exact ? min(d, rho_h + r) : d;
        float w_in = ns == 1 ? bw : dphi;
        vec4 tc_b = local_tri_cos(bw), ts_b = local_tri_sin(bw);
        vec4 tc_d = local_tri_cos(dphi), ts_d = local_tri_sin(dphi);
        vec4 tc_i = local_tri_cos(w_in), ts_i = local_tri_sin(w_in);
        float num = 0.0, den = 0.0, den_scale = 0.0;
        for (int k = 0; k < ns; ++k) {
            vec2 cs;
            if (full) {
                cs = u_ldir[k].xy;
            } else {
                float phi = phi0 + float(k) * dphi;
                cs = vec2(cos(phi), sin(phi));
                cs = mix(cs, vec2(0.0), lessThan(abs(cs), vec2(1e-12)));
            }
            float lo = glo, hi = ghi;
            if (exact) {
                float a = dot(dir.xy, cs), w = -dir.x * cs.y + dir.y * cs.x;
                float qq = sin_a * sin_a - w * w;
                if (!(qq > 0.0) || !(cos_a >= 0.0))
                    continue;
                float psi = atan(dir.z, a), half_w = atan(sqrt(qq), cos_a);
                lo = max(psi - half_w, -HFS_HALF_PI);
                hi = min(psi + half_w, HFS_HALF_PI);
                if (!(lo < hi))
                    continue;
            }
            float fl = hfs_floor(n, cs);
            float t_near = -1.0, cut = reach;
            if (exact) {
                float u = dot(cs, v.xy), wp = -cs.y * v.x + cs.x * v.y;
                float g = sqrt(max(0.0, r * r - wp * wp));
                t_near = u - g;
                cut = min(reach, u + g);
            }
            float clo = cos(lo), slo = sin(lo), chi = cos(hi), shi = sin(hi);
            /* Per-scale angles fine to coarse with the B-spline max on the
             * fly (hfs_bspline_push); a scale beyond the cut or off the grid,
             * and every coarser one, is the floor. */
            float best = fl;
            vec4 w = vec4(fl);
            int tail = 3;
            int i = HFS_NLEV - 1;
            for (; i >= 0; --i) {
                float a = fl;
                if (tail == 3) {
                    vec4 sc = u_scale[i];
                    float dist = sc.x * dx;
                    vec2 o;
                    if (!hfs_scale_offset(p, u_size, sc.x, cs, o) || dist > cut) {
                        --tail;
                    } else {
                        float D = hfs_scale_slope(u_levels, p, u_size, o, sc, hx[int(sc.z)]);
                        float om = atan(D);
                        if (dist < t_near) {
                            a = om;
                        } else {
                            float ce = inversesqrt(1.0 + D * D), se = D * ce;
                            if (om < lo) {
                                ce = clo;
                                se = slo;
                            } else if (om > hi) {
                                ce = chi;
                                se = shi;
                            }
                            a = dist <= local_entry(v, c_tan, cs, ce, se) ? om : fl;
                        }
                    }
                } else if (--tail < 0) {
                    break;
                }
                hfs_bspline_push(best, w, a, i);
            }
            if (i < 0)
                best = hfs_bspline_close(best, w);
            float omega = clamp(best, -HFS_HALF_PI, HFS_HALF_PI);

            /* g = sum_r m_r A_k[r] E[r]; hat half-widths (left, right). */
            vec4 gcm, gsm;
            if (k == 0) {
                gcm = tc_b + tc_i;
                gsm = ts_i - ts_b;
            } else if (k == ns - 1) {
                gcm = tc_i + tc_b;
                gsm = ts_b - ts_i;
            } else {
                gcm = 2.0 * tc_d;
                gsm = vec4(0.0);
            }
            if (full) {
                gcm = 2.0 * tc_d;
                gsm = vec4(0.0);
            }
            vec4 A[4];
            local_weights(cs, gcm, gsm, A);
            vec4 g4 = vec4(0.0);
            for (int gi = 0; gi < 4; ++gi) {
                vec4 mw = M[gi] * A[gi];
                g4 += mw.x * u_lE[4 * gi] + mw.y * u_lE[4 * gi + 1] + mw.z * u_lE[4 * gi + 2] +
                      mw.w * u_lE[4 * gi + 3];
            }
            vec4 win = vec4(lo, hi, 0.0, 0.0), top = hfs_nlp_occ(hi);
            vec4 vb = hfs_visible(omega, win, top), ob = hfs_visible(fl, win, top);
            num += dot(g4, vb);
            den += dot(g4, ob);
            den_scale += dot(abs(g4 * ob), vec4(1.0));
        }
        float ratio;
        if (num == den)
            ratio = 1.0;
        else if (den > 1e-12 * den_scale)
            ratio = clamp(num / den, 0.0, 1.0);
        else
            ratio = 0.0;
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
            lo[c] += u_misc.x * hfs_sh_dot(T, L);
        }
    }
    for (int q = 0; q < u_nkeys; ++q)
        lo += key_light(u_koff[q], n, H, uv);
#ifdef HFS_LOCAL
    lo += local_lights(p, n, H);
#endif
    vec3 v = lo * u_misc.y;
    /* Never NaN/Inf in the target (fp16 saturates at 65504). */
    v = clamp(v, vec3(-65504.0), vec3(65504.0));
    v = mix(vec3(0.0), v, equal(v, v));
    vec4 hi = hfs_f16v(vec4(v, 1.0));
    o_hi = hi;
    o_lo = hfs_f16v(vec4(v, 1.0) - hi);
}
