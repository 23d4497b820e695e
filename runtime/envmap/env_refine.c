/*
 * env_refine.c — a light candidate refined on the full-resolution texels
 * around it, and its extraction (env_decompose.h "Energy").
 *
 * Refinement (4 rounds): with the current direction d and radius alpha,
 * one pass over the texels within r_out of d sums, for the inner cap
 * (angle < r_in = 1.5 alpha + 1 texel) and the surround ring [r_in, r_out),
 * the solid angle, the luminance energy, and the solid-angle and energy
 * weighted directions.  The surround's mean luminance
 * bg makes the excess Y - bg linear in the sums, so one pass gives the
 * excess energy X, its centroid (the new d) and its second moment
 * m = mean(1 - cos angle) about the centroid, 1 - |centroid| / X; a
 * uniform cap of radius a has m = (1 - cos a)/2, so alpha = acos(1 - 2 m).  Unclamped excess keeps noise unbiased.
 *
 * Extraction: removal radius alpha + 0.75 texel (the centres of partly
 * covered texels), fill F = mean RGB of the ring [r_rm, r_rm + max(2
 * texels, r_rm / 2)), light energy R - A F per channel (F lowered for a
 * channel where it would go negative), written back as float.
 */
#include "env_internal.h"

#include <math.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

typedef struct cap_sums {
    double a, y, dir_a[3], dir_y[3];             /* inner cap            */
    double rgb[3];                               /* inner cap, L dOmega  */
    double ra, ry, rrgb[3];                      /* surround ring        */
} cap_sums;

double envr_texel_size(const env_ctx *c, double e)
{
    const double v = M_PI / c->h, u = 2.0 * M_PI / c->w * cos(e);
    return v > u ? v : u;
}

void env_dir_to_angles(const double d[3], double *phi, double *elev)
{
    double p = atan2(d[1], d[0]);
    if (p < 0.0)
        p += 2.0 * M_PI;
    *phi = p;
    *elev = asin(fmax(-1.0, fmin(1.0, d[2])));
}

/* cos of the angle between texel (i, j) and d: one expression for the scan
 * and the fill, so both take exactly the same texels. */
static inline double texel_cos(const env_ctx *c, int i, int j, const double d[3])
{
    const double ce = c->row_cos[j];
    return ce * c->col_cos[i] * d[0] + ce * c->col_sin[i] * d[1] + c->row_sin[j] * d[2];
}

/* Columns [*i0, *i0 + *n) of row j that may lie within angle r of d (a
 * superset: the widest azimuth over the row's band, plus one texel). */
static void row_span(const env_ctx *c, const double d[3], double r, int j, int *i0, int *n)
{
    const double ed = asin(fmax(-1.0, fmin(1.0, d[2])));
    const double cd = cos(ed), sd = sin(ed), cr = cos(r);
    const double e_edge[3] = {0.5 * M_PI - M_PI * j / c->h,
                              0.5 * M_PI - M_PI * (j + 0.5) / c->h,
                              0.5 * M_PI - M_PI * (j + 1.0) / c->h};
    double half = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double ce = cos(e_edge[k]), den = ce * cd;
        if (den < 1e-12) {
            half = M_PI;
            break;
        }
        const double q = (cr - sin(e_edge[k]) * sd) / den;
        const double hk = q <= -1.0 ? M_PI : q >= 1.0 ? 0.0 : acos(q);
        half = fmax(half, hk);
    }
    /* Nearest latitude of the cap to the band lies inside it: widest there. */
    if ((e_edge[2] <= ed && ed <= e_edge[0]) && r >= M_PI / c->h)
        half = fmax(half, asin(fmin(1.0, sin(r) / fmax(cd, 1e-12))));
    half += 2.0 * M_PI / c->w;
    if (half >= M_PI) {
        *i0 = 0;
        *n = c->w;
        return;
    }
    double phid = atan2(d[1], d[0]);
    const double u0 = (phid - half) / (2.0 * M_PI) * c->w - 0.5;
    *i0 = (int)floor(u0);
    *n = (int)ceil((phid + half) / (2.0 * M_PI) * c->w - 0.5) - *i0 + 1;
    if (*n > c->w)
        *n = c->w;
}

/* Row range that may lie within angle r of d. */
static void row_range(const env_ctx *c, const double d[3], double r, int *j0, int *j1)
{
    const double ed = asin(fmax(-1.0, fmin(1.0, d[2])));
    const double top = ed + r, bot = ed - r;
    *j0 = top >= 0.5 * M_PI ? 0 : (int)floor((0.5 * M_PI - top) / M_PI * c->h);
    *j1 = bot <= -0.5 * M_PI ? c->h : (int)ceil((0.5 * M_PI - bot) / M_PI * c->h);
    if (*j0 < 0)
        *j0 = 0;
    if (*j1 > c->h)
        *j1 = c->h;
}

/* Sums over the cap (angle < r_in) and the ring [r_in, r_out) about d. */
static void cap_scan(const env_ctx *c, const double d[3], double r_in, double r_out, cap_sums *s)
{
    const double ci = cos(r_in), co = cos(r_out);
    int j0, j1;
    memset(s, 0, sizeof *s);
    row_range(c, d, r_out, &j0, &j1);
    for (int j = j0; j < j1; ++j) {
        int i0, n;
        row_span(c, d, r_out, j, &i0, &n);
        const double dom = c->row_domega[j], se = c->row_sin[j], ce = c->row_cos[j];
        for (int k = 0; k < n; ++k) {
            const int i = ((i0 + k) % c->w + c->w) % c->w;
            const double v[3] = {ce * c->col_cos[i], ce * c->col_sin[i], se};
            const double ct = texel_cos(c, i, j, d);
            if (ct <= co)
                continue;
            const float *p = c->rgb + ((size_t)j * c->w + i) * 3;
            const double yd = env_lum(p[0], p[1], p[2]) * dom;
            if (ct > ci) {
                s->a += dom;
                s->y += yd;
                for (int q = 0; q < 3; ++q) {
                    s->dir_a[q] += dom * v[q];
                    s->dir_y[q] += yd * v[q];
                    s->rgb[q] += p[q] * dom;
                }
            } else {
                s->ra += dom;
                s->ry += yd;
                for (int q = 0; q < 3; ++q)
                    s->rrgb[q] += p[q] * dom;
            }
        }
    }
}

/* Refines seed into (d, alpha); 0 if the excess vanishes. */
static int refine(const env_ctx *c, const env_seed *seed, double d[3], double *alpha)
{
    double a = seed->r0;
    memcpy(d, seed->d, 3 * sizeof *d);
    for (int round = 0; round < 4; ++round) {
        const double px = envr_texel_size(c, asin(fmax(-1.0, fmin(1.0, d[2]))));
        const double r_in = fmin(1.5 * a + px, 0.75 * M_PI);
        const double r_out = fmin(r_in + fmax(2.0 * px, 0.5 * r_in), M_PI);
        cap_sums s;
        cap_scan(c, d, r_in, r_out, &s);
        const double bg = s.ra > 0.0 ? s.ry / s.ra : 0.0;
        const double x = s.y - bg * s.a;
        if (!(x > 0.0))
            return 0;
        double v[3], len = 0.0;
        for (int q = 0; q < 3; ++q) {
            v[q] = s.dir_y[q] - bg * s.dir_a[q];
            len += v[q] * v[q];
        }
        len = sqrt(len);
        if (!(len > 0.0))
            return 0;
        /* Mean of 1 - cos(angle) about the centroid itself. */
        const double m_c = fmax(0.0, 1.0 - len / x);
        for (int q = 0; q < 3; ++q)
            d[q] = v[q] / len;
        a = acos(fmax(-1.0, 1.0 - 2.0 * m_c));
        a = fmax(a, 0.25 * px);
    }
    *alpha = fmin(a, 89.0 * M_PI / 180.0);
    return 1;
}

/* Writes fill over the cap (angle < r) about d, updating level 0. */
static void fill_cap(env_ctx *c, const double d[3], double r, const float fill[3])
{
    const double cr = cos(r);
    const double yf = env_lum(fill[0], fill[1], fill[2]);
    int j0, j1;
    row_range(c, d, r, &j0, &j1);
    for (int j = j0; j < j1; ++j) {
        int i0, n;
        row_span(c, d, r, j, &i0, &n);
        for (int k = 0; k < n; ++k) {
            const int i = ((i0 + k) % c->w + c->w) % c->w;
            const double ct = texel_cos(c, i, j, d);
            if (ct <= cr)
                continue;
            float *p = c->rgb + ((size_t)j * c->w + i) * 3;
            envc_add(c, i, j, (yf - env_lum(p[0], p[1], p[2])) * c->row_domega[j]);
            memcpy(p, fill, 3 * sizeof *p);
        }
    }
}

int envr_extract(env_ctx *c, const env_seed *seed, double min_share, hfs_env_light *out)
{
    double d[3], alpha;
    if (!(c->total_lum > 0.0) || !refine(c, seed, d, &alpha))
        return 0;
    if (c->opts.max_radius > 0.0 && alpha > c->opts.max_radius)
        return 0; /* broad: left to the residual (hfs_env_decompose_opts) */
    const double px = envr_texel_size(c, asin(fmax(-1.0, fmin(1.0, d[2]))));
    /* Within pi: a cap or ring past the antipode would wrap its cosines. */
    const double r_rm = fmin(alpha + 0.75 * px, 0.75 * M_PI);
    const double r_ring = fmin(r_rm + fmax(2.0 * px, 0.5 * r_rm), M_PI);
    cap_sums s;
    cap_scan(c, d, r_rm, r_ring, &s);
    if (!(s.a > 0.0))
        return 0;
    float fill[3];
    double e[3];
    for (int q = 0; q < 3; ++q) {
        double f = s.ra > 0.0 ? s.rrgb[q] / s.ra : 0.0;
        if (f * s.a > s.rgb[q])
            f = s.rgb[q] / s.a;
        fill[q] = (float)f;
        /* The energy the stored fill leaves, exactly as written. */
        e[q] = s.rgb[q] - (double)fill[q] * s.a;
        if (e[q] < 0.0) { /* float rounding of f above R / A */
            fill[q] = nextafterf(fill[q], 0.0f);
            e[q] = s.rgb[q] - (double)fill[q] * s.a;
        }
    }
    const double lum = env_lum(e[0], e[1], e[2]);
    if (!(lum > 0.0) || lum < min_share * c->total_lum)
        return 0;
    fill_cap(c, d, r_rm, fill);
    const double omega = 2.0 * M_PI * (1.0 - cos(alpha));
    memset(out, 0, sizeof *out);
    env_dir_to_angles(d, &out->phi, &out->elev);
    out->alpha = alpha;
    for (int q = 0; q < 3; ++q) {
        out->radiance[q] = (float)(e[q] / omega);
        out->energy[q] = (double)out->radiance[q] * omega;
    }
    out->share = env_lum(out->energy[0], out->energy[1], out->energy[2]) / c->total_lum;
    return 1;
}
