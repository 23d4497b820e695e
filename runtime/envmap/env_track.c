/*
 * env_track.c — temporal stability of the decomposition for maps that change
 * a little every frame (env_decompose.h "temporal stability").
 *
 * Per frame: (1) every tracked light is extracted first, seeded at its last
 * direction and radius, so identities never swap and a light is found even
 * where detection would rank it differently; (2) new candidates are found on
 * a copy of what remains (the map itself keeps them); (3) a candidate seen
 * within a few of its radii of last frame's candidate counts one more frame
 * in a row, and after appear_frames frames at >= appear_share it is
 * extracted from the map and tracked with a new id; (4) a tracked light
 * under vanish_share (or not found) for vanish_frames frames in a row is
 * dropped.  The first frame takes its candidates at once (no history).
 * Energy stays exact in every frame: a light is either extracted or left in
 * the residual, never both.  The copy costs one map of memory (probes are
 * small).
 */
#include "env_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static void light_dir(const hfs_env_light *l, double d[3])
{
    d[0] = cos(l->elev) * cos(l->phi);
    d[1] = cos(l->elev) * sin(l->phi);
    d[2] = sin(l->elev);
}

static double angle_between(const hfs_env_light *a, const hfs_env_light *b)
{
    double u[3], v[3];
    light_dir(a, u);
    light_dir(b, v);
    const double c = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    return acos(fmax(-1.0, fmin(1.0, c)));
}

void hfs_env_tracker_init(hfs_env_tracker *t, const hfs_env_decompose_opts *o)
{
    memset(t, 0, sizeof *t);
    if (o)
        t->opts = *o;
    else
        hfs_env_decompose_defaults(&t->opts);
    t->appear_share = 1.25 * t->opts.min_share;
    t->vanish_share = 0.5 * t->opts.min_share;
    t->appear_frames = 3;
    t->vanish_frames = 3;
    t->gain = 0.3;
    t->vel_gain = 0.05;
}

static void normalize3(double v[3])
{
    const double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int q = 0; q < 3; ++q)
        v[q] /= n;
}

/* Alpha-beta filter of tracked light k's direction: prediction from its
 * last direction and velocity, corrected towards the measured got; a jump
 * of more than 4 texels + 2 radii restarts it at the measurement. */
static void smooth(hfs_env_tracker *t, const env_ctx *c, int k, hfs_env_light *got)
{
    double last[3], pred[3], meas[3], r[3];
    light_dir(&t->tracked[k], last);
    light_dir(got, meas);
    for (int q = 0; q < 3; ++q)
        pred[q] = last[q] + t->vel[k][q];
    normalize3(pred);
    double rn = 0.0;
    for (int q = 0; q < 3; ++q) {
        r[q] = meas[q] - pred[q];
        rn += r[q] * r[q];
    }
    const double jump = 4.0 * envr_texel_size(c, got->elev) + 2.0 * got->alpha;
    if (sqrt(rn) > jump) {
        memset(t->vel[k], 0, sizeof t->vel[k]);
        return;
    }
    double d[3];
    for (int q = 0; q < 3; ++q) {
        d[q] = pred[q] + t->gain * r[q];
        t->vel[k][q] += t->vel_gain * r[q];
    }
    normalize3(d);
    env_dir_to_angles(d, &got->phi, &got->elev);
}

static int extract_at(env_ctx *c, const hfs_env_light *l, hfs_env_light *out)
{
    env_seed s;
    light_dir(l, s.d);
    s.r0 = l->alpha;
    const int ok = envr_extract(c, &s, 0.0, out);
    if (ok)
        envc_merge_levels(c);
    return ok;
}

/* Step (1): the tracked lights, in tracking order; drops the vanished.
 * missed[k]: the light kept as k was not found where it was. */
static void extract_tracked(hfs_env_tracker *t, env_ctx *c, hfs_env_decomp *out, int *missed)
{
    int keep = 0;
    for (int k = 0; k < t->n; ++k) {
        hfs_env_light got;
        const int ok = extract_at(c, &t->tracked[k], &got);
        missed[keep] = !ok;
        if (ok) {
            got.id = t->tracked[k].id;
            smooth(t, c, k, &got);
            out->light[out->n_lights++] = got;
        }
        t->weak[k] = (ok && got.share >= t->vanish_share) ? 0 : t->weak[k] + 1;
        if (t->weak[k] >= t->vanish_frames)
            continue;
        t->tracked[keep] = ok ? got : t->tracked[k];
        memmove(t->vel[keep], t->vel[k], sizeof t->vel[k]);
        t->weak[keep++] = t->weak[k];
    }
    t->n = keep;
}

/* Step (2): candidates on a copy of the current residual. */
static int candidates(const hfs_env_tracker *t, const env_ctx *c, int room,
                      hfs_env_light *cand, hfs_error *err)
{
    const size_t n = (size_t)c->w * c->h * 3;
    float *copy = malloc(n * sizeof *copy);
    env_ctx cc;
    int found = 0;
    if (!copy)
        return hfs_fail(err, HFS_E_NOMEM, "out of memory for a %dx%d tracking copy", c->w, c->h);
    memcpy(copy, c->rgb, n * sizeof *copy);
    int rc = envc_init(&cc, copy, c->w, c->h, &t->opts, err);
    if (!rc) {
        cc.total_lum = c->total_lum; /* shares of the whole map */
        while (found < room) {
            env_seed seed;
            if (!envc_detect(&cc, &seed) ||
                !envr_extract(&cc, &seed, t->opts.min_share, &cand[found]))
                break;
            found++;
            envc_merge_levels(&cc);
        }
        envc_free(&cc);
    }
    free(copy);
    return rc ? rc : found;
}

/* Step (2b): a tracked light not found where it was (a frame skipped by a
 * slow consumer lets a sun move past its search window) takes the nearest
 * candidate within REACQUIRE_RAD, keeping its identity, instead of
 * vanishing and coming back as a new light; the candidate is used up. */
#define REACQUIRE_RAD (20.0 * 3.14159265358979323846 / 180.0)
static void reacquire(hfs_env_tracker *t, env_ctx *c, hfs_env_light *cand, int *nc,
                      const int *missed, hfs_env_decomp *out)
{
    for (int k = 0; k < t->n; ++k) {
        if (!missed[k])
            continue;
        int best = -1;
        double bd = REACQUIRE_RAD;
        for (int j = 0; j < *nc; ++j) {
            const double d = angle_between(&cand[j], &t->tracked[k]);
            if (d < bd)
                bd = d, best = j;
        }
        hfs_env_light got;
        if (best < 0 || !extract_at(c, &cand[best], &got))
            continue;
        got.id = t->tracked[k].id;
        t->tracked[k] = got;
        memset(t->vel[k], 0, sizeof t->vel[k]);
        t->weak[k] = got.share >= t->vanish_share ? 0 : t->weak[k];
        out->light[out->n_lights++] = got;
        cand[best] = cand[--*nc];
    }
}

/* Step (3): counts candidates against last frame's; promotes the steady. */
static void promote(hfs_env_tracker *t, env_ctx *c, const hfs_env_light *cand, int nc,
                    hfs_env_decomp *out)
{
    hfs_env_light pend[HFS_ENV_MAX_LIGHTS];
    int seen[HFS_ENV_MAX_LIGHTS], np = 0;
    const int first = t->frames == 0;
    for (int k = 0; k < nc; ++k) {
        int count = cand[k].share >= t->appear_share;
        for (int p = 0; p < t->n_pending && count; ++p) {
            const double px = envr_texel_size(c, cand[k].elev);
            const double near = fmax(3.0 * (cand[k].alpha + t->pending[p].alpha), 4.0 * px);
            if (angle_between(&cand[k], &t->pending[p]) < near) {
                count = t->seen[p] + 1;
                break;
            }
        }
        if (!count)
            continue;
        hfs_env_light got;
        if ((first || count >= t->appear_frames) && t->n < t->opts.max_lights &&
            extract_at(c, &cand[k], &got)) {
            got.id = ++t->next_id;
            t->tracked[t->n] = got;
            memset(t->vel[t->n], 0, sizeof t->vel[t->n]);
            t->weak[t->n++] = 0;
            out->light[out->n_lights++] = got;
            continue;
        }
        pend[np] = cand[k];
        seen[np++] = count;
    }
    memcpy(t->pending, pend, sizeof pend);
    memcpy(t->seen, seen, sizeof seen);
    t->n_pending = np;
}

int hfs_env_track(hfs_env_tracker *t, float *rgb, int w, int h, const char *name,
                  hfs_env_decomp *out, hfs_error *err)
{
    env_ctx c;
    memset(out, 0, sizeof *out);
    int rc = envd_begin(&c, rgb, w, h, &t->opts, name, err);
    if (rc)
        return rc;
    int missed[HFS_ENV_MAX_LIGHTS] = {0};
    extract_tracked(t, &c, out, missed);
    hfs_env_light cand[HFS_ENV_MAX_LIGHTS];
    int nc = candidates(t, &c, t->opts.max_lights - t->n, cand, err);
    if (nc < 0) {
        envc_free(&c);
        memset(out, 0, sizeof *out);
        return nc;
    }
    reacquire(t, &c, cand, &nc, missed, out);
    promote(t, &c, cand, nc, out);
    t->frames++;
    envd_finish(&c, out);
    envc_free(&c);
    return HFS_OK;
}
