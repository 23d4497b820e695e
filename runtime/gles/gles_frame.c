/*
 * gles_frame.c — one GLES frame: the profile and its limits, the
 * resources, the plan (which passes and which of their instances run, and
 * why), then a loop over the pass table (pass.h).  What the passes share
 * is in pass_common.c, below them.
 */
#include "gles_backend.h"

#include "lights.h"

#include <string.h>

/* The profile, the layout, and every limit the frame must meet (each
 * pass's own through its layout hook), before anything is allocated. */
static int check_limits(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err)
{
    const hfs_gl_caps *caps = &g->caps;
    const hfs_gles_layout *L = &fr->L;
    int rc;
    if ((rc = hfs_gl_caps_check_texture(caps, L->w, L->h, L->n_layers,
                                        "height levels (the field's size)", err)) ||
        (rc = hfs_gl_caps_check_texture(caps, HFS_VIS_TABLE_SIZE, HFS_VIS_TABLE_SIZE,
                                        4 * (HFS_MAX_KEY_LIGHTS + 1), "wedge tables", err)) ||
        (rc = hfs_gl_caps_check_draw_buffers(caps, 4, "SH visibility (16 coefficients)", err)) ||
        (rc = hfs_gl_caps_check_samplers(caps, 10, "shading pass", err)) ||
        (rc = hfs_gl_caps_check_uniform_block(caps, hfs_gles_scales_vec4() * 16,
                                              "per-scale constants", err)))
        return rc;
    for (int p = 0; p < HFS_PASS_COUNT; ++p) {
        const hfs_gles_pass *pass = hfs_gles_pass_table[p];
        if (pass->layout && (!pass->present || pass->present(fr)) &&
            (rc = pass->layout(g, fr, err)))
            return rc;
    }
    return HFS_OK;
}

/* Textures follow the frame's sizes; what a reallocated texture held is
 * lost, and the planner is told so before it plans. */
static int fit_resources(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err)
{
    const hfs_gles_resources *r = &g->r;
    const unsigned gens[5] = {r->terrain_gen, r->grid_gen, r->keyhz_gen, r->localv_gen,
                              r->kf_gen};
    const hfs_gles_layers n = {.hor = fr->hor_layers, .far = fr->split.on ? fr->split.heights : 0,
                               .far_w = fr->far_aw, .far_h = fr->far_ah, .key = fr->key_layers,
                               .local = (fr->n_local + 1) / 2, .n_keys = fr->n_keys,
                               .venv = fr->has_env && !fr->slice};
    int rc = hfs_gles_resources_ensure(&g->r, &g->gl, &g->caps, &fr->L, &n, err);
    if (rc)
        return rc;
    if (r->terrain_gen != gens[0])
        g->terrain_valid = 0;
    hfs_gles_plan_lost(&g->plan, r->grid_gen != gens[1], r->keyhz_gen != gens[2],
                       r->localv_gen != gens[3], r->kf_gen != gens[4]);
    hfs_gles_wedge_textures_follow(&g->wedge, &g->gl, &g->caps);
    rc = hfs_gles_albedo_texture_follow(&g->albedo, &g->gl, &g->caps, fr->albedo, fr->f->width,
                                        fr->f->height, err);
    fr->albedo_gen = g->albedo.gen;
    const unsigned occ_gen = g->envmap.occ_gen;
    const int occ = fr->has_env && fr->env_map == 2;
    if (!rc)
        rc = hfs_gles_env_occ_ensure(&g->envmap, &g->gl, &g->caps, occ ? fr->L.w : 0,
                                     occ ? fr->L.h : 0, err);
    if (g->envmap.occ_gen != occ_gen)
        hfs_plan_drop(&g->plan.p, g->plan.pr_mocc);
    /* The frame keeps the transfer or the sky occlusion, not both. */
    if (fr->env_fold ? hfs_gles_transfer_free(&g->r, &g->gl)
                     : hfs_gles_skyocc_free(&g->r, &g->gl))
        hfs_plan_drop(&g->plan.p, fr->env_fold ? g->plan.pr_transfer : g->plan.pr_skyocc);
    return rc;
}

/* Whether the frame's SH sky is shaded from the sky occlusion (T_occ
 * dotted with the sky per texel: 3 values as fp16 pairs, 12 bytes) rather
 * than a kept transfer (16 values in 4 RGBA targets, 32): on the slice path, for the SH sky's own
 * occlusion (not env-shade = map's), when nothing else reads T (a glossy
 * lobe, bounces capped at the grid's horizons), and until the sky turns.
 * A sky turned or re-tinted between two frames says a knob moves it: from
 * then on this renderer keeps the transfer, so that a turn costs the
 * shading alone (the first turn pays the transfer once).  Both give the
 * shading the same values (hfs_env_occ). */
static int env_fold(hfs_gles *g, const hfs_gles_frame *fr)
{
    if (!fr->has_env)
        return 0;
    if (g->env_seen_valid && memcmp(g->env_seen, fr->l_env, sizeof g->env_seen))
        g->env_turned = 1;
    memcpy(g->env_seen, fr->l_env, sizeof g->env_seen);
    g->env_seen_valid = 1;
    return fr->slice && fr->env_map != 2 && !fr->gloss.on && !(fr->bounces > 0 && fr->capped) &&
           !g->env_turned;
}

/* What this frame's passes are computed from, for the planner. */
static void frame_signature(const hfs_gles_frame *fr, hfs_gles_frame_sig *s)
{
    const hfs_quality *q = fr->q;
    memset(s, 0, sizeof *s);
    s->sub = fr->L.sub, s->vw = fr->L.vw, s->vh = fr->L.vh;
    s->has_env = fr->has_env;
    s->nphi_env = q->nphi_env;
    s->vis_path = (int)q->visibility;
    s->hz_refine = q->refine;
    if (fr->split.on) {
        s->far_from = (int)fr->split.from;
        s->far_k = fr->split.k;
        s->far_step = fr->split.step;
    }
    if (fr->has_env) {
        memcpy(s->l_env, fr->l_env, sizeof s->l_env);
        s->env_map = fr->env_map;
        s->env_fold = fr->env_fold;
    }
    if (s->env_map > 0) { /* FNV-1a of the open-sky table: it stands for the map */
        const unsigned char *b = (const unsigned char *)fr->l->env_open;
        uint64_t h = 1469598103934665603ull;
        for (size_t i = 0; i < HFS_ENV_OPEN_FLOATS * sizeof(float); ++i)
            h = (h ^ b[i]) * 1099511628211ull;
        s->eopen_hash = h;
        s->emap = fr->env_map == 2 ? fr->l->env_shade_map : NULL;
        s->emap_w = fr->l->env_map_width, s->emap_h = fr->l->env_map_height;
    }
    s->rho_pi = fr->rho_pi;
    s->albedo_map = fr->albedo != NULL;
    s->albedo_gen = fr->albedo_gen;
    if (fr->gloss.on) {
        const hfs_gloss *g = &fr->gloss;
        const double gsig[9] = {g->ks, g->s, g->view[0], g->view[1], g->view[2], g->at_eye,
                                g->eye[0], g->eye[1], g->eye[2]};
        memcpy(s->gloss, gsig, sizeof gsig);
    }
    s->n_keys = fr->n_keys;
    for (int i = 0; i < fr->n_keys && i < HFS_GLES_PLAN_KEYS; ++i) {
        const hfs_gles_key *k = &fr->keys[i].k;
        s->key[i].swath = k->swath;
        s->key[i].hz_layer = k->hz_layer;
        memcpy(s->key[i].dir, k->dir, sizeof k->dir);
        s->key[i].alpha = k->alpha;
        memcpy(s->key[i].le, k->le, sizeof k->le);
    }
    s->bounces = fr->bounces;
    s->bounce_dirs = fr->bounces > 0 ? hfs_bounce_dirs(q) : 0;
    s->bounce_stride = fr->bounces > 0 ? q->nphi_env / hfs_bounce_dirs(q) : 0;
    s->refine = fr->bounces > 0 ? q->bounce_refine : 0;
    s->capped = fr->bounces > 0 && fr->capped;
    s->bsub = fr->bounces > 0 ? fr->bsub : 0;
    s->bnear = fr->bounces > 0 ? q->bounce_near : 0;
    s->n_local = fr->n_local;
    s->nphi_local = q->nphi_local;
    s->local_full = q->local_full_swath;
    for (int i = 0; i < fr->n_local; ++i) {
        memcpy(s->local[i].pos, fr->local[i].pos, sizeof fr->local[i].pos);
        s->local[i].radius = fr->local[i].radius;
        memcpy(s->local[i].le, fr->local[i].radiance, sizeof fr->local[i].radiance);
        s->local[i].open = fr->local_open[i];
    }
    if (fr->cam) {
        s->view = 1;
        s->cam = *fr->cam;
        s->view_w = fr->view_w, s->view_h = fr->view_h;
    }
    if (fr->lit) {
        s->texture = 1;
        s->lit_encoding = (int)fr->lit->encoding;
        s->lit_tonemap = fr->lit->tonemap;
        s->lit_exposure = fr->lit->exposure;
    }
}

/* Whether a frame whose heights changed by the edit g->edit holds may
 * recompute only what the edit reaches: nothing else changed and every
 * product the frame needs is current (the planner, on a copy, would run
 * nothing), and the kept image and view hold. */
static int edit_path(hfs_gles *g, const hfs_gles_frame_sig *sig, int kept)
{
    g->plan_dry = g->plan;
    return kept && !hfs_gles_grid_horizons_freed(&g->r) &&
           hfs_gles_plan_frame(&g->plan_dry, sig, NULL) == 0;
}

/* Plans the frame; 0 when no pass needs to run (the kept image holds). */
static int plan(hfs_gles *g, hfs_gles_frame *fr)
{
    const char *terrain_why = hfs_gles_terrain_change(g, fr->f, fr->q);
    const char *edit_why =
        terrain_why == hfs_gles_heights_changed ? hfs_gles_edit_begin(g, fr) : NULL;
    if (terrain_why == hfs_gles_heights_changed)
        g->heights_edited = 1; /* later edits find the grid's horizons kept */
    if (terrain_why) {
        g->terrain_valid = 0;
        g->extent_valid = 0;
    }
    /* Local lights the terrain cannot shadow need no ratios (lights.h). */
    if (fr->n_local > 0 && !g->extent_valid) {
        hfs_field_extent_make(fr->f, &g->extent);
        g->extent_valid = 1;
    }
    for (int i = 0; i < fr->n_local; ++i)
        fr->local_open[i] = hfs_local_light_open(&g->extent, &fr->local[i]);
    hfs_gles_frame_sig sig;
    frame_signature(fr, &sig);
    if (!fr->lit) { /* an image frame keeps the texture's encoding: no change to it */
        sig.lit_encoding = g->plan.last.lit_encoding;
        sig.lit_tonemap = g->plan.last.lit_tonemap;
        sig.lit_exposure = g->plan.last.lit_exposure;
    }
    const size_t n_img = (size_t)fr->L.w * fr->L.h * 3;
    /* A texture frame needs no image: the planner alone says whether the
     * kept texture holds. */
    const int kept = fr->lit || (g->last_img && g->last_img_cap >= n_img);
    const int view_kept = !fr->cam || hfs_gles_view_copy_kept(g, fr);
    if (edit_why && edit_path(g, &sig, kept && view_kept) && !hfs_gles_edit_regions(g, fr)) {
        fr->edit = 1;
        terrain_why = edit_why;
    }
    if (hfs_gles_plan_frame(&g->plan, &sig, terrain_why) == 0 && kept && view_kept &&
        !fr->objects)
        return 0;
    /* The first view after a failed one; or objects, lit anew each frame. */
    if (!view_kept || fr->objects)
        g->plan.run[HFS_PASS_VIEW][0] = 1;
    /* The readback needs this frame's output scale, and a shaded frame is
     * read back: the two go together (as does a frame without a kept
     * image, e.g. the first after a failure).  The lit texture reads the
     * scale the targets were shaded with (g->lit_scale) instead. */
    if (!fr->lit &&
        (g->plan.run[HFS_PASS_SHADE][0] || g->plan.run[HFS_PASS_READBACK][0] || !kept))
        g->plan.run[HFS_PASS_SHADE][0] = g->plan.run[HFS_PASS_READBACK][0] = 1;
    for (int p = 0; p < HFS_PASS_COUNT; ++p)
        fr->run[p] = g->plan.run[p];
    return 1;
}

/* The grid's horizons and far grid (the slice path's environment
 * visibility) are read again only when the environment's product is made
 * anew: by the first turn of the sky or the map, by an edit of the
 * heights, by bounces.  So after a frame that made the sky occlusion or
 * the map's occluded light from them, and while this renderer has seen
 * neither a turn nor an edit, they are freed (3.4 MiB of a 512² frame's
 * 14.6, issue 37); the planner still holds them valid, and grid_restore
 * makes them anew the first time a pass reads them.  A renderer that has
 * seen a turn or an edit keeps them, so that its later turns cost the
 * shading and its later edits their own region (issue 38). */
static void grid_release(hfs_gles *g, const hfs_gles_frame *fr)
{
    if (fr->slice && fr->has_env && (fr->env_fold || fr->env_map == 2) && fr->bounces == 0 &&
        !g->env_turned && !g->heights_edited)
        hfs_gles_grid_horizons_free(&g->r, &g->gl);
}

/* Before the passes: the grid's horizons, freed after an earlier frame,
 * made anew and filled again by the environment pass when this frame
 * reads them (the same values: the pass's inputs have not changed, or the
 * plan runs it anyway; what read them before need not run again). */
static void grid_restore(hfs_gles *g, hfs_gles_frame *fr)
{
    if (!hfs_gles_grid_horizons_freed(&g->r))
        return;
    const int reads = fr->run[HFS_PASS_ENV_HORIZONS][0] || fr->run[HFS_PASS_ENV_TRANSFER][0] ||
                      fr->run[HFS_PASS_ENV_MAP_SLICES][0] ||
                      fr->run[HFS_PASS_ENV_SKY_OCCLUSION][0] ||
                      (fr->run[HFS_PASS_BOUNCE][0] && fr->capped) || g->timing.level >= 2;
    if (!reads)
        return;
    hfs_gles_grid_horizons_remake(&g->r, &g->gl, &g->caps);
    hfs_gles_plan_force(&g->plan, HFS_PASS_ENV_HORIZONS,
                        "env visibility made anew (freed after an earlier frame)");
}

static void mark_cached(hfs_gles *g, const hfs_gles_frame *fr, int p)
{
    const hfs_gles_pass *pass = hfs_gles_pass_table[p];
    for (int s = 0; s < HFS_PASS_MAX_STAGES && pass->stages[s]; ++s)
        if (!pass->stage_present || pass->stage_present(fr, s))
            g->timing.cached[g->stage_slot[p] + s] = 1;
}

/* One row of the table: prepare, then the instances the plan chose. */
static int run_pass(hfs_gles *g, hfs_gles_frame *fr, int p, hfs_error *err)
{
    const hfs_gles_pass *pass = hfs_gles_pass_table[p];
    int rc;
    if (pass->present && !pass->present(fr))
        return HFS_OK;
    if (pass->prepare && (rc = pass->prepare(g, fr, err)))
        return rc;
    const int n = hfs_gles_pass_max_instances(pass);
    int any = 0;
    for (int i = 0; i < n; ++i)
        any |= fr->run[p][i];
    if (!any) {
        mark_cached(g, fr, p);
        return HFS_OK;
    }
    const int self_timed = pass->stages[1] != NULL; /* times its own stages */
    if (!self_timed)
        hfs_gles_stage_begin(g, (hfs_gles_pass_id)p, 0);
    if ((rc = pass->run(g, fr, fr->run[p], err)))
        return rc;
    if (!self_timed)
        hfs_gles_stage_end(g, (hfs_gles_pass_id)p, 0);
    for (int i = 0; i < n; ++i)
        if (fr->run[p][i])
            hfs_gles_plan_done(&g->plan, (hfs_gles_pass_id)p, i);
    return HFS_OK;
}

/* Counting twins of the passes that have one (timing level 2): their
 * fetch counts, at the price of their targets (dropped after). */
static int count_fetches(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err)
{
    for (int p = 0; p < HFS_PASS_COUNT; ++p) {
        const hfs_gles_pass *pass = hfs_gles_pass_table[p];
        if (!pass->count)
            continue;
        double *fetch = &g->timing.fetch[g->stage_slot[p]];
        for (int s = 0; s < HFS_PASS_MAX_STAGES && pass->stages[s]; ++s)
            fetch[s] = g->timing.level < 2 ? -1.0 : 0.0;
        if (g->timing.level < 2)
            continue;
        int rc;
        if ((!pass->present || pass->present(fr)) && (rc = pass->count(g, fr, fetch, err)))
            return rc;
    }
    if (g->timing.level >= 2) /* their targets now hold counts */
        hfs_gles_plan_lost(&g->plan, 1, 0, 0, 1);
    return HFS_OK;
}

int hfs_gles_frame_render(hfs_gles *g, hfs_gles_frame *fr, hfs_error *err)
{
    const int fp32 = fr->q->precision == HFS_PRECISION_FP32;
    int rc;
    if ((rc = hfs_gl_caps_select(&g->driver, g->profile[0] ? g->profile : NULL, fp32,
                                 g->strict_limits, &g->caps, err)) ||
        (rc = hfs_gles_layout_init(&fr->L, fr->f, fr->q, err)))
        return rc;
    hfs_gles_timing_select(&g->timing, g->caps.timer_query);
    fr->tables = fr->q->visibility == HFS_VIS_WEDGE_TABLE;
    fr->slice = fr->q->visibility == HFS_VIS_SLICE;
    fr->env_fold = env_fold(g, fr);
    if ((rc = check_limits(g, fr, err)) || (rc = fit_resources(g, fr, err)))
        return rc;
    const size_t n_img = (size_t)fr->L.w * fr->L.h * 3;
    if (!plan(g, fr)) { /* nothing changed: no pass; the last image (texture) again */
        if (fr->out)
            memcpy(fr->out->rgb, g->last_img, n_img * sizeof *fr->out->rgb);
        for (int p = 0; p < HFS_PASS_COUNT; ++p)
            if (p != HFS_PASS_VIEW || fr->cam)
                mark_cached(g, fr, p);
        return HFS_OK; /* plan() copied the kept view */
    }
    g->stats.offset_mismatches = 0;
    grid_restore(g, fr);
    for (int p = 0; p < HFS_PASS_COUNT; ++p) {
        if (p == HFS_PASS_SHADE && !fr->run[p][0]) {
            /* No shading: the kept image holds (a frame with an image
             * shades whenever it reads back, plan()), and so do the
             * shaded targets, so the passes after it run as planned: the
             * bounce for new bounce settings in a lit-texture frame (it
             * was skipped too, and the texture kept the old bounces),
             * the lit texture, the view. */
            if (fr->out)
                memcpy(fr->out->rgb, g->last_img, n_img * sizeof *fr->out->rgb);
            mark_cached(g, fr, HFS_PASS_SHADE);
            continue;
        }
        if ((rc = run_pass(g, fr, p, err)))
            return rc;
        if (p == HFS_PASS_SHADE) /* what the lit targets hold, for later views */
            g->lit_scale = fr->out_scale;
    }
    if (!(rc = count_fetches(g, fr, err)))
        grid_release(g, fr);
    return rc;
}
