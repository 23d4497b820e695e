/*
 * env_coarse.c — the coarse pyramid of the environment map decomposition
 * and its centre-surround detection (env_decompose.h, env_internal.h).
 *
 * Level 0 has at most 256 x 128 cells; texel (i, j) lies in cell
 * (i cw / w, j ch / h), so any map size works (a map smaller than that is
 * its own level 0).  A cell holds the luminance energy sum Y dOmega, the
 * exact solid angle and the energy-weighted direction sum of its texels;
 * level l + 1 merges 2 x 2 cells of level l.  The full-resolution pass is
 * row-parallel (one coarse row per task, fixed partition) and also checks
 * every value and sums the map's energy per channel.  NaN and Inf are
 * errors; so is a value below -ENV_NEG_TOLERANCE x the map's mean
 * luminance radiance (any negative value in a map of mean <= 0).  Smaller
 * negatives are kept, as hfs_envmap_load keeps them: lossy EXR compression
 * leaves them (data/courtyard.exr has 1818 values down to -0.0032 where its
 * mean is 0.56), and they stay in the residual like any texel.
 *
 * Detection: at every level with >= 8 rows and >= 16 columns (blocks up
 * to 45 degrees; a map below 16 x 8 texels gets no light: a texel of over
 * 22.5 degrees cannot place one),
 * every block of 2 rows by nb columns, nb = cw / (ch cos e) (square on
 * the sphere; e the latitude of the block's edge nearer the equator; whole
 * rings where nb > cw / 3 and for the two rows at each pole, so a light at
 * a pole is one block), starting at every column (azimuth wraps).
 * Its surround is the ring of cells around it (1 row above and below, nb/2
 * columns each side, up to 2 rows for whole rings).  Response
 * E_in - contrast * A_in * E_ring / A_ring; the largest positive one wins
 * (scan order breaks ties, so the result is deterministic).
 */
#include "env_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "parallel.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static int level_alloc(env_level *l, int cw, int ch)
{
    const size_t n = (size_t)cw * (size_t)ch;
    l->cw = cw;
    l->ch = ch;
    l->e = calloc(5 * n, sizeof *l->e);
    if (!l->e)
        return -1;
    l->a = l->e + n;
    l->sx = l->a + n;
    l->sy = l->sx + n;
    l->sz = l->sy + n;
    return 0;
}

typedef struct build_job {
    env_ctx *c;
    double (*row_total)[3];       /* per coarse row, per channel          */
    long long *bad;               /* per coarse row: first NaN/Inf value  */
    long long *neg;               /* per coarse row: its most negative    */
} build_job;

/* Coarse row y: its texel rows, checked, summed into level 0. */
static void build_row(void *ctx, int y, int worker)
{
    build_job *job = ctx;
    env_ctx *c = job->c;
    env_level *l0 = &c->lv[0];
    const int j0 = (int)(((long long)y * c->h + l0->ch - 1) / l0->ch);
    const int j1 = (int)(((long long)(y + 1) * c->h + l0->ch - 1) / l0->ch);
    double tot[3] = {0, 0, 0};
    float low = 0.0f;
    (void)worker;
    job->bad[y] = job->neg[y] = -1;
    for (int j = j0; j < j1; ++j) {
        const float *row = c->rgb + (size_t)j * (size_t)c->w * 3;
        const double dom = c->row_domega[j], se = c->row_sin[j], ce = c->row_cos[j];
        double *e = l0->e + (size_t)y * l0->cw, *sx = l0->sx + (size_t)y * l0->cw;
        double *sy = l0->sy + (size_t)y * l0->cw, *sz = l0->sz + (size_t)y * l0->cw;
        double *a = l0->a + (size_t)y * l0->cw;
        for (int i = 0; i < c->w; ++i) {
            const float *p = row + 3 * i;
            for (int q = 0; q < 3; ++q) {
                if (!isfinite(p[q]) && job->bad[y] < 0)
                    job->bad[y] = ((long long)j * c->w + i) * 3 + q;
                if (p[q] < low) {
                    low = p[q];
                    job->neg[y] = ((long long)j * c->w + i) * 3 + q;
                }
            }
            const int x = c->col_cell[i];
            const double y_dom = env_lum(p[0], p[1], p[2]) * dom;
            e[x] += y_dom;
            a[x] += dom;
            sx[x] += y_dom * ce * c->col_cos[i];
            sy[x] += y_dom * ce * c->col_sin[i];
            sz[x] += y_dom * se;
            tot[0] += p[0] * dom;
            tot[1] += p[1] * dom;
            tot[2] += p[2] * dom;
        }
    }
    memcpy(job->row_total[y], tot, sizeof tot);
}

static int tables_alloc(env_ctx *c)
{
    const int w = c->w, h = c->h;
    c->row_domega = malloc((size_t)h * 3 * sizeof(double));
    c->col_cos = malloc((size_t)w * 2 * sizeof(double));
    c->col_cell = malloc(((size_t)w + (size_t)h) * sizeof(int));
    if (!c->row_domega || !c->col_cos || !c->col_cell)
        return -1;
    c->row_sin = c->row_domega + h;
    c->row_cos = c->row_sin + h;
    c->col_sin = c->col_cos + w;
    c->row_cell = c->col_cell + w;
    const double dphi = 2.0 * M_PI / w;
    for (int j = 0; j < h; ++j) {
        const double e = 0.5 * M_PI - M_PI * (j + 0.5) / h;
        const double et = 0.5 * M_PI - M_PI * j / h, eb = 0.5 * M_PI - M_PI * (j + 1.0) / h;
        c->row_domega[j] = dphi * (sin(et) - sin(eb));
        c->row_sin[j] = sin(e);
        c->row_cos[j] = cos(e);
    }
    for (int i = 0; i < w; ++i) {
        const double phi = (i + 0.5) * dphi;
        c->col_cos[i] = cos(phi);
        c->col_sin[i] = sin(phi);
    }
    return 0;
}

/* Value idx (texel idx / 3, channel idx % 3) is not finite or negative. */
static int bad_value(const env_ctx *c, long long idx, double mean, hfs_error *err)
{
    const float v = c->rgb[idx];
    const long long t = idx / 3;
    const char ch = "RGB"[idx % 3];
    if (!isfinite(v))
        return hfs_fail(err, HFS_E_INVALID, "texel (%lld, %lld) %c is %s", t % c->w, t / c->w,
                        ch, isnan(v) ? "NaN" : "infinite");
    return hfs_fail(err, HFS_E_INVALID, "texel (%lld, %lld) %c is %g, below -%g x the map's "
                    "mean radiance %g", t % c->w, t / c->w, ch, v, ENV_NEG_TOLERANCE, mean);
}

/* The first NaN/Inf, else a texel more negative than the tolerance. */
static int check_values(env_ctx *c, const build_job *job, int ch, hfs_error *err)
{
    for (int y = 0; y < ch; ++y)
        if (job->bad[y] >= 0)
            return bad_value(c, job->bad[y], 0.0, err);
    for (int y = 0; y < ch; ++y)
        for (int k = 0; k < 3; ++k)
            c->total[k] += job->row_total[y][k];
    c->total_lum = env_lum(c->total[0], c->total[1], c->total[2]);
    const double mean = c->total_lum / (4.0 * M_PI);
    for (int y = 0; y < ch; ++y)
        if (job->neg[y] >= 0 && c->rgb[job->neg[y]] < -ENV_NEG_TOLERANCE * fmax(mean, 0.0))
            return bad_value(c, job->neg[y], mean, err);
    return HFS_OK;
}

int envc_init(env_ctx *c, float *rgb, int w, int h, const hfs_env_decompose_opts *o,
              hfs_error *err)
{
    memset(c, 0, sizeof *c);
    c->rgb = rgb;
    c->w = w;
    c->h = h;
    c->opts = *o;
    const int cw = w < ENV_COARSE_W ? w : ENV_COARSE_W, ch = h < ENV_COARSE_H ? h : ENV_COARSE_H;
    if (tables_alloc(c) || level_alloc(&c->lv[0], cw, ch))
        goto nomem;
    c->n_levels = 1;
    for (int i = 0; i < w; ++i)
        c->col_cell[i] = (int)((long long)i * cw / w);
    for (int j = 0; j < h; ++j)
        c->row_cell[j] = (int)((long long)j * ch / h);
    build_job job = {c, malloc((size_t)ch * sizeof *job.row_total),
                     malloc(2 * (size_t)ch * sizeof *job.bad), NULL};
    if (!job.row_total || !job.bad) {
        free(job.row_total);
        free(job.bad);
        goto nomem;
    }
    job.neg = job.bad + ch;
    /* Small maps (a probe frame) on one thread: starting workers costs more
     * than the pass, and their start-up jitter would be the frame's. */
    const int threads = o->threads == 0 && (long long)w * h < (1LL << 18) ? 1 : o->threads;
    hfs_parallel_rows(ch, threads, build_row, &job, NULL, NULL);
    const int rc = check_values(c, &job, ch, err);
    free(job.row_total);
    free(job.bad);
    if (rc) {
        envc_free(c);
        return rc;
    }
    while (c->n_levels < ENV_MAX_LEVELS) {
        const env_level *p = &c->lv[c->n_levels - 1];
        if (p->ch < 8)
            break;
        if (level_alloc(&c->lv[c->n_levels], (p->cw + 1) / 2, (p->ch + 1) / 2))
            goto nomem;
        c->n_levels++;
    }
    envc_merge_levels(c);
    return HFS_OK;
nomem:
    envc_free(c);
    return hfs_fail(err, HFS_E_NOMEM, "out of memory for a %dx%d map's decomposition", w, h);
}

void envc_free(env_ctx *c)
{
    free(c->row_domega);
    free(c->col_cos);
    free(c->col_cell);
    for (int l = 0; l < ENV_MAX_LEVELS; ++l)
        free(c->lv[l].e);
    memset(c, 0, sizeof *c);
}

void envc_merge_levels(env_ctx *c)
{
    for (int l = 1; l < c->n_levels; ++l) {
        const env_level *p = &c->lv[l - 1];
        env_level *q = &c->lv[l];
        const size_t n = (size_t)q->cw * q->ch;
        memset(q->e, 0, 5 * n * sizeof *q->e);
        for (int y = 0; y < p->ch; ++y)
            for (int x = 0; x < p->cw; ++x) {
                const size_t s = (size_t)y * p->cw + x, d = (size_t)(y / 2) * q->cw + x / 2;
                q->e[d] += p->e[s];
                q->a[d] += p->a[s];
                q->sx[d] += p->sx[s];
                q->sy[d] += p->sy[s];
                q->sz[d] += p->sz[s];
            }
    }
}

void envc_add(env_ctx *c, int i, int j, double dlum)
{
    env_level *l0 = &c->lv[0];
    const size_t k = (size_t)c->row_cell[j] * l0->cw + c->col_cell[i];
    l0->e[k] += dlum;
    l0->sx[k] += dlum * c->row_cos[j] * c->col_cos[i];
    l0->sy[k] += dlum * c->row_cos[j] * c->col_sin[i];
    l0->sz[k] += dlum * c->row_sin[j];
}

/* Sum of v over columns [x0, x0 + n) of a row, wrapping; p is the row's
 * prefix sum over two periods (2 cw + 1 entries). */
static double span(const double *p, int cw, int x0, int n)
{
    x0 = ((x0 % cw) + cw) % cw;
    return p[x0 + n] - p[x0];
}

typedef struct det_best {
    double resp;
    int level, y, x, nb, rows;
} det_best;

/* Block width in cells for rows [y, y + 2) of level l (whole ring: cw;
 * always at the first and last two rows, the caps about the poles). */
static int block_width(const env_level *l, int y)
{
    if (y == 0 || y + 2 == l->ch)
        return l->cw;
    const double et = 0.5 * M_PI - M_PI * y / l->ch, eb = 0.5 * M_PI - M_PI * (y + 2.0) / l->ch;
    const double cmax = (et >= 0.0 && eb <= 0.0) ? 1.0 : fmax(cos(et), cos(eb));
    const double nb = l->cw / (l->ch * fmax(cmax, 1e-9));
    if (nb > l->cw / 3.0)
        return l->cw;
    return nb < 2.0 ? 2 : (int)lround(nb);
}

static void detect_level(const env_ctx *c, int li, double *pe, double *pa, det_best *best)
{
    const env_level *l = &c->lv[li];
    const int cw = l->cw, stride = 2 * cw + 1;
    for (int y = 0; y < l->ch; ++y) {
        double *re = pe + (size_t)y * stride, *ra = pa + (size_t)y * stride;
        re[0] = ra[0] = 0.0;
        for (int k = 0; k < 2 * cw; ++k) {
            re[k + 1] = re[k] + l->e[(size_t)y * cw + k % cw];
            ra[k + 1] = ra[k] + l->a[(size_t)y * cw + k % cw];
        }
    }
    for (int y = 0; y + 2 <= l->ch; ++y) {
        const int nb = block_width(l, y), ring = nb == cw;
        const int side = ring ? 0 : (nb + 1) / 2, outer = ring ? cw : nb + 2 * side;
        const int up = ring ? 2 : 1;
        for (int x = 0; x < (ring ? 1 : cw); ++x) {
            double ein = 0, ain = 0, eo = 0, ao = 0;
            for (int r = y - up; r < y + 2 + up; ++r) {
                if (r < 0 || r >= l->ch)
                    continue;
                const double *re = pe + (size_t)r * stride, *ra = pa + (size_t)r * stride;
                eo += span(re, cw, x - side, outer);
                ao += span(ra, cw, x - side, outer);
                if (r >= y && r < y + 2) {
                    ein += span(re, cw, x, nb);
                    ain += span(ra, cw, x, nb);
                }
            }
            eo -= ein;
            ao -= ain;
            if (ao <= 0.0 || ain <= 0.0)
                continue;
            const double resp = ein - c->opts.contrast * ain * (eo / ao);
            if (resp > best->resp) {
                det_best b = {resp, li, y, x, nb, 2};
                *best = b;
            }
        }
    }
}

int envc_detect(const env_ctx *c, env_seed *out)
{
    const env_level *l0 = &c->lv[0];
    const size_t n = (size_t)l0->ch * (2 * (size_t)l0->cw + 1);
    double *pe = malloc(2 * n * sizeof *pe);
    det_best best = {0.0, -1, 0, 0, 0, 0};
    if (!pe)
        return 0;
    for (int li = 0; li < c->n_levels; ++li)
        if (c->lv[li].ch >= 8 && c->lv[li].cw >= 16)
            detect_level(c, li, pe, pe + n, &best);
    free(pe);
    if (best.level < 0)
        return 0;
    const env_level *l = &c->lv[best.level];
    double s[3] = {0, 0, 0};
    for (int r = best.y; r < best.y + best.rows; ++r)
        for (int k = 0; k < best.nb; ++k) {
            const size_t q = (size_t)r * l->cw + (size_t)((best.x + k) % l->cw);
            s[0] += l->sx[q];
            s[1] += l->sy[q];
            s[2] += l->sz[q];
        }
    const double len = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    if (!(len > 0.0))
        return 0;
    for (int k = 0; k < 3; ++k)
        out->d[k] = s[k] / len;
    out->r0 = M_PI / l->ch * (best.nb == l->cw ? 2.0 : 1.5);
    return 1;
}
