/*
 * kiosk_world.c — the scene, the input configuration and the knob state,
 * loaded and checked as one unit.
 *
 * Why one unit: a SIGHUP reloads both files, and either may be broken.  A
 * new world is built beside the old one and swapped in only when every part
 * loaded and the configuration fits the scene, so a bad edit on the board
 * never leaves the kiosk half-reloaded.
 *
 * The expensive inputs (heights, the environment map's SH) are loaded here
 * once per world; knob edits only recompute the lighting
 * (kiosk_world_relight).
 */
#include "kiosk.h"

#include <stdlib.h>
#include <string.h>

kiosk_world *kiosk_world_load(const char *scene_path, const char *input_path, hfs_error *err)
{
    kiosk_world *w = calloc(1, sizeof *w);
    if (!w) {
        hfs_fail(err, HFS_E_NOMEM, "out of memory");
        return NULL;
    }
    hfs_scene_init(&w->scene);
    if (hfs_scene_load_file(&w->scene, scene_path, err))
        goto fail;
    if (input_path && hfs_input_config_load(input_path, &w->cfg, err))
        goto fail;
    if (input_path && hfs_input_check_scene(&w->cfg, &w->scene, err)) {
        /* The check does not know the file names: add them. */
        hfs_error e = *err;
        hfs_fail(err, HFS_E_INVALID, "%s: %s (scene %s)", input_path, e.msg, scene_path);
        goto fail;
    }
    if (hfs_scene_inputs_load(&w->scene, &w->in, err)) {
        /* Cross-key problems say "scene: ..."; name the file instead. */
        if (!strncmp(err->msg, "scene:", 6)) {
            hfs_error e = *err;
            hfs_fail(err, HFS_E_INVALID, "%s:%s", scene_path, e.msg + 6);
        }
        goto fail;
    }
    hfs_input_state_init(&w->st, &w->scene);
    return w;
fail:
    kiosk_world_free(w);
    return NULL;
}

void kiosk_world_free(kiosk_world *w)
{
    if (!w)
        return;
    hfs_scene_inputs_free(&w->in);
    free(w);
}

int kiosk_world_relight(kiosk_world *w, hfs_error *err)
{
    return hfs_scene_inputs_relight(&w->scene, &w->in, err);
}
