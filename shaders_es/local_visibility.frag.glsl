/*
 * local_visibility.frag - local spherical lights' visibility on the visibility
 * grid (DESIGN.md "Local lights", "GLES path"; mirrors runtime/cpu/cpu_local.c
 * shade() for the Legendre path).  One fragment per receiver of the grid
 * (grid point min(a*sub, W-1)), lights [u_light0, u_light0 + u_nl) of the
 * frame, two per RGBA target as fp16 (hi, lo) pairs, up to HFS_NOUT targets
 * (8 lights per draw at ES 3.0's four draw buffers).  Per light it writes the
 * visibility RATIO num/den in [0, 1]: the cosine-weighted visible part of
 * the light's cap over the part above the receiver's tangent plane.  The
 * shading pass multiplies it, read bilinearly, by rho/pi Le E_cap computed
 * at each full-resolution texel's own position and normal: like the
 * environment's, only the terrain's occlusion is interpolated, and a
 * texel on a grid point gets exactly the ratio of the full-resolution path.
 *
 * Per receiver (lifted by 1e-4 dx) and light: the partial swath around the
 * light's azimuth (or the full swath of nphi_local when the light surrounds
 * the receiver or u_lq.y forces it), exact per-sample cap windows, per-scale
 * horizons cut at the light's entry distance, the B-spline max over scale
 * (as key_horizons.frag), closed-form hat weights A_k and the constant elevation
 * moments E, num/den as 4-dots with the NLP bands.  A receiver inside the
 * sphere writes 1 (the shading pass gives it rho Le); one whose tangent
 * plane hides the whole cap writes the ratio for the plane facing the light
 * (see local_ratio), so that interpolation toward it stays meaningful.
 *
 * HFS_TABLES: the SN08 wedge-table path of the CPU reference (cpu_local.c
 * with HFS_VIS_WEDGE_TABLE): always the full swath of nphi_local, per sample
 * the omega and the floor as above (the exact window, or the key-light
 * window, only orients the entry test), V_k and V_open summed from the
 * interior table of dphi = 2 pi / nphi_local (u_tab) placed per wedge by a
 * z-rotation (u_lrot), num = V_k . M, den = V_open . M.
 *
 * HFS_COUNT: writes the fetch count to o_r0 instead (see env_horizons.frag).
 */
// hfs-base: HFS_CELLS 1
// hfs-variant: HFS_NOUT 4
// hfs-variant: HFS_TABLES 1
// hfs-variant: HFS_FP32 1, HFS_COUNT 1
// hfs-variant: HFS_LOCAL_TEX 1
// hfs-variant: HFS_LOCAL_TEX 1, HFS_TABLES 1

#ifndef HFS_SCALES_MAX
#define HFS_SCALES_MAX 256
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
#ifndef HFS_NOUT
#define HFS_NOUT 1
#endif
#ifndef HFS_HALF_PI
#define HFS_HALF_PI 1.5707963267948966
#endif
#ifndef HFS_PI
#define HFS_PI 3.14159265358979
#endif
#ifndef HFS_TABLE_N
#define HFS_TABLE_N 257
#endif

precision highp float;
precision highp int;
precision highp sampler2D;
precision highp sampler2DArray;

float hfs_h(vec2 t);
vec2 hfs_split(float v);
ivec2 hfs_receiver(ivec2 size, int sub);
vec4 hfs_nlp_occ(float sigma);
vec4 hfs_visible(float omega, vec4 win, vec4 occ_top);
void hfs_sh_cosine(vec3 n, out vec4 h[4]);
float hfs_cap_irradiance(float cos_beta, float alpha);
float hfs_sin_acc(float x);
vec4 hfs_sin_acc4(vec4 x);
void hfs_sh_product(in vec4 a[4], in vec4 b[4], out vec4 c[4]);
void hfs_receiver_heights(highp sampler2DArray levels, ivec2 g, out vec2 hx[HFS_NLAYERS]);
float hfs_floor(vec3 n, vec2 cs);
bool hfs_scale_offset(ivec2 g, ivec2 size, float d, vec2 cs, out vec2 o);
float hfs_scale_slope(highp sampler2DArray levels, ivec2 g, ivec2 size, vec2 o, vec4 sc, vec2 h);
void hfs_bspline_push(inout float best, inout vec4 w, float a, int i, int n);
float hfs_bspline_close(float best, vec4 w, int n);
float hfs_sh_dot(vec4 a[4], vec4 b[4]);
float hfs_table_coord(float omega, float n);
void hfs_sh_basis(vec3 d, out vec4 y[4]);
void hfs_table_add(highp sampler2DArray tab, vec2 uv, float layer0, bool mirror, vec3 c,
                   vec3 s, inout vec4 V[4]);
vec3 hfs_normal_sides(highp sampler2DArray h, ivec2 p, ivec2 size, float zf, vec2 zp,
                      out vec4 d, out bvec4 on);
float hfs_own_cell_slope(highp sampler2DArray h, ivec2 p, ivec2 size, vec2 cs, vec2 zp, vec4 ns,
                         float rise, inout int fetches);
#define HFS_RAY_LEVELS 16
float hfs_gap_search_cells(highp sampler2DArray heights, highp sampler2D bounds,
                           ivec2 at[HFS_RAY_LEVELS], ivec2 size, ivec2 g, vec2 cs, float t_first,
                           float t_last, float zf, float tie, vec2 h0, float best, float stop,
                           inout float dist, inout int fetches);

uniform highp sampler2DArray u_levels;
uniform highp sampler2DArray u_height;   /* the heights (hi, lo): normals, the own rays */
uniform float u_zf;                      /* hscale zscale / dx, clamped to 1e30 */
uniform ivec2 u_size;
uniform int u_sub;
uniform int u_light0;                    /* first light of this draw */
uniform int u_nl;                        /* lights in this draw, <= 2 * HFS_NOUT */
uniform int u_lmask;                     /* bit q: compute light u_light0 + q (the
                                            others are kept: masked from writes) */
/* each sample's own ray (ray_horizon): the max pyramid's atlas
 * (runtime/core/ray_bound.h) and the heights' rise, hscale zscale / dx */
uniform highp sampler2D u_bounds;
uniform ivec2 u_rb_at[HFS_RAY_LEVELS];
uniform float u_rise;
/* runtime/core/local_geometry.h HFS_LOCAL_RAY_FROM */
#define HFS_LOCAL_RAY_FROM 1.5

layout(std140) uniform HfsScales {
    ivec4 u_nscales;                     /* (N: the scales, 0, 0, 0) */
    vec4 u_scale[HFS_SCALES_MAX];        /* (d_i, inv_run_i, read layer, 0) */
};
#define HFS_NLEV (u_nscales.x)           /* the scale count: a uniform */
layout(std140) uniform HfsLocal {
    vec4 u_lE[16];                       /* elevation moments, row r = E[r][0..3] */
    vec4 u_lg;                           /* (1, base, hscale, zscale/dx): texel units */
    vec4 u_lq;                           /* (nphi_local, forced full swath, 0, 0) */
    vec4 u_lights[2 * HFS_LOCAL_MAX];    /* (centre.xyz, radius), (-, -, -, open) */
#ifndef HFS_LOCAL_TEX
    vec4 u_ldir[HFS_LOCAL_DIRS];         /* full swath: (cos, sin) of 2 pi k/n */
    vec4 u_lrot[2 * HFS_LOCAL_DIRS];     /* per wedge (cos ma), (sin ma), m = 1..3 */
#endif
};
#ifdef HFS_LOCAL_TEX
/* The swath from a texture (too large for a uniform block): the whole
 * block's data, the swath after the head's 18 + 2 HFS_LOCAL_MAX vec4. */
vec4 hfs_block_vec4(highp usampler2D t, int i);
uniform highp usampler2D u_local_tex;
#define LOCAL_DIR(k) hfs_block_vec4(u_local_tex, 18 + 2 * HFS_LOCAL_MAX + (k))
#define LOCAL_ROT(i) hfs_block_vec4(u_local_tex, 18 + 2 * HFS_LOCAL_MAX + HFS_LOCAL_DIRS + (i))
#else
#define LOCAL_DIR(k) u_ldir[k]
#define LOCAL_ROT(i) u_lrot[i]
#endif
#ifdef HFS_TABLES
uniform highp sampler2DArray u_tab;      /* interior wedge table, 4 layers */

/* V += the interior table(a, b) placed at wedge w of the full swath. */
void local_wedge(inout vec4 V[4], float a, float b, int w)
{
    float n = float(HFS_TABLE_N);
    hfs_table_add(u_tab, vec2(hfs_table_coord(a, n), hfs_table_coord(b, n)), 0.0, false,
                  LOCAL_ROT(2 * w).xyz, LOCAL_ROT(2 * w + 1).xyz, V);
}
#endif

layout(location = 0) out vec4 o_r0;
#if HFS_NOUT > 1
layout(location = 1) out vec4 o_r1;
#endif
#if HFS_NOUT > 2
layout(location = 2) out vec4 o_r2;
#endif
#if HFS_NOUT > 3
layout(location = 3) out vec4 o_r3;
#endif

vec2 g_hx[HFS_NLAYERS];                  /* the receiver's heights per layer */
int g_fetches;
vec2 g_zp;                               /* the receiver's height (hi, lo) */
vec4 g_ns;                               /* its one-sided slopes, -1e30 off the field */

/* tan(a) for a in [-pi/2, pi/2], whose ends in float lie past +-pi/2,
 * where tan changes sign: the angle held inside them. */
float local_tan(float a)
{
    return tan(clamp(a, -1.5707962, 1.5707962));
}

/* Sample cs's own ray from receiver p (issue 36 item 1; cpu_local.c
 * ray_horizon): its own cell and every crossing and cell of the bilinear
 * surface out to t_last texels, where the sphere's section by the sample's
 * half-plane can begin; the largest of `start` and their slopes, as an
 * angle, the search ending once it reaches `stop` (the window's top: the
 * sample is then dark whatever lies beyond). */
float ray_horizon(ivec2 p, vec2 cs, float t_last, float start, float stop)
{
    float dist = 0.0;
    float t = hfs_gap_search_cells(u_height, u_bounds, u_rb_at, u_size, p, cs, 0.0, t_last,
                                   u_rise, 0.0, g_zp, start, stop, dist, g_fetches);
    return atan(max(t, hfs_own_cell_slope(u_height, p, u_size, cs, g_zp, g_ns, u_rise,
                                          g_fetches)));
}

/* integral_0^w (1 - u/w) cos(m u) du and ... sin(m u) du for m = 0..3
 * (cpu_local.c tri_cos / tri_sin; the sin series up to x = 0.5 in float). */
vec4 local_tri_cos(float w)
{
    if (!(w > 0.0))
        return vec4(0.0);
    vec4 m = vec4(1.0, 1.0, 2.0, 3.0);
    vec4 x = m * w, hs = hfs_sin_acc4(0.5 * x);
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
    float c = cos(alpha), s = hfs_sin_acc(alpha), s2 = s * s, h = hfs_sin_acc(0.5 * alpha);
    float f0 = 12.566370614359172 * h * h, f1 = 3.141592653589793 * s2;
    float f2 = f1 * c, f3 = 0.7853981633974483 * s2 * (5.0 * c * c - 1.0);
    vec4 y[4];
    hfs_sh_basis(d, y);
    L[0] = y[0] * vec4(f0, f1, f1, f1);
    L[1] = y[1] * f2;
    L[2] = y[2] * vec4(f2, f3, f3, f3);
    L[3] = y[3] * f3;
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

/* Visibility ratio of light q at receiver p (normal n, its clamped cosine
 * Hn as SH, lifted point pw). */
float local_ratio(ivec2 p, vec3 n, vec4 Hn[4], vec3 pw, int q)
{
    float dx = u_lg.x;
    int nphi = int(u_lq.x);
    vec4 l0 = u_lights[2 * q];
    vec3 v = l0.xyz - pw;
    float r = l0.w;
    /* (d - r)(d + r) as (rho_h^2 - r^2) + v_z^2: a receiver on the
     * sphere's horizontal great circle (integer centre and radius) is
     * decided by the 1e-4 dx lift alone, which d in float cannot see. */
    float rho2 = dot(v.xy, v.xy);
    float c_tan = (rho2 - r * r) + v.z * v.z;
    if (!(c_tan > 0.0))              /* inside: E = pi, nothing in between */
        return 1.0;
    float d = length(v);
    vec3 dir = v / d;
    float rho_h = sqrt(rho2);
    float sin_a = r / d, cos_a = sqrt(c_tan) / d;
    float alpha = atan(sin_a, cos_a);
    /* The cap wholly below this receiver's tangent plane: no ratio of
     * its own, but texels between it and lit grid points need one, so
     * give the visible fraction of the cap over the terrain alone: the
     * receiver's plane replaced by the one facing the light (tilted up to
     * at least 0.05 in z, so that its floors stay below a light that is
     * lower than the receiver). */
    vec4 H[4] = Hn;
    if (!(hfs_cap_irradiance(dot(n, dir), alpha) > 0.0)) {
        vec3 nf = vec3(dir.xy, max(dir.z, 0.05));
        n = nf / length(nf);
        hfs_sh_cosine(n, H);
    }
    vec4 L[4], M[4];
    local_cap_sh(alpha, dir, L);
    hfs_sh_product(H, L, M);

    bool surround = r >= rho_h;
#ifdef HFS_TABLES
    bool full = true;
    vec4 Vk[4], Vo[4];
    for (int g = 0; g < 4; ++g) {
        Vk[g] = vec4(0.0);
        Vo[g] = vec4(0.0);
    }
    float om_first = 0.0, fl_first = 0.0, om_prev = 0.0, fl_prev = 0.0;
#else
    bool full = u_lq.y > 0.5 || surround;
#endif
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
            cs = LOCAL_DIR(k).xy;
        } else {
            float phi = phi0 + float(k) * dphi;
            cs = vec2(cos(phi), sin(phi));
            cs = mix(cs, vec2(0.0), lessThan(abs(cs), vec2(1e-12)));
        }
        float lo = glo, hi = ghi;
        if (exact) {
            float a = dot(dir.xy, cs), w = -dir.x * cs.y + dir.y * cs.x;
            float qq = sin_a * sin_a - w * w;
            bool window = qq > 0.0 && cos_a >= 0.0;
            if (window) {
                float psi = atan(dir.z, a), half_w = atan(sqrt(qq), cos_a);
                lo = max(psi - half_w, -HFS_HALF_PI);
                hi = min(psi + half_w, HFS_HALF_PI);
                window = lo < hi;
            }
            if (!window) {
#ifdef HFS_TABLES
                lo = glo;                /* tables have no window: it only */
                hi = ghi;                /* orients the entry test          */
#else
                continue;                /* an empty band adds 0 to num and den */
#endif
            }
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
                    float D = hfs_scale_slope(u_levels, p, u_size, o, sc, g_hx[int(sc.z)]);
                    ++g_fetches;
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
            hfs_bspline_push(best, w, a, i, HFS_NLEV);
        }
        if (i < 0)
            best = hfs_bspline_close(best, w, HFS_NLEV);
        float omega = clamp(best, -HFS_HALF_PI, HFS_HALF_PI);
        /* the ray itself, where the light's section lies past the own cell,
         * searched from what the scales found (tables count every
         * elevation; the Legendre bands none below lo, none at all from hi) */
#ifdef HFS_TABLES
        if (exact && t_near >= HFS_LOCAL_RAY_FROM)
            omega = max(omega, ray_horizon(p, cs, t_near, local_tan(omega), 1e30));
#else
        if (exact && t_near >= HFS_LOCAL_RAY_FROM && omega < hi)
            omega = max(omega, ray_horizon(p, cs, t_near, local_tan(max(omega, lo)),
                                           hi < HFS_HALF_PI ? local_tan(hi) : 1e30));
#endif
#ifdef HFS_TABLES
        if (k == 0) {
            om_first = omega;
            fl_first = fl;
        } else {
            local_wedge(Vk, om_prev, omega, k - 1);
            local_wedge(Vo, fl_prev, fl, k - 1);
            g_fetches += 8;
        }
        om_prev = omega;
        fl_prev = fl;
#else
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
#endif
    }
#ifdef HFS_TABLES
    local_wedge(Vk, om_prev, om_first, ns - 1);
    local_wedge(Vo, fl_prev, fl_first, ns - 1);
    g_fetches += 8;
    num = hfs_sh_dot(Vk, M);
    den = hfs_sh_dot(Vo, M);
    den_scale = sqrt(hfs_sh_dot(M, M) * hfs_sh_dot(Vo, Vo));
#endif
    if (num == den)
        return 1.0;                      /* nothing above the floors */
    return den > 1e-12 * den_scale ? clamp(num / den, 0.0, 1.0) : 0.0;
}

void main()
{
    ivec2 p = hfs_receiver(u_size, u_sub);
    hfs_receiver_heights(u_levels, p, g_hx);
    g_zp = g_hx[HFS_NLAYERS - 1]; /* the heights' layer, u_height's (u_hlayer) */
    vec4 side;
    bvec4 side_on;
    vec3 n = hfs_normal_sides(u_height, p, u_size, u_zf, g_zp, side, side_on);
    g_ns = mix(vec4(-1e30), u_rise * side, side_on);
    g_fetches = 4 + HFS_NLAYERS; /* the normal's 4 heights, the receiver's layers */
    float z = u_lg.w * (u_lg.y + u_lg.z * hfs_h(g_hx[HFS_NLAYERS - 1]));
    vec3 pw = vec3(vec2(p) * u_lg.x, z + 1e-4 * u_lg.x);

    vec4 H[4];
    hfs_sh_cosine(n, H); /* shared by the lights that see above the plane */
    float ratio[2 * HFS_NOUT];
    for (int q = 0; q < 2 * HFS_NOUT; ++q)
        ratio[q] = q < u_nl && ((u_lmask >> q) & 1) != 0 ? local_ratio(p, n, H, pw, u_light0 + q)
                                                          : 0.0;
#ifdef HFS_COUNT
    o_r0 = vec4(float(g_fetches % 1024), float(g_fetches / 1024), 0.0, 0.0);
#if HFS_NOUT > 1
    o_r1 = vec4(0.0);
#endif
#if HFS_NOUT > 2
    o_r2 = vec4(0.0);
#endif
#if HFS_NOUT > 3
    o_r3 = vec4(0.0);
#endif
#else
    o_r0 = vec4(hfs_split(ratio[0]), hfs_split(ratio[1]));
#if HFS_NOUT > 1
    o_r1 = vec4(hfs_split(ratio[2]), hfs_split(ratio[3]));
#endif
#if HFS_NOUT > 2
    o_r2 = vec4(hfs_split(ratio[4]), hfs_split(ratio[5]));
#endif
#if HFS_NOUT > 3
    o_r3 = vec4(hfs_split(ratio[6]), hfs_split(ratio[7]));
#endif
#endif
}
