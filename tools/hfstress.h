/*
 * hfstress.h — numerical stability under extremes (issue 5): the pieces of
 * the hfstress tool.  docs/STRESS.md describes the cases, the checks, the
 * tolerances and why each bound has the size it has.
 *
 *   hfstress_cases.c   the case table and the scenes it builds (terrain,
 *                      lighting, quality; scaled copies for invariance);
 *   hfstress_checks.c  the checks on one image: non-finite count, the
 *                      unshadowed bound, differences, the fp16 bound;
 *   hfstress_backends.c  the renderers, made on first use and probed;
 *   hfstress.c         command line, the run and its report.
 */
#ifndef HFS_HFSTRESS_H
#define HFS_HFSTRESS_H

#include "hfshade.h"

#include <stddef.h>

/* ---- cases ------------------------------------------------------------------ */

typedef enum stress_terrain {
    TER_FRACTAL,  /* value-noise fBm (tools/terrain_gen.h)                      */
    TER_CONES,    /* five cones of slope 0.8 (tools/terrain_gen.h)              */
    TER_FLAT,     /* all zero                                                    */
    TER_SPIKE,    /* flat, one texel at the centre raised to the relief          */
    TER_RANDOM,   /* independent hashed heights (tiny fields)                    */
    TER_RAMP,     /* a plane rising along +x and +y                              */
    TER_SUN_RAMP  /* a plane rising toward the sun (azimuth 336) at its 15-degree
                     elevation, and (relief > 0) a spike of the relief at the
                     centre                                                    */
} stress_terrain;

typedef enum stress_holes {
    HOLES_NONE,
    HOLES_RAW,    /* a NaN left in the heights: must be refused               */
    HOLES_RAW_INF,/* +Inf and -Inf left in the heights: must be refused       */
    HOLES_FILLED  /* NaN, +-Inf, nodata and a block hole filled by the io layer */
} stress_holes;

typedef enum stress_light {
    LIGHT_STD,          /* sky + 2-degree sun + one local light above       */
    LIGHT_SKY_UNIFORM,  /* the uniform sky of radiance 1 alone              */
    LIGHT_STD_UNIFORM,  /* LIGHT_STD with the uniform sky (exact when flat:
                           the order-4 product is exact for a constant L)  */
    LIGHT_KEY_ZENITH,   /* sky + a key light straight up                    */
    LIGHT_KEY_HORIZON,  /* sky + a key light centred on the horizon         */
    LIGHT_KEY_BELOW,    /* a key light below the horizon (slopes see it)    */
    LIGHT_KEY_NADIR,    /* a key light straight down                        */
    LIGHT_KEY_HUGE,     /* a disk of angular radius 1.5 rad                 */
    LIGHT_KEY_TINY,     /* a disk of angular radius 1e-5 rad                */
    LIGHT_KEY_GRAZING,  /* a 1e-8 rad disk in the plane of TER_SUN_RAMP     */
    LIGHT_TINY,         /* uniform sky, a 1e-8 rad sun and local light      */
    LIGHT_LOCAL_BURIED, /* local lights inside the terrain and across it    */
    LIGHT_LOCAL_R0,     /* sky + a local light of radius 0                  */
    LIGHT_LOCAL_HUGE_IN,  /* a sphere 100x the field around it: all inside  */
    LIGHT_LOCAL_HUGE_OUT, /* a sphere 2x the field, above it: all outside   */
    LIGHT_LOCAL_ZENITH, /* over a grid point, and centred on a receiver     */
    LIGHT_LOCAL_HORIZON,/* level with the terrain, far off the grid         */
    LIGHT_LOCAL_BELOW,  /* below the terrain, beside the grid               */
    LIGHT_RADIANCE_0,   /* every light present with radiance 0              */
    LIGHT_RADIANCE_1E6, /* every light kind at radiance 1e6                 */
    LIGHT_MIXED_1E6,    /* a 1e6 sun over a sky of 1                        */
    LIGHT_ENV_HOT_ZENITH,  /* equirect map: 0 but one 1e5 pixel at the top  */
    LIGHT_ENV_HOT_HORIZON, /* ... just above the horizon                    */
    LIGHT_ENV_HOT_BELOW    /* ... below the horizon                         */
} stress_light;

typedef enum stress_expect {
    EXPECT_RENDER,  /* renders; every check applies                          */
    EXPECT_REFUSE   /* every backend refuses it with a one-line error        */
} stress_expect;

#define STRESS_MAX_SCALES 2
#define STRESS_EXPECT_U (-2.0)

typedef struct stress_case {
    const char *name;
    const char *what;       /* one line: what is extreme here                */
    int fast;               /* in the --fast subset (CI)                     */
    int w, h;
    stress_terrain terrain;
    double relief;          /* heights rescaled to [0, relief] (> 0), or 0:
                               the generator's own (texel units)             */
    double dx, zscale;
    stress_holes holes;
    stress_light light;
    int truth;              /* also on the ground truth (tiny fields only)   */
    stress_expect expect;
    double expect_value;    /* >= 0: every output channel must equal it;
                               STRESS_EXPECT_U: every output equals the
                               unshadowed image (a flat, unoccluded field)   */
    double scales[STRESS_MAX_SCALES]; /* invariance factors s (0 = unused)   */
    int tables;             /* SN08 wedge tables instead of Legendre         */
    int radiance;           /* also under every radiance times each of
                               STRESS_RADIANCE_SCALES: out(r) / r = out(1)  */
} stress_case;

/* Radiance invariance factors (issue 13): the GLES path scales radiance by
 * a power of two into fp16's range, so a sky of 1e-30 or a sun of 3e38 must
 * come out as exactly scaled copies (within float rounding of the inputs). */
#define STRESS_RADIANCE_SCALES {1e-30, 1e30, 1e36}

/* The table, in run order. */
const stress_case *stress_cases(int *count);
const stress_case *stress_case_find(const char *name);

/* A built scene.  lneg[c] = max(0, -min over the sphere of the environment's
 * radiance L_c(s)): 0 for a non-negative sky; the band-limited projection of
 * a single hot pixel rings below zero (docs/STRESS.md, "bounds"). */
typedef struct stress_scene {
    hfs_field f;
    float *z;
    hfs_lighting l;
    hfs_quality q;
    double lneg[3];
} stress_scene;

/* Builds case c with dx, zscale, local-light positions and radii multiplied
 * by s (s = 1: the case itself).  Returns 0, or -1 with a message in msg. */
int stress_scene_build(const stress_case *c, double s, stress_scene *sc, char *msg, size_t n);
void stress_scene_free(stress_scene *sc);

/* ---- backends (hfstress_backends.c) ------------------------------------------- */

/* gles-*: the product profile (es30-half for fp16, es30-float for fp32)
 * with strict limits (the smallest ES 3.0 device: textures stop at the
 * guaranteed 2048); gles-es32-*: the same
 * renderer under the es32 profile (the driver's limits), run only on
 * fields with a side beyond 2048; truth only on the cases that ask. */
enum { BK_CPU, BK_GLES16, BK_GLES32, BK_ES32_16, BK_ES32_32, BK_TRUTH, BK_COUNT };
#define STRESS_ES30_MAX_TEXTURE 2048

typedef struct stress_backends {
    hfs_renderer *r[BK_COUNT];
    int state[BK_COUNT];        /* 0 untried, 1 ready, -1 unavailable       */
    char why[BK_COUNT][600];    /* why unavailable                          */
    int broken[BK_COUNT];       /* unavailable though the machine could run
                                   it (runtime/gl/gl_require.h): a failure       */
    int subsample;              /* GLES visibility grid step; 0 = default   */
} stress_backends;

const char *stress_backend_name(int b);
int stress_backend_is_gles(int b);
int stress_backend_fp32(int b);
/* Parses "cpu,gles,truth,..." (gles = every GLES backend, all = every
 * backend) into want[BK_COUNT]; -1 with a message on stderr if unknown. */
int stress_backend_parse(const char *list, int want[BK_COUNT]);
/* Creates backend b on first use (GLES: renders a 2x2 probe; a failure,
 * e.g. no context, makes it unavailable with its reason in why[b]).
 * Returns 1 when ready. */
int stress_backend_ready(stress_backends *s, int b);
/* Renders sc on backend b into img (allocated here when img->rgb is NULL). */
int stress_render(stress_backends *s, int b, const stress_scene *sc, hfs_image *img,
                  hfs_error *err);
void stress_backends_close(stress_backends *s);

/* ---- checks ---------------------------------------------------------------------- */

/* Unshadowed bound check of one image (docs/STRESS.md, "bounds"): per
 * texel and channel  -rho lneg_c <= out <= U(x) + rho lneg_c,  U the exact
 * unshadowed image.  over = the largest violation / umax (0: none). */
typedef struct stress_bound {
    long nonfinite;
    double over;       /* worst violation / umax, >= 0 */
    double min_out, max_out;
    int worst_x, worst_y, worst_c;   /* where the worst violation is (-1: none) */
    double worst_out, worst_u;       /* and the values there */
} stress_bound;

void stress_check_bound(const hfs_image *out, const hfs_image *unshadowed, double umax,
                        const double lneg[3], double albedo, stress_bound *b);

/* max |a - b| / norm over every texel and channel (norm > 0), or, when
 * norm == 0, max |a - b| itself (an image that must be exactly 0). */
double stress_max_diff(const hfs_image *a, const hfs_image *b, double norm);
/* The same, and where (*at: the index into rgb of the largest difference). */
double stress_max_diff_at(const hfs_image *a, const hfs_image *b, double norm, size_t *at);

/* max |out - value| / max(value, 1e-300) over every texel and channel. */
double stress_const_err(const hfs_image *out, double value);

/* The fp16-vs-fp32 bound of the GLES path for scene sc, relative to umax
 * (docs/STRESS.md, "fp16 against fp32"), term by term. */
typedef struct stress_fp16_terms {
    double env;      /* V_env - hemisphere stored as single fp16: 2^-11   */
    double excess;   /* key horizon excess / local ratios as pairs (2^-22 / alpha),
                        key ratios from fp16 wedge tables (2^-10)           */
    double heights;  /* heights as pairs (2^-22 of the half relief) x slope / alpha */
    double normals;  /* normals from those heights: 2^-23 x slope, x solid angle */
    double pairs;    /* normals and output pairs                          */
    double total;
} stress_fp16_terms;

void stress_fp16_bound(const stress_scene *sc, double umax, stress_fp16_terms *t);

/* Over the sphere, f = sum_k sh[k] y_k: *neg = max(0, -min f), *absmax =
 * max |f| (1-degree grid). */
void stress_sh_range(const double sh[HFS_SH_COEFFS], double *neg, double *absmax);

#endif /* HFS_HFSTRESS_H */
