/*
 * uniform_blocks.h — the C side of the C-to-shader contract: every std140
 * uniform block the GLES passes read, packed by named fields, as pure
 * functions (unit-tested without a driver).
 *
 *   HfsScales   per-scale constants of the pyramid          (all grid passes)
 *   HfsSwath    a swath's directions, folded Legendre matrices
 *               (hfs_visibility_sample_matrix of the CPU reference) or wedge
 *               placements                     (env_horizons, key_horizons)
 *   HfsKeys     key-light records                              (key_visibility)
 *   HfsShade    the shading constants                                   (shade)
 *   HfsLocal    local lights                         (local_visibility, shade)
 *   offsets     the shader's float form of the sample offsets and a check
 *               that it classifies every (direction, scale) sample as the
 *               CPU reference's double form does (DESIGN.md, "GLES path").
 *
 * Each block's layout is documented at its struct or packer and mirrored by
 * the `layout(std140) uniform` declarations in shaders_es/; the fixed-size
 * ones are C structs whose offsets are pinned by _Static_assert.
 */
#ifndef HFS_GLES_UNIFORM_BLOCKS_H
#define HFS_GLES_UNIFORM_BLOCKS_H

#include <stddef.h>
#include <stdint.h>

#include "layout.h"
#include "visibility.h"
#include "hfshade.h"

/* ---- std140 blocks ---------------------------------------------------------- */

/* HfsScales: N vec4, scale i: (d_i, inv_run_i, read layer, 0) with
 * inv_run_i = hscale * zscale / (d_i * dx) (clamped to 1e30). */
size_t hfs_gles_scales_vec4(const hfs_gles_layout *L);
void hfs_gles_pack_scales(const hfs_gles_layout *L, float *dst);

/* HfsSwath for a swath of n samples (visibility object v):
 *   [0]            (elev_lo, elev_hi, n, full)
 *   [1]            NLP occlusion vector of elev_hi (visible band top)
 *   [2 .. 2+n)     (cos phi_j, sin phi_j, |C_j|_F, 0): the direction as
 *                  hfs_gles_swath_float_dirs gives it, the Frobenius norm
 *                  of C_j (0 for the table path)
 *   [2+n .. 2+17n) Legendre: C_j as 4 column-major mat4 (16 vec4, row r of
 *                  C_j at vec4 16j + r); zeros for the table path
 *   [2+17n ..)     n + 1 wedge placements, 2 vec4 each:
 *                  (cos a, cos 2a, cos 3a, mirror), (sin a, sin 2a, sin 3a, 0)
 *                  with a the wedge's placement angle (table path)
 * Total 2 + 17n + 2(n+1) vec4. */
size_t hfs_gles_swath_vec4(int n);
void hfs_gles_pack_swath(const hfs_gles_layout *L, const hfs_visibility *v, float *dst);

/* The direction (cos, sin) used for sample j, in double, snapped exactly as
 * cpu_horizon.c does (|c| < 1e-12 -> 0). */
void hfs_gles_swath_dir(const hfs_swath *s, int j, double *c, double *sn);

/* ---- sample offsets ---------------------------------------------------------- */

/* The shader computes sample offsets in float: o = float(d_i) * c_j per
 * component, snapped to round(o) when |o - round(o)| <= |o| * SNAP_REL +
 * SNAP_ABS (3 ulps of the product cover the rounding of d, c and the
 * product when the CPU's double offset is an integer), and decides in-grid
 * on floor and fraction exactly as cpu_horizon.c does.  A double offset that
 * merely lies within a few ulps of an integer (2^(31/4) cos(3 pi/32) =
 * 103.0000253...) would be snapped by the GPU and not by the CPU, so the
 * direction floats are chosen here: the nearest float to the CPU's snapped
 * (cos, sin), or a neighbour a few ulps away with which every scale is
 * classified like the CPU AND lies at least a factor 2 from the snapping
 * threshold (robust to a GPU that rounds the product differently by an
 * ulp).  cs receives 2n floats; returns the number of components for which
 * no such float exists within 64 ulps (0 in every configuration tested). */
#define HFS_GLES_SNAP_REL 4.8e-7f
#define HFS_GLES_SNAP_ABS 1e-9f
long hfs_gles_swath_float_dirs(const hfs_gles_layout *L, const hfs_swath *s, float *cs);

/* (direction, scale, component) samples the float rule, with the floats of
 * hfs_gles_swath_float_dirs, classifies differently from the CPU (or not
 * robustly); 0 means the GPU's in-grid decisions equal the CPU's for every
 * receiver. */
long hfs_gles_offset_mismatches(const hfs_gles_layout *L, const hfs_swath *s);

/* ---- key lights (shading pass block HfsKeys) ---------------------------------- */

/* A key light as the shading pass sees it: record offsets in vec4 units. */
typedef struct hfs_gles_key {
    hfs_swath swath;
    double dir[3], alpha, le[3];
    double l_sh[16], l_norm;  /* SH of the unit-radiance disk and its norm    */
    int hz_layer;             /* first layer of its horizon excess texture    */
    int table_set;            /* wedge table set (table path)                 */
} hfs_gles_key;

/* Record of key light q in HfsKeys (vec4 units, relative to its start):
 *   [0] (n, full, hz_layer, table_set)
 *   [1] (dir.xyz, alpha)
 *   [2] (Le.rgb, l_norm)
 *   [3..7) l_sh (16 floats)
 *   [7 ..) the light's HfsSwath block (hfs_gles_pack_swath)
 * Total 7 + hfs_gles_swath_vec4(n). */
size_t hfs_gles_key_vec4(int n);
void hfs_gles_pack_key(const hfs_gles_layout *L, const hfs_gles_key *k, const hfs_visibility *v,
                       float *dst);


/* The open part of the environment's transfer, H(N) * hemisphere(N) (the
 * SH product of the clamped cosine and the hemisphere about the normal),
 * is zonal about N: its coefficient (l, m) is k_l Y_lm(N).  Writes k_l for
 * each of the 16 coefficients (std140: 4 vec4) for the shading pass, which
 * adds it to the stored occluded part (env_transfer.frag). */
void hfs_gles_open_transfer(float dst[16]);

/* The shading pass's uniform block HfsShade (shade.frag.glsl), std140,
 * by name: every member is a vec4 array there, so the C layout (floats,
 * no padding) is the std140 one; the asserts pin the offsets the shader
 * relies on.  Radiances (env, env_neg, kle, lle) come multiplied by the
 * frame's power-of-two output scale. */
typedef struct hfs_gles_shade_block {
    float env[3][16];                   /* u_env[12]: L_env, 4 vec4 per channel  */
    float misc[4];                      /* u_misc: (rho/pi, 1, has env, 0)        */
    float env_neg[4];                   /* u_env_neg: rho * negative part of L_c  */
    float kle[HFS_MAX_KEY_LIGHTS][4];   /* u_kle[8]: rho/pi Le E_max per key      */
    float topen[16];                    /* u_topen[4]: k_l per coefficient        */
    float lle[HFS_MAX_LOCAL_LIGHTS][4]; /* u_lle[16]: Le per local light          */
} hfs_gles_shade_block;
_Static_assert(HFS_MAX_KEY_LIGHTS == 8 && HFS_MAX_LOCAL_LIGHTS == 16,
               "shade.frag.glsl declares u_kle[8] and u_lle[16]");
_Static_assert(offsetof(hfs_gles_shade_block, misc) == 12 * 16, "HfsShade.u_misc");
_Static_assert(offsetof(hfs_gles_shade_block, env_neg) == 13 * 16, "HfsShade.u_env_neg");
_Static_assert(offsetof(hfs_gles_shade_block, kle) == 14 * 16, "HfsShade.u_kle");
_Static_assert(offsetof(hfs_gles_shade_block, topen) == 22 * 16, "HfsShade.u_topen");
_Static_assert(offsetof(hfs_gles_shade_block, lle) == 26 * 16, "HfsShade.u_lle");
_Static_assert(sizeof(hfs_gles_shade_block) == 42 * 16, "HfsShade size");

/* The fixed head of the local-light block HfsLocal (local_visibility.frag.glsl and
 * shade.frag.glsl), std140, by name; u_ldir[nphi_local] follows it,
 * one vec4 (cos, sin, 0, 0) per direction of the full swath.  Lengths are in
 * texel units (dx = 1). */
typedef struct hfs_gles_local_block {
    float moments[16][4];   /* u_lE[16]: elevation moments, row r = E[r][0..3]     */
    float geom[4];          /* u_lg: (1, base, hscale, zscale / dx)                 */
    float swath[4];         /* u_lq: (nphi_local, forced full swath, 0, 0)          */
    float lights[HFS_MAX_LOCAL_LIGHTS][2][4]; /* u_lights: (centre.xyz, radius),
                                                 (-, -, -, open: no shadow possible) */
} hfs_gles_local_block;
_Static_assert(offsetof(hfs_gles_local_block, geom) == 16 * 16, "HfsLocal.u_lg");
_Static_assert(offsetof(hfs_gles_local_block, swath) == 17 * 16, "HfsLocal.u_lq");
_Static_assert(offsetof(hfs_gles_local_block, lights) == 18 * 16, "HfsLocal.u_lights");
_Static_assert(sizeof(hfs_gles_local_block) == (18 + 2 * 16) * 16, "HfsLocal head size");

#endif /* HFS_GLES_UNIFORM_BLOCKS_H */
