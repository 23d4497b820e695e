/*
 * env_slices.frag - exact slice lighting at full resolution (runtime/
 * slice_light.h, DESIGN.md "Exact slice lighting"): per texel and azimuth
 * slice, the horizon elevation x = max(the grid's far horizon read
 * bilinearly, the near scales searched here at the texel itself, the
 * texel's tangent plane), then the occluded part of the slice's transfer,
 * Int_floor^x Y_k (a cos e + b sin e) cos e de, in closed form with the
 * texel's own normal (a = N.d, b = N_z).  Writes T_occ, the transfer's
 * occluded part, as 16 coefficients in 4 RGBA targets (the shading pass
 * adds the open hemisphere H(N) exactly); like the seeds' transfer it does
 * not depend on the environment's radiance or rotation.
 *
 * HFS_PAIRS (a sub-sampled grid): the grid holds each direction's
 * occluder (height over its receiver, distance), blended bilinearly and
 * moved to this texel's height (hfs_far_slope), instead of tan(x / 2).
 *
 * Why split the horizon: on a sub-sampled grid a texel's nearest
 * occluders (a texel away) are not its grid neighbours' - interpolating
 * those brightens pits and darkens peaks on rough relief - while far ones
 * are shared.  With u_near = 1 (the grid pass leaves the finest scale out)
 * the texel's own cell is searched here exactly, from its 3 x 3
 * neighbourhood fetched once (hfs_field_first_cell_slope: the bilinear
 * surface's slope along the ray there is linear in the distance, so its
 * max is at the cell's near end, the one-sided slopes weighted by |cos|,
 * |sin|, or at its far edge, a fixed weighting of the 9 heights per
 * direction, u_nearw, uniform_blocks.c): 9 fetches for every direction.
 * u_near = 0 only on a one-level layout.
 *
 * HFS_FARK K (split horizons, runtime/core/split_horizon.h): the grid holds
 * the near part only; each slice's horizon is K sub-horizons, max(near,
 * the far occluder of sub-direction j K + h from u_far, the far grid's
 * pairs blended and moved to this texel's height), and the slice's part is
 * their mean, integrated with the slice's own N.d (slice_add_mean).
 *
 * HFS_ENV_MAP 1 (env-shade = map, pass_env_map_slices.c): the same
 * horizons, but each slice's occluded part integrated against the
 * environment map itself, dphi (S_j(x) - S_j(floor)) with S_j = a F_j +
 * b G_j read from the slice's rows of u_mslices (runtime/core/env_map_slices.h;
 * over their largest value), into one target: the texel's occluded
 * irradiance over dphi (RGB, <= 0).
 *
 * HFS_ENV_DOT 1 (the sky occlusion, pass_env_sky_occlusion.c): T_occ as
 * above, rounded to fp16 as its targets would store it, dotted here with
 * the SH sky u_envo (each channel's 16 coefficients over their sum of
 * magnitudes, uniform_blocks.h hfs_gles_env_occ_weights), into two targets
 * (hfs_env_occ: RGBA hi + lo_r, RG lo_g, lo_b): 3 values a texel, as fp16
 * (hi, lo) pairs, kept instead of 16, for a frame whose sky is not being
 * turned.
 */
// hfs-variant: HFS_FP32 1
// hfs-variant: HFS_SWATH_TEX 1
// hfs-variant: HFS_ENV_MAP 1
// hfs-variant: HFS_ENV_MAP 1, HFS_FP32 1
// hfs-variant: HFS_PAIRS 1
// hfs-variant: HFS_PAIRS 1, HFS_ENV_MAP 1
// hfs-variant: HFS_FARK 3
// hfs-variant: HFS_PAIRS 1, HFS_FARK 3
// hfs-variant: HFS_PAIRS 1, HFS_FARK 2, HFS_ENV_MAP 1
// hfs-variant: HFS_ENV_DOT 1
// hfs-variant: HFS_ENV_DOT 1, HFS_FP32 1
// hfs-variant: HFS_PAIRS 1, HFS_FARK 2, HFS_ENV_DOT 1
// hfs-variant: HFS_PAIRS 1, HFS_FARK 2, HFS_FARH 3

#ifndef HFS_SCALES_MAX
#define HFS_SCALES_MAX 256
#endif
#ifndef HFS_NDIR
#define HFS_NDIR 32
#endif
#define HFS_DIR_UNROLLED 32              /* HFS_DIR in main */
#ifndef HFS_FARK
#define HFS_NSUB 1                       /* horizons per slice */
#else
#define HFS_NSUB HFS_FARK
#endif
#ifndef HFS_FARH
#define HFS_FARH 1                       /* far occluders' heights (layers of u_far) */
#endif

precision highp float;
precision highp int;
precision highp sampler2D;
precision highp sampler2DArray;

vec3 hfs_normal_at(highp sampler2DArray h, ivec2 p, ivec2 size, float zf);
vec3 hfs_normal_from(vec2 hx0, vec2 hx1, vec2 hy0, vec2 hy1, ivec2 span_i, float zf);
vec2 hfs_height_at(highp sampler2DArray h, ivec2 p);
vec4 hfs_f16v(vec4 v);
void hfs_env_occ(vec4 t[4], vec4 l[12], out vec4 a, out vec2 b);
vec2 hfs_grid_uv(ivec2 p, int sub, ivec2 size, ivec2 vsize);
vec2 hfs_far_tile_uv(vec2 fpix, float i, int cols, ivec2 fsize, vec2 atlas);
float hfs_far_pair_slope(vec4 v, int k, float shift, float dz, float inv_step);
float hfs_hdiff(vec2 a, vec2 b);
float hfs_grid_rise(highp sampler2DArray levels, ivec2 p, int step, ivec2 size, vec4 sc,
                    out vec2 t, out vec2 off);
float hfs_grid_blend(ivec2 p, ivec2 x0, ivec2 x1, vec4 r, out vec2 t, out vec2 off);
vec2 hfs_grid_uv_at(ivec2 p, int sub, vec2 t, ivec2 vsize);
vec2 hfs_grid_pix_at(ivec2 p, int sub, vec2 t);

uniform highp sampler2DArray u_levels;   /* R_L, layer L - lmin, RG hi+lo, LINEAR */
uniform highp sampler2DArray u_height;   /* the heights (hi, lo): normals, near slopes */
uniform float u_zf;                      /* hscale zscale / dx, clamped to 1e30 */
uniform highp sampler2DArray u_hor;      /* grid horizons, tan(x / 2), 4 a layer, LINEAR */
uniform ivec2 u_size;                    /* W, H */
uniform ivec2 u_vsize;                   /* visibility grid size */
uniform int u_sub;
uniform int u_near;                      /* 1: the finest scale is searched here */
#ifdef HFS_FARK
uniform highp sampler2DArray u_far;      /* far occluders, 2 a texel, LINEAR: an atlas
                                            of tiles (env_horizons.frag HFS_FAR_ATLAS) */
uniform ivec2 u_fsize;                   /* the far grid's size (a tile) */
uniform int u_fstep;                     /* and step */
uniform int u_fcols;                     /* tiles a row */
uniform vec2 u_fatlas;                   /* the atlas' size */
uniform vec2 u_fsub[HFS_FARK];           /* sub-direction h at phi + delta_h:
                                            (cos delta_h, sin delta_h) */
#endif

layout(std140) uniform HfsScales {
    ivec4 u_nscales;                     /* (N: the scales, 0, 0, 0) */
    vec4 u_scale[HFS_SCALES_MAX];        /* (d_i, inv_run_i, layer, 0) */
};
#define HFS_NLEV (u_nscales.x)           /* the scale count: a uniform */
#ifdef HFS_SWATH_TEX
vec4 hfs_block_vec4(highp usampler2D t, int i);
uniform highp usampler2D u_swath_tex;
#define SW_DIR(j) hfs_block_vec4(u_swath_tex, 2 + (j))
#define SW_COEF(k) hfs_block_vec4(u_swath_tex, 2 + HFS_NDIR + (k))
#define SW_NEARW(i) hfs_block_vec4(u_swath_tex, 18 + HFS_NDIR + (i))
#define SW_TRIG(j) hfs_block_vec4(u_swath_tex, 18 + 4 * HFS_NDIR + (j))
#else
layout(std140) uniform HfsSwath {
    vec4 u_win;
    vec4 u_occtop;
    vec4 u_dir[HFS_NDIR];                /* (cos, sin, 0, 0) */
    vec4 u_coef[16];                     /* dphi x profile terms per k (see below) */
    vec4 u_nearw[3 * HFS_NDIR];          /* per direction: 3 x 3 weights, row-major */
    vec4 u_trig[HFS_NDIR];               /* (cos 2phi, sin 2phi, cos 3phi, sin 3phi) */
};
#define SW_NEARW(i) u_nearw[i]
#define SW_TRIG(j) u_trig[j]
#define SW_DIR(j) u_dir[j]
#define SW_COEF(k) u_coef[k]
#endif

layout(location = 0) out vec4 o_t0;
#ifdef HFS_ENV_MAP
#ifndef HFS_PI
#define HFS_PI 3.14159265358979
#endif
#define HFS_MAP_E 257                    /* env_map_slices.h HFS_MAP_SLICE_E */
uniform highp sampler2D u_mslices;       /* per slice: F row, G row; LINEAR */

/* S_j at elevation e: a F_j(e) + b G_j(e), linear between the table's
 * elevations (env_map_slices.c slice_s). */
vec3 map_s(int j, float a, float b, float e)
{
    float u = ((e + 0.5 * HFS_PI) / HFS_PI * float(HFS_MAP_E - 1) + 0.5) / float(HFS_MAP_E);
    float h = 1.0 / float(2 * HFS_NDIR);
    return a * texture(u_mslices, vec2(u, (float(2 * j) + 0.5) * h)).rgb +
           b * texture(u_mslices, vec2(u, (float(2 * j) + 1.5) * h)).rgb;
}
#elif defined(HFS_ENV_DOT)
uniform vec4 u_envo[12];                 /* the sky, 4 vec4 a channel, over its size */
layout(location = 1) out vec4 o_t1;      /* (lo_g, lo_b) into an RG target */
#else
layout(location = 1) out vec4 o_t1;
layout(location = 2) out vec4 o_t2;
layout(location = 3) out vec4 o_t3;
#endif

/* Sums over the slices, by azimuthal factor: Y_k along slice j is
 * trig_k(phi_j) sum_m a_km f_m(e) (runtime/core/slice_light.h
 * hfs_slice_profile), so T_k = sum_m a_km sum_j trig_k(phi_j) d_jm, d_jm
 * the slice's integral of f_m between its tangent plane and its horizon.
 * Each factor needs only a few m (uniform_blocks.h): accumulating those
 * per slice (22 products) and contracting with a once per texel costs a
 * fifth of contracting each slice with its 16 x 7 coefficients. */
struct Sums {
    vec4 one, c2, s2;   /* factor 1, cos 2phi, sin 2phi: m = 0, 2, 3, 6 */
    vec3 c1, s1;        /* cos phi, sin phi: m = 1, 4, 5 */
    vec2 c3, s3;        /* cos 3phi, sin 3phi: m = 1, 5 */
};

/* cos kx, sin kx for k = 1..5 from (cos x, sin x). */
void multiples(vec2 x, out float c[5], out float s[5])
{
    c[0] = x.x;
    s[0] = x.y;
    for (int k = 1; k < 5; ++k) {
        c[k] = c[k - 1] * x.x - s[k - 1] * x.y;
        s[k] = s[k - 1] * x.x + c[k - 1] * x.y;
    }
}

/* d_m = g_m(x) - g_m(xf), g_m(x) = Int_x^{pi/2} f_m(e) (a cos e + b sin e)
 * cos e de (runtime/core/slice_light.c hfs_slice_integrals: the same closed
 * forms, differenced): cos kx, sin kx of x (cx, sx) and of xf (cf, sf),
 * k = 1..5, and dj0 = xf - x.  With Jc_k = Int_x^{pi/2} cos ke de and
 * Js_k = Int sin ke de, their differences need only those; all of it is
 * linear in them, so a mean over sub-horizons is the same expressions of
 * their mean multiples. */
void slice_dg(float a, float b, float cx[5], float sx[5], float cf[5], float sf[5], float dj0,
              out vec4 d0236, out vec3 d145)
{
    float Jc[5], Js[5]; /* differences, index k - 1 */
    for (int k = 0; k < 5; ++k) {
        Jc[k] = (sf[k] - sx[k]) / float(k + 1);
        Js[k] = (cx[k] - cf[k]) / float(k + 1);
    }
    float J0 = dj0;
    d0236 = vec4(a * (J0 + Jc[1]) / 2.0 + b * Js[1] / 2.0,
                 a * (Js[0] + Js[2]) / 4.0 + b * (Jc[0] - Jc[2]) / 4.0,
                 a * (J0 / 4.0 + Jc[1] / 2.0 + Jc[3] / 4.0) + b * Js[3] / 4.0,
                 a * (Js[0] / 4.0 + Js[2] / 2.0 + Js[4] / 4.0) + b * (Jc[0] - Jc[4]) / 4.0);
    d145 = vec3(a * (3.0 * Jc[0] + Jc[2]) / 4.0 + b * (Js[0] + Js[2]) / 4.0,
                a * (Js[1] / 2.0 + Js[3] / 4.0) + b * (J0 - Jc[3]) / 4.0,
                a * (Jc[0] / 4.0 + Jc[2] / 2.0 + Jc[4] / 4.0) + b * (Js[4] - Js[0]) / 4.0);
}

/* (cos e, sin e) of the elevation e = atan(t) of slope t. */
vec2 slope_dir(float t)
{
    float c = inversesqrt(1.0 + t * t);
    return vec2(c, t * c);
}

/* Adds slice j's part (cs = cos, sin phi) between its tangent plane (slope
 * tf, elevation xf = atan(tf)) and its horizons, the mean over the
 * HFS_NSUB sub-horizons of slopes t[h] (each at least tf): one inverse
 * square root and one atan per horizon, no division. */
void slice_add_mean(int j, vec2 cs, float a, float b, float tf, float xf, float t[HFS_NSUB],
                    inout Sums S)
{
    float cf[5], sf[5], cx[5], sx[5];
    multiples(slope_dir(tf), cf, sf);
    float dj0 = xf;
#if HFS_NSUB == 1
    multiples(slope_dir(t[0]), cx, sx);
    dj0 -= atan(t[0]);
#elif HFS_NSUB == 2
    /* Two elevations x0, x1 = m -+ D: the mean of e^{ikx} is e^{ikm}
     * cos(kD), and e^{im} cos D is the mean of the two unit vectors, so one
     * set of multiples, cos kD by Chebyshev's recurrence, one atan.  The
     * direction e^{im} is the sum's where the two lie within 120 degrees
     * (r >= 1), else their difference's turned a quarter: u1 - u0 = 2 sin D
     * (-sin m, cos m).  Near +-pi/2 at once (a wall's two sides, slopes
     * past ~1e7) the sum's components are a few ulps of 1 each and its
     * direction was rounding: at subsample 2 the sky moved by up to a tenth
     * of the maximum from the CPU's (BENCHMARKS.md "Past slopes of 1e7 and of 1e18"). */
    vec2 u0 = slope_dir(t[0]), u1 = slope_dir(t[1]);
    vec2 sum = u0 + u1, dif = u1 - u0;
    float r = length(sum); /* 2 cos D >= 0: both elevations in (-pi/2, pi/2] */
    vec2 em = r >= 1.0 ? sum / r
                       : vec2(dif.y, -dif.x) * ((t[1] >= t[0] ? 1.0 : -1.0) / length(dif));
    multiples(em, cx, sx);
    float ck[5];
    ck[0] = 0.5 * r;
    ck[1] = 2.0 * ck[0] * ck[0] - 1.0;
    for (int k = 2; k < 5; ++k)
        ck[k] = 2.0 * ck[0] * ck[k - 1] - ck[k - 2];
    for (int k = 0; k < 5; ++k) {
        cx[k] *= ck[k];
        sx[k] *= ck[k];
    }
    dj0 -= atan(r >= 1.0 ? sum.y / sum.x : em.y / em.x); /* > 0 denominators: |m| < pi/2 */
#else
    float c1[5], s1[5];
    for (int k = 0; k < 5; ++k) {
        cx[k] = 0.0;
        sx[k] = 0.0;
    }
    for (int h = 0; h < HFS_NSUB; ++h) {
        multiples(slope_dir(t[h]), c1, s1);
        for (int k = 0; k < 5; ++k) {
            cx[k] += c1[k] / float(HFS_NSUB);
            sx[k] += s1[k] / float(HFS_NSUB);
        }
        dj0 -= atan(t[h]) / float(HFS_NSUB);
    }
#endif
    vec4 d0236;
    vec3 d145;
    slice_dg(a, b, cx, sx, cf, sf, dj0, d0236, d145);
    vec2 d15 = d145.xz;
    vec4 tr = SW_TRIG(j); /* cos 2phi, sin 2phi, cos 3phi, sin 3phi */
    S.one += d0236;
    S.c1 += cs.x * d145;
    S.s1 += cs.y * d145;
    S.c2 += tr.x * d0236;
    S.s2 += tr.y * d0236;
    S.c3 += tr.z * d15;
    S.s3 += tr.w * d15;
}

/* T_k from the sums: k = l(l+1) + m, factor 1 (m = 0), cos(m phi) (m > 0),
 * sin(|m| phi) (m < 0). */
void contract(Sums S, out vec4 T[4])
{
    T[0] = vec4(dot(SW_COEF(0), S.one), dot(SW_COEF(1).xyz, S.s1),
                dot(SW_COEF(2), S.one), dot(SW_COEF(3).xyz, S.c1));
    T[1] = vec4(dot(SW_COEF(4), S.s2), dot(SW_COEF(5).xyz, S.s1),
                dot(SW_COEF(6), S.one), dot(SW_COEF(7).xyz, S.c1));
    T[2] = vec4(dot(SW_COEF(8), S.c2), dot(SW_COEF(9).xy, S.s3),
                dot(SW_COEF(10), S.s2), dot(SW_COEF(11).xyz, S.s1));
    T[3] = vec4(dot(SW_COEF(12), S.one), dot(SW_COEF(13).xyz, S.c1),
                dot(SW_COEF(14), S.c2), dot(SW_COEF(15).xy, S.c3));
}

/* The slopes to the 3 x 3 neighbours over 1 texel (row-major from
 * (-1, -1)), -1e30 off the field: a sample that needs one never wins,
 * as hfs_scale_offset would skip it; and the normal from the same reads
 * (hfs_normal_from: its central differences' 4 heights are among them,
 * clamped to the field as hfs_normal_at clamps them), 9 fetches for both.
 * The finest scale reads the heights themselves (pyramid_layout.c
 * hfs_pyramid_read_level: level N-1 reads the input at any offset), so
 * u_height's layer holds the values u_levels does there. */
vec3 near_slopes(ivec2 p, out vec4 s0, out vec4 s1, out float s8)
{
    float rise = u_scale[HFS_NLEV - 1].y;
    vec2 hq[9];
    for (int i = 0; i < 9; ++i)
        hq[i] = hfs_height_at(u_height, clamp(p + ivec2(i % 3 - 1, i / 3 - 1), ivec2(0),
                                              u_size - 1));
    float s[9];
    for (int i = 0; i < 9; ++i) {
        ivec2 q = p + ivec2(i % 3 - 1, i / 3 - 1);
        bool in_field = all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, u_size));
        s[i] = in_field ? hfs_hdiff(hq[i], hq[4]) * rise : -1e30;
    }
    s0 = vec4(s[0], s[1], s[2], s[3]);
    s1 = vec4(s[4], s[5], s[6], s[7]);
    s8 = s[8];
    ivec2 lo = max(p - 1, ivec2(0)), hi = min(p + 1, u_size - 1);
    return hfs_normal_from(hq[3], hq[5], hq[1], hq[7], hi - lo, u_zf);
}

/* One of the 3 x 3 neighbours' height differences (near_slopes; i
 * row-major from (-1, -1), 4 the texel itself: 0). */
float near_rise(int i, vec4 s0, vec4 s1, float s8)
{
    return i < 4 ? s0[i] : (i == 4 ? 0.0 : (i < 8 ? s1[i - 4] : s8));
}

/* How far the receivers of the grid of step `step` around texel p stand
 * above it, in texels: their heights blended with p's bilinear weights,
 * minus p's.  Each receiver's horizon is an occluder's height above that
 * receiver, so above p it is this much higher.  On a 2-step grid the
 * receivers are among p's 3 x 3 neighbours, whose differences near_slopes
 * already holds (a receiver 2 away has weight 0); on a coarser grid four
 * fetches.  t and off: where p reads the grid (off a receiver across a
 * wall), and that place less p's (hfs_grid_blend). */
float grid_rise(ivec2 p, int step, vec4 s0, vec4 s1, float s8, out vec2 t, out vec2 off)
{
    if (step != 2 || u_near == 0)
        return hfs_grid_rise(u_levels, p, step, u_size, u_scale[HFS_NLEV - 1], t, off);
    ivec2 x0 = (p / step) * step;
    ivec2 x1 = min(x0 + step, u_size - 1);
    ivec2 o0 = x0 - p + 1, o1 = x1 - p + 1; /* 0..2 */
    vec4 r = vec4(near_rise(3 * o0.y + o0.x, s0, s1, s8), near_rise(3 * o0.y + o1.x, s0, s1, s8),
                  near_rise(3 * o1.y + o0.x, s0, s1, s8), near_rise(3 * o1.y + o1.x, s0, s1, s8));
    return hfs_grid_blend(p, x0, x1, r, t, off);
}



/* Slice j's part: its horizon x = max(the grid's horizon farj, the near
 * slope from the 3 x 3 neighbourhood (s0, s1, s8), the tangent plane),
 * or with split horizons HFS_NSUB of them, each also at least its far
 * sub-direction's slope fsub[h]; integrated above the tangent plane into
 * S (or, HFS_ENV_MAP, against the map into occ).  All as slopes (tan of
 * the elevation: monotonic, so the max is the max), clamped so that
 * 1 + t^2 stays finite. */
void dir_step(int j, float farj, float fsub[HFS_NSUB], vec3 n, vec4 s0, vec4 s1, float s8,
              inout Sums S, inout vec3 occ)
{
    vec2 cs = SW_DIR(j).xy;
    float a = n.x * cs.x + n.y * cs.y;
    float tf = -a / n.z; /* the tangent plane: N_z > 0 */
    float tn = dot(SW_NEARW(3 * j), s0) + dot(SW_NEARW(3 * j + 1), s1) +
               SW_NEARW(3 * j + 2).x * s8;
    /* The cell's near end: the slopes to (+-1, 0) and (0, +-1). */
    tn = max(tn, abs(cs.x) * (cs.x > 0.0 ? s1.y : s0.w) + abs(cs.y) * (cs.y > 0.0 ? s1.w : s0.y));
#ifdef HFS_PAIRS
    tn = max(tn, farj); /* farj: a slope (hfs_far_slope) */
#else
    /* farj: tan(x / 2), -1 where nothing rises */
    tn = max(tn, farj > -1.0 ? 2.0 * farj / max(1.0 - farj * farj, 1e-30) : -1e30);
#endif
    float t[HFS_NSUB];
    float top = -1e30;
#ifdef HFS_FARK
    float ap = n.y * cs.x - n.x * cs.y; /* N.d rotated a quarter turn */
#endif
    for (int h = 0; h < HFS_NSUB; ++h) {
#ifdef HFS_FARK
        /* only where it rises above its own sub-direction's tangent plane
         * (runtime/core/split_horizon.h hfs_split_above_plane) */
        float plane = -(a * u_fsub[h].x + ap * u_fsub[h].y) / n.z;
        float th = max(tn, fsub[h] > plane + 1e-3 * (1.0 + abs(plane)) ? fsub[h] : -1e30);
#else
        float th = tn;
#endif
        th = clamp(th, -1e18, 1e18);
        top = max(top, th);
        t[h] = max(th, tf);
    }
    /* Only slices whose horizon rises above the tangent plane carry an
     * occluded part (0 exactly elsewhere). */
    if (top > tf) {
        float xf = atan(tf);
#ifdef HFS_ENV_MAP
        vec3 m = vec3(0.0);
        for (int h = 0; h < HFS_NSUB; ++h)
            m += map_s(j, a, n.z, atan(t[h]));
        occ += m / float(HFS_NSUB) - map_s(j, a, n.z, xf);
#else
        slice_add_mean(j, cs, a, n.z, tf, xf, t, S);
#endif
    }
}

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec2 uv = hfs_grid_uv(p, u_sub, u_size, u_vsize);
    vec4 s0 = vec4(-1e30), s1 = vec4(-1e30);
    float s8 = -1e30;
    vec3 n = u_near > 0 ? near_slopes(p, s0, s1, s8) : hfs_normal_at(u_height, p, u_size, u_zf);
    Sums S = Sums(vec4(0.0), vec4(0.0), vec4(0.0), vec3(0.0), vec3(0.0), vec2(0.0), vec2(0.0));
    vec3 occ = vec3(0.0);
    /* Up to HFS_DIR_UNROLLED directions are written out one by one, so
     * that every uniform index is a constant: llvmpipe reads a uniform
     * array at a loop-dependent index lane by lane (a gather), which made
     * this pass 1.7x slower (BENCHMARKS.md "Uniform indices"). */
    vec4 far = vec4(0.0);
    /* direction J's index where the unrolled code reads it (only J <
     * HFS_NDIR runs, but every constant index must be in range) */
#define HFS_DIR_AT(J) ((J) < HFS_NDIR ? (J) : HFS_NDIR - 1)
    float fsub[HFS_NSUB];
    fsub[0] = -1e30;
#ifdef HFS_FARK
    /* Split horizons: the far grid's occluders, moved to this texel. */
    vec2 tf, of; /* where it reads them, and that less its place */
    float dzf = grid_rise(p, u_fstep, s0, s1, s8, tf, of), inv_fstep = 1.0 / float(u_fstep);
    vec2 fpix = hfs_grid_pix_at(p, u_fstep, tf); /* in a tile */
    vec4 fv[HFS_FARH];
    /* the largest of the heights' occluders (split_horizon.h) */
#define HFS_SUBS(J)                                                         \
    vec2 dj = SW_DIR(HFS_DIR_AT(J)).xy;                                     \
    vec2 ofj = vec2(dot(of, dj), dot(of, vec2(-dj.y, dj.x)));               \
    for (int h = 0; h < HFS_FARK; ++h) {                                    \
        int e = (J) * HFS_FARK + h;                                         \
        vec2 fuv = hfs_far_tile_uv(fpix, float(e / 2), u_fcols, u_fsize, u_fatlas); \
        for (int c = 0; c < HFS_FARH && e % 2 == 0; ++c)                    \
            fv[c] = texture(u_far, vec3(fuv, float(c)));                    \
        fsub[h] = -1e30;                                                    \
        for (int c = 0; c < HFS_FARH; ++c)                                  \
            fsub[h] = max(fsub[h], hfs_far_pair_slope(fv[c], e % 2, dot(ofj, u_fsub[h]), dzf, \
                                                      inv_fstep));          \
    }
#else
#define HFS_SUBS(J)
#endif
    /* The grid's occluder in one direction, blended between the receivers
     * around this texel (its height h over them and its distance d, in
     * texels), seen from this texel as a slope: the receivers stand dz above
     * it, so the occluder stands h + dz above it.  Blending the occluder's
     * position, not its slope, keeps a receiver on a spike, whose horizon
     * lies far below it, from lifting its neighbours' horizons.  An occluder
     * within a grid step moves in proportion (d / u_sub of dz): it need not
     * lie on this texel's own line of sight, and a step at some distance
     * would make fp16's rounding of d flip texels (BENCHMARKS.md "Occluders
     * moved to each texel"). */
#ifdef HFS_PAIRS
    /* On a sub-sampled grid its horizons move to this texel's height. */
    vec2 tv, ov;
    float dz = grid_rise(p, u_sub, s0, s1, s8, tv, ov), inv_sub = 1.0 / float(u_sub);
    uv = hfs_grid_uv_at(p, u_sub, tv, u_vsize);
#define HFS_FAR(J)                                                          \
    if ((J) % 2 == 0)                                                       \
        far = texture(u_hor, vec3(uv, float((J) / 2)));                     \
    float fu = hfs_far_pair_slope(far, (J) % 2, dot(ov, SW_DIR(HFS_DIR_AT(J)).xy), dz, inv_sub);
#else
#define HFS_FAR(J)                                                          \
    if ((J) % 4 == 0)                                                       \
        far = texture(u_hor, vec3(uv, float((J) / 4)));                     \
    float fu = far[(J) % 4];
#endif
#define HFS_DIR(J)                                                          \
    if ((J) < HFS_NDIR) {                                                   \
        HFS_FAR(J)                                                          \
        HFS_SUBS(J)                                                         \
        dir_step(J, fu, fsub, n, s0, s1, s8, S, occ);                       \
    }
#if HFS_NDIR <= HFS_DIR_UNROLLED
    HFS_DIR(0) HFS_DIR(1) HFS_DIR(2) HFS_DIR(3) HFS_DIR(4) HFS_DIR(5) HFS_DIR(6) HFS_DIR(7)
    HFS_DIR(8) HFS_DIR(9) HFS_DIR(10) HFS_DIR(11) HFS_DIR(12) HFS_DIR(13) HFS_DIR(14)
    HFS_DIR(15) HFS_DIR(16) HFS_DIR(17) HFS_DIR(18) HFS_DIR(19) HFS_DIR(20) HFS_DIR(21)
    HFS_DIR(22) HFS_DIR(23) HFS_DIR(24) HFS_DIR(25) HFS_DIR(26) HFS_DIR(27) HFS_DIR(28)
    HFS_DIR(29) HFS_DIR(30) HFS_DIR(31)
#else
    for (int j = 0; j < HFS_NDIR; ++j)
        HFS_DIR(j)
#endif
#ifdef HFS_ENV_MAP
    o_t0 = hfs_f16v(vec4(occ, 0.0)); /* the shading multiplies by dphi */
#else
    vec4 T[4];
    contract(S, T);
    for (int k = 0; k < 4; ++k)
        T[k] = hfs_f16v(T[k]);
#ifdef HFS_ENV_DOT
    vec2 lo_gb;
    hfs_env_occ(T, u_envo, o_t0, lo_gb);
    o_t1 = vec4(lo_gb, 0.0, 0.0);
#else
    o_t0 = T[0];
    o_t1 = T[1];
    o_t2 = T[2];
    o_t3 = T[3];
#endif
#endif
}
