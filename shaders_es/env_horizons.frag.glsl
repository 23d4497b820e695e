/*
 * env_horizons.frag - environment visibility on the full swath (DESIGN.md
 * "Horizons", "Visibility to SH", "GLES path").  One fragment per receiver
 * of the visibility grid (grid point min(a*sub, W-1)); writes the 16 SH
 * coefficients of V_env to four RGBA targets.
 *
 * Horizons (fast path): per direction, omega = max(floor, atan(max_i D_i))
 * over in-grid scales, D_i = (R_L(p_i) - R_L(x)) * inv_run_i.  Fetches are
 * cut three ways, none of which changes the result:
 *   - R_L(x), the receiver's own height per level, does not depend on the
 *     direction: fetched once per level before the direction loop;
 *   - scales run fine to coarse (growing distance) and stop at the first
 *     off-grid sample: the grid is convex, so all farther ones are off too;
 *   - a sample whose best case (the field's largest height, u_vmax) cannot
 *     beat the running max (started at tan(floor)) is skipped without a
 *     fetch.  (A local max-mip bound was measured and rejected: even per
 *     direction it skips only ~12% of the samples on the test terrains,
 *     less than the bound fetches cost; DESIGN.md "GLES path".)
 * Visibility: Legendre + folded M_lin (V += C_j v_j, hfs_visibility_sample_
 * matrix), or with HFS_TABLES the SN08 wedge tables (2D table per wedge,
 * placed by a z-rotation).  Written: V_env minus the hemisphere above the
 * receiver's tangent plane (hfs_sh_hemisphere), which the shading pass adds
 * back at each texel's own normal: on a sub-sampled grid the part of V that
 * only follows the normal is then exact at every texel, and only the
 * terrain's occlusion is interpolated.
 *
 * HFS_SLICE (exact slice lighting, runtime/core/slice_light.h): instead of V,
 * the horizons themselves (as tan(omega / 2)), four per target (a layer
 * each of the grid's horizon array), HFS_NOUT targets from direction
 * u_dir0; with HFS_PAIRS (a sub-sampled grid) each horizon's occluder,
 * two per target (write_horizons).  The full-resolution pass
 * env_slices.frag integrates them with each texel's own normal.  On a sub-sampled grid the u_near finest scales are left to
 * that pass too (they differ from texel to texel), and the search starts
 * below any tangent plane, since the receivers that read it have their own.
 *
 * Split horizons (runtime/core/split_horizon.h): the near pass searches only
 * the scales from u_coarsest in.  HFS_FAR_ATLAS 1 is the far pass
 * (env_far_grid.c): on the far grid (receivers u_sub apart, u_fgrid of
 * them), laid out as an atlas of tiles, tile i holding sub-directions 2i
 * and 2i + 1 (u_fcols tiles a row) so that one draw covers them all (one
 * small draw per group would run on one thread of a tiled rasterizer); it
 * skips the u_near near scales and writes each occluder as a pair.
 *
 * HFS_COUNT: instead of V, write the number of texture fetches made
 * (o_v0 = (count mod 1024, floor(count / 1024), 0, 0)), for measurement.
 */
// hfs-variant: HFS_TABLES 1
// hfs-variant: HFS_FP32 1, HFS_COUNT 1
// hfs-variant: HFS_SWATH_TEX 1
// hfs-variant: HFS_SWATH_TEX 1, HFS_TABLES 1
// hfs-variant: HFS_SLICE 1
// hfs-variant: HFS_SLICE 1, HFS_SWATH_TEX 1
// hfs-variant: HFS_SLICE 1, HFS_PAIRS 1
// hfs-variant: HFS_SLICE 1, HFS_PAIRS 1, HFS_NOUT 6
// hfs-variant: HFS_SLICE 1, HFS_NOUT 8
// hfs-variant: HFS_SLICE 1, HFS_COUNT 1
// hfs-variant: HFS_SLICE 1, HFS_FAR_ATLAS 1, HFS_NOUT 1
// hfs-variant: HFS_SLICE 1, HFS_FAR_ATLAS 1, HFS_NOUT 1, HFS_SWATH_TEX 1
// hfs-variant: HFS_SLICE 1, HFS_FAR_ATLAS 1, HFS_NOUT 1, HFS_COUNT 1
// hfs-variant: HFS_SLICE 1, HFS_FAR_ATLAS 1, HFS_NOUT 3

#ifndef HFS_SCALES_MAX
#define HFS_SCALES_MAX 256
#endif
#ifndef HFS_NLAYERS
#define HFS_NLAYERS 25
#endif
#ifndef HFS_NDIR
#define HFS_NDIR 32
#endif
#ifndef HFS_NOUT
#define HFS_NOUT 4                       /* targets: 4, or on the slice path 1 to 8 */
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

float hfs_h(vec2 t);
float hfs_hdiff(vec2 a, vec2 b);
vec3 hfs_normal_at(highp sampler2DArray h, ivec2 p, ivec2 size, float zf);
ivec2 hfs_receiver(ivec2 size, int sub);
void hfs_receiver_heights(highp sampler2DArray levels, ivec2 g, out vec2 hx[HFS_NLAYERS]);
bool hfs_scale_offset(ivec2 g, ivec2 size, float d, vec2 cs, out vec2 o);
bool hfs_ray_box(vec2 p, vec2 cs, vec4 box, float t_max, out vec2 t);
float hfs_scale_slope(highp sampler2DArray levels, ivec2 g, ivec2 size, vec2 o, vec4 sc, vec2 h);
bool hfs_scale_takes_over(float sl, float ref, float tie);
float hfs_refine_about(highp sampler2DArray levels, ivec2 g, ivec2 size, vec2 cs, vec4 sc,
                       vec2 h, int n, float k, float best, inout float dist, inout int fetches);
vec4 hfs_nlp_occ_tan(float t);
vec4 hfs_f16v(vec4 v);
void hfs_sh_hemisphere(vec3 n, out vec4 h[4]);
float hfs_table_coord(float omega, float n);
float hfs_pair_h(float h);
void hfs_table_add(highp sampler2DArray tab, vec2 uv, float layer0, bool mirror, vec3 c,
                   vec3 s, inout vec4 V[4]);

uniform highp sampler2DArray u_levels;   /* R_L, layer L - lmin, RG hi+lo, LINEAR */
uniform highp sampler2DArray u_height;   /* heights (hi, lo), layer u_hlayer: normals, gap search */
uniform float u_zf;                      /* hscale zscale / dx, clamped to 1e30 */
#ifdef HFS_TABLES
uniform highp sampler2DArray u_tab;      /* interior table, 4 layers (k/4) */
#endif
uniform ivec2 u_size;                    /* W, H */
uniform int u_sub;                       /* visibility grid step */
uniform float u_vmax;                    /* largest normalized height, a hair up */

layout(std140) uniform HfsScales {
    ivec4 u_nscales;                     /* (N: the scales, 0, 0, 0) */
    vec4 u_scale[HFS_SCALES_MAX];        /* (d_i, inv_run_i, layer, 0) */
};
#define HFS_NLEV (u_nscales.x)           /* the scale count: a uniform */
uniform int u_refine;                    /* samples refining the max between scales */
uniform float u_lk;                      /* the pyramid's levels per octave k */
uniform float u_tie;                     /* hfs_horizon_tie_slope */
#ifdef HFS_SLICE
uniform int u_dir0;                      /* first direction of this draw */
uniform int u_near;                      /* finest scales left to env_slices.frag
                                            (the far pass: the near ones) */
#endif
uniform int u_coarsest;                  /* coarsest scale searched: split horizons'
                                            near part stops at far-from (0: all) */
#ifdef HFS_FAR_ATLAS
uniform ivec2 u_fgrid;                   /* the far grid's receivers (a tile) */
uniform int u_fcols;                     /* tiles a row of the atlas */
/* The gap search (runtime/core/ray_bound.h) from far-from on: the max
 * pyramid's atlas, its levels' corners, the slope per normalized height
 * and texel, and far-from. */
#define HFS_RAY_LEVELS 16
float hfs_gap_search(highp sampler2DArray heights, highp sampler2D bounds, ivec2 at[HFS_RAY_LEVELS],
                     ivec2 size, ivec2 g, vec2 cs, float t_first, float t_last, float zf, float tie,
                     vec2 h0, float best, float stop, inout float dist, inout int fetches);
uniform highp sampler2D u_bounds;
uniform ivec2 u_rb_at[HFS_RAY_LEVELS];
uniform float u_gap_from;
/* After an edit of the heights (runtime/gles/edit_frame.c): u_edit 1 draws
 * only the texels whose search can end differently and leaves the others
 * as the last frame left them.  u_edit_box: the changed texels (x0, y0,
 * x1, y1), inclusive; per layer, how far a read's footprint reaches
 * (u_edit_reach) and the highest value a read reaching them can take,
 * before or after (u_edit_top); and the largest of each. */
uniform int u_edit;
uniform vec4 u_edit_box;
uniform float u_edit_reach[HFS_NLAYERS];
uniform float u_edit_top[HFS_NLAYERS];
uniform float u_edit_reach_max;
uniform float u_edit_top_max;
#endif
#ifdef HFS_SWATH_TEX
/* The same data from a texture (too large for a uniform block): vec4 i of
 * the block below is SW(i). */
vec4 hfs_block_vec4(highp usampler2D t, int i);
uniform highp usampler2D u_swath_tex;
#define SW(i) hfs_block_vec4(u_swath_tex, (i))
#define SW_OCCTOP SW(1)
#define SW_DIR(j) SW(2 + (j))
#define SW_C(k) mat4(SW(2 + HFS_NDIR + 4 * (k)), SW(3 + HFS_NDIR + 4 * (k)), \
                     SW(4 + HFS_NDIR + 4 * (k)), SW(5 + HFS_NDIR + 4 * (k)))
#define SW_ROT(i) SW(2 + 17 * HFS_NDIR + (i))
#else
layout(std140) uniform HfsSwath {
    vec4 u_win;                          /* (elev_lo, elev_hi, n, full) */
    vec4 u_occtop;
    vec4 u_dir[HFS_NDIR];                /* (cos, sin, 0, 0) */
#ifdef HFS_SLICE
    vec4 u_coef[16];                     /* read by env_slices.frag */
    vec4 u_nearw[3 * HFS_NDIR];
    vec4 u_trig[HFS_NDIR];
#else
    mat4 u_C[HFS_NDIR * 4];              /* folded M_lin, rows as columns */
    vec4 u_rot[2 * HFS_NDIR + 2];        /* per wedge (cos ma, mirror), (sin ma) */
#endif
};
#define SW_OCCTOP u_occtop
#define SW_DIR(j) u_dir[j]
#define SW_C(k) u_C[k]
#define SW_ROT(i) u_rot[i]
#endif

layout(location = 0) out vec4 o_v0;
layout(location = 1) out vec4 o_v1;
layout(location = 2) out vec4 o_v2;
layout(location = 3) out vec4 o_v3;
#if HFS_NOUT > 4
layout(location = 4) out vec4 o_v4;
#endif
#if HFS_NOUT > 5
layout(location = 5) out vec4 o_v5;
#endif
#if HFS_NOUT > 6
layout(location = 6) out vec4 o_v6;
#endif
#if HFS_NOUT > 7
layout(location = 7) out vec4 o_v7;
#endif

#ifdef HFS_TABLES
/* V += placement of the interior wedge table(a, b). */
void add_wedge(inout vec4 V[4], float a, float b, int w)
{
    float n = float(HFS_TABLE_N);
    hfs_table_add(u_tab, vec2(hfs_table_coord(a, n), hfs_table_coord(b, n)), 0.0, false,
                  SW_ROT(2 * w).xyz, SW_ROT(2 * w + 1).xyz, V);
}
#endif


/* The largest slope tan(omega) in direction cs over the scales from
 * `first` (finest searched) to the coarsest in the grid, not below `best`,
 * then (u_refine > 0) over u_refine samples about the scale holding it
 * (cpu_horizon.h hfs_horizon_refined, seeded with `best`: a scale takes
 * over when it beats the current one by more than the tie); counts its
 * fetches.  A scale whose largest possible slope cannot beat `best` is
 * skipped: it could not take over either. */
float horizon_tan(ivec2 g, vec2 cs, vec2 hx[HFS_NLAYERS], float best, int first,
                  inout int fetches, out float dist)
{
    float ref = best;
    int bi = first;
    dist = 0.0;
    for (int i = first; i >= u_coarsest; --i) {
        vec4 sc = u_scale[i];
        vec2 o;
        if (!hfs_scale_offset(g, u_size, sc.x, cs, o))
            break;
        vec2 h = hx[int(sc.z)];
        if ((u_vmax - hfs_h(h)) * sc.y <= best)
            continue;
        float sl = hfs_scale_slope(u_levels, g, u_size, o, sc, h);
        ++fetches;
        if (hfs_scale_takes_over(sl, ref, u_tie)) {
            ref = sl;
            bi = i;
        }
        if (sl > best) {
            /* the distance moves only past the tie (as ray_bound.c's), so
             * that float and double name the same sample where slopes tie */
            if (hfs_scale_takes_over(sl, best, u_tie))
                dist = sc.x;
            best = sl;
        }
    }
    if (bi < 0)
        return best;
    vec4 sc = u_scale[bi];
    return hfs_refine_about(u_levels, g, u_size, cs, sc, hx[int(sc.z)], u_refine, u_lk, best,
                            dist, fetches);
}

/* The HFS_NOUT targets' texels out. */
void write_outputs(vec4 res[HFS_NOUT])
{
    o_v0 = res[0];
#if HFS_NOUT > 1
    o_v1 = res[1];
#endif
#if HFS_NOUT > 2
    o_v2 = res[2];
#endif
#if HFS_NOUT > 3
    o_v3 = res[3];
#endif
#if HFS_NOUT > 4
    o_v4 = res[4];
#endif
#if HFS_NOUT > 5
    o_v5 = res[5];
#endif
#if HFS_NOUT > 6
    o_v6 = res[6];
#endif
#if HFS_NOUT > 7
    o_v7 = res[7];
#endif
}

/* The fetch count (HFS_COUNT) in place of the pass's output. */
void write_count(int fetches)
{
    vec4 res[HFS_NOUT];
    for (int t = 0; t < HFS_NOUT; ++t)
        res[t] = vec4(0.0);
    res[0] = vec4(float(fetches % 1024), float(fetches / 1024), 0.0, 0.0);
    write_outputs(res);
}

#ifdef HFS_SLICE
#ifdef HFS_PAIRS
#define HFS_PER_TARGET 2
#else
#define HFS_PER_TARGET 4
#endif
#define HFS_PER_DRAW (HFS_NOUT * HFS_PER_TARGET)

/* Target t's texel: 4 horizons, or 2 (height, distance) pairs. */
vec4 target(int t, vec2 om[HFS_PER_DRAW])
{
#ifdef HFS_PAIRS
    return hfs_f16v(vec4(om[2 * t], om[2 * t + 1]));
#else
    return hfs_f16v(vec4(om[4 * t].x, om[4 * t + 1].x, om[4 * t + 2].x, om[4 * t + 3].x));
#endif
}

/* Slice path: HFS_NOUT x 4 horizons as tan(omega / 2) (bounded,
 * monotonic in omega, and rational in cos, sin omega; -1 where nothing
 * rises, and past the swath's last direction), or (HFS_PAIRS) HFS_NOUT x 2
 * occluders, each as its height over the receiver (in u_hunit texels,
 * gles_lib.frag hfs_pair_h) and its distance, in texels (-3e4 and 0 where there is
 * none): env_slices.frag blends them
 * and moves them to each texel's height. */
void write_horizons(ivec2 g, vec3 n, vec2 hx[HFS_NLAYERS], int fetches)
{
    vec2 om[HFS_PER_DRAW];
    for (int q = 0; q < HFS_PER_DRAW; ++q) {
        om[q] = vec2(-1.0, 0.0);
        int j = u_dir0 + q;
        if (j >= HFS_NDIR)
            continue;
        vec2 cs = SW_DIR(j).xy;
        /* A receiver that is its own grid point starts at its tangent
         * plane (a slope below it never wins); the others below any. */
        float best = u_sub == 1 ? -(n.x * cs.x + n.y * cs.y) / n.z : -1e30;
        float dist;
        best = horizon_tan(g, cs, hx, best, HFS_NLEV - 1 - u_near, fetches, dist);
#ifdef HFS_PAIRS
        /* the occluder's height over the receiver, and its distance: from
         * the slope as found (at most u_zf, 1e30, times a height: finite),
         * not clamped as a slope, which cut walls steeper than 1e18 down
         * to 1e18 times their distance (as cpu_far_grid.c stores it) */
        om[q] = dist > 0.0 ? vec2(hfs_pair_h(best * dist), dist) : vec2(-3e4, 0.0);
#else
        best = clamp(best, -1e18, 1e18); /* 1 + best^2 finite */
        om[q].x = best / (1.0 + sqrt(1.0 + best * best)); /* tan(omega / 2) */
#endif
    }
#ifdef HFS_COUNT
    write_count(fetches);
#else
    vec4 res[HFS_NOUT];
    for (int t = 0; t < HFS_NOUT; ++t)
        res[t] = target(t, om);
    write_outputs(res);
#endif
}
#endif

#ifdef HFS_FAR_ATLAS
bool edit_near(vec2 q, float r)
{
    return all(greaterThanEqual(q, u_edit_box.xy - r)) &&
           all(lessThanEqual(q, u_edit_box.zw + r));
}

/* The largest slope from height hz at g along cs of anything within r of
 * the edit's box as high as top: the slab test's entry (a rise) or exit
 * (a fall); -1e30 where the ray misses it. */
float edit_ray_bound(ivec2 g, vec2 cs, float r, float top, float hz)
{
    vec2 t;
    if (!hfs_ray_box(vec2(g), cs, u_edit_box + vec4(-r, -r, r, r), 1e9, t))
        return -1e30;
    float dz = (top - hz) * u_zf;
    return dz / max(dz >= 0.0 ? t.x : t.y, 1e-6);
}

/* Whether the far search from g along cs (horizon_tan from scale `first`,
 * its refinement, then the gap search) can end differently after the edit
 * (DESIGN.md "Local edits"): each sample it reads is either clean or, old
 * and new, below the best the search holds when it gets there - a no-op
 * (it neither raises the best nor takes the lead: the lead is never more
 * than the tie below the best) - so the bests of the clean scales met
 * before a changed sample bound what it must stay below.  The refinement
 * and the crossings come after every scale. */
bool far_edit_changes(ivec2 g, vec2 cs, vec2 hx[HFS_NLAYERS], int first)
{
    float lb = -1e30; /* the clean scales' best so far */
    for (int i = first; i >= 0; --i) {
        vec4 sc = u_scale[i];
        vec2 o;
        if (!hfs_scale_offset(g, u_size, sc.x, cs, o))
            break;
        int l = int(sc.z);
        if (edit_near(vec2(g) + o, u_edit_reach[l])) {
            if ((u_edit_top[l] - hfs_h(hx[l])) * sc.y >= lb - 1e-4 * (1.0 + abs(lb)))
                return true;
        } else {
            lb = max(lb, hfs_scale_slope(u_levels, g, u_size, o, sc, hx[l]));
        }
    }
    float hmin = hfs_h(hx[0]);
    for (int l = 1; l < HFS_NLAYERS; ++l)
        hmin = min(hmin, hfs_h(hx[l]));
    return edit_ray_bound(g, cs, u_edit_reach_max, u_edit_top_max, hmin) >=
           lb - 1e-4 * (1.0 + abs(lb));
}

#if HFS_NOUT > 1
/* The finest heights (pairs) of the lowest and the highest of the 3 x 3
 * far receivers around grid point a (itself included; the first met of
 * equal heights, rows then columns: cpu_far_grid.c receivers_around). */
void far_around(ivec2 a, out vec2 lo, out vec2 hi)
{
    float zlo = 1e30, zhi = -1e30;
    for (int v = -1; v <= 1; ++v)
        for (int u = -1; u <= 1; ++u) {
            ivec2 r = min(clamp(a + ivec2(u, v), ivec2(0), u_fgrid - 1) * u_sub, u_size - 1);
            vec2 h = texelFetch(u_levels, ivec3(r, HFS_NLAYERS - 1), 0).xy;
            if (hfs_h(h) < zlo) {
                zlo = hfs_h(h);
                lo = h;
            }
            if (hfs_h(h) > zhi) {
                zhi = hfs_h(h);
                hi = h;
            }
        }
}
#endif

/* Split horizons' far pass: this texel's tile, its receiver, and the
 * occluders of its two sub-directions beyond the u_near near scales, each
 * search starting below any tangent plane (cpu_horizon.h
 * hfs_horizon_occluder), then searched in every gap from far-from on
 * (hfs_gap_search; cpu_far_grid.c); with HFS_NOUT 3 (split_horizon.h
 * HFS_SPLIT_HEIGHTS) also seen from the lowest and the highest receivers
 * around, each from the receiver's own occluder on (hfs_horizon_gap_from),
 * into layers 1 and 2. */
void main()
{
    ivec2 q = ivec2(gl_FragCoord.xy);
    ivec2 tile = q / u_fgrid;
    ivec2 a = q - tile * u_fgrid;
    ivec2 g = min(a * u_sub, u_size - 1);
    int j0 = 2 * (tile.y * u_fcols + tile.x);
    /* After an edit: a receiver none of whose rays meets the box grown by
     * the largest reach reads nothing that changed (before any fetch); with
     * the heights around, none of those receivers may lie in it either */
    float reach = u_edit_reach_max + float(HFS_NOUT > 1 ? u_sub : 0);
    bool edit_far = u_edit != 0 && !edit_near(vec2(g), reach);
    if (edit_far) {
        bool meets = false;
        for (int h = 0; h < 2; ++h)
            if (j0 + h < HFS_NDIR)
                meets = meets ||
                        edit_ray_bound(g, SW_DIR(j0 + h).xy, u_edit_reach_max, 1.0, 0.0) > -1e30;
        if (!meets)
            discard;
    }
    vec2 hx[HFS_NLAYERS];
    hfs_receiver_heights(u_levels, g, hx);
    if (edit_far && HFS_NOUT == 1) { /* the heights around: each ray that meets it */
        bool changes = false;
        for (int h = 0; h < 2; ++h)
            if (j0 + h < HFS_NDIR)
                changes = changes ||
                          far_edit_changes(g, SW_DIR(j0 + h).xy, hx, HFS_NLEV - 1 - u_near);
        if (!changes)
            discard;
    }
    int fetches = 1 + HFS_NLAYERS;
    vec4 res[HFS_NOUT];
    for (int c = 0; c < HFS_NOUT; ++c)
        res[c] = vec4(-3e4, 0.0, -3e4, 0.0);
#if HFS_NOUT > 1
    vec2 around[2];
    far_around(a, around[0], around[1]);
    fetches += 9;
#endif
    for (int h = 0; h < 2; ++h) {
        int j = j0 + h;
        if (j >= HFS_NDIR)
            continue;
        float dist;
        vec2 cs = SW_DIR(j).xy;
        float best = horizon_tan(g, cs, hx, -1e30, HFS_NLEV - 1 - u_near, fetches, dist);
        best = hfs_gap_search(u_height, u_bounds, u_rb_at, u_size, g, cs, u_gap_from, 1e9,
                              u_zf, u_tie, hx[HFS_NLAYERS - 1], dist > 0.0 ? best : -1e30, 1e30,
                              dist, fetches);
        if (dist > 0.0) { /* the height from the slope as found (write_horizons) */
            res[0][2 * h] = hfs_pair_h(best * dist);
            res[0][2 * h + 1] = dist;
        }
#if HFS_NOUT > 1
        for (int c = 1; c < HFS_NOUT; ++c) { /* stored over this receiver */
            float rise = hfs_hdiff(around[c - 1], hx[HFS_NLAYERS - 1]) * u_zf, d = dist;
            if (rise == 0.0) { /* its own height: its own occluder */
                res[c] = h == 0 ? vec4(res[0].xy, res[c].zw) : vec4(res[c].xy, res[0].zw);
                continue;
            }
            float t = hfs_gap_search(u_height, u_bounds, u_rb_at, u_size, g, cs, u_gap_from, 1e9,
                                     u_zf, u_tie, around[c - 1],
                                     dist > 0.0 ? best - rise / dist : -1e30, 1e30, d, fetches);
            if (d > 0.0) {
                res[c][2 * h] = hfs_pair_h(t * d + rise);
                res[c][2 * h + 1] = d;
            }
        }
#endif
    }
#ifdef HFS_COUNT
    write_count(fetches);
#else
    for (int c = 0; c < HFS_NOUT; ++c)
        res[c] = hfs_f16v(res[c]);
    write_outputs(res);
#endif
}
#else
void main()
{
    ivec2 g = hfs_receiver(u_size, u_sub);
    vec3 n = hfs_normal_at(u_height, g, u_size, u_zf);
    vec2 hx[HFS_NLAYERS];
    hfs_receiver_heights(u_levels, g, hx);
    int fetches = 4 + HFS_NLAYERS; /* the normal's 4 heights, the receiver's layers */
#ifdef HFS_SLICE
    write_horizons(g, n, hx, fetches);
#else
    vec4 V[4];
    for (int q = 0; q < 4; ++q)
        V[q] = vec4(0.0);
#ifdef HFS_TABLES
    float om_first = 0.0, om_prev = 0.0;
#endif
    for (int j = 0; j < HFS_NDIR; ++j) {
        vec2 cs = SW_DIR(j).xy;
        /* Start at tan(floor): a slope below the tangent plane never wins. */
        float dist;
        float best = horizon_tan(g, cs, hx, -(n.x * cs.x + n.y * cs.y) / n.z, HFS_NLEV - 1,
                                 fetches, dist);
#ifdef HFS_TABLES
        float om = clamp(atan(best), -HFS_HALF_PI, HFS_HALF_PI);
        if (j == 0) {
            om_first = om;
        } else {
            add_wedge(V, om_prev, om, j - 1);
            fetches += 4;
        }
        om_prev = om;
#else
        /* The environment's window is the whole [-pi/2, pi/2]: the visible
         * band is (omega, pi/2], and its NLP vector needs only sin(omega)
         * and cos^2(omega), both rational in tan(omega) = best. */
        vec4 v = SW_OCCTOP - hfs_nlp_occ_tan(best);
        V[0] += v * SW_C(4 * j);
        V[1] += v * SW_C(4 * j + 1);
        V[2] += v * SW_C(4 * j + 2);
        V[3] += v * SW_C(4 * j + 3);
#endif
    }
#ifdef HFS_TABLES
    add_wedge(V, om_prev, om_first, HFS_NDIR - 1);
    fetches += 4;
#endif
#ifdef HFS_COUNT
    write_count(fetches);
#else
    vec4 hemi[4];
    hfs_sh_hemisphere(n, hemi);
    for (int q = 0; q < 4; ++q)
        V[q] -= hemi[q];
    o_v0 = hfs_f16v(V[0]);
    o_v1 = hfs_f16v(V[1]);
    o_v2 = hfs_f16v(V[2]);
    o_v3 = hfs_f16v(V[3]);
#endif
#endif
}
#endif
