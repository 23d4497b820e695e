/*
 * truth_envmap.c — the ground truth of an environment map (truth_envmap.h).
 *
 * Tables, made once per render: the row edges' elevations and the
 * antiderivatives Fcc(e) = e/2 + sin(2e)/4 (of cos^2 e) and Fsc(e) =
 * sin^2(e)/2 (of sin e cos e) there; per wedge a and row r the sums
 * P[a][r] = (L C, L S, L D) per channel over the row's ordinary pixels
 * inside the wedge, and Q[a][r] = sum over the rows above r of
 * (P_C Icc, P_S Icc, P_D Isc), so that the rows wholly above a horizon cost
 * one lookup.  Sums run in double in a fixed order; the tables hold floats
 * (relative 6e-8, far below the wedge approximation).
 */
#include "truth_envmap.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define NQ 9            /* (C, S, D) x 3 channels */

typedef struct bright_col {
    double cphi, sphi;    /* the column's middle azimuth (world) */
    double cc, ss, dd;    /* C, S, D over the column */
    int first, count;     /* its pixels in px[] */
} bright_col;

typedef struct bright_px {
    int row;
    float le[3];
} bright_px;

struct hfs_truth_envmap {
    const float *map;
    int w, h, n_az;
    double rot;
    double *edge, *fcc, *fsc; /* h+1 row edges (top first): e, Fcc(e), Fsc(e) */
    double *wc, *ws;          /* wedge middle azimuths: cos, sin */
    float *p, *q;             /* n_az x h x NQ, n_az x (h+1) x NQ */
    int n_bright, n_cols;
    bright_col *cols;
    bright_px *px;
};

static double f_cc(double e) { return 0.5 * e + 0.25 * sin(2.0 * e); }
static double f_sc(double e) { const double s = sin(e); return 0.5 * s * s; }

/* C, S, D of the azimuths [lo, hi] (hi - lo small: no cancellation). */
static void az_moments(double lo, double hi, double *c, double *s, double *d)
{
    const double m = 0.5 * (lo + hi), h = sin(0.5 * (hi - lo));
    *c = 2.0 * cos(m) * h;
    *s = 2.0 * sin(m) * h;
    *d = hi - lo;
}

/* Column c's azimuths, env_rotate applied: [*lo, *lo + 2 pi / w], *lo in
 * [0, 2 pi). */
static double column_start(const hfs_truth_envmap *m, int c)
{
    double lo = fmod(2.0 * PI * c / m->w + m->rot, 2.0 * PI);
    return lo < 0.0 ? lo + 2.0 * PI : lo;
}

void hfs_truth_envmap_free(hfs_truth_envmap *m)
{
    if (!m)
        return;
    free(m->edge);
    free(m->fcc);
    free(m->fsc);
    free(m->wc);
    free(m->ws);
    free(m->p);
    free(m->q);
    free(m->cols);
    free(m->px);
    free(m);
}

void hfs_truth_envmap_counts(const hfs_truth_envmap *m, int *n_bright, int *n_columns)
{
    *n_bright = m ? m->n_bright : 0;
    *n_columns = m ? m->n_cols : 0;
}

/* ---- bright pixels -------------------------------------------------------------- */

typedef struct cand {
    float lum;
    int idx, col;
} cand;

static int by_lum_desc(const void *a, const void *b)
{
    const cand *x = a, *y = b;
    if (x->lum != y->lum)
        return x->lum > y->lum ? -1 : 1;
    return (x->idx > y->idx) - (x->idx < y->idx);
}

/* Column first, then row (idx = r w + c). */
static int by_column(const void *a, const void *b)
{
    const cand *x = a, *y = b;
    if (x->col != y->col)
        return (x->col > y->col) - (x->col < y->col);
    return (x->idx > y->idx) - (x->idx < y->idx);
}

static float lum_of(const float *p) { return (p[0] + p[1] + p[2]) * (1.0f / 3.0f); }

/* Selects the bright pixels (marked in `mask`) and groups them by column.
 * Returns HFS_OK or HFS_E_NOMEM; *any = 0 for an all-black map.  None is
 * bright when the mean is not positive. */
static int pick_bright(hfs_truth_envmap *m, double k, int max_bright, unsigned char *mask,
                       int *any)
{
    const int w = m->w, h = m->h;
    double sum = 0.0;
    *any = 0;
    for (int r = 0; r < h; ++r) {
        double row = 0.0;
        for (int c = 0; c < w; ++c) {
            const float *p = m->map + 3 * ((size_t)r * w + c);
            row += lum_of(p);
            *any |= p[0] != 0.0f || p[1] != 0.0f || p[2] != 0.0f;
        }
        sum += row * (2.0 * PI / w) * (sin(m->edge[r]) - sin(m->edge[r + 1]));
    }
    const double thr = k * sum / (4.0 * PI);
    int n = 0;
    for (size_t i = 0; i < (size_t)w * h; ++i)
        n += lum_of(m->map + 3 * i) > thr && thr > 0.0;
    cand *cd = malloc((size_t)(n > 0 ? n : 1) * sizeof *cd);
    if (!cd)
        return HFS_E_NOMEM;
    n = 0;
    for (size_t i = 0; i < (size_t)w * h; ++i)
        if (lum_of(m->map + 3 * i) > thr && thr > 0.0)
            cd[n++] = (cand){lum_of(m->map + 3 * i), (int)i, (int)(i % (size_t)w)};
    if (n > max_bright) {
        qsort(cd, (size_t)n, sizeof *cd, by_lum_desc);
        n = max_bright > 0 ? max_bright : 0;
    }
    qsort(cd, (size_t)n, sizeof *cd, by_column);
    m->px = malloc((size_t)(n > 0 ? n : 1) * sizeof *m->px);
    m->cols = malloc((size_t)(n > 0 ? n : 1) * sizeof *m->cols);
    if (!m->px || !m->cols) {
        free(cd);
        return HFS_E_NOMEM;
    }
    for (int b = 0; b < n; ++b) {
        const int c = cd[b].idx % w, r = cd[b].idx / w;
        mask[cd[b].idx] = 1;
        m->px[b].row = r;
        memcpy(m->px[b].le, m->map + 3 * (size_t)cd[b].idx, sizeof m->px[b].le);
        if (b == 0 || cd[b - 1].idx % w != c) {
            bright_col *bc = &m->cols[m->n_cols++];
            const double lo = column_start(m, c), hi = lo + 2.0 * PI / w;
            az_moments(lo, hi, &bc->cc, &bc->ss, &bc->dd);
            bc->cphi = cos(0.5 * (lo + hi));
            bc->sphi = sin(0.5 * (lo + hi));
            bc->first = b;
            bc->count = 0;
        }
        m->cols[m->n_cols - 1].count++;
    }
    m->n_bright = n;
    free(cd);
    return HFS_OK;
}

/* ---- wedges ------------------------------------------------------------------------ */

typedef struct piece {
    int a;
    double c, s, d;
} piece;

/* Each column's parts in the wedges it overlaps: pieces[start[c] ..
 * start[c+1]). */
static piece *column_pieces(const hfs_truth_envmap *m, int **start_out)
{
    const double dw = 2.0 * PI / m->n_az, dc = 2.0 * PI / m->w;
    const size_t cap = (size_t)m->w * 2 + (size_t)m->n_az * 2 + 2;
    piece *pc = malloc(cap * sizeof *pc);
    int *start = malloc(((size_t)m->w + 1) * sizeof *start);
    if (!pc || !start) {
        free(pc);
        free(start);
        return NULL;
    }
    int n = 0;
    for (int c = 0; c < m->w; ++c) {
        start[c] = n;
        const double lo = column_start(m, c), hi = lo + dc;
        for (long k = (long)floor(lo / dw); (double)k * dw < hi && (size_t)n < cap; ++k) {
            const double a0 = fmax(lo, (double)k * dw), a1 = fmin(hi, (double)(k + 1) * dw);
            if (!(a1 > a0))
                continue;
            piece *p = &pc[n++];
            p->a = (int)(k % m->n_az);
            az_moments(a0, a1, &p->c, &p->s, &p->d);
        }
    }
    start[m->w] = n;
    *start_out = start;
    return pc;
}

/* Fills p and q from the map's ordinary pixels (mask 0). */
static int build_wedges(hfs_truth_envmap *m, const unsigned char *mask)
{
    const int A = m->n_az, h = m->h;
    int *start = NULL;
    piece *pc = column_pieces(m, &start);
    double *row = malloc((size_t)A * NQ * sizeof *row);
    double *run = calloc((size_t)A * NQ, sizeof *run);
    m->p = malloc((size_t)A * h * NQ * sizeof *m->p);
    m->q = malloc((size_t)A * (h + 1) * NQ * sizeof *m->q);
    if (!pc || !row || !run || !m->p || !m->q) {
        free(pc), free(start), free(row), free(run);
        return HFS_E_NOMEM;
    }
    for (int r = 0; r < h; ++r) {
        memset(row, 0, (size_t)A * NQ * sizeof *row);
        for (int c = 0; c < m->w; ++c) {
            const size_t idx = (size_t)r * m->w + c;
            const float *le = m->map + 3 * idx;
            if (mask[idx] || (le[0] == 0.0f && le[1] == 0.0f && le[2] == 0.0f))
                continue;
            for (int k = start[c]; k < start[c + 1]; ++k) {
                double *t = row + (size_t)pc[k].a * NQ;
                for (int ch = 0; ch < 3; ++ch) {
                    t[3 * ch] += le[ch] * pc[k].c;
                    t[3 * ch + 1] += le[ch] * pc[k].s;
                    t[3 * ch + 2] += le[ch] * pc[k].d;
                }
            }
        }
        const double icc = m->fcc[r] - m->fcc[r + 1], isc = m->fsc[r] - m->fsc[r + 1];
        for (int a = 0; a < A; ++a) {
            double *t = row + (size_t)a * NQ, *u = run + (size_t)a * NQ;
            float *pq = m->q + ((size_t)a * (h + 1) + r) * NQ;
            float *pp = m->p + ((size_t)a * h + r) * NQ;
            for (int k = 0; k < NQ; ++k) {
                pq[k] = (float)u[k];
                pp[k] = (float)t[k];
                u[k] += t[k] * (k % 3 == 2 ? isc : icc);
            }
            if (r == h - 1)
                for (int k = 0; k < NQ; ++k)
                    pq[NQ + k] = (float)u[k];
        }
    }
    free(pc), free(start), free(row), free(run);
    return HFS_OK;
}

int hfs_truth_envmap_make(const hfs_lighting *l, int n_az, double k, int max_bright,
                          hfs_truth_envmap **out)
{
    *out = NULL;
    hfs_truth_envmap *m = calloc(1, sizeof *m);
    if (!m)
        return HFS_E_NOMEM;
    m->map = l->env_map;
    m->w = l->env_map_width;
    m->h = l->env_map_height;
    m->rot = l->env_rotate;
    m->n_az = n_az;
    const int h = m->h;
    m->edge = malloc((size_t)(h + 1) * sizeof *m->edge);
    m->fcc = malloc((size_t)(h + 1) * sizeof *m->fcc);
    m->fsc = malloc((size_t)(h + 1) * sizeof *m->fsc);
    m->wc = malloc((size_t)n_az * sizeof *m->wc);
    m->ws = malloc((size_t)n_az * sizeof *m->ws);
    unsigned char *mask = calloc((size_t)m->w * h, 1);
    int rc = HFS_E_NOMEM, any = 0;
    if (!m->edge || !m->fcc || !m->fsc || !m->wc || !m->ws || !mask)
        goto fail;
    for (int r = 0; r <= h; ++r) {
        m->edge[r] = r == h ? -0.5 * PI : 0.5 * PI - PI * r / h;
        m->fcc[r] = f_cc(m->edge[r]);
        m->fsc[r] = f_sc(m->edge[r]);
    }
    for (int a = 0; a < n_az; ++a) {
        const double phi = (a + 0.5) * 2.0 * PI / n_az; /* as the SH truth */
        m->wc[a] = cos(phi);
        m->ws[a] = sin(phi);
    }
    if ((rc = pick_bright(m, k, max_bright, mask, &any)) != HFS_OK)
        goto fail;
    if (!any) {
        free(mask);
        hfs_truth_envmap_free(m);
        return HFS_OK;
    }
    if ((rc = build_wedges(m, mask)) != HFS_OK)
        goto fail;
    free(mask);
    *out = m;
    return HFS_OK;
fail:
    free(mask);
    hfs_truth_envmap_free(m);
    return rc;
}

/* ---- one receiver ------------------------------------------------------------------ */

double hfs_truth_env_lo(const hfs_truth_grid *g, int i, int j, double z0, const double n[3],
                        double c, double s, double *hint)
{
    const double na = n[0] * c + n[1] * s;
    const double e0 = atan2(-na, n[2]); /* N.s(phi, e) >= 0 for e >= e0 */
    /* Horizon slopes whose atan is <= e0 cannot change the result: let the
     * walk skip them (identical result, and flat ground costs nothing). */
    double cut = -na / n[2], dc = 1e-12 * (1.0 + fabs(cut));
    while (atan(cut - dc) > e0)
        dc *= 16.0;
    cut -= dc;
    const double m = hfs_truth_horizon(g, i, j, z0, c, s, cut, hint);
    const double horizon = m > -INFINITY ? atan(m) : -PI / 2;
    return horizon > e0 ? horizon : e0;
}

/* The row r with edge[r+1] < lo <= edge[r] (lo in [-pi/2, pi/2)). */
static int row_of(const hfs_truth_envmap *m, double lo)
{
    int r = (int)floor((0.5 * PI - lo) * m->h / PI);
    r = r < 0 ? 0 : r > m->h - 1 ? m->h - 1 : r;
    while (r > 0 && lo > m->edge[r])
        --r;
    while (r < m->h - 1 && lo <= m->edge[r + 1])
        ++r;
    return r;
}

static void wedges(const hfs_truth_envmap *m, const hfs_truth_grid *g, int i, int j, double z0,
                   const double n[3], double sum[3])
{
    double hint = 0.0;
    for (int a = 0; a < m->n_az; ++a) {
        const double lo = hfs_truth_env_lo(g, i, j, z0, n, m->wc[a], m->ws[a], &hint);
        if (!(lo < 0.5 * PI))
            continue;
        const int r = row_of(m, lo);
        const double el = fmax(lo, m->edge[r + 1]);
        const double pcc = m->fcc[r] - f_cc(el), psc = m->fsc[r] - f_sc(el);
        const float *q = m->q + ((size_t)a * (m->h + 1) + r) * NQ;
        const float *p = m->p + ((size_t)a * m->h + r) * NQ;
        for (int ch = 0; ch < 3; ++ch) {
            const int o = 3 * ch;
            const double v = n[0] * (q[o] + p[o] * pcc) + n[1] * (q[o + 1] + p[o + 1] * pcc) +
                             n[2] * (q[o + 2] + p[o + 2] * psc);
            sum[ch] += v;
        }
    }
}

static void bright(const hfs_truth_envmap *m, const hfs_truth_grid *g, int i, int j, double z0,
                   const double n[3], double sum[3])
{
    double hint = 0.0;
    for (int b = 0; b < m->n_cols; ++b) {
        const bright_col *bc = &m->cols[b];
        const double lo = hfs_truth_env_lo(g, i, j, z0, n, bc->cphi, bc->sphi, &hint);
        const double az = n[0] * bc->cc + n[1] * bc->ss, z = n[2] * bc->dd;
        for (int k = bc->first; k < bc->first + bc->count; ++k) {
            const int r = m->px[k].row;
            if (!(lo < m->edge[r]))
                continue;
            const double el = fmax(lo, m->edge[r + 1]);
            const double wgt = az * (m->fcc[r] - f_cc(el)) + z * (m->fsc[r] - f_sc(el));
            if (wgt > 0.0)
                for (int ch = 0; ch < 3; ++ch)
                    sum[ch] += m->px[k].le[ch] * wgt;
        }
    }
}

void hfs_truth_envmap_receiver(const hfs_truth_envmap *m, const hfs_truth_grid *g, int i,
                               int j, double z0, const double n[3], double rho,
                               double lo[3])
{
    double sum[3] = {0.0, 0.0, 0.0};
    wedges(m, g, i, j, z0, n, sum);
    bright(m, g, i, j, z0, n, sum);
    for (int ch = 0; ch < 3; ++ch)
        lo[ch] += rho / PI * sum[ch];
}

void hfs_truth_envmap_radiance(const hfs_truth_envmap *m, const double s[3], double out[3])
{
    double u = (atan2(s[1], s[0]) - m->rot) / (2.0 * PI);
    u -= floor(u);
    const double e = asin(fmax(-1.0, fmin(1.0, s[2])));
    int c = (int)(u * m->w), r = (int)((0.5 * PI - e) / PI * m->h);
    c = c < 0 ? 0 : c >= m->w ? m->w - 1 : c;
    r = r < 0 ? 0 : r >= m->h ? m->h - 1 : r;
    for (int ch = 0; ch < 3; ++ch)
        out[ch] = m->map[3 * ((size_t)r * m->w + c) + ch];
}
