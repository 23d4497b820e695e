/*
 * input_map.c — input events to scene edits (input_map.h).
 *
 * Why these rules: a turn must feel the same whatever the light count or
 * the frame rate, so the edit depends only on the event (detents, time)
 * and the control's configuration; clamping returns 0 so the kiosk does
 * not re-render for a knob turned past its end.
 */
#include "input_map.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const char *const preset_names[HFS_INPUT_N_PRESETS] = {"kiosk", "panel", "headless"};

const char *hfs_input_preset_name(int index)
{
    return index >= 0 && index < HFS_INPUT_N_PRESETS ? preset_names[index] : NULL;
}

void hfs_input_state_init(hfs_input_state *st, const hfs_scene *scene)
{
    memset(st, 0, sizeof *st);
    st->cam_azimuth = HFS_INPUT_CAMERA_AZIMUTH;
    st->cam_elevation = HFS_INPUT_CAMERA_ELEVATION;
    st->cam_zoom = 1.0;
    for (int i = 0; i < HFS_INPUT_N_PRESETS; ++i)
        if (scene && !strcmp(scene->preset, preset_names[i]))
            st->preset = i;
}

double hfs_input_gain(const hfs_control_config *k, int64_t dt_ns, int delta)
{
    if (!(k->accel > 1.0) || !(k->accel_ms > 0.0) || delta == 0 || dt_ns < 0)
        return 1.0;
    const double spacing_ms = (double)dt_ns / 1e6 / fabs((double)delta);
    if (spacing_ms >= k->accel_ms)
        return 1.0;
    return 1.0 + (k->accel - 1.0) * (1.0 - spacing_ms / k->accel_ms);
}

/* The surface value a surface.* action edits, given from now on (the
 * lighting's default where the scene named none). */
static double *surface_value(hfs_action a, hfs_scene *s)
{
    hfs_lighting d;
    hfs_lighting_defaults(&d);
    double *v = a == HFS_ACTION_SURFACE_ALBEDO     ? &s->albedo
                : a == HFS_ACTION_SURFACE_SPECULAR ? &s->specular
                                                   : &s->gloss;
    int *given = a == HFS_ACTION_SURFACE_ALBEDO     ? &s->albedo_given
                 : a == HFS_ACTION_SURFACE_SPECULAR ? &s->specular_given
                                                    : &s->gloss_given;
    if (!*given)
        *v = a == HFS_ACTION_SURFACE_ALBEDO     ? d.albedo
             : a == HFS_ACTION_SURFACE_SPECULAR ? d.specular
                                                : d.gloss;
    *given = 1;
    return v;
}

/* albedo + specular <= 1 (energy; the renderer refuses more): the knob
 * that would pass it stops there. */
static double surface_energy(hfs_action a, const hfs_scene *s, double x)
{
    if (a == HFS_ACTION_SURFACE_ALBEDO && s->specular_given)
        return fmin(x, 1.0 - s->specular);
    if (a == HFS_ACTION_SURFACE_SPECULAR)
        return fmin(x, 1.0 - (s->albedo_given ? s->albedo : 1.0));
    return x;
}

/* The value a continuous action edits, or NULL (no such light now). */
static double *target_value(const hfs_control_config *k, hfs_input_state *st, hfs_scene *s)
{
    int key = -1, local = -1;
    const hfs_action_info *a = hfs_action_get(k->action);
    if (a->target == HFS_TARGET_KEY)
        key = k->light >= 0 ? k->light : st->selected;
    else if (a->target == HFS_TARGET_LOCAL)
        local = k->light >= 0 ? k->light : st->selected - s->n_key;
    if (a->target == HFS_TARGET_KEY && (key < 0 || key >= s->n_key))
        return NULL;
    if (a->target == HFS_TARGET_LOCAL && (local < 0 || local >= s->n_local))
        return NULL;

    switch (k->action) {
    case HFS_ACTION_KEY_AZIMUTH: return &s->key[key].phi;
    case HFS_ACTION_KEY_ELEVATION: return &s->key[key].elev;
    case HFS_ACTION_KEY_RADIUS: return &s->key[key].alpha;
    case HFS_ACTION_KEY_RADIANCE: return &s->key[key].le;
    case HFS_ACTION_LOCAL_X: return &s->local[local].x;
    case HFS_ACTION_LOCAL_Y: return &s->local[local].y;
    case HFS_ACTION_LOCAL_Z: return &s->local[local].z;
    case HFS_ACTION_LOCAL_RADIUS: return &s->local[local].r;
    case HFS_ACTION_LOCAL_RADIANCE: return &s->local[local].le;
    case HFS_ACTION_ENV_ROTATE: return &s->env_rotate_deg;
    case HFS_ACTION_CAMERA_AZIMUTH: return &st->cam_azimuth;
    case HFS_ACTION_CAMERA_ELEVATION: return &st->cam_elevation;
    case HFS_ACTION_CAMERA_ZOOM: return &st->cam_zoom;
    case HFS_ACTION_SURFACE_ALBEDO:
    case HFS_ACTION_SURFACE_SPECULAR:
    case HFS_ACTION_SURFACE_GLOSS: return surface_value(k->action, s);
    default: return NULL;
    }
}

static double limit(const hfs_control_config *k, double v)
{
    if (k->wrap) {
        const double range = k->max - k->min;
        v = k->min + fmod(v - k->min, range);
        if (v < k->min)
            v += range;
        if (v >= k->max) /* fmod's rounding at the seam */
            v = k->min;
        return v;
    }
    return v < k->min ? k->min : v > k->max ? k->max : v;
}

/* The turn's acceleration gain, its time and direction kept for the next. */
static double turn_gain(const hfs_control_config *k, int index, hfs_input_state *st,
                        const hfs_input_event *ev)
{
    const int dir = ev->delta > 0 ? 1 : -1;
    double gain = 1.0;
    if (st->last_turn[index].dir == dir)
        gain = hfs_input_gain(k, ev->t_ns - st->last_turn[index].t_ns, ev->delta);
    st->last_turn[index].t_ns = ev->t_ns;
    st->last_turn[index].dir = dir;
    return gain;
}

/* map.pan_x / map.pan_y: step display pixels a detent, a pixel being
 * 2^map_level texels of the field; the centre stays on the field. */
static int pan_map(const hfs_control_config *k, int index, hfs_input_state *st,
                   const hfs_input_event *ev)
{
    const double gain = turn_gain(k, index, st, ev);
    if (st->map_levels <= 0)
        return 0;
    const int x = k->action == HFS_ACTION_MAP_PAN_X;
    double *v = x ? &st->map_x : &st->map_y;
    const double end = x ? st->map_w : st->map_h;
    double n = *v + ev->delta * k->step * gain * ldexp(1.0, st->map_level);
    n = n < 0.0 ? 0.0 : n > end ? end : n;
    if (!isfinite(n) || n == *v)
        return 0;
    *v = n;
    return 1;
}

/* map.zoom: a clockwise detent one level in (finer), counter-clockwise one
 * out, clamped; a press one level in, from the finest back to the whole
 * field. */
static int zoom_map(hfs_input_state *st, int delta, int button)
{
    const int before = st->map_level, top = st->map_levels - 1;
    if (top < 0)
        return 0;
    const long long l = button ? (st->map_level == 0 ? top : st->map_level - 1)
                               : (long long)st->map_level - delta; /* an evdev delta: any int */
    st->map_level = l < 0 ? 0 : l > top ? top : (int)l;
    return st->map_level != before;
}

static int turn_value(const hfs_control_config *k, int index, hfs_input_state *st,
                      const hfs_input_event *ev, hfs_scene *s)
{
    const double gain = turn_gain(k, index, st, ev);
    double *v = target_value(k, st, s);
    if (!v)
        return 0;
    const double old = *v;
    double x = hfs_action_get(k->action)->multiplicative
                   ? old * pow(k->step, ev->delta * gain)
                   : old + ev->delta * k->step * gain;
    x = surface_energy(k->action, s, limit(k, x));
    if (!isfinite(x) || x == old)
        return 0;
    *v = x;
    return 1;
}

static int wrap_index(int i, int n) { return ((i % n) + n) % n; }

static int select_light(hfs_input_state *st, const hfs_scene *s, int delta)
{
    const int n = s->n_key + s->n_local;
    if (n == 0)
        return 0;
    const int before = st->selected;
    st->selected = wrap_index(st->selected + delta % n, n);
    return st->selected != before;
}

static int next_preset(hfs_input_state *st, hfs_scene *s, int delta)
{
    const int before = st->preset;
    st->preset = wrap_index(st->preset + delta % HFS_INPUT_N_PRESETS, HFS_INPUT_N_PRESETS);
    const int changed = st->preset != before || strcmp(s->preset, preset_names[st->preset]);
    snprintf(s->preset, sizeof s->preset, "%s", preset_names[st->preset]);
    return changed;
}

int hfs_input_apply(const hfs_input_config *cfg, hfs_input_state *st,
                    const hfs_input_event *ev, hfs_scene *scene, hfs_error *err)
{
    /* A source bug could leave the name unterminated: never read past it. */
    const hfs_control_config *k = memchr(ev->control, '\0', sizeof ev->control)
                                      ? hfs_input_config_find(cfg, ev->control)
                                      : NULL;
    if (!k)
        return hfs_fail(err, HFS_E_INVALID, "input: unknown control '%.*s'",
                        HFS_CONTROL_NAME_MAX, ev->control);
    const int index = (int)(k - cfg->control);
    const int turn = ev->kind == HFS_INPUT_TURN;
    if (turn != (k->kind == HFS_CONTROL_KNOB) ||
        (ev->kind != HFS_INPUT_TURN && ev->kind != HFS_INPUT_PRESS &&
         ev->kind != HFS_INPUT_RELEASE))
        return hfs_fail(err, HFS_E_INVALID, "input: control '%s' is a %s, it cannot be %s",
                        k->name, k->kind == HFS_CONTROL_KNOB ? "knob" : "button",
                        turn ? "turned" : "pressed or released");
    if (ev->kind == HFS_INPUT_RELEASE || (turn && ev->delta == 0))
        return 0;
    const int delta = turn ? ev->delta : 1; /* a press steps forward once */

    switch (k->action) {
    case HFS_ACTION_LIGHT_SELECT:
        return select_light(st, scene, delta);
    case HFS_ACTION_PRESET:
        return next_preset(st, scene, delta);
    case HFS_ACTION_OVERLAY:
        st->overlay = !st->overlay;
        return 1;
    case HFS_ACTION_VIEW:
        st->view = !st->view;
        return 1;
    case HFS_ACTION_MAP_ZOOM:
        return zoom_map(st, delta, !turn);
    case HFS_ACTION_MAP_PAN_X:
    case HFS_ACTION_MAP_PAN_Y:
        return pan_map(k, index, st, ev);
    case HFS_ACTION_NONE:
    case HFS_ACTION_COUNT:
        return hfs_fail(err, HFS_E_INVALID, "input: control '%s' has no action", k->name);
    default:
        return turn_value(k, index, st, ev, scene);
    }
}

int hfs_input_check_scene(const hfs_input_config *cfg, const hfs_scene *scene,
                          hfs_error *err)
{
    for (int i = 0; i < cfg->n_controls; ++i) {
        const hfs_control_config *k = &cfg->control[i];
        const hfs_action_info *a = hfs_action_get(k->action);
        if (!a || k->light < 0)
            continue;
        if (a->target == HFS_TARGET_KEY && k->light >= scene->n_key)
            return hfs_fail(err, HFS_E_INVALID, "%s: light %d: the scene has %d key light%s",
                            k->name, k->light, scene->n_key, scene->n_key == 1 ? "" : "s");
        if (a->target == HFS_TARGET_LOCAL && k->light >= scene->n_local)
            return hfs_fail(err, HFS_E_INVALID, "%s: light %d: the scene has %d local light%s",
                            k->name, k->light, scene->n_local, scene->n_local == 1 ? "" : "s");
    }
    return HFS_OK;
}
