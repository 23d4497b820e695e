/*
 * truth.c — the brute-force ground truth (SPEC.md, DESIGN.md "Ground truth").
 *
 * Per receiver (grid point, lifted by 1e-4*dx, SPEC normal):
 *   - environment: exact horizon (hfs_truth_horizon: the bilinear surface's
 *     largest slope along the ray, cell by cell in closed form) at each of A azimuth midpoints (a + 0.5) 2pi/A,
 *     then Gauss-Legendre in elevation of L(s) (N.s) cos e over
 *     [max(horizon, tangent-plane elevation), pi/2]; midpoint rule in azimuth;
 *     an environment map (lighting->env_map) is integrated itself instead
 *     (truth_envmap.h), and the key lights extracted from it are skipped;
 *   - key / local lights: stratified jittered samples of the cap's solid
 *     angle (a sqrt(n) x sqrt(n) grid over (cos theta, psi): sqrt(n) rings,
 *     each jittered in cos theta and randomly rotated in psi), each an exact
 *     ray test against the bilinear surface (hfs_truth_ray_hits), up to the
 *     grid edge (key) or the sphere's surface (local).
 *
 * Determinism: receivers are independent, sums run in a fixed order and the
 * jitter comes from a random stream seeded by a hash of (receiver, light), so
 * the output is bit identical for any thread count.  Nothing here prints; progress goes
 * through the caller's callback (hfs_parallel_rows, calling thread).
 */
#include "albedo.h"
#include "backends.h"
#include "field_geom.h"
#include "lights.h"
#include "parallel.h"
#include "sh.h"
#include "truth_bounce.h"
#include "truth_envmap.h"
#include "truth_gloss.h"
#include "truth_raycast.h"
#include "truth_sampling.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define TRIG_N 7           /* L along a vertical great circle: degree-3 trig */
#define LOCAL_SLOT0 64     /* RNG stream ids of local lights start here     */
#define GLOSS_SLOT 4096    /* RNG stream id of the glossy environment term  */

/* L_c(phi_a, e) = t[0] + sum_{n=1..3} t[2n-1] cos(n e) + t[2n] sin(n e):
 * exact, since L is a cubic polynomial in s and s(phi, e) is linear in
 * (cos e, sin e).  Lets the inner loop avoid re-evaluating the SH basis. */
typedef struct env_azimuth {
    double c, s;            /* cos, sin of the azimuth */
    double trig[3][TRIG_N];
} env_azimuth;

typedef struct key_prep {
    double d[3], t1[3], t2[3]; /* axis and an orthonormal frame           */
    double omc;                /* 1 - cos(alpha), computed stably          */
    double sin_a;
    double le[3];
    int slot;
} key_prep;

typedef struct local_prep {
    const hfs_local_light *light;
    double le[3];
    int slot;
} local_prep;

typedef struct truth_ctx {
    const hfs_field *f;
    hfs_truth_grid grid;
    double rho;

    int n_az;                  /* 0: no environment */
    int env_grey;              /* all channels equal: integrate one */
    env_azimuth *az;
    int n_gl;
    double gl_x[64], gl_w[64];

    int n_theta, n_psi;        /* stratification of light samples */
    int n_key, n_local;
    key_prep key[HFS_MAX_KEY_LIGHTS];
    local_prep local[HFS_MAX_LOCAL_LIGHTS];

    float *out;
    hfs_gloss gloss;           /* glossy surfaces (gloss.h) */
    float *spec;               /* W x H x 3 glossy term when gloss.on */
    double env_rot[3][HFS_SH_N]; /* the rotated sky, for the glossy term */
    int env_samples;           /* lobe samples per receiver (truth-samples) */
    hfs_truth_envmap *emap;    /* the environment map itself, or NULL */
} truth_ctx;

static int radiance_zero(const float le[3])
{
    return le[0] == 0.0f && le[1] == 0.0f && le[2] == 0.0f;
}

/* Sum over the stratified samples of the cap (axis d, frame t1/t2,
 * 1 - cos alpha = omc) of V(s) max(0, N.s); times Omega/n it estimates the
 * integral over the cap.  r non-NULL (glossy): *lobe_sum += the same sum
 * weighted by the lobe (S+2)/(2 pi) max(0, r.s)^S.  V from an exact ray from o (grid xy, world z) up to
 * the grid edge (key: sphere_c NULL) or to the sphere's surface (local). */
static double cap_visible_irradiance(const truth_ctx *x, const double o[3],
                                     const double p_world[3], const double n[3],
                                     const double d[3], const double t1[3],
                                     const double t2[3], double omc,
                                     const double *sphere_c, double sphere_r2,
                                     uint64_t rng, const hfs_gloss *gl, const double *r,
                                     double *lobe_sum)
{
    const int nt = x->n_theta, np = x->n_psi;
    double sum = 0.0;
    for (int a = 0; a < nt; ++a) {
        /* Ring a: cos theta jittered inside its stratum, the np azimuths
         * equispaced with a random rotation.  Every sample is uniform in its
         * (cos theta, psi) cell, so the estimator is unbiased, and a ring sums
         * cos(psi) terms exactly: without shadows the error is only the 1D
         * stratification of the (linear) cos theta part. */
        const double xi1 = rng_uniform(&rng), xi2 = rng_uniform(&rng);
        const double one_m_ct = omc * ((double)a + xi1) / nt; /* 1 - cos theta */
        const double ct = 1.0 - one_m_ct;
        const double st = sqrt(fmax(0.0, one_m_ct * (2.0 - one_m_ct)));
        for (int b = 0; b < np; ++b) {
            const double psi = 2.0 * PI * ((double)b + xi2) / np;
            const double cp = cos(psi), sp = sin(psi);
            double s[3];
            for (int k = 0; k < 3; ++k)
                s[k] = ct * d[k] + st * (cp * t1[k] + sp * t2[k]);
            const double ns = n[0] * s[0] + n[1] * s[1] + n[2] * s[2];
            if (!(ns > 0.0))
                continue;
            double tmax = INFINITY;
            if (sphere_c) {
                /* First intersection with the sphere along s. */
                const double v[3] = {sphere_c[0] - p_world[0], sphere_c[1] - p_world[1],
                                     sphere_c[2] - p_world[2]};
                const double bb = s[0] * v[0] + s[1] * v[1] + s[2] * v[2];
                const double cc = v[0] * v[0] + v[1] * v[1] + v[2] * v[2] - sphere_r2;
                tmax = bb - sqrt(fmax(0.0, bb * bb - cc));
                if (tmax < 0.0)
                    tmax = 0.0;
            }
            if (!hfs_truth_ray_hits(&x->grid, o, s, tmax)) {
                sum += ns;
                if (r) /* glossy: the same visible sample, weighted by the lobe */
                    *lobe_sum += ns * hfs_gloss_lobe(gl, r, s);
            }
        }
    }
    return sum;
}

/* ---- one receiver --------------------------------------------------------------- */

/* One Gauss-Legendre node at elevation e = atan2(se, ce): adds
 * w * L(s) * max(0, N.s) * cos e for the n_ch channels. */
static inline void env_node(const env_azimuth *az, int n_ch, double na, double nz,
                            double ce, double se, double w, double acc[3])
{
    double ns = na * ce + nz * se;
    if (ns < 0.0)
        ns = 0.0;
    const double wgt = w * ns * ce;
    const double c2 = ce * ce - se * se, s2 = 2.0 * se * ce;
    const double c3 = c2 * ce - s2 * se, s3 = s2 * ce + c2 * se;
    for (int ch = 0; ch < n_ch; ++ch) {
        const double *t = az->trig[ch];
        acc[ch] += wgt * (t[0] + t[1] * ce + t[2] * se + t[3] * c2 + t[4] * s2 + t[5] * c3 +
                          t[6] * s3);
    }
}

static void env_receiver(const truth_ctx *x, int i, int j, double z0,
                         const double n[3], double lo_out[3])
{
    const int n_ch = x->env_grey ? 1 : 3;
    double sum[3] = {0.0, 0.0, 0.0};
    double hint = 0.0; /* where the previous azimuth's maximum lay: horizons
                        * are nearly continuous in azimuth, so it seeds the walk */
    for (int a = 0; a < x->n_az; ++a) {
        const env_azimuth *az = &x->az[a];
        const double na = n[0] * az->c + n[1] * az->s;
        const double lo =
            hfs_truth_env_lo(&x->grid, i, j, z0, n, az->c, az->s, &hint);
        if (!(lo < PI / 2))
            continue;
        /* GL on [lo, pi/2]: nodes mid +- half*x_g in symmetric pairs, so one
         * sincos serves two nodes (angle addition). */
        const double half = 0.5 * (PI / 2 - lo), mid = lo + half;
        const double cm = cos(mid), sm = sin(mid);
        double acc[3] = {0.0, 0.0, 0.0};
        for (int g = 0; g < x->n_gl / 2; ++g) {
            const double d = half * x->gl_x[x->n_gl - 1 - g], w = x->gl_w[x->n_gl - 1 - g];
            const double cd = cos(d), sd = sin(d);
            env_node(az, n_ch, na, n[2], cm * cd - sm * sd, sm * cd + cm * sd, w, acc);
            env_node(az, n_ch, na, n[2], cm * cd + sm * sd, sm * cd - cm * sd, w, acc);
        }
        if (x->n_gl % 2)
            env_node(az, n_ch, na, n[2], cm, sm, x->gl_w[x->n_gl / 2], acc);
        for (int ch = 0; ch < n_ch; ++ch)
            sum[ch] += acc[ch] * half;
    }
    if (n_ch == 1)
        sum[1] = sum[2] = sum[0];
    /* rho/pi * (2 pi / A) * sum */
    for (int ch = 0; ch < 3; ++ch)
        lo_out[ch] += x->rho * 2.0 / x->n_az * sum[ch];
}

static void truth_row(void *vctx, int j, int worker)
{
    (void)worker;
    const truth_ctx *x = vctx;
    const hfs_field *f = x->f;
    const int ns = x->n_theta * x->n_psi;
    for (int i = 0; i < f->width; ++i) {
        const uint64_t rid = (uint64_t)j * (uint64_t)f->width + (uint64_t)i;
        double n[3];
        hfs_field_normal(f, i, j, n);
        const double z0 = hfs_field_lifted_z(f, i, j);
        const double o[3] = {(double)i, (double)j, z0};        /* grid xy, world z */
        const double pw[3] = {i * f->dx, j * f->dx, z0};       /* world */
        double lo[3] = {0.0, 0.0, 0.0};
        double rv[3], sp[3] = {0.0, 0.0, 0.0}; /* glossy: R and the term */
        const double *r = x->gloss.on && hfs_gloss_reflect(&x->gloss, pw, n, rv) > 0.0 ? rv : NULL;

        if (x->n_az > 0)
            env_receiver(x, i, j, z0, n, lo);
        if (x->emap)
            hfs_truth_envmap_receiver(x->emap, &x->grid, i, j, z0, n, x->rho, lo);
        if ((x->n_az > 0 || x->emap) && r)
            hfs_truth_gloss_env(&x->grid, &x->gloss, x->env_rot, x->emap, x->env_samples, o, n,
                                r, rng_seed(rid, GLOSS_SLOT), sp);

        for (int k = 0; k < x->n_key; ++k) {
            const key_prep *kp = &x->key[k];
            /* Whole cap below the tangent plane: every sample gives 0. */
            if (n[0] * kp->d[0] + n[1] * kp->d[1] + n[2] * kp->d[2] <= -kp->sin_a)
                continue;
            double lobe = 0.0;
            const double e = cap_visible_irradiance(x, o, pw, n, kp->d, kp->t1, kp->t2,
                                                    kp->omc, NULL, 0.0,
                                                    rng_seed(rid, kp->slot), &x->gloss, r, &lobe);
            const double scale = x->rho / PI * (2.0 * PI * kp->omc) / ns * e;
            const double gs = x->gloss.ks * (2.0 * PI * kp->omc) / ns * lobe;
            for (int ch = 0; ch < 3; ++ch) {
                lo[ch] += scale * kp->le[ch];
                sp[ch] += gs * kp->le[ch];
            }
        }

        for (int k = 0; k < x->n_local; ++k) {
            const local_prep *lp = &x->local[k];
            const hfs_local_light *L = lp->light;
            double d[3], dist, alpha;
            if (hfs_local_light_cap(L, pw, d, &dist, &alpha)) {
                /* Inside the sphere: light from every direction, nothing
                 * between: E = integral max(0, N.s) over the sphere = pi. */
                for (int ch = 0; ch < 3; ++ch) { /* glossy: ks Le, as the CPU */
                    lo[ch] += x->rho * lp->le[ch];
                    sp[ch] += r ? x->gloss.ks * lp->le[ch] : 0.0;
                }
                continue;
            }
            const double sa = L->radius / dist;
            if (n[0] * d[0] + n[1] * d[1] + n[2] * d[2] <= -sa)
                continue;
            const double omc = sa * sa / (1.0 + sqrt(fmax(0.0, 1.0 - sa * sa)));
            double t1[3], t2[3];
            frame_around(d, t1, t2);
            double lobe = 0.0;
            const double e = cap_visible_irradiance(x, o, pw, n, d, t1, t2, omc, L->pos,
                                                    L->radius * L->radius,
                                                    rng_seed(rid, lp->slot), &x->gloss, r, &lobe);
            const double scale = x->rho / PI * (2.0 * PI * omc) / ns * e;
            const double gs = x->gloss.ks * (2.0 * PI * omc) / ns * lobe;
            for (int ch = 0; ch < 3; ++ch) {
                lo[ch] += scale * lp->le[ch];
                sp[ch] += gs * lp->le[ch];
            }
        }

        float *px = x->out + 3 * rid;
        for (int ch = 0; ch < 3; ++ch) {
            double v = lo[ch];
            if (!(v == v))
                v = 0.0; /* unreachable for valid inputs; never emit NaN */
            px[ch] = (float)fmin(fmax(v, -FLT_MAX), FLT_MAX);
            if (x->spec) /* never NaN: finite sums of finite terms */
                x->spec[3 * rid + ch] = (float)fmin(fmax(sp[ch], -FLT_MAX), FLT_MAX);
        }
    }
}

/* ---- setup ------------------------------------------------------------------------ */

static int env_setup(truth_ctx *x, const hfs_lighting *l, int n_az)
{
    double rot[3][HFS_SH_N];
    int any = 0;
    for (int ch = 0; ch < 3; ++ch) {
        hfs_sh_rotate_z(l->env_sh[ch], l->env_rotate, rot[ch]);
        for (int k = 0; k < HFS_SH_N; ++k)
            any |= l->env_sh[ch][k] != 0.0;
    }
    if (!any)
        return HFS_OK; /* a black environment costs nothing */
    memcpy(x->env_rot, rot, sizeof x->env_rot);
    x->env_grey = 1;
    for (int k = 0; k < HFS_SH_N; ++k)
        x->env_grey &= l->env_sh[1][k] == l->env_sh[0][k] && l->env_sh[2][k] == l->env_sh[0][k];
    x->az = malloc((size_t)n_az * sizeof *x->az);
    if (!x->az)
        return HFS_E_NOMEM;
    x->n_az = n_az;
    /* 8 equispaced samples along the vertical great circle of each azimuth
     * determine the degree-3 trig polynomial exactly (no aliasing < 4). */
    enum { M = 8 };
    for (int a = 0; a < n_az; ++a) {
        env_azimuth *az = &x->az[a];
        const double phi = (a + 0.5) * 2.0 * PI / n_az;
        az->c = cos(phi);
        az->s = sin(phi);
        double val[3][M];
        for (int m = 0; m < M; ++m) {
            const double e = 2.0 * PI * m / M;
            double y[HFS_SH_N];
            hfs_sh_eval(az->c * cos(e), az->s * cos(e), sin(e), y);
            for (int ch = 0; ch < 3; ++ch)
                val[ch][m] = hfs_sh_dot(rot[ch], y);
        }
        for (int ch = 0; ch < 3; ++ch) {
            double *t = az->trig[ch];
            t[0] = 0.0;
            for (int m = 0; m < M; ++m)
                t[0] += val[ch][m] / M;
            for (int h = 1; h <= 3; ++h) {
                double cs = 0.0, sn = 0.0;
                for (int m = 0; m < M; ++m) {
                    const double e = 2.0 * PI * m / M;
                    cs += val[ch][m] * cos(h * e);
                    sn += val[ch][m] * sin(h * e);
                }
                t[2 * h - 1] = 2.0 * cs / M;
                t[2 * h] = 2.0 * sn / M;
            }
        }
    }
    return HFS_OK;
}

/* The caller's progress over stages: stage k of n reports [k/n, (k+1)/n]. */
typedef struct progress_span {
    hfs_progress_fn fn;
    void *user;
    double base, width;
} progress_span;

static void span_progress(void *user, double fraction)
{
    const progress_span *s = user;
    s->fn(s->user, s->base + s->width * fraction);
}

/* out (Lo_0, the albedo map applied) += Lo_1 + ... + Lo_B (truth_bounce.h):
 * each bounce gathers the one before. */
static int add_bounces(const hfs_truth_grid *g, const hfs_lighting *l, const hfs_quality *q,
                       hfs_image *out, progress_span *span, hfs_error *err)
{
    const size_t n = (size_t)out->width * (size_t)out->height * 3;
    float *prev = malloc(n * sizeof *prev), *cur = malloc(n * sizeof *cur);
    if (!prev || !cur) {
        free(prev);
        free(cur);
        return hfs_fail(err, HFS_E_NOMEM, "truth: out of memory for %d bounces", l->bounces);
    }
    memcpy(prev, out->rgb, n * sizeof *prev);
    hfs_gloss gloss;
    hfs_gloss_make(l, &gloss);
    for (int b = 1; b <= l->bounces; ++b) {
        const hfs_truth_bounce_in in = {g, prev, l->albedo, l->albedo_map,
                                        q->truth_light_samples, b, q->threads, &gloss};
        span->base = b * span->width;
        hfs_truth_bounce(&in, cur, span->fn ? span_progress : NULL, span);
        for (size_t i = 0; i < n; ++i)
            out->rgb[i] += cur[i];
        float *t = prev;
        prev = cur;
        cur = t;
    }
    free(prev);
    free(cur);
    return HFS_OK;
}

int hfs_truth_render(const hfs_field *f, const hfs_lighting *l,
                     const hfs_quality *q, hfs_image *out,
                     hfs_progress_fn progress, void *user, hfs_error *err)
{
    if (q->truth_azimuths < 1 || q->truth_elev_order < 1 || q->truth_elev_order > 64 ||
        q->truth_light_samples < 1)
        return hfs_fail(err, HFS_E_INVALID,
                        "truth: azimuths %d (>= 1), elevation order %d (1..64) or "
                        "light samples %d (>= 1) out of range",
                        q->truth_azimuths, q->truth_elev_order, q->truth_light_samples);

    truth_ctx *x = calloc(1, sizeof *x);
    if (!x)
        return hfs_fail(err, HFS_E_NOMEM, "truth: out of memory");
    x->f = f;
    x->rho = l->albedo;
    x->out = out->rgb;
    int rc = HFS_OK;
    hfs_gloss_make(l, &x->gloss);
    x->env_samples = q->truth_light_samples;
    if (x->gloss.on &&
        !(x->spec = malloc((size_t)f->width * (size_t)f->height * 3 * sizeof *x->spec))) {
        rc = hfs_fail(err, HFS_E_NOMEM, "truth: out of memory for the glossy term");
        goto done;
    }

    x->n_gl = q->truth_elev_order;
    if (hfs_gauss_legendre(x->n_gl, x->gl_x, x->gl_w) != 0) {
        rc = hfs_fail(err, HFS_E_INVALID, "truth: no Gauss-Legendre rule of order %d", x->n_gl);
        goto done;
    }
    x->n_theta = (int)floor(sqrt((double)q->truth_light_samples));
    if (x->n_theta < 1)
        x->n_theta = 1;
    x->n_psi = (q->truth_light_samples + x->n_theta - 1) / x->n_theta;

    for (int k = 0; k < l->n_key; ++k) {
        const hfs_key_light *kl = &l->key[k];
        if (kl->disabled || radiance_zero(kl->radiance) || !(kl->alpha > 0.0) ||
            (kl->from_env && l->env_map && l->has_env)) /* the map holds it */
            continue;
        key_prep *kp = &x->key[x->n_key++];
        hfs_dir(kl->phi, kl->elev, kp->d);
        frame_around(kp->d, kp->t1, kp->t2);
        const double sh = sin(0.5 * kl->alpha);
        kp->omc = 2.0 * sh * sh;
        kp->sin_a = sin(kl->alpha);
        for (int ch = 0; ch < 3; ++ch)
            kp->le[ch] = kl->radiance[ch];
        kp->slot = k;
    }
    for (int k = 0; k < l->n_local; ++k) {
        const hfs_local_light *ll = &l->local[k];
        /* radius 0: a point light has zero solid angle and contributes 0. */
        if (ll->disabled || radiance_zero(ll->radiance) || !(ll->radius > 0.0))
            continue;
        local_prep *lp = &x->local[x->n_local++];
        lp->light = ll;
        for (int ch = 0; ch < 3; ++ch)
            lp->le[ch] = ll->radiance[ch];
        lp->slot = LOCAL_SLOT0 + k;
    }
    if (l->has_env && l->env_map)
        rc = hfs_truth_envmap_make(l, q->truth_azimuths, HFS_ENVMAP_BRIGHT_K,
                                   HFS_ENVMAP_BRIGHT_MAX, &x->emap);
    else if (l->has_env)
        rc = env_setup(x, l, q->truth_azimuths);
    if (rc != HFS_OK) {
        rc = hfs_fail(err, rc, "truth: out of memory for %d azimuths", q->truth_azimuths);
        goto done;
    }

    if (x->n_az == 0 && !x->emap && x->n_key == 0 && x->n_local == 0) {
        for (size_t p = 0; p < (size_t)f->width * (size_t)f->height * 3; ++p)
            out->rgb[p] = 0.0f;
        if (progress)
            progress(user, 1.0);
        goto done;
    }
    if (hfs_truth_grid_init(&x->grid, f) != HFS_OK) {
        rc = hfs_fail(err, HFS_E_NOMEM, "truth: out of memory for the %dx%d height tree",
                      f->width, f->height);
        goto done;
    }
    progress_span span = {progress, user, 0.0, 1.0 / (1 + l->bounces)};
    hfs_parallel_rows(f->height, q->threads, truth_row, x, progress ? span_progress : NULL,
                      &span);
    hfs_albedo_map_apply(l->albedo_map, out);
    for (size_t p = 0; x->spec && p < (size_t)f->width * (size_t)f->height * 3; ++p)
        out->rgb[p] += x->spec[p]; /* after the map (not the albedo's), before bounces */
    if (l->bounces > 0)
        rc = add_bounces(&x->grid, l, q, out, &span, err);

done:
    hfs_truth_grid_free(&x->grid);
    free(x->spec);
    free(x->az);
    hfs_truth_envmap_free(x->emap);
    free(x);
    return rc;
}
