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
 * HFS_COUNT: instead of V, write the number of texture fetches made
 * (o_v0 = (count mod 1024, floor(count / 1024), 0, 0)), for measurement.
 */
// hfs-variant: HFS_TABLES 1
// hfs-variant: HFS_FP32 1, HFS_COUNT 1
// hfs-variant: HFS_SWATH_TEX 1
// hfs-variant: HFS_SWATH_TEX 1, HFS_TABLES 1
// hfs-variant: HFS_SLICE 1
// hfs-variant: HFS_SLICE 1, HFS_SWATH_TEX 1

#ifndef HFS_NLEV
#define HFS_NLEV 33
#endif
#ifndef HFS_NLAYERS
#define HFS_NLAYERS 25
#endif
#ifndef HFS_NDIR
#define HFS_NDIR 32
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
vec3 hfs_normal(vec4 t);
ivec2 hfs_receiver(ivec2 size, int sub);
void hfs_receiver_heights(highp sampler2DArray levels, ivec2 g, out vec2 hx[HFS_NLAYERS]);
bool hfs_scale_offset(ivec2 g, ivec2 size, float d, vec2 cs, out vec2 o);
float hfs_scale_slope(highp sampler2DArray levels, ivec2 g, ivec2 size, vec2 o, vec4 sc, vec2 h);
vec4 hfs_nlp_occ_tan(float t);
vec4 hfs_f16v(vec4 v);
void hfs_sh_hemisphere(vec3 n, out vec4 h[4]);
float hfs_table_coord(float omega, float n);
void hfs_table_add(highp sampler2DArray tab, vec2 uv, float layer0, bool mirror, vec3 c,
                   vec3 s, inout vec4 V[4]);

uniform highp sampler2DArray u_levels;   /* R_L, layer L - lmin, RG hi+lo, LINEAR */
uniform highp sampler2D u_normals;       /* full resolution, texelFetch */
#ifdef HFS_TABLES
uniform highp sampler2DArray u_tab;      /* interior table, 4 layers (k/4) */
#endif
uniform ivec2 u_size;                    /* W, H */
uniform int u_sub;                       /* visibility grid step */
uniform float u_vmax;                    /* largest normalized height, a hair up */

layout(std140) uniform HfsScales {
    vec4 u_scale[HFS_NLEV];              /* (d_i, inv_run_i, layer, 0) */
};
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
#define SW_P(i) SW(2 + HFS_NDIR + (i))
#else
layout(std140) uniform HfsSwath {
    vec4 u_win;                          /* (elev_lo, elev_hi, n, full) */
    vec4 u_occtop;
    vec4 u_dir[HFS_NDIR];                /* (cos, sin, 0, 0) */
#ifdef HFS_SLICE
    vec4 u_P[28 * HFS_NDIR];             /* dphi P_km(phi_j): vec4 28 j + 4 m + k/4 */
#else
    mat4 u_C[HFS_NDIR * 4];              /* folded M_lin, rows as columns */
    vec4 u_rot[2 * HFS_NDIR + 2];        /* per wedge (cos ma, mirror), (sin ma) */
#endif
};
#define SW_P(i) u_P[i]
#define SW_OCCTOP u_occtop
#define SW_DIR(j) u_dir[j]
#define SW_C(k) u_C[k]
#define SW_ROT(i) u_rot[i]
#endif

layout(location = 0) out vec4 o_v0;
layout(location = 1) out vec4 o_v1;
layout(location = 2) out vec4 o_v2;
layout(location = 3) out vec4 o_v3;

#ifdef HFS_TABLES
/* V += placement of the interior wedge table(a, b). */
void add_wedge(inout vec4 V[4], float a, float b, int w)
{
    float n = float(HFS_TABLE_N);
    hfs_table_add(u_tab, vec2(hfs_table_coord(a, n), hfs_table_coord(b, n)), 0.0, false,
                  SW_ROT(2 * w).xyz, SW_ROT(2 * w + 1).xyz, V);
}
#endif

#ifdef HFS_SLICE
/* Exact slice lighting (runtime/slice_light.h): g[m] = Int_x^{pi/2} f_m(e)
 * (a cos e + b sin e) cos e de, f = (1, cos e, sin e, cos 2e, sin 2e,
 * cos 3e, sin 3e), in closed form (the table of slice_light.c). */
void slice_g(float a, float b, float x, out float g[7])
{
    float c1 = cos(x), s1 = sin(x);
    float c2 = c1 * c1 - s1 * s1, s2 = 2.0 * s1 * c1;
    float c3 = c2 * c1 - s2 * s1, s3 = s2 * c1 + c2 * s1;
    float c4 = c3 * c1 - s3 * s1, s4 = s3 * c1 + c3 * s1;
    float c5 = c4 * c1 - s4 * s1, s5 = s4 * c1 + c4 * s1;
    float J0 = HFS_HALF_PI - x;
    float Jc1 = 1.0 - s1, Js1 = c1;
    float Jc2 = -s2 / 2.0, Js2 = (c2 + 1.0) / 2.0;
    float Jc3 = (-1.0 - s3) / 3.0, Js3 = c3 / 3.0;
    float Jc4 = -s4 / 4.0, Js4 = (c4 - 1.0) / 4.0;
    float Jc5 = (1.0 - s5) / 5.0, Js5 = c5 / 5.0;
    g[0] = a * (J0 + Jc2) / 2.0 + b * Js2 / 2.0;
    g[1] = a * (3.0 * Jc1 + Jc3) / 4.0 + b * (Js1 + Js3) / 4.0;
    g[2] = a * (Js1 + Js3) / 4.0 + b * (Jc1 - Jc3) / 4.0;
    g[3] = a * (J0 / 4.0 + Jc2 / 2.0 + Jc4 / 4.0) + b * Js4 / 4.0;
    g[4] = a * (Js2 / 2.0 + Js4 / 4.0) + b * (J0 - Jc4) / 4.0;
    g[5] = a * (Jc1 / 4.0 + Jc3 / 2.0 + Jc5 / 4.0) + b * (Js5 - Js1) / 4.0;
    g[6] = a * (Js1 / 4.0 + Js3 / 2.0 + Js5 / 4.0) + b * (Jc1 - Jc5) / 4.0;
}

/* V += the occluded part of slice j: the transfer between the tangent
 * plane (tan tf) and the horizon (tan tx), negated. */
void slice_add(int j, float a, float b, float tf, float tx, inout vec4 V[4])
{
    float gx[7], gf[7];
    slice_g(a, b, atan(tx), gx);
    slice_g(a, b, atan(tf), gf);
    for (int m = 0; m < 7; ++m) {
        float d = gx[m] - gf[m];
        int base = 28 * j + 4 * m;
        V[0] += d * SW_P(base);
        V[1] += d * SW_P(base + 1);
        V[2] += d * SW_P(base + 2);
        V[3] += d * SW_P(base + 3);
    }
}
#endif

void main()
{
    ivec2 g = hfs_receiver(u_size, u_sub);
    vec3 n = hfs_normal(texelFetch(u_normals, g, 0));
    vec2 hx[HFS_NLAYERS];
    hfs_receiver_heights(u_levels, g, hx);
    int fetches = 1 + HFS_NLAYERS;

    vec4 V[4];
    for (int q = 0; q < 4; ++q)
        V[q] = vec4(0.0);
#ifdef HFS_TABLES
    float om_first = 0.0, om_prev = 0.0;
#endif
    for (int j = 0; j < HFS_NDIR; ++j) {
        vec2 cs = SW_DIR(j).xy;
        /* Start at tan(floor): a slope below the tangent plane never wins. */
        float best = -(n.x * cs.x + n.y * cs.y) / n.z;
        for (int i = HFS_NLEV - 1; i >= 0; --i) {
            vec4 sc = u_scale[i];
            vec2 o;
            if (!hfs_scale_offset(g, u_size, sc.x, cs, o))
                break;
            vec2 h = hx[int(sc.z)];
            if ((u_vmax - hfs_h(h)) * sc.y <= best)
                continue;
            best = max(best, hfs_scale_slope(u_levels, g, u_size, o, sc, h));
            ++fetches;
        }
#ifdef HFS_TABLES
        float om = clamp(atan(best), -HFS_HALF_PI, HFS_HALF_PI);
        if (j == 0) {
            om_first = om;
        } else {
            add_wedge(V, om_prev, om, j - 1);
            fetches += 4;
        }
        om_prev = om;
#elif defined(HFS_SLICE)
        /* Exact: only slices whose horizon rises above the tangent plane
         * carry an occluded part (0 exactly elsewhere). */
        float tfl = -(n.x * cs.x + n.y * cs.y) / n.z;
        if (best > tfl)
            slice_add(j, n.x * cs.x + n.y * cs.y, n.z, tfl, best, V);
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
    o_v0 = vec4(float(fetches % 1024), float(fetches / 1024), 0.0, 0.0);
    o_v1 = vec4(0.0);
    o_v2 = vec4(0.0);
    o_v3 = vec4(0.0);
#else
#ifndef HFS_SLICE /* the slices' V is already the occluded transfer */
    vec4 hemi[4];
    hfs_sh_hemisphere(n, hemi);
    for (int q = 0; q < 4; ++q)
        V[q] -= hemi[q];
#endif
    o_v0 = hfs_f16v(V[0]);
    o_v1 = hfs_f16v(V[1]);
    o_v2 = hfs_f16v(V[2]);
    o_v3 = hfs_f16v(V[3]);
#endif
}
