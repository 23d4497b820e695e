/*
 * test_input_config.c — the input configuration (board/input_config.h):
 * board/kiosk.ini loads with the values it states, defaults per action are
 * filled in, and each broken file in tests/data/input/bad_*.ini (its first
 * line says what is wrong) fails with exactly "PATH:LINE: problem".
 * Arguments: the data directory, then board/kiosk.ini.
 */
#include "input_config.h"

#include <linux/input-event-codes.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"

static const char *data_dir;

static void kiosk(const char *path)
{
    hfs_input_config cfg;
    hfs_error err = {{0}};
    const int rc = hfs_input_config_load(path, &cfg, &err);
    CHECK(rc == 0, "kiosk.ini: %s", err.msg);
    if (rc)
        return;
    CHECK(cfg.n_controls == 14, "kiosk.ini: %d controls", cfg.n_controls);
    const hfs_control_config *az = hfs_input_config_find(&cfg, "azimuth");
    CHECK(az && az->kind == HFS_CONTROL_KNOB && az->device == HFS_DEVICE_GPIO &&
              !strcmp(az->path, "gpiochip0") && az->lines[0] == 17 && az->lines[1] == 18 &&
              az->steps_per_detent == 4 && az->action == HFS_ACTION_KEY_AZIMUTH &&
              az->light == -1 && az->step == 2 && az->accel == 4 && az->accel_ms == 30 &&
              az->min == 0 && az->max == 360 && az->wrap == 1,
          "kiosk.ini: azimuth");
    const hfs_control_config *el = hfs_input_config_find(&cfg, "elevation");
    CHECK(el && el->min == 5 && el->max == 90 && !el->wrap && el->steps_per_detent == 4 &&
              el->accel_ms == 40,
          "kiosk.ini: elevation (defaults: 4 steps, 40 ms, no wrap)");
    const hfs_control_config *env = hfs_input_config_find(&cfg, "environment");
    CHECK(env && env->steps_per_detent == 2 && env->wrap && env->max == 360, "environment");
    const hfs_control_config *next = hfs_input_config_find(&cfg, "next");
    CHECK(next && next->kind == HFS_CONTROL_BUTTON && next->lines[0] == 27 &&
              next->active_low && next->debounce_ms == 10 &&
              next->action == HFS_ACTION_LIGHT_SELECT,
          "kiosk.ini: next");
    const hfs_control_config *dial = hfs_input_config_find(&cfg, "dial");
    CHECK(dial && dial->device == HFS_DEVICE_EVDEV && dial->evdev_type == EV_REL &&
              dial->evdev_code == REL_DIAL && dial->step == 1.1 && dial->min == 0.05 &&
              !strcmp(dial->path, "/dev/input/by-id/usb-Griffin_PowerMate-event-if00"),
          "kiosk.ini: dial");
    const hfs_control_config *p = hfs_input_config_find(&cfg, "preset");
    CHECK(p && p->evdev_type == EV_KEY && p->evdev_code == KEY_P &&
              p->action == HFS_ACTION_PRESET,
          "kiosk.ini: preset");
    const hfs_control_config *lx = hfs_input_config_find(&cfg, "local_x");
    CHECK(lx && lx->device == HFS_DEVICE_NONE && lx->light == -1 && lx->min == -100,
          "kiosk.ini: local_x (replay only)");
    const hfs_control_config *view = hfs_input_config_find(&cfg, "view");
    CHECK(view && view->kind == HFS_CONTROL_BUTTON && view->evdev_code == KEY_V &&
              view->action == HFS_ACTION_VIEW,
          "kiosk.ini: view");
    const hfs_control_config *zoom = hfs_input_config_find(&cfg, "camera_zoom");
    CHECK(zoom && zoom->device == HFS_DEVICE_NONE && zoom->action == HFS_ACTION_CAMERA_ZOOM &&
              zoom->step == 1.1 && zoom->min == 0.1 && zoom->max == 10.0,
          "kiosk.ini: camera_zoom (replay only, the action's defaults)");
    CHECK(hfs_input_config_find(&cfg, "nope") == NULL, "find: unknown name");
}

static void defaults(void)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/map.ini", data_dir);
    hfs_input_config cfg;
    hfs_error err = {{0}};
    CHECK(hfs_input_config_load(path, &cfg, &err) == 0, "map.ini: %s", err.msg);
    const hfs_control_config *k = hfs_input_config_find(&cfg, "el");
    CHECK(k && k->step == 1 && k->min == 0 && k->max == 90 && !k->wrap && k->accel == 1,
          "key.elevation defaults");
    k = hfs_input_config_find(&cfg, "lle");
    CHECK(k && k->step == 1.1 && k->min == 0.01 && !k->wrap, "local.radiance defaults");
    k = hfs_input_config_find(&cfg, "env");
    CHECK(k && k->step == 5 && k->min == 0 && k->max == 360 && k->wrap, "env.rotate defaults");
    k = hfs_input_config_find(&cfg, "alpha");
    CHECK(k && k->step == 0.5 && k->min == 0.5 && k->max == 30, "key.radius defaults");
    CHECK(k && k->config_line == 15, "config_line: %d", k ? k->config_line : -1);
    for (int a = HFS_ACTION_NONE + 1; a < HFS_ACTION_COUNT; ++a) {
        const hfs_action_info *info = hfs_action_get((hfs_action)a);
        CHECK(info && hfs_action_from_name(info->name) == (hfs_action)a, "action %d", a);
    }
    CHECK(hfs_action_get(HFS_ACTION_NONE) == NULL, "no info for NONE");
}

typedef struct bad_case {
    const char *file;
    int code;
    const char *expect; /* the message after "PATH" */
} bad_case;

static const bad_case bad[] = {
    {"bad_unknown_key.ini", HFS_E_FORMAT, ":4: unknown key 'stepz' (known: gpio, evdev, "
     "steps_per_detent, active_low, debounce_ms, action, light, step, accel, accel_ms, min, "
     "max, wrap)"},
    {"bad_unknown_action.ini", HFS_E_FORMAT, ":3: unknown action 'key.azimut' (known: "
     "key.azimuth, key.elevation, key.radius, key.radiance, local.x, local.y, local.z, "
     "local.radius, local.radiance, env.rotate, light.select, preset.next, overlay.toggle, "
     "camera.azimuth, camera.elevation, camera.zoom, view.toggle, surface.albedo, "
     "surface.specular, surface.gloss, map.pan_x, map.pan_y, map.zoom)"},
    {"bad_number.ini", HFS_E_FORMAT, ":4: step: '2x' is not a number"},
    {"bad_nan.ini", HFS_E_FORMAT, ":4: step: 'nan' is not a number"},
    {"bad_no_action.ini", HFS_E_FORMAT, ":2: [knob az]: no action"},
    {"bad_duplicate_control.ini", HFS_E_FORMAT, ":5: control 'az' defined twice (first at "
     "line 2)"},
    {"bad_button_knob_action.ini", HFS_E_FORMAT, ":4: action key.elevation needs a knob, "
     "'up' is a button"},
    {"bad_knob_button_action.ini", HFS_E_FORMAT, ":3: action overlay.toggle needs a button, "
     "'o' is a knob"},
    {"bad_outside_section.ini", HFS_E_FORMAT, ":2: 'action' outside a [knob NAME] or "
     "[button NAME] section"},
    {"bad_gpio_and_evdev.ini", HFS_E_FORMAT, ":4: gpio and evdev both given: a control is "
     "wired to one device (or none, for replay)"},
    {"bad_gpio_one_line.ini", HFS_E_FORMAT, ":3: gpio: 'gpiochip0:17' is not CHIP:A,B"},
    {"bad_gpio_same_line.ini", HFS_E_FORMAT, ":3: gpio: A and B are the same line (17)"},
    {"bad_gpio_shared.ini", HFS_E_FORMAT, ":6: gpio gpiochip0:18 used by both 'az' and "
     "'next'"},
    {"bad_evdev_code.ini", HFS_E_FORMAT, ":3: evdev: unknown event code 'REL_DAIL'"},
    {"bad_evdev_kind.ini", HFS_E_FORMAT, ":3: evdev: a knob needs a REL_ or ABS_ code, not "
     "KEY_UP"},
    {"bad_steps.ini", HFS_E_FORMAT, ":4: steps_per_detent: '3' is not 1, 2 or 4"},
    {"bad_min_max.ini", HFS_E_FORMAT, ":5: min/max: min 50 is not below max 40"},
    {"bad_range.ini", HFS_E_FORMAT, ":4: min/max: [-100, 90] is outside what key.elevation "
     "accepts, [-90, 90]"},
    {"bad_wrap_radiance.ini", HFS_E_FORMAT, ":4: wrap: key.radiance cannot wrap (it "
     "multiplies)"},
    {"bad_radiance_step.ini", HFS_E_FORMAT, ":4: step: 0.5: key.radiance multiplies by step "
     "per detent, which must be in (1, 10]"},
    {"bad_duplicate_key.ini", HFS_E_FORMAT, ":5: step given twice (first at line 4)"},
    {"bad_syntax.ini", HFS_E_FORMAT, ":4: syntax error (expected [knob NAME], [button NAME] "
     "or key = value)"},
    {"bad_empty_section.ini", HFS_E_FORMAT, ":2: empty section"},
    {"bad_section_type.ini", HFS_E_FORMAT, ":2: [slider az]: unknown section type 'slider' "
     "(knob, button or capture)"},
    {"bad_section_name.ini", HFS_E_FORMAT, ":2: [knob a z]: sections are [knob NAME], "
     "[button NAME] or [capture NAME]"},
    {"bad_light_index.ini", HFS_E_FORMAT, ":4: light: 9 is not a key light index in [0, 7]"},
    {"bad_light_word.ini", HFS_E_FORMAT, ":4: light: 'first' is not 'selected' or an index "
     "in [0, 15]"},
    {"bad_light_env.ini", HFS_E_FORMAT, ":4: light: this action has no light"},
    {"bad_button_step.ini", HFS_E_FORMAT, ":4: step: does not apply to this action"},
    {"bad_knob_debounce.ini", HFS_E_FORMAT, ":5: debounce_ms: applies to buttons"},
    {"bad_bool.ini", HFS_E_FORMAT, ":4: active_low: 'maybe' is not yes or no"},
    {"bad_accel.ini", HFS_E_FORMAT, ":4: accel: 0.5 is out of range [1, 100]"},
    {"bad_too_many.ini", HFS_E_FORMAT, ":98: more than 32 controls"},
    {"bad_long_line.ini", HFS_E_FORMAT, ":4: line longer than 190 characters"},
    {"bad_empty.ini", HFS_E_FORMAT, ": no [knob NAME], [button NAME] or [capture NAME] sections"},
    {"bad_capture_format.ini", HFS_E_FORMAT, ":4: format: role heights needs depth (Z16 or "
     "Y16), not YUYV"},
    {"bad_capture_roi.ini", HFS_E_FORMAT, ":5: roi: 600 0 100 100 is outside the 640x480 "
     "frame"},
    {"bad_capture_nosource.ini", HFS_E_FORMAT, ":2: [capture cam]: give device = PATH or "
     "replay = DIR (one of them)"},
    {"bad_capture_role.ini", HFS_E_FORMAT, ":5: format: role environment needs colour or grey "
     "(YUYV or GREY), not Z16"},
    {"bad_capture_mapping.ini", HFS_E_FORMAT, ":5: mapping: 'cube' is not mirrorball, fisheye "
     "or equirect"},
    {"bad_capture_fov.ini", HFS_E_FORMAT, ":5: fov: applies to mapping = fisheye"},
    {"bad_capture_exposure.ini", HFS_E_FORMAT, ":5: exposure: '-1' is not a number in [1e-06, "
     "1e+09] (radiance per unit code)"},
    {"bad_capture_sky_key.ini", HFS_E_FORMAT, ":4: mapping: applies to role = environment"},
    {"bad_capture_depth_key.ini", HFS_E_FORMAT, ":5: depth_scale: applies to role = heights"},
    {"bad_capture_env_lights.ini", HFS_E_FORMAT, ":5: env_lights: 'many' is not off, auto or "
     "0..8"},
    {"bad_capture_center.ini", HFS_E_FORMAT, ":6: center: 700 100 is outside the 640x480 "
     "frame"},
    {"bad_capture_transfer.ini", HFS_E_FORMAT, ":5: transfer: 'gamma' is not srgb or linear"},
    {"bad_capture_plane.ini", HFS_E_FORMAT, ":4: plane: '0 0' is not 'auto' or A B C (metres; "
     "C > 0)"},
    {"bad_capture_key.ini", HFS_E_FORMAT, ":4: unknown capture key 'zoom' (known: device, "
     "replay, loop, pace, format, size, rate, buffers, role, depth_scale, min_depth, max_depth, "
     "plane, roi, grid, zgain, window, gate_mm, hysteresis_mm, jump_mm, mapping, center, "
     "radius, fov, rotate, hemisphere, transfer, exposure, env_size, smoothing, env_lights)"},
    {"bad_capture_pace.ini", HFS_E_FORMAT, ":4: pace: 'fast' is not time or shown"},
    {"bad_capture_pace_device.ini", HFS_E_FORMAT, ":4: pace: applies to replay"},
    {"missing.ini", HFS_E_IO, ": cannot open input configuration: No such file or directory"},
};

/* A file with only a camera: every key read. */
static void capture_only(void)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/capture_only.ini", data_dir);
    hfs_input_config cfg;
    hfs_error err = {{0}};
    CHECK(hfs_input_config_load(path, &cfg, &err) == 0, "capture_only: %s", err.msg);
    const hfs_capture_config *c = &cfg.captures.c[0];
    const hfs_depth_params *p = &c->depth;
    CHECK(cfg.n_controls == 0 && cfg.captures.n == 1 && !strcmp(c->name, "cam") &&
              !strcmp(c->replay, "rec") && c->loop && c->pace_shown && c->width == 512 &&
              c->height == 384 &&
              c->role == HFS_ROLE_HEIGHTS && c->format == HFS_PIX_Z16 && c->config_line == 2,
          "capture_only: the section");
    CHECK(p->roi[2] == 512 && p->grid_w == 128 && p->grid_h == 96 && p->plane_set &&
              p->plane[2] == 1.05 && p->scale == 0.0001 && p->window == 4 &&
              fabs(p->gate - 0.002) < 1e-12 && fabs(p->hysteresis - 0.001) < 1e-12 &&
              fabs(p->jump - 0.008) < 1e-12 && p->zgain == 10 && p->min_depth == 0.3 &&
              p->max_depth == 2, "capture_only: the depth parameters");
}

/* Both roles at once, every sky key read. */
static void capture_both(void)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/capture_both.ini", data_dir);
    hfs_input_config cfg;
    hfs_error err = {{0}};
    CHECK(hfs_input_config_load(path, &cfg, &err) == 0, "capture_both: %s", err.msg);
    const hfs_capture_config *h = &cfg.captures.c[0], *e = &cfg.captures.c[1];
    const hfs_camenv_params *p = &e->env;
    CHECK(cfg.captures.n == 2 && h->role == HFS_ROLE_HEIGHTS && e->role == HFS_ROLE_ENVIRONMENT &&
              !strcmp(e->replay, "skyrec") && e->format == HFS_PIX_GREY, "capture_both: roles");
    CHECK(p->mapping == HFS_MAP_FISHEYE && p->has_center && p->cx == 320 && p->cy == 240 &&
              p->radius == 230 && p->fov_deg == 190 && p->rotate_deg == 90 && p->lower &&
              p->linear && p->exposure == 2.5 && p->map_w == 128 && p->map_h == 64 &&
              p->smoothing_s == 0.5 && p->env_lights == 2, "capture_both: the sky parameters");
    /* The defaults of a bare environment section: YUYV, mirror ball. */
    hfs_capture_configs cc = {0};
    char msg[200];
    CHECK(!hfs_capture_config_begin(&cc, "s", 1, msg, sizeof msg) &&
              !hfs_capture_config_key(&cc, "replay", "r", 2, msg, sizeof msg) &&
              !hfs_capture_config_key(&cc, "role", "environment", 3, msg, sizeof msg) &&
              !hfs_capture_config_end(&cc, msg, sizeof msg), "bare sky: %s", msg);
    CHECK(cc.c[0].format == HFS_PIX_YUYV && cc.c[0].env.mapping == HFS_MAP_MIRRORBALL &&
              cc.c[0].env.map_w == 256 && cc.c[0].env.map_h == 128 &&
              cc.c[0].env.exposure == 1.0 && cc.c[0].env.smoothing_s == 0.2 &&
              cc.c[0].env.env_lights == -2 && !cc.c[0].env.linear, "bare sky: the defaults");
}

static void broken(void)
{
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        char path[1024], want[2048];
        snprintf(path, sizeof path, "%s/%s", data_dir, bad[i].file);
        snprintf(want, sizeof want, "%s%s", path, bad[i].expect);
        hfs_input_config cfg;
        hfs_error err = {{0}};
        const int rc = hfs_input_config_load(path, &cfg, &err);
        CHECK(rc == bad[i].code, "%s: returned %d, expected %d (%s)", bad[i].file, rc,
              bad[i].code, err.msg);
        CHECK(!strcmp(err.msg, want), "%s:\n  got  '%s'\n  want '%s'", bad[i].file, err.msg,
              want);
        CHECK(cfg.n_controls == 0, "%s: config not cleared", bad[i].file);
    }
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: test_input_config DATA_DIR KIOSK_INI\n");
        return 2;
    }
    data_dir = argv[1];
    kiosk(argv[2]);
    defaults();
    broken();
    capture_only();
    capture_both();
    if (failures)
        fprintf(stderr, "test_input_config: %d failure(s)\n", failures);
    return failures ? 1 : 0;
}
