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
#define NW HFS_ENV_GLOSS_NW
#define CELL_ROWS 64
#define LOBE_CUT 1e-4 /* lobe values below this share of its peak: skipped */

/* The map gathered into NW columns of cells (the table's columns: cell k
 * centred at azimuth 2 pi (k + 1/2) / NW) and at most CELL_ROWS rows:
 * per cell its radiance times solid angle per channel; per row its cells'
 * solid angle (all equal) and the elevation of its solid-angle centroid.
 * A map narrower than NW gives each cell the pixel at its centre. */
typedef struct gloss_cells {
    int rows;
    double *energy;     /* rows x NW x 3 */
    double *omega, *e;  /* per row */
} gloss_cells;

static void cells_free(gloss_cells *g)
{
    free(g->energy);
    free(g->omega);
    free(g->e);
}

static int cells_gather(const float *rgb, int w, int h, gloss_cells *g)
{
    g->rows = h < CELL_ROWS ? h : CELL_ROWS;
    g->energy = calloc((size_t)g->rows * NW * 3, sizeof *g->energy);
    g->omega = calloc((size_t)g->rows, sizeof *g->omega);
    g->e = calloc((size_t)g->rows, sizeof *g->e);
    double *mz = calloc((size_t)g->rows * 2, sizeof *mz); /* per row: Int z, Int rho */
    if (!g->energy || !g->omega || !g->e || !mz) {
        free(mz);
        return HFS_E_NOMEM;
    }
    for (int y = 0; y < h; ++y) {
        const double e0 = 0.5 * PI - PI * y / h, e1 = 0.5 * PI - PI * (y + 1.0) / h;
        const double band = 2.0 * PI * (sin(e0) - sin(e1)); /* the pixel row's solid angle */
        const int r = (int)((long)y * g->rows / h);
        g->omega[r] += band / NW;
        mz[2 * r] += PI * (sin(e0) * sin(e0) - sin(e1) * sin(e1)); /* Int z dw */
        mz[2 * r + 1] += PI * (e0 - e1 + 0.5 * (sin(2.0 * e0) - sin(2.0 * e1))); /* Int rho */
        const float *px = rgb + (size_t)y * (size_t)w * 3;
        double *row = g->energy + (size_t)r * NW * 3;
        if (w >= NW) { /* pixel x into cell x NW / w, each its own solid angle */
            for (int x = 0; x < w; ++x)
                for (int k = 0; k < 3; ++k)
                    row[3 * ((long)x * NW / w) + k] += band / w * (double)px[3 * x + k];
        } else {
            for (int c = 0; c < NW; ++c) {
                const int x = (int)((c + 0.5) * w / NW);
                for (int k = 0; k < 3; ++k)
                    row[3 * c + k] += band / NW * (double)px[3 * x + k];
            }
        }
    }
    for (int r = 0; r < g->rows; ++r)
        g->e[r] = atan2(mz[2 * r], mz[2 * r + 1]);
    free(mz);
    return HFS_OK;
}

/* Node row j of the table: P_map at its NW nodes into p (NW x 3).  Cell
 * (r, k) lies at azimuth offset 2 pi (k - i + 1/2) / NW from node i, so
 * the lobe's weight depends on k - i alone: per cell row a circular
 * convolution whose kernel is non-zero only within the lobe's reach, and
 * a denominator the same for every node of the row. */
static void node_row(const gloss_cells *g, int j, double s, double *kern, int *dk, double *p)
{
    const double ej = 0.5 * PI - PI * j / (HFS_ENV_GLOSS_NH - 1);
    const double cut = exp(log(LOBE_CUT) / s);
    double den = 0.0, all = 0.0;
    for (int i = 0; i < 3 * NW; ++i)
        p[i] = 0.0;
    for (int r = 0; r < g->rows; ++r) {
        const double a = cos(ej) * cos(g->e[r]), b = sin(ej) * sin(g->e[r]);
        const double *row = g->energy + (size_t)r * NW * 3;
        all += g->omega[r] * NW;
        int nk = 0; /* kern[q] at offset dk[q]: the non-zero weights */
        for (int d = 0; d < NW; ++d) {
            const double c = a * cos(2.0 * PI * (d + 0.5) / NW) + b;
            if (!(c > cut))
                continue;
            kern[nk] = exp(s * log(c));
            dk[nk++] = d;
            den += kern[nk - 1] * g->omega[r];
        }
        for (int q = 0; q < nk; ++q) { /* p[i] += kern[q] row[(i + dk[q]) mod NW] */
            const double wq = kern[q];
            const int n1 = 3 * (NW - dk[q]);
            const double *src = row + 3 * dk[q];
            for (int i = 0; i < n1; ++i)
                p[i] += wq * src[i];
            for (int i = n1; i < 3 * NW; ++i)
                p[i] += wq * row[i - n1];
        }
    }
    if (den > 0.0) {
        for (int i = 0; i < 3 * NW; ++i)
            p[i] /= den;
        return;
    }
    /* No cell within the lobe's reach (a map of a row or two against a
     * lobe narrower than its rows): the map's mean radiance. */
    double m[3] = {0.0, 0.0, 0.0};
    for (size_t c = 0; c < (size_t)g->rows * NW; ++c)
        for (int k = 0; k < 3; ++k)
            m[k] += g->energy[3 * c + (size_t)k];
    for (int i = 0; i < 3 * NW; ++i)
        p[i] = all > 0.0 ? m[i % 3] / all : 0.0;
}

int hfs_env_gloss_build(const float *rgb, int w, int h, const double sh[3][HFS_SH_COEFFS],
                        double s, float *table, hfs_error *err)
{
    if (!rgb || w < 1 || h < 1 || !(s >= 1.0))
        return hfs_fail(err, HFS_E_INVALID,
                        "environment map: size %dx%d, gloss %g (needs 1x1 or more, gloss >= 1)",
                        w, h, s);
    gloss_cells g = {0};
    double *p = malloc(3 * NW * sizeof *p);
    double *kern = malloc(NW * sizeof *kern);
    int *dk = malloc(NW * sizeof *dk);
    if (!p || !kern || !dk || cells_gather(rgb, w, h, &g)) {
        free(p), free(kern), free(dk);
        cells_free(&g);
        return hfs_fail(err, HFS_E_NOMEM, "environment map: out of memory for its glossy table");
    }
    double zh[HFS_ZH_N];
    hfs_gloss_zh(s, zh);
    for (int j = 0; j < HFS_ENV_GLOSS_NH; ++j) {
        node_row(&g, j, s, kern, dk, p);
        const double e = 0.5 * PI - PI * j / (HFS_ENV_GLOSS_NH - 1);
        for (int i = 0; i <= NW; ++i) { /* column NW repeats column 0 */
            const double phi = 2.0 * PI * (i % NW) / NW;
            double y[HFS_SH_N];
            hfs_sh_eval(cos(e) * cos(phi), cos(e) * sin(phi), sin(e), y);
            for (int k = 0; k < HFS_SH_N; ++k) /* Q_lm = g_l y_lm(R) */
                y[k] *= zh[hfs_sh_band(k)];
            float *t = table + 3 * ((size_t)j * (NW + 1) + (size_t)i);
            for (int k = 0; k < 3; ++k)
                t[k] = (float)(p[3 * (i % NW) + k] - hfs_sh_dot(sh[k], y));
        }
    }
    free(p), free(kern), free(dk);
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
