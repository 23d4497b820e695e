/*
 * bounce_gather.frag - one indirect bounce on the visibility grid
 * (runtime/cpu/cpu_bounce.h, DESIGN.md "Indirect light"), the CPU reference's
 * walk at each grid receiver g: along each bounce azimuth (u_edir[j * u_bhead.z]: every
 * u_bhead.z-th of the environment's), outward from the receiver's tangent
 * plane, its own cell (the near end's one-sided slopes or the far edge,
 * whichever rises more: field_geom.h hfs_field_first_cell_slope), then
 * each scale of the pyramid and u_refine samples after it, read as the
 * horizons read them.  A scale's group of samples, when one rises above
 * everything nearer, casts the band of elevations between the old top and
 * its highest sample's, lit by the previous bounce's exit radiance at the
 * first sample that rose (u_rad, bilinear) and weighted by
 * the clamped cosine's exact integral over the band (hfs_slice_cosine,
 * as slice_light.c's).  HFS_SLICE: the bands stop at the
 * direct light's horizon of the slice (the grid's horizons of
 * env_horizons.frag, and the own cell), so what a receiver gathers and the
 * sky it sees never overlap (lights.h hfs_bounce_capped).
 * Writes E_b = dphi / pi * sum over slices and bands (RGB); HFS_SLICE also
 * the receiver's occluded part over pi, W = dphi / pi sum over all of the
 * environment's slices of the clamped cosine's integral below the direct
 * horizon (alpha: 1 would be the whole hemisphere), by which
 * bounce_light.frag scales E to each texel's own.
 * Samples whose best case (the field's largest height, u_vmax) cannot
 * rise above the current top are skipped without a fetch: they could not
 * cast a band.
 * HFS_FARK K (HFS_SLICE with split horizons, split_horizon.h): the direct
 * light's horizon of a slice is K sub-horizons, max(the grid's near part,
 * each sub-direction's far occluders (HFS_FARH heights) from u_far moved
 * to the receiver, as env_slices.frag), each band clipped to each of them
 * (hfs_split_band, the mean of the parts, as W): bounces leave the direct
 * light as it is (issue 36).
 * The near part (HFS_SLICE, u_near_d > 0; issue 36 "the gather sees what
 * a point sees"): the bands cast by the own cell and the scales within
 * u_near_d texels are what changes from texel to texel on rough relief
 * (a pit's own walls), so on a sub-sampled bounce grid they are gathered
 * at every texel (HFS_NEAR) and the grid keeps only the rest.  Grid
 * receivers then write E - E_near and W - W_near (W_near: the near bands'
 * cosine weights, dphi / pi times their sum), bounce_light.frag adds each
 * texel's own near part and scales the grid's rest by the texel's own
 * occluded part beyond its near part.
 * HFS_NEAR 1: that near pass, at every texel (u_sub 1): the own cell and
 * the scales within u_near_d, capped by the texel's direct horizons (the
 * grid's occluders read bilinearly and moved to the texel's height, as
 * env_slices.frag reads them), into (E_near, W_near).
 * HFS_GLOSSY (a glossy receiver, gloss.h): each band is also weighed by
 * the Phong lobe about the receiver's R times its cosine (lobe_band, as
 * slice_light.c hfs_lobe_slice_band), written as G = ks (S+2)/(2 pi)
 * dphi sum Lo W_lobe into the second target (HFS_GLOSSY 2: R for the
 * view from u_geye, the receiver's own point).
 */
// hfs-variant: HFS_SLICE 1
// hfs-variant: HFS_FP32 1
// hfs-variant: HFS_SLICE 1, HFS_GLOSSY 1
// hfs-variant: HFS_SLICE 1, HFS_PAIRS 1
// hfs-variant: HFS_SLICE 1, HFS_GLOSSY 2, HFS_FP32 1
// hfs-variant: HFS_SLICE 1, HFS_FARK 3
// hfs-variant: HFS_SLICE 1, HFS_PAIRS 1, HFS_FARK 2, HFS_GLOSSY 1
// hfs-variant: HFS_SLICE 1, HFS_NEAR 1
// hfs-variant: HFS_SLICE 1, HFS_PAIRS 1, HFS_FARK 2, HFS_NEAR 1
// hfs-variant: HFS_SLICE 1, HFS_PAIRS 1, HFS_NEAR 1, HFS_FP32 1
// hfs-variant: HFS_SLICE 1, HFS_PAIRS 1, HFS_FARK 2, HFS_FARH 3
#ifndef HFS_SCALES_MAX
#define HFS_SCALES_MAX 256
#endif
#ifndef HFS_NLAYERS
#define HFS_NLAYERS 25
#endif
#ifndef HFS_NDIR
#define HFS_NDIR 32                      /* the environment's directions */
#endif
#ifndef HFS_NBDIR
#define HFS_NBDIR 16                     /* the bounces': every u_bhead.z-th of those */
#endif
#ifndef HFS_HALF_PI
#define HFS_HALF_PI 1.5707963267948966
#endif
#ifndef HFS_FARK
#define HFS_NSUB 1                       /* the direct light's horizons per slice */
#else
#define HFS_NSUB HFS_FARK
#endif
#ifndef HFS_FARH
#define HFS_FARH 1                       /* far occluders' heights: u_far's layers */
#endif

precision highp float;
precision highp int;
precision highp sampler2D;
precision highp sampler2DArray;

float hfs_h(vec2 t);
float hfs_hdiff(vec2 a, vec2 b);
vec3 hfs_normal_sides(highp sampler2DArray h, ivec2 p, ivec2 size, float zf, vec2 zp,
                      out vec4 d, out bvec4 on);
ivec2 hfs_receiver(ivec2 size, int sub);
void hfs_receiver_heights(highp sampler2DArray levels, ivec2 g, out vec2 hx[HFS_NLAYERS]);
bool hfs_scale_offset(ivec2 g, ivec2 size, float d, vec2 cs, out vec2 o);
float hfs_scale_slope(highp sampler2DArray levels, ivec2 g, ivec2 size, vec2 o, vec4 sc, vec2 h);
bool hfs_scale_takes_over(float sl, float ref, float tie);
float hfs_slice_cosine(float a, float b, float x);
#if defined(HFS_FARK) || defined(HFS_NEAR)
vec2 hfs_grid_uv(ivec2 p, int sub, ivec2 size, ivec2 vsize);
vec2 hfs_far_tile_uv(vec2 fpix, float i, int cols, ivec2 fsize, vec2 atlas);
float hfs_far_pair_slope(vec4 v, int k, float shift, float dz, float inv_step);
float hfs_grid_rise(highp sampler2DArray levels, ivec2 p, int step, ivec2 size, vec4 sc,
                    out vec2 t, out vec2 off);
vec2 hfs_grid_uv_at(ivec2 p, int sub, vec2 t, ivec2 vsize);
vec2 hfs_grid_pix_at(ivec2 p, int sub, vec2 t);
#endif

uniform highp sampler2DArray u_levels;   /* R_L, layer L - lmin, RG hi+lo, LINEAR */
uniform highp sampler2DArray u_height;   /* the heights (hi, lo): normals, one-sided slopes */
uniform float u_zf;                      /* hscale zscale / dx, clamped to 1e30 */
uniform highp sampler2D u_rad;           /* Lo_{b-1}, full resolution, LINEAR */
#ifdef HFS_SLICE
uniform highp sampler2DArray u_hor;      /* grid horizons, tan(x / 2), 4 a layer (HFS_PAIRS:
                                            2 occluders, (height, distance)) */
#endif
uniform ivec2 u_size;                    /* W, H */
uniform int u_sub;                       /* the bounce grid's step */
#ifdef HFS_SLICE
uniform int u_vsub;                      /* the visibility grid's (u_hor's) step */
uniform ivec2 u_vsize;                   /* and size */
#endif
#ifdef HFS_FARK
uniform highp sampler2DArray u_far;      /* far occluders, 2 a texel, LINEAR: an atlas of
                                            tiles (env_slices.frag, hfs_gles_bind_env_far) */
uniform ivec2 u_fsize;                   /* the far grid's size (a tile) */
uniform int u_fstep;                     /* and step */
uniform int u_fcols;                     /* tiles a row */
uniform vec2 u_fatlas;                   /* the atlas' size */
uniform vec2 u_fsub[HFS_FARK];           /* sub-direction h's turn: (cos, sin) */
vec2 g_fpix, g_fo;                       /* the receiver's place in a far tile, less its own */
float g_fdz;                             /* and how far the far receivers stand above it */
#endif
uniform float u_vmax;                    /* largest normalized height, a hair up */
uniform int u_refine;                    /* samples per scale besides the scale's own */
uniform float u_near_d;                  /* the near part's reach, texels (0: none) */
#ifdef HFS_NEAR
vec2 g_vuv, g_vo;                        /* the texel's place on the visibility grid, less its own */
float g_vdz;                             /* and how far its receivers stand above it */
#endif
uniform float u_tie;                     /* hfs_horizon_tie_slope */
#ifdef HFS_GLOSSY
uniform vec4 u_gpar;                     /* (S, step, 1e-6^(1/S), 0): hfs_lobe_slice */
uniform vec4 u_gview;                    /* (V towards the viewer, ks (S+2)/(2 pi) dphi) */
uniform vec4 u_geye;                     /* HFS_GLOSSY 2: the eye, texel units */
uniform vec4 u_ghgt;                     /* (base, hscale, zscale / dx, 0) */
#endif

layout(std140) uniform HfsScales {
    ivec4 u_nscales;                     /* (N: the scales, 0, 0, 0) */
    vec4 u_scale[HFS_SCALES_MAX];        /* (d_i, inv_run_i, layer, 0) */
};
#define HFS_NLEV (u_nscales.x)           /* the scale count: a uniform */
layout(std140) uniform HfsBounce {
    vec4 u_bhead;                        /* (dphi / pi, levels per octave k, stride, 0) */
    vec4 u_edir[HFS_NDIR];               /* the environment's (cos, sin, 0, 0) */
};

layout(location = 0) out vec4 o_e;
#ifdef HFS_GLOSSY
layout(location = 1) out vec4 o_g;       /* G (RGB) */
#endif

#ifdef HFS_GLOSSY
#ifndef HFS_LOBE_STEPS
#define HFS_LOBE_STEPS 64
#endif
/* max(0, R.s)^S max(0, N.s) cos e along the slice: t_R = l.x cos e +
 * l.y sin e, t_N = n.x cos e + n.y sin e. */
float lobe_at(vec4 l, float e)
{
    float ce = cos(e), se = sin(e);
    float tr = l.x * ce + l.y * se, tn = l.z * ce + l.w * se;
    return tr > 0.0 && tn > 0.0 ? pow(tr, u_gpar.x) * tn * ce : 0.0;
}

/* Int_x1^x2 of lobe_at over the lobe's support (sup) in steps of at most
 * u_gpar.y, 2-point Gauss-Legendre each (slice_light.c hfs_lobe_slice_band). */
float lobe_band(vec4 l, vec2 sup, float x1, float x2)
{
    float lo = max(x1, sup.x), hi = min(x2, sup.y);
    if (!(hi > lo))
        return 0.0;
    int n = clamp(int(ceil((hi - lo) / u_gpar.y)), 1, HFS_LOBE_STEPS);
    float step = (hi - lo) / float(n), g = 0.5 * step / sqrt(3.0), sum = 0.0;
    for (int k = 0; k < n; ++k) {
        float mid = lo + (float(k) + 0.5) * step;
        sum += lobe_at(l, mid - g) + lobe_at(l, mid + g);
    }
    return 0.5 * step * sum;
}
#endif

/* The walk's state along one slice.  The top is kept as a slope (samples
 * compare slopes: no atan per sample) and as its elevation's cosine
 * integral (one hfs_slice_cosine per band). */
struct Walk {
    float a, b;      /* N.d, N_z */
    float t_top;     /* slope of the highest sample so far */
    float s_top;     /* hfs_slice_cosine at its elevation */
    float t_cap;     /* the slope where the bands stop: the highest sub-horizon */
#ifdef HFS_SLICE
    float s_cap[HFS_NSUB]; /* hfs_slice_cosine at each sub-horizon (at least the plane) */
#ifdef HFS_GLOSSY
    float x_cap[HFS_NSUB]; /* and its elevation (-1e30 below the plane) */
#endif
#endif
    vec3 acc;        /* sum of Lo_{b-1} W beyond the near part */
    vec3 last;       /* the last band's radiance */
    bool near;       /* the bands cast now are the near part's */
    vec3 acc_near;   /* the near part's sum of Lo_{b-1} W */
    float w_near;    /* and of W */
#ifdef HFS_GLOSSY
    vec4 l;          /* (R.d, R_z, N.d, N_z) */
    vec2 sup;        /* the lobe's support along the slice (x > y: none) */
    vec3 gacc;       /* sum of Lo_{b-1} W_lobe */
#endif
};

/* The band from the top to elevation x (hfs_slice_cosine s there; s = -1e30,
 * x = 1e30: up to each sub-horizon), HFS_SLICE: clipped to each
 * sub-horizon, the mean of the parts (split_horizon.h hfs_split_band).
 * Its cosine weight, and HFS_GLOSSY its lobe's into *wl. */
float band_weight(Walk w, float s, float x, out float wl)
{
    wl = 0.0;
#ifdef HFS_SLICE
    float sum = 0.0;
#ifdef HFS_GLOSSY
    float xt = atan(w.t_top);
#endif
    for (int h = 0; h < HFS_NSUB; ++h) {
        sum += max(w.s_top, w.s_cap[h]) - max(s, w.s_cap[h]);
#ifdef HFS_GLOSSY
        if (w.x_cap[h] > xt)
            wl += lobe_band(w.l, w.sup, xt, min(x, w.x_cap[h])) / float(HFS_NSUB);
#endif
    }
    return sum / float(HFS_NSUB);
#else
#ifdef HFS_GLOSSY
    wl = lobe_band(w.l, w.sup, atan(w.t_top), x);
#endif
    return w.s_top - s;
#endif
}

/* A sample at grid position g + o rising to slope t: casts the band
 * (top, min(t, cap)] lit by the radiance there. */
void cast_band(inout Walk w, float t, ivec2 g, vec2 o)
{
    t = min(t, w.t_cap);
    if (!(t > w.t_top))
        return;
    vec3 lo = texture(u_rad, (vec2(g) + o + 0.5) / vec2(u_size)).rgb;
    float x = atan(t);
    float s = hfs_slice_cosine(w.a, w.b, x);
    float wl;
    float wgt = band_weight(w, s, x, wl);
    /* apart: the grid's rest is no difference of two sums (lo may be < 0) */
    if (w.near) {
        w.acc_near += lo * wgt;
        w.w_near += wgt;
    } else {
        w.acc += lo * wgt;
    }
#ifdef HFS_GLOSSY
    w.gacc += lo * wl;
#endif
    w.last = lo;
    w.t_top = t;
    w.s_top = s;
}

/* The receiver's own cell along cs: the elevation of the max of the near
 * end's slope (the axis neighbours' one-sided slopes, weighted by |cos|,
 * |sin|; ns = (+x, -x, +y, -y)) and the far edge's (bilinear on the finest
 * level) as a slope t, at the far edge's offset o, the two ends' slopes in
 * nf (near, far); false when the cell leaves the field. */
bool own_cell(ivec2 g, vec2 cs, vec4 ns, vec4 sc, vec2 h0, out float t, out vec2 o, out vec2 nf)
{
    float tc = 1.0 / max(abs(cs.x), abs(cs.y));
    t = -1e30;
    nf = vec2(-1e30);
    if (!hfs_scale_offset(g, u_size, tc, cs, o))
        return false;
    float near = abs(cs.x) * (cs.x > 0.0 ? ns.x : ns.y) + abs(cs.y) * (cs.y > 0.0 ? ns.z : ns.w);
    float far = hfs_scale_slope(u_levels, g, u_size, o, sc, h0) * sc.x / tc;
    nf = vec2(near, far);
    t = max(near, far);
    return true;
}

/* The scales, nearest first, each with u_refine samples after it
 * (distances d 2^(q / ((refine + 1) k))): a scale's group casts one band,
 * up to its highest sample, lit at the first one that rose, until the top
 * reaches the cap or a sample leaves the grid (then all farther ones do:
 * the grid is convex).  One band per scale, not per sample: the samples
 * between scales find the peaks the scales miss (the band's top), while
 * each band costs a radiance fetch and an atan.  Lit at the first sample
 * that rises, the band sees the slope facing the receiver; the highest is
 * often a sunlit ridge, and lit there the bounces leaned bright (DEM
 * 128^2: +1.1% of the indirect part's maximum against the truth, now
 * -0.04%; BENCHMARKS.md "Indirect light"). */
void walk_scales(inout Walk w, ivec2 g, vec2 cs, vec2 hx[HFS_NLAYERS])
{
    float step = exp2(1.0 / (float(u_refine + 1) * u_bhead.y));
    bool in_grid = true;
    for (int i = HFS_NLEV - 1; i >= 0 && in_grid && w.t_top < w.t_cap; --i) {
        vec4 sc = u_scale[i];
        w.near = sc.x <= u_near_d;
#ifdef HFS_NEAR
        if (!w.near)
            break; /* the grid gathers the rest */
#endif
        vec2 h = hx[int(sc.z)];
        float most = (u_vmax - hfs_h(h)) * sc.y; /* the largest slope at distance d */
        float f = 1.0, t_best = w.t_top;
        vec2 o_clear = vec2(0.0); /* the band's light: the first sample that rose */
        bool cleared = false;
        for (int q = 0; q <= u_refine; ++q, f *= step) {
            vec2 o;
            if (!hfs_scale_offset(g, u_size, sc.x * f, cs, o)) {
                in_grid = false;
                break;
            }
            if (most <= t_best * f)
                continue; /* cannot rise above the group's best */
            float t = hfs_scale_slope(u_levels, g, u_size, o, sc, h) / f;
            if (!cleared && hfs_scale_takes_over(t, w.t_top, u_tie)) {
                o_clear = o;
                cleared = true;
            }
            t_best = max(t_best, t);
        }
        /* ... by more than the horizons' tie: a rise of a rounding error
         * must not pick the light, nor cast a band (cpu_bounce.c
         * slice_gather). */
        if (cleared)
            cast_band(w, t_best, g, o_clear);
    }
}

#ifdef HFS_SLICE
/* The direct horizon's slope along environment direction je: the grid's
 * far horizon (tan(x / 2) in u_hor) or the own cell's slope t1, whichever
 * is higher. */
float direct_horizon(ivec2 g, int je, vec2 cs, float t1)
{
#ifdef HFS_NEAR
    /* Any texel: the grid's horizons blended at its place (env_slices.frag
     * reads them so), HFS_PAIRS the occluders moved to its height. */
#ifdef HFS_PAIRS
    vec4 o = texture(u_hor, vec3(g_vuv, float(je / 2)));
    float fs = hfs_far_pair_slope(o, je % 2, dot(g_vo, cs), g_vdz, 1.0 / float(u_vsub));
    return max(fs, t1);
#else
    float u = texture(u_hor, vec3(g_vuv, float(je / 4)))[je % 4];
    return max(u > -1.0 ? 2.0 * u / max(1.0 - u * u, 1e-30) : -1e30, t1);
#endif
#else
    /* g is a visibility receiver: a multiple of u_vsub, or the last. */
    ivec2 v = ivec2(g.x == u_size.x - 1 ? u_vsize.x - 1 : g.x / u_vsub,
                    g.y == u_size.y - 1 ? u_vsize.y - 1 : g.y / u_vsub);
#ifdef HFS_PAIRS
    vec4 o = texelFetch(u_hor, ivec3(v, je / 2), 0); /* (height, distance) pairs */
    float h = o[2 * (je % 2)], d = o[2 * (je % 2) + 1];
    return max(d > 0.0 ? h / d : -1e30, t1);
#else
    float u = texelFetch(u_hor, ivec3(v, je / 4), 0)[je % 4];
    return max(u > -1.0 ? 2.0 * u / max(1.0 - u * u, 1e-30) : -1e30, t1);
#endif
#endif
}

/* The clamped cosine's integral between the tangent plane and the direct
 * horizon t_cap of one slice (a = N.d), 0 where the horizon is below it. */
float slice_occluded(float a, float nz, float t_cap)
{
    return t_cap > -a / nz
               ? hfs_slice_cosine(a, nz, atan(-a, nz)) - hfs_slice_cosine(a, nz, atan(t_cap))
               : 0.0;
}

/* The direct light's sub-horizons of environment direction je (cs) at
 * receiver g (normal n) as slopes into t, from its near part tn
 * (direct_horizon): HFS_FARK, each at least its sub-direction's far
 * occluder where that rises above its own tangent plane (env_slices.frag
 * dir_step).  Returns the mean of their slice_occluded. */
float sub_horizons(int je, vec2 cs, vec3 n, float tn, out float t[HFS_NSUB])
{
    float a = n.x * cs.x + n.y * cs.y, occ = 0.0;
#ifdef HFS_FARK
    float ap = n.y * cs.x - n.x * cs.y; /* N.d rotated a quarter turn */
    vec4 fv[HFS_FARH];
#endif
    for (int h = 0; h < HFS_NSUB; ++h) {
#ifdef HFS_FARK
        int e = je * HFS_FARK + h;
        vec2 fuv = hfs_far_tile_uv(g_fpix, float(e / 2), u_fcols, u_fsize, u_fatlas);
        for (int c = 0; c < HFS_FARH && (h == 0 || e % 2 == 0); ++c)
            fv[c] = texture(u_far, vec3(fuv, float(c)));
        float fs = -1e30, shift = dot(g_fo, cs * u_fsub[h].x + vec2(-cs.y, cs.x) * u_fsub[h].y);
        for (int c = 0; c < HFS_FARH; ++c) /* the largest of the heights' (split_horizon.h) */
            fs = max(fs, hfs_far_pair_slope(fv[c], e % 2, shift, g_fdz, 1.0 / float(u_fstep)));
        float plane = -(a * u_fsub[h].x + ap * u_fsub[h].y) / n.z;
        t[h] = clamp(max(tn, fs > plane + 1e-3 * (1.0 + abs(plane)) ? fs : -1e30), -1e18, 1e18);
#else
        t[h] = tn;
#endif
#ifndef HFS_NEAR /* the near pass weighs only its own bands */
        occ += slice_occluded(a, n.z, t[h]);
#endif
    }
    return occ / float(HFS_NSUB);
}

/* The sum of slice_occluded over the environment's directions the bounces
 * skip (the walk adds its own directions'): with the walk's, dphi / pi
 * times it is the receiver's occluded part over pi, what env_slices.frag's
 * T_occ,0 holds per texel, so that their ratio is 1 at a receiver. */
float skipped_occluded(ivec2 g, vec3 n, vec4 ns, vec4 fine, vec2 h0)
{
    float w = 0.0;
    int stride = int(u_bhead.z);
    for (int je = 0; je < HFS_NDIR; ++je) {
        if (je % stride == 0)
            continue;
        vec2 cs = u_edir[je].xy;
        float t1;
        vec2 o1, nf;
        own_cell(g, cs, ns, fine, h0, t1, o1, nf);
        float t[HFS_NSUB];
        w += sub_horizons(je, cs, n, direct_horizon(g, je, cs, t1), t);
    }
    return w;
}
#endif

void main()
{
    ivec2 g = hfs_receiver(u_size, u_sub);
    vec2 hx[HFS_NLAYERS];
    vec4 fine = u_scale[HFS_NLEV - 1];
#ifdef HFS_NEAR
    /* Only the layers the near scales read (the finest, at the defaults). */
    hx[int(fine.z)] = texelFetch(u_levels, ivec3(g, int(fine.z)), 0).xy;
    for (int i = HFS_NLEV - 2; i >= 0 && u_scale[i].x <= u_near_d; --i)
        hx[int(u_scale[i].z)] = texelFetch(u_levels, ivec3(g, int(u_scale[i].z)), 0).xy;
#else
    hfs_receiver_heights(u_levels, g, hx);
#endif
    vec2 h0 = hx[int(fine.z)];
#ifdef HFS_FARK
    vec2 tf; /* where the receiver reads the grids (off a wall: hfs_grid_snap) */
    g_fdz = hfs_grid_rise(u_levels, g, u_fstep, u_size, fine, tf, g_fo);
    g_fpix = hfs_grid_pix_at(g, u_fstep, tf);
#endif
#ifdef HFS_NEAR
    g_vuv = hfs_grid_uv(g, u_vsub, u_size, u_vsize);
#ifdef HFS_PAIRS
    vec2 tv;
    g_vdz = hfs_grid_rise(u_levels, g, u_vsub, u_size, fine, tv, g_vo);
    g_vuv = hfs_grid_uv_at(g, u_vsub, tv, u_vsize);
#endif
#endif
    /* the normal and the one-sided slopes to (+x, -x, +y, -y), -1e30 off
     * the field, from the 4 neighbours' heights read once (the finest
     * scale reads the heights' layer, u_height's) */
    vec4 side;
    bvec4 side_on;
    vec3 n = hfs_normal_sides(u_height, g, u_size, u_zf, h0, side, side_on);
    vec4 ns = mix(vec4(-1e30), side * fine.y * fine.x, side_on);
    vec3 acc = vec3(0.0), acc_near = vec3(0.0);
    float w_occ = 0.0; /* slice_occluded summed over the environment's directions */
    float w_near = 0.0; /* the near bands' weights */
#ifdef HFS_GLOSSY
    /* R at the receiver (gloss.h hfs_gloss_reflect); nv <= 0: no lobe. */
    vec3 view = u_gview.xyz;
#if HFS_GLOSSY == 2
    vec3 d = u_geye.xyz - vec3(vec2(g), u_ghgt.z * (u_ghgt.x + u_ghgt.y * hfs_h(h0)));
    view = length(d) > 0.0 ? normalize(d) : vec3(0.0, 0.0, 1.0);
#endif
    float nv = dot(n, view);
    vec3 r = 2.0 * nv * n - view;
    vec3 gacc = vec3(0.0);
#endif
    for (int j = 0; j < HFS_NBDIR; ++j) {
        int je = j * int(u_bhead.z); /* the environment's direction */
        vec2 cs = u_edir[je].xy;
        Walk w;
        w.a = n.x * cs.x + n.y * cs.y;
        w.b = n.z;
        w.t_top = -w.a / n.z; /* the tangent plane */
        w.s_top = hfs_slice_cosine(w.a, w.b, atan(-w.a, n.z));
        w.t_cap = 1e30;
        w.acc = vec3(0.0);
        w.last = vec3(0.0);
        w.near = u_near_d > 0.0; /* the own cell: near, when there is a near part */
        w.acc_near = vec3(0.0);
        w.w_near = 0.0;
        float s0 = w.s_top;
#ifdef HFS_GLOSSY
        w.l = vec4(dot(r.xy, cs), r.z, w.a, w.b);
        float rho = length(w.l.xy);
        w.sup = vec2(1.0, 0.0);
        if (nv > 0.0 && rho > u_gpar.z) {
            float eps = atan(w.l.y, w.l.x), u = acos(u_gpar.z / rho);
            w.sup = vec2(eps - u, eps + u);
        }
        w.gacc = vec3(0.0);
#endif
        /* The caps: the direct horizons (the own cell's among them), then
         * the own cell's band. */
        float t1;
        vec2 o1, nf;
        bool cell = own_cell(g, cs, ns, fine, h0, t1, o1, nf);
#ifdef HFS_SLICE
        float tc[HFS_NSUB];
        float occ = sub_horizons(je, cs, n, direct_horizon(g, je, cs, t1), tc);
        w.t_cap = w.t_top;
        for (int h = 0; h < HFS_NSUB; ++h) {
            bool above = tc[h] > w.t_top; /* the tangent plane */
            w.s_cap[h] = above ? hfs_slice_cosine(w.a, w.b, atan(tc[h])) : s0;
#ifdef HFS_GLOSSY
            w.x_cap[h] = above ? atan(tc[h]) : -1e30;
#endif
            w.t_cap = max(w.t_cap, tc[h]);
        }
#endif
        if (cell && u_sub > 1 && !(u_near_d > 0.0)) {
            /* A sub-sampled grid: the band takes the far edge's light.
             * The receiver's own light would stand for the texels between
             * receivers, whose own cells differ (issue 36: measured worse
             * on the DEM, the fractal and the cones at the defaults, with
             * and without that part lit per texel by its own light). */
            cast_band(w, t1, g, o1);
        } else if (cell) {
            /* Below the near end's slope the ray meets the cell at once:
             * the receiver's own radiance; the rest (a twisted cell) where
             * the ray at its middle elevation meets it; each part only
             * where it rises by more than the tie (cpu_bounce.c
             * slice_gather). */
            if (hfs_scale_takes_over(nf.x, w.t_top, u_tie))
                cast_band(w, nf.x, g, vec2(0.0));
            float e = min(nf.y, w.t_cap);
            if (hfs_scale_takes_over(nf.y, max(nf.x, w.t_top), u_tie) && e > w.t_top) {
                float u = tan(0.5 * (atan(w.t_top) + atan(e)));
                float tc = 1.0 / max(abs(cs.x), abs(cs.y));
                float tx = clamp(tc * (u - nf.x) / (nf.y - nf.x), 0.0, tc);
                cast_band(w, e, g, cs * tx);
            }
        }
        walk_scales(w, g, cs, hx);
        w.near = false;
#if defined(HFS_SLICE) && !defined(HFS_NEAR)
        /* The terrain reaches the direct horizons, which the sparser walk
         * may not (a peak between its samples): the last band's radiance
         * fills the rest up to each (cpu_bounce.c slice_gather). */
        if (w.s_top < s0 && w.t_top < w.t_cap) {
            float wl;
            w.acc += w.last * band_weight(w, -1e30, 1e30, wl);
#ifdef HFS_GLOSSY
            w.gacc += w.last * wl;
#endif
        }
        w_occ += occ;
#endif
        acc += w.acc;
        acc_near += w.acc_near;
        w_near += w.w_near;
#ifdef HFS_GLOSSY
        gacc += w.gacc;
#endif
    }
#ifdef HFS_NEAR
    /* The near part alone. */
    acc = acc_near;
    w_occ = w_near * u_bhead.x;
#elif defined(HFS_SLICE)
    w_occ = (w_occ + skipped_occluded(g, n, ns, fine, h0)) * (2.0 / float(HFS_NDIR));
    /* With a near part the grid keeps the rest (acc: no near band in it). */
    w_occ = max(w_occ - w_near * u_bhead.x, 0.0);
#else
    acc += acc_near;
#endif
    /* not clamped at 0: Lo_{b-1} as it is (SPEC; DESIGN.md "Indirect light") */
    vec3 e = acc * u_bhead.x;
    e = clamp(e, vec3(-65504.0), vec3(65504.0));
    o_e = vec4(mix(vec3(0.0), e, equal(e, e)), clamp(w_occ, 0.0, 1.0));
#ifdef HFS_GLOSSY
    vec3 gs = clamp(gacc * u_gview.w, vec3(-65504.0), vec3(65504.0));
    o_g = vec4(mix(vec3(0.0), gs, equal(gs, gs)), 0.0);
#endif
}
