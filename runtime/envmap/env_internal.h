/*
 * env_internal.h — shared state of the environment map decomposition
 * (env_decompose.c: API and loop; env_coarse.c: coarse pyramid and
 * detection; env_refine.c: full-resolution refinement and extraction;
 * env_track.c: temporal tracking).  Not installed.
 */
#ifndef HFS_ENV_INTERNAL_H
#define HFS_ENV_INTERNAL_H

#include "env_decompose.h"

#define ENV_COARSE_W 256
#define ENV_COARSE_H 128
#define ENV_MAX_LEVELS 8
/* Negative texels allowed down to this fraction of the mean radiance. */
#define ENV_NEG_TOLERANCE 0.01

/* Rec. 709 luminance: the energy budget (shares) is measured in it. */
static inline double env_lum(double r, double g, double b)
{
    return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}

/* One level of the coarse pyramid: per cell the luminance energy, the exact
 * solid angle and the luminance-weighted sum of texel directions. */
typedef struct env_level {
    int cw, ch;
    double *e, *a, *sx, *sy, *sz;   /* cw * ch each, row 0 = zenith        */
} env_level;

typedef struct env_ctx {
    float *rgb;
    int w, h;
    hfs_env_decompose_opts opts;
    double *row_domega;              /* h: texel solid angle of row j       */
    double *row_sin, *row_cos;       /* h: sin e, cos e of row centres      */
    double *col_cos, *col_sin;       /* w: cos phi, sin phi of col centres  */
    int *col_cell, *row_cell;        /* full-res texel -> level-0 cell      */
    int n_levels;
    env_level lv[ENV_MAX_LEVELS];
    double total[3], total_lum;      /* the input map's integral            */
} env_ctx;

/* A candidate: a direction (unit vector) and a first radius (radians). */
typedef struct env_seed {
    double d[3];
    double r0;
} env_seed;

/* env_coarse.c */
int envc_init(env_ctx *c, float *rgb, int w, int h, const hfs_env_decompose_opts *o,
              hfs_error *err);
void envc_free(env_ctx *c);
/* Rebuilds levels 1.. from level 0. */
void envc_merge_levels(env_ctx *c);
/* The strongest centre-surround block with a positive response; 1 if found. */
int envc_detect(const env_ctx *c, env_seed *out);
/* Adds a luminance energy change of texel (i, j) to its level-0 cell. */
void envc_add(env_ctx *c, int i, int j, double dlum);

/* env_refine.c: refines the seed on full-resolution texels and, if the
 * light holds at least min_share of the map's luminance energy (and a
 * positive energy), removes it from the map (updating level 0) and fills
 * *out.  Returns 1 if a light was extracted, 0 if not (map untouched). */
int envr_extract(env_ctx *c, const env_seed *seed, double min_share, hfs_env_light *out);
/* Texel size (radians) about elevation e: the larger side. */
double envr_texel_size(const env_ctx *c, double e);
void env_dir_to_angles(const double d[3], double *phi, double *elev);

/* env_decompose.c: checks the options (o NULL: defaults) and the map and
 * builds c; errors are prefixed with name. */
int envd_begin(env_ctx *c, float *rgb, int w, int h, const hfs_env_decompose_opts *o,
               const char *name, hfs_error *err);
/* env_decompose.c: residual SH and energies of the current map into out. */
void envd_finish(const env_ctx *c, hfs_env_decomp *out);

#endif /* HFS_ENV_INTERNAL_H */
