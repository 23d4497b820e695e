/*
 * env_map_slices.c — an environment map integrated along the azimuth
 * slices (env_map_slices.h).
 */
#include "env_map_slices.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

void hfs_map_slices_free(hfs_map_slices *ms)
{
    if (!ms)
        return;
    free(ms->dir);
    free(ms->fg);
    memset(ms, 0, sizeof *ms);
}

/* Row y's elevations: top pi/2 - pi y / h (SPEC equirect). */
static double row_top(int y, int h)
{
    return 0.5 * PI - PI * y / h;
}

/* The wedge [u0, u1) in map columns (u0 may be negative or u1 beyond w:
 * the seam wraps), per row: sum of L times the covered part of each column,
 * divided by the width. */
static void wedge_means(const float *rgb, int w, int h, double u0, double u1, double *l)
{
    const double width = u1 - u0;
    for (int y = 0; y < h; ++y) {
        double s[3] = {0.0, 0.0, 0.0};
        const float *row = rgb + (size_t)y * (size_t)w * 3;
        for (long x = (long)floor(u0); x < u1; ++x) {
            const double lo = fmax(u0, (double)x), hi = fmin(u1, x + 1.0);
            if (!(hi > lo))
                continue;
            long xm = x % w;
            xm = xm < 0 ? xm + w : xm;
            for (int c = 0; c < 3; ++c)
                s[c] += (hi - lo) * row[3 * xm + c];
        }
        for (int c = 0; c < 3; ++c)
            l[3 * y + c] = s[c] / width;
    }
}

/* One slice's exact F, G at the rows' tops (fg: (h + 1) x 6) from the
 * wedge's mean radiance per row l (h x 3). */
static void exact_rows(const double *l, int h, double *fg)
{
    for (int c = 0; c < 6; ++c)
        fg[c] = 0.0;
    for (int y = 0; y < h; ++y) {
        const double e0 = row_top(y, h), e1 = row_top(y + 1, h);
        const double ic = 0.5 * (e0 - e1) + 0.25 * (sin(2.0 * e0) - sin(2.0 * e1));
        const double is = 0.5 * (sin(e0) * sin(e0) - sin(e1) * sin(e1));
        for (int c = 0; c < 3; ++c) {
            fg[6 * (y + 1) + c] = fg[6 * y + c] + l[3 * y + c] * ic;
            fg[6 * (y + 1) + 3 + c] = fg[6 * y + 3 + c] + l[3 * y + c] * is;
        }
    }
}

/* F, G at elevation x: from the top of x's row plus the row's radiance
 * over [x, the row's top], in closed form. */
static void exact_at(const double *l, const double *fg, int h, double x, double out[6])
{
    int y = (int)floor((0.5 * PI - x) / PI * h);
    y = y < 0 ? 0 : (y >= h ? h - 1 : y);
    const double e0 = row_top(y, h);
    const double ic = 0.5 * (e0 - x) + 0.25 * (sin(2.0 * e0) - sin(2.0 * x));
    const double is = 0.5 * (sin(e0) * sin(e0) - sin(x) * sin(x));
    for (int c = 0; c < 3; ++c) {
        out[c] = fg[6 * y + c] + l[3 * y + c] * ic;
        out[3 + c] = fg[6 * y + 3 + c] + l[3 * y + c] * is;
    }
}

int hfs_map_slices_build(hfs_map_slices *ms, const float *rgb, int w, int h, double rotate,
                         const double *dir, int n, double dphi, hfs_error *err)
{
    memset(ms, 0, sizeof *ms);
    ms->n = n;
    ms->dphi = dphi;
    ms->dir = malloc((size_t)n * 2 * sizeof *ms->dir);
    ms->fg = malloc((size_t)n * HFS_MAP_SLICE_E * 6 * sizeof *ms->fg);
    double *l = malloc((size_t)h * 3 * sizeof *l);
    double *rows = malloc((size_t)(h + 1) * 6 * sizeof *rows);
    if (!ms->dir || !ms->fg || !l || !rows) {
        free(l);
        free(rows);
        hfs_map_slices_free(ms);
        return hfs_fail(err, HFS_E_NOMEM, "environment map: out of memory for its slices");
    }
    memcpy(ms->dir, dir, (size_t)n * 2 * sizeof *dir);
    for (int j = 0; j < n; ++j) {
        /* The slice's azimuth in the map's frame, in columns. */
        const double phi = atan2(dir[2 * j + 1], dir[2 * j]) - rotate;
        const double uc = phi / (2.0 * PI) * w, half = dphi / (2.0 * PI) * w * 0.5;
        wedge_means(rgb, w, h, uc - half, uc + half, l);
        exact_rows(l, h, rows);
        double *fg = ms->fg + (size_t)j * HFS_MAP_SLICE_E * 6;
        for (int i = 0; i < HFS_MAP_SLICE_E; ++i)
            exact_at(l, rows, h, -0.5 * PI + PI * i / (HFS_MAP_SLICE_E - 1), fg + 6 * i);
    }
    free(l);
    free(rows);
    return HFS_OK;
}

/* S_j(x) per channel: a F(x) + b G(x), F and G linear between samples. */
static void slice_s(const hfs_map_slices *ms, int j, double a, double b, double x, double s[3])
{
    double f = (x + 0.5 * PI) / PI * (HFS_MAP_SLICE_E - 1);
    f = f < 0.0 ? 0.0 : (f > HFS_MAP_SLICE_E - 1 ? HFS_MAP_SLICE_E - 1 : f);
    int i = (int)f;
    i = i >= HFS_MAP_SLICE_E - 1 ? HFS_MAP_SLICE_E - 2 : i;
    const double t = f - i;
    const double *p = ms->fg + ((size_t)j * HFS_MAP_SLICE_E + i) * 6;
    for (int c = 0; c < 3; ++c)
        s[c] = a * ((1.0 - t) * p[c] + t * p[6 + c]) + b * ((1.0 - t) * p[3 + c] + t * p[9 + c]);
}

void hfs_map_slices_occluded(const hfs_map_slices *ms, int j, const double n[3], double x,
                             double e[3])
{
    const double a = n[0] * ms->dir[2 * j] + n[1] * ms->dir[2 * j + 1], b = n[2];
    const double fl = atan2(-a, b);
    if (!(x > fl))
        return;
    double sx[3], sf[3];
    slice_s(ms, j, a, b, x, sx);
    slice_s(ms, j, a, b, fl, sf);
    for (int c = 0; c < 3; ++c)
        e[c] += ms->dphi * (sx[c] - sf[c]);
}

void hfs_map_slices_occluded_mean(const hfs_map_slices *ms, int j, const double n[3],
                                  const double *x, int nx, double e[3])
{
    double sum[3] = {0.0, 0.0, 0.0};
    for (int h = 0; h < nx; ++h)
        hfs_map_slices_occluded(ms, j, n, x[h], sum);
    for (int c = 0; c < 3; ++c)
        e[c] += sum[c] / nx;
}
