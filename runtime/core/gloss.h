/*
 * gloss.h — glossy surfaces (SPEC "Glossy", DESIGN.md "Glossy surfaces"),
 * shared by every backend (neutral names: the CPU reference, the truth and
 * the GLES path's setup; shade.frag.glsl mirrors hfs_gloss_reflect,
 * hfs_gloss_lobe and hfs_gloss_env).
 *
 * The BRDF is the energy-normalized Phong lobe about the view direction V
 * reflected at the texel's normal N, R = 2 (N.V) N - V:
 *     f_s(w) = ks (S+2)/(2 pi) max(0, R.w)^S,
 * and a glossy texel's exit radiance towards V adds
 *     Lo_s = Int L(w) V(w) f_s(w) max(0, N.w) dw
 * (with the cosine; (S+2)/(2 pi) makes Int f_s max(0, N.w) <= ks for every
 * R, equality at R = N, so albedo + ks <= 1 conserves energy).  Where N.V
 * <= 0 (R below the tangent plane) Lo_s = 0.
 *
 * Header-only (inline) so that the CPU reference, the GLES setup, the truth
 * and the unshadowed normalizer use the very same definitions.
 */
#ifndef HFS_GLOSS_H
#define HFS_GLOSS_H

#include "hfshade.h"
#include "sh.h"

#include <math.h>

typedef struct hfs_gloss {
    int on;             /* specular > 0: the glossy term exists          */
    double ks, s;       /* specular albedo, Phong exponent               */
    double view[3];     /* unit, towards the viewer                      */
    int at_eye;         /* 1: each point looks towards eye, not view      */
    double eye[3];      /* the viewer's point (world units), at_eye = 1   */
    double norm;        /* (S+2)/(2 pi)                                  */
    double zh[HFS_ZH_N];/* the lobe's convolution ZH, hfs_gloss_zh       */
} hfs_gloss;

/* g_l of the normalized lobe (S+1)/(2 pi) max(0, cos)^S: (lobe * L)(R) =
 * sum_lm g_l L_lm y_lm(R).  Exact: g_l = (S+1) Int_0^1 t^S P_l(t) dt =
 * {1, (S+1)/(S+2), S/(S+3), (S+1)(S-1)/((S+2)(S+4))}.  NS09 section 7's
 * {1, e^(-1/(2S)), e^(-2/S), e^(-9/(2S))} is its large-S limit (1.4% high
 * at l = 1, S = 32). */
static inline void hfs_gloss_zh(double s, double g[HFS_ZH_N])
{
    g[0] = 1.0;
    g[1] = (s + 1.0) / (s + 2.0);
    g[2] = s / (s + 3.0);
    g[3] = (s + 1.0) * (s - 1.0) / ((s + 2.0) * (s + 4.0));
}

static inline void hfs_gloss_make(const hfs_lighting *l, hfs_gloss *g)
{
    g->on = l->specular > 0.0;
    g->ks = l->specular;
    g->s = l->gloss;
    const double len = sqrt(l->view_dir[0] * l->view_dir[0] + l->view_dir[1] * l->view_dir[1] +
                            l->view_dir[2] * l->view_dir[2]);
    for (int k = 0; k < 3; ++k)
        g->view[k] = len > 0.0 ? l->view_dir[k] / len : (k == 2);
    g->at_eye = g->on && l->view_from_eye != 0;
    for (int k = 0; k < 3; ++k)
        g->eye[k] = g->at_eye ? l->view_eye[k] : 0.0;
    g->norm = (l->gloss + 2.0) / (2.0 * 3.14159265358979323846);
    hfs_gloss_zh(l->gloss, g->zh);
}

/* The unit direction towards the viewer from world point p (x = i dx,
 * y = j dx, z = zscale h): the view direction, or towards the eye of a
 * perspective viewer (straight up at the eye itself). */
static inline void hfs_gloss_view_at(const hfs_gloss *g, const double p[3], double v[3])
{
    if (!g->at_eye) {
        for (int k = 0; k < 3; ++k)
            v[k] = g->view[k];
        return;
    }
    const double d[3] = {g->eye[0] - p[0], g->eye[1] - p[1], g->eye[2] - p[2]};
    const double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int k = 0; k < 3; ++k)
        v[k] = len > 0.0 ? d[k] / len : (k == 2);
}

/* R = 2 (N.V) N - V for unit n at world point p (V = hfs_gloss_view_at);
 * returns N.V (= N.R), or 0 with r = N when the viewer is below the
 * tangent plane (no glossy term there). */
static inline double hfs_gloss_reflect(const hfs_gloss *g, const double p[3], const double n[3],
                                       double r[3])
{
    double v[3];
    hfs_gloss_view_at(g, p, v);
    const double nv = n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
    for (int k = 0; k < 3; ++k)
        r[k] = nv > 0.0 ? 2.0 * nv * n[k] - v[k] : n[k];
    return nv > 0.0 ? nv : 0.0;
}

/* (S+2)/(2 pi) max(0, R.d)^S: f_s / ks in direction unit d. */
static inline double hfs_gloss_lobe(const hfs_gloss *g, const double r[3], const double d[3])
{
    const double c = r[0] * d[0] + r[1] * d[1] + r[2] * d[2];
    return c > 0.0 ? g->norm * pow(c, g->s) : 0.0;
}

/* The environment's glossy term (CPU reference; shade.frag mirrors it):
 *     out_c += ks (N.R) v (L_c*lobe(R) + dmap_c),   v = clamp(T.Q / H.Q, 0, 1),
 * Q = the lobe's ZH rotated to R (Q_lm = g_l y_lm(R)), T the texel's
 * transfer (H * V_env: the slice path's exact one or the SH product), H its
 * clamped cosine, L_env per channel (already rotated).  N.R stands for the
 * cosine over the lobe: exact for a lobe above the tangent plane under a
 * constant sky (the lobe's mean direction is (S+1)/(S+2) R, and
 * (S+2)/(S+1) of it is the normalization).  v is the visible fraction of
 * the cosine-weighted lobe at order 4, the key lights' ratio form; 0 where
 * H.Q <= 1e-9 |H| |Q|.  dmap: NULL, or the map's lobe beyond order 4 at R
 * (env_gloss.h D_g; env-shade = map), so that L*lobe + dmap is the map
 * itself convolved with the lobe. */
static inline void hfs_gloss_env(const hfs_gloss *g, double n_dot_r, const double r[3],
                                 const double t[HFS_SH_N], const double hn[HFS_SH_N],
                                 const double l_env[3][HFS_SH_N], const double *dmap,
                                 double out[3])
{
    if (!(n_dot_r > 0.0))
        return;
    /* hfs_sh_rotate_zonal multiplies zh_l by sqrt(4 pi/(2l+1)): divide it
     * out so that Q_lm = g_l y_lm(R). */
    double zh[HFS_ZH_N], q[HFS_SH_N];
    for (int l = 0; l < HFS_ZH_N; ++l)
        zh[l] = g->zh[l] * sqrt((2.0 * l + 1.0) / (4.0 * 3.14159265358979323846));
    hfs_sh_rotate_zonal(zh, r[0], r[1], r[2], q);
    const double num = hfs_sh_dot(t, q), den = hfs_sh_dot(hn, q);
    double v = 0.0;
    if (den > 1e-9 * sqrt(hfs_sh_dot(hn, hn) * hfs_sh_dot(q, q)))
        v = num / den < 0.0 ? 0.0 : (num / den > 1.0 ? 1.0 : num / den);
    const double w = g->ks * n_dot_r * v;
    for (int ch = 0; ch < 3; ++ch)
        out[ch] += w * (hfs_sh_dot(l_env[ch], q) + (dmap ? dmap[ch] : 0.0));
}

#endif /* HFS_GLOSS_H */
