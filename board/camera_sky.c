/*
 * camera_sky.c — see camera_sky.h.
 */
#include "camera_sky.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sh.h"

struct hfs_camsky {
    hfs_camenv_params p;
    hfs_camenv *conv;
    float *map;
    int max_lights;
    hfs_env_tracker tracker;
    int have;                      /* out holds a frame's lighting          */
    int64_t last_t;
    hfs_camsky_out out;
};

int hfs_camsky_max_lights(int cfg_lights, int scene_lights, int scene_keys)
{
    const int want = cfg_lights != -2 ? cfg_lights : scene_lights;
    if (want == 0)
        return 0;
    hfs_env_decompose_opts o;
    hfs_env_decompose_defaults(&o);
    int n = want > 0 ? want : o.max_lights;
    if (n > HFS_MAX_KEY_LIGHTS - scene_keys)
        n = HFS_MAX_KEY_LIGHTS - scene_keys;
    return n < 0 ? 0 : n;
}

int hfs_camsky_create(const hfs_camenv_params *p, int max_lights, hfs_camsky **out,
                      hfs_error *err)
{
    *out = NULL;
    hfs_camsky *s = calloc(1, sizeof *s);
    if (!s)
        return hfs_fail(err, HFS_E_NOMEM, "camera environment: out of memory");
    s->p = *p;
    s->max_lights = max_lights;
    int rc = hfs_camenv_create(p, &s->conv, err);
    if (!rc && !(s->map = malloc((size_t)p->map_w * p->map_h * 3 * sizeof *s->map)))
        rc = hfs_fail(err, HFS_E_NOMEM, "camera environment: out of memory");
    if (rc) {
        hfs_camsky_destroy(s);
        return rc;
    }
    if (max_lights > 0) {
        hfs_env_decompose_opts o;
        hfs_env_decompose_defaults(&o);
        o.max_lights = max_lights;
        o.threads = 1; /* the kiosk's loop thread: deterministic and cheap here */
        hfs_env_tracker_init(&s->tracker, &o);
    }
    *out = s;
    return HFS_OK;
}

void hfs_camsky_destroy(hfs_camsky *s)
{
    if (!s)
        return;
    hfs_camenv_destroy(s->conv);
    free(s->map);
    free(s);
}

static int same_ids(const hfs_camsky_out *a, const int *ids, int n)
{
    if (a->n_keys != n)
        return 0;
    for (int i = 0; i < n; ++i)
        if (a->ids[i] != ids[i])
            return 0;
    return 1;
}

/* The new frame's lighting (sh, keys with ids) folded into the average. */
static void smooth(hfs_camsky *s, int64_t t_ns, double sh[3][HFS_SH_COEFFS],
                   const hfs_key_light *keys, const int *ids, int n)
{
    hfs_camsky_out *o = &s->out;
    double a = 1.0;
    if (s->have && s->p.smoothing_s > 0.0 && same_ids(o, ids, n)) {
        double dt = (double)(t_ns - s->last_t) * 1e-9;
        dt = dt < 0.0 ? 0.0 : dt > 10.0 ? 10.0 : dt;
        a = 1.0 - exp(-dt / s->p.smoothing_s);
    }
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < HFS_SH_COEFFS; ++k)
            o->sh[c][k] = a >= 1.0 ? sh[c][k] : o->sh[c][k] + a * (sh[c][k] - o->sh[c][k]);
    for (int i = 0; i < n; ++i) {
        hfs_key_light k = keys[i];
        if (a < 1.0)
            for (int c = 0; c < 3; ++c)
                k.radiance[c] = (float)(o->keys[i].radiance[c] +
                                        a * (keys[i].radiance[c] - o->keys[i].radiance[c]));
        o->keys[i] = k;
        o->ids[i] = ids[i];
    }
    o->n_keys = n;
    s->have = 1;
    s->last_t = t_ns;
}

int hfs_camsky_push(hfs_camsky *s, const hfs_capture_frame *f, hfs_error *err)
{
    int rc = hfs_camenv_convert(s->conv, f, s->map, err);
    if (rc)
        return rc;
    double sh[3][HFS_SH_COEFFS];
    hfs_key_light keys[HFS_MAX_KEY_LIGHTS];
    int ids[HFS_MAX_KEY_LIGHTS], n = 0;
    if (s->max_lights > 0) {
        hfs_env_decomp d;
        rc = hfs_env_track(&s->tracker, s->map, s->p.map_w, s->p.map_h, "camera", &d, err);
        if (rc)
            return rc;
        n = hfs_env_decomp_keys(&d, keys, s->max_lights);
        for (int i = 0; i < n; ++i)
            ids[i] = d.light[i].id;
        memcpy(sh, d.residual_sh, sizeof sh);
    } else {
        hfs_sh_project_equirect(s->map, s->p.map_w, s->p.map_h, sh);
    }
    smooth(s, f->t_ns, sh, keys, ids, n);
    return HFS_OK;
}

const hfs_camsky_out *hfs_camsky_get(const hfs_camsky *s)
{
    return s->have ? &s->out : NULL;
}

const float *hfs_camsky_map(const hfs_camsky *s, int *w, int *h)
{
    *w = s->p.map_w;
    *h = s->p.map_h;
    return s->map;
}
