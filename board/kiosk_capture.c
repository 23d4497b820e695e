/*
 * kiosk_capture.c — [capture NAME] sections in the kiosk (docs/CAPTURE.md
 * "In the kiosk"): a role = heights camera's frames become the heights, a
 * role = environment camera's the lighting (either, or both at once).
 *
 * The live source (capture_live.h) is polled with the knobs; when a frame
 * changed the heights, the world's field points at them under their new
 * serial, so the next frame renders them (the GLES planner compares the
 * heights themselves, so it reruns the terrain passes for new heights at
 * the same address).  Loss and bad frames are the live source's business:
 * logged, never fatal; the last good heights stay on screen.
 *
 * The sky: each converted frame's smoothed SH replaces the environment's
 * (the scene's env-sh or env-map: the camera is the sky now) and its lights
 * replace the map's lights (env_keys, after the scene's own key lights,
 * turned with env-rotate as a map's); the lighting is recomputed
 * (kiosk_world_relight) and nothing else changes, so the planner reruns the
 * shading and the moved lights' passes only.
 */
#include "kiosk.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void capture_log(void *user, int warning, const char *line)
{
    (void)user;
    kiosk_log(warning ? KIOSK_WARNING : KIOSK_INFO, "%s", line);
}

static const hfs_capture_config *role_config(const hfs_input_config *cfg, hfs_capture_role r)
{
    for (int i = 0; i < cfg->captures.n; ++i)
        if (cfg->captures.c[i].role == r)
            return &cfg->captures.c[i];
    return NULL;
}

/* Opens c into *out (nothing with --no-devices and a device). */
static int open_one(kiosk *k, const kiosk_world *w, const hfs_capture_config *c,
                    const char *record, hfs_capture_live **out, hfs_error *err)
{
    if (!c || (k->opt.no_devices && !c->replay[0]))
        return HFS_OK; /* --no-devices: the camera is not opened either */
    hfs_capture_live_desc d = {.config = c, .config_path = k->opt.input_path,
                               .grid_w = w->in.field.width, .grid_h = w->in.field.height,
                               .record_dir = record, .start_ns = hfs_input_now_ns(),
                               .log = capture_log, .scene_env_lights = w->scene.env_lights,
                               .scene_keys = w->scene.n_key};
    const int rc = hfs_capture_live_open(&d, out, err);
    char what[64];
    if (c->role == HFS_ROLE_ENVIRONMENT)
        snprintf(what, sizeof what, "%s %dx%d environment", hfs_camenv_mapping_name(c->env.mapping),
                 c->env.map_w, c->env.map_h);
    else
        snprintf(what, sizeof what, "%dx%d heights", c->depth.grid_w ? c->depth.grid_w : d.grid_w,
                 c->depth.grid_h ? c->depth.grid_h : d.grid_h);
    if (!rc)
        kiosk_log(KIOSK_INFO, "capture %s: %s %s -> %s%s%s", c->name,
                  c->replay[0] ? "replay" : "device", c->replay[0] ? c->replay : c->device, what,
                  record ? ", recording to " : "", record ? record : "");
    return rc;
}

int kiosk_capture_open(kiosk *k, const kiosk_world *w, hfs_error *err)
{
    const hfs_capture_config *h = role_config(&w->cfg, HFS_ROLE_HEIGHTS);
    const hfs_capture_config *e = role_config(&w->cfg, HFS_ROLE_ENVIRONMENT);
    if (!h && !e)
        return k->opt.capture_record
                   ? hfs_fail(err, HFS_E_INVALID, "--capture-record: %s has no [capture NAME] "
                              "section", k->opt.input_path ? k->opt.input_path : "no --input")
                   : HFS_OK;
    /* --capture-record records the heights camera, or the sky's alone. */
    int rc = open_one(k, w, h, k->opt.capture_record, &k->capture, err);
    if (!rc)
        rc = open_one(k, w, e, h ? NULL : k->opt.capture_record, &k->capture_env, err);
    return rc;
}

int kiosk_capture_sky_apply(hfs_capture_live *live, kiosk_world *w)
{
    if (!live)
        return 0;
    uint64_t serial;
    const hfs_camsky_out *o = hfs_capture_live_sky(live, &serial);
    if (!o)
        return 0;
    hfs_scene_inputs *in = &w->in;
    hfs_scene_inputs saved = *in; /* the sky before, should the relight fail */
    memcpy(in->env_map_sh, o->sh, sizeof in->env_map_sh);
    in->has_env_map = 1;
    in->n_env_keys = o->n_keys;
    memcpy(in->env_keys, o->keys, sizeof o->keys);
    free(in->env_map); /* the scene's map is not the sky any more */
    in->env_map = NULL;
    free(in->env_residual); /* nor its residual, nor their open sky */
    in->env_residual = NULL;
    in->has_env_open = 0;
    in->env_map_width = in->env_map_height = 0;
    hfs_error err = {{0}};
    static char last[sizeof err.msg]; /* one kiosk per process: said once */
    if (kiosk_world_relight(w, &err)) {
        if (strcmp(last, err.msg))
            kiosk_log(KIOSK_WARNING, "capture: the camera's lighting: %s (the last good "
                      "lighting stays)", err.msg);
        snprintf(last, sizeof last, "%s", err.msg);
        memcpy(in->env_map_sh, saved.env_map_sh, sizeof in->env_map_sh);
        in->has_env_map = saved.has_env_map;
        in->n_env_keys = saved.n_env_keys;
        memcpy(in->env_keys, saved.env_keys, sizeof in->env_keys);
        return 0;
    }
    last[0] = 0;
    return 1;
}

int kiosk_capture_sky_drain(hfs_capture_live *live, kiosk_world *w)
{
    if (!hfs_capture_live_drain(live, hfs_input_now_ns()))
        return 0;
    return kiosk_capture_sky_apply(live, w);
}

void kiosk_capture_apply(hfs_capture_live *live, kiosk_world *w)
{
    if (!live)
        return;
    int gw, gh;
    uint64_t serial;
    const float *z = hfs_capture_live_heights(live, &gw, &gh, &serial);
    if (!z)
        return;
    w->in.field.z = z;
    w->in.field.width = gw;
    w->in.field.height = gh;
    w->in.serial = serial;
}

int kiosk_capture_drain(hfs_capture_live *live, kiosk_world *w)
{
    if (!hfs_capture_live_drain(live, hfs_input_now_ns()))
        return 0;
    kiosk_capture_apply(live, w);
    return 1;
}
