/*
 * hfshade_inputs.h — the inputs of every render call of libhfshade: the
 * height field, the lighting (environment, key lights, local lights,
 * albedo, bounces, glossy surfaces) and the quality settings with their
 * defaults and presets.  Part of the public interface: hfshade.h includes
 * it, and users include <hfshade.h> (the conventions stated there, radians
 * and world units, hold here too).
 */
#ifndef HFSHADE_INPUTS_H
#define HFSHADE_INPUTS_H

#ifndef HFSHADE_H
#error "include <hfshade.h>, which includes hfshade_inputs.h"
#endif

/* ---- height field -------------------------------------------------------- */

/* A height grid as loaded; holes are already filled (see hfs_io.h).
 * Immutable view: the caller owns z. */
typedef struct hfs_field {
    int width;        /* W >= 2 (columns, x)                                */
    int height;       /* Hh >= 2 (rows, y)                                  */
    const float *z;   /* W*Hh finite heights, row-major, row j = 0 first    */
    double dx;        /* world units per texel (> 0)                        */
    double zscale;    /* world z = zscale * z (>= 0)                        */
} hfs_field;

/* ---- lights -------------------------------------------------------------- */

#define HFS_SH_COEFFS 16
#define HFS_MAX_KEY_LIGHTS 8
#define HFS_MAX_LOCAL_LIGHTS 16

/* Distant disk light: direction (phi, elev), angular radius alpha, uniform
 * radiance over the disk. */
typedef struct hfs_key_light {
    double phi, elev, alpha; /* radians; alpha in (0, pi/2)                 */
    float radiance[3];       /* linear RGB, >= 0                            */
    int disabled;            /* non-zero: ignored (costs nothing)           */
    int from_env;            /* non-zero: extracted from the environment map
                                (env_decompose.h); the truth, which
                                integrates lighting->env_map itself, skips it */
} hfs_key_light;

/* Local spherical light: centre in world units, radius, uniform radiance
 * over the cap it subtends.  Occluded only between receiver and light. */
typedef struct hfs_local_light {
    double pos[3];
    double radius;           /* world units, >= 0                            */
    float radiance[3];
    int disabled;
} hfs_local_light;

typedef struct hfs_lighting {
    /* Environment: 16 SH coefficients per channel (SPEC basis), rotated about
     * +z by env_rotate before use.  has_env = 0 means no environment. */
    int has_env;
    double env_sh[3][HFS_SH_COEFFS];
    double env_rotate;       /* radians */
    /* The environment map itself (SPEC "Lights": a map's radiance is the
     * map, piecewise constant per pixel): NULL (default) or env_map_width x
     * env_map_height x 3 finite linear RGB values (negative ones, which some
     * HDR files hold, count as they are), equirectangular
     * as SPEC "Directions" (column u -> phi = 2 pi u, row 0 = zenith), rows
     * first like albedo_map; sizes >= 1.  Needs has_env, with env_sh its SH
     * projection (hfs_sh_project_equirect; the scene layer does both).  Only
     * the ground truth reads it: it integrates the map pixel by pixel
     * (DESIGN.md "Ground truth of an environment map") instead of env_sh,
     * rotated about +z by env_rotate exactly as env_sh (a pixel at azimuth
     * phi moves to phi + env_rotate), and skips the key lights marked
     * from_env; the CPU reference and GLES use env_sh and those lights.
     * Read during hfs_renderer_render only; the caller owns it. */
    const float *env_map;
    int env_map_width, env_map_height;
    /* The environment as the CPU reference and GLES shade it (issue 17;
     * DESIGN.md "Shading from the map itself").  Order 4 holds a map's
     * light only up to the bands it drops, and the drop covers the whole
     * image; with these two the diffuse environment term comes from the
     * map instead, and a glossy surface's lobe too (its visibility is
     * still order 4):
     *   env_open: NULL (default) or the table hfs_env_open_build writes
     *     (env_open.h: 33 x 33 normals x RGB, D(N) = the map's unshadowed
     *     irradiance minus env_sh's, in the map's frame), added to the
     *     environment's term (turned with env_rotate): an open texel gets
     *     the map's own irradiance;
     *   env_shade_map: NULL (default) or the map whose projection env_sh is
     *     (env_map itself, or with lights decomposed from it their
     *     residual), env_map_width x env_map_height; needs env_open.  On
     *     the exact-slice path (HFS_VIS_SLICE) each slice's occluded part
     *     is then integrated against this map along the slice
     *     (env_map_slices.h) instead of against env_sh.  On every path a
     *     glossy surface (specular > 0) reflects this map convolved with
     *     its lobe: the renderers build the table of env_gloss.h from it,
     *     env_sh and gloss.
     * The truth ignores both (it integrates env_map, or env_sh without
     * it).  The scene layer builds them for an env-map (scene key
     * env-shade = map).  Read during hfs_renderer_render only; the caller
     * owns them. */
    const float *env_open;
    const float *env_shade_map;

    int n_key;
    hfs_key_light key[HFS_MAX_KEY_LIGHTS];
    int n_local;
    hfs_local_light local[HFS_MAX_LOCAL_LIGHTS];

    double albedo;           /* Lambertian albedo rho, default 1 */
    /* Per-texel albedo (SPEC "Albedo"): NULL (default) or W*H*3 linear RGB
     * values in [0, 1], row-major like the heights (row j = 0 first); the
     * albedo of texel (i, j) is then albedo * albedo_map[3 (j W + i) + c].
     * Read during hfs_renderer_render only; the caller owns it. */
    const float *albedo_map;
    /* Indirect diffuse bounces (SPEC "Indirect light"), 0..3, default 0:
     * the ground truth path-traces them, the CPU reference and the GLES
     * backend gather them along the environment's azimuths (quality
     * nphi_bounce, bounce_refine; GLES on the bounce_subsample grid). */
    int bounces;
    /* Glossy surfaces (SPEC "Glossy", DESIGN.md "Glossy surfaces"): an
     * energy-normalized Phong lobe beside the Lambertian term,
     * f_s = specular (gloss+2)/(2 pi) max(0, R.w)^gloss, R the view
     * direction reflected about the texel's normal.  specular in [0, 1]
     * (albedo + specular <= 1), default 0 = diffuse only (the old output,
     * bit for bit); gloss >= 1, default 32; view_dir: unit vector towards
     * the viewer, z > 0, default (0, 0, 1).  Not multiplied by albedo_map.
     * view_from_eye non-zero: a viewer at a point instead (a perspective
     * camera; hfs_renderer_render_view sets it), each texel's view
     * direction towards view_eye (world units: x = i dx, y = j dx,
     * z = zscale h); view_dir is then unused (still checked). */
    double specular;
    double gloss;
    double view_dir[3];
    int view_from_eye;
    double view_eye[3];
} hfs_lighting;

/* No environment, no lights, albedo 1. */
HFS_API void hfs_lighting_defaults(hfs_lighting *l);

/* ---- quality settings ----------------------------------------------------- */

typedef enum hfs_backend {
    HFS_BACKEND_DEFAULT = 0, /* = GLES, the product                         */
    HFS_BACKEND_GLES,
    HFS_BACKEND_CPU,
    HFS_BACKEND_TRUTH
} hfs_backend;

/* How horizons become SH visibility (docs/DESIGN.md). */
typedef enum hfs_visibility_path {
    HFS_VIS_LEGENDRE = 1,    /* NS09: Legendre occlusion vector + M_lin,
                                with the light's elevation window           */
    HFS_VIS_WEDGE_TABLE,     /* SN08: 2D/1D tabulated visibility wedges     */
    HFS_VIS_SLICE            /* exact per-slice lighting of the environment
                                (slice_light.h, issue 15; default); key and
                                local lights as HFS_VIS_LEGENDRE           */
} hfs_visibility_path;

/* Texture precision of the GLES path: fp16 is the product (profile
 * es30-half); fp32 is for comparison and needs EXT_color_buffer_float. */
typedef enum hfs_precision {
    HFS_PRECISION_FP16 = 1,
    HFS_PRECISION_FP32
} hfs_precision;

/* Start from hfs_quality_defaults() (which sets EVERY field) and change what
 * you need; 0 is then a real value where a field allows it (offset = 0).
 * The defaults are the "kiosk" preset (hfs_quality_preset), picked from the
 * measured error/time front: the exact slice path, k=2, offset=8 (every
 * scale within 256 texels reads the heights themselves), 12 env / 3 key
 * directions, 4 refining samples per horizon, subsample 2, split horizons
 * (SN08/NS09 used Legendre at k=4, offset=2, 32 directions: dominated on
 * every benchmark scene, BENCHMARKS.md "Run time against error"). */
typedef struct hfs_quality {
    int k;                   /* pyramid level step (levels per octave), 2   */
    int offset;              /* level offset o (levels biased by k*o), 8    */
    int nphi_env;            /* azimuth samples, environment (full swath) 12 */
    int nphi_key;            /* azimuth samples per key light swath, 3      */
    int refine;              /* samples refining each environment and key-
                                light horizon between the pyramid's scales,
                                about the highest, 4; 0: the seeds' (plain
                                max for the environment, SN08's B-spline
                                max over scale for key lights)              */
    int split;               /* split horizons (slice path; DESIGN.md
                                "Split horizons"), 1: the environment's
                                horizons beyond far_from texels come from a
                                coarser grid (far_step) at far_dirs sub-
                                directions per direction, each slice the
                                mean over them; 0: one horizon per
                                direction (before issue 15's last part), 1  */
    int far_from;            /* texels; 0: by subsample, 8 at 1, 16 at 2, 4 */
    int far_dirs;            /* 1..8; 0: by subsample, 3 at 1, 2 at 2, 4    */
    int far_step;            /* the far grid's step, texels, 1..64; 0: by
                                subsample, 2 at 1, 8 at 2, 16 at 4          */
    int nphi_bounce;         /* azimuths the indirect bounces gather along:
                                the largest divisor of nphi_env not above
                                it, every (nphi_env / that)-th environment
                                direction (so that the direct horizons cap
                                them), 12                                   */
    int bounce_refine;       /* samples after each scale of the bounces'
                                walk, 1                                     */
    int bounce_subsample;    /* grid step of the GLES path's bounce gather
                                1|2|4|8, at least subsample's (the gathered
                                light is scaled to each texel's own
                                occluded part), 4                           */
    int bounce_near;         /* on a sub-sampled bounce grid, the GLES path
                                gathers each texel's own cell and the scales
                                within this many texels at the texel itself
                                and only the rest on the grid (0: the whole
                                gather on the grid), 2                      */
    int nphi_local;          /* azimuth samples per local light's full swath, 16 */
    int local_full_swath;    /* 0: per-receiver partial swath where the light
                                does not surround the receiver (default);
                                1: always the full swath (the thesis)        */
    int subsample;           /* visibility grid step 1|2|4 (GLES path: env,
                                key and local-light visibility), 2          */
    hfs_precision precision; /* texture precision of the GLES path          */
    hfs_visibility_path visibility; /* HFS_VIS_SLICE                        */
    int threads;             /* CPU/truth worker threads; 0 = all cores     */

    /* Ground truth only. */
    int truth_azimuths;      /* exact horizons at this many azimuths, 720   */
    int truth_elev_order;    /* Gauss-Legendre points per elevation span, 16 */
    int truth_light_samples; /* stratified samples per key/local light, 256  */
} hfs_quality;

/* Overwrite every field with its default (= the "kiosk" preset). */
HFS_API void hfs_quality_defaults(hfs_quality *q);

/* Settings per use, picked from the measured front of error against
 * full-frame time over cones, fractal terrain and the real DEM at 256^2
 * under the demo lighting (BENCHMARKS.md "Run time against error",
 * tools/bench_pareto.sh; tools/bench_front.h states the rules):
 *   "kiosk"     the most accurate setting whose worst full frame fits
 *               100 ms on the reference device (the defaults);
 *   "panel"     the most accurate setting within 500 ms;
 *   "headless"  the fastest setting whose worst mean error is <= 3% of
 *               the unshadowed maximum (CI and batch checks).
 * Fields a preset does not set keep hfs_quality_defaults().  Returns 0, or
 * HFS_E_INVALID for an unknown use (q then holds the defaults). */
HFS_API int hfs_quality_preset(hfs_quality *q, const char *use);

#endif /* HFSHADE_INPUTS_H */
