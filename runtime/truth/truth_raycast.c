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
#include "truth_walk.h"

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

/* ---- rays ---------------------------------------------------------------------- */

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
    int ci = hfs_truth_cell_of(ox, u, ncx), cj = hfs_truth_cell_of(oy, v, ncy);
    int level = 0;
    double t = 0.0;
    for (;;) {
        if (ci < 0 || ci >= ncx || cj < 0 || cj >= ncy)
            return 0; /* left the grid: no terrain beyond */
        if (use_tree && w >= 0.0 && oz + t * w > ztop)
            return 0; /* above everything from here on */
        const hfs_truth_node nd = hfs_truth_node_at(ci, cj, level, ncx, ncy);
        const double tx = hfs_truth_exit_param(ox, u, nd.x0, nd.x1);
        const double ty = hfs_truth_exit_param(oy, v, nd.y0, nd.y1);
        double te = tx < ty ? tx : ty;
        if (te < t)
            te = t;
        const double tend = te < tmax ? te : tmax;

        if (use_tree) {
            const double zlo = w >= 0.0 ? oz + t * w : oz + tend * w;
            const double zn =
                (double)g->zmax[level][(size_t)nd.ny * g->lw[level] + nd.nx] + g->margin;
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
        hfs_truth_walk_step(ox, oy, u, v, te, tx, ty, &nd, ncx, ncy, &ci, &cj);
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
