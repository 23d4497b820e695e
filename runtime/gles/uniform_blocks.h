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
 *   HfsView     the 3-D view's camera and sky                  (view, view_sky)
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
#include "slice_light.h"
#include "visibility.h"
#include "hfshade.h"

/* ---- std140 blocks ---------------------------------------------------------- */

/* HfsScales: a head holding the scale count N (u_nscales.x: the shaders
 * loop to it, so one program serves fields of any N), then u_scale[i], one
 * vec4 per scale i, declared HFS_SCALES_MAX (= HFS_GLES_MAX_LEVELS) long;
 * zeros past N. */
typedef struct hfs_gles_scales_head {
    int32_t n_scales; /* N                                                     */
    int32_t pad[3];
} hfs_gles_scales_head;
_Static_assert(sizeof(hfs_gles_scales_head) == 16, "HfsScales: u_nscales is an ivec4");
typedef struct hfs_gles_scale {
    float spacing;    /* d_i                                                  */
    float inv_run;    /* hscale * zscale / (d_i * dx), clamped to 1e30         */
    float read_layer; /* the reconstructed layer scale i reads                 */
    float pad;
} hfs_gles_scale;
_Static_assert(sizeof(hfs_gles_scale) == 16, "HfsScales: a vec4 per scale");

/* The block's size in vec4, one for every field (the head and
 * HFS_GLES_MAX_LEVELS scales), and L's scales packed into dst (that many
 * vec4). */
size_t hfs_gles_scales_vec4(void);
void hfs_gles_pack_scales(const hfs_gles_layout *L, float *dst);

/* HfsSwath for a swath of n samples (env_horizons.frag declares it whole;
 * key_horizons.frag its prefix; key_visibility.frag reads it inside a key
 * record), std140, in this order:
 *   head    u_win, u_occtop
 *   dir     u_dir[n]: the direction as hfs_gles_swath_float_dirs gives it
 *           and the Frobenius norm of C_j (0 for the table path)
 *   matrix  u_C[4n]: C_j (folded Legendre, hfs_visibility_sample_matrix) as
 *           4 column-major mat4, row r of C_j at vec4 16j + r; zeros on the
 *           table path
 *   rot     u_rot[2(n+1)]: per wedge its placement angle a for the tables
 * Total hfs_gles_swath_vec4(n) vec4. */
typedef struct hfs_gles_swath_head {
    float elev_lo, elev_hi, n, full; /* u_win: the elevation window, samples, full swath */
    float occ_top[4];                /* u_occtop: NLP occlusion vector of elev_hi        */
} hfs_gles_swath_head;
typedef struct hfs_gles_swath_sample {
    float cos, sin, c_norm, pad;
} hfs_gles_swath_sample;
typedef struct hfs_gles_swath_matrix {
    float row[16][4];
} hfs_gles_swath_matrix;
typedef struct hfs_gles_wedge_rot {
    float cos_ma[3], mirror;         /* (cos a, cos 2a, cos 3a, mirrored wedge)         */
    float sin_ma[3], pad;            /* (sin a, sin 2a, sin 3a, 0)                      */
} hfs_gles_wedge_rot;
_Static_assert(sizeof(hfs_gles_swath_head) == 2 * 16, "HfsSwath: u_win, u_occtop");
_Static_assert(sizeof(hfs_gles_swath_sample) == 16, "HfsSwath: u_dir[j] is a vec4");
_Static_assert(sizeof(hfs_gles_swath_matrix) == 16 * 16, "HfsSwath: C_j is 4 mat4");
_Static_assert(sizeof(hfs_gles_wedge_rot) == 2 * 16, "HfsSwath: 2 vec4 per wedge");

/* The parts of a swath block of n samples at dst (vec4-aligned). */
typedef struct hfs_gles_swath_block {
    hfs_gles_swath_head *head;
    hfs_gles_swath_sample *dir;       /* [n]     */
    hfs_gles_swath_matrix *matrix; /* [n]     */
    hfs_gles_wedge_rot *rot;       /* [n + 1] */
} hfs_gles_swath_block;
hfs_gles_swath_block hfs_gles_swath_view(float *dst, int n);
/* A wedge's placement: (cos m a, sin m a) for m = 1..3, and whether the
 * wedge is the mirrored table wedge (visibility.c table_placement). */
void hfs_gles_wedge_rot_set(hfs_gles_wedge_rot *r, double a, int mirror);

size_t hfs_gles_swath_vec4(int n);
void hfs_gles_pack_swath(const hfs_gles_layout *L, const hfs_visibility *v, float *dst);

/* HfsSwath of the slice path (env_horizons.frag, env_slices.frag): the
 * head and u_dir[n] as above, then u_coef[16]: per coefficient k, dphi
 * times its profile's terms (slice_light.h hfs_slice_profile) on the slots
 * of k's azimuthal factor, as env_slices.frag accumulates them:
 *   factor 1, cos 2phi, sin 2phi: f_0, f_2, f_3, f_6
 *   cos phi, sin phi:             f_1, f_4, f_5
 *   cos 3phi, sin 3phi:           f_1, f_5
 * (every other term of a profile is zero); then u_nearw[3 n]: per
 * direction the finest scale's bilinear sample (distance 1) as weights on
 * the 3 x 3 neighbourhood, row-major (9 floats in 3 vec4); then
 * u_trig[n]: per direction (cos 2phi, sin 2phi, cos 3phi, sin 3phi).
 * Total 2 + 16 + 5 n vec4. */
size_t hfs_gles_slices_vec4(int n);
/* The slices' block with only its head and directions (the rest 0): what
 * the far pass of split horizons reads (split_horizon.h), for swath s. */
void hfs_gles_pack_dirs(const hfs_gles_layout *L, const hfs_swath *s, float *dst);
void hfs_gles_pack_slices(const hfs_gles_layout *L, const hfs_visibility *v,
                          const hfs_slice_table *t, float *dst);

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
    int hz_layer;             /* first layer of its horizon texture           */
    int table_set;            /* wedge table set (table path)                 */
} hfs_gles_key;

/* Record of a key light in HfsKeys (key_visibility.frag reads it from
 * u_k[u_kb]): this head, then the light's HfsSwath block.  Total
 * hfs_gles_key_vec4(n) vec4. */
typedef struct hfs_gles_key_record {
    float n, full, hz_layer, table_set; /* the swath, its horizon layers, table set */
    float dir[3], alpha;                /* unit direction, angular radius          */
    float le[3], l_norm;                /* radiance, |l_sh|                        */
    float l_sh[16];                     /* SH of the unit-radiance disk            */
} hfs_gles_key_record;
_Static_assert(sizeof(hfs_gles_key_record) == 7 * 16,
               "key_visibility.frag: the swath block starts at u_k[u_kb + 7]");
size_t hfs_gles_key_vec4(int n);
void hfs_gles_pack_key(const hfs_gles_layout *L, const hfs_gles_key *k, const hfs_visibility *v,
                       float *dst);


/* The open part of the environment's transfer, H(N) * hemisphere(N) (the
 * SH product of the clamped cosine and the hemisphere about the normal),
 * is zonal about N: its coefficient (l, m) is k_l Y_lm(N).  Writes k_l for
 * each of the 16 coefficients (std140: 4 vec4) for the shading pass, which
 * adds it to the stored occluded part (env_transfer.frag). */
void hfs_gles_open_transfer(float dst[16]);

/* The same for the exact slice path (--visibility slice): there the open
 * part is the clamped cosine itself, H(N) (slice_light.h), whose (l, m)
 * coefficient is k_l Y_lm(N) with k_l from the clamped cosine's zonal
 * coefficients. */
void hfs_gles_cosine_transfer(float dst[16]);

/* The weights the occluded part of the transfer is dotted with (the sky
 * occlusion, env_slices.frag HFS_ENV_DOT, and shade.frag from a kept
 * T_occ: hfs_env_occ): each channel of the rotated sky l_env over its own
 * size m_c = sum_k |L_ck| (0 for a dark channel), into out[c][k]; m_c into
 * m[c].  The dot, |T_occ . L_c / m_c| <= max_k |T_occ,k| < 3.5, is then
 * stored in fp16 at a relative rounding that does not depend on the sky's
 * brightness (the image scales with the radiance, tools/hfstress), nor on
 * the other lights; the shading multiplies it by rho/pi m_c s. */
void hfs_gles_env_occ_weights(const double l_env[3][HFS_SH_N], float out[3][16], double m[3]);

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
    float emap[4];                      /* u_emap: env-shade = map's scales
                                           (rho/pi D_max, cos rot, sin rot,
                                           rho/pi F_max dphi), times s for
                                           the radiances                       */
    float envo[3][16];                  /* u_envo[12]: L_c / m_c, the occluded
                                           light's weights, and u_occs: its
                                           scale rho/pi m_c s per channel
                                           (hfs_gles_env_occ_weights)           */
    float occs[4];
    /* Glossy surfaces (gloss.h), read only by the HFS_GLOSSY variant (the
     * others declare the block up to u_envo: a prefix). */
    float gview[4];                     /* u_gview: (V, ks)                      */
    float gpar[4];                      /* u_gpar: (S, ks (S+2)/(2 pi), 0, 0)    */
    float gzh[16];                      /* u_gzh[4]: g_l per coefficient         */
    float kspec[HFS_MAX_KEY_LIGHTS][4]; /* u_kspec[8]: ks (S+2)/(2pi) Le E_max   */
    float kdir[HFS_MAX_KEY_LIGHTS][4];  /* u_kdir[8]: the disk's centre, unit    */
    /* A viewer at a point (HFS_GLOSSY 2, gloss.h at_eye), texel units. */
    float geye[4];                      /* u_geye: (eye x/dx, y/dx, z/dx, 0)     */
    float ghgt[4];                      /* u_ghgt: (base, hscale, zscale/dx, 0)  */
} hfs_gles_shade_block;
_Static_assert(HFS_MAX_KEY_LIGHTS == 8 && HFS_MAX_LOCAL_LIGHTS == 16,
               "shade.frag.glsl declares u_kle[8] and u_lle[16]");
_Static_assert(offsetof(hfs_gles_shade_block, misc) == 12 * 16, "HfsShade.u_misc");
_Static_assert(offsetof(hfs_gles_shade_block, env_neg) == 13 * 16, "HfsShade.u_env_neg");
_Static_assert(offsetof(hfs_gles_shade_block, kle) == 14 * 16, "HfsShade.u_kle");
_Static_assert(offsetof(hfs_gles_shade_block, topen) == 22 * 16, "HfsShade.u_topen");
_Static_assert(offsetof(hfs_gles_shade_block, lle) == 26 * 16, "HfsShade.u_lle");
_Static_assert(offsetof(hfs_gles_shade_block, gview) == 56 * 16, "HfsShade.u_gview");
_Static_assert(offsetof(hfs_gles_shade_block, gpar) == 57 * 16, "HfsShade.u_gpar");
_Static_assert(offsetof(hfs_gles_shade_block, gzh) == 58 * 16, "HfsShade.u_gzh");
_Static_assert(offsetof(hfs_gles_shade_block, kspec) == 62 * 16, "HfsShade.u_kspec");
_Static_assert(offsetof(hfs_gles_shade_block, kdir) == 70 * 16, "HfsShade.u_kdir");
_Static_assert(offsetof(hfs_gles_shade_block, geye) == 78 * 16, "HfsShade.u_geye");
_Static_assert(offsetof(hfs_gles_shade_block, ghgt) == 79 * 16, "HfsShade.u_ghgt");
_Static_assert(offsetof(hfs_gles_shade_block, emap) == 42 * 16, "HfsShade.u_emap");
_Static_assert(offsetof(hfs_gles_shade_block, envo) == 43 * 16, "HfsShade.u_envo");
_Static_assert(offsetof(hfs_gles_shade_block, occs) == 55 * 16, "HfsShade.u_occs");
_Static_assert(sizeof(hfs_gles_shade_block) == 80 * 16, "HfsShade size");

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

/* The head of HfsBounce (bounce_gather.frag.glsl), std140; u_edir[n]
 * follows it, one vec4 (cos, sin, 0, 0) per direction of the
 * environment's full swath as hfs_gles_swath_float_dirs gives them (the
 * directions of the grid's horizons, which cap the bands); the bounces
 * gather along every stride-th (lights.h hfs_bounce_dirs). */
typedef struct hfs_gles_bounce_head {
    float weight;   /* dphi / pi of the bounce directions          */
    float k;        /* the pyramid's levels per octave             */
    float stride;   /* environment directions per bounce direction */
    float pad;
} hfs_gles_bounce_head;
_Static_assert(sizeof(hfs_gles_bounce_head) == 16, "HfsBounce.u_bhead is one vec4");

/* HfsView (view.vert.glsl, view.frag.glsl, view_sky.frag.glsl,
 * view_objects.*.glsl; filled by runtime/gles/pass_view.c and view_sky.c),
 * std140, by name. */
typedef struct hfs_gles_view_block {
    float mvp[16];      /* u_mvp: eye-relative world -> clip, column-major     */
    float eye[4];       /* u_eye: eye (world), 1 for ortho                     */
    float zmap[4];      /* u_zmap: (z per normalized height, z offset, dx,
                           lit texture scale -> view scale)                    */
    float sizes[4];     /* u_sizes: (W, H, view w, view h)                     */
    float fwd[4];       /* u_fwd: forward, then the side walls' bottom z       */
    float right[4];     /* u_right: right * tan(fov/2) * w/h                   */
    float up[4];        /* u_up: up * tan(fov/2)                               */
    float env[3][16];   /* u_env[12]: sky SH times the view scale, per channel */
    /* The background and the haze (runtime/core/view_look.h; view_sky.c). */
    float bg[4];        /* u_bg: (mode: 0 SH sky, 1 map, 2 studio, 3 colour;
                           map texel -> view scale; env_rotate; 0)             */
    float bg_rgb[4];    /* u_bg_rgb: studio level or colour times the scale    */
    float haze[4];      /* u_haze: (sigma, z0, scale height, 0); sigma 0: off  */
    float haze_in[4];   /* u_haze_in: in-scattered radiance times the scale    */
} hfs_gles_view_block;
_Static_assert(offsetof(hfs_gles_view_block, eye) == 4 * 16, "HfsView.u_eye");
_Static_assert(offsetof(hfs_gles_view_block, zmap) == 5 * 16, "HfsView.u_zmap");
_Static_assert(offsetof(hfs_gles_view_block, sizes) == 6 * 16, "HfsView.u_sizes");
_Static_assert(offsetof(hfs_gles_view_block, fwd) == 7 * 16, "HfsView.u_fwd");
_Static_assert(offsetof(hfs_gles_view_block, right) == 8 * 16, "HfsView.u_right");
_Static_assert(offsetof(hfs_gles_view_block, up) == 9 * 16, "HfsView.u_up");
_Static_assert(offsetof(hfs_gles_view_block, env) == 10 * 16, "HfsView.u_env");
_Static_assert(offsetof(hfs_gles_view_block, bg) == 22 * 16, "HfsView.u_bg");
_Static_assert(offsetof(hfs_gles_view_block, bg_rgb) == 23 * 16, "HfsView.u_bg_rgb");
_Static_assert(offsetof(hfs_gles_view_block, haze) == 24 * 16, "HfsView.u_haze");
_Static_assert(offsetof(hfs_gles_view_block, haze_in) == 25 * 16, "HfsView.u_haze_in");
_Static_assert(sizeof(hfs_gles_view_block) == 26 * 16, "HfsView size");

#endif /* HFS_GLES_UNIFORM_BLOCKS_H */
