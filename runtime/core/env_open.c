/*
 * env_open.c — an environment map's open-sky irradiance beyond order 4
 * (env_open.h).
 */
#include "env_open.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sh.h"

#define PI 3.14159265358979323846
#define CELLS_W 128
#define CELLS_H 64

/* A cell of the map: its energy's vector moment per channel,
 * sum_p L_p Int_p w dw, and its geometric direction (the moment of 1). */
typedef struct cell {
    double m[3][3];
    double dir[3];
} cell;

/* Node (i, j)'s direction (env_open.h). */
static void node_dir(int i, int j, double n[3])
{
    const double u = -1.0 + 2.0 * i / (HFS_ENV_OPEN_N - 1);
    const double v = -1.0 + 2.0 * j / (HFS_ENV_OPEN_N - 1);
    const double r = sqrt(u * u + v * v);
    const double th = 0.5 * PI * (r < 1.0 ? r : 1.0);
    const double s = r > 0.0 ? sin(th) / r : 0.0;
    n[0] = s * u;
    n[1] = s * v;
    n[2] = cos(th);
}

/* Gathers the map's pixel moments into cells.  A pixel of azimuths
 * [p0, p1] and elevations [e1, e0] has Int w dw = (A (sin p1 - sin p0),
 * A (cos p0 - cos p1), B (p1 - p0)) with A = Int cos^2 e de and
 * B = Int sin e cos e de over the row: exact. */
static int gather_cells(const float *rgb, int w, int h, cell *cells, int cw, int ch)
{
    double *col = malloc((size_t)w * 3 * sizeof *col);
    if (!col)
        return HFS_E_NOMEM;
    for (int x = 0; x < w; ++x) {
        const double p0 = 2.0 * PI * x / w, p1 = 2.0 * PI * (x + 1.0) / w;
        col[3 * x] = sin(p1) - sin(p0);
        col[3 * x + 1] = cos(p0) - cos(p1);
        col[3 * x + 2] = p1 - p0;
    }
    for (int y = 0; y < h; ++y) {
        const double e0 = 0.5 * PI - PI * y / h, e1 = 0.5 * PI - PI * (y + 1.0) / h;
        const double A = 0.5 * (e0 - e1) + 0.25 * (sin(2.0 * e0) - sin(2.0 * e1));
        const double B = 0.5 * (sin(e0) * sin(e0) - sin(e1) * sin(e1));
        cell *row = cells + (size_t)((long)y * ch / h) * cw;
        const float *px = rgb + (size_t)y * (size_t)w * 3;
        for (int x = 0; x < w; ++x) {
            cell *c = row + (long)x * cw / w;
            const double m[3] = {A * col[3 * x], A * col[3 * x + 1], B * col[3 * x + 2]};
            for (int k = 0; k < 3; ++k) {
                c->dir[k] += m[k];
                for (int ch3 = 0; ch3 < 3; ++ch3)
                    c->m[ch3][k] += (double)px[3 * x + ch3] * m[k];
            }
        }
    }
    free(col);
    return HFS_OK;
}

int hfs_env_open_build(const float *rgb, int w, int h, const double sh[3][HFS_SH_COEFFS],
                       float *table, hfs_error *err)
{
    if (!rgb || w < 1 || h < 1)
        return hfs_fail(err, HFS_E_INVALID, "environment map: size %dx%d (needs 1x1 or more)",
                        w, h);
    const int cw = w < CELLS_W ? w : CELLS_W, ch = h < CELLS_H ? h : CELLS_H;
    cell *cells = calloc((size_t)cw * (size_t)ch, sizeof *cells);
    if (!cells || gather_cells(rgb, w, h, cells, cw, ch)) {
        free(cells);
        return hfs_fail(err, HFS_E_NOMEM, "environment map: out of memory for its open-sky table");
    }
    double hz[HFS_ZH_N];
    hfs_zh_clamped_cosine(hz);
    const int nc = cw * ch;
    for (int j = 0; j < HFS_ENV_OPEN_N; ++j)
        for (int i = 0; i < HFS_ENV_OPEN_N; ++i) {
            double n[3], e[3] = {0.0, 0.0, 0.0}, hn[HFS_SH_N];
            node_dir(i, j, n);
            for (int q = 0; q < nc; ++q) {
                const cell *c = &cells[q];
                if (n[0] * c->dir[0] + n[1] * c->dir[1] + n[2] * c->dir[2] <= 0.0)
                    continue;
                for (int k = 0; k < 3; ++k)
                    e[k] += n[0] * c->m[k][0] + n[1] * c->m[k][1] + n[2] * c->m[k][2];
            }
            hfs_sh_rotate_zonal(hz, n[0], n[1], n[2], hn);
            float *t = table + 3 * ((size_t)j * HFS_ENV_OPEN_N + i);
            for (int k = 0; k < 3; ++k)
                t[k] = (float)(e[k] - hfs_sh_dot(hn, sh[k]));
        }
    free(cells);
    return HFS_OK;
}

void hfs_env_open_uv(const double n[3], double rotate, double uv[2])
{
    const double c = cos(rotate), s = sin(rotate);
    const double x = c * n[0] + s * n[1], y = -s * n[0] + c * n[1];
    const double rxy = sqrt(x * x + y * y);
    const double z = n[2] > 1.0 ? 1.0 : (n[2] < 0.0 ? 0.0 : n[2]);
    const double r = acos(z) / (0.5 * PI);
    uv[0] = rxy > 0.0 ? r * x / rxy : 0.0;
    uv[1] = rxy > 0.0 ? r * y / rxy : 0.0;
}

void hfs_env_open_lookup(const float *table, const double n[3], double rotate, double out[3])
{
    double uv[2];
    hfs_env_open_uv(n, rotate, uv);
    const int last = HFS_ENV_OPEN_N - 1;
    double fx = (uv[0] + 1.0) * 0.5 * last, fy = (uv[1] + 1.0) * 0.5 * last;
    fx = fx < 0.0 ? 0.0 : (fx > last ? last : fx);
    fy = fy < 0.0 ? 0.0 : (fy > last ? last : fy);
    int i = (int)fx, j = (int)fy;
    i = i >= last ? last - 1 : i;
    j = j >= last ? last - 1 : j;
    const double ax = fx - i, ay = fy - j;
    const float *t00 = table + 3 * ((size_t)j * HFS_ENV_OPEN_N + i);
    const float *t10 = t00 + 3, *t01 = t00 + 3 * HFS_ENV_OPEN_N, *t11 = t01 + 3;
    for (int k = 0; k < 3; ++k)
        out[k] = (1.0 - ay) * ((1.0 - ax) * t00[k] + ax * t10[k]) +
                 ay * ((1.0 - ax) * t01[k] + ax * t11[k]);
}

double hfs_env_open_max(const float *table)
{
    double m = 0.0;
    for (int k = 0; k < HFS_ENV_OPEN_FLOATS; ++k)
        m = fmax(m, fabs((double)table[k]));
    return m;
}
