/*
 * pass.h — one GLES pass, one file, one row of the pass table.
 *
 * A pass declares, where it is defined (pass_*.c):
 *   - what it reads and writes, as nodes of the frame planner (plan.h
 *     builds the frame_plan.h graph from these rows: inputs are what a
 *     caller edits, products what passes write; "%d" in a name is the
 *     light the instance is for);
 *   - its scope: once a frame, or once per key light / per local light
 *     (each instance planned on its own: one moved light reruns only its
 *     own instance);
 *   - its timed stages (the names hfs_timings reports);
 *   - how it runs: layout (its sizes and limits, checked through the
 *     capability layer before anything is allocated), prepare (every
 *     frame it is part of, run or not: the
 *     uniform data later passes also read), run (the instances the planner
 *     chose, which[i] set) and optionally count (the fetch-counting twin,
 *     timing level 2).
 * The frame (gles_frame.c) is a loop over this table in order; a pass only
 * ever comes after the passes that write what it reads.
 *
 * Adding a pass: docs/DESIGN.md "Code map", "Adding a pass".
 */
#ifndef HFS_GLES_PASS_H
#define HFS_GLES_PASS_H

#include "backends.h"

typedef enum hfs_gles_pass_id {
    HFS_PASS_TERRAIN,        /* pass_terrain.c: heights -> pyramid, bounds         */
    HFS_PASS_ENV_HORIZONS,   /* pass_env_horizons.c: env SH visibility on the grid */
    HFS_PASS_KEY_HORIZONS,   /* pass_key_horizons.c: key horizons, per key         */
    HFS_PASS_LOCAL_LIGHTS,   /* pass_local_lights.c: local ratios, per local light */
    HFS_PASS_ENV_TRANSFER,   /* pass_env_transfer.c: T = H * V_env per texel       */
    HFS_PASS_ENV_MAP_SLICES, /* pass_env_map_slices.c: an env map's occluded light */
    HFS_PASS_ENV_SKY_OCCLUSION, /* pass_env_sky_occlusion.c: the SH sky's, a sky kept */
    HFS_PASS_KEY_VISIBILITY, /* pass_key_visibility.c: key factor, per key         */
    HFS_PASS_SHADE,          /* pass_shade.c: exit radiance (hi, lo)               */
    HFS_PASS_BOUNCE,         /* pass_bounce.c: indirect bounces, direct + indirect */
    HFS_PASS_READBACK,       /* pass_readback.c: the image                         */
    HFS_PASS_LIT_TEXTURE,    /* pass_lit_texture.c: the lit texture (embedding)    */
    HFS_PASS_VIEW,           /* pass_view.c: the 3-D view and its read-back        */
    HFS_PASS_COUNT
} hfs_gles_pass_id;

typedef enum hfs_gles_pass_scope {
    HFS_SCOPE_FRAME,         /* one instance                                      */
    HFS_SCOPE_KEY,           /* one per key light (HFS_MAX_KEY_LIGHTS)             */
    HFS_SCOPE_LOCAL          /* one per local light (HFS_MAX_LOCAL_LIGHTS)         */
} hfs_gles_pass_scope;

#define HFS_PASS_MAX_IO 6
#define HFS_PASS_MAX_STAGES 4

typedef struct hfs_gles_frame hfs_gles_frame; /* gles_backend.h */

typedef struct hfs_gles_pass {
    hfs_gles_pass_id id;
    const char *plan_name;                      /* "key %d factor"             */
    hfs_gles_pass_scope scope;
    int deferrable;                             /* may wait when amortizing    */
    const char *reads[HFS_PASS_MAX_IO];         /* plan nodes, NULL-terminated */
    const char *writes[HFS_PASS_MAX_IO];
    const char *stages[HFS_PASS_MAX_STAGES];    /* timed stages                */
    /* Whether this frame has the pass at all (e.g. an environment). */
    int (*present)(const hfs_gles_frame *fr);
    /* Whether this frame has stage s of the pass (NULL: every stage); a
     * cached pass reports only the stages its frame has. */
    int (*stage_present)(const hfs_gles_frame *fr, int s);
    /* Sizes and limits, before the resources are fitted (optional). */
    int (*layout)(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err);
    int (*prepare)(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err);
    int (*run)(hfs_gles *g, hfs_gles_frame *fr, const int *which, hfs_error *err);
    /* Its counting twin (timing level 2): adds each stage's texture
     * fetches to fetches[stage] (set to 0 before). */
    int (*count)(hfs_gles *g, hfs_gles_frame *fr, double *fetches, hfs_error *err);
} hfs_gles_pass;

/* The table, in frame order (pass_table.c). */
extern const hfs_gles_pass *const hfs_gles_pass_table[HFS_PASS_COUNT];

/* Instances a pass can have (1, HFS_MAX_KEY_LIGHTS or HFS_MAX_LOCAL_LIGHTS). */
int hfs_gles_pass_max_instances(const hfs_gles_pass *p);

extern const hfs_gles_pass hfs_pass_terrain, hfs_pass_env_horizons, hfs_pass_key_horizons,
    hfs_pass_local_lights, hfs_pass_env_transfer, hfs_pass_env_map_slices,
    hfs_pass_env_sky_occlusion,
    hfs_pass_key_visibility, hfs_pass_shade,
    hfs_pass_bounce, hfs_pass_readback, hfs_pass_lit_texture;
extern const hfs_gles_pass hfs_pass_view;

#endif /* HFS_GLES_PASS_H */
