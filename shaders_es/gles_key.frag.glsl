/*
 * gles_key.frag - key-light horizons on a swath (DESIGN.md "Horizons": the
 * B-spline max over scale).  One fragment per receiver of the visibility
 * grid; directions [u_dir0, u_dir0 + u_ndir) of the light's swath, two per
 * RGBA target, up to HFS_NOUT targets.  Per direction it writes the horizon
 * EXCESS over the receiver's floor, omega - floor >= 0 (0 where nothing
 * rises above the tangent plane), as an fp16 (hi, lo) pair: the shading
 * pass adds it to the floor of each full-resolution normal, so unoccluded
 * texels stay exactly unoccluded whatever the sub-sampling, and a key
 * light's narrow elevation window (a few degrees) does not see fp16's
 * 2^-11 rounding of the angle (DESIGN.md "GLES path").
 *
 * Per scale omega_i = atan(D_i) in-grid and the floor off-grid; scales run
 * fine to coarse and stop fetching at the first off-grid sample (all
 * farther ones are off-grid too and contribute the floor).  The receiver's
 * own heights are fetched once per level.
 *
 * HFS_COUNT: writes the fetch count to o_h0 instead (see gles_env.frag).
 */
// hfs-variant: HFS_NOUT 4
// hfs-variant: HFS_FP32 1, HFS_COUNT 1

#ifndef HFS_NLEV
#define HFS_NLEV 33
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

precision highp float;
precision highp int;
precision highp sampler2D;
precision highp sampler2DArray;

float hfs_h(vec2 t);
float hfs_hdiff(vec2 a, vec2 b);
vec3 hfs_normal(vec4 t);
vec2 hfs_snap(vec2 o);
vec2 hfs_split(float v);

uniform highp sampler2DArray u_levels;
uniform highp sampler2D u_normals;
uniform ivec2 u_size;
uniform int u_sub;
uniform int u_dir0;                      /* first direction of this pass */
uniform int u_ndir;                      /* directions in this pass, <= 2 * HFS_NOUT */

layout(std140) uniform HfsScales {
    vec4 u_scale[HFS_NLEV];
};
layout(std140) uniform HfsSwath {        /* the light's swath (prefix) */
    vec4 u_win;
    vec4 u_occtop;
    vec4 u_dir[HFS_NDIR];
};

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

void main()
{
    ivec2 g = min(ivec2(gl_FragCoord.xy) * u_sub, u_size - 1);
    vec3 n = hfs_normal(texelFetch(u_normals, g, 0));
    int fetches = 1;

    vec2 hx[HFS_NLAYERS];
    for (int l = 0; l < HFS_NLAYERS; ++l)
        hx[l] = texelFetch(u_levels, ivec3(g, l), 0).xy;
    fetches += HFS_NLAYERS;

    vec2 inv_size = 1.0 / vec2(u_size);
    vec2 gc = vec2(g) + 0.5;
    ivec2 last = u_size - 1;
    float ex[2 * HFS_NOUT];
    for (int q = 0; q < 2 * HFS_NOUT; ++q)
        ex[q] = 0.0;

    for (int q = 0; q < u_ndir; ++q) {
        vec2 cs = u_dir[u_dir0 + q].xy;
        float fl = atan(-(n.x * cs.x + n.y * cs.y), n.z);
        /* Per-scale angles from fine (i = N-1) to coarse, and on the fly the
         * B-spline over the scale index at every knot and midpoint, indices
         * clamped (runtime/cpu_horizon.c hfs_horizon_bspline_max, same
         * expressions): after om[i] arrives, w0..w3 = om[i..i+3] and knot
         * i+1 and midpoint i+1 are complete.  Past the grid every angle is
         * the floor: three more steps flush the window, then nothing can
         * exceed the floor any more. */
        float best = fl, w0 = fl, w1 = fl, w2 = fl, w3 = fl;
        int tail = 3;
        int i = HFS_NLEV - 1;
        for (; i >= 0; --i) {
            float a = fl;
            if (tail == 3) {
                vec4 sc = u_scale[i];
                vec2 o = hfs_snap(sc.x * cs);
                vec2 io = floor(o);
                ivec2 p = g + ivec2(io);
                ivec2 lim = last - ivec2(notEqual(o, io));
                if (any(lessThan(p, ivec2(0))) || any(greaterThan(p, lim))) {
                    --tail;
                } else {
                    vec2 h = hx[int(sc.z)];
                    vec2 t = texture(u_levels, vec3((gc + o) * inv_size, sc.z)).xy;
                    a = atan(hfs_hdiff(t, h) * sc.y);
                    ++fetches;
                }
            } else if (--tail < 0) {
                break;
            }
            if (i == HFS_NLEV - 1) {
                w0 = w1 = w2 = w3 = a;
                continue;
            }
            w3 = w2;
            w2 = w1;
            w1 = w0;
            w0 = a;
            best = max(best, w1 + ((w0 - w1) + (w2 - w1)) / 6.0);                 /* knot i+1 */
            if (i + 2 < HFS_NLEV)
                best = max(best, w1 + ((w0 - w1) + 23.0 * (w2 - w1) + (w3 - w1)) / 48.0);
        }
        if (i < 0) {
            /* Knot 0 and midpoint 0 (om[-1] clamps to om[0]). */
            best = max(best, w0 + ((w0 - w0) + (w1 - w0)) / 6.0);
            if (HFS_NLEV > 1)
                best = max(best, w0 + ((w0 - w0) + 23.0 * (w1 - w0) + (w2 - w0)) / 48.0);
        }
        best = clamp(best, -HFS_HALF_PI, HFS_HALF_PI);
        ex[q] = max(best - fl, 0.0);
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
    o_h0 = vec4(hfs_split(ex[0]), hfs_split(ex[1]));
#if HFS_NOUT > 1
    o_h1 = vec4(hfs_split(ex[2]), hfs_split(ex[3]));
#endif
#if HFS_NOUT > 2
    o_h2 = vec4(hfs_split(ex[4]), hfs_split(ex[5]));
#endif
#if HFS_NOUT > 3
    o_h3 = vec4(hfs_split(ex[6]), hfs_split(ex[7]));
#endif
#endif
}
