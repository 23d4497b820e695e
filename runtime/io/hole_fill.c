/*
 * hole_fill.c — fills nodata texels of a height field by push-pull
 * (Gortler, Grzeszczuk, Szeliski, Cohen, "The Lumigraph", SIGGRAPH 1996).
 *
 * Push: level L+1 has ceil(W_L/2) x ceil(H_L/2) texels; each is the mean of
 * the VALID texels among its (up to) 2x2 children, or invalid if none is.
 * Repeat to 1x1, which is valid as soon as any input texel is.
 * Pull: from the coarsest level down, every invalid texel of level L takes
 * the bilinear interpolation of level L+1 (already complete) at its own
 * position, clamped to the edge.  A level-(L+1) texel sits at the centre of
 * its children: level-L coordinate 2X + 0.5, i.e. level-(L+1) coordinate
 * (x - 0.5)/2 for level-L texel x.
 *
 * Odd sizes.  When W_L is odd, the last column of level L+1 has one child
 * column, the last one (and likewise rows): that texel sits ON level-L
 * column W_L - 1, not half a texel past the border, so the pull's last
 * interval is 3/4 of a texel wide and level-L column W_L - 1 reads that
 * texel alone (coarse_coord).  And when that lone child column is all
 * holes (a missing border line), the texel takes the valid texels of the
 * column beside it instead, as an even level's last block would
 * (lone_fallback): otherwise it would be a hole too, with no sibling to
 * fill it, at every odd level up, and the border line would be filled from
 * a level far coarser than the hole (a 9-wide ramp 0..7 missing its last
 * column got 4.625, now 7).  So every border behaves as the first row and
 * column of any level do: a missing border line gets the next line's values
 * (heights are never extrapolated: see below), interpolated along the border
 * between level-(L+1) texel centres and clamped beyond the first and last.
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

static float at(const level *l, int x, int y)
{
    return l->v[(size_t)y * (size_t)l->w + (size_t)x];
}

/* Mean of the valid texels of fine[y0..y1][x0..x1], or NaN if none is. */
static float block_mean(const level *fine, int x0, int x1, int y0, int y1)
{
    double sum = 0.0;
    int count = 0;
    for (int fy = y0; fy <= y1; ++fy)
        for (int fx = x0; fx <= x1; ++fx) {
            const float v = at(fine, fx, fy);
            if (!isnan(v)) {
                sum += v;
                ++count;
            }
        }
    return count ? (float)(sum / count) : NAN;
}

/* The lone border texel of an odd level (children: the last column and/or
 * row alone) whose children are all holes: see "Odd sizes" above.  The
 * lone corner (both) takes its row and column neighbours, or if both are
 * holes its diagonal one: the texels an even level's corner block holds. */
static float lone_fallback(const level *fine, int x0, int x1, int y0, int y1)
{
    const int lx = x1 == x0 && x0 > 0, ly = y1 == y0 && y0 > 0;
    if (lx && ly) {
        const float a = at(fine, x0 - 1, y0), b = at(fine, x0, y0 - 1);
        if (isnan(a) && isnan(b))
            return at(fine, x0 - 1, y0 - 1);
        return isnan(a) ? b : isnan(b) ? a : (float)(0.5 * ((double)a + b));
    }
    if (lx)
        return block_mean(fine, x0 - 1, x0 - 1, y0, y1);
    if (ly)
        return block_mean(fine, x0, x1, y0 - 1, y0 - 1);
    return NAN;
}

static void push(const level *fine, level *coarse)
{
    for (int y = 0; y < coarse->h; ++y) {
        const int y0 = 2 * y, y1 = 2 * y + 1 < fine->h ? 2 * y + 1 : fine->h - 1;
        for (int x = 0; x < coarse->w; ++x) {
            const int x0 = 2 * x, x1 = 2 * x + 1 < fine->w ? 2 * x + 1 : fine->w - 1;
            float v = block_mean(fine, x0, x1, y0, y1);
            if (isnan(v))
                v = lone_fallback(fine, x0, x1, y0, y1);
            coarse->v[(size_t)y * (size_t)coarse->w + (size_t)x] = v;
        }
    }
}

/* Maps fine index i to a clamped coarse coordinate: integer part and weight.
 * Coarse texel k is centred at c = k, except the last one of an odd-sized
 * fine level: its only child is fine n_fine - 1, at c = n_coarse - 1.25. */
static void coarse_coord(int i, int n_fine, int n_coarse, int *i0, int *i1, double *t)
{
    const int last = n_coarse - 1;
    const double c_last = (n_fine & 1) ? last - 0.25 : last;
    double c = (i - 0.5) * 0.5;
    int k;

    if (c <= 0.0) {
        *i0 = *i1 = 0;
        *t = 0.0;
        return;
    }
    if (c >= c_last) {
        *i0 = *i1 = last;
        *t = 0.0;
        return;
    }
    k = (int)c;
    *i0 = k;
    *i1 = k + 1;
    *t = k + 1 == last ? (c - k) / (c_last - k) : c - k;
}

static void pull(level *fine, const level *coarse)
{
    for (int y = 0; y < fine->h; ++y) {
        int y0, y1;
        double ty;
        coarse_coord(y, fine->h, coarse->h, &y0, &y1, &ty);
        for (int x = 0; x < fine->w; ++x) {
            float *dst = &fine->v[(size_t)y * (size_t)fine->w + (size_t)x];
            const float *r0, *r1;
            int x0, x1;
            double tx, a, b;
            if (!isnan(*dst))
                continue;
            coarse_coord(x, fine->w, coarse->w, &x0, &x1, &tx);
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
