/*
 * scene_load.c — scene to renderer inputs (scene_load.h).
 *
 * The environment map's SH projection is kept in the inputs so that a
 * relight never reads the map again: projecting a 2k x 1k map costs tens of
 * milliseconds, far more than a knob's frame budget.  The map is kept as
 * well, for the ground truth (lighting.env_map).
 */
#include "scene_load.h"

#include <math.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include "env_decompose.h"
#include "env_open.h"
#include "hfshade_envmap.h"
#include "sh.h"

/* Serials of loaded heights (hfs_renderer_set_field_serial): unique in the
 * process, so that heights loaded where freed ones lay never pass for them.
 * A counter only: nothing else is shared between loads. */
static atomic_ulong last_serial;

void hfs_scene_inputs_free(hfs_scene_inputs *in)
{
    if (!in)
        return;
    hfs_heightmap_free(&in->hm);
    free(in->albedo_map);
    free(in->env_map);
    free(in->env_residual);
    memset(in, 0, sizeof *in);
}

/* The build options of the scene's env-map (env-lights, env-shade,
 * truth-env, nphi_env). */
static hfs_env_lighting_opts env_opts(const hfs_scene *s)
{
    hfs_quality q;
    hfs_scene_quality(s, &q);
    const hfs_env_lighting_opts o = {.lights = s->env_lights, .n_scene_keys = s->n_key,
                                     .shade_sh = s->env_shade_sh, .truth_sh = s->truth_env_sh,
                                     .nphi_env = q.nphi_env};
    return o;
}

/* A view of the state kept in in (the kiosk's camera sky may have
 * replaced it: no open sky then). */
static hfs_env_lighting env_state(const hfs_scene_inputs *in)
{
    hfs_env_lighting e;
    memset(&e, 0, sizeof e);
    memcpy(e.sh, in->env_map_sh, sizeof e.sh);
    e.n_keys = in->n_env_keys;
    memcpy(e.keys, in->env_keys, sizeof e.keys);
    e.residual = in->env_residual;
    e.open = in->has_env_open ? (float *)in->env_open : NULL;
    return e;
}

/* The map's SH, or with env-lights its lights + the residual's SH, and
 * the open sky beyond order 4 (env_open.h) of the map or residual:
 * hfs_env_lighting_build (hfshade_envmap.h), kept in in.  The
 * decomposition works on a copy: env stays the map as loaded (the truth
 * integrates the whole map), the copy becomes the residual the other
 * backends shade from (env-shade = map). */
static int env_map_light(const hfs_scene *s, const hfs_envmap *env, hfs_scene_inputs *in,
                         hfs_error *err)
{
    const hfs_env_lighting_opts o = env_opts(s);
    hfs_env_lighting e;
    const int rc = hfs_env_lighting_build(env->rgb, env->width, env->height, &o, s->env_map, &e,
                                          err);
    if (rc)
        return rc;
    memcpy(in->env_map_sh, e.sh, sizeof in->env_map_sh);
    in->n_env_keys = e.n_keys;
    memcpy(in->env_keys, e.keys, sizeof in->env_keys);
    memcpy(in->env_open, e.open, sizeof in->env_open);
    in->has_env_open = 1;
    in->env_residual = e.residual; /* taken over */
    e.residual = NULL;
    hfs_env_lighting_free(&e);
    return HFS_OK;
}

int hfs_scene_inputs_relight(const hfs_scene *s, hfs_scene_inputs *in, hfs_error *err)
{
    hfs_lighting l;
    hfs_quality q;
    hfs_scene_lighting(s, NULL, &l);
    hfs_scene_quality(s, &q);
    l.albedo_map = in->albedo_map; /* checked by its loader */
    /* The map's lights after the scene's (turned with the residual), its
     * SH, the map and its open sky: hfs_env_lighting_apply, as every
     * program of the library does it (hfshade_envmap.h). */
    if (in->has_env_map) {
        const hfs_env_lighting_opts o = env_opts(s);
        hfs_env_lighting e = env_state(in);
        hfs_env_lighting_apply(&e, &o, in->env_map, in->env_map_width, in->env_map_height, &l);
    }
    /* The field does not change here: hfs_scene_inputs_load checked it.
     * The maps after the check: their loader found every pixel finite,
     * and a relight (a knob's frame) must not scan millions of them
     * again. */
    hfs_lighting v = l;
    v.env_map = v.env_shade_map = NULL;
    v.env_open = NULL;
    int rc = hfs_validate_lighting(&v, err);
    if (!rc)
        rc = hfs_validate_quality(&q, err);
    if (rc)
        return rc;
    in->lighting = l;
    in->quality = q;
    return HFS_OK;
}

int hfs_scene_inputs_load(const hfs_scene *s, hfs_scene_inputs *in, hfs_error *err)
{
    memset(in, 0, sizeof *in);
    int rc = hfs_scene_validate(s, err);
    if (rc)
        return rc;

    hfs_height_load_opts opts = {0};
    opts.has_nodata = s->has_nodata;
    opts.nodata = (float)s->nodata;
    opts.raw_width = s->raw_width;
    opts.raw_height = s->raw_height;
    if ((rc = hfs_height_load(s->height, &opts, &in->hm, err)))
        goto fail;
    in->field.width = in->hm.width;
    in->field.height = in->hm.height;
    in->field.z = in->hm.z;
    in->field.dx = s->dx_given ? s->dx : (in->hm.cellsize > 0.0 ? in->hm.cellsize : 1.0);
    in->field.zscale = s->zscale_given ? s->zscale : 1.0;

    if (s->env_map[0]) {
        hfs_envmap env;
        if ((rc = hfs_envmap_load(s->env_map, &env, err)))
            goto fail;
        if ((rc = env_map_light(s, &env, in, err))) {
            hfs_envmap_free(&env);
            goto fail;
        }
        in->env_map = env.rgb; /* kept: the truth integrates the map itself */
        in->env_map_width = env.width;
        in->env_map_height = env.height;
        in->has_env_map = 1;
    }
    if (s->albedo_map[0] &&
        (rc = hfs_albedo_load(s->albedo_map, in->field.width, in->field.height, &in->albedo_map,
                              err)))
        goto fail;
    if ((rc = hfs_validate_field(&in->field, err)) || (rc = hfs_scene_inputs_relight(s, in, err)))
        goto fail;
    in->serial = (uint64_t)atomic_fetch_add(&last_serial, 1) + 1;
    return HFS_OK;
fail:
    hfs_scene_inputs_free(in);
    return rc;
}
