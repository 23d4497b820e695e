/*
 * test_input_map.c — input events applied to a scene (board/input_map.h):
 * every action, acceleration with exactly computed values, limits and wrap,
 * light selection (keys first, then locals), preset cycling, the overlay,
 * the map's pan and zoom, and events no control can take.  Controls: tests/data/input/map.ini.
 * Argument: that directory.
 */
#include "input_map.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"

#define MS(x) ((int64_t)((x) * 1000000.0))
#define NEAR(a, b) (fabs((a) - (b)) < 1e-9 * (1.0 + fabs(b)))

static hfs_input_config cfg;
static hfs_input_state st;
static hfs_scene scene;

static int ev(const char *control, hfs_input_kind kind, int delta, int64_t t_ns)
{
    hfs_input_event e;
    memset(&e, 0, sizeof e);
    snprintf(e.control, sizeof e.control, "%s", control);
    e.kind = kind;
    e.delta = delta;
    e.t_ns = t_ns;
    hfs_error err = {{0}};
    const int rc = hfs_input_apply(&cfg, &st, &e, &scene, &err);
    if (rc < 0)
        CHECK(err.msg[0], "error without a message");
    return rc;
}

static int turn(const char *control, int delta, double t_ms)
{
    return ev(control, HFS_INPUT_TURN, delta, MS(t_ms));
}

static int press(const char *control) { return ev(control, HFS_INPUT_PRESS, 0, 0); }

static void reset_scene(void)
{
    hfs_scene_init(&scene);
    scene.n_key = 2;
    scene.key[0].phi = 10;
    scene.key[0].elev = 45;
    scene.key[0].alpha = 1;
    scene.key[0].le = 1;
    scene.key[1].phi = 200;
    scene.key[1].elev = 30;
    scene.key[1].alpha = 2;
    scene.key[1].le = 3;
    scene.n_local = 1;
    scene.local[0].x = 1;
    scene.local[0].y = 2;
    scene.local[0].z = 3;
    scene.local[0].r = 1;
    scene.local[0].le = 10;
    hfs_input_state_init(&st, &scene);
}

static void acceleration(void)
{
    reset_scene();
    /* az: step 2, accel 5, accel_ms 40: gain = 1 + 4 * (1 - spacing / 40). */
    CHECK(turn("az", 1, 0) == 1 && scene.key[0].phi == 12, "first turn: gain 1");
    CHECK(turn("az", 1, 1000) == 1 && scene.key[0].phi == 14, "slow turn: gain 1");
    CHECK(turn("az", 1, 1010) == 1 && scene.key[0].phi == 22, "10 ms: gain 4 -> +8, got %g",
          scene.key[0].phi);
    CHECK(turn("az", 2, 1030) == 1 && scene.key[0].phi == 38,
          "2 detents in 20 ms: spacing 10, gain 4 -> +16, got %g", scene.key[0].phi);
    CHECK(turn("az", -1, 1035) == 1 && scene.key[0].phi == 36, "reversal: gain 1, got %g",
          scene.key[0].phi);
    CHECK(turn("az", -1, 1055) == 1 && scene.key[0].phi == 30, "20 ms: gain 3 -> -6, got %g",
          scene.key[0].phi);
    CHECK(turn("az", -1, 1095) == 1 && scene.key[0].phi == 28, "40 ms: gain 1, got %g",
          scene.key[0].phi);
    CHECK(turn("az", -1, 1095) == 1 && scene.key[0].phi == 18, "0 ms: gain 5 -> -10, got %g",
          scene.key[0].phi);

    const hfs_control_config *az = hfs_input_config_find(&cfg, "az");
    CHECK(NEAR(hfs_input_gain(az, MS(30), 1), 2.0), "gain at 30 ms");
    CHECK(NEAR(hfs_input_gain(az, MS(30), 3), 4.0), "gain, 3 detents in 30 ms");
    CHECK(hfs_input_gain(az, MS(100), 1) == 1.0, "gain when slow");
    /* Acceleration is per knob: another knob's turns do not speed it up. */
    CHECK(turn("env", 1, 2000) == 1 && scene.env_rotate_deg == 5, "env first");
    CHECK(turn("az", 1, 5000) == 1 && scene.key[0].phi == 20, "az after a pause");
    CHECK(turn("env", 1, 5001) == 1 && scene.env_rotate_deg == 10, "env: accel 1 by default");
}

static void limits(void)
{
    reset_scene();
    /* Wrap: azimuth 0..360. */
    scene.key[0].phi = 358;
    CHECK(turn("az", 1, 0) == 1 && scene.key[0].phi == 0, "358 + 2 wraps to 0, got %g",
          scene.key[0].phi);
    CHECK(turn("az", -1, 1000) == 1 && scene.key[0].phi == 358, "0 - 2 wraps to 358");
    CHECK(turn("az", 20, 2000) == 1 && scene.key[0].phi == 38, "358 + 40 -> 38, got %g",
          scene.key[0].phi);
    scene.key[0].phi = -725; /* the scene allows it; a turn brings it into range */
    CHECK(turn("az", 1, 3000) == 1 && scene.key[0].phi == 357, "-723 wraps to 357, got %g",
          scene.key[0].phi);
    CHECK(turn("env", -1, 0) == 1 && scene.env_rotate_deg == 355, "env 0 - 5 wraps to 355");
    /* Clamp: elevation 0..90, light = selected (key 0). */
    scene.key[0].elev = 89;
    CHECK(turn("el", 1, 0) == 1 && scene.key[0].elev == 90, "elevation to 90");
    CHECK(turn("el", 1, 1000) == 0 && scene.key[0].elev == 90, "clamped at 90: no change");
    CHECK(turn("el", -100, 2000) == 1 && scene.key[0].elev == 0, "clamped at 0");
    CHECK(turn("el", -1, 3000) == 0, "clamped at 0: no change");
    /* key1: azimuth with wrap = no clamps at 360. */
    scene.key[1].phi = 359;
    CHECK(turn("key1", 1, 0) == 1 && scene.key[1].phi == 360, "key1 clamps at 360");
    CHECK(turn("key1", 1, 1000) == 0 && scene.key[1].phi == 360, "key1 at the limit");
    CHECK(scene.key[0].phi == 357, "light 1's knob leaves light 0 alone");
}

static void every_action(void)
{
    reset_scene();
    CHECK(turn("alpha", 1, 0) == 1 && scene.key[0].alpha == 1.5, "key.radius +0.5");
    CHECK(turn("alpha", -10, 1000) == 1 && scene.key[0].alpha == 0.5, "key.radius min 0.5");
    /* Radiance multiplies: step 2, limits 0.5..8. */
    CHECK(turn("rad", 1, 0) == 1 && scene.key[0].le == 2, "radiance x2");
    CHECK(turn("rad", 2, 1000) == 1 && scene.key[0].le == 8, "radiance x4");
    CHECK(turn("rad", 1, 2000) == 0 && scene.key[0].le == 8, "radiance clamped at 8");
    CHECK(turn("rad", -3, 3000) == 1 && scene.key[0].le == 1, "radiance /8");
    CHECK(turn("rad", -2, 4000) == 1 && scene.key[0].le == 0.5, "radiance clamped at 0.5");
    CHECK(turn("lle", 1, 0) == 1 && NEAR(scene.local[0].le, 11.0), "local radiance x1.1: %g",
          scene.local[0].le);
    CHECK(turn("lle", -1, 1000) == 1 && NEAR(scene.local[0].le, 10.0), "local radiance back");
    CHECK(turn("ly", 3, 0) == 1 && scene.local[0].y == 5, "local.y +3");
    CHECK(turn("lz", -5, 0) == 1 && scene.local[0].z == 0, "local.z clamped at 0");
    CHECK(turn("lr", 1, 0) == 1 && scene.local[0].r == 1.5, "local.radius +0.5");
    CHECK(turn("lr", -100, 1000) == 1 && NEAR(scene.local[0].r, 0.1), "local.radius min 0.1");
    /* local.x follows the selection: a local light must be selected. */
    CHECK(turn("lx", 1, 0) == 0 && scene.local[0].x == 1, "local.x with a key light selected");
}

static void selection(void)
{
    reset_scene(); /* 2 key lights (0, 1), 1 local (2) */
    CHECK(st.selected == 0, "light 0 selected at start");
    CHECK(press("next") == 1 && st.selected == 1, "next: 1");
    CHECK(turn("el", 1, 0) == 1 && scene.key[1].elev == 31 && scene.key[0].elev == 45,
          "elevation acts on the selected key light");
    CHECK(press("next") == 1 && st.selected == 2, "next: 2 (the local light)");
    CHECK(turn("el", 1, 1000) == 0 && scene.key[1].elev == 31,
          "key action while a local light is selected: nothing");
    CHECK(turn("lx", 3, 0) == 1 && scene.local[0].x == 2.5, "local.x on the selected local");
    CHECK(turn("lx", 100, 1000) == 1 && scene.local[0].x == 10, "local.x clamped at 10");
    CHECK(press("next") == 1 && st.selected == 0, "next wraps to 0");
    CHECK(ev("next", HFS_INPUT_RELEASE, 0, 0) == 0 && st.selected == 0, "release: nothing");
    CHECK(turn("sel", -1, 0) == 1 && st.selected == 2, "knob -1 wraps to the last light");
    CHECK(turn("sel", 4, 1) == 1 && st.selected == 0, "knob +4 of 3 lights: 0, got %d",
          st.selected);
    CHECK(turn("sel", 3, 2) == 0 && st.selected == 0, "a full round: no change");
    scene.n_key = 0;
    scene.n_local = 0;
    CHECK(press("next") == 0, "no lights: nothing to select");
    /* Fixed light indices the scene lacks. */
    reset_scene();
    scene.n_local = 0;
    CHECK(turn("ly", 1, 0) == 0, "local light 0 missing: nothing");
    hfs_error err = {{0}};
    CHECK(hfs_input_check_scene(&cfg, &scene, &err) == HFS_E_INVALID &&
              strstr(err.msg, "the scene has 0 local lights"),
          "check_scene: '%s'", err.msg);
    reset_scene();
    CHECK(hfs_input_check_scene(&cfg, &scene, &err) == 0, "check_scene ok: '%s'", err.msg);
}

static void presets_and_overlay(void)
{
    reset_scene();
    CHECK(st.preset == 0, "no preset in the scene: kiosk");
    CHECK(press("preset") == 1 && !strcmp(scene.preset, "panel"), "kiosk -> panel");
    CHECK(press("preset") == 1 && !strcmp(scene.preset, "headless"), "panel -> headless");
    CHECK(press("preset") == 1 && !strcmp(scene.preset, "kiosk"), "headless -> kiosk");
    CHECK(turn("presets", -1, 0) == 1 && !strcmp(scene.preset, "headless"), "knob back");
    CHECK(turn("presets", 2, 1000) == 1 && !strcmp(scene.preset, "panel"), "knob +2");
    hfs_scene_init(&scene);
    snprintf(scene.preset, sizeof scene.preset, "panel");
    hfs_input_state_init(&st, &scene);
    CHECK(st.preset == 1, "state starts at the scene's preset");
    CHECK(press("preset") == 1 && !strcmp(scene.preset, "headless"), "panel -> headless");
    CHECK(hfs_input_preset_name(3) == NULL, "preset name out of range");

    CHECK(press("overlay") == 1 && st.overlay == 1, "overlay on");
    CHECK(ev("overlay", HFS_INPUT_RELEASE, 0, 0) == 0 && st.overlay == 1, "release: nothing");
    CHECK(press("overlay") == 1 && st.overlay == 0, "overlay off");
}

static void bad_events(void)
{
    reset_scene();
    hfs_input_event e;
    memset(&e, 0, sizeof e);
    hfs_error err = {{0}};
    snprintf(e.control, sizeof e.control, "nope");
    e.kind = HFS_INPUT_TURN;
    e.delta = 1;
    CHECK(hfs_input_apply(&cfg, &st, &e, &scene, &err) == HFS_E_INVALID &&
              !strcmp(err.msg, "input: unknown control 'nope'"),
          "unknown control: '%s'", err.msg);
    snprintf(e.control, sizeof e.control, "az");
    e.kind = HFS_INPUT_PRESS;
    CHECK(hfs_input_apply(&cfg, &st, &e, &scene, &err) == HFS_E_INVALID &&
              strstr(err.msg, "'az' is a knob"),
          "press on a knob: '%s'", err.msg);
    snprintf(e.control, sizeof e.control, "next");
    e.kind = HFS_INPUT_TURN;
    CHECK(hfs_input_apply(&cfg, &st, &e, &scene, &err) == HFS_E_INVALID &&
              strstr(err.msg, "'next' is a button"),
          "turn on a button: '%s'", err.msg);
    memset(e.control, 'x', sizeof e.control); /* no terminating NUL */
    CHECK(hfs_input_apply(&cfg, &st, &e, &scene, &err) == HFS_E_INVALID,
          "unterminated name: '%s'", err.msg);
    CHECK(turn("az", 0, 0) == 0, "a zero turn changes nothing");
}

/* surface.*: a value the scene did not name starts from the lighting's
 * default and is given from then on; albedo + specular never passes 1
 * (the renderer would refuse the scene); gloss multiplies. */
static void surface(void)
{
    reset_scene();
    CHECK(turn("alb", -2, 0) == 1 && scene.albedo_given && NEAR(scene.albedo, 0.9),
          "albedo from the default 1 - 2 x 0.05: %g", scene.albedo);
    CHECK(turn("spec", 3, 1000) == 1 && scene.specular_given && NEAR(scene.specular, 0.1),
          "specular 0.15 stops at 1 - albedo = 0.1: %g", scene.specular);
    CHECK(turn("spec", 1, 2000) == 0, "specular at 1 - albedo: no change");
    CHECK(turn("alb", 1, 3000) == 0 && NEAR(scene.albedo, 0.9), "albedo at 1 - specular");
    CHECK(turn("alb", -4, 4000) == 1 && NEAR(scene.albedo, 0.7), "albedo down: %g",
          scene.albedo);
    CHECK(turn("gl", 2, 5000) == 1 && scene.gloss_given && NEAR(scene.gloss, 32 * 1.5625),
          "gloss 32 x 1.25^2: %g", scene.gloss);
}

/* The map's centre moves step display pixels a detent, 2^level texels
 * each, accelerated like any knob, kept on the field; zoom clamps (a knob)
 * or wraps to the whole field (a button); without a map nothing moves. */
static void map_actions(void)
{
    reset_scene();
    CHECK(turn("panx", 1, 0) == 0 && turn("zoom", 1, 0) == 0 && press("zoomin") == 0,
          "no map: the map's actions change nothing");
    st.map_levels = 4, st.map_w = 1000, st.map_h = 600;
    st.map_level = 3, st.map_x = 300, st.map_y = 300;
    CHECK(turn("panx", 1, 1000) == 1 && st.map_x == 300 + 64 * 8, "pan: 64 px x 2^3: %g",
          st.map_x);
    CHECK(turn("panx", 1, 2000) == 1 && st.map_x == 1000, "pan: kept on the field: %g",
          st.map_x);
    CHECK(turn("panx", 1, 3000) == 0, "pan past the edge: no change");
    st.map_level = 1;
    CHECK(turn("panx", -1, 4000) == 1 && st.map_x == 1000 - 64 * 2, "pan back at level 1: %g",
          st.map_x);
    CHECK(turn("panx", -1, 4050) == 1 && NEAR(st.map_x, 872 - 64 * 2 * 2.0),
          "pan: accelerated 2x at 50 ms: %g", st.map_x);
    st.map_level = 3;
    CHECK(turn("pany", -2, 0) == 1 && st.map_y == 300 - 2 * 10 * 8, "pan y: step 10: %g",
          st.map_y);
    CHECK(turn("zoom", 1, 0) == 1 && st.map_level == 2, "zoom in a level");
    CHECK(turn("pany", 1, 1000) == 1 && st.map_y == 140 + 10 * 4, "pan y at level 2: %g",
          st.map_y);
    CHECK(turn("zoom", 5, 1000) == 1 && st.map_level == 0, "zoom in: clamped at 0");
    CHECK(turn("zoom", 1, 2000) == 0, "zoom in at 0: no change");
    CHECK(turn("zoom", -1000000, 3000) == 1 && st.map_level == 3, "zoom out: clamped at 3");
    CHECK(press("zoomin") == 1 && st.map_level == 2, "button: a level in");
    st.map_level = 0;
    CHECK(press("zoomin") == 1 && st.map_level == 3, "button at 0: the whole field");
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: test_input_map DATA_DIR\n");
        return 2;
    }
    char path[4096];
    snprintf(path, sizeof path, "%s/map.ini", argv[1]);
    hfs_error err = {{0}};
    if (hfs_input_config_load(path, &cfg, &err)) {
        fprintf(stderr, "test_input_map: %s\n", err.msg);
        return 1;
    }
    acceleration();
    limits();
    every_action();
    selection();
    presets_and_overlay();
    surface();
    map_actions();
    bad_events();
    if (failures)
        fprintf(stderr, "test_input_map: %d failure(s)\n", failures);
    return failures ? 1 : 0;
}
