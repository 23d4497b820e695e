/*
 * unshadowed.c — exact Lo with V = 1 everywhere: the normalizer of SPEC.md's
 * error metrics, and the "no terrain" limit every backend must reach.
 *
 *   environment: rho/pi * sum_k H_k(N) L_k per channel, H = the clamped-cosine
 *                ZH rotated to N.  Exact: L is band-limited to order 4, so
 *                only H's first 16 coefficients meet it.
 *   key light:   rho/pi * Le * E_cap(N.d, alpha)      (lights.c, closed form)
 *   local light: the same with the cap seen from the lifted receiver; inside
 *                the sphere E = pi; radius 0 (a point) contributes 0.
 * Cheap (a few hundred flops per texel), so single-threaded.
 */
#include "albedo.h"
#include "gloss.h"
#include "backends.h"
#include "field_geom.h"
#include "lights.h"
#include "sh.h"

#include <float.h>
#include <math.h>

#define PI 3.14159265358979323846

/* The glossy term of texel (i, j) with V = 1 (gloss.h): the environment's
 * ks (N.R) L*lobe(R) (visible fraction 1), each light's lobe at its centre
 * times E_cap, ks Le inside a local light: the backends' own expressions. */
static void gloss_unshadowed(const hfs_field *f, const hfs_lighting *l, const hfs_gloss *g,
                             const double env[3][HFS_SH_N], int has_env, int i, int j,
                             double sp[3])
{
    double n[3], r[3];
    hfs_field_normal(f, i, j, n);
    const double pw[3] = {i * f->dx, j * f->dx, hfs_field_lifted_z(f, i, j)};
    const double nr = hfs_gloss_reflect(g, pw, n, r);
    if (!(nr > 0.0))
        return;
    if (has_env) {
        double zh[HFS_ZH_N], h[HFS_SH_N];
        hfs_zh_clamped_cosine(zh);
        hfs_sh_rotate_zonal(zh, n[0], n[1], n[2], h);
        hfs_gloss_env(g, nr, r, h, h, env, NULL, sp);
    }
    for (int k = 0; k < l->n_key; ++k) {
        const hfs_key_light *kl = &l->key[k];
        double d[3];
        hfs_dir(kl->phi, kl->elev, d);
        const double w = kl->disabled ? 0.0 : g->ks * hfs_gloss_lobe(g, r, d) *
            hfs_cap_irradiance(n[0] * d[0] + n[1] * d[1] + n[2] * d[2], kl->alpha);
        for (int ch = 0; ch < 3; ++ch)
            sp[ch] += w * kl->radiance[ch];
    }
    for (int k = 0; k < l->n_local; ++k) {
        const hfs_local_light *ll = &l->local[k];
        if (ll->disabled || !(ll->radius > 0.0))
            continue;
        double d[3], dist, alpha;
        const int inside = hfs_local_light_cap(ll, pw, d, &dist, &alpha);
        const double w = inside ? g->ks : g->ks * hfs_gloss_lobe(g, r, d) *
            hfs_cap_irradiance(n[0] * d[0] + n[1] * d[1] + n[2] * d[2], alpha);
        for (int ch = 0; ch < 3; ++ch)
            sp[ch] += w * ll->radiance[ch];
    }
}

int hfs_unshadowed_render(const hfs_field *f, const hfs_lighting *l,
                          const hfs_quality *q, hfs_image *out, hfs_error *err)
{
    (void)q;
    (void)err;
    const double rho = l->albedo;
    double env[3][HFS_SH_N];
    int has_env = 0;
    if (l->has_env) {
        for (int ch = 0; ch < 3; ++ch) {
            hfs_sh_rotate_z(l->env_sh[ch], l->env_rotate, env[ch]);
            for (int k = 0; k < HFS_SH_N; ++k)
                has_env |= l->env_sh[ch][k] != 0.0;
        }
    }
    double zh[HFS_ZH_N];
    hfs_zh_clamped_cosine(zh);

    for (int j = 0; j < f->height; ++j) {
        for (int i = 0; i < f->width; ++i) {
            double n[3];
            hfs_field_normal(f, i, j, n);
            const double pw[3] = {i * f->dx, j * f->dx, hfs_field_lifted_z(f, i, j)};
            double lo[3] = {0.0, 0.0, 0.0};
            if (has_env) {
                double h[HFS_SH_N];
                hfs_sh_rotate_zonal(zh, n[0], n[1], n[2], h);
                for (int ch = 0; ch < 3; ++ch)
                    lo[ch] += rho / PI * hfs_sh_dot(h, env[ch]);
            }
            for (int k = 0; k < l->n_key; ++k) {
                const hfs_key_light *kl = &l->key[k];
                if (kl->disabled)
                    continue;
                double d[3];
                hfs_dir(kl->phi, kl->elev, d);
                const double e = hfs_cap_irradiance(n[0] * d[0] + n[1] * d[1] + n[2] * d[2],
                                                    kl->alpha);
                for (int ch = 0; ch < 3; ++ch)
                    lo[ch] += rho / PI * kl->radiance[ch] * e;
            }
            for (int k = 0; k < l->n_local; ++k) {
                const hfs_local_light *ll = &l->local[k];
                if (ll->disabled || !(ll->radius > 0.0))
                    continue;
                double d[3], dist, alpha;
                hfs_local_light_cap(ll, pw, d, &dist, &alpha);
                const double e = hfs_cap_irradiance(n[0] * d[0] + n[1] * d[1] + n[2] * d[2],
                                                    alpha);
                for (int ch = 0; ch < 3; ++ch)
                    lo[ch] += rho / PI * ll->radiance[ch] * e;
            }
            float *px = out->rgb + 3 * ((size_t)j * (size_t)f->width + (size_t)i);
            for (int ch = 0; ch < 3; ++ch) {
                double v = lo[ch];
                if (!(v == v))
                    v = 0.0; /* unreachable for valid inputs; never emit NaN */
                px[ch] = (float)fmin(fmax(v, -FLT_MAX), FLT_MAX);
            }
        }
    }
    hfs_albedo_map_apply(l->albedo_map, out);
    hfs_gloss g;
    hfs_gloss_make(l, &g);
    for (int j = 0; j < f->height && g.on; ++j) /* after the map: not the albedo's */
        for (int i = 0; i < f->width; ++i) {
            double sp[3] = {0.0, 0.0, 0.0};
            gloss_unshadowed(f, l, &g, (const double(*)[HFS_SH_N])env, has_env, i, j, sp);
            float *px = out->rgb + 3 * ((size_t)j * (size_t)f->width + (size_t)i);
            for (int ch = 0; ch < 3; ++ch)
                px[ch] = (float)fmin(fmax(px[ch] + sp[ch], -FLT_MAX), FLT_MAX);
        }
    return HFS_OK;
}
