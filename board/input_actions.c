/*
 * input_actions.c — what each input action does, its defaults and the
 * values it accepts (input_config.h hfs_action_info; docs/INPUT.md
 * "Actions" is this table in prose).
 */
#include "input_config.h"

#include <stdio.h>
#include <string.h>

static const hfs_action_info actions[] = {
    /* action, name, knob, button, target, continuous, multiplicative,
     * step, min, max, wrap (defaults), the scene key and number it edits
     * (its range: what min/max may reach) */
    {HFS_ACTION_KEY_AZIMUTH, "key.azimuth", 1, 0, HFS_TARGET_KEY, 1, 0,
     2.0, 0.0, 360.0, 1, HFS_SK_KEY, 0},
    {HFS_ACTION_KEY_ELEVATION, "key.elevation", 1, 0, HFS_TARGET_KEY, 1, 0,
     1.0, 0.0, 90.0, 0, HFS_SK_KEY, 1},
    {HFS_ACTION_KEY_RADIUS, "key.radius", 1, 0, HFS_TARGET_KEY, 1, 0,
     0.5, 0.5, 30.0, 0, HFS_SK_KEY, 2},
    {HFS_ACTION_KEY_RADIANCE, "key.radiance", 1, 0, HFS_TARGET_KEY, 1, 1,
     1.1, 0.01, 1e6, 0, HFS_SK_KEY, 3},
    {HFS_ACTION_LOCAL_X, "local.x", 1, 0, HFS_TARGET_LOCAL, 1, 0,
     1.0, -1e9, 1e9, 0, HFS_SK_LOCAL, 0},
    {HFS_ACTION_LOCAL_Y, "local.y", 1, 0, HFS_TARGET_LOCAL, 1, 0,
     1.0, -1e9, 1e9, 0, HFS_SK_LOCAL, 1},
    {HFS_ACTION_LOCAL_Z, "local.z", 1, 0, HFS_TARGET_LOCAL, 1, 0,
     1.0, -1e9, 1e9, 0, HFS_SK_LOCAL, 2},
    {HFS_ACTION_LOCAL_RADIUS, "local.radius", 1, 0, HFS_TARGET_LOCAL, 1, 0,
     0.5, 0.1, 1e9, 0, HFS_SK_LOCAL, 3},
    {HFS_ACTION_LOCAL_RADIANCE, "local.radiance", 1, 0, HFS_TARGET_LOCAL, 1, 1,
     1.1, 0.01, 1e9, 0, HFS_SK_LOCAL, 4},
    {HFS_ACTION_ENV_ROTATE, "env.rotate", 1, 0, HFS_TARGET_NONE, 1, 0,
     5.0, 0.0, 360.0, 1, HFS_SK_ENV_ROTATE, 0},
    {HFS_ACTION_LIGHT_SELECT, "light.select", 1, 1, HFS_TARGET_NONE, 0, 0,
     1.0, 0.0, 0.0, 1, HFS_SK_COUNT, 0},
    {HFS_ACTION_PRESET, "preset.next", 1, 1, HFS_TARGET_NONE, 0, 0,
     1.0, 0.0, 0.0, 1, HFS_SK_COUNT, 0},
    {HFS_ACTION_OVERLAY, "overlay.toggle", 0, 1, HFS_TARGET_NONE, 0, 0,
     1.0, 0.0, 0.0, 0, HFS_SK_COUNT, 0},
    {HFS_ACTION_CAMERA_AZIMUTH, "camera.azimuth", 1, 0, HFS_TARGET_NONE, 1, 0,
     5.0, 0.0, 360.0, 1, HFS_SK_COUNT, 0},
    {HFS_ACTION_CAMERA_ELEVATION, "camera.elevation", 1, 0, HFS_TARGET_NONE, 1, 0,
     2.0, 5.0, 90.0, 0, HFS_SK_COUNT, 0},
    {HFS_ACTION_CAMERA_ZOOM, "camera.zoom", 1, 0, HFS_TARGET_NONE, 1, 1,
     1.1, 0.1, 10.0, 0, HFS_SK_COUNT, 0},
    {HFS_ACTION_VIEW, "view.toggle", 0, 1, HFS_TARGET_NONE, 0, 0,
     1.0, 0.0, 0.0, 0, HFS_SK_COUNT, 0},
    {HFS_ACTION_SURFACE_ALBEDO, "surface.albedo", 1, 0, HFS_TARGET_NONE, 1, 0,
     0.05, 0.0, 1.0, 0, HFS_SK_ALBEDO, 0},
    {HFS_ACTION_SURFACE_SPECULAR, "surface.specular", 1, 0, HFS_TARGET_NONE, 1, 0,
     0.05, 0.0, 1.0, 0, HFS_SK_SPECULAR, 0},
    {HFS_ACTION_SURFACE_GLOSS, "surface.gloss", 1, 0, HFS_TARGET_NONE, 1, 1,
     1.25, 1.0, 10000.0, 0, HFS_SK_GLOSS, 0},
    /* the map's centre: step in display pixels (texels of the level
     * shown); the kiosk keeps it on the DEM, whatever min and max say */
    {HFS_ACTION_MAP_PAN_X, "map.pan_x", 1, 0, HFS_TARGET_NONE, 1, 0,
     64.0, -1e9, 1e9, 0, HFS_SK_COUNT, 0},
    {HFS_ACTION_MAP_PAN_Y, "map.pan_y", 1, 0, HFS_TARGET_NONE, 1, 0,
     64.0, -1e9, 1e9, 0, HFS_SK_COUNT, 0},
    {HFS_ACTION_MAP_ZOOM, "map.zoom", 1, 1, HFS_TARGET_NONE, 0, 0,
     1.0, 0.0, 0.0, 0, HFS_SK_COUNT, 0},
};
#define N_ACTIONS ((int)(sizeof actions / sizeof actions[0]))

const hfs_action_info *hfs_action_get(hfs_action action)
{
    for (int i = 0; i < N_ACTIONS; ++i)
        if (actions[i].action == action)
            return &actions[i];
    return NULL;
}

hfs_key_range hfs_action_range(const hfs_action_info *a)
{
    if (a->continuous && a->key == HFS_SK_COUNT) /* the kiosk's own state: its defaults */
        return (hfs_key_range){a->min, a->max, 0};
    const hfs_key_number *n = hfs_scene_key_number(a->key, a->number);
    if (!n)
        return (hfs_key_range){0.0, 0.0, 1}; /* holds nothing */
    hfs_key_range r = n->range;
    if (a->multiplicative && r.lo == 0.0)
        r.lo_open = 1;
    return r;
}

hfs_action hfs_action_from_name(const char *name)
{
    for (int i = 0; i < N_ACTIONS; ++i)
        if (!strcmp(actions[i].name, name))
            return actions[i].action;
    return HFS_ACTION_NONE;
}

void hfs_action_names(char *buf, size_t size)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < N_ACTIONS && used < size; ++i)
        used += (size_t)snprintf(buf + used, size - used, "%s%s", i ? ", " : "",
                                 actions[i].name);
}

