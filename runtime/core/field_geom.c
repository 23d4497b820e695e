/*
 * field_geom.c — see field_geom.h.
 */
#include "field_geom.h"

#include <float.h>
#include <math.h>

int hfs_field_bilinear(const hfs_field *f, double gx, double gy, double *z)
{
    const int w = f->width, h = f->height;
    if (!(gx >= 0.0 && gy >= 0.0 && gx <= (double)(w - 1) && gy <= (double)(h - 1)))
        return 0;
    int i = (int)gx, j = (int)gy;
    if (i > w - 2)
        i = w - 2;
    if (j > h - 2)
        j = h - 2;
    const double fx = gx - i, fy = gy - j;
    const double z00 = hfs_field_z(f, i, j), z10 = hfs_field_z(f, i + 1, j);
    const double z01 = hfs_field_z(f, i, j + 1), z11 = hfs_field_z(f, i + 1, j + 1);
    *z = (z00 * (1.0 - fx) + z10 * fx) * (1.0 - fy) + (z01 * (1.0 - fx) + z11 * fx) * fy;
    return 1;
}

double hfs_field_first_cell_slope(const hfs_field *f, int i, int j, double c, double s)
{
    double near, far;
    return hfs_field_first_cell(f, i, j, c, s, &near, &far);
}

double hfs_field_first_cell(const hfs_field *f, int i, int j, double c, double s, double *near_out,
                            double *far_out)
{
    *near_out = *far_out = -DBL_MAX;
    const double ac = fabs(c) < 1e-12 ? 0.0 : fabs(c), as = fabs(s) < 1e-12 ? 0.0 : fabs(s);
    const int sx = c > 0.0 ? 1 : -1, sy = s > 0.0 ? 1 : -1;
    const int x = ac > 0.0 ? i + sx : i, y = as > 0.0 ? j + sy : j;
    if (x < 0 || y < 0 || x >= f->width || y >= f->height)
        return -DBL_MAX;
    const double z0 = hfs_field_z(f, i, j);
    /* t -> 0: the cell's edges' slopes, weighted by the direction. */
    const double near = ac * (hfs_field_z(f, x, j) - z0) + as * (hfs_field_z(f, i, y) - z0);
    /* The far edge: an integer in the dominant axis, the other fraction
     * linear along that edge. */
    double zf, run;
    if (ac >= as) {
        const double fy = as / ac;
        zf = hfs_field_z(f, x, j) * (1.0 - fy) + hfs_field_z(f, x, y) * fy;
        run = 1.0 / ac;
    } else {
        const double fx = ac / as;
        zf = hfs_field_z(f, i, y) * (1.0 - fx) + hfs_field_z(f, x, y) * fx;
        run = 1.0 / as;
    }
    *near_out = near / f->dx;
    *far_out = (zf - z0) / run / f->dx;
    return fmax(near, (zf - z0) / run) / f->dx;
}

void hfs_field_normal(const hfs_field *f, int i, int j, double n[3])
{
    const int w = f->width, h = f->height;
    const int i0 = i > 0 ? i - 1 : i, i1 = i < w - 1 ? i + 1 : i;
    const int j0 = j > 0 ? j - 1 : j, j1 = j < h - 1 ? j + 1 : j;
    const double dzdx = (hfs_field_z(f, i1, j) - hfs_field_z(f, i0, j)) / ((i1 - i0) * f->dx);
    const double dzdy = (hfs_field_z(f, i, j1) - hfs_field_z(f, i, j0)) / ((j1 - j0) * f->dx);
    /* Scale before squaring so huge slopes (zscale * dH / dx near DBL_MAX)
     * give a vertical-ish normal instead of Inf/Inf = NaN. */
    const double m = fmax(1.0, fmax(fabs(dzdx), fabs(dzdy)));
    const double gx = dzdx / m, gy = dzdy / m, gz = 1.0 / m;
    const double len = sqrt(gx * gx + gy * gy + gz * gz);
    n[0] = -gx / len;
    n[1] = -gy / len;
    n[2] = gz / len;
}

void hfs_dir(double phi, double e, double s[3])
{
    const double ce = cos(e);
    s[0] = cos(phi) * ce;
    s[1] = sin(phi) * ce;
    s[2] = sin(e);
}

void hfs_horizon_dir(double phi, double *c, double *s)
{
    *c = cos(phi), *s = sin(phi);
    *c = fabs(*c) < 1e-12 ? 0.0 : *c;
    *s = fabs(*s) < 1e-12 ? 0.0 : *s;
}

void hfs_field_range(const hfs_field *f, double *lo, double *hi)
{
    /* Four running extremes instead of one: a frame's scan at 1024² was a
     * chain of a million dependent compares (issue 37, the host's part).
     * The same extremes (the heights are finite, hfs_field_validate);
     * zeros of both signs may come out as either. */
    const size_t n = (size_t)f->width * (size_t)f->height;
    const float *z = f->z;
    float a[4] = {z[0], z[0], z[0], z[0]}, b[4] = {z[0], z[0], z[0], z[0]};
    size_t i = 0;
    for (; i + 4 <= n; i += 4)
        for (int k = 0; k < 4; ++k) {
            a[k] = z[i + (size_t)k] < a[k] ? z[i + (size_t)k] : a[k];
            b[k] = z[i + (size_t)k] > b[k] ? z[i + (size_t)k] : b[k];
        }
    for (; i < n; ++i) {
        a[0] = z[i] < a[0] ? z[i] : a[0];
        b[0] = z[i] > b[0] ? z[i] : b[0];
    }
    for (int k = 1; k < 4; ++k) {
        a[0] = a[k] < a[0] ? a[k] : a[0];
        b[0] = b[k] > b[0] ? b[k] : b[0];
    }
    *lo = a[0];
    *hi = b[0];
}

void hfs_rgb_bilinear(const float *rgb, int w, int h, double gx, double gy, double out[3])
{
    gx = fmin(fmax(gx, 0.0), w - 1.0);
    gy = fmin(fmax(gy, 0.0), h - 1.0);
    int i = (int)gx, j = (int)gy;
    i = i > w - 2 ? w - 2 : i;
    j = j > h - 2 ? h - 2 : j;
    const double fx = gx - i, fy = gy - j;
    const float *p00 = rgb + 3 * ((size_t)j * (size_t)w + (size_t)i), *p01 = p00 + 3 * (size_t)w;
    for (int c = 0; c < 3; ++c)
        out[c] = (p00[c] * (1.0 - fx) + p00[3 + c] * fx) * (1.0 - fy) +
                 (p01[c] * (1.0 - fx) + p01[3 + c] * fx) * fy;
}
