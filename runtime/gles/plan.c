/*
 * plan.c — see plan.h.
 */
#include "plan.h"

#include <stdio.h>
#include <string.h>

/* Node `name` (a printf format with the instance i), or -1. */
static int node_find(const hfs_plan *p, const char *fmt, int i)
{
    char name[HFS_PLAN_NAME];
    snprintf(name, sizeof name, fmt, i);
    for (int n = 0; n < p->n_nodes; ++n)
        if (!strcmp(p->node[n], name))
            return n;
    return -1;
}

_Static_assert(HFS_MAX_LOCAL_LIGHTS < 100 && HFS_GLES_PLAN_KEYS < 100,
               "an instance's input name holds a two-digit index");

/* Input "<what> <i> <part>", e.g. "key 2 direction". The index is taken
 * modulo 100 (a no-op by the assert above) so that the compiler can prove
 * the name fits HFS_PLAN_NAME at any optimisation level. */
static int indexed_input(hfs_plan *p, const char *what, int i, const char *part)
{
    char name[HFS_PLAN_NAME];
    snprintf(name, sizeof name, "%s %u %s", what, (unsigned)i % 100u, part);
    return hfs_plan_input(p, name);
}

/* The inputs: what a frame signature carries (diff_inputs below). */
static void declare_inputs(hfs_gles_plan *gp)
{
    hfs_plan *p = &gp->p;
    gp->in_terrain = hfs_plan_input(p, "terrain");
    gp->in_grid = hfs_plan_input(p, "subsample");
    gp->in_env_set = hfs_plan_input(p, "env settings");
    gp->in_env_light = hfs_plan_input(p, "env light");
    gp->in_albedo = hfs_plan_input(p, "albedo");
    gp->in_local_set = hfs_plan_input(p, "local settings");
    for (int i = 0; i < HFS_MAX_LOCAL_LIGHTS; ++i)
        gp->in_local_geom[i] = indexed_input(p, "local", i, "geometry");
    gp->in_local_rad = hfs_plan_input(p, "local radiance");
    gp->in_light_set = hfs_plan_input(p, "light set");
    gp->in_bounce = hfs_plan_input(p, "bounce settings");
    gp->in_camera = hfs_plan_input(p, "camera");
    gp->in_lit = hfs_plan_input(p, "lit texture settings");
    for (int i = 0; i < HFS_GLES_PLAN_KEYS; ++i) {
        gp->in_key_geom[i] = indexed_input(p, "key", i, "swath");
        gp->in_key_dir[i] = indexed_input(p, "key", i, "direction");
        gp->in_key_rad[i] = indexed_input(p, "key", i, "radiance");
    }
}

/* Instance i of a pass of the table as a frame_plan pass. */
static int add_pass(hfs_gles_plan *gp, const hfs_gles_pass *pass, int i, hfs_error *err)
{
    hfs_plan *p = &gp->p;
    int reads[HFS_PASS_MAX_IO + 1], writes[HFS_PASS_MAX_IO + 1], nr = 0, nw = 0;
    for (int k = 0; k < HFS_PASS_MAX_IO && pass->reads[k]; ++k)
        if ((reads[nr++] = node_find(p, pass->reads[k], i)) < 0)
            return hfs_fail(err, HFS_E_INVALID, "gles plan: pass %s reads %s, which no input "
                            "or earlier pass declares", pass->plan_name, pass->reads[k]);
    for (int k = 0; k < HFS_PASS_MAX_IO && pass->writes[k]; ++k) {
        int n = node_find(p, pass->writes[k], i);
        if (n < 0) {
            char name[HFS_PLAN_NAME];
            snprintf(name, sizeof name, pass->writes[k], i);
            n = hfs_plan_product(p, name);
        }
        if (n < 0)
            return hfs_fail(err, HFS_E_INVALID, "gles plan: too many nodes");
        writes[nw++] = n;
    }
    reads[nr] = writes[nw] = -1;
    char name[HFS_PLAN_NAME];
    snprintf(name, sizeof name, pass->plan_name, i);
    const int id = hfs_plan_pass_add(p, name, nr ? reads : NULL, writes);
    if (id < 0)
        return hfs_fail(err, HFS_E_INVALID, "gles plan: too many passes");
    hfs_plan_set_deferrable(p, id, pass->deferrable);
    gp->pass[pass->id][i] = id;
    return HFS_OK;
}

int hfs_gles_plan_init(hfs_gles_plan *gp, hfs_error *err)
{
    memset(gp, 0, sizeof *gp);
    hfs_plan *p = &gp->p;
    hfs_plan_init(p);
    declare_inputs(gp);
    for (int k = 0; k < HFS_PASS_COUNT; ++k) {
        const hfs_gles_pass *pass = hfs_gles_pass_table[k];
        for (int i = 0; i < HFS_GLES_PLAN_INSTANCES; ++i)
            gp->pass[k][i] = -1;
        for (int i = 0; i < hfs_gles_pass_max_instances(pass); ++i) {
            int rc = add_pass(gp, pass, i, err);
            if (rc)
                return rc;
        }
    }
    /* The products the planner itself names (drops, the shading's reads). */
    gp->pr_pyramid = node_find(p, "pyramid", 0);
    gp->pr_env = node_find(p, "env visibility", 0);
    gp->pr_transfer = node_find(p, "env transfer", 0);
    gp->pr_targets = node_find(p, "output targets", 0);
    gp->pr_image = node_find(p, "image", 0);
    gp->pr_bounced = node_find(p, "bounced targets", 0);
    gp->pr_view = node_find(p, "view image", 0);
    gp->pr_mocc = node_find(p, "env map occlusion", 0);
    gp->pr_skyocc = node_find(p, "env sky occlusion", 0);
    gp->pr_lit = node_find(p, "lit texture", 0);
    int ok = gp->pr_pyramid >= 0 && gp->pr_env >= 0 && gp->pr_transfer >= 0 &&
             gp->pr_targets >= 0 && gp->pr_image >= 0 && gp->pr_bounced >= 0;
    ok &= gp->pr_view >= 0 && gp->pr_mocc >= 0 && gp->pr_skyocc >= 0 && gp->pr_lit >= 0;
    for (int i = 0; i < HFS_GLES_PLAN_KEYS; ++i) {
        ok &= (gp->pr_key[i] = node_find(p, "key %d horizons", i)) >= 0;
        ok &= (gp->pr_kfactor[i] = node_find(p, "key %d factor", i)) >= 0;
    }
    for (int i = 0; i < HFS_MAX_LOCAL_LIGHTS; ++i)
        ok &= (gp->pr_local[i] = node_find(p, "local %d ratios", i)) >= 0;
    return ok ? HFS_OK : hfs_fail(err, HFS_E_INVALID, "gles plan: a product the planner "
                                  "needs is written by no pass");
}

static int swath_equal(const hfs_swath *a, const hfs_swath *b)
{
    return a->n == b->n && a->full == b->full && a->phi0 == b->phi0 && a->dphi == b->dphi;
}

static int camera_equal(const hfs_camera *a, const hfs_camera *b)
{
    return a->azimuth == b->azimuth && a->elevation == b->elevation &&
           a->distance == b->distance && a->fov == b->fov && a->target[0] == b->target[0] &&
           a->target[1] == b->target[1] && a->target[2] == b->target[2] &&
           a->exaggeration == b->exaggeration && a->ortho == b->ortho &&
           hfs_view_look_equal(&a->look, &b->look);
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
    if (a->nphi_env != b->nphi_env || a->vis_path != b->vis_path || a->has_env != b->has_env ||
        a->far_from != b->far_from || a->far_k != b->far_k || a->far_step != b->far_step ||
        a->hz_refine != b->hz_refine)
        hfs_plan_change(p, gp->in_env_set, "environment settings changed");
    if (a->has_env != b->has_env || memcmp(a->l_env, b->l_env, sizeof a->l_env))
        hfs_plan_change(p, gp->in_env_light, "environment light changed (rotation, tint)");
    else if (a->env_map != b->env_map || a->emap != b->emap || a->emap_w != b->emap_w ||
             a->emap_h != b->emap_h || a->eopen_hash != b->eopen_hash)
        hfs_plan_change(p, gp->in_env_light, "environment map or env-shade changed");
    if (a->rho_pi != b->rho_pi)
        hfs_plan_change(p, gp->in_albedo, "albedo changed");
    else if (a->albedo_map != b->albedo_map || a->albedo_gen != b->albedo_gen)
        hfs_plan_change(p, gp->in_albedo, "albedo map changed");
    else if (memcmp(a->gloss, b->gloss, sizeof a->gloss)) /* reshades, as the albedo */
        hfs_plan_change(p, gp->in_albedo, "glossy surface or view direction changed");
    for (int i = 0; i < HFS_GLES_PLAN_KEYS; ++i) {
        const int ha = i < a->n_keys, hb = i < b->n_keys;
        if (!ha && !hb)
            continue;
        if (ha != hb || !swath_equal(&a->key[i].swath, &b->key[i].swath) ||
            a->key[i].hz_layer != b->key[i].hz_layer || a->vis_path != b->vis_path ||
            a->hz_refine != b->hz_refine) {
            snprintf(why, sizeof why, "key %d: %s", i,
                     ha != hb                         ? "light added or removed"
                     : a->hz_refine != b->hz_refine ? "horizon refinement changed"
                                                      : "moved to a new swath");
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
    if (a->view != b->view || a->view_w != b->view_w || a->view_h != b->view_h ||
        (b->view && !camera_equal(&a->cam, &b->cam)))
        hfs_plan_change(p, gp->in_camera, "camera or view size changed");
    if (a->lit_encoding != b->lit_encoding || a->lit_tonemap != b->lit_tonemap ||
        a->lit_exposure != b->lit_exposure)
        hfs_plan_change(p, gp->in_lit, "lit texture encoding changed");
    if (a->bounces != b->bounces || a->bounce_dirs != b->bounce_dirs ||
        a->bounce_stride != b->bounce_stride || a->refine != b->refine ||
        a->capped != b->capped || a->bsub != b->bsub || a->bnear != b->bnear)
        hfs_plan_change(p, gp->in_bounce, "bounce settings changed");
}

/* The bounce pass reads the grid's horizons when they cap its bands, and
 * the read-back and the view the bounced targets when the frame has
 * bounces. */
static void bounce_reads(hfs_gles_plan *gp, const hfs_gles_frame_sig *now)
{
    hfs_plan *p = &gp->p;
    int reads[10], n = 0;
    reads[n++] = gp->pr_targets;
    reads[n++] = gp->pr_pyramid;
    reads[n++] = gp->in_grid;
    reads[n++] = gp->in_albedo;
    reads[n++] = gp->in_bounce;
    if (now->capped) { /* the grid's horizons, each texel's occluded part */
        reads[n++] = gp->pr_env;
        reads[n++] = gp->pr_transfer;
    }
    reads[n] = -1;
    hfs_plan_pass_reads(p, gp->pass[HFS_PASS_BOUNCE][0], reads);
    n = 0;
    reads[n++] = gp->pr_targets;
    reads[n++] = gp->in_bounce;
    if (now->bounces > 0)
        reads[n++] = gp->pr_bounced;
    reads[n] = -1;
    hfs_plan_pass_reads(p, gp->pass[HFS_PASS_READBACK][0], reads);
    reads[n++] = gp->in_lit; /* the lit texture: the read-back's reads and its encoding */
    reads[n] = -1;
    hfs_plan_pass_reads(p, gp->pass[HFS_PASS_LIT_TEXTURE][0], reads);
    n = 0;
    reads[n++] = gp->pr_pyramid;
    reads[n++] = gp->pr_targets;
    reads[n++] = gp->in_env_light;
    reads[n++] = gp->in_light_set;
    reads[n++] = gp->in_camera;
    if (now->bounces > 0)
        reads[n++] = gp->pr_bounced;
    reads[n] = -1;
    hfs_plan_pass_reads(p, gp->pass[HFS_PASS_VIEW][0], reads);
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
        if (now->env_fold)
            reads[n++] = gp->pr_skyocc; /* T_occ . L_env, no T kept */
        else if (now->env_map != 2 || now->gloss[0] != 0.0 || now->gloss[1] != 0.0)
            reads[n++] = gp->pr_transfer; /* T: the environment, or the glossy lobe */
        if (now->env_map == 2)
            reads[n++] = gp->pr_mocc;
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
    hfs_plan_pass_reads(p, gp->pass[HFS_PASS_SHADE][0], reads);
    bounce_reads(gp, now);

    hfs_plan_set need = {{0}};
    hfs_plan_set_add(&need, now->texture ? gp->pr_lit : gp->pr_image);
    if (now->view)
        hfs_plan_set_add(&need, gp->pr_view);
    gp->deferred = 0;
    if (gp->amortize > 0 && !terrain_why)
        gp->n_run = hfs_plan_frame_amortized(p, &need, gp->amortize, gp->steps, &gp->deferred);
    else
        gp->n_run = hfs_plan_frame(p, &need, gp->steps);
    for (int k = 0; k < HFS_PASS_COUNT; ++k)
        for (int i = 0; i < HFS_GLES_PLAN_INSTANCES; ++i)
            gp->run[k][i] = gp->pass[k][i] >= 0 && gp->steps[gp->pass[k][i]].run;
    return gp->n_run;
}

void hfs_gles_plan_force(hfs_gles_plan *gp, hfs_gles_pass_id p, const char *reason)
{
    const int s = gp->pass[p][0];
    if (s < 0 || gp->run[p][0])
        return;
    gp->run[p][0] = 1;
    gp->steps[s].run = 1;
    snprintf(gp->steps[s].reason, sizeof gp->steps[s].reason, "%s", reason);
    ++gp->n_run;
}

void hfs_gles_plan_done(hfs_gles_plan *gp, hfs_gles_pass_id p, int i)
{
    hfs_plan_done(&gp->p, gp->pass[p][i]);
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
        /* A frame without a view; a frame that wants the image, not the
         * lit texture, or the other way round. */
        const char *name = gp->p.pass[i].name;
        if (!s->run && !strcmp(s->reason, "not needed") &&
            (!strcmp(name, "view") || !strcmp(name, "lit texture") || !strcmp(name, "readback")))
            continue;
        hfs_frame_step *o = &out->step[out->n_steps++];
        snprintf(o->pass, sizeof o->pass, "%s", gp->p.pass[i].name);
        o->ran = s->run;
        snprintf(o->reason, sizeof o->reason, "%s", s->reason);
        out->n_ran += s->run;
    }
    out->n_deferred = gp->deferred;
}
