/*
 * truth_raycast.c — see truth_raycast.h.
 *
 * Both queries walk the max mip "stacklessly": at the current position take
 * the node of the current level that contains it; if the node provably
 * cannot matter (its max height is below what would count), jump past it
 * and climb one level, otherwise descend; at level 0 do the exact work for
 * that cell.  Every jump only skips samples / segments that the plain
 * version would have found harmless, so results are unchanged.
 */
#include "truth_raycast.h"

#include "field_geom.h"

#include <math.h>
#include <stdlib.h>

static float round_up_to_float(double v)
{
    float r = (float)v;
    if ((double)r < v)
        r = nextafterf(r, INFINITY);
    return r;
}

void hfs_truth_grid_free(hfs_truth_grid *g)
{
    if (!g)
        return;
    for (int l = 0; l < HFS_TRUTH_MAX_LEVELS; ++l) {
        free(g->zmax[l]);
        g->zmax[l] = NULL;
    }
    g->n_levels = 0;
}

int hfs_truth_grid_init(hfs_truth_grid *g, const hfs_field *f)
{
    *g = (hfs_truth_grid){.f = f, .w = f->width, .h = f->height};
    const int cw = f->width - 1, ch = f->height - 1;

    double lo = INFINITY, hi = -INFINITY;
    for (int j = 0; j < f->height; ++j)
        for (int i = 0; i < f->width; ++i) {
            const double z = hfs_field_z(f, i, j);
            lo = z < lo ? z : lo;
            hi = z > hi ? z : hi;
        }
    g->z_lo = lo;
    g->z_hi = hi;
    /* Covers rounding of bilinear evaluation (a few ulps of |z|) and, in
     * the ray test, of cell-local positions (~1e-16 texel * W, times slopes
     * up to hi - lo per texel), with a wide safety factor.  Kept small next
     * to the receiver lift (1e-4 dx) so that flat ground is still skipped. */
    g->margin = 1e-12 * (fabs(lo) + fabs(hi)) + 1e-10 * (hi - lo) + 1e-300;

    g->lw[0] = cw;
    g->lh[0] = ch;
    g->zmax[0] = malloc((size_t)cw * (size_t)ch * sizeof(float));
    if (!g->zmax[0])
        goto err_nomem;
    for (int j = 0; j < ch; ++j)
        for (int i = 0; i < cw; ++i) {
            double m = hfs_field_z(f, i, j);
            const double z10 = hfs_field_z(f, i + 1, j);
            const double z01 = hfs_field_z(f, i, j + 1);
            const double z11 = hfs_field_z(f, i + 1, j + 1);
            m = z10 > m ? z10 : m;
            m = z01 > m ? z01 : m;
            m = z11 > m ? z11 : m;
            g->zmax[0][(size_t)j * cw + i] = round_up_to_float(m);
        }
    int l = 0;
    while (g->lw[l] > 1 || g->lh[l] > 1) {
        if (l + 1 >= HFS_TRUTH_MAX_LEVELS)
            goto err_nomem; /* unreachable for int-sized fields */
        const int pw = g->lw[l], ph = g->lh[l];
        const int nw = (pw + 1) / 2, nh = (ph + 1) / 2;
        float *src = g->zmax[l];
        float *dst = malloc((size_t)nw * (size_t)nh * sizeof(float));
        if (!dst)
            goto err_nomem;
        for (int j = 0; j < nh; ++j)
            for (int i = 0; i < nw; ++i) {
                float m = -INFINITY;
                for (int b = 0; b < 2; ++b)
                    for (int a = 0; a < 2; ++a) {
                        const int si = 2 * i + a, sj = 2 * j + b;
                        if (si < pw && sj < ph) {
                            const float v = src[(size_t)sj * pw + si];
                            m = v > m ? v : m;
                        }
                    }
                dst[(size_t)j * nw + i] = m;
            }
        ++l;
        g->zmax[l] = dst;
        g->lw[l] = nw;
        g->lh[l] = nh;
    }
    g->n_levels = l + 1;
    return HFS_OK;

err_nomem:
    hfs_truth_grid_free(g);
    return HFS_E_NOMEM;
}

/* ---- horizons --------------------------------------------------------------- */

/* Sample k of the march; one definition shared by both marches so that they
 * see bit-identical positions. */
static inline void march_pos(int i, int j, double c, double s, double t,
                             double *gx, double *gy)
{
    *gx = (double)i + t * c;
    *gy = (double)j + t * s;
}

/* hfs_field_bilinear's in-grid predicate. */
static inline int in_grid(const hfs_field *f, double gx, double gy)
{
    return gx >= 0.0 && gy >= 0.0 && gx <= (double)(f->width - 1) &&
           gy <= (double)(f->height - 1);
}

/* Parameter at which p0 + t*dir leaves [lo, hi] (dir != 0), else +inf. */
static inline double exit_param(double p0, double dir, double lo, double hi)
{
    if (dir > 0.0)
        return (hi - p0) / dir;
    if (dir < 0.0)
        return (lo - p0) / dir;
    return INFINITY;
}

double hfs_truth_horizon_plain(const hfs_field *f, int i, int j, double z0,
                               double c, double s, double step)
{
    double m = -INFINITY;
    for (long k = 1;; ++k) {
        const double t = (double)k * step;
        double gx, gy, z;
        march_pos(i, j, c, s, t, &gx, &gy);
        if (!hfs_field_bilinear(f, gx, gy, &z))
            break;
        const double sl = (z - z0) / (t * f->dx);
        if (sl > m)
            m = sl;
    }
    return m;
}

/* Slope of the in-grid march sample at distance t: hfs_field_bilinear
 * inlined with the identical arithmetic, so both marches agree bit for bit. */
static inline double sample_slope(const hfs_field *f, int i, int j, double z0,
                                  double c, double s, double t)
{
    const int w = f->width;
    double px, py;
    march_pos(i, j, c, s, t, &px, &py);
    int ci = (int)px, cj = (int)py;
    ci = ci < w - 2 ? ci : w - 2;
    cj = cj < f->height - 2 ? cj : f->height - 2;
    const double fx = px - ci, fy = py - cj;
    const float *r0 = f->z + (size_t)cj * (size_t)w + (size_t)ci, *r1 = r0 + w;
    const double zs = f->zscale;
    const double z00 = zs * (double)r0[0], z10 = zs * (double)r0[1];
    const double z01 = zs * (double)r1[0], z11 = zs * (double)r1[1];
    const double z = (z00 * (1.0 - fx) + z10 * fx) * (1.0 - fy) +
                     (z01 * (1.0 - fx) + z11 * fx) * fy;
    return (z - z0) / (t * f->dx);
}

/* Number of leading march samples inside the grid (positions are monotone
 * in k, so in-grid samples form a prefix). */
static long march_count(const hfs_field *f, int i, int j, double c, double s,
                        double step)
{
    const double te = fmin(exit_param(i, c, 0.0, f->width - 1),
                           exit_param(j, s, 0.0, f->height - 1));
    long k = (long)floor(te / step);
    if (k < 0)
        k = 0;
    double gx, gy;
    for (;;) { /* at most a step or two either way */
        if (k >= 1) {
            march_pos(i, j, c, s, (double)k * step, &gx, &gy);
            if (!in_grid(f, gx, gy)) {
                --k;
                continue;
            }
        }
        march_pos(i, j, c, s, (double)(k + 1) * step, &gx, &gy);
        if (in_grid(f, gx, gy)) {
            ++k;
            continue;
        }
        return k;
    }
}

double hfs_truth_horizon(const hfs_truth_grid *g, int i, int j, double z0,
                         double c, double s, double step, double cutoff, long *hint)
{
    const hfs_field *f = g->f;
    const long n = march_count(f, i, j, c, s, step);
    const int ncx = g->w - 1, ncy = g->h - 1;
    const int top = g->n_levels - 1;
    const double dxw = f->dx, margin = g->margin;
    const double dz_top = g->z_hi + margin - z0;
    const double inv_c = c != 0.0 ? 1.0 / c : 0.0, inv_s = s != 0.0 ? 1.0 / s : 0.0;
    const double inv_step = 1.0 / step;
    /* m: the running maximum, never below cutoff (samples at or below it are
     * irrelevant to the caller, and skipping them is what makes flat ground
     * cheap).  Skip tests compare dz <= m * t * dx rather than dividing; the
     * node margin (1e-9 of the height scale) dwarfs that rounding. */
    double m = cutoff;
    long best = 0;
    /* The maximum does not depend on the order of the samples: evaluating
     * the hinted one first only raises m early, so more gets skipped. */
    if (hint && *hint >= 1 && *hint <= n) {
        const double sl = sample_slope(f, i, j, z0, c, s, (double)*hint * step);
        if (sl > m) {
            m = sl;
            best = *hint;
        }
    }
    int level = 0;
    long k = 1;
    while (k <= n) {
        const double t = (double)k * step;
        if (dz_top >= 0.0 && dz_top <= m * (t * dxw))
            break; /* nothing anywhere ahead can rise above m */
        double gx, gy;
        march_pos(i, j, c, s, t, &gx, &gy);
        int cx = (int)gx, cy = (int)gy; /* >= 0: sample k is in the grid */
        cx = cx < ncx ? cx : ncx - 1;
        cy = cy < ncy ? cy : ncy - 1;
        const int nx = cx >> level, ny = cy >> level;
        const int x0 = nx << level, y0 = ny << level;
        const int x1 = x0 + (1 << level) < ncx ? x0 + (1 << level) : ncx;
        const int y1 = y0 + (1 << level) < ncy ? y0 + (1 << level) : ncy;
        const double tx = c > 0.0 ? (x1 - i) * inv_c : c < 0.0 ? (x0 - i) * inv_c : INFINITY;
        const double ty = s > 0.0 ? (y1 - j) * inv_s : s < 0.0 ? (y0 - j) * inv_s : INFINITY;
        const double te = tx < ty ? tx : ty;
        /* Last sample surely inside the node (closed box), at least k. */
        long kend = (long)((te - 1e-9 * (1.0 + te)) * inv_step);
        if (kend > n)
            kend = n;
        if (kend < k)
            kend = k;
        if (m > -INFINITY) {
            const double dz = (double)g->zmax[level][(size_t)ny * g->lw[level] + nx] +
                              margin - z0;
            /* Can any sample k..kend of this node have a slope above m? */
            const int skip = dz >= 0.0 ? dz <= m * (t * dxw)
                                       : dz <= m * ((double)kend * step * dxw);
            if (skip) {
                k = kend + 1;
                if (level < top)
                    ++level;
                continue;
            }
        }
        if (level > 0) {
            --level;
            continue;
        }
        for (long kk = k; kk <= kend; ++kk) {
            const double sl = sample_slope(f, i, j, z0, c, s, (double)kk * step);
            if (sl > m) {
                m = sl;
                best = kk;
            }
        }
        k = kend + 1;
    }
    if (hint)
        *hint = best;
    return m > cutoff ? m : -INFINITY;
}

/* ---- rays ---------------------------------------------------------------------- */

/* Index of the cell the ray enters at coordinate p moving with sign(dir);
 * a ray along a grid line (dir == 0) may take either neighbour (the bilinear
 * surface agrees on the shared edge), clamped into [0, ncell-1]. */
static inline int cell_of(double p, double dir, int ncell)
{
    if (p < -2.0)
        p = -2.0;
    if (p > ncell + 2.0)
        p = ncell + 2.0;
    if (dir > 0.0)
        return (int)floor(p);
    if (dir < 0.0)
        return (int)ceil(p) - 1;
    int c = (int)floor(p);
    return c < 0 ? 0 : (c > ncell - 1 ? ncell - 1 : c);
}

/* The smallest s in [0, len] with c0 + b s + a s^2 <= 0, for a segment
 * cell_hit finds hitting (so one exists up to rounding, which the
 * fallbacks absorb: the vertex, else the end). */
static double first_root(double c0, double b, double a, double len)
{
    if (c0 <= 0.0)
        return 0.0;
    double best = INFINITY;
    if (a == 0.0) {
        if (b < 0.0)
            best = -c0 / b;
    } else {
        const double disc = b * b - 4.0 * a * c0;
        if (disc >= 0.0) {
            const double q = -0.5 * (b + copysign(sqrt(disc), b));
            const double r[2] = {q / a, q != 0.0 ? c0 / q : INFINITY};
            for (int k = 0; k < 2; ++k)
                if (r[k] >= 0.0 && r[k] < best)
                    best = r[k];
        } else if (a > 0.0) {
            best = -b / (2.0 * a); /* the minimum only touches 0 */
        }
    }
    return best <= len ? best : len;
}

/* Exact test of the ray segment t in [ta, tb] against the bilinear patch of
 * cell (ci, cj).  With s = t - ta and the cell-local position (fx, fy) at ta,
 * g(s) = ray z - surface z = C + B s + A s^2; hit iff min over [0, tb-ta]
 * of g is <= 0 (end points and, for A > 0, the vertex).  On a hit, *t_hit
 * (when non-NULL) gets the first t where g <= 0 (first_root). */
static int cell_hit(const hfs_field *f, int ci, int cj, const double o[3],
                    double u, double v, double w, double ta, double tb, double *t_hit)
{
    const double z00 = hfs_field_z(f, ci, cj), z10 = hfs_field_z(f, ci + 1, cj);
    const double z01 = hfs_field_z(f, ci, cj + 1), z11 = hfs_field_z(f, ci + 1, cj + 1);
    const double ex = z10 - z00, ey = z01 - z00, exy = (z11 - z10) - (z01 - z00);
    const double fx = (o[0] - ci) + ta * u, fy = (o[1] - cj) + ta * v;
    const double c0 = (o[2] + ta * w) - (z00 + ex * fx + ey * fy + exy * fx * fy);
    if (c0 <= 0.0) {
        if (t_hit)
            *t_hit = ta;
        return 1;
    }
    const double b = w - (ex * u + ey * v + exy * (fx * v + fy * u));
    const double a = -exy * u * v;
    const double len = tb - ta;
    int hit;
    if (isinf(len))
        hit = a < 0.0 || (a == 0.0 && b < 0.0);
    else if (!(len > 0.0))
        hit = 0;
    else
        hit = c0 + len * (b + len * a) <= 0.0 ||
              (a > 0.0 && b < 0.0 && -b < 2.0 * a * len && c0 - b * b / (4.0 * a) <= 0.0);
    if (hit && t_hit)
        *t_hit = ta + first_root(c0, b, a, len);
    return hit;
}

/* Walks the ray's cells in order; the first that hits holds the first hit
 * (its parameter into *t_hit when non-NULL). */
static int ray_walk(const hfs_truth_grid *g, const double o[3], const double d[3],
                    double tmax, int use_tree, double *t_hit)
{
    const hfs_field *f = g->f;
    const int ncx = g->w - 1, ncy = g->h - 1;
    const double u = d[0] / f->dx, v = d[1] / f->dx, w = d[2];
    const double ox = o[0], oy = o[1], oz = o[2];
    const int top = g->n_levels - 1;
    const double ztop = (double)g->zmax[top][0] + g->margin;
    if (!(tmax > 0.0))
        return 0;
    int ci = cell_of(ox, u, ncx), cj = cell_of(oy, v, ncy);
    int level = 0;
    double t = 0.0;
    for (;;) {
        if (ci < 0 || ci >= ncx || cj < 0 || cj >= ncy)
            return 0; /* left the grid: no terrain beyond */
        if (use_tree && w >= 0.0 && oz + t * w > ztop)
            return 0; /* above everything from here on */
        const int nx = ci >> level, ny = cj >> level;
        const int x0 = nx << level, y0 = ny << level;
        const int x1 = x0 + (1 << level) < ncx ? x0 + (1 << level) : ncx;
        const int y1 = y0 + (1 << level) < ncy ? y0 + (1 << level) : ncy;
        const double tx = exit_param(ox, u, x0, x1), ty = exit_param(oy, v, y0, y1);
        double te = tx < ty ? tx : ty;
        if (te < t)
            te = t;
        const double tend = te < tmax ? te : tmax;

        if (use_tree) {
            const double zlo = w >= 0.0 ? oz + t * w : oz + tend * w;
            const double zn = (double)g->zmax[level][(size_t)ny * g->lw[level] + nx] + g->margin;
            if (!(zlo > zn)) {
                if (level > 0) {
                    --level;
                    continue;
                }
                if (cell_hit(f, ci, cj, o, u, v, w, t, tend, t_hit))
                    return 1;
            } else if (level < top) {
                ++level; /* skipped: climb (the node below is still addressed by ci, cj) */
                /* the jump below uses this node's bounds x0..y1 */
            }
        } else if (cell_hit(f, ci, cj, o, u, v, w, t, tend, t_hit)) {
            return 1;
        }

        if (te >= tmax)
            return 0; /* the segment up to the light is clear (also te = inf) */
        t = te;
        if (tx <= ty) {
            const int nci = u > 0.0 ? x1 : x0 - 1;
            if (v != 0.0) {
                int c = cell_of(oy + te * v, v, ncy);
                c = v > 0.0 ? (c > cj ? c : cj) : (c < cj ? c : cj);
                cj = c < y0 ? y0 : (c > y1 - 1 ? y1 - 1 : c);
            }
            ci = nci;
        } else {
            const int ncj = v > 0.0 ? y1 : y0 - 1;
            if (u != 0.0) {
                int c = cell_of(ox + te * u, u, ncx);
                c = u > 0.0 ? (c > ci ? c : ci) : (c < ci ? c : ci);
                ci = c < x0 ? x0 : (c > x1 - 1 ? x1 - 1 : c);
            }
            cj = ncj;
        }
    }
}

int hfs_truth_ray_hits(const hfs_truth_grid *g, const double o[3],
                       const double d[3], double tmax)
{
    return ray_walk(g, o, d, tmax, 1, NULL);
}

int hfs_truth_ray_first_hit(const hfs_truth_grid *g, const double o[3], const double d[3],
                            double tmax, double *t)
{
    return ray_walk(g, o, d, tmax, 1, t);
}

int hfs_truth_ray_hits_plain(const hfs_truth_grid *g, const double o[3],
                             const double d[3], double tmax)
{
    return ray_walk(g, o, d, tmax, 0, NULL);
}
