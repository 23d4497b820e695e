/*
 * gloss.c — the environment's glossy term (gloss.h, DESIGN.md "Glossy
 * surfaces"), shared by the CPU reference; shade.frag.glsl (HFS_GLOSSY)
 * computes the same expression in float.
 */
#include "gloss.h"

void hfs_gloss_env(const hfs_gloss *g, double n_dot_r, const double r[3],
                   const double t[HFS_SH_N], const double hn[HFS_SH_N],
                   const double l_env[3][HFS_SH_N], double out[3])
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
        out[ch] += w * hfs_sh_dot(l_env[ch], q);
}
