/*
 * key_horizons.frag - key-light horizons on a swath (DESIGN.md "Horizons": the
 * B-spline max over scale).  One fragment per receiver of the visibility
 * grid; directions [u_dir0, u_dir0 + u_ndir) of the light's swath, one per
 * RGBA target, up to HFS_NOUT targets.  Per direction it writes
 *   (omega hi, omega lo, D, 0) at subsample 1, (tan omega hi, lo, D, 0)
 *   on a sub-sampled grid (omega clamped to +-HFS_KEY_TAN_ANGLE there):
 * the horizon as an fp16 (hi, lo) pair (a key light's narrow elevation
 * window, a few degrees, must not see fp16's 2^-11 rounding of the angle),
 * and D, the distance in texels at which the B-spline max was reached (a
 * knot's scale d_i, or the geometric mean of a midpoint's two; tracked as
 * the code c = 2 (N-1-i) + 1 of knot i and c = 2 (N-1-i) of the midpoint
 * between i and i + 1, D = 2^((c - 1) / 2k)), rounded to fp16 in every
 * precision so that fp16 and fp32 frames correct alike; D = 0 where no
 * scale's sample lies on the grid.  The max starts below every
 * tangent plane (off-grid samples still enter the B-spline as the floor),
 * so a texel whose own plane lies lower still finds the occluder; on a
 * sub-sampled grid the u_near finest scales are left to the factor pass,
 * which searches them per texel.  The key factor
 * pass (key_visibility.frag) takes max(its own floor, omega) at subsample 1;
 * between grid receivers it moves each neighbour's occluder, at height
 * tan(omega) D above that receiver and D ahead of it, to the texel's own
 * height and position (DESIGN.md "GLES path", "Key lights on the 2x2
 * grid").
 *
 * Per scale omega_i = atan(D_i) in-grid and the floor off-grid; scales run
 * fine to coarse and stop fetching at the first off-grid sample (all
 * farther ones are off-grid too and contribute the floor).  The receiver's
 * own heights are fetched once per level.
 *
 * HFS_COUNT: writes the fetch count to o_h0 instead (see env_horizons.frag).
 */
// hfs-base: HFS_CELLS 1
// hfs-variant: HFS_NOUT 4
// hfs-variant: HFS_FP32 1, HFS_COUNT 1
// hfs-variant: HFS_SWATH_TEX 1

#ifndef HFS_SCALES_MAX
#define HFS_SCALES_MAX 256
#endif
#ifndef HFS_NLAYERS
#define HFS_NLAYERS 25
#endif
#ifndef HFS_NDIR
#define HFS_NDIR 3
#endif
#ifndef HFS_NOUT
#define HFS_NOUT 1
#endif

#ifndef HFS_HALF_PI
#define HFS_HALF_PI 1.5707963267948966
#endif
/* Horizons stored as tangents are clamped to this elevation (tan < 1e4). */
#define HFS_KEY_TAN_ANGLE 1.5706963

precision highp float;
precision highp int;
precision highp sampler2D;
precision highp sampler2DArray;

vec3 hfs_normal_at(highp sampler2DArray h, ivec2 p, ivec2 size, float zf);
vec2 hfs_split(float v);
float hfs_half_nearest(float v);
ivec2 hfs_receiver(ivec2 size, int sub);
void hfs_receiver_heights(highp sampler2DArray levels, ivec2 g, out vec2 hx[HFS_NLAYERS]);
float hfs_floor(vec3 n, vec2 cs);
bool hfs_scale_offset(ivec2 g, ivec2 size, float d, vec2 cs, out vec2 o);
float hfs_scale_slope(highp sampler2DArray levels, ivec2 g, ivec2 size, vec2 o, vec4 sc, vec2 h);
void hfs_bspline_push_at(inout float best, inout float bd, inout vec4 w, float a, int i,
                         int n, float dk, float dm);
void hfs_bspline_close_at(inout float best, inout float bd, vec4 w, int n, float dk,
                          float dm);
bool hfs_scale_takes_over(float sl, float ref, float tie);
float hfs_refine_about(highp sampler2DArray levels, ivec2 g, ivec2 size, vec2 cs, vec4 sc,
                       vec2 h, int n, float k, float best, inout float dist, inout int fetches);
#define HFS_RAY_LEVELS 16
float hfs_gap_search_cells(highp sampler2DArray heights, highp sampler2D bounds,
                           ivec2 at[HFS_RAY_LEVELS], ivec2 size, ivec2 g, vec2 cs, float t_first,
                           float t_last, float zf, float tie, vec2 h0, float best, float stop,
                           inout float dist, inout int fetches);

uniform highp sampler2DArray u_levels;
uniform ivec2 u_size;
uniform int u_sub;
uniform int u_dir0;                      /* first direction of this pass */
uniform int u_ndir;                      /* directions in this pass, <= HFS_NOUT */
uniform int u_near;                      /* finest scales left to key_visibility.frag */
uniform float u_lk;                      /* the pyramid's levels per octave k */
uniform int u_refine;                    /* samples refining the max between scales; 0: B-spline */
uniform float u_tie;                     /* hfs_horizon_tie_slope */
/* The gap search (runtime/core/ray_bound.h) after the refined max: the
 * max pyramid's atlas, its levels' corners, the slope per normalized
 * height and texel (hscale zscale / dx), and where the search starts
 * (where the grid's scales start: the near ones are the texels'). */
uniform highp sampler2DArray u_height;   /* the heights (hi, lo), layer u_hlayer */
uniform highp sampler2D u_bounds;
uniform ivec2 u_rb_at[HFS_RAY_LEVELS];
uniform float u_zf;
uniform float u_gap_from;

layout(std140) uniform HfsScales {
    ivec4 u_nscales;                     /* (N: the scales, 0, 0, 0) */
    vec4 u_scale[HFS_SCALES_MAX];
};
#define HFS_NLEV (u_nscales.x)           /* the scale count: a uniform */
#ifdef HFS_SWATH_TEX
/* The swath from a texture (too large for a uniform block): this light's
 * starts at vec4 u_swath_base. */
vec4 hfs_block_vec4(highp usampler2D t, int i);
uniform highp usampler2D u_swath_tex;
uniform int u_swath_base;
#define SW_DIR(j) hfs_block_vec4(u_swath_tex, u_swath_base + 2 + (j))
#else
layout(std140) uniform HfsSwath {        /* the light's swath (prefix) */
    vec4 u_win;
    vec4 u_occtop;
    vec4 u_dir[HFS_NDIR];
};
#define SW_DIR(j) u_dir[j]
#endif

layout(location = 0) out vec4 o_h0;
#if HFS_NOUT > 1
layout(location = 1) out vec4 o_h1;
#endif
#if HFS_NOUT > 2
layout(location = 2) out vec4 o_h2;
#endif
#if HFS_NOUT > 3
layout(location = 3) out vec4 o_h3;
#endif

/* SN08's B-spline max over scale (u_refine 0): per-scale angles from fine
 * to coarse into the B-spline max.  Past the grid every angle is the
 * floor: three more steps flush the window, then nothing can exceed the
 * floor any more.  The max starts below every tangent plane; *dist is the
 * winning knot's (or midpoint's) distance. */
float bspline_horizon(ivec2 g, vec2 cs, float fl, vec2 hx[HFS_NLAYERS], inout int fetches,
                      out float dist, out bool seen)
{
    float best = -HFS_HALF_PI, bd = 0.0;
    seen = false;
    vec4 w = vec4(fl);
    int tail = 3;
    int top = HFS_NLEV - 1 - u_near;
    int i = top;
    for (; i >= 0; --i) {
        float a = fl;
        if (tail == 3) {
            vec4 sc = u_scale[i];
            vec2 o;
            if (!hfs_scale_offset(g, u_size, sc.x, cs, o)) {
                --tail;
            } else {
                a = atan(hfs_scale_slope(u_levels, g, u_size, o, sc, hx[int(sc.z)]));
                seen = true;
                ++fetches;
            }
        } else if (--tail < 0) {
            break;
        }
        if (i < top) {
            float c = float(2 * (HFS_NLEV - 2 - i));
            hfs_bspline_push_at(best, bd, w, a, i, HFS_NLEV, c + 1.0, c);
        } else {
            w = vec4(a);
        }
    }
    if (i < 0 && top >= 0) {
        float c = float(2 * (HFS_NLEV - 1));
        hfs_bspline_close_at(best, bd, w, HFS_NLEV, c + 1.0, c);
    }
    dist = exp2((bd - 1.0) / (2.0 * u_lk));
    return best;
}

/* The max refined between scales (u_refine > 0; cpu_horizon.c
 * hfs_horizon_refined): the plain max of the scales' slopes from fine
 * to coarse (the first scale off the grid contributes the floor, and every
 * coarser one is off the grid too), then u_refine samples about the finest
 * scale t holding it (hfs_scale_takes_over, hfs_refine_about), then the
 * gap search from u_gap_from (hfs_gap_search_cells: every crossing of the
 * ray with the grid's lines, and every cell between, that could beat it).  Slopes, not angles, are
 * compared: one atan. */
float refined_horizon(ivec2 g, vec2 cs, vec3 n, float fl, vec2 hx[HFS_NLAYERS],
                      inout int fetches, out float dist, out bool seen)
{
    /* The floor's slope from the normal, not tan(fl): past slopes of ~1e7
     * fl rounds to float's +-pi/2, which lies beyond +-pi/2, and its tan
     * has the other sign (a plane falling steeply away from the light
     * became a wall towards it: the texel dark at subsample 1). */
    float tfl = clamp(-(n.x * cs.x + n.y * cs.y) / n.z, -1e30, 1e30);
    float best = -3e38, ref = 0.0;       /* the max; the slope at bi */
    int bi = -1;
    seen = false;
    for (int i = HFS_NLEV - 1 - u_near; i >= 0; --i) {
        vec4 sc = u_scale[i];
        vec2 o;
        float sl = tfl;
        bool in_grid = hfs_scale_offset(g, u_size, sc.x, cs, o);
        if (in_grid) {
            sl = hfs_scale_slope(u_levels, g, u_size, o, sc, hx[int(sc.z)]);
            seen = true;
            ++fetches;
        }
        if (bi < 0 || hfs_scale_takes_over(sl, ref, u_tie)) {
            ref = sl;
            bi = i;
        }
        best = max(best, sl);
        if (!in_grid)
            break;
    }
    if (bi < 0) {
        dist = 0.0;
        return fl;
    }
    vec4 sc = u_scale[bi];
    dist = sc.x;
    best = hfs_refine_about(u_levels, g, u_size, cs, sc, hx[int(sc.z)], u_refine, u_lk, best,
                            dist, fetches);
    /* and every band between the scales: no narrow occluder is stepped over */
    best = hfs_gap_search_cells(u_height, u_bounds, u_rb_at, u_size, g, cs, u_gap_from, 1e9, u_zf,
                          u_tie, hx[HFS_NLAYERS - 1], best, 1e30, dist, fetches);
    return atan(best);
}

void main()
{
    ivec2 g = hfs_receiver(u_size, u_sub);
    vec3 n = hfs_normal_at(u_height, g, u_size, u_zf);
    vec2 hx[HFS_NLAYERS];
    hfs_receiver_heights(u_levels, g, hx);
    int fetches = 4 + HFS_NLAYERS; /* the normal's 4 heights, the receiver's layers */

    vec4 res[HFS_NOUT];
    for (int q = 0; q < HFS_NOUT; ++q)
        res[q] = vec4(0.0);

    for (int q = 0; q < u_ndir; ++q) {
        vec2 cs = SW_DIR(u_dir0 + q).xy;
        float fl = hfs_floor(n, cs), dist;
        bool seen;
        float best = u_refine > 0 ? refined_horizon(g, cs, n, fl, hx, fetches, dist, seen)
                                  : bspline_horizon(g, cs, fl, hx, fetches, dist, seen);
        best = clamp(best, -HFS_HALF_PI, HFS_HALF_PI);
        float stored = u_near > 0 ? tan(clamp(best, -HFS_KEY_TAN_ANGLE, HFS_KEY_TAN_ANGLE)) : best;
        /* D rounded to fp16 whatever the targets hold, so that fp16 and
         * fp32 frames correct with the same distance */
        dist = hfs_half_nearest(dist);
        res[q] = vec4(hfs_split(stored), seen ? dist : 0.0, 0.0);
    }
#ifdef HFS_COUNT
    o_h0 = vec4(float(fetches % 1024), float(fetches / 1024), 0.0, 0.0);
#if HFS_NOUT > 1
    o_h1 = vec4(0.0);
#endif
#if HFS_NOUT > 2
    o_h2 = vec4(0.0);
#endif
#if HFS_NOUT > 3
    o_h3 = vec4(0.0);
#endif
#else
    o_h0 = res[0];
#if HFS_NOUT > 1
    o_h1 = res[1];
#endif
#if HFS_NOUT > 2
    o_h2 = res[2];
#endif
#if HFS_NOUT > 3
    o_h3 = res[3];
#endif
#endif
}
