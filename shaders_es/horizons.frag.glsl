/*
 * horizons.frag - the GIS horizons (hfshade.h hfs_renderer_horizons,
 * runtime/gles/horizons.c): for two azimuths a draw, each grid point's gap
 * search (gles_ray.frag hfs_gap_search_cells, the key lights' whole search
 * with every cell between crossings solved) over the ray within u_reach
 * texels, the near end of its own cell,
 * where it leaves the grid and where it reaches the radius, from the
 * point's own height; the
 * elevation angle atan(max slope) per azimuth as an fp16 (hi, lo) pair
 * (angle, 0 at fp32), -2 (below every angle, exact in fp16) where the
 * ray crosses nothing.  A window (u_window, hfs_horizon_desc's) starts the
 * search from its low slope and stops it at its high one; -2 then also
 * stands for nothing above the low end and 2 for the high end reached.
 */
// hfs-base: HFS_CELLS 1
// hfs-variant: HFS_FP32 1

precision highp float;
precision highp int;
precision highp sampler2D;

vec2 hfs_split(float v);
float hfs_hdiff(vec2 a, vec2 b);
vec2 hfs_height_at(highp sampler2DArray h, ivec2 p);
#define HFS_RAY_LEVELS 16
/* gles_ray.frag, compiled with HFS_CELLS 1 (runtime/gles/horizons.c) */
float hfs_gap_search_cells(highp sampler2DArray heights, highp sampler2D bounds,
                           ivec2 at[HFS_RAY_LEVELS], ivec2 size, ivec2 g, vec2 cs, float t_first,
                           float t_last, float zf, float tie, vec2 h0, float best, float stop,
                           inout float dist, inout int fetches);

uniform highp sampler2DArray u_height;   /* normalized heights (hi, lo) */
uniform highp sampler2D u_bounds;        /* the max pyramid's atlas */
uniform ivec2 u_rb_at[HFS_RAY_LEVELS];   /* level l's corner in the atlas */
uniform ivec2 u_size;                    /* W, H */
uniform float u_zf;                      /* normalized height to slope: hscale zscale / dx */
uniform float u_reach;                   /* texels searched */
uniform vec4 u_cs;                       /* (cos, sin) of the two azimuths */
uniform int u_pair;                      /* 0: the first azimuth alone (an odd count's last) */
uniform vec2 u_window;                   /* slopes: start from x, stop at y (-1e30, 1e30: all) */

layout(location = 0) out vec4 o_h;

/* The receiver's own cell as t -> 0: the surface there rises t (A + B t)
 * (B the cell's twist), so its slope is highest at t -> 0 or at the far
 * edge, which is the search's first crossing; this is the near end A
 * (runtime/core/field_geom.h hfs_field_first_cell_slope). -1e30 where the
 * cell lies off the grid. */
float near_slope(ivec2 p, vec2 cs, vec2 h0)
{
    ivec2 q = p + ivec2(sign(cs));
    if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, u_size)))
        return -1e30;
    float ax = hfs_hdiff(hfs_height_at(u_height, ivec2(q.x, p.y)), h0) * abs(cs.x);
    float ay = hfs_hdiff(hfs_height_at(u_height, ivec2(p.x, q.y)), h0) * abs(cs.y);
    return (ax + ay) * u_zf;
}

/* Where the ray leaves the grid through a side parallel to its major axis
 * (between two crossings), the surface's slope there
 * (runtime/cpu/cpu_horizons.c exit_slope); -1e30 when it leaves at a
 * crossing or past u_reach. */
float exit_slope(ivec2 p, vec2 cs, vec2 h0)
{
    bool xm = abs(cs.x) >= abs(cs.y);
    float ma = xm ? cs.x : cs.y, mi = xm ? cs.y : cs.x;
    int pp = xm ? p.x : p.y, q = xm ? p.y : p.x;
    int np = xm ? u_size.x : u_size.y, nq = xm ? u_size.y : u_size.x;
    int e = mi > 0.0 ? nq - 1 : 0;
    float t = mi != 0.0 ? float(e - q) / mi : -1.0;
    float pm = float(pp) + t * ma;
    if (!(t > 0.0 && t <= u_reach && pm >= 0.0 && pm <= float(np - 1)) || pm == floor(pm))
        return -1e30;
    int a = min(int(floor(pm)), np - 2);
    float fr = pm - float(a);
    vec2 za = hfs_height_at(u_height, xm ? ivec2(a, e) : ivec2(e, a));
    vec2 zb = hfs_height_at(u_height, xm ? ivec2(a + 1, e) : ivec2(e, a + 1));
    return (hfs_hdiff(za, h0) + fr * hfs_hdiff(zb, za)) * u_zf / t;
}

/* The surface where the ray reaches the radius, bilinear between its four
 * grid points (runtime/cpu/cpu_horizons.c end_slope); -1e30 past the grid
 * or with no radius. */
float end_slope(ivec2 p, vec2 cs, vec2 h0)
{
    vec2 e = vec2(p) + u_reach * cs, last = vec2(u_size - 1);
    if (u_reach >= 1e8 || any(lessThan(e, vec2(0.0))) || any(greaterThan(e, last)))
        return -1e30;
    ivec2 c = min(ivec2(floor(e)), u_size - 2);
    vec2 f = e - vec2(c);
    float d00 = hfs_hdiff(hfs_height_at(u_height, c), h0);
    float d10 = hfs_hdiff(hfs_height_at(u_height, c + ivec2(1, 0)), h0);
    float d01 = hfs_hdiff(hfs_height_at(u_height, c + ivec2(0, 1)), h0);
    float d11 = hfs_hdiff(hfs_height_at(u_height, c + ivec2(1, 1)), h0);
    float d = mix(mix(d00, d10, f.x), mix(d01, d11, f.x), f.y);
    return d * u_zf / u_reach;
}

float horizon(ivec2 p, vec2 cs, vec2 h0)
{
    float dist = 0.0;
    int fetches = 0;
    float best = hfs_gap_search_cells(u_height, u_bounds, u_rb_at, u_size, p, cs, 0.0, u_reach,
                                      u_zf, 0.0, h0,
                                      max(max(near_slope(p, cs, h0), u_window.x),
                                          max(exit_slope(p, cs, h0), end_slope(p, cs, h0))),
                                      u_window.y, dist, fetches);
    /* at the window's ends the sentinels, not atan(tan(lo)) a rounding off
     * lo: the host clamps them to lo and hi exactly (-2 also: no terrain) */
    return best >= u_window.y ? 2.0 : best > max(u_window.x, -1e29) ? atan(best) : -2.0;
}

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec2 h0 = hfs_height_at(u_height, p);
    float a = horizon(p, u_cs.xy, h0), b = u_pair != 0 ? horizon(p, u_cs.zw, h0) : a;
    o_h = vec4(hfs_split(a), hfs_split(b));
}
