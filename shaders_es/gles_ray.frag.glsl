/*
 * gles_ray.frag - the gap search (runtime/core/ray_bound.h
 * hfs_ray_bound_search, DESIGN.md "Horizons"), the second part of the
 * GLES renderer's shader library: every pass is compiled as
 *     "#version 300 es" + variant defines + gles_lib.frag + gles_ray.frag
 *     + [sh_product.glsl.inc] + the pass shader
 * (runtime/gles/programs.c; source string 3 in driver messages).  Kept
 * apart from gles_lib.frag so that each library file stays one job.
 */
precision highp float;
precision highp int;
precision highp sampler2D;

float hfs_h(vec2 t);
float hfs_hdiff(vec2 a, vec2 b);
bool hfs_scale_takes_over(float sl, float ref, float tie);

/* ---- the gap search (runtime/core/ray_bound.h hfs_ray_bound_search) ----- */

#define HFS_RAY_LEVELS 16       /* ray_bound.h HFS_RAY_BOUND_MAX_LEVELS */
#define HFS_RAY_EDGE_TOL 1e-3   /* ray_bound.c RAY_EDGE_TOL */

/* The level whose one read bounds the grid points [lo, hi]. */
int hfs_ray_level(ivec2 lo, ivec2 hi)
{
    int l = 1;
    while (any(greaterThan((hi >> l) - (lo >> l), ivec2(1))))
        ++l;
    return l;
}

/* max(best, the slope of every crossing at distance >= t_first and <=
 * t_last) of receiver g (height h0 at g) in direction cs: bounds from the atlas
 * `bounds` (level l at at[l]), heights (hi, lo) from `heights` (the input,
 * texelFetch), slopes (v - v0) zf / t (zf = hscale zscale / dx); *dist
 * moves to a crossing only past the horizons' tie (hfs_scale_takes_over,
 * as ray_bound.c), the value is the max; it
 * returns as soon as best reaches `stop` (1e30: never; a key light's
 * window fully blocked needs no more).  *dist: the distance of the
 * crossing that raised best.  Counts its reads. */
float hfs_gap_search(highp sampler2D heights, highp sampler2D bounds, ivec2 at[HFS_RAY_LEVELS],
                     ivec2 size, ivec2 g, vec2 cs, float t_first, float t_last, float zf,
                     float tie, vec2 h0, float best, float stop, inout float dist,
                     inout int fetches)
{
    bool xm = abs(cs.x) >= abs(cs.y);
    float ma = xm ? cs.x : cs.y, mi = xm ? cs.y : cs.x;
    int step = ma >= 0.0 ? 1 : -1;
    float inv = 1.0 / abs(ma), r = mi / abs(ma);
    int p = xm ? g.x : g.y, q = xm ? g.y : g.x;
    int nq = xm ? size.y : size.x;
    int last = step > 0 ? (xm ? size.x : size.y) - 1 - p : p;
    float lim = r > 0.0 ? (float(nq - 1 - q) + HFS_RAY_EDGE_TOL) / r
                        : (r < 0.0 ? (float(q) + HFS_RAY_EDGE_TOL) / -r : 1e9);
    if (lim < float(last))
        last = int(floor(lim));
    float lim_t = floor(t_last * abs(ma) + 1e-4);
    if (lim_t < float(last))
        last = int(max(lim_t, 0.0));
    int m = max(1, int(ceil(t_first * abs(ma) - 1e-4)));
    float v0 = hfs_h(h0);
    int l = 0;
    float lead = best; /* the slope of the crossing dist names (ray_bound.c) */
    while (m <= last && best < stop) {
        float t = float(m) * inv;
        if (l == 0) { /* one crossing: the surface there, exactly */
            float y = clamp(float(q) + float(m) * r, 0.0, float(nq - 1));
            int y0 = min(int(floor(y)), max(nq - 2, 0));
            float f = y - float(y0);
            int x = p + step * m;
            ivec2 ia = xm ? ivec2(x, y0) : ivec2(y0, x);
            ivec2 ib = nq >= 2 ? ia + (xm ? ivec2(0, 1) : ivec2(1, 0)) : ia;
            vec2 a = texelFetch(heights, ia, 0).xy;
            vec2 b = texelFetch(heights, ib, 0).xy;
            float sl = (hfs_hdiff(a, h0) + f * hfs_hdiff(b, a)) * zf / t;
            fetches += 2;
            if (hfs_scale_takes_over(sl, lead, tie)) {
                lead = sl;
                dist = t;
            }
            best = max(best, sl);
            ++m;
            l = 1;
            continue;
        }
        int m1 = min(m + (1 << l) - 1, last);
        float ya = float(q) + float(m) * r, yb = float(q) + float(m1) * r;
        int q0 = max(int(floor(min(ya, yb) - HFS_RAY_EDGE_TOL)), 0);
        int q1 = min(int(ceil(max(ya, yb) + HFS_RAY_EDGE_TOL)), nq - 1);
        int pa = p + step * m, pb = p + step * m1;
        ivec2 lo = xm ? ivec2(min(pa, pb), q0) : ivec2(q0, min(pa, pb));
        ivec2 hi = xm ? ivec2(max(pa, pb), q1) : ivec2(q1, max(pa, pb));
        int lv = hfs_ray_level(lo, hi);
        float rise = texelFetch(bounds, at[lv] + (lo >> lv), 0).x - v0;
        ++fetches;
        /* the largest slope the run can hold: a rise over its nearest
         * crossing, a fall over its farthest */
        if (rise * zf / (rise >= 0.0 ? t : float(m1) * inv) > best) {
            --l;
            continue;
        }
        m = m1 + 1;
        ++l;
    }
    return best;
}
