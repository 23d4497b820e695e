/*
 * cpu_pyramid.c — see cpu_pyramid.h.
 *
 * Both filters are written in difference ("lerp") form, a + f*(b - a) and
 * c1 + sum_k beta_k*(c_k - c1), which equals the textbook weighted sum in
 * exact arithmetic and is exact in floating point for a constant input: a flat
 * field must produce exactly zero height differences, hence exactly flat
 * horizons, at every level.
 */
#include "cpu_pyramid.h"

#include "parallel.h"
#include "ray_bound.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

struct hfs_cpu_pyramid {
    int w, h, k, n_levels, first_full;
    int *lw, *lh;          /* per-level sizes */
    double *spacing;       /* s_i */
    double **samples;      /* per-level decimated samples (pointers into pool) */
    double *pool;          /* all decimated levels */
    double *full;          /* reconstructed levels first_full..N-1 */
    size_t full_size;      /* (w+1)*(h+1) */
    hfs_ray_bound_layout rb; /* the gap search's bounds (ray_bound.h) */
    double *rb_atlas;
};

/* ---- filters ------------------------------------------------------------------ */

static inline int clampi(int v, int lo, int hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}

/* Level dst (dw x dh) samples level src (sw x sh) bilinearly at its own texel
 * centres, clamped to the edge. */
static void decimate(const double *src, int sw, int sh, double *dst, int dw, int dh)
{
    for (int r = 0; r < dh; ++r) {
        const double y = ((double)r + 0.5) * (double)sh / (double)dh - 0.5;
        const double yf = floor(y);
        const double fy = y - yf;
        const int y0 = clampi((int)yf, 0, sh - 1), y1 = clampi((int)yf + 1, 0, sh - 1);
        const double *row0 = src + (size_t)y0 * (size_t)sw;
        const double *row1 = src + (size_t)y1 * (size_t)sw;
        for (int t = 0; t < dw; ++t) {
            const double x = ((double)t + 0.5) * (double)sw / (double)dw - 0.5;
            const double xf = floor(x);
            const double fx = x - xf;
            const int x0 = clampi((int)xf, 0, sw - 1), x1 = clampi((int)xf + 1, 0, sw - 1);
            const double top = row0[x0] + fx * (row0[x1] - row0[x0]);
            const double bot = row1[x0] + fx * (row1[x1] - row1[x0]);
            dst[(size_t)r * (size_t)dw + (size_t)t] = top + fy * (bot - top);
        }
    }
}

/* Taps of the uniform cubic B-spline of n samples (clamped indices) evaluated
 * at full-resolution grid point g of a grid of size full. */
typedef struct bspline_tap {
    int i[4];
    double b0, b2, b3; /* beta_1 is implicit: difference form around i[1] */
} bspline_tap;

static void bspline_taps(int n, int full, bspline_tap *taps)
{
    for (int g = 0; g < full; ++g) {
        const double x = ((double)g + 0.5) * (double)n / (double)full - 0.5;
        const double xf = floor(x);
        const double f = x - xf;
        const int x0 = (int)xf;
        bspline_tap *t = &taps[g];
        for (int q = 0; q < 4; ++q)
            t->i[q] = clampi(x0 - 1 + q, 0, n - 1);
        const double u = 1.0 - f;
        t->b0 = u * u * u / 6.0;
        t->b2 = (((-3.0 * f + 3.0) * f + 3.0) * f + 1.0) / 6.0;
        t->b3 = f * f * f / 6.0;
    }
}

static inline double bspline_apply(const bspline_tap *t, double c0, double c1,
                                   double c2, double c3)
{
    return c1 + t->b0 * (c0 - c1) + t->b2 * (c2 - c1) + t->b3 * (c3 - c1);
}

/* Per-worker scratch of the reconstruction. */
typedef struct recon_scratch {
    double *tmp;         /* max_lh * w */
    bspline_tap *xt;     /* w */
    bspline_tap *yt;     /* h */
} recon_scratch;

typedef struct recon_job {
    hfs_cpu_pyramid *p;
    recon_scratch *scratch;
} recon_job;

/* Fills the padded (w+1) x (h+1) block from its w x h interior. */
static void pad_edges(double *out, int w, int h)
{
    const size_t stride = (size_t)w + 1;
    for (int j = 0; j < h; ++j)
        out[(size_t)j * stride + (size_t)w] = out[(size_t)j * stride + (size_t)w - 1];
    memcpy(out + (size_t)h * stride, out + (size_t)(h - 1) * stride, stride * sizeof *out);
}

static void reconstruct_level(void *ctx, int row, int worker)
{
    recon_job *job = ctx;
    hfs_cpu_pyramid *p = job->p;
    const int level = p->first_full + row;
    const int w = p->w, h = p->h;
    const size_t stride = (size_t)w + 1;
    double *out = p->full + (size_t)row * p->full_size;

    if (level == p->n_levels - 1) {
        const double *in = p->samples[level];
        for (int j = 0; j < h; ++j)
            memcpy(out + (size_t)j * stride, in + (size_t)j * (size_t)w, (size_t)w * sizeof *out);
        pad_edges(out, w, h);
        return;
    }

    recon_scratch *s = &job->scratch[worker];
    const int lw = p->lw[level], lh = p->lh[level];
    const double *in = p->samples[level];
    bspline_taps(lw, w, s->xt);
    bspline_taps(lh, h, s->yt);
    /* Horizontal pass: every level row to full width. */
    for (int r = 0; r < lh; ++r) {
        const double *src = in + (size_t)r * (size_t)lw;
        double *dst = s->tmp + (size_t)r * (size_t)w;
        for (int g = 0; g < w; ++g) {
            const bspline_tap *t = &s->xt[g];
            dst[g] = bspline_apply(t, src[t->i[0]], src[t->i[1]], src[t->i[2]], src[t->i[3]]);
        }
    }
    /* Vertical pass. */
    for (int g = 0; g < h; ++g) {
        const bspline_tap *t = &s->yt[g];
        const double *r0 = s->tmp + (size_t)t->i[0] * (size_t)w;
        const double *r1 = s->tmp + (size_t)t->i[1] * (size_t)w;
        const double *r2 = s->tmp + (size_t)t->i[2] * (size_t)w;
        const double *r3 = s->tmp + (size_t)t->i[3] * (size_t)w;
        double *dst = out + (size_t)g * stride;
        for (int i = 0; i < w; ++i)
            dst[i] = bspline_apply(t, r0[i], r1[i], r2[i], r3[i]);
    }
    pad_edges(out, w, h);
}

/* ---- object ------------------------------------------------------------------- */

int hfs_cpu_pyramid_create(const hfs_field *f, int k, int first_full,
                           int threads, hfs_cpu_pyramid **out, hfs_error *err)
{
    *out = NULL;
    if (!f || !f->z || f->width < 1 || f->height < 1)
        return hfs_fail(err, HFS_E_INVALID, "pyramid: invalid height field");
    if (k < 1 || k > 64)
        return hfs_fail(err, HFS_E_INVALID, "pyramid: level step k=%d is out of range [1, 64]", k);
    const int w = f->width, h = f->height;
    if ((size_t)w + 1 > SIZE_MAX / sizeof(double) / ((size_t)h + 1))
        return hfs_fail(err, HFS_E_INVALID, "pyramid: field %dx%d is too large", w, h);

    hfs_cpu_pyramid *p = calloc(1, sizeof *p);
    if (!p)
        goto err_nomem;
    p->w = w;
    p->h = h;
    p->k = k;
    p->n_levels = hfs_pyramid_level_count(w, h, k);
    const int n = p->n_levels;
    p->first_full = clampi(first_full, 0, n - 1);
    p->lw = calloc((size_t)n, sizeof *p->lw);
    p->lh = calloc((size_t)n, sizeof *p->lh);
    p->spacing = calloc((size_t)n, sizeof *p->spacing);
    p->samples = calloc((size_t)n, sizeof *p->samples);
    if (!p->lw || !p->lh || !p->spacing || !p->samples)
        goto err_nomem;

    size_t pool = 0;
    for (int i = 0; i < n; ++i) {
        hfs_pyramid_level_size(w, h, k, i, &p->lw[i], &p->lh[i]);
        p->spacing[i] = hfs_pyramid_spacing(n, k, i);
        pool += (size_t)p->lw[i] * (size_t)p->lh[i];
    }
    p->pool = malloc(pool * sizeof *p->pool);
    p->full_size = ((size_t)w + 1) * ((size_t)h + 1);
    const size_t n_full = (size_t)(n - p->first_full);
    if (!p->pool || p->full_size > SIZE_MAX / sizeof(double) / n_full)
        goto err_nomem;
    p->full = malloc(n_full * p->full_size * sizeof *p->full);
    if (!p->full)
        goto err_nomem;

    /* Decimation, fine to coarse; level N-1 is the input in double. */
    size_t at = 0;
    for (int i = 0; i < n; ++i) {
        p->samples[i] = p->pool + at;
        at += (size_t)p->lw[i] * (size_t)p->lh[i];
    }
    for (size_t q = 0; q < (size_t)w * (size_t)h; ++q)
        p->samples[n - 1][q] = (double)f->z[q];
    for (int i = n - 2; i >= 0; --i)
        decimate(p->samples[i + 1], p->lw[i + 1], p->lh[i + 1], p->samples[i], p->lw[i], p->lh[i]);

    /* Reconstruction, one level per parallel "row". */
    int workers = threads > 0 ? threads : hfs_parallel_default_threads();
    if (workers > (int)n_full)
        workers = (int)n_full;
    if (workers > 64)
        workers = 64;
    int max_lh = 1;
    for (int i = p->first_full; i < n - 1; ++i)
        if (p->lh[i] > max_lh)
            max_lh = p->lh[i];
    recon_scratch *scratch = calloc((size_t)workers, sizeof *scratch);
    if (!scratch)
        goto err_nomem;
    int ok = 1;
    for (int t = 0; t < workers && ok; ++t) {
        scratch[t].tmp = malloc((size_t)max_lh * (size_t)w * sizeof(double));
        scratch[t].xt = malloc((size_t)w * sizeof(bspline_tap));
        scratch[t].yt = malloc((size_t)h * sizeof(bspline_tap));
        ok = scratch[t].tmp && scratch[t].xt && scratch[t].yt;
    }
    if (ok) {
        recon_job job = {.p = p, .scratch = scratch};
        hfs_parallel_rows((int)n_full, workers, reconstruct_level, &job, NULL, NULL);
    }
    for (int t = 0; t < workers; ++t) {
        free(scratch[t].tmp);
        free(scratch[t].xt);
        free(scratch[t].yt);
    }
    free(scratch);
    if (!ok)
        goto err_nomem;
    /* The gap search's bounds of the input heights (ray_bound.h). */
    hfs_ray_bound_layout_make(w, h, &p->rb);
    p->rb_atlas = malloc((size_t)p->rb.aw * (size_t)p->rb.ah * sizeof *p->rb_atlas);
    double *rb_scratch = malloc(2 * (size_t)p->rb.lw[1] * (size_t)p->rb.lh[1] * sizeof *rb_scratch);
    if (p->rb_atlas && rb_scratch)
        hfs_ray_bound_build(&p->rb, f->z, 0.0, 1.0, -HUGE_VAL, p->rb_atlas, rb_scratch);
    free(rb_scratch);
    if (!p->rb_atlas || !rb_scratch)
        goto err_nomem;
    *out = p;
    return HFS_OK;

err_nomem:
    hfs_cpu_pyramid_destroy(p);
    return hfs_fail(err, HFS_E_NOMEM, "pyramid: out of memory for a %dx%d field", w, h);
}

void hfs_cpu_pyramid_destroy(hfs_cpu_pyramid *p)
{
    if (!p)
        return;
    free(p->rb_atlas);
    free(p->full);
    free(p->pool);
    free(p->samples);
    free(p->spacing);
    free(p->lh);
    free(p->lw);
    free(p);
}

int hfs_cpu_pyramid_width(const hfs_cpu_pyramid *p) { return p->w; }
int hfs_cpu_pyramid_height(const hfs_cpu_pyramid *p) { return p->h; }
int hfs_cpu_pyramid_k(const hfs_cpu_pyramid *p) { return p->k; }
int hfs_cpu_pyramid_count(const hfs_cpu_pyramid *p) { return p->n_levels; }
int hfs_cpu_pyramid_first_full(const hfs_cpu_pyramid *p) { return p->first_full; }
int hfs_cpu_pyramid_stride(const hfs_cpu_pyramid *p) { return p->w + 1; }

double hfs_cpu_pyramid_spacing(const hfs_cpu_pyramid *p, int level)
{
    return p->spacing[level];
}

void hfs_cpu_pyramid_size(const hfs_cpu_pyramid *p, int level, int *lw, int *lh)
{
    *lw = p->lw[level];
    *lh = p->lh[level];
}

const double *hfs_cpu_pyramid_samples(const hfs_cpu_pyramid *p, int level)
{
    return p->samples[level];
}

const double *hfs_cpu_pyramid_full(const hfs_cpu_pyramid *p, int level)
{
    if (level < p->first_full || level >= p->n_levels)
        return NULL;
    return p->full + (size_t)(level - p->first_full) * p->full_size;
}

double hfs_cpu_pyramid_sample(const hfs_cpu_pyramid *p, int level, double gx, double gy)
{
    const double *r = hfs_cpu_pyramid_full(p, level);
    const size_t stride = (size_t)p->w + 1;
    gx = gx < 0.0 ? 0.0 : (gx > (double)(p->w - 1) ? (double)(p->w - 1) : gx);
    gy = gy < 0.0 ? 0.0 : (gy > (double)(p->h - 1) ? (double)(p->h - 1) : gy);
    const double xf = floor(gx), yf = floor(gy);
    const double fx = gx - xf, fy = gy - yf;
    const double *r0 = r + (size_t)yf * stride + (size_t)xf;
    const double *r1 = r0 + stride;
    const double top = r0[0] + fx * (r0[1] - r0[0]);
    const double bot = r1[0] + fx * (r1[1] - r1[0]);
    return top + fy * (bot - top);
}

const double *hfs_cpu_pyramid_bounds(const hfs_cpu_pyramid *p, const hfs_ray_bound_layout **L)
{
    *L = &p->rb;
    return p->rb_atlas;
}
