/*
 * gles_ray.frag - the gap search (runtime/core/ray_bound.h
 * hfs_ray_bound_search, DESIGN.md "Horizons"), the second part of the
 * GLES renderer's shader library: every pass is compiled as
 *     "#version 300 es" + variant defines + gles_pairs.frag + gles_lib.frag
 *     + gles_ray.frag + gles_view.frag + [sh_product.glsl.inc] + the pass
 * (runtime/gles/programs.c; source string 3 in driver messages).  Kept
 * apart from gles_lib.frag so that each library file stays one job.
 *
 * HFS_CELLS 1 (the key lights' programs, key_horizons.frag and
 * key_visibility.frag, and the GIS horizons', runtime/gles/horizons.c)
 * compiles the whole ray's supremum as hfs_gap_search_cells instead of the
 * crossings' hfs_gap_search: the cells' code stays out of every other
 * program, whose compile it would slow, and a program that calls the
 * search it was not built with fails to link.
 */
// hfs-variant: HFS_CELLS 1
precision highp float;
precision highp int;
precision highp sampler2D;

float hfs_h(vec2 t);
float hfs_hdiff(vec2 a, vec2 b);
bool hfs_scale_takes_over(float sl, float ref, float tie);
vec2 hfs_height_at(highp sampler2DArray h, ivec2 p);
vec2 hfs_height_bilinear(highp sampler2DArray h, vec2 uv, ivec2 size, vec2 p);
bool hfs_scale_offset(ivec2 g, ivec2 size, float d, vec2 cs, out vec2 o);

/* ---- the gap search (runtime/core/ray_bound.h hfs_ray_bound_search) ----- */

#define HFS_RAY_LEVELS 16       /* ray_bound.h HFS_RAY_BOUND_MAX_LEVELS */
#define HFS_RAY_EDGE_TOL 1e-3   /* ray_bound.c RAY_EDGE_TOL */
#ifndef HFS_CELLS
#define HFS_CELLS 0
#endif

/* The level whose one read bounds the grid points [lo, hi]: the least
 * l >= 1 at which both axes' ends lie in the same or neighbouring blocks
 * (ray_bound.c hfs_ray_bound_level, the same value).  With e = floor(log2)
 * of the larger span, read exactly from its float's exponent, that l is
 * e - 1, e or e + 1 (a span of 2^e or more crosses at least three blocks
 * of 2^(e-2); one under 2^(e+1) at most two of 2^(e+1)): two tests in
 * place of a loop, which a SIMD device runs for its slowest lane. */
int hfs_ray_level(ivec2 lo, ivec2 hi)
{
    ivec2 d = hi - lo;
    int e = (floatBitsToInt(float(max(max(d.x, d.y), 1))) >> 23) - 127;
    int l = max(e - 1, 1);
    l += any(greaterThan((hi >> l) - (lo >> l), ivec2(1))) ? 1 : 0;
    l += any(greaterThan((hi >> l) - (lo >> l), ivec2(1))) ? 1 : 0;
    return l;
}

/* One search with cells (runtime/core/ray_bound.c ray_search, the same
 * steps): the ray, its receiver and the result so far, and the last
 * segment's far column (rows col_v0 .. col_v0 + col_n - 1, relative to
 * h0), which is the next segment's near one wherever crossings are
 * evaluated in a row: a segment then reads 2-3 heights, not 4-6, as the
 * CPU's (an evaluated crossing of the crossings alone reads 2). */
struct hfs_ray {
    bool xm;
    int step, p, q, nq;
    float am, inv, r, zf, tie; /* am: |the major component| */
    vec2 h0;
    float best, lead, dist;
    int fetches;
    vec3 col;
    int col_u, col_v0, col_n;
};

/* A surface point's slope sl at distance t: the max, and dist past the
 * tie (ray_bound.c take). */
void hfs_ray_take(inout hfs_ray R, float sl, float t)
{
    if (hfs_scale_takes_over(sl, R.lead, R.tie)) {
        R.lead = sl;
        R.dist = t;
    }
    R.best = max(R.best, sl);
}

#if HFS_CELLS
/* Crossing m's surface from its column c (rows v0 .. v0 + 2) at the
 * clamped minor coordinate y (ray_bound.c crossing_from; a row that
 * weighs 0 adds 0). */
float hfs_ray_crossing_from(float y, int nq, vec3 c, int v0)
{
    int y0 = max(min(int(floor(y)), nq - 2), 0);
    vec2 ab = y0 == v0 ? c.xy : c.yz;
    return ab.x + (y - float(y0)) * (ab.y - ab.x);
}

/* The cells from a0 to a1 crossings past crossing m (0 <= a0 < a1 <= 1),
 * crossing m where a0 = 0 and crossing m + 1 where a1 = 1 (ray_bound.c
 * segment, the same steps): the rows the stretch's cells span, of both
 * columns, the near one kept from the segment before where it holds
 * them.  a1 = 0: crossing m alone, from its column (the last crossing,
 * and every crossing of a one-row grid, whose second row repeats its
 * first).  The rows are read in one loop, as many turns as this texel
 * needs reads (2-3 a segment where segments run on): a SIMD device that
 * runs a loop body for its slowest lane then reads no more (issue 37:
 * a read per row of each column cost llvmpipe twice the time). */
void hfs_ray_segment(highp sampler2DArray heights, inout hfs_ray R, int m, float a0, float a1)
{
    bool lone = !(a1 > 0.0);
    float fm = float(m);
    float ya = float(R.q) + fm * R.r, yb = float(R.q) + (fm + a1) * R.r;
    float ys = float(R.q) + (fm + a0) * R.r; /* where the stretch starts */
    float ca = clamp(ys, 0.0, float(R.nq - 1)), cb = clamp(yb, 0.0, float(R.nq - 1));
    int v_lo = max(min(int(floor(min(ca, cb))), R.nq - 2), 0);
    int v_hi = max(int(ceil(max(ca, cb))), v_lo + 1);
    int u0 = R.p + R.step * m, u1 = u0 + R.step, n = v_hi - v_lo + 1;
    /* the near column's rows [k0, k1) that the kept one lacks: one run, as
     * the kept column has at least two rows and a segment at most three */
    int k0 = 0, k1 = n;
    vec3 c0 = vec3(0.0), c1 = vec3(0.0);
    if (u0 == R.col_u) {
        int kr0 = R.col_v0 - v_lo, kr1 = kr0 + R.col_n;
        for (int k = 0; k < 3; ++k)
            c0[k] = k >= kr0 && k < kr1 ? R.col[clamp(k - kr0, 0, 2)] : 0.0;
        if (kr0 <= 0 && kr1 >= n)
            k1 = 0;
        else if (kr0 <= 0 && kr1 > 0)
            k0 = kr1;
        else if (kr1 >= n && kr0 < n)
            k1 = kr0;
    }
    int miss = k1 - k0, reads = miss + (lone ? 0 : n);
    for (int i = 0; i < reads; ++i) {
        bool near = i < miss;
        int k = near ? k0 + i : i - miss;
        int u = near ? u0 : u1, v = min(v_lo + k, R.nq - 1);
        float h = hfs_hdiff(hfs_height_at(heights, R.xm ? ivec2(u, v) : ivec2(v, u)), R.h0);
        if (near)
            c0[k] = h;
        else
            c1[k] = h;
    }
    R.fetches += reads;
    if (n < 3) {
        c0.z = c0.y;
        c1.z = c1.y;
    }
    R.col = lone ? c0 : c1;
    R.col_u = lone ? u0 : u1, R.col_v0 = v_lo, R.col_n = n;
    if (a0 <= 0.0)
        hfs_ray_take(R, hfs_ray_crossing_from(ca, R.nq, c0, v_lo) * R.zf / (fm * R.inv),
                     fm * R.inv);
    if (a1 >= 1.0)
        hfs_ray_take(R, hfs_ray_crossing_from(cb, R.nq, c1, v_lo) * R.zf / ((fm + 1.0) * R.inv),
                     (fm + 1.0) * R.inv);
    if (lone)
        return;
    /* the cells lie below their highest corner: most never reach the best */
    float top = max(max(max(c0.x, c0.y), c0.z), max(max(c1.x, c1.y), c1.z));
    if (top * R.zf / ((top >= 0.0 ? fm + a0 : fm + a1) * R.inv) <= R.best)
        return;
    float cut = -1.0;
    if (R.r > 0.0 && floor(ys) + 1.0 < yb)
        cut = (floor(ys) + 1.0 - ya) / R.r;
    else if (R.r < 0.0 && ceil(ys) - 1.0 > yb)
        cut = (ceil(ys) - 1.0 - ya) / R.r;
    cut = cut > a0 ? cut : -1.0;
    for (int pc = 0; pc < 2; ++pc) {
        if (pc == 1 && !(cut > 0.0))
            break;
        float lo = pc == 0 ? a0 : cut, hi = pc == 0 && cut > 0.0 ? cut : a1;
        int v0 = clamp(int(floor(float(R.q) + (fm + 0.5 * (lo + hi)) * R.r)), v_lo, v_hi - 1);
        vec2 n0 = v0 == v_lo ? c0.xy : c0.yz, n1 = v0 == v_lo ? c1.xy : c1.yz;
        float z00 = n0.x, z10 = n1.x, z01 = n0.y, z11 = n1.y;
        float b0 = ya - float(v0), e = z11 - z10 - z01 + z00;
        float A = z00 + (z01 - z00) * b0, B = z10 - z00 + (z01 - z00) * R.r + e * b0;
        float C = e * R.r;
        /* the far end (a crossing's is taken above), the inner peak and,
         * where the stretch starts past a crossing, its near end */
        vec3 at = vec3(hi < 1.0 ? hi : -1.0, -1.0, pc == 0 && a0 > 0.0 ? a0 : -1.0);
        if (C < 0.0) {
            float D = C * C * fm * fm - C * (B * fm - A);
            if (D >= 0.0)
                at.y = (B * fm - A) / (sqrt(D) - C * fm);
        }
        for (int i = 0; i < 3; ++i) {
            float a = i == 0 ? at.x : (i == 1 ? at.y : at.z);
            if (!(i == 2 ? a >= lo : a > lo && a <= hi))
                continue;
            float b = clamp(b0 + R.r * a, 0.0, 1.0);
            float v = z00 + (z10 - z00) * a + (z01 - z00) * b + e * a * b;
            /* the value only: the lead stays a crossing's (ray_bound.c) */
            R.best = max(R.best, v * R.zf / ((fm + a) * R.inv));
        }
    }
}
#define HFS_GAP_SEARCH hfs_gap_search_cells
#else
#define HFS_GAP_SEARCH hfs_gap_search
#endif

/* The bound of the grid points in [lo, hi] (inclusive, on the grid): one
 * read of the max pyramid's atlas at the level hfs_ray_level picks. */
float hfs_ray_bound(highp sampler2D bounds, ivec2 at[HFS_RAY_LEVELS], ivec2 lo, ivec2 hi)
{
    int lv = hfs_ray_level(lo, hi);
    return texelFetch(bounds, at[lv] + (lo >> lv), 0).x;
}

/* The bound of the grid points of the ray's stretch from ua to ub
 * crossings, its columns ma .. mb (ray_bound.c box_rise): one read. */
float hfs_ray_box_rise(highp sampler2D bounds, ivec2 at[HFS_RAY_LEVELS], inout hfs_ray R,
                       float ua, float ub, int ma, int mb)
{
    float ya = float(R.q) + ua * R.r, yb = float(R.q) + ub * R.r;
    int q0 = max(int(floor(min(ya, yb) - HFS_RAY_EDGE_TOL)), 0);
    int q1 = min(int(ceil(max(ya, yb) + HFS_RAY_EDGE_TOL)), R.nq - 1);
    int pa = R.p + R.step * ma, pb = R.p + R.step * mb;
    ivec2 lo = R.xm ? ivec2(min(pa, pb), q0) : ivec2(q0, min(pa, pb));
    ivec2 hi = R.xm ? ivec2(max(pa, pb), q1) : ivec2(q1, max(pa, pb));
    ++R.fetches;
    return hfs_ray_bound(bounds, at, lo, hi);
}

/* The ray from grid point g (height h0) in direction cs: its axes and
 * steps, the result so far, no column kept. */
hfs_ray hfs_ray_make(ivec2 size, ivec2 g, vec2 cs, float zf, float tie, vec2 h0, float best,
                     float dist, int fetches)
{
    hfs_ray R;
    R.xm = abs(cs.x) >= abs(cs.y);
    float ma = R.xm ? cs.x : cs.y, mi = R.xm ? cs.y : cs.x;
    R.step = ma >= 0.0 ? 1 : -1;
    R.am = abs(ma);
    R.inv = 1.0 / R.am, R.r = mi / R.am;
    R.p = R.xm ? g.x : g.y, R.q = R.xm ? g.y : g.x;
    R.nq = R.xm ? size.y : size.x;
    R.zf = zf, R.tie = tie, R.h0 = h0;
    R.best = best, R.lead = best, R.dist = dist, R.fetches = fetches;
    R.col = vec3(0.0), R.col_u = -1, R.col_v0 = 0, R.col_n = 0;
    return R;
}

/* The crossings from the receiver to the grid's side along the major axis. */
int hfs_ray_side(hfs_ray R, ivec2 size)
{
    return R.step > 0 ? (R.xm ? size.x : size.y) - 1 - R.p : R.p;
}

/* The last crossing inside the grid (the minor coordinate within the edge
 * tolerance of it) at distance <= t_last (ray_bound.c walk_make). */
int hfs_ray_last(hfs_ray R, ivec2 size, float t_last)
{
    int last = hfs_ray_side(R, size);
    float lim = R.r > 0.0 ? (float(R.nq - 1 - R.q) + HFS_RAY_EDGE_TOL) / R.r
                          : (R.r < 0.0 ? (float(R.q) + HFS_RAY_EDGE_TOL) / -R.r : 1e9);
    if (lim < float(last))
        last = int(floor(lim));
    float lim_t = floor(t_last * R.am + 1e-4);
    if (lim_t < float(last))
        last = int(max(lim_t, 0.0));
    return last;
}

#if HFS_CELLS
/* Where the ray ends, in crossings: the radius t_last, or where it leaves
 * the grid. */
float hfs_ray_end(hfs_ray R, ivec2 size, float t_last)
{
    float u_end = min(t_last * R.am, float(hfs_ray_side(R, size)));
    if (R.r != 0.0)
        u_end = min(u_end, R.r > 0.0 ? float(R.nq - 1 - R.q) / R.r : float(R.q) / -R.r);
    return u_end;
}
#else
/* Crossing m alone (the crossings' search): one pair of heights, the
 * minor axis' linear interpolation (ray_bound.c crossing). */
void hfs_ray_crossing(highp sampler2DArray heights, inout hfs_ray R, int m)
{
    float y = clamp(float(R.q) + float(m) * R.r, 0.0, float(R.nq - 1));
    int y0 = min(int(floor(y)), max(R.nq - 2, 0));
    float f = y - float(y0);
    int x = R.p + R.step * m;
    ivec2 ia = R.xm ? ivec2(x, y0) : ivec2(y0, x);
    ivec2 ib = R.nq >= 2 ? ia + (R.xm ? ivec2(0, 1) : ivec2(1, 0)) : ia;
    vec2 a = hfs_height_at(heights, ia);
    vec2 b = hfs_height_at(heights, ib);
    R.fetches += 2;
    float t = float(m) * R.inv;
    hfs_ray_take(R, (hfs_hdiff(a, R.h0) + f * hfs_hdiff(b, a)) * R.zf / t, t);
}
#endif

/* max(best, the slope of every crossing at distance >= t_first and <=
 * t_last) of receiver g (height h0 at g) in direction cs: bounds from the atlas
 * `bounds` (level l at at[l]), heights (hi, lo) from `heights` (the input,
 * texelFetch), slopes (v - v0) zf / t (zf = hscale zscale / dx); *dist
 * moves to a crossing only past the horizons' tie (hfs_scale_takes_over,
 * as ray_bound.c), the value is the max; it
 * returns as soon as best reaches `stop` (1e30: never; a key light's
 * window fully blocked needs no more).  *dist: the distance of the
 * crossing that raised best.  Counts its reads.  With HFS_CELLS, as
 * hfs_gap_search_cells: the whole ray's supremum instead, every cell
 * between crossings solved or bounded (ray_bound.h "cells",
 * hfs_ray_bound_search_cells; the key lights and the GIS horizons).  (A second walk from the
 * crossings' max, to solve only the cells that can beat it, was no faster
 * on llvmpipe: it reads more.) */
float HFS_GAP_SEARCH(highp sampler2DArray heights, highp sampler2D bounds, ivec2 at[HFS_RAY_LEVELS],
                     ivec2 size, ivec2 g, vec2 cs, float t_first, float t_last, float zf, float tie,
                     vec2 h0, float best, float stop, inout float dist, inout int fetches)
{
    hfs_ray R = hfs_ray_make(size, g, cs, zf, tie, h0, best, dist, fetches);
    int last = hfs_ray_last(R, size, t_last);
    float inv = R.inv;
#if HFS_CELLS
    bool cells = R.nq >= 2; /* one row: linear between crossings */
#else
    const bool cells = false;
#endif
    float u0 = t_first * R.am; /* in crossings */
    int m = max(1, int(ceil(u0 - 1e-4)));
    int m_first = m;
    float v0 = hfs_h(h0);
#if HFS_CELLS
    float u_end = hfs_ray_end(R, size, t_last);
    /* the stretch from t_first to its first crossing (ray_bound.c search):
     * a search that continues another leaves no gap between them */
    int phase = cells && m_first >= 2 && float(m_first) - u0 > 1e-4 && u_end > u0 ? 0 : 1;
    float a1s = min(u_end - float(m_first - 1), 1.0);
#else
    int phase = 1;
    const float a1s = 0.0, u_end = 0.0;
#endif
    /* One loop does the whole search, a bound read or a segment (or both)
     * a turn, in the order of ray_bound.c search: phase 0 the stretch
     * from t_first to the first crossing, 1 the crossings (and with cells
     * the cells between), 2 the cells past the last crossing.  One call
     * site for the segment: a SIMD device runs each site for all its
     * lanes (issue 37). */
    int l = 0;
    while (phase < 3 && R.best < stop) {
        if (phase == 1 && m > last) {
#if HFS_CELLS
            if (!(cells && last >= m_first && u_end - float(last) > 0.0))
                break;
            phase = 2;
#else
            break;
#endif
        }
        /* the run's bounding box of grid points; with cells, also those of
         * the cells on to the next crossing (a skipped run bounds them) */
        int m1 = min(m + (1 << l) - 1, last);
        int mb = cells && m1 < last ? m1 + 1 : m1;
        bool beats = false;
        if (phase == 0 || (phase == 1 && l > 0)) {
            float ua = phase == 0 ? u0 : float(m);
            float ub = phase == 0 ? float(m_first - 1) + a1s : float(mb);
            int ca = phase == 0 ? m_first - 1 : m, cb = phase == 0 ? m_first : mb;
            float rise = hfs_ray_box_rise(bounds, at, R, ua, ub, ca, cb) - v0;
            /* the largest slope the stretch can hold: a rise over its
             * nearest point, a fall over its farthest */
            beats = rise * zf / ((rise >= 0.0 ? ua : ub) * inv) > R.best;
        }
        int sm = -1; /* the segment (or crossing) evaluated exactly, if any */
        float sa0 = 0.0, sa1 = 0.0;
        if (phase == 0) { /* solved where its cells' bound can beat the start */
            sm = beats ? m_first - 1 : -1;
            sa0 = u0 - float(m_first - 1);
            sa1 = a1s;
            phase = 1;
        } else if (phase == 2) {
            sm = last;
            sa1 = min(u_end - float(last), 1.0);
            phase = 3;
        } else if (l == 0 || (l == 1 && beats)) {
            /* one crossing (and with cells its segment), at once where
             * the smallest run's bound beats the best: a turn saved */
            sm = m;
            sa1 = cells && m < last ? 1.0 : 0.0;
            ++m;
            l = 1;
        } else if (beats) {
            --l;
        } else {
            m = m1 + 1;
            ++l;
        }
        if (sm >= 0) {
#if HFS_CELLS
            hfs_ray_segment(heights, R, sm, sa0, sa1);
#else
            hfs_ray_crossing(heights, R, sm);
#endif
        }
    }
    dist = R.dist;
    fetches = R.fetches;
    return R.best;
}

/* Grid point p's own cell along cs (field_geom.h hfs_field_first_cell_slope),
 * the stretch a gap search from t_first <= 1 leaves to its caller: the
 * larger of its near end's slope (ns: the one-sided slopes to (+x, -x, +y,
 * -y), -1e30 off the field, weighted by |cos|, |sin|) and its far edge's,
 * read bilinearly from heights h (hfs_height_bilinear, one fetch, counted),
 * slopes as rise (v - v_p) / t; -1e30 where the cell leaves the field.
 * The key lights (key_visibility.frag) and the local lights
 * (local_visibility.frag). */
float hfs_own_cell_slope(highp sampler2DArray h, ivec2 p, ivec2 size, vec2 cs, vec2 zp, vec4 ns,
                         float rise, inout int fetches)
{
    vec2 a = abs(cs);
    float nx = cs.x > 0.0 ? ns.x : ns.y, ny = cs.y > 0.0 ? ns.z : ns.w;
    if ((a.x > 0.0 && nx < -1e29) || (a.y > 0.0 && ny < -1e29))
        return -1e30;
    float near = (a.x > 0.0 ? a.x * nx : 0.0) + (a.y > 0.0 ? a.y * ny : 0.0);
    float d = 1.0 / max(a.x, a.y);
    vec2 o;
    if (!hfs_scale_offset(p, size, d, cs, o))
        return max(near, -1e30);
    vec2 t = hfs_height_bilinear(h, (vec2(p) + 0.5 + o) / vec2(size), size, vec2(p) + o);
    ++fetches;
    return max(near, rise * hfs_hdiff(t, zp) / d);
}
