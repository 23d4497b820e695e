/*
 * lights.c — see lights.h.
 */
#include "lights.h"

#include <math.h>

int hfs_local_light_contributes(const hfs_local_light *l)
{
    if (l->disabled || !(l->radius > 0.0))
        return 0;
    return l->radiance[0] > 0.0f || l->radiance[1] > 0.0f || l->radiance[2] > 0.0f;
}

int hfs_env_contributes(const hfs_lighting *l)
{
    int on = 0;
    if (l->has_env)
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < HFS_SH_COEFFS; ++k)
                on |= l->env_sh[c][k] != 0.0;
    return on;
}

int hfs_bounce_capped(const hfs_lighting *l, const hfs_quality *q)
{
    return hfs_env_contributes(l) && q->visibility == HFS_VIS_SLICE;
}

int hfs_bounce_dirs(const hfs_quality *q)
{
    int n = q->nphi_bounce < q->nphi_env ? q->nphi_bounce : q->nphi_env;
    while (n > 1 && q->nphi_env % n)
        --n;
    return n > 0 ? n : 1;
}

double hfs_key_vis_alpha(double alpha)
{
    return alpha > HFS_MIN_VIS_ALPHA ? alpha : HFS_MIN_VIS_ALPHA;
}

double hfs_cap_irradiance(double cos_beta, double alpha)
{
    const double pi = 3.14159265358979323846;
    if (cos_beta > 1.0)
        cos_beta = 1.0;
    if (cos_beta < -1.0)
        cos_beta = -1.0;
    if (alpha <= 0.0)
        return 0.0;
    if (alpha >= pi)
        return pi;
    const double beta = acos(cos_beta);
    if (alpha > pi / 2) {
        /* A cap larger than a hemisphere: the whole upper hemisphere (pi)
         * minus the complementary cap (half-angle pi - alpha, axis -d),
         * which is itself at most a hemisphere. */
        return pi - hfs_cap_irradiance(-cos_beta, pi - alpha);
    }
    const double s = sin(alpha), s2 = s * s;
    if (beta + alpha <= pi / 2)
        return pi * s2 * cos_beta;          /* cap fully above the plane */
    if (beta - alpha >= pi / 2)
        return 0.0;                         /* cap fully below the plane */
    /* Straddling the tangent plane (Snyder 1996): with x = cot(alpha),
     *   E = (cos_beta acos(y) - x q) s2 + atan2(q, x).
     * For a small cap the last two terms are ~alpha each and E ~alpha^3:
     * written so, a 2-degree disk at the horizon keeps 1/500 of the
     * arithmetic's precision (3e-5 relative in the GLES path's float), and
     * a 1e-8 rad one none (0 in double: tools/hfstress key_grazing_1e-8).
     * With t = q tan(alpha), atan2(q, x) - x q s2 = (atan(t) - t) + t s2,
     * and atan(t) - t = -t^3 (1/3 - t^2/5 + t^4/7 - ...) is summed as a
     * series below t = 1/4: no term cancels.  Above it the textbook form
     * is as good. */
    const double sin_beta = sin(beta);
    const double x = cos(alpha) / s;
    double y = -x * cos_beta / sin_beta;
    if (y > 1.0)
        y = 1.0;
    if (y < -1.0)
        y = -1.0;
    const double q = sin_beta * sqrt(1.0 - y * y);
    const double t = q * s / cos(alpha); /* q tan(alpha) */
    double e;
    if (t < 0.25) {
        const double u = t * t;
        double sum = 0.0, term = 1.0;
        for (int k = 0; k < 14; ++k) { /* u^14 < 2^-56 */
            sum += (k % 2 ? -term : term) / (2 * k + 3);
            term *= u;
        }
        e = -t * u * sum + t * s2 + s2 * cos_beta * acos(y);
    } else {
        /* alpha >= 0.24: the terms are O(1) like E itself (and tan(alpha)
         * would overflow the rewritten form as alpha -> pi/2). */
        e = (cos_beta * acos(y) - x * q) * s2 + atan2(q, x);
    }
    return e > 0.0 ? e : 0.0;
}

int hfs_local_light_cap(const hfs_local_light *l, const double p[3],
                        double dir[3], double *dist, double *alpha)
{
    const double pi = 3.14159265358979323846;
    const double v[3] = {l->pos[0] - p[0], l->pos[1] - p[1], l->pos[2] - p[2]};
    const double d = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    *dist = d;
    if (d > 0.0) {
        dir[0] = v[0] / d;
        dir[1] = v[1] / d;
        dir[2] = v[2] / d;
    } else {
        dir[0] = 0.0;
        dir[1] = 0.0;
        dir[2] = 1.0;
    }
    if (!(l->radius > 0.0)) {
        *alpha = 0.0; /* a point light: zero solid angle, never "inside" */
        return 0;
    }
    if (d <= l->radius) {
        *alpha = pi;
        return 1;
    }
    *alpha = asin(l->radius / d);
    return 0;
}

int hfs_key_light_contributes(const hfs_key_light *k, double albedo)
{
    if (k->disabled || !(k->radiance[0] > 0.0f || k->radiance[1] > 0.0f || k->radiance[2] > 0.0f))
        return 0;
    const double le = fmax(k->radiance[0], fmax(k->radiance[1], k->radiance[2]));
    return albedo / 3.14159265358979323846 * le * hfs_cap_irradiance(1.0, k->alpha) > 0.0;
}

void hfs_field_extent_make(const hfs_field *f, hfs_field_extent *e)
{
    const size_t w = (size_t)f->width, h = (size_t)f->height;
    double top = -INFINITY, dzx = 0.0, dzy = 0.0;
    for (size_t j = 0; j < h; ++j) {
        const float *row = f->z + j * w;
        for (size_t i = 0; i < w; ++i) {
            const double z = row[i];
            top = z > top ? z : top;
            if (i + 1 < w)
                dzx = fmax(dzx, fabs((double)row[i + 1] - z));
            if (j + 1 < h)
                dzy = fmax(dzy, fabs((double)row[i + w] - z));
        }
    }
    e->z_top = f->zscale * top;
    e->slope = f->zscale * hypot(dzx, dzy) / f->dx;
    e->x_max = (double)(w - 1) * f->dx;
    e->y_max = (double)(h - 1) * f->dx;
}

int hfs_local_light_open(const hfs_field_extent *e, const hfs_local_light *l)
{
    const double rise = l->pos[2] - l->radius - e->z_top;
    if (!(rise > 0.0))
        return 0;
    /* Farthest receiver: a corner of the field. */
    const double fx = fmax(fabs(l->pos[0]), fabs(l->pos[0] - e->x_max));
    const double fy = fmax(fabs(l->pos[1]), fabs(l->pos[1] - e->y_max));
    const double reach = hypot(fx, fy) + l->radius;
    return rise > e->slope * reach;
}
