/*
 * gles_plan.c — see gles_plan.h.
 */
#include "gles_plan.h"

#include <stdio.h>
#include <string.h>

void hfs_gles_plan_init(hfs_gles_plan *gp)
{
    memset(gp, 0, sizeof *gp);
    hfs_plan *p = &gp->p;
    hfs_plan_init(p);
    char name[HFS_PLAN_NAME];
    gp->in_terrain = hfs_plan_input(p, "terrain");
    gp->in_grid = hfs_plan_input(p, "subsample");
    gp->in_env_set = hfs_plan_input(p, "env settings");
    gp->in_env_light = hfs_plan_input(p, "env light");
    gp->in_albedo = hfs_plan_input(p, "albedo");
    gp->in_local_set = hfs_plan_input(p, "local settings");
    for (int i = 0; i < HFS_MAX_LOCAL_LIGHTS; ++i) {
        snprintf(name, sizeof name, "local %d geometry", i);
        gp->in_local_geom[i] = hfs_plan_input(p, name);
    }
    gp->in_local_rad = hfs_plan_input(p, "local radiance");
    gp->in_light_set = hfs_plan_input(p, "light set");
    for (int i = 0; i < HFS_GLES_PLAN_KEYS; ++i) {
        snprintf(name, sizeof name, "key %d swath", i);
        gp->in_key_geom[i] = hfs_plan_input(p, name);
        snprintf(name, sizeof name, "key %d direction", i);
        gp->in_key_dir[i] = hfs_plan_input(p, name);
        snprintf(name, sizeof name, "key %d radiance", i);
        gp->in_key_rad[i] = hfs_plan_input(p, name);
    }
    gp->pr_pyramid = hfs_plan_product(p, "pyramid");
    gp->pr_env = hfs_plan_product(p, "env visibility");
    for (int i = 0; i < HFS_GLES_PLAN_KEYS; ++i) {
        snprintf(name, sizeof name, "key %d horizons", i);
        gp->pr_key[i] = hfs_plan_product(p, name);
    }
    for (int i = 0; i < HFS_MAX_LOCAL_LIGHTS; ++i) {
        snprintf(name, sizeof name, "local %d ratios", i);
        gp->pr_local[i] = hfs_plan_product(p, name);
    }
    gp->pr_transfer = hfs_plan_product(p, "env transfer");
    for (int i = 0; i < HFS_GLES_PLAN_KEYS; ++i) {
        snprintf(name, sizeof name, "key %d factor", i);
        gp->pr_kfactor[i] = hfs_plan_product(p, name);
    }
    gp->pr_targets = hfs_plan_product(p, "output targets");
    gp->pr_image = hfs_plan_product(p, "image");

    gp->pass[GP_TERRAIN] = hfs_plan_pass_add(p, "terrain", (int[]){gp->in_terrain, -1},
                                             (int[]){gp->pr_pyramid, -1});
    gp->pass[GP_ENV] = hfs_plan_pass_add(
        p, "env", (int[]){gp->pr_pyramid, gp->in_grid, gp->in_env_set, -1},
        (int[]){gp->pr_env, -1});
    for (int i = 0; i < HFS_GLES_PLAN_KEYS; ++i) {
        snprintf(name, sizeof name, "key %d", i);
        gp->pass[GP_KEY0 + i] = hfs_plan_pass_add(
            p, name, (int[]){gp->pr_pyramid, gp->in_grid, gp->in_key_geom[i], -1},
            (int[]){gp->pr_key[i], -1});
    }
    for (int i = 0; i < HFS_MAX_LOCAL_LIGHTS; ++i) {
        snprintf(name, sizeof name, "local %d", i);
        gp->pass[GP_LOCAL0 + i] = hfs_plan_pass_add(
            p, name,
            (int[]){gp->pr_pyramid, gp->in_grid, gp->in_local_set, gp->in_local_geom[i], -1},
            (int[]){gp->pr_local[i], -1});
    }
    gp->pass[GP_TRANSFER] = hfs_plan_pass_add(p, "transfer", (int[]){gp->pr_pyramid, gp->pr_env, -1},
                                              (int[]){gp->pr_transfer, -1});
    for (int i = 0; i < HFS_GLES_PLAN_KEYS; ++i) {
        snprintf(name, sizeof name, "key %d factor", i);
        gp->pass[GP_KFACTOR0 + i] = hfs_plan_pass_add(
            p, name, (int[]){gp->pr_pyramid, gp->pr_key[i], gp->in_key_dir[i], -1},
            (int[]){gp->pr_kfactor[i], -1});
    }
    /* The expensive visibility passes may wait when amortizing. */
    hfs_plan_set_deferrable(p, gp->pass[GP_ENV], 1);
    for (int i = 0; i < HFS_GLES_PLAN_KEYS; ++i)
        hfs_plan_set_deferrable(p, gp->pass[GP_KEY0 + i], 1);
    for (int i = 0; i < HFS_MAX_LOCAL_LIGHTS; ++i)
        hfs_plan_set_deferrable(p, gp->pass[GP_LOCAL0 + i], 1);
    gp->pass[GP_SHADE] = hfs_plan_pass_add(p, "shade", NULL, (int[]){gp->pr_targets, -1});
    gp->pass[GP_READBACK] = hfs_plan_pass_add(p, "readback", (int[]){gp->pr_targets, -1},
                                              (int[]){gp->pr_image, -1});
}

static int swath_equal(const hfs_swath *a, const hfs_swath *b)
{
    return a->n == b->n && a->full == b->full && a->phi0 == b->phi0 && a->dphi == b->dphi;
}

/* Marks the inputs that differ between the last frame and now. */
static void diff_inputs(hfs_gles_plan *gp, const hfs_gles_frame_sig *a,
                        const hfs_gles_frame_sig *b)
{
    hfs_plan *p = &gp->p;
    char why[HFS_PLAN_REASON];
    if (a->has_env != b->has_env || a->n_keys != b->n_keys || a->n_local != b->n_local)
        hfs_plan_change(p, gp->in_light_set, "a light kind or a light added or removed");
    if (a->sub != b->sub || a->vw != b->vw || a->vh != b->vh)
        hfs_plan_change(p, gp->in_grid, "subsample changed");
    if (a->nphi_env != b->nphi_env || a->vis_path != b->vis_path || a->has_env != b->has_env)
        hfs_plan_change(p, gp->in_env_set, "environment settings changed");
    if (a->has_env != b->has_env || memcmp(a->l_env, b->l_env, sizeof a->l_env))
        hfs_plan_change(p, gp->in_env_light, "environment light changed (rotation, tint)");
    if (a->rho_pi != b->rho_pi)
        hfs_plan_change(p, gp->in_albedo, "albedo changed");
    for (int i = 0; i < HFS_GLES_PLAN_KEYS; ++i) {
        const int ha = i < a->n_keys, hb = i < b->n_keys;
        if (!ha && !hb)
            continue;
        if (ha != hb || !swath_equal(&a->key[i].swath, &b->key[i].swath) ||
            a->key[i].hz_layer != b->key[i].hz_layer || a->vis_path != b->vis_path) {
            snprintf(why, sizeof why, "key %d: %s", i,
                     ha != hb ? "light added or removed" : "moved to a new swath");
            hfs_plan_change(p, gp->in_key_geom[i], why);
        }
        if (ha != hb || memcmp(a->key[i].dir, b->key[i].dir, sizeof a->key[i].dir) ||
            a->key[i].alpha != b->key[i].alpha || a->key[i].swath.elev_lo != b->key[i].swath.elev_lo ||
            a->key[i].swath.elev_hi != b->key[i].swath.elev_hi) {
            snprintf(why, sizeof why, "key %d: direction or size changed", i);
            hfs_plan_change(p, gp->in_key_dir[i], why);
        }
        if (ha != hb || memcmp(a->key[i].le, b->key[i].le, sizeof a->key[i].le)) {
            snprintf(why, sizeof why, "key %d: radiance changed", i);
            hfs_plan_change(p, gp->in_key_rad[i], why);
        }
    }
    if (a->nphi_local != b->nphi_local || a->local_full != b->local_full ||
        a->vis_path != b->vis_path)
        hfs_plan_change(p, gp->in_local_set, "local-light settings changed");
    int rad = a->n_local != b->n_local;
    for (int i = 0; i < HFS_MAX_LOCAL_LIGHTS; ++i) {
        const int ha = i < a->n_local, hb = i < b->n_local;
        if (!ha && !hb)
            continue;
        if (ha != hb || memcmp(a->local[i].pos, b->local[i].pos, sizeof a->local[i].pos) ||
            a->local[i].radius != b->local[i].radius || a->local[i].open != b->local[i].open) {
            snprintf(why, sizeof why, "local %d: %s", i,
                     ha != hb ? "light added or removed" : "moved or resized");
            hfs_plan_change(p, gp->in_local_geom[i], why);
        }
        if (ha && hb)
            rad |= memcmp(a->local[i].le, b->local[i].le, sizeof a->local[i].le) != 0;
    }
    if (rad)
        hfs_plan_change(p, gp->in_local_rad, "local radiance changed");
}

int hfs_gles_plan_frame(hfs_gles_plan *gp, const hfs_gles_frame_sig *now, const char *terrain_why)
{
    hfs_plan *p = &gp->p;
    gp->black = 0;
    if (terrain_why)
        hfs_plan_change(p, gp->in_terrain, terrain_why);
    if (gp->have_last)
        diff_inputs(gp, &gp->last, now);
    gp->last = *now;
    gp->have_last = 1;

    /* The shading reads what this frame's lights use. */
    int reads[10 + 2 * HFS_GLES_PLAN_KEYS + 2 * HFS_MAX_LOCAL_LIGHTS], n = 0;
    reads[n++] = gp->pr_pyramid;
    reads[n++] = gp->in_albedo;
    reads[n++] = gp->in_light_set;
    if (now->has_env) {
        reads[n++] = gp->pr_transfer;
        reads[n++] = gp->in_env_light;
    }
    for (int i = 0; i < now->n_keys && i < HFS_GLES_PLAN_KEYS; ++i) {
        reads[n++] = gp->pr_kfactor[i];
        reads[n++] = gp->in_key_rad[i];
    }
    if (now->n_local > 0)
        reads[n++] = gp->in_local_rad;
    for (int i = 0; i < now->n_local && i < HFS_MAX_LOCAL_LIGHTS; ++i) {
        reads[n++] = gp->in_local_geom[i]; /* E_cap at each texel */
        if (!now->local[i].open) /* an open light's ratio is 1: nothing to read */
            reads[n++] = gp->pr_local[i];
    }
    reads[n] = -1;
    hfs_plan_pass_reads(p, gp->pass[GP_SHADE], reads);

    hfs_plan_set need = {{0}};
    hfs_plan_set_add(&need, gp->pr_image);
    gp->deferred = 0;
    if (gp->amortize > 0 && !terrain_why)
        gp->n_run = hfs_plan_frame_amortized(p, &need, gp->amortize, gp->steps, &gp->deferred);
    else
        gp->n_run = hfs_plan_frame(p, &need, gp->steps);
    for (int k = 0; k < GP_PASSES; ++k)
        gp->run[k] = gp->steps[gp->pass[k]].run;
    return gp->n_run;
}

void hfs_gles_plan_done(hfs_gles_plan *gp, int which)
{
    hfs_plan_done(&gp->p, gp->pass[which]);
}

void hfs_gles_plan_drop_all(hfs_gles_plan *gp)
{
    hfs_plan_drop_all(&gp->p);
    gp->have_last = 0;
}

void hfs_gles_plan_drop_grids(hfs_gles_plan *gp)
{
    hfs_plan_drop(&gp->p, gp->pr_env);
    for (int i = 0; i < HFS_MAX_LOCAL_LIGHTS; ++i)
        hfs_plan_drop(&gp->p, gp->pr_local[i]);
    for (int i = 0; i < HFS_GLES_PLAN_KEYS; ++i)
        hfs_plan_drop(&gp->p, gp->pr_key[i]);
}

void hfs_gles_plan_lost(hfs_gles_plan *gp, int grid, int key_horizons, int local_ratios,
                        int key_factors)
{
    if (key_factors)
        for (int i = 0; i < HFS_GLES_PLAN_KEYS; ++i)
            hfs_plan_drop(&gp->p, gp->pr_kfactor[i]);
    if (grid) {
        hfs_gles_plan_drop_grids(gp);
        return;
    }
    if (key_horizons)
        for (int i = 0; i < HFS_GLES_PLAN_KEYS; ++i)
            hfs_plan_drop(&gp->p, gp->pr_key[i]);
    if (local_ratios)
        for (int i = 0; i < HFS_MAX_LOCAL_LIGHTS; ++i)
            hfs_plan_drop(&gp->p, gp->pr_local[i]);
}

void hfs_gles_plan_report(const hfs_gles_plan *gp, hfs_frame_report *out)
{
    memset(out, 0, sizeof *out);
    if (gp->black) {
        out->n_steps = 1;
        snprintf(out->step[0].pass, sizeof out->step[0].pass, "none");
        snprintf(out->step[0].reason, sizeof out->step[0].reason,
                 "no light contributes (or albedo 0): black image");
        return;
    }
    for (int i = 0; i < gp->p.n_passes && out->n_steps < HFS_REPORT_STEPS; ++i) {
        const hfs_plan_step *s = &gp->steps[i];
        /* Key and local slots beyond the frame's lights (and open lights)
         * say nothing: leave them out. */
        if (!s->run && !strcmp(s->reason, "not needed") &&
            (!strncmp(gp->p.pass[i].name, "key ", 4) || !strncmp(gp->p.pass[i].name, "local ", 6)))
            continue;
        hfs_frame_step *o = &out->step[out->n_steps++];
        snprintf(o->pass, sizeof o->pass, "%s", gp->p.pass[i].name);
        o->ran = s->run;
        snprintf(o->reason, sizeof o->reason, "%s", s->reason);
        out->n_ran += s->run;
    }
    out->n_deferred = gp->deferred;
}
