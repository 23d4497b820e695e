/*
 * env_gloss.c — an environment map's glossy lobe beyond order 4
 * (env_gloss.h).
 */
#include "env_gloss.h"

#include <math.h>
#include <stdlib.h>

#include "gloss.h"
#include "sh.h"

#define PI 3.14159265358979323846
#define CELL_COLS 128
#define CELL_ROWS 64
#define LOBE_CUT 1e-4 /* lobe values below this share of its peak: skipped */

/* The map gathered into cells: per cell its solid angle, its radiance
 * times solid angle per channel and its solid-angle centroid (unit after
 * the gather).  Rows of cells are bands of elevation, listed with the
 * extreme elevations their pixels reach. */
typedef struct gloss_cells {
    int cols, rows;
    double *omega, *energy, *dir; /* cols x rows, x 3, x 3 */
    double *top, *bottom;         /* per row of cells: elevations, radians */
} gloss_cells;

static void cells_free(gloss_cells *g)
{
    free(g->omega);
    free(g->energy);
    free(g->dir);
    free(g->top);
    free(g->bottom);
}

static int cells_gather(const float *rgb, int w, int h, gloss_cells *g)
{
    g->cols = w < CELL_COLS ? w : CELL_COLS;
    g->rows = h < CELL_ROWS ? h : CELL_ROWS;
    const size_t n = (size_t)g->cols * (size_t)g->rows;
    g->omega = calloc(n, sizeof *g->omega);
    g->energy = calloc(3 * n, sizeof *g->energy);
    g->dir = calloc(3 * n, sizeof *g->dir);
    g->top = malloc((size_t)g->rows * sizeof *g->top);
    g->bottom = malloc((size_t)g->rows * sizeof *g->bottom);
    if (!g->omega || !g->energy || !g->dir || !g->top || !g->bottom)
        return HFS_E_NOMEM;
    for (int r = 0; r < g->rows; ++r)
        g->top[r] = -PI, g->bottom[r] = PI;
    for (int y = 0; y < h; ++y) {
        const double e0 = 0.5 * PI - PI * y / h, e1 = 0.5 * PI - PI * (y + 1.0) / h;
        const double em = 0.5 * (e0 + e1), om = 2.0 * PI / w * (sin(e0) - sin(e1));
        const int r = (int)((long)y * g->rows / h);
        g->top[r] = fmax(g->top[r], e0);
        g->bottom[r] = fmin(g->bottom[r], e1);
        const float *px = rgb + (size_t)y * (size_t)w * 3;
        for (int x = 0; x < w; ++x) {
            const double phi = 2.0 * PI * (x + 0.5) / w;
            const size_t c = (size_t)r * (size_t)g->cols + (size_t)((long)x * g->cols / w);
            g->omega[c] += om;
            g->dir[3 * c] += om * cos(em) * cos(phi);
            g->dir[3 * c + 1] += om * cos(em) * sin(phi);
            g->dir[3 * c + 2] += om * sin(em);
            for (int k = 0; k < 3; ++k)
                g->energy[3 * c + (size_t)k] += om * (double)px[3 * x + k];
        }
    }
    for (size_t c = 0; c < n; ++c) {
        double *d = g->dir + 3 * c;
        const double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (int k = 0; k < 3 && len > 0.0; ++k)
            d[k] /= len;
    }
    return HFS_OK;
}

/* Node (i, j)'s direction, the map's frame. */
static void node_dir(int i, int j, double r[3])
{
    const double phi = 2.0 * PI * i / HFS_ENV_GLOSS_NW;
    const double e = 0.5 * PI - PI * j / (HFS_ENV_GLOSS_NH - 1);
    r[0] = cos(e) * cos(phi);
    r[1] = cos(e) * sin(phi);
    r[2] = sin(e);
}

/* P_map at r: the lobe-weighted mean radiance of the cells (env_gloss.h). */
static void lobe_mean(const gloss_cells *g, const double r[3], double s, double out[3])
{
    const double cut = exp(log(LOBE_CUT) / s);      /* R.d below it: skipped */
    const double reach = acos(cut);                 /* the lobe's angular reach */
    const double er = asin(r[2] > 1.0 ? 1.0 : (r[2] < -1.0 ? -1.0 : r[2]));
    double num[3] = {0.0, 0.0, 0.0}, den = 0.0, best = -2.0;
    size_t best_c = 0;
    for (int row = 0; row < g->rows; ++row) {
        /* A row wholly farther than the reach in elevation cannot hold a
         * cell the lobe sees; the nearest cell is still tracked below. */
        const int far = g->bottom[row] > er + reach || g->top[row] < er - reach;
        for (int col = 0; col < g->cols; ++col) {
            const size_t c = (size_t)row * (size_t)g->cols + (size_t)col;
            if (far && best > -2.0)
                break;
            const double *d = g->dir + 3 * c;
            const double rd = r[0] * d[0] + r[1] * d[1] + r[2] * d[2];
            if (rd > best)
                best = rd, best_c = c;
            if (!(rd > cut))
                continue;
            const double wt = exp(s * log(rd));
            den += wt * g->omega[c];
            for (int k = 0; k < 3; ++k)
                num[k] += wt * g->energy[3 * c + (size_t)k];
        }
    }
    if (!(den > 0.0)) { /* a lobe narrower than a cell: the nearest cell */
        den = g->omega[best_c];
        for (int k = 0; k < 3; ++k)
            num[k] = g->energy[3 * best_c + (size_t)k];
    }
    for (int k = 0; k < 3; ++k)
        out[k] = den > 0.0 ? num[k] / den : 0.0;
}

int hfs_env_gloss_build(const float *rgb, int w, int h, const double sh[3][HFS_SH_COEFFS],
                        double s, float *table, hfs_error *err)
{
    if (!rgb || w < 1 || h < 1 || !(s >= 1.0))
        return hfs_fail(err, HFS_E_INVALID,
                        "environment map: size %dx%d, gloss %g (needs 1x1 or more, gloss >= 1)",
                        w, h, s);
    gloss_cells g = {0};
    if (cells_gather(rgb, w, h, &g)) {
        cells_free(&g);
        return hfs_fail(err, HFS_E_NOMEM, "environment map: out of memory for its glossy table");
    }
    double zh[HFS_ZH_N];
    hfs_gloss_zh(s, zh);
    for (int j = 0; j < HFS_ENV_GLOSS_NH; ++j)
        for (int i = 0; i < HFS_ENV_GLOSS_NW; ++i) {
            double r[3], p[3], y[HFS_SH_N];
            node_dir(i, j, r);
            lobe_mean(&g, r, s, p);
            hfs_sh_eval(r[0], r[1], r[2], y);
            for (int k = 0; k < HFS_SH_N; ++k) /* Q_lm = g_l y_lm(R) */
                y[k] *= zh[hfs_sh_band(k)];
            float *t = table + 3 * ((size_t)j * (HFS_ENV_GLOSS_NW + 1) + (size_t)i);
            for (int k = 0; k < 3; ++k)
                t[k] = (float)(p[k] - hfs_sh_dot(sh[k], y));
        }
    for (int j = 0; j < HFS_ENV_GLOSS_NH; ++j) { /* column W = column 0 */
        float *t = table + 3 * (size_t)j * (HFS_ENV_GLOSS_NW + 1);
        for (int k = 0; k < 3; ++k)
            t[3 * HFS_ENV_GLOSS_NW + k] = t[k];
    }
    cells_free(&g);
    return HFS_OK;
}

void hfs_env_gloss_xy(const double r[3], double rotate, double xy[2])
{
    const double c = cos(rotate), s = sin(rotate);
    const double x = c * r[0] + s * r[1], y = -s * r[0] + c * r[1];
    double phi = atan2(y, x);
    phi = phi < 0.0 ? phi + 2.0 * PI : phi;
    const double z = r[2] > 1.0 ? 1.0 : (r[2] < -1.0 ? -1.0 : r[2]);
    xy[0] = phi / (2.0 * PI) * HFS_ENV_GLOSS_NW;
    xy[1] = (0.5 * PI - asin(z)) / PI * (HFS_ENV_GLOSS_NH - 1);
}

void hfs_env_gloss_lookup(const float *table, const double r[3], double rotate, double out[3])
{
    double xy[2];
    hfs_env_gloss_xy(r, rotate, xy);
    const int lx = HFS_ENV_GLOSS_NW, ly = HFS_ENV_GLOSS_NH - 1;
    const double fx = xy[0] < 0.0 ? 0.0 : (xy[0] > lx ? lx : xy[0]);
    const double fy = xy[1] < 0.0 ? 0.0 : (xy[1] > ly ? ly : xy[1]);
    int i = (int)fx, j = (int)fy;
    i = i >= lx ? lx - 1 : i;
    j = j >= ly ? ly - 1 : j;
    const double ax = fx - i, ay = fy - j;
    const size_t stride = 3 * (HFS_ENV_GLOSS_NW + 1);
    const float *t00 = table + (size_t)j * stride + 3 * (size_t)i;
    const float *t10 = t00 + 3, *t01 = t00 + stride, *t11 = t01 + 3;
    for (int k = 0; k < 3; ++k)
        out[k] = (1.0 - ay) * ((1.0 - ax) * t00[k] + ax * t10[k]) +
                 ay * ((1.0 - ax) * t01[k] + ax * t11[k]);
}

double hfs_env_gloss_max(const float *table)
{
    double m = 0.0;
    for (int k = 0; k < HFS_ENV_GLOSS_FLOATS; ++k)
        m = fmax(m, fabs((double)table[k]));
    return m;
}
