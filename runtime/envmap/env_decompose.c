/*
 * env_decompose.c — hfs_env_decompose() and friends (env_decompose.h):
 * options, the extraction loop, the residual's SH and energies.
 */
#include "env_internal.h"

#include <math.h>
#include <string.h>

#include "sh.h"

void hfs_env_decompose_defaults(hfs_env_decompose_opts *o)
{
    memset(o, 0, sizeof *o);
    o->max_lights = 4;
    o->min_share = 0.02;
    o->contrast = 4.0;
    o->threads = 0;
}

static int check_opts(const hfs_env_decompose_opts *o, hfs_error *err)
{
    if (o->max_lights < 0 || o->max_lights > HFS_ENV_MAX_LIGHTS)
        return hfs_fail(err, HFS_E_INVALID, "max lights %d is out of range [0, %d]",
                        o->max_lights, HFS_ENV_MAX_LIGHTS);
    if (!(o->min_share >= 0.0 && o->min_share <= 1.0))
        return hfs_fail(err, HFS_E_INVALID, "min share %g is out of range [0, 1]", o->min_share);
    if (!(o->contrast >= 1.0 && o->contrast <= 1e6))
        return hfs_fail(err, HFS_E_INVALID, "contrast %g is out of range [1, 1e6]", o->contrast);
    if (!(o->max_radius >= 0.0 && o->max_radius <= 3.14159265358979323846))
        return hfs_fail(err, HFS_E_INVALID, "max radius %g is out of range [0, pi]",
                        o->max_radius);
    if (o->threads < 0 || o->threads > 64)
        return hfs_fail(err, HFS_E_INVALID, "threads %d is out of range [0, 64]", o->threads);
    return HFS_OK;
}

/* Prefixes err's message with name ("sky.pfm: ..."). */
static int named(int rc, const char *name, hfs_error *err)
{
    if (rc && err && name) {
        hfs_error e = *err;
        hfs_fail(err, rc, "%s: %s", name, e.msg);
    }
    return rc;
}

int envd_begin(env_ctx *c, float *rgb, int w, int h, const hfs_env_decompose_opts *o,
               const char *name, hfs_error *err)
{
    hfs_env_decompose_opts d;
    if (!o) {
        hfs_env_decompose_defaults(&d);
        o = &d;
    }
    int rc = check_opts(o, err);
    if (!rc && (!rgb || w < 1 || h < 1))
        rc = hfs_fail(err, HFS_E_INVALID, "no map or a size below 1x1 (%dx%d)", w, h);
    if (!rc && (long long)w * h > HFS_ENVMAP_DECOMP_MAX_TEXELS)
        rc = hfs_fail(err, HFS_E_INVALID, "%dx%d texels is more than the %lld a map may have",
                      w, h, (long long)HFS_ENVMAP_DECOMP_MAX_TEXELS);
    if (!rc)
        rc = envc_init(c, rgb, w, h, o, err);
    return named(rc, name ? name : "environment map", err);
}

void envd_finish(const env_ctx *c, hfs_env_decomp *out)
{
    hfs_sh_project_equirect(c->rgb, c->w, c->h, out->residual_sh);
    /* y_0 = 1 / sqrt(4 pi): the integral of a map is c_0 sqrt(4 pi). */
    for (int q = 0; q < 3; ++q) {
        out->total_energy[q] = c->total[q];
        out->residual_energy[q] = out->residual_sh[q][0] * sqrt(4.0 * 3.14159265358979323846);
    }
}

int hfs_env_decompose(float *rgb, int w, int h, const hfs_env_decompose_opts *o,
                      const char *name, hfs_env_decomp *out, hfs_error *err)
{
    env_ctx c;
    memset(out, 0, sizeof *out);
    int rc = envd_begin(&c, rgb, w, h, o, name, err);
    if (rc)
        return rc;
    while (out->n_lights < c.opts.max_lights) {
        env_seed seed;
        if (!envc_detect(&c, &seed) ||
            !envr_extract(&c, &seed, c.opts.min_share, &out->light[out->n_lights]))
            break;
        out->n_lights++;
        envc_merge_levels(&c);
    }
    envd_finish(&c, out);
    envc_free(&c);
    return HFS_OK;
}

int hfs_env_decomp_keys(const hfs_env_decomp *d, hfs_key_light *keys, int max)
{
    int n = 0;
    for (int i = 0; i < d->n_lights && n < max; ++i, ++n) {
        memset(&keys[n], 0, sizeof keys[n]);
        keys[n].phi = d->light[i].phi;
        keys[n].elev = d->light[i].elev;
        keys[n].alpha = d->light[i].alpha;
        memcpy(keys[n].radiance, d->light[i].radiance, sizeof keys[n].radiance);
        keys[n].from_env = 1;
    }
    return n;
}
