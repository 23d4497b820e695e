/*
 * plan.h — the GLES renderer's frame as a frame_plan.h graph (issue 6):
 * what each pass reads and writes, what a scene edit invalidates, and which
 * passes a frame runs.  The graph is built from the pass table (pass.h):
 * each pass declares its reads and writes where it is defined; this file
 * declares the inputs (what a frame signature carries) and turns the
 * difference between two signatures into changed inputs.
 *
 *   inputs   terrain (heights, size, dx, zscale, k, offset, precision),
 *            grid (subsample), env settings (nphi_env, visibility path,
 *            split horizons, horizon refinement),
 *            env light (rotated SH), albedo, key i geometry (its swath,
 *            horizon layers and refinement), key i direction (direction, size, elevation
 *            window), key i radiance, local settings (nphi_local, swath
 *            mode, path), local i geometry (centre, radius, and whether the
 *            terrain can shadow it at all: lights.h hfs_local_light_open),
 *            local radiance, bounce settings (bounces, their directions and
 *            samples, whether the grid's horizons cap them)
 *   passes   terrain -> env -> key i -> local i -> transfer -> key i factor
 *            -> shade -> readback
 *            terrain  reads terrain                 writes pyramid
 *            env      reads pyramid, grid, env set  writes env visibility
 *            key i    reads pyramid, grid, key i geometry   writes key i horizons
 *            local i  reads pyramid, grid, local settings, local i geometry
 *                                                   writes local i ratios
 *            transfer reads pyramid, env visibility writes env transfer (T)
 *            key i factor reads pyramid, key i horizons, key i direction
 *                                                   writes key i factor
 *            shade    reads the light set (which kinds, how many lights), what
 *                     the frame's lights use: env transfer + env light, key i
 *                     factor + key i radiance, local i ratios (of the lights
 *                     the terrain can shadow) + local radiance; albedo
 *                                                   writes the output targets
 *            bounce   reads the output targets, pyramid, grid, albedo, bounce
 *                     settings (and env visibility and transfer when the
 *                     grid's horizons cap the bands)  writes the bounced targets
 *            readback reads the output targets, bounce settings (and the
 *                     bounced targets with bounces)   writes the image
 *            lit texture reads the output targets, bounce settings, lit
 *                     texture settings (and the bounced targets with
 *                     bounces)  writes lit texture (needed only by frames
 *                     that want it, instead of the image)
 *            view     reads pyramid, output targets (and the bounced
 *                     targets with bounces), env light, light set,
 *                     camera (camera and view size)  writes view image
 *                     (needed only by frames with a view: a camera move
 *                     reruns the view alone)
 * A key light's horizons depend only on its swath (the sample directions):
 * moved inside it, the light costs its factor pass and the shading; the
 * environment's transfer vectors and the key factors do not depend on
 * radiance or (environment) rotation, so a turned, re-tinted or dimmed light
 * costs the shading only.  One local light moved costs its own ratios; a
 * local light beyond the terrain's shadow range needs none (ratio 1).  Nothing changed: no pass, no GL call; the last
 * image is handed out again.
 */
#ifndef HFS_GLES_PLAN_H
#define HFS_GLES_PLAN_H

#include <stdint.h>

#include "visibility.h"
#include "frame_plan.h"
#include "hfshade.h"
#include "pass.h"
#include "view_camera.h"

#define HFS_GLES_PLAN_KEYS HFS_MAX_KEY_LIGHTS

/* What a frame is computed from (besides the heights, compared by the
 * renderer against its kept copy). */
typedef struct hfs_gles_frame_sig {
    int sub, vw, vh;
    int has_env, nphi_env, vis_path;
    int far_from, far_k, far_step; /* split horizons (0: not split) */
    int hz_refine;                /* quality refine: samples between scales of
                                     every env and key horizon */
    double l_env[3][HFS_SH_COEFFS];
    int env_map;                  /* gles_backend.h hfs_gles_frame env_map */
    int env_fold;                 /* ... env_fold: the shading reads the sky occlusion */
    const float *emap;            /* env-shade = map: the map, its size and */
    int emap_w, emap_h;           /* its open-sky table's contents (a hash, */
    uint64_t eopen_hash;          /* standing for the map's)                */
    double rho_pi;
    unsigned albedo_gen;          /* the albedo map's contents (0: none yet) */
    int albedo_map;
    double gloss[9];              /* glossy: specular, exponent, view, at eye,
                                     eye (0: off) */
    int n_keys;
    struct {
        hfs_swath swath;
        int hz_layer;
        double dir[3], alpha, le[3];
    } key[HFS_GLES_PLAN_KEYS];
    int bounces, bounce_dirs, bounce_stride, refine, capped, bsub, bnear; /* the bounce pass's settings */
    int n_local, nphi_local, local_full;
    struct {
        double pos[3], radius;
        float le[3];
        int open;                 /* hfs_local_light_open: no ratios needed */
    } local[HFS_MAX_LOCAL_LIGHTS];
    int view;                     /* the frame has a 3-D view: */
    hfs_camera cam;               /* its camera */
    int view_w, view_h;           /* and size */
    int texture;                  /* the frame wants the lit texture, not the image: */
    int lit_encoding, lit_tonemap;/* its encoding (hfs_lit_texture_desc) */
    double lit_exposure;
} hfs_gles_frame_sig;

/* Instances of a pass: at most this many (the most lights of a kind). */
#define HFS_GLES_PLAN_INSTANCES (HFS_MAX_LOCAL_LIGHTS > HFS_MAX_KEY_LIGHTS ? \
                                 HFS_MAX_LOCAL_LIGHTS : HFS_MAX_KEY_LIGHTS)

typedef struct hfs_gles_plan {
    hfs_plan p;
    int in_terrain, in_grid, in_env_set, in_env_light, in_albedo, in_local_set, in_local_rad;
    int in_local_geom[HFS_MAX_LOCAL_LIGHTS];
    int in_light_set;             /* which light kinds / how many lights */
    int in_bounce;                /* bounce settings */
    int in_camera, pr_view;       /* the 3-D view: camera and size; its image */
    int in_lit, pr_lit;           /* the lit texture: its encoding; the texture */
    int in_key_geom[HFS_GLES_PLAN_KEYS], in_key_dir[HFS_GLES_PLAN_KEYS];
    int in_key_rad[HFS_GLES_PLAN_KEYS];
    int pr_pyramid, pr_env, pr_transfer, pr_targets, pr_image, pr_bounced;
    int pr_mocc;                  /* the map's occluded light (env-shade = map) */
    int pr_skyocc;                /* the SH sky's, when no transfer is kept */
    int pr_local[HFS_MAX_LOCAL_LIGHTS];
    int pr_key[HFS_GLES_PLAN_KEYS], pr_kfactor[HFS_GLES_PLAN_KEYS];
    /* frame_plan pass id of each (pass, instance); -1 past the pass's
     * instances. */
    int pass[HFS_PASS_COUNT][HFS_GLES_PLAN_INSTANCES];
    hfs_gles_frame_sig last;
    int have_last;
    hfs_plan_step steps[HFS_PLAN_MAX_PASSES];
    int run[HFS_PASS_COUNT][HFS_GLES_PLAN_INSTANCES]; /* this frame's decisions */
    int n_run;
    int black;                    /* the last frame was black: no light, no pass */
    int amortize;                 /* visibility passes per frame; 0 = all (off) */
    int deferred;                 /* passes the last frame left for later ones */
} hfs_gles_plan;

/* Builds the graph from the pass table; HFS_E_INVALID (a bug) when a pass
 * reads a node nothing declares or the graph does not fit frame_plan.h. */
int hfs_gles_plan_init(hfs_gles_plan *gp, hfs_error *err);

/* Plans a frame: terrain_why is NULL when the terrain is unchanged, else
 * why it changed.  Fills gp->run[][] and returns the number of passes to run.
 * With gp->amortize > 0 and the terrain unchanged, at most that many of the
 * visibility passes (env, key i, local i) run, the others wait
 * (frame_plan.h "Amortization"; gp->deferred counts them); a terrain change
 * runs everything, as NS09 does. */
int hfs_gles_plan_frame(hfs_gles_plan *gp, const hfs_gles_frame_sig *now,
                        const char *terrain_why);

/* Pass p (one instance) runs this frame after all, for `reason` (the
 * report's): its products are kept valid but their storage was freed
 * (gles_frame.c grid_restore).  What reads them need not follow: the pass
 * makes the same values from the same inputs. */
void hfs_gles_plan_force(hfs_gles_plan *gp, hfs_gles_pass_id p, const char *reason);

/* Instance i of pass p ran: its products are valid. */
void hfs_gles_plan_done(hfs_gles_plan *gp, hfs_gles_pass_id p, int i);

/* Products that no longer hold their values (a failed frame, counting
 * twins writing fetch counts into the visibility targets, reallocation). */
void hfs_gles_plan_drop_all(hfs_gles_plan *gp);
void hfs_gles_plan_drop_grids(hfs_gles_plan *gp);

/* Textures were reallocated: the whole visibility grid (env, keys, local),
 * the key horizons, the local ratios or the key factors lost their
 * contents.  Call before hfs_gles_plan_frame: the passes that wrote them
 * then run again ("not computed yet"), and what reads them after. */
void hfs_gles_plan_lost(hfs_gles_plan *gp, int grid, int key_horizons, int local_ratios,
                        int key_factors);

/* The last frame's steps as a report (public hfs_frame_report). */
void hfs_gles_plan_report(const hfs_gles_plan *gp, hfs_frame_report *out);

#endif /* HFS_GLES_PLAN_H */
