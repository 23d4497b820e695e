/*
 * validate.c — the checks of every renderer input (hfs_validate_*,
 * hfshade.h; renderer.c runs them before each frame).  Every range is the
 * table of scene keys' (scene_keys.h).
 */
#include "albedo.h"
#include "env_open.h"
#include "scene_keys.h"
#include "validate.h"

#include <float.h>
#include <math.h>
#include <stdio.h>

/* ---- validation -------------------------------------------------------------------
 * Every range is the table of scene keys' (scene_keys.h), in library units:
 * a value the scene parser accepts passes here, one just outside fails both.
 * Fields without a scene key (counts of lights, enumerations, the truth's
 * elevation order) are checked here alone. */

#define CHECK_LIB(id, i, x, who) hfs_scene_key_check_lib((id), (i), (x), (who), err)

static int check_radiance(hfs_scene_key_id id, int i, const float v[3], const char *who,
                          hfs_error *err)
{
    int rc = HFS_OK;
    for (int c = 0; c < 3 && !rc; ++c)
        rc = CHECK_LIB(id, i, (double)v[c], who);
    return rc;
}

/* Everything about the field but its heights: O(1). */
static int check_field_params(const hfs_field *f, hfs_error *err)
{
    if (!f || !f->z)
        return hfs_fail(err, HFS_E_INVALID, "render: missing field, lighting or quality");
    const hfs_key_range side = hfs_scene_key_lib_range(HFS_SK_SIZE, 0);
    if (f->width < side.lo || f->height < side.lo)
        return hfs_fail(err, HFS_E_INVALID, "height field: %dx%d is smaller than %.0fx%.0f",
                        f->width, f->height, side.lo, side.lo);
    if (f->width > side.hi || f->height > side.hi)
        return hfs_fail(err, HFS_E_INVALID, "height field: %dx%d is larger than %.0fx%.0f",
                        f->width, f->height, side.hi, side.hi);
    int rc = CHECK_LIB(HFS_SK_DX, 0, f->dx, "dx");
    return rc ? rc : CHECK_LIB(HFS_SK_ZSCALE, 0, f->zscale, "zscale");
}

/* The heights: a pass over the whole field. */
static int check_heights(const hfs_field *f, hfs_error *err)
{
    const size_t n = (size_t)f->width * (size_t)f->height;
    for (size_t i = 0; i < n; ++i)
        if (!isfinite(f->z[i]))
            return hfs_fail(err, HFS_E_INVALID, "height field: non-finite height at texel %zu "
                            "(holes must be filled before rendering)", i);
    return HFS_OK;
}

int hfs_validate_field(const hfs_field *f, hfs_error *err)
{
    const int rc = check_field_params(f, err);
    return rc ? rc : check_heights(f, err);
}

static int check_lights(const hfs_lighting *l, hfs_error *err)
{
    char who[32];
    int rc = HFS_OK;
    if (l->n_key < 0 || l->n_key > HFS_MAX_KEY_LIGHTS)
        return hfs_fail(err, HFS_E_INVALID, "key: %d lights (at most %d)", l->n_key, HFS_MAX_KEY_LIGHTS);
    for (int i = 0; i < l->n_key && !rc; ++i) {
        const hfs_key_light *k = &l->key[i];
        snprintf(who, sizeof who, "key light %d", i + 1);
        const double angle[3] = {k->phi, k->elev, k->alpha};
        for (int j = 0; j < 3 && !rc; ++j)
            rc = CHECK_LIB(HFS_SK_KEY, j, angle[j], who);
        if (!rc)
            rc = check_radiance(HFS_SK_KEY, 3, k->radiance, who, err);
    }
    if (!rc && (l->n_local < 0 || l->n_local > HFS_MAX_LOCAL_LIGHTS))
        return hfs_fail(err, HFS_E_INVALID, "local: %d lights (at most %d)", l->n_local, HFS_MAX_LOCAL_LIGHTS);
    for (int i = 0; i < l->n_local && !rc; ++i) {
        const hfs_local_light *o = &l->local[i];
        snprintf(who, sizeof who, "local light %d", i + 1);
        for (int j = 0; j < 3 && !rc; ++j)
            rc = CHECK_LIB(HFS_SK_LOCAL, j, o->pos[j], who);
        if (!rc)
            rc = CHECK_LIB(HFS_SK_LOCAL, 3, o->radius, who);
        if (!rc)
            rc = check_radiance(HFS_SK_LOCAL, 4, o->radiance, who, err);
    }
    return rc;
}

/* Glossy surfaces: specular and gloss in their keys' ranges, albedo +
 * specular <= 1 (the lobe and the Lambertian term share the energy), a
 * unit view direction above the horizon.  gloss and view_dir are checked
 * only when specular > 0: a lighting zeroed by its caller (no
 * hfs_lighting_defaults) stays the valid diffuse one it was. */
static int check_gloss(const hfs_lighting *l, hfs_error *err)
{
    int rc = CHECK_LIB(HFS_SK_SPECULAR, 0, l->specular, "specular");
    if (rc || l->specular == 0.0)
        return rc;
    if (!rc)
        rc = CHECK_LIB(HFS_SK_GLOSS, 0, l->gloss, "gloss");
    if (!rc && !(l->albedo + l->specular <= 1.0 + 1e-12))
        return hfs_fail(err, HFS_E_INVALID, "albedo %g + specular %g is above 1 (energy)",
                        l->albedo, l->specular);
    const double *v = l->view_dir;
    const double len2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    if (!rc && !(fabs(len2 - 1.0) <= 1e-9 && v[2] > 0.0))
        return hfs_fail(err, HFS_E_INVALID, "view-dir: (%g, %g, %g) is not a unit vector above "
                        "the horizon (elevation in (0, 90] degrees)", v[0], v[1], v[2]);
    const double *e = l->view_eye;
    if (!rc && l->view_from_eye && !(isfinite(e[0]) && isfinite(e[1]) && isfinite(e[2])))
        return hfs_fail(err, HFS_E_INVALID, "view eye: (%g, %g, %g) is not a finite point",
                        e[0], e[1], e[2]);
    return rc;
}

/* The environment map (hfshade.h): only with has_env (env_sh is its
 * projection, what every backend but the truth renders), sane sizes, and
 * (scan) finite values (hfs_envmap_load keeps negative ones): a pass over
 * the map. */
static int check_map(const hfs_lighting *l, const float *m, const char *name, int scan,
                     hfs_error *err)
{
    if (!m)
        return HFS_OK;
    const int w = l->env_map_width, h = l->env_map_height;
    if (!l->has_env)
        return hfs_fail(err, HFS_E_INVALID, "%s: given without has_env (env_sh must hold "
                        "the map's SH projection)", name);
    if (w < 1 || h < 1 || w > 65536 || h > 65536 || (long long)w * h > (1ll << 28))
        return hfs_fail(err, HFS_E_INVALID, "%s: size %dx%d out of range (1..65536 per "
                        "side, at most 2^28 pixels)", name, w, h);
    const size_t n = scan ? (size_t)w * (size_t)h * 3 : 0;
    for (size_t i = 0; i < n; ++i)
        if (!(fabsf(m[i]) <= FLT_MAX))
            return hfs_fail(err, HFS_E_INVALID, "%s: pixel (%zu, %zu) channel %zu is %g "
                            "(must be finite)", name, i / 3 % (size_t)w, i / 3 / (size_t)w,
                            i % 3, (double)m[i]);
    return HFS_OK;
}

/* The maps beside env_sh: env_map (the truth's), env_shade_map with its
 * open-sky table env_open (the CPU reference's and GLES's). */
static int check_env_map(const hfs_lighting *l, int scan, hfs_error *err)
{
    int rc = check_map(l, l->env_map, "env-map", scan, err);
    if (!rc)
        rc = check_map(l, l->env_shade_map, "env-shade-map", scan, err);
    if (rc)
        return rc;
    if (l->env_shade_map && !l->env_open)
        return hfs_fail(err, HFS_E_INVALID, "env-shade-map: given without env_open (its "
                        "open-sky table, hfs_env_open_build)");
    if (l->env_open && !l->has_env)
        return hfs_fail(err, HFS_E_INVALID, "env-open: given without has_env");
    for (int i = 0; l->env_open && i < HFS_ENV_OPEN_FLOATS; ++i)
        if (!(fabsf(l->env_open[i]) <= FLT_MAX))
            return hfs_fail(err, HFS_E_INVALID, "env-open: entry %d is %g (must be finite)",
                            i, (double)l->env_open[i]);
    return HFS_OK;
}

static int validate_lighting(const hfs_lighting *l, int scan_map, hfs_error *err)
{
    if (!l)
        return hfs_fail(err, HFS_E_INVALID, "render: missing field, lighting or quality");
    int rc = CHECK_LIB(HFS_SK_ALBEDO, 0, l->albedo, "albedo");
    if (!rc)
        rc = CHECK_LIB(HFS_SK_BOUNCES, 0, l->bounces, "bounces");
    for (int c = 0; c < 3 && l->has_env && !rc; ++c)
        for (int k = 0; k < HFS_SH_COEFFS && !rc; ++k)
            rc = CHECK_LIB(HFS_SK_ENV_SH, k, l->env_sh[c][k], "env-sh");
    if (!rc && l->has_env)
        rc = CHECK_LIB(HFS_SK_ENV_ROTATE, 0, l->env_rotate, "env-rotate");
    if (!rc)
        rc = check_env_map(l, scan_map, err);
    if (!rc)
        rc = check_gloss(l, err);
    return rc ? rc : check_lights(l, err);
}

int hfs_validate_lighting(const hfs_lighting *l, hfs_error *err)
{
    return validate_lighting(l, 1, err);
}

int hfs_validate_quality(const hfs_quality *q, hfs_error *err)
{
    if (!q)
        return hfs_fail(err, HFS_E_INVALID, "render: missing field, lighting or quality");
    const struct { hfs_scene_key_id id; int value; } counts[] = {
        {HFS_SK_K, q->k}, {HFS_SK_OFFSET, q->offset}, {HFS_SK_NPHI_ENV, q->nphi_env},
        {HFS_SK_NPHI_KEY, q->nphi_key}, {HFS_SK_REFINE, q->refine},
        {HFS_SK_SPLIT, q->split}, {HFS_SK_FAR_FROM, q->far_from}, {HFS_SK_FAR_DIRS, q->far_dirs},
        {HFS_SK_FAR_STEP, q->far_step},
        {HFS_SK_NPHI_BOUNCE, q->nphi_bounce}, {HFS_SK_BOUNCE_REFINE, q->bounce_refine},
        {HFS_SK_BOUNCE_SUBSAMPLE, q->bounce_subsample}, {HFS_SK_BOUNCE_NEAR, q->bounce_near},
        {HFS_SK_NPHI_LOCAL, q->nphi_local},
        {HFS_SK_SUBSAMPLE, q->subsample}, {HFS_SK_THREADS, q->threads},
        {HFS_SK_TRUTH_AZIMUTHS, q->truth_azimuths}, {HFS_SK_TRUTH_SAMPLES, q->truth_light_samples},
    };
    for (size_t i = 0; i < sizeof counts / sizeof counts[0]; ++i) {
        const hfs_scene_key *k = hfs_scene_key_get(counts[i].id);
        const int rc = CHECK_LIB(counts[i].id, 0, counts[i].value, k->name);
        if (rc)
            return rc;
        if (!hfs_scene_key_int_allowed(k, counts[i].value)) {
            char allowed[64];
            hfs_scene_key_allowed_text(k, allowed, sizeof allowed);
            return hfs_fail(err, HFS_E_INVALID, "%s: %d is not one of %s", k->name,
                            counts[i].value, allowed);
        }
    }
    if (q->precision != HFS_PRECISION_FP16 && q->precision != HFS_PRECISION_FP32)
        return hfs_fail(err, HFS_E_INVALID, "precision: unknown value %d", (int)q->precision);
    if (q->local_full_swath != 0 && q->local_full_swath != 1)
        return hfs_fail(err, HFS_E_INVALID, "local-swath: unknown value %d", q->local_full_swath);
    if (q->visibility != HFS_VIS_LEGENDRE && q->visibility != HFS_VIS_WEDGE_TABLE &&
        q->visibility != HFS_VIS_SLICE)
        return hfs_fail(err, HFS_E_INVALID, "visibility: unknown value %d", (int)q->visibility);
    if (q->truth_elev_order < 1 || q->truth_elev_order > 64)
        return hfs_fail(err, HFS_E_INVALID, "quality: truth_elev_order %d is out of range [1, 64]",
                        q->truth_elev_order);
    return HFS_OK;
}

#undef CHECK_LIB

/* Inputs in the order a message should name them; the heights only when
 * `heights` (the renderer scans them once per serial). */
int hfs_validate_frame_inputs(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                              int heights, int scan_map, hfs_error *err)
{
    if (!f || !l || !q || !f->z)
        return hfs_fail(err, HFS_E_INVALID, "render: missing field, lighting or quality");
    int rc = check_field_params(f, err);
    if (!rc && heights)
        rc = check_heights(f, err);
    if (!rc)
        rc = validate_lighting(l, scan_map, err);
    if (!rc)
        rc = hfs_albedo_map_check(l->albedo_map, f->width, f->height, err);
    return rc ? rc : hfs_validate_quality(q, err);
}

int hfs_validate_inputs(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                        hfs_error *err)
{
    return hfs_validate_frame_inputs(f, l, q, 1, 1, err);
}


int hfs_validate_horizon_desc(const hfs_horizon_desc *d, const float *out, hfs_error *err)
{
    if (!d || !d->azimuth || !out)
        return hfs_fail(err, HFS_E_INVALID, "horizons: no %s",
                        !d ? "request" : !d->azimuth ? "azimuths" : "output array");
    if (d->n_azimuths < 1 || d->n_azimuths > HFS_MAX_HORIZON_AZIMUTHS)
        return hfs_fail(err, HFS_E_INVALID, "horizons: %d azimuths (1..%d allowed)",
                        d->n_azimuths, HFS_MAX_HORIZON_AZIMUTHS);
    for (int a = 0; a < d->n_azimuths; ++a)
        if (!isfinite(d->azimuth[a]))
            return hfs_fail(err, HFS_E_INVALID, "horizons: azimuth %d is not finite", a + 1);
    if (!(isfinite(d->radius) && d->radius >= 0.0))
        return hfs_fail(err, HFS_E_INVALID, "horizons: radius %g (a finite distance >= 0, "
                        "0 for the whole field)", d->radius);
    if (d->window != 0 && d->window != 1)
        return hfs_fail(err, HFS_E_INVALID, "horizons: window %d (0 or 1)", d->window);
    const double half_pi = 1.5707963267948966;
    if (d->window && !(d->lo >= -half_pi && d->lo <= d->hi && d->hi <= half_pi))
        return hfs_fail(err, HFS_E_INVALID, "horizons: window [%g, %g] (radians, -pi/2 <= lo "
                        "<= hi <= pi/2)", d->lo, d->hi);
    return HFS_OK;
}
