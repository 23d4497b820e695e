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

int hfs_scene_inputs_relight(const hfs_scene *s, hfs_scene_inputs *in, hfs_error *err)
{
    hfs_lighting l;
    hfs_quality q;
    hfs_scene_lighting(s, in->has_env_map ? (const double(*)[HFS_SH_COEFFS])in->env_map_sh : NULL,
                       &l);
    hfs_scene_quality(s, &q);
    /* The map's lights after the scene's, turned with the residual (the
     * backends rotate env_sh by env_rotate about +z: phi + angle). */
    for (int i = 0; i < in->n_env_keys && l.n_key < HFS_MAX_KEY_LIGHTS; ++i) {
        hfs_key_light k = in->env_keys[i];
        k.phi = fmod(k.phi + l.env_rotate, 6.283185307179586);
        if (k.phi < 0.0)
            k.phi += 6.283185307179586;
        l.key[l.n_key++] = k;
    }
    l.albedo_map = in->albedo_map; /* checked by its loader */
    /* The field does not change here: hfs_scene_inputs_load checked it. */
    int rc = hfs_validate_lighting(&l, err);
    if (!rc)
        rc = hfs_validate_quality(&q, err);
    if (rc)
        return rc;
    /* The map after the check: its loader found every pixel finite, and a
     * relight (a knob's frame) must not scan millions of them again. */
    l.env_map = s->truth_env_sh ? NULL : in->env_map; /* NULL: no map */
    l.env_map_width = in->env_map_width;
    l.env_map_height = in->env_map_height;
    if (in->has_env_open && !s->env_shade_sh) {
        l.env_open = in->env_open;
        l.env_shade_map = in->env_residual ? in->env_residual : in->env_map;
    }
    in->lighting = l;
    in->quality = q;
    return HFS_OK;
}

/* The open sky beyond order 4 (env_open.h) of rgb (the map or its
 * residual), whose projection in->env_map_sh already holds. */
static int env_open_table(const float *rgb, const hfs_envmap *env, hfs_scene_inputs *in,
                          hfs_error *err)
{
    int rc = hfs_env_open_build(rgb, env->width, env->height,
                                (const double(*)[HFS_SH_COEFFS])in->env_map_sh, in->env_open, err);
    in->has_env_open = !rc;
    return rc;
}

/* The map's SH, or with env-lights its lights + the residual's SH.  The
 * lights fit beside the scene's own key lights (HFS_MAX_KEY_LIGHTS in all);
 * auto takes the decomposition's defaults (up to 4, 2% of the energy).
 * The decomposition works on a copy: env stays the map as loaded (the
 * truth integrates the whole map), the copy becomes the residual the other
 * backends shade from (env-shade = map). */
static int env_map_light(const hfs_scene *s, const hfs_envmap *env, hfs_scene_inputs *in,
                         hfs_error *err)
{
    if (!s->env_lights) {
        hfs_sh_project_equirect(env->rgb, env->width, env->height, in->env_map_sh);
        return env_open_table(env->rgb, env, in, err);
    }
    hfs_env_decompose_opts o;
    hfs_env_decompose_defaults(&o);
    if (s->env_lights > 0)
        o.max_lights = s->env_lights;
    if (o.max_lights > HFS_MAX_KEY_LIGHTS - s->n_key)
        o.max_lights = HFS_MAX_KEY_LIGHTS - s->n_key;
    if (!s->env_shade_sh) { /* the slices shade what is as wide as their wedge */
        hfs_quality q;
        hfs_scene_quality(s, &q);
        o.max_radius = 3.14159265358979323846 / q.nphi_env;
    }
    const size_t n = (size_t)env->width * (size_t)env->height * 3;
    float *work = malloc(n * sizeof *work);
    if (!work)
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory for its decomposition",
                        s->env_map);
    memcpy(work, env->rgb, n * sizeof *work);
    hfs_env_decomp d;
    int rc = hfs_env_decompose(work, env->width, env->height, &o, s->env_map, &d, err);
    if (!rc) {
        in->n_env_keys = hfs_env_decomp_keys(&d, in->env_keys, HFS_MAX_KEY_LIGHTS);
        memcpy(in->env_map_sh, d.residual_sh, sizeof in->env_map_sh);
        rc = env_open_table(work, env, in, err); /* of the residual */
    }
    if (rc || in->n_env_keys == 0)
        free(work); /* no light: the residual is the map */
    else
        in->env_residual = work;
    return rc;
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
