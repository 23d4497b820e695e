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

double hfs_ray_bound_search(const hfs_ray_bound_layout *L, const double *atlas, const double *z,
                            size_t stride, int i, int j, double c, double s, double t_first,
                            double t_last, double zs, double tie, double best, double *dist,
                            long *reads)
{
    ray_walk k = walk_make(L->w, L->h, i, j, c, s);
    const double m_last = floor(t_last / k.inv + 1e-4); /* as in float */
    if (m_last < k.last)
        k.last = m_last < 0.0 ? 0 : (int)m_last;
    const int p = k.x_major ? i : j, q = k.x_major ? j : i, nq = k.x_major ? L->h : L->w;
    const double z0 = z[(size_t)j * stride + (size_t)i];
    int m = (int)ceil(t_first / k.inv - 1e-4); /* as in float */
    m = m < 1 ? 1 : m;
    long n_reads = 0;
    int l = 0;
    /* the slope of the crossing *dist names: it moves only past the tie */
    double lead = best;
    while (m <= k.last) {
        const double t = m * k.inv;
        if (l == 0) { /* one crossing: the surface there, exactly */
            double y = q + m * k.r;
            y = y < 0.0 ? 0.0 : (y > nq - 1 ? nq - 1 : y);
            int y0 = (int)floor(y);
            y0 = y0 > nq - 2 ? (nq >= 2 ? nq - 2 : 0) : y0;
            const double f = y - y0;
            const int x = p + k.step * m;
            const double *a = k.x_major ? z + (size_t)y0 * stride + (size_t)x
                                        : z + (size_t)x * stride + (size_t)y0;
            const double b = nq >= 2 ? (k.x_major ? a[stride] : a[1]) : a[0];
            const double v = a[0] + f * (b - a[0]);
            const double sl = (v - z0) * zs / t;
            ++n_reads;
            if (sl > lead + HFS_HORIZON_TIE * fabs(lead) + tie) {
                lead = sl;
                *dist = t;
            }
            best = sl > best ? sl : best;
            ++m;
            l = 1;
            continue;
        }
        const int m1 = m + (1 << l) - 1 > k.last ? k.last : m + (1 << l) - 1;
        /* the run's bounding box of grid points */
        const double ya = q + m * k.r, yb = q + m1 * k.r;
        int q0 = (int)floor((ya < yb ? ya : yb) - RAY_EDGE_TOL);
        int q1 = (int)ceil((ya > yb ? ya : yb) + RAY_EDGE_TOL);
        q0 = q0 < 0 ? 0 : q0;
        q1 = q1 > nq - 1 ? nq - 1 : q1;
        const int pa = p + k.step * m, pb = p + k.step * m1;
        const int p0 = pa < pb ? pa : pb, p1 = pa < pb ? pb : pa;
        const int x0 = k.x_major ? p0 : q0, x1 = k.x_major ? p1 : q1;
        const int y0 = k.x_major ? q0 : p0, y1 = k.x_major ? q1 : p1;
        const int lv = hfs_ray_bound_level(x0, x1, y0, y1);
        const double rise = atlas[(size_t)(L->y0[lv] + (y0 >> lv)) * L->aw +
                                  (size_t)(L->x0[lv] + (x0 >> lv))] - z0;
        ++n_reads;
        /* the largest slope the run can hold: a rise over its nearest
         * crossing, a fall over its farthest */
        if (rise * zs / (rise >= 0.0 ? t : m1 * k.inv) > best) {
            --l;
            continue;
        }
        m = m1 + 1;
        ++l;
    }
    if (reads)
        *reads += n_reads;
    return best;
}
