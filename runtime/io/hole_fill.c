/*
 * hole_fill.c — fills nodata texels of a height field by push-pull
 * (Gortler, Grzeszczuk, Szeliski, Cohen, "The Lumigraph", SIGGRAPH 1996).
 *
 * Push: level L+1 has ceil(W_L/2) x ceil(H_L/2) texels; each is the mean of
 * the VALID texels among its (up to) 2x2 children, or invalid if none is.
 * Repeat to 1x1, which is valid as soon as any input texel is.
 * Pull: from the coarsest level down, every invalid texel of level L takes
 * the bilinear interpolation of level L+1 (already complete) at its own
 * centre, (x - 0.5)/2 in level-(L+1) texel units, clamped to the edge.
 *
 * Invariants: valid input texels are never modified; every output value is a
 * convex combination of valid inputs (means of means, bilinear weights), so
 * it is finite and inside their range; the result depends only on the input
 * (no threads, fixed traversal order).  Cost: O(W*H) time, ~W*H/3 extra
 * floats.  Invalid is encoded as NaN throughout, so no mask is needed.
 */
#include "hfs_io.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct level {
    int w, h;
    float *v;
} level;

static void push(const level *fine, level *coarse)
{
    for (int y = 0; y < coarse->h; ++y) {
        for (int x = 0; x < coarse->w; ++x) {
            double sum = 0.0;
            int count = 0;
            for (int dy = 0; dy < 2; ++dy) {
                int fy = 2 * y + dy;
                if (fy >= fine->h)
                    break;
                for (int dx = 0; dx < 2; ++dx) {
                    int fx = 2 * x + dx;
                    float v;
                    if (fx >= fine->w)
                        break;
                    v = fine->v[(size_t)fy * (size_t)fine->w + (size_t)fx];
                    if (!isnan(v)) {
                        sum += v;
                        ++count;
                    }
                }
            }
            coarse->v[(size_t)y * (size_t)coarse->w + (size_t)x] =
                count ? (float)(sum / count) : NAN;
        }
    }
}

/* Maps fine index i to a clamped coarse coordinate: integer part and weight. */
static void coarse_coord(int i, int n_coarse, int *i0, int *i1, double *t)
{
    double c = (i - 0.5) * 0.5;
    int k;

    if (c <= 0.0) {
        *i0 = *i1 = 0;
        *t = 0.0;
        return;
    }
    if (c >= n_coarse - 1) {
        *i0 = *i1 = n_coarse - 1;
        *t = 0.0;
        return;
    }
    k = (int)c;
    *i0 = k;
    *i1 = k + 1;
    *t = c - k;
}

static void pull(level *fine, const level *coarse)
{
    for (int y = 0; y < fine->h; ++y) {
        int y0, y1;
        double ty;
        coarse_coord(y, coarse->h, &y0, &y1, &ty);
        for (int x = 0; x < fine->w; ++x) {
            float *dst = &fine->v[(size_t)y * (size_t)fine->w + (size_t)x];
            const float *r0, *r1;
            int x0, x1;
            double tx, a, b;
            if (!isnan(*dst))
                continue;
            coarse_coord(x, coarse->w, &x0, &x1, &tx);
            r0 = coarse->v + (size_t)y0 * (size_t)coarse->w;
            r1 = coarse->v + (size_t)y1 * (size_t)coarse->w;
            a = r0[x0] + (r0[x1] - (double)r0[x0]) * tx;
            b = r1[x0] + (r1[x1] - (double)r1[x0]) * tx;
            *dst = (float)(a + (b - a) * ty);
        }
    }
}

int hfs_height_fill_holes(float *z, int width, int height, int has_nodata,
                          float nodata, long *holes, hfs_error *err)
{
    level lv[64];
    int nlev = 1;
    size_t n, extra = 0;
    long count = 0;
    float *pool;

    if (holes)
        *holes = 0;
    if (!z || width < 1 || height < 1)
        return hfs_fail(err, HFS_E_INVALID, "hole fill: invalid field %dx%d", width, height);
    n = (size_t)width * (size_t)height;
    for (size_t k = 0; k < n; ++k)
        if (!isfinite(z[k]) || (has_nodata && z[k] == nodata))
            ++count;
    if (count == 0)
        return HFS_OK;
    if ((size_t)count == n)
        return hfs_fail(err, HFS_E_FORMAT, "no valid heights (all %ld texels are nodata)", count);

    lv[0].w = width;
    lv[0].h = height;
    lv[0].v = z;
    while (lv[nlev - 1].w > 1 || lv[nlev - 1].h > 1) {
        lv[nlev].w = (lv[nlev - 1].w + 1) / 2;
        lv[nlev].h = (lv[nlev - 1].h + 1) / 2;
        extra += (size_t)lv[nlev].w * (size_t)lv[nlev].h;
        ++nlev; /* at most 32 halvings of an int side: lv[64] cannot overflow */
    }
    /* Allocate before touching z so that failure leaves z as it was. */
    pool = malloc((extra ? extra : 1) * sizeof *pool);
    if (!pool)
        return hfs_fail(err, HFS_E_NOMEM, "hole fill: out of memory for %dx%d", width, height);
    {
        size_t off = 0;
        for (int l = 1; l < nlev; ++l) {
            lv[l].v = pool + off;
            off += (size_t)lv[l].w * (size_t)lv[l].h;
        }
    }

    /* One hole encoding from here on. */
    for (size_t k = 0; k < n; ++k)
        if (!isfinite(z[k]) || (has_nodata && z[k] == nodata))
            z[k] = NAN;
    for (int l = 1; l < nlev; ++l)
        push(&lv[l - 1], &lv[l]);
    for (int l = nlev - 2; l >= 0; --l)
        pull(&lv[l], &lv[l + 1]);

    free(pool);
    if (holes)
        *holes = count;
    return HFS_OK;
}
