/*
 * key_visibility.frag - one key light's per-texel factor at full resolution
 * (DESIGN.md "Shading", "GLES path", "Frame planner"):
 *   f = E_cap(N.d, alpha) * clamp(num/den, 0, 1),
 *   num = V_key . (H * L_key), den = V_open . (H * L_key); the horizons are
 *   max(floor_j(N), omega_j), omega_j from the visibility grid
 *   (key_horizons.frag, key_horizon below), and V_open uses the floors of
 *   this texel's normal.
 * The shading pass multiplies f by rho/pi Le: a re-tinted or dimmed key
 * light, or any change of the other lights, keeps f.  Stored as f / E_max
 * (u_emax = pi sin^2 alpha, f's largest value, so the stored value is in
 * [0, 1] whatever the disk's size: a 1e-7 rad sun's E_cap is far below
 * fp16's range) as an fp16 (hi, lo) pair in one layer of an RG array.
 * HfsKeys holds one record per key light (runtime/gles/uniform_blocks.h
 * hfs_gles_pack_key), this light's from vec4 u_k[u_kb].
 * HFS_COUNT: instead of f, the texture fetches this texel made (heights,
 * normals, horizons, bounds, tables; not the records' texture), as (count
 * mod 1024, floor(count / 1024)), for measurement.
 */
// hfs-base: HFS_CELLS 1
// hfs-variant: HFS_TABLES 1
// hfs-variant: HFS_FP32 1
// hfs-variant: HFS_KEYS_TEX 1
// hfs-variant: HFS_KEYS_TEX 1, HFS_TABLES 1
// hfs-variant: HFS_COUNT 1

#ifndef HFS_KEY_VEC4
#define HFS_KEY_VEC4 1
#endif
#ifndef HFS_TABLE_N
#define HFS_TABLE_N 257
#endif
#ifndef HFS_WEDGE_TOL
#define HFS_WEDGE_TOL 1e-3 /* gles_ray.frag HFS_RAY_EDGE_TOL: a row this near counts */
#endif
#ifndef HFS_HALF_PI
#define HFS_HALF_PI 1.5707963267948966
#endif

precision highp float;
precision highp int;
precision highp sampler2D;
precision highp sampler2DArray;

vec3 hfs_normal_sides(highp sampler2DArray h, ivec2 p, ivec2 size, float zf, vec2 zp,
                      out vec4 d, out bvec4 on);
vec4 hfs_visible(float omega, vec4 win, vec4 occ_top);
void hfs_sh_cosine(vec3 n, out vec4 h[4]);
float hfs_sh_dot(vec4 a[4], vec4 b[4]);
float hfs_table_coord(float omega, float n);
void hfs_table_add(highp sampler2DArray tab, vec2 uv, float layer0, bool mirror, vec3 c,
                   vec3 s, inout vec4 V[4]);
float hfs_cap_irradiance(float cos_beta, float alpha);
vec2 hfs_split(float v);
vec2 hfs_height_bilinear(highp sampler2DArray h, vec2 uv, ivec2 size, vec2 p);
vec2 hfs_height_at(highp sampler2DArray h, ivec2 p);
float hfs_h(vec2 t);
float hfs_hdiff(vec2 a, vec2 b);
bool hfs_ray_box(vec2 p, vec2 cs, vec4 box, float t_max, out vec2 t);
bool hfs_scale_offset(ivec2 g, ivec2 size, float d, vec2 cs, out vec2 o);
void hfs_sh_product(in vec4 a[4], in vec4 b[4], out vec4 c[4]);
void hfs_sh_basis(vec3 d, out vec4 y[4]);
float hfs_refine_factor(int q, int n, float k);
#define HFS_RAY_LEVELS 16
float hfs_ray_bound(highp sampler2D bounds, ivec2 at[HFS_RAY_LEVELS], ivec2 lo, ivec2 hi);
float hfs_own_cell_slope(highp sampler2DArray h, ivec2 p, ivec2 size, vec2 cs, vec2 zp, vec4 ns,
                         float rise, inout int fetches);
float hfs_gap_search_cells(highp sampler2DArray heights, highp sampler2D bounds,
                           ivec2 at[HFS_RAY_LEVELS], ivec2 size, ivec2 g, vec2 cs, float t_first,
                           float t_last, float zf, float tie, vec2 h0, float best, float stop,
                           inout float dist, inout int fetches);

uniform float u_zf;                      /* hscale zscale / dx, clamped to 1e30 */
uniform highp sampler2DArray u_keyhz;    /* key horizons (hi, lo, D, 0), a direction a layer */
uniform highp sampler2DArray u_height;   /* normalized heights (hi, lo), full resolution, LINEAR */
#ifdef HFS_TABLES
uniform highp sampler2DArray u_ktab;     /* interior tables, 4 layers per set */
uniform highp sampler2DArray u_ktabb;    /* boundary tables (n x 1), 4 per set */
#endif
uniform ivec2 u_size;                    /* W, H */
uniform ivec2 u_vsize;                   /* visibility grid size */
uniform int u_sub;
uniform int u_kb;                        /* this light's record in u_k */
uniform float u_emax;                    /* pi sin^2 alpha */
uniform float u_rise;                    /* normalized height to texels: hscale zscale / dx */
uniform float u_far;                     /* occluders this far (texels) move to each texel's height */
/* The near search (runtime/core/key_setup.h hfs_key_near_make): the
 * u_near finest scales, within u_reach texels, along u_near_cs, or (u_near_dir,
 * a full swath) in each direction. */
uniform int u_near;
uniform int u_near_dir;
uniform float u_reach;
uniform vec2 u_near_cs;
uniform float u_lk;                      /* levels per octave: d_m = 2^(m / k) */
uniform int u_refine;                    /* samples refining the near max */
/* and every crossing of the texel's ray with the grid's lines up to
 * u_near_to texels (where the grid pass's gap search starts): the max
 * pyramid's atlas (runtime/core/ray_bound.h) */
uniform float u_near_to;
uniform float u_edge;                    /* each direction's own ray from u_near_to to here */
uniform int u_whole;                     /* 1: u_edge is the field's end and the grid unused */
uniform highp sampler2D u_bounds;
uniform ivec2 u_rb_at[HFS_RAY_LEVELS];
/* After an edit of the heights (runtime/gles/edit_frame.c, edit_region.h):
 * u_edit 1 draws only the texels the edit can reach and leaves the others
 * as the last frame left them.  u_edit_box: the changed texels grown by 2,
 * (x0, y0, x1, y1) inclusive; u_edit_top: their highest normalized height,
 * before or after. */
uniform int u_edit;
uniform vec4 u_edit_box;
uniform float u_edit_top;

#ifdef HFS_KEYS_TEX
/* The records from a texture (too large for a uniform block). */
vec4 hfs_block_vec4(highp usampler2D t, int i);
uniform highp usampler2D u_keys_tex;
#define KREC(i) hfs_block_vec4(u_keys_tex, (i))
#else
layout(std140) uniform HfsKeys {
    vec4 u_k[HFS_KEY_VEC4];
};
#define KREC(i) u_k[i]
#endif

layout(location = 0) out vec4 o_f;       /* (f / E_max hi, lo, 0, 1) */

int g_fetches = 0;                       /* HFS_COUNT: this texel's texture fetches */

#ifdef HFS_TABLES
void tab_add(inout vec4 V[4], float a, float b, bool boundary, int rot, float set)
{
    float n = float(HFS_TABLE_N);
    bool mirror = KREC(rot).w > 0.5;
    g_fetches += 4;
    if (boundary)
        hfs_table_add(u_ktabb, vec2(hfs_table_coord(a, n), 0.5), 4.0 * set, mirror,
                      KREC(rot).xyz, KREC(rot + 1).xyz, V);
    else
        hfs_table_add(u_ktab, vec2(hfs_table_coord(a, n), hfs_table_coord(b, n)), 4.0 * set,
                      mirror, KREC(rot).xyz, KREC(rot + 1).xyz, V);
}
#endif

/* The sample at distance d from texel p in direction cs, as a slope (tan
 * of its elevation): the heights read bilinearly (the pyramid's input
 * level, the same values), zp = the height at p; -1e30 (never the max)
 * off the grid. */
float near_slope(ivec2 p, vec2 cs, float d, vec2 zp)
{
    vec2 o;
    if (!hfs_scale_offset(p, u_size, d, cs, o))
        return -1e30;
    vec2 t = hfs_height_bilinear(u_height, (vec2(p) + 0.5 + o) / vec2(u_size), u_size, vec2(p) + o);
    ++g_fetches;
    return u_rise * hfs_hdiff(t, zp) / d;
}

vec4 g_ns; /* the texel's one-sided slopes to (+x, -x, +y, -y), -1e30 off the field */

/* The texel's own cell along cs (field_geom.h hfs_field_first_cell_slope):
 * the larger of its near end's slope (g_ns weighted by |cos|, |sin|) and
 * its far edge's; -1e30 where the cell leaves the field.  Its near end is
 * no scale's sample (issue 36: on texel-scale relief the sun was seen
 * through it). */
float own_cell_slope(ivec2 p, vec2 cs, vec2 zp)
{
    return hfs_own_cell_slope(u_height, p, u_size, cs, zp, g_ns, u_rise, g_fetches);
}

/* Texel p's near horizon on a sub-sampled grid (DESIGN.md "Key lights on
 * the 2x2 grid", "Sharp edges on the grid"): the max over the u_near
 * finest scales, u_refine samples about the finest scale holding it (as
 * the grid pass refines, hfs_refine_about), then every crossing of the
 * texel's own ray up to u_near_to and every cell between
 * (hfs_gap_search_cells): no occluder within
 * reach is stepped over, and a shadow edge falls on the texel it falls on.
 * One search serves every direction of the swath.  win_t: the slopes at
 * which the light's window starts and closes; the search starts at the
 * first (a lower horizon shows the light the same) and stops at the second
 * (the light is hidden).  win_t.x when there is none (subsample 1, a full
 * swath). */
float near_horizon(ivec2 p, vec2 zp, vec2 win_t)
{
    float best = win_t.x;
    int bm = -1;
    for (int m = 0; u_near_dir == 0 && m < u_near && best < win_t.y; ++m) {
        float sl = near_slope(p, u_near_cs, exp2(float(m) / u_lk), zp);
        if (sl > best) {
            best = sl;
            bm = m;
        }
    }
    float d = exp2(float(bm) / u_lk);
    for (int q = 0; bm >= 0 && q < u_refine && best < win_t.y; ++q)
        best = max(best, near_slope(p, u_near_cs, d * hfs_refine_factor(q, u_refine, u_lk), zp));
    if (u_near_dir == 0 && u_near > 0) {
        float dist = 0.0;
        best = hfs_gap_search_cells(u_height, u_bounds, u_rb_at, u_size, p, u_near_cs, 1.0, u_near_to,
                              u_rise, 0.0, zp, best, win_t.y, dist, g_fetches);
    }
    return best;
}

/* What texel p needs of its grid cell, whatever the direction: the four
 * neighbours' grid coordinates, offsets g - p, their height above p in
 * texel units (rise (z_g - z_p)) and p's bilinear weights; at subsample 1
 * only ga[0] = p. */
struct Cell {
    ivec2 ga[4];
    vec2 rel[4];
    float rz[4];
    vec2 f;
};

Cell grid_cell(ivec2 p, vec2 zp)
{
    Cell c;
    ivec2 a = p / u_sub;
    ivec2 x0 = a * u_sub;
    ivec2 x1 = min(x0 + u_sub, u_size - 1);
    c.f = vec2(p - x0) / vec2(max(x1 - x0, ivec2(1)));
    ivec2 a1 = min(a + 1, u_vsize - 1);
    for (int k = 0; k < 4; ++k) {
        c.ga[k] = ivec2(k % 2 == 0 ? a.x : a1.x, k < 2 ? a.y : a1.y);
        ivec2 g = min(c.ga[k] * u_sub, u_size - 1);
        c.rel[k] = vec2(g - p);
        /* the receivers' heights only where the grid's occluders are
         * blended (not when the texel searches its rays to the field's
         * end: 4 fetches a texel saved, issue 37) */
        c.rz[k] = 0.0;
        if (u_sub > 1 && u_whole == 0) {
            c.rz[k] = u_rise * hfs_hdiff(hfs_height_at(u_height, g), zp);
            ++g_fetches;
        }
    }
    return c;
}

/* Texel p's horizon in direction cs above its floor fl (normal n), from
 * layer `layer` of the grid.  At subsample 1 it is the grid's own.  Between
 * grid receivers (DESIGN.md "Key lights on the 2x2 grid") each of the four
 * neighbours g lends its occluder, t_g D_g above its height and D_g ahead
 * (t_g and D_g as stored):
 * seen from p its slope is (t_g D_g + rise (z_g - z_p)) / (D_g + (g - p).cs)
 * (one that ends up less than u_reach ahead of p, which the near search
 * covers, or a neighbour with no sample on the grid, lends p's floor); the
 * four slopes are blended with the bilinear weights, and p's own near
 * horizon (slope `near`, and its own ray's crossings from t_from, u_near_to
 * or further where the swath's rays are clear that far (wedge_clear), to
 * u_edge, searched until the slope reaches `stop`) can only raise the
 * result: one atan. */
float key_horizon(Cell c, vec3 n, vec2 cs, float fl, float layer, float near, float stop,
                  float t_from, ivec2 p, vec2 zp)
{
    float own = own_cell_slope(p, cs, zp);
    if (u_sub == 1) {
        vec4 t = texelFetch(u_keyhz, ivec3(c.ga[0], int(layer)), 0);
        ++g_fetches;
        return max(max(fl, t.x + t.y), atan(own));
    }
    /* the floor's slope, tan(fl), as the stored tangents are clamped */
    float tfl = clamp(-(n.x * cs.x + n.y * cs.y) / n.z, -1e4, 1e4);
    /* the grid's occluders blended, unless the texel searches its rays to
     * the field's end (u_whole) */
    float s = tfl;
    if (u_whole == 0) {
        float sl[4];
        for (int k = 0; k < 4; ++k) {
            vec4 t = texelFetch(u_keyhz, ivec3(c.ga[k], int(layer)), 0);
            ++g_fetches;
            float ahead = t.z + dot(c.rel[k], cs);
            float rz = t.z >= u_far ? c.rz[k] : 0.0;
            sl[k] = t.z > 0.0 && ahead >= u_reach ? max(tfl, ((t.x + t.y) * t.z + rz) / ahead)
                                                  : tfl;
        }
        s = mix(mix(sl[0], sl[1], c.f.x), mix(sl[2], sl[3], c.f.x), c.f.y);
    }
    near = max(near, own);
    for (int m = 0; u_near_dir > 0 && m < u_near; ++m)
        near = max(near, near_slope(p, cs, exp2(float(m) / u_lk), zp));
    if (u_near_dir == 0 && u_edge > t_from) {
        float dist = 0.0;
        near = hfs_gap_search_cells(u_height, u_bounds, u_rb_at, u_size, p, cs, t_from, u_edge,
                              u_rise, 0.0, zp, near, stop, dist, g_fetches);
    }
    return max(fl, atan(max(s, near)));
}

/* How far every direction of the swath is clear (issue 37; DESIGN.md
 * "Sharp edges on the grid", "the swath's rays at once"): the distance t
 * such that no direction's ray, from t0 to t, passes over a grid point
 * (crossing or cell corner) whose slope can beat `best`, the lowest of the
 * directions' starts; 1e30 where that holds to the field's end.  cr: the
 * directions' (min cos, max cos, min sin, max sin).  A run of distances
 * [ta, tb] is bounded by one read of the max pyramid over the box of every
 * direction's points in it (each ray's stretch is the segment between its
 * points at ta and tb, so the box of the 4 extreme products bounds all of
 * them), skipped when its bound cannot beat best, as the gap search skips
 * runs of crossings: a clear texel then pays one search of about two reads
 * an octave for all its directions, not one each.  The directions' own
 * searches start where this one stops, and find exactly what they would
 * from t0: what lies before it cannot raise their max. */
float wedge_clear(ivec2 p, vec2 zp, float best, float t0, vec4 cr)
{
    float v0 = hfs_h(zp);
    vec2 fp = vec2(p);
    ivec2 top = u_size - 1;
    float t = t0, len = 1.0;
    for (int i = 0; i < 256; ++i) {
        float tb = t + len;
        vec2 lo = fp + vec2(min(t * cr.x, tb * cr.x), min(t * cr.z, tb * cr.z));
        vec2 hi = fp + vec2(max(t * cr.y, tb * cr.y), max(t * cr.w, tb * cr.w));
        ivec2 il = ivec2(floor(lo - HFS_WEDGE_TOL)), ih = ivec2(ceil(hi + HFS_WEDGE_TOL));
        if (any(lessThan(ih, ivec2(0))) || any(greaterThan(il, top)))
            return 1e30; /* every ray has left the field (a convex one) */
        il = clamp(il, ivec2(0), top);
        ih = clamp(ih, ivec2(0), top);
        ++g_fetches;
        float rise = hfs_ray_bound(u_bounds, u_rb_at, il, ih) - v0;
        if (!(rise * u_rise / (rise >= 0.0 ? t : tb) > best)) {
            t = tb;
            len *= 2.0;
        } else if (len > 1.0) {
            len *= 0.5;
        } else {
            return t;
        }
    }
    return t;
}

/* E_cap * ratio for the key light whose record starts at b. */
float key_factor(int b, vec3 n, vec4 H[4], Cell cell, ivec2 p, vec2 zp)
{
    vec4 h0 = KREC(b), h1 = KREC(b + 1), h2 = KREC(b + 2);
    float e_cap = hfs_cap_irradiance(dot(n, h1.xyz), h1.w);
    if (!(e_cap > 0.0))
        return 0.0;
#ifdef HFS_TABLES
    vec4 L[4];
    for (int g = 0; g < 4; ++g)
        L[g] = KREC(b + 3 + g);
    vec4 M[4];
    hfs_sh_product(H, L, M);
#else
    vec4 y[4];
    hfs_sh_basis(n, y);
#endif

    int nd = int(h0.x);
    bool full = h0.y > 0.5;
    float layer0 = h0.z;
    int sw = b + 7;                      /* the light's HfsSwath record */
    vec4 win = KREC(sw), occtop = KREC(sw + 1);
    /* The Legendre path sees a horizon only through max(omega, win.x) and
     * not at all from win.y (hfs_visible); the table path counts every
     * elevation (visibility.h). */
#ifdef HFS_TABLES
    vec2 win_t = vec2(-1e30, 1e30);
#else
    vec2 win_t = vec2(tan(max(win.x, -1.5)), win.y < 1.57 ? tan(win.y) : 1e30);
#endif
    float near = near_horizon(p, zp, win_t);
    int dirs = sw + 2, cm = sw + 2 + nd, rot = sw + 2 + 17 * nd;
    /* the swath's rays searched at once as far as they are clear: each
     * direction's own search starts there (its start is near or above) */
    float t_from = u_near_to;
    if (u_sub > 1 && u_whole != 0 && u_near_dir == 0 && nd > 1 && near < win_t.y) {
        vec4 cr = vec4(1.0, -1.0, 1.0, -1.0);
        for (int j = 0; j < nd; ++j) {
            vec2 cs = KREC(dirs + j).xy;
            cr = vec4(min(cr.x, cs.x), max(cr.y, cs.x), min(cr.z, cs.y), max(cr.w, cs.y));
        }
        t_from = wedge_clear(p, zp, near, u_near_to, cr);
    }
#ifdef HFS_TABLES
    vec4 Vk[4], Vo[4];
    for (int g = 0; g < 4; ++g) {
        Vk[g] = vec4(0.0);
        Vo[g] = vec4(0.0);
    }
    float om_prev = 0.0, fl_prev = 0.0, om_first = 0.0, fl_first = 0.0;
    /* One table lookup per wedge between consecutive directions, with a
     * closing step j = nd: from direction nd - 1 back to direction 0 on a
     * full circle, or to the swath's boundary (a boundary table, as at
     * j = 0) on a partial one.  One call site per sum keeps the program
     * the program quick to compile (BENCHMARKS.md "The CI's time", session 43). */
    for (int j = 0; j <= nd; ++j) {
        float om = om_first, fl = fl_first;
        if (j < nd) {
            vec4 dj = KREC(dirs + j);
            fl = atan(-(n.x * dj.x + n.y * dj.y), n.z);
            om = min(key_horizon(cell, n, dj.xy, fl, layer0 + float(j), near, win_t.y, t_from,
                                 p, zp),
                     HFS_HALF_PI);
        }
        if (j == 0) {
            om_first = om;
            fl_first = fl;
        }
        bool edge = !full && (j == 0 || j == nd);
        if (j > 0 || !full) {
            int at = rot + 2 * (full ? j - 1 : j);
            tab_add(Vk, j == 0 ? om : om_prev, edge ? 0.0 : om, edge, at, h0.w);
            tab_add(Vo, j == 0 ? fl : fl_prev, edge ? 0.0 : fl, edge, at, h0.w);
        }
        om_prev = om;
        fl_prev = fl;
    }
    float num = hfs_sh_dot(Vk, M), den = hfs_sh_dot(Vo, M);
    float vo_norm = sqrt(hfs_sh_dot(Vo, Vo));
#else
    /* V.M = sum_j v_j . w_j, w_j = C_j^T M = A_j Y(N) (the swath's
     * matrices come folded with the light and the clamped cosine,
     * uniform_blocks.c fold_key_matrices: no SH product per texel, 9 terms
     * a direction), serves num and den.  |V_open| (the threshold's scale) is bounded by
     * sum_j |C_j|_F |v_open_j| (KREC(dirs + j).z), so a den that the CPU's
     * test 1e-12 |L| |V_open| calls zero is zero here too. */
    float num = 0.0, den = 0.0, vo_norm = 0.0;
    for (int j = 0; j < nd; ++j) {
        vec4 dj = KREC(dirs + j);
        float fl = atan(-(n.x * dj.x + n.y * dj.y), n.z);
        float om = min(key_horizon(cell, n, dj.xy, fl, layer0 + float(j), near, win_t.y, t_from,
                                   p, zp),
                       HFS_HALF_PI);
        int c = cm + 16 * j;
        vec4 w = y[0].x * KREC(c) + y[0].y * KREC(c + 1) + y[0].z * KREC(c + 2) +
                 y[0].w * KREC(c + 3) + y[1].x * KREC(c + 4) + y[1].y * KREC(c + 5) +
                 y[1].z * KREC(c + 6) + y[1].w * KREC(c + 7) + y[2].x * KREC(c + 8);
        vec4 vo = hfs_visible(fl, win, occtop);
        num += dot(hfs_visible(om, win, occtop), w);
        den += dot(vo, w);
        vo_norm += dj.z * length(vo);
    }
#endif
    float ratio = 0.0;
    if (den > 1e-12 * h2.w * vo_norm)
        ratio = clamp(num / den, 0.0, 1.0);
    return e_cap * ratio;
}


/* Whether the ray p + t cs, 0 <= t <= t_max, crosses the edit's box where
 * an occluder as high as its top (dz above p, texel units) could rise
 * above slope sl: the slab test's entry and exit, the bound dz / t at the
 * nearer for a rise, at the farther for a fall. */
bool edit_ray(vec2 p, vec2 cs, float t_max, float dz, float sl)
{
    vec2 t;
    return hfs_ray_box(p, cs, u_edit_box, t_max, t) && dz / max(dz >= 0.0 ? t.x : t.y, 1e-6) > sl;
}

/* Whether an edit of the heights can change texel p's factor (issue 38):
 * p near the changed texels (its normal, its own cell and neighbours), or a
 * sample of its searches - the near search along u_near_cs, each
 * direction's ray to u_edge - that reads them and could rise above the
 * light's lowest slope (where every search starts: a sample below it never
 * moves the result) less edit_region.h's margin. */
bool edit_reaches(ivec2 p, vec2 zp)
{
    vec2 q = vec2(p);
    if (all(greaterThanEqual(q, u_edit_box.xy)) && all(lessThanEqual(q, u_edit_box.zw)))
        return true;
    int b = u_kb, sw = b + 7, nd = int(KREC(b).x);
#ifdef HFS_TABLES
    float sl = -1e30;
#else
    float sl = tan(max(KREC(sw).x, -1.5));
#endif
    sl -= 1e-3 * (1.0 + abs(sl));
    float dz = (u_edit_top - hfs_h(zp)) * u_rise;
    if (u_near_dir == 0 && u_near > 0 &&
        edit_ray(q, u_near_cs, max(u_near_to, 2.0 * u_reach) + 2.0, dz, sl))
        return true;
    for (int j = 0; j < nd; ++j)
        if (edit_ray(q, KREC(sw + 2 + j).xy, u_edge, dz, sl))
            return true;
    return false;
}

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec2 zp = hfs_height_at(u_height, p);
    if (u_edit != 0 && !edit_reaches(p, zp))
        discard;
    /* the normal and the one-sided slopes (g_ns, -1e30 off the field)
     * from the 4 neighbours' heights, read once */
    vec4 side;
    bvec4 side_on;
    vec3 n = hfs_normal_sides(u_height, p, u_size, u_zf, zp, side, side_on);
    vec4 H[4];
    hfs_sh_cosine(n, H);
    g_ns = mix(vec4(-1e30), u_rise * side, side_on);
    g_fetches = 5; /* its height and the 4 neighbours' */
    float f = clamp(key_factor(u_kb, n, H, grid_cell(p, zp), p, zp) / u_emax, 0.0, 1.0);
#ifdef HFS_COUNT
    o_f = vec4(float(g_fetches % 1024), float(g_fetches / 1024), 0.0, 1.0);
#else
    o_f = vec4(hfs_split(f), 0.0, 1.0);
#endif
}
