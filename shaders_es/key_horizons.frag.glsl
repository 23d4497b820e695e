/*
 * key_horizons.frag - key-light horizons on a swath (DESIGN.md "Horizons": the
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
 * HFS_COUNT: writes the fetch count to o_h0 instead (see env_horizons.frag).
 */
// hfs-variant: HFS_NOUT 4
// hfs-variant: HFS_FP32 1, HFS_COUNT 1
// hfs-variant: HFS_SWATH_TEX 1

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

vec3 hfs_normal(vec4 t);
vec2 hfs_split(float v);
ivec2 hfs_receiver(ivec2 size, int sub);
void hfs_receiver_heights(highp sampler2DArray levels, ivec2 g, out vec2 hx[HFS_NLAYERS]);
float hfs_floor(vec3 n, vec2 cs);
bool hfs_scale_offset(ivec2 g, ivec2 size, float d, vec2 cs, out vec2 o);
float hfs_scale_slope(highp sampler2DArray levels, ivec2 g, ivec2 size, vec2 o, vec4 sc, vec2 h);
void hfs_bspline_push(inout float best, inout vec4 w, float a, int i);
float hfs_bspline_close(float best, vec4 w);

uniform highp sampler2DArray u_levels;
uniform highp sampler2D u_normals;
uniform ivec2 u_size;
uniform int u_sub;
uniform int u_dir0;                      /* first direction of this pass */
uniform int u_ndir;                      /* directions in this pass, <= 2 * HFS_NOUT */

layout(std140) uniform HfsScales {
    vec4 u_scale[HFS_NLEV];
};
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

void main()
{
    ivec2 g = hfs_receiver(u_size, u_sub);
    vec3 n = hfs_normal(texelFetch(u_normals, g, 0));
    vec2 hx[HFS_NLAYERS];
    hfs_receiver_heights(u_levels, g, hx);
    int fetches = 1 + HFS_NLAYERS;

    float ex[2 * HFS_NOUT];
    for (int q = 0; q < 2 * HFS_NOUT; ++q)
        ex[q] = 0.0;

    for (int q = 0; q < u_ndir; ++q) {
        vec2 cs = SW_DIR(u_dir0 + q).xy;
        float fl = hfs_floor(n, cs);
        /* Per-scale angles from fine to coarse into the B-spline max.  Past
         * the grid every angle is the floor: three more steps flush the
         * window, then nothing can exceed the floor any more. */
        float best = fl;
        vec4 w = vec4(fl);
        int tail = 3;
        int i = HFS_NLEV - 1;
        for (; i >= 0; --i) {
            float a = fl;
            if (tail == 3) {
                vec4 sc = u_scale[i];
                vec2 o;
                if (!hfs_scale_offset(g, u_size, sc.x, cs, o)) {
                    --tail;
                } else {
                    a = atan(hfs_scale_slope(u_levels, g, u_size, o, sc, hx[int(sc.z)]));
                    ++fetches;
                }
            } else if (--tail < 0) {
                break;
            }
            hfs_bspline_push(best, w, a, i);
        }
        if (i < 0)
            best = hfs_bspline_close(best, w);
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
