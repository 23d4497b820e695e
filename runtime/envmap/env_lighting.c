/*
 * env_lighting.c — an environment map's lighting state (hfshade_envmap.h):
 * its projection, or its decomposition into lights + residual, and the
 * open sky beyond order 4, put into an hfs_lighting.  The scene layer
 * (runtime/scene/scene_load.c) and every binding build it here, so that
 * `hfshade render --env-map` and a program of the library agree bit for
 * bit.
 */
#include "env_decompose.h"
#include "env_open.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sh.h"

#define ENV_TWO_PI 6.283185307179586

/* A size the map can have, and every texel finite ("NAME: texel (i, j) G
 * is NaN", as the decomposition says it). */
static int check_map(const float *rgb, int w, int h, const char *name, hfs_error *err)
{
    if (!name)
        name = "environment map";
    if (!rgb || w < 1 || h < 1)
        return hfs_fail(err, HFS_E_INVALID, "%s: no map or a size below 1x1 (%dx%d)", name, w,
                        h);
    if ((long long)w * h > HFS_ENVMAP_DECOMP_MAX_TEXELS)
        return hfs_fail(err, HFS_E_INVALID, "%s: %dx%d texels is more than the %lld a map may "
                        "have", name, w, h, (long long)HFS_ENVMAP_DECOMP_MAX_TEXELS);
    const size_t n = (size_t)w * (size_t)h * 3;
    for (size_t p = 0; p < n; ++p)
        if (!isfinite(rgb[p])) {
            const size_t t = p / 3;
            return hfs_fail(err, HFS_E_INVALID, "%s: texel (%zu, %zu) %c is %s", name,
                            t % (size_t)w, t / (size_t)w, "RGB"[p % 3],
                            isnan(rgb[p]) ? "NaN" : "infinite");
        }
    return HFS_OK;
}

int hfs_envmap_project(const float *rgb, int w, int h, const char *name,
                       double sh[3][HFS_SH_COEFFS], hfs_error *err)
{
    memset(sh, 0, 3 * sizeof sh[0]);
    const int rc = check_map(rgb, w, h, name, err);
    if (!rc)
        hfs_sh_project_equirect(rgb, w, h, sh);
    return rc;
}

static int check_opts(const hfs_env_lighting_opts *o, const char *name, hfs_error *err)
{
    if (o->lights < -1 || o->lights > HFS_MAX_KEY_LIGHTS)
        return hfs_fail(err, HFS_E_INVALID, "%s: env-lights %d is out of range (-1 auto, 0 "
                        "none, 1..%d)", name, o->lights, HFS_MAX_KEY_LIGHTS);
    if (o->n_scene_keys < 0 || o->n_scene_keys > HFS_MAX_KEY_LIGHTS)
        return hfs_fail(err, HFS_E_INVALID, "%s: %d scene key lights is out of range [0, %d]",
                        name, o->n_scene_keys, HFS_MAX_KEY_LIGHTS);
    if (!o->shade_sh && o->lights && o->nphi_env < 1)
        return hfs_fail(err, HFS_E_INVALID, "%s: nphi_env %d is below 1", name, o->nphi_env);
    return HFS_OK;
}

/* The map's lights and residual (a copy of rgb becomes the residual):
 * the decomposition's defaults, as many lights as asked and fit beside
 * the scene's, only those the slices cannot shade unless shade_sh. */
static int decompose(const float *rgb, int w, int h, const hfs_env_lighting_opts *o,
                     const char *name, hfs_env_lighting *out, hfs_error *err)
{
    hfs_env_decompose_opts d;
    hfs_env_decompose_defaults(&d);
    if (o->lights > 0)
        d.max_lights = o->lights;
    if (d.max_lights > HFS_MAX_KEY_LIGHTS - o->n_scene_keys)
        d.max_lights = HFS_MAX_KEY_LIGHTS - o->n_scene_keys;
    if (!o->shade_sh) /* the slices shade what is as wide as their wedge */
        d.max_radius = 3.14159265358979323846 / o->nphi_env;
    const size_t n = (size_t)w * (size_t)h * 3;
    float *work = malloc(n * sizeof *work);
    if (!work)
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory for its decomposition", name);
    memcpy(work, rgb, n * sizeof *work);
    hfs_env_decomp dec;
    int rc = hfs_env_decompose(work, w, h, &d, name, &dec, err);
    if (!rc) {
        out->n_keys = hfs_env_decomp_keys(&dec, out->keys, HFS_MAX_KEY_LIGHTS);
        memcpy(out->sh, dec.residual_sh, sizeof out->sh);
        rc = hfs_env_open_build(work, w, h, (const double(*)[HFS_SH_COEFFS])out->sh, out->open,
                                err); /* of the residual */
    }
    if (rc || out->n_keys == 0)
        free(work); /* no light: the residual is the map */
    else
        out->residual = work;
    return rc;
}

int hfs_env_lighting_build(const float *rgb, int w, int h, const hfs_env_lighting_opts *o,
                           const char *name, hfs_env_lighting *out, hfs_error *err)
{
    const hfs_env_lighting_opts none = {.nphi_env = 12};
    memset(out, 0, sizeof *out);
    if (!o)
        o = &none;
    if (!name)
        name = "environment map";
    int rc = check_opts(o, name, err);
    if (!rc)
        rc = check_map(rgb, w, h, name, err);
    if (!rc && !(out->open = malloc(HFS_ENV_OPEN_FLOATS * sizeof *out->open)))
        rc = hfs_fail(err, HFS_E_NOMEM, "%s: out of memory for its open sky", name);
    if (!rc && o->lights) {
        rc = decompose(rgb, w, h, o, name, out, err);
    } else if (!rc) {
        hfs_sh_project_equirect(rgb, w, h, out->sh);
        rc = hfs_env_open_build(rgb, w, h, (const double(*)[HFS_SH_COEFFS])out->sh, out->open,
                                err);
    }
    if (rc)
        hfs_env_lighting_free(out);
    return rc;
}

void hfs_env_lighting_apply(const hfs_env_lighting *e, const hfs_env_lighting_opts *o,
                            const float *map, int w, int h, hfs_lighting *l)
{
    const hfs_env_lighting_opts none = {.nphi_env = 12};
    if (!o)
        o = &none;
    l->has_env = 1;
    memcpy(l->env_sh, e->sh, sizeof l->env_sh);
    /* The map's lights after the scene's, turned with the residual (the
     * backends rotate env_sh by env_rotate about +z: phi + angle). */
    for (int i = 0; i < e->n_keys && l->n_key < HFS_MAX_KEY_LIGHTS; ++i) {
        hfs_key_light k = e->keys[i];
        k.phi = fmod(k.phi + l->env_rotate, ENV_TWO_PI);
        if (k.phi < 0.0)
            k.phi += ENV_TWO_PI;
        l->key[l->n_key++] = k;
    }
    l->env_map = o->truth_sh ? NULL : map; /* NULL: no map */
    l->env_map_width = w;
    l->env_map_height = h;
    if (e->open && !o->shade_sh) {
        l->env_open = e->open;
        l->env_shade_map = e->residual ? e->residual : map;
    }
}

void hfs_env_lighting_free(hfs_env_lighting *e)
{
    if (!e)
        return;
    free(e->residual);
    free(e->open);
    memset(e, 0, sizeof *e);
}
