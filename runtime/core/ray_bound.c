/*
 * ray_bound.c — see ray_bound.h.
 */
#include "ray_bound.h"

#include "pyramid_layout.h"

#include <math.h>

/* Crossings whose minor coordinate lies this far outside the grid still
 * count (clamped): a direction snapped to a rational slope lands on the
 * last row within rounding, in double and in float alike. */
#define RAY_EDGE_TOL 1e-3

void hfs_ray_bound_layout_make(int w, int h, hfs_ray_bound_layout *L)
{
    *L = (hfs_ray_bound_layout){.w = w, .h = h};
    const int n = w > h ? w : h;
    int top = 1;
    while ((1 << top) < n && top + 1 < HFS_RAY_BOUND_MAX_LEVELS)
        ++top;
    L->n_levels = top + 1;
    int y = 0;
    for (int l = 1; l <= top; ++l) {
        L->lw[l] = (w + (1 << l) - 1) >> l;
        L->lh[l] = (h + (1 << l) - 1) >> l;
        L->x0[l] = l == 1 ? 0 : L->lw[1];
        L->y0[l] = l == 1 ? 0 : y;
        if (l >= 2)
            y += L->lh[l];
    }
    L->aw = L->lw[1] + (top >= 2 ? L->lw[2] : 0);
    L->ah = L->lh[1] > y ? L->lh[1] : y;
}

static double max2(double a, double b) { return a > b ? a : b; }

/* Level l's 2x2-block bounds into the atlas from its plain block maxima g
 * (lw x lh). */
static void store_level(const hfs_ray_bound_layout *L, int l, const double *g, double *atlas)
{
    const int lw = L->lw[l], lh = L->lh[l];
    for (int b = 0; b < lh; ++b)
        for (int a = 0; a < lw; ++a) {
            double v = g[(size_t)b * lw + a];
            if (a + 1 < lw)
                v = max2(v, g[(size_t)b * lw + a + 1]);
            if (b + 1 < lh) {
                v = max2(v, g[(size_t)(b + 1) * lw + a]);
                if (a + 1 < lw)
                    v = max2(v, g[(size_t)(b + 1) * lw + a + 1]);
            }
            atlas[(size_t)(L->y0[l] + b) * L->aw + (size_t)(L->x0[l] + a)] = v;
        }
}

void hfs_ray_bound_build(const hfs_ray_bound_layout *L, const float *z, double base,
                         double scale, double fill, double *atlas, double *scratch)
{
    for (size_t t = 0; t < (size_t)L->aw * L->ah; ++t)
        atlas[t] = fill;
    /* level 1: the plain maxima of 2x2 points */
    double *g = scratch, *next = scratch + (size_t)L->lw[1] * L->lh[1];
    for (int b = 0; b < L->lh[1]; ++b)
        for (int a = 0; a < L->lw[1]; ++a) {
            double v = -INFINITY;
            for (int y = 2 * b; y < 2 * b + 2 && y < L->h; ++y)
                for (int x = 2 * a; x < 2 * a + 2 && x < L->w; ++x)
                    v = max2(v, ((double)z[(size_t)y * L->w + x] - base) / scale);
            g[(size_t)b * L->lw[1] + a] = v;
        }
    for (int l = 1; l < L->n_levels; ++l) {
        store_level(L, l, g, atlas);
        if (l + 1 == L->n_levels)
            break;
        const int pw = L->lw[l], ph = L->lh[l], nw = L->lw[l + 1], nh = L->lh[l + 1];
        for (int b = 0; b < nh; ++b)
            for (int a = 0; a < nw; ++a) {
                double v = -INFINITY;
                for (int y = 2 * b; y < 2 * b + 2 && y < ph; ++y)
                    for (int x = 2 * a; x < 2 * a + 2 && x < pw; ++x)
                        v = max2(v, g[(size_t)y * pw + x]);
                next[(size_t)b * nw + a] = v;
            }
        double *t = g;
        g = next;
        next = t;
    }
}

int hfs_ray_bound_level(int x0, int x1, int y0, int y1)
{
    int l = 1;
    while ((x1 >> l) - (x0 >> l) > 1 || (y1 >> l) - (y0 >> l) > 1)
        ++l;
    return l;
}

/* One direction's crossings from a grid point: the major axis' step, the
 * minor coordinate's slope r per crossing, and the last crossing inside
 * the grid. */
typedef struct ray_walk {
    int x_major;      /* 1: x is the major axis */
    int step;         /* +-1 along the major axis */
    double r;         /* minor coordinate per crossing */
    double inv;       /* distance per crossing, 1 / |major component| */
    int last;         /* the last crossing inside the grid */
} ray_walk;

static ray_walk walk_make(int w, int h, int i, int j, double c, double s)
{
    ray_walk k;
    k.x_major = fabs(c) >= fabs(s);
    const double ma = k.x_major ? c : s, mi = k.x_major ? s : c;
    k.step = ma >= 0.0 ? 1 : -1;
    k.inv = 1.0 / fabs(ma);
    k.r = mi / fabs(ma);
    const int p = k.x_major ? i : j, q = k.x_major ? j : i, np = k.x_major ? w : h,
              nq = k.x_major ? h : w;
    k.last = k.step > 0 ? np - 1 - p : p;
    if (k.r > 0.0) {
        const double lim = floor((nq - 1 - q + RAY_EDGE_TOL) / k.r);
        if (lim < k.last)
            k.last = (int)lim;
    } else if (k.r < 0.0) {
        const double lim = floor((q + RAY_EDGE_TOL) / -k.r);
        if (lim < k.last)
            k.last = (int)lim;
    }
    return k;
}

/* One search's state: the ray from its receiver, the result so far and
 * (cells) the column of heights the last segment ended on, which the next
 * one starts from. */
typedef struct ray_search {
    const hfs_ray_bound_layout *L;
    const double *atlas, *z;
    size_t stride;
    ray_walk k;
    int p, q, nq;              /* the receiver's major, minor coordinate; minor size */
    double z0, zs, tie;
    double best, lead, *dist;  /* lead: the slope *dist names */
    long reads;
    int col_u, col_v0, col_n;  /* the kept column: major u, rows v0 .. v0 + n - 1 */
    double col[3];
} ray_search;

/* A surface point's slope sl at distance t: the max, and the lead past
 * the tie (ray_bound.h). */
static void take(ray_search *S, double sl, double t)
{
    if (sl > S->lead + HFS_HORIZON_TIE * fabs(S->lead) + S->tie) {
        S->lead = sl;
        *S->dist = t;
    }
    S->best = sl > S->best ? sl : S->best;
}

/* Rows v0 .. v0 + n - 1 (n <= 3) of major column u, from the kept column
 * where it holds them. */
static void column(ray_search *S, int u, int v0, int n, double *out)
{
    for (int r = 0; r < n; ++r) {
        const int v = v0 + r;
        if (u == S->col_u && v >= S->col_v0 && v < S->col_v0 + S->col_n) {
            out[r] = S->col[v - S->col_v0];
            continue;
        }
        const int x = S->k.x_major ? u : v, y = S->k.x_major ? v : u;
        out[r] = S->z[(size_t)y * S->stride + (size_t)x];
        ++S->reads;
    }
}

/* The minor coordinate at u crossings, clamped to the grid. */
static double minor_at(const ray_search *S, double u)
{
    const double y = S->q + u * S->k.r;
    return y < 0.0 ? 0.0 : (y > S->nq - 1 ? S->nq - 1 : y);
}

/* Crossing m's surface from its column c (rows v0 ..): the minor axis'
 * linear interpolation (a row that weighs 0 is not needed). */
static double crossing_from(const ray_search *S, int m, const double *c, int v0)
{
    const double y = minor_at(S, m);
    int y0 = (int)floor(y);
    y0 = y0 > S->nq - 2 ? S->nq - 2 : y0;
    const double f = y - y0, a = c[y0 - v0];
    return f == 0.0 ? a : a + f * (c[y0 + 1 - v0] - a);
}

/* One crossing alone (the crossings' search, a one-row grid): one read,
 * its two heights being one pair. */
static void crossing(ray_search *S, int m)
{
    const double y = minor_at(S, m);
    int y0 = (int)floor(y);
    y0 = y0 > S->nq - 2 ? (S->nq >= 2 ? S->nq - 2 : 0) : y0;
    const int x = S->p + S->k.step * m;
    const double *a = S->k.x_major ? S->z + (size_t)y0 * S->stride + (size_t)x
                                   : S->z + (size_t)x * S->stride + (size_t)y0;
    const double b = S->nq >= 2 ? (S->k.x_major ? a[S->stride] : a[1]) : a[0];
    const double v = a[0] + (y - y0) * (b - a[0]);
    ++S->reads;
    take(S, (v - S->z0) * S->zs / (m * S->k.inv), m * S->k.inv);
}

/* The ray's cells from a0 to a1 crossings past crossing m (0 <= a0 < a1
 * <= 1; ray_bound.h "cells"), crossing m where a0 = 0 and crossing m + 1
 * where a1 = 1, from the columns of the two crossings (2-3 rows each, the
 * first kept from the segment before); a1 = 0: crossing m alone, from its
 * column, which is then the one kept (the last crossing: the segment
 * before kept its rows).  Split where the ray crosses a
 * minor grid line, a piece's surface is the quadratic z(a) = A + B a + C a^2 (relative to z0) of one
 * bilinear cell; its slope z / (m + a) peaks inside only where C < 0, at
 * the root of C a^2 + 2 C m a + (B m - A) = 0 nearer 0, written so that
 * nothing cancels at large m.  Takes the crossings (value and lead) and,
 * as a value only, that point and every piece's far end. */
static void segment(ray_search *S, int m, double a0, double a1)
{
    const ray_walk *k = &S->k;
    const double ya = S->q + m * k->r, yb = S->q + (m + a1) * k->r;
    const double y0 = S->q + (m + a0) * k->r; /* where the stretch starts */
    const double ca = minor_at(S, m + a0), cb = minor_at(S, m + a1);
    int v_lo = (int)floor(ca < cb ? ca : cb), v_hi = (int)ceil(ca > cb ? ca : cb);
    v_lo = v_lo > S->nq - 2 ? S->nq - 2 : v_lo;
    v_hi = v_hi < v_lo + 1 ? v_lo + 1 : v_hi;
    const int u0 = S->p + k->step * m, n = v_hi - v_lo + 1, lone = !(a1 > 0.0);
    double c0[3], c1[3] = {0.0, 0.0, 0.0};
    column(S, u0, v_lo, n, c0);
    if (!lone)
        column(S, u0 + k->step, v_lo, n, c1);
    S->col_u = lone ? u0 : u0 + k->step, S->col_v0 = v_lo, S->col_n = n;
    for (int r = 0; r < n; ++r)
        S->col[r] = lone ? c0[r] : c1[r];
    if (a0 <= 0.0)
        take(S, (crossing_from(S, m, c0, v_lo) - S->z0) * S->zs / (m * k->inv), m * k->inv);
    if (lone)
        return;
    if (a1 >= 1.0)
        take(S, (crossing_from(S, m + 1, c1, v_lo) - S->z0) * S->zs / ((m + 1) * k->inv),
             (m + 1) * k->inv);
    /* the cells lie below their highest corner: most never reach the best */
    double top = -HUGE_VAL;
    for (int r = 0; r < n; ++r)
        top = fmax(top, fmax(c0[r], c1[r]) - S->z0);
    if (top * S->zs / ((top >= 0.0 ? m + a0 : m + a1) * k->inv) <= S->best)
        return;
    double cut = -1.0; /* where the ray crosses a minor grid line inside */
    if (k->r > 0.0 && floor(y0) + 1.0 < yb)
        cut = (floor(y0) + 1.0 - ya) / k->r;
    else if (k->r < 0.0 && ceil(y0) - 1.0 > yb)
        cut = (ceil(y0) - 1.0 - ya) / k->r;
    cut = cut > a0 ? cut : -1.0;
    const double ends[3] = {a0, cut > 0.0 ? cut : a1, a1};
    for (int pc = 0; pc < (cut > 0.0 ? 2 : 1); ++pc) {
        const double lo = ends[pc], hi = ends[pc + 1];
        int v0 = (int)floor(S->q + (m + 0.5 * (lo + hi)) * k->r);
        v0 = v0 < v_lo ? v_lo : (v0 > v_hi - 1 ? v_hi - 1 : v0);
        const double z00 = c0[v0 - v_lo] - S->z0, z10 = c1[v0 - v_lo] - S->z0;
        const double z01 = c0[v0 + 1 - v_lo] - S->z0, z11 = c1[v0 + 1 - v_lo] - S->z0;
        const double b0 = ya - v0, e = z11 - z10 - z01 + z00;
        const double A = z00 + (z01 - z00) * b0, B = z10 - z00 + (z01 - z00) * k->r + e * b0;
        const double C = e * k->r;
        /* the far end (a crossing's is taken above), the inner peak and,
         * where the stretch starts past a crossing, its near end */
        double at[3] = {hi < 1.0 ? hi : -1.0, -1.0, pc == 0 && a0 > 0.0 ? a0 : -1.0};
        if (C < 0.0) {
            const double D = C * C * m * m - C * (B * m - A);
            if (D >= 0.0)
                at[1] = (B * m - A) / (sqrt(D) - C * m);
        }
        for (int i = 0; i < 3; ++i) {
            const double a = at[i];
            if (!(i == 2 ? a >= lo : a > lo && a <= hi))
                continue;
            double b = b0 + k->r * a;
            b = b < 0.0 ? 0.0 : (b > 1.0 ? 1.0 : b);
            const double v = z00 + (z10 - z00) * a + (z01 - z00) * b + e * a * b;
            /* the value only: the lead (dist) stays a crossing's, so that a
             * cell's peak a rounding above a crossing beside it cannot move
             * the occluder a grid receiver lends its texels (the float and
             * double searches, fp16 and fp32 heights, would name different
             * points) */
            const double sl = v * S->zs / ((m + a) * k->inv);
            S->best = sl > S->best ? sl : S->best;
        }
    }
}

/* The bound, relative to z0, of the grid points of the ray's stretch from
 * ua to ub crossings (its columns floor(ua) .. ceil(ub), its rows the
 * minor coordinate's floor and ceiling there, within the edge tolerance):
 * one read of the max pyramid. */
static double box_rise(ray_search *S, double ua, double ub)
{
    const ray_walk *k = &S->k;
    const hfs_ray_bound_layout *L = S->L;
    const double ya = S->q + ua * k->r, yb = S->q + ub * k->r;
    int q0 = (int)floor((ya < yb ? ya : yb) - RAY_EDGE_TOL);
    int q1 = (int)ceil((ya > yb ? ya : yb) + RAY_EDGE_TOL);
    q0 = q0 < 0 ? 0 : q0;
    q1 = q1 > S->nq - 1 ? S->nq - 1 : q1;
    const int pa = S->p + k->step * (int)floor(ua), pb = S->p + k->step * (int)ceil(ub);
    const int p0 = pa < pb ? pa : pb, p1 = pa < pb ? pb : pa;
    const int x0 = k->x_major ? p0 : q0, x1 = k->x_major ? p1 : q1;
    const int y0 = k->x_major ? q0 : p0, y1 = k->x_major ? q1 : p1;
    const int lv = hfs_ray_bound_level(x0, x1, y0, y1);
    ++S->reads;
    return S->atlas[(size_t)(L->y0[lv] + (y0 >> lv)) * L->aw + (size_t)(L->x0[lv] + (x0 >> lv))] -
           S->z0;
}

/* The crossings (cells = 0) or the whole ray (cells = 1) from t_first to
 * t_last: ray_bound.h. */
static double search(const hfs_ray_bound_layout *L, const double *atlas, const double *z,
                     size_t stride, int i, int j, double c, double s, double t_first,
                     double t_last, double zs, double tie, double best, double *dist,
                     long *reads, int cells, const double *z0)
{
    ray_search S = {.L = L, .atlas = atlas, .z = z, .stride = stride, .zs = zs, .tie = tie,
                    .best = best, .lead = best, .dist = dist, .col_u = -1};
    ray_walk *k = &S.k;
    *k = walk_make(L->w, L->h, i, j, c, s);
    const double m_last = floor(t_last / k->inv + 1e-4); /* as in float */
    if (m_last < k->last)
        k->last = m_last < 0.0 ? 0 : (int)m_last;
    S.p = k->x_major ? i : j, S.q = k->x_major ? j : i, S.nq = k->x_major ? L->h : L->w;
    const int p = S.p, q = S.q, nq = S.nq;
    S.z0 = z0 ? *z0 : z[(size_t)j * stride + (size_t)i];
    cells = cells && nq >= 2; /* one row: the surface is linear between crossings */
    const double u0 = t_first / k->inv; /* in crossings */
    int m = (int)ceil(u0 - 1e-4);        /* as in float */
    m = m < 1 ? 1 : m;
    const int m_first = m;
    /* with cells, where the ray ends: the radius, or where it leaves the
     * grid (the crossings' search needs no more than k->last) */
    double u_end = 0.0;
    if (cells) {
        const int np = k->x_major ? L->w : L->h;
        const double side = k->step > 0 ? np - 1 - p : p;
        u_end = t_last / k->inv;
        u_end = side < u_end ? side : u_end;
        if (k->r != 0.0) {
            const double out = k->r > 0.0 ? (nq - 1 - q) / k->r : q / -k->r;
            u_end = out < u_end ? out : u_end;
        }
    }
    /* with cells, the stretch from t_first to its first crossing (past the
     * receiver's own cell, whose slope peaks at an end): a search that
     * continues another from t_first leaves no gap between them */
    if (cells && m_first >= 2 && m_first - u0 > 1e-4 && u_end > u0) {
        const int ms = m_first - 1;
        const double a1 = u_end - ms < 1.0 ? u_end - ms : 1.0;
        /* solved where its cells' bound (one read) can beat the start */
        const double rise = box_rise(&S, u0, ms + a1);
        if (rise * zs / ((rise >= 0.0 ? u0 : ms + a1) * k->inv) > S.best)
            segment(&S, ms, u0 - ms, a1);
    }
    int l = 0;
    while (m <= k->last) {
        const double t = m * k->inv;
        if (l == 0) { /* one crossing (and with cells its segment): exactly */
            if (cells) /* the last crossing from its column, which the segment before kept */
                segment(&S, m, 0.0, m < k->last ? 1.0 : 0.0);
            else
                crossing(&S, m);
            ++m;
            l = 1;
            continue;
        }
        const int m1 = m + (1 << l) - 1 > k->last ? k->last : m + (1 << l) - 1;
        /* the run's bounding box of grid points; with cells, also those of
         * the cells on to the next crossing (a skipped run bounds them) */
        const int mb = cells && m1 < k->last ? m1 + 1 : m1;
        const double rise = box_rise(&S, m, mb);
        /* the largest slope the run can hold: a rise over its nearest
         * crossing, a fall over its farthest */
        if (rise * zs / (rise >= 0.0 ? t : mb * k->inv) > S.best) {
            --l;
            continue;
        }
        m = m1 + 1;
        ++l;
    }
    if (cells && k->last >= m_first && u_end - k->last > 0.0) /* past the last crossing */
        segment(&S, k->last, 0.0, u_end - k->last < 1.0 ? u_end - k->last : 1.0);
    if (reads)
        *reads += S.reads;
    return S.best;
}

double hfs_ray_bound_search(const hfs_ray_bound_layout *L, const double *atlas, const double *z,
                            size_t stride, int i, int j, double c, double s, double t_first,
                            double t_last, double zs, double tie, double best, double *dist,
                            long *reads)
{
    return search(L, atlas, z, stride, i, j, c, s, t_first, t_last, zs, tie, best, dist, reads, 0,
                  NULL);
}

double hfs_ray_bound_search_from(const hfs_ray_bound_layout *L, const double *atlas,
                                 const double *z, size_t stride, int i, int j, double z0,
                                 double c, double s, double t_first, double zs, double tie,
                                 double best, double *dist)
{
    return search(L, atlas, z, stride, i, j, c, s, t_first, HUGE_VAL, zs, tie, best, dist, NULL,
                  0, &z0);
}

double hfs_ray_bound_search_cells(const hfs_ray_bound_layout *L, const double *atlas,
                                  const double *z, size_t stride, int i, int j, double c,
                                  double s, double t_first, double t_last, double zs, double tie,
                                  double best, double *dist, long *reads)
{
    return search(L, atlas, z, stride, i, j, c, s, t_first, t_last, zs, tie, best, dist, reads, 1,
                  NULL);
}
