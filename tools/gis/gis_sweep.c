/*
 * gis_sweep.c — see gis_sweep.h.
 */
#include "gis_sweep.h"

#include "gis_sweep_blocks.h"
#include "parallel.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>

#define HFS_SWEEP_HALF_PI 1.5707963267948966

/* A crossing this close outside the field's side is on it (ray_bound.c's
 * RAY_EDGE_TOL, so a ray along the last row keeps its crossings). */
#define EDGE_TOL 1e-3

/* One azimuth's frame: u runs along its major axis in the direction of
 * the rays, v across it so that the rays climb in v (r >= 0); the field's
 * index of (u, v) is off + u du + v dv. */
typedef struct sweep_dir {
    int nu, nv;      /* the field's size along u and v                  */
    ptrdiff_t off, du, dv;
    double r;        /* v gained per column, |minor / major|, in [0, 1] */
    double unit;     /* horizontal world distance of one column: dx / |major| */
    gis_sweep_frame frame; /* the same frame by axes and signs (the blocks') */
} sweep_dir;

static void dir_make(sweep_dir *d, const hfs_field *f, double phi)
{
    const double c = cos(phi), s = sin(phi);
    const int xm = fabs(c) >= fabs(s);
    const double ma = xm ? c : s, mi = xm ? s : c;
    const ptrdiff_t w = f->width, h = f->height;
    /* steps along x and y of one u and one v, and the origin's (x, y) */
    const ptrdiff_t su = ma >= 0.0 ? 1 : -1, sv = mi >= 0.0 ? 1 : -1;
    d->nu = xm ? f->width : f->height;
    d->nv = xm ? f->height : f->width;
    const ptrdiff_t x0 = (xm ? su : sv) > 0 ? 0 : w - 1, y0 = (xm ? sv : su) > 0 ? 0 : h - 1;
    d->off = y0 * w + x0;
    d->du = xm ? su : su * w;
    d->dv = xm ? sv * w : sv;
    d->r = fabs(mi) / fabs(ma);
    d->unit = f->dx / fabs(ma);
    d->frame = (gis_sweep_frame){xm, su > 0, sv > 0, d->nu, d->nv, d->r};
}

/* The field's index of (u, v). */
static inline size_t texel_of(const sweep_dir *d, int u, int v)
{
    return (size_t)(d->off + (ptrdiff_t)u * d->du + (ptrdiff_t)v * d->dv);
}

/* The height (world units) where column u is crossed at v = y: linear
 * between the two texels about y, y clamped to the field. */
static double crossing(const hfs_field *f, const sweep_dir *d, int u, double y)
{
    y = y < 0.0 ? 0.0 : (y > d->nv - 1 ? d->nv - 1 : y);
    int y0 = (int)y;
    if (y0 > d->nv - 2)
        y0 = d->nv >= 2 ? d->nv - 2 : 0;
    const double a = f->z[texel_of(d, u, y0)];
    const double b = d->nv >= 2 ? f->z[texel_of(d, u, y0 + 1)] : a;
    return f->zscale * (a + (y - y0) * (b - a));
}

/* The last crossing of the ray from (u, v) inside the field; where the
 * ray stays within the rows for more than cap + 2 columns, possibly a
 * larger number (the field's end along u).  Its callers only compare it
 * with cap, and most texels are spared the division (the margin covers
 * its rounding). */
static int last_crossing(const sweep_dir *d, int u, int v, int cap)
{
    int last = d->nu - 1 - u;
    const double room = d->nv - 1 - v + EDGE_TOL;
    if (d->r > 0.0 && room < (cap + 3.0) * d->r) {
        const double lim = room / d->r;
        if (lim < last)
            last = (int)floor(lim);
    }
    return last;
}

/* The upper convex hull of a line's surface points beyond the texels
 * still to come, nearest last: (x, z) in columns and world units. */
typedef struct hull {
    double *x, *z;
    int n;
    double ztop;  /* the highest z added since the line began (a vertex) */
    double *rise; /* a worker's scratch for line_bounds, a column each */
} hull;

/* Adds a point nearer than all the hull holds; drops the ones that fall
 * under the hull with it (each point leaves at most once). */
static inline void hull_add(hull *h, double x, double z)
{
    while (h->n >= 2 &&
           (h->z[h->n - 1] - z) * (h->x[h->n - 2] - x) <= (h->z[h->n - 2] - z) * (h->x[h->n - 1] - x))
        --h->n;
    h->x[h->n] = x, h->z[h->n] = z, ++h->n;
    h->ztop = z > h->ztop ? z : h->ztop;
}

/* A slope as a fraction, rise num (world units) over den columns: the
 * searches compare candidates by cross-multiplication and divide once, at
 * the end (a division per winning candidate was the sweep's largest cost).
 * {-1, 0} is no candidate yet: every candidate (den > 0) beats it. */
typedef struct slope {
    double num, den;
} slope;

/* Whether num / den (den > 0) is steeper than b. */
static inline int steeper(double num, double den, slope b)
{
    return num * b.den > b.num * den;
}

/* The steepest slope from (x, z), nearer than every point of the hull:
 * along the hull the slopes rise to the tangent's vertex and fall after
 * it, so a binary search finds it. */
static slope hull_tangent(const hull *h, double x, double z)
{
    int lo = 0, hi = h->n - 1; /* index 0 the farthest */
    while (lo < hi) {
        const int mid = (lo + hi + 1) / 2;
        if ((h->z[mid - 1] - z) * (h->x[mid] - x) > (h->z[mid] - z) * (h->x[mid - 1] - x))
            hi = mid - 1;
        else
            lo = mid;
    }
    return (slope){h->z[lo] - z, h->x[lo] - x};
}

/* One cell's part of a line from column u (a = 0) to u + 1 (a = 1): for
 * a in [lo, hi] the line stays in one cell, and the bilinear surface along
 * it is z(a) = A + B a + C a^2 (world units). */
typedef struct piece {
    double lo, hi, A, B, C;
} piece;

/* The piece for a in [lo, hi] of the cell from column u and row y0 (the
 * next row y0 + 1, or y0 itself on a one-row field), the line at b0 + rb a
 * rows above y0 (b0 may be negative: the cell after a row crossing). */
static inline piece piece_make(const hfs_field *f, const sweep_dir *d, int u, int y0, double lo,
                        double hi, double b0, double rb)
{
    const int y1 = d->nv >= 2 ? y0 + 1 : y0;
    const size_t t00 = texel_of(d, u, y0), t01 = texel_of(d, u, y1);
    const double zs = f->zscale;
    const double z00 = zs * f->z[t00], z10 = zs * f->z[(size_t)((ptrdiff_t)t00 + d->du)];
    const double z01 = zs * f->z[t01], z11 = zs * f->z[(size_t)((ptrdiff_t)t01 + d->du)];
    const double e = z11 - z10 - z01 + z00;
    return (piece){lo, hi, z00 + (z01 - z00) * b0, z10 - z00 + (z01 - z00) * rb + e * b0, e * rb};
}

/* The pieces (one or two: the line crosses at most one row between two
 * columns, r <= 1) of the line from (u, y) to (u + 1, y + r); at the
 * field's side the heights clamped as `crossing` clamps them. */
static inline int pieces_of(const hfs_field *f, const sweep_dir *d, int u, double y, piece p[2])
{
    const double r = d->r;
    if (y >= 0.0 && y + r <= d->nv - 1 && d->nv >= 2) { /* inside: no clamp */
        int y0 = (int)y;
        y0 = y0 > d->nv - 2 ? d->nv - 2 : y0;
        const double b0 = y - y0;
        if (y0 + 1 < y + r && y0 + 1 < d->nv - 1) { /* crosses row y0 + 1 */
            const double cut = (y0 + 1 - y) / r;
            p[0] = piece_make(f, d, u, y0, 0.0, cut, b0, r);
            p[1] = piece_make(f, d, u, y0 + 1, cut, 1.0, b0 - 1.0, r);
            return 2;
        }
        p[0] = piece_make(f, d, u, y0, 0.0, 1.0, b0, r);
        return 1;
    }
    /* at the field's side: the line clamped to its last row, as crossings
     * are (a line outside the field runs along it) */
    const double yc = y < 0.0 ? 0.0 : (y > d->nv - 1 ? d->nv - 1 : y);
    int y0 = (int)yc;
    y0 = y0 > d->nv - 2 ? (d->nv >= 2 ? d->nv - 2 : 0) : y0;
    p[0] = piece_make(f, d, u, y0, 0.0, 1.0, d->nv >= 2 ? yc - y0 : 0.0, 0.0);
    return 1;
}

/* best raised by a concave piece's (C < 0) interior: where the slope of
 * (z(a) - zp) / (m + a) turns, C a^2 + 2 C m a + (B m - A + zp) = 0, the
 * root past -m, if it lies inside the piece. */
static inline slope piece_root(const piece *p, double m, double zp, slope best)
{
    const double q = m * m - (p->B * m - p->A + zp) / p->C;
    if (q >= 0.0) {
        const double a = -m + sqrt(q), den = m + a;
        const double num = p->A + (p->B + p->C * a) * a - zp;
        if (a > p->lo && a < p->hi && den > 0.0 && steeper(num, den, best))
            best = (slope){num, den};
    }
    return best;
}

/* best raised to the steepest slope (rise per column) from height zp at
 * column distance m before the piece's a = 0: its ends, and inside it
 * where the slope of (z(a) - zp) / (m + a) turns (a concave piece, C < 0:
 * the surface along the ray bulges above the chord, a twisted cell). */
static inline slope piece_max(const piece *p, double m, double zp, slope best)
{
    /* from the texel itself (m = 0, a = 0, A = zp): the surface's slope
     * leaving it, the limit of the ratio as a -> 0 (its own cell, which
     * rises from the texel at B however near) */
    if (m == 0.0 && p->lo == 0.0 && steeper(p->B, 1.0, best))
        best = (slope){p->B, 1.0};
    const double ends[2] = {p->lo, p->hi};
    for (int k = 0; k < 2; ++k) {
        const double a = ends[k], den = m + a, num = p->A + (p->B + p->C * a) * a - zp;
        if (den > 0.0 && steeper(num, den, best))
            best = (slope){num, den};
    }
    return p->C < 0.0 ? piece_root(p, m, zp, best) : best;
}

/* best raised by texel (u, v)'s own ray over its first `own` columns
 * (own >= 1), the ray within the field's rows there (v + own r <= nv - 1,
 * nv >= 2): pieces_of's pieces and piece_max's candidates with each
 * surface point read once.  A column's crossing is taken as the next
 * column's start (A: the same bits as piece_max's a = 0 end), a row's
 * crossing along its row, the last column's end as a crossing too; a
 * piece's coefficients are made only for the slope leaving the texel and
 * where the piece bulges (the same arithmetic as piece_make and
 * piece_max there).  The ends piece_max also takes at a = 1 and at a
 * row's crossing are those same points by another rounding. */
static slope own_inside(const hfs_field *f, const sweep_dir *d, int u, int v, int own, double zp,
                        slope best)
{
    const double r = d->r, zs = f->zscale;
    const ptrdiff_t su = d->du, sv = d->dv;
    for (int m = 0;; ++m) {
        const double y = v + m * r;
        int y0 = (int)y;
        y0 = y0 > d->nv - 2 ? d->nv - 2 : y0;
        const double b0 = y - y0;
        const ptrdiff_t t = (ptrdiff_t)texel_of(d, u + m, y0);
        const double z00 = zs * f->z[t], z01 = zs * f->z[t + sv];
        const double A = z00 + (z01 - z00) * b0; /* column u + m's crossing */
        if (m > 0 && steeper(A - zp, m, best))
            best = (slope){A - zp, m};
        if (m == own)
            return best;
        const double z10 = zs * f->z[t + su], z11 = zs * f->z[t + su + sv];
        const double e = z11 - z10 - z01 + z00;
        const int cross = y0 + 1 < y + r && y0 + 1 < d->nv - 1;
        const double cut = cross ? (y0 + 1 - y) / r : 1.0;
        if (m == 0 || e * r < 0.0) {
            const piece p = {0.0, cut, A, z10 - z00 + (z01 - z00) * r + e * b0, e * r};
            if (m == 0 && steeper(p.B, 1.0, best)) /* the slope leaving the texel */
                best = (slope){p.B, 1.0};
            best = p.C < 0.0 ? piece_root(&p, m, zp, best) : best;
        }
        if (cross) { /* row y0 + 1's crossing, then the cell above it */
            const double zr = z01 + (z11 - z01) * cut - zp;
            if (steeper(zr, m + cut, best))
                best = (slope){zr, m + cut};
            const double z02 = zs * f->z[t + 2 * sv], z12 = zs * f->z[t + su + 2 * sv];
            if ((z12 - z11 - z02 + z01) * r < 0.0) {
                const piece q = piece_make(f, d, u + m, y0 + 1, cut, 1.0, b0 - 1.0, r);
                best = piece_root(&q, m, zp, best);
            }
        }
    }
}

/* The angles wanted, [lo, hi] radians (hfs_horizon_desc's window; the
 * whole [-pi/2, pi/2] without one), and as rises per column of the
 * azimuth at hand (-inf / +inf where they cut nothing). */
typedef struct sweep_window {
    double lo, hi, rlo, rhi;
    double eps; /* what a candidate's rounding can add to its rise (line_bounds) */
} sweep_window;

/* Texel (u, v)'s horizon clamped to w: the bilinear surface along its own
 * ray up to `near` columns, exactly, then the tangent to its line's hull.
 * A hull that already hides the window's top decides it without the near
 * columns (they can only raise it), and a rise outside the window needs
 * no arctangent: the same values as clamping afterwards.  With rise (a
 * sun above the horizontal: line_bounds) the own columns are left out
 * where they cannot rise to the window's bottom. */
static float texel_horizon(const hfs_field *f, const sweep_dir *d, const hull *h, int near,
                           const double *rise, int u, int v, const sweep_window *w)
{
    const int last = last_crossing(d, u, v, near);
    if (last < 1)
        return (float)w->lo;
    const double zp = f->zscale * f->z[texel_of(d, u, v)];
    /* the hull first: a steep far horizon leaves the near candidates
     * fewer wins.  Not searched where no slope to it reaches the window
     * (a sun above a ridge's texels): its highest point as if at its
     * nearest (or, below the texel, at its farthest); then its tangent
     * could only lose to the bottom or to a near candidate. */
    slope best = {-1.0, 0.0};
    if (h->n > 0 && last > near) {
        const double top = h->ztop - zp, span = (top >= 0.0 ? h->x[h->n - 1] : h->x[0]) - u;
        if (!(top + w->eps < w->rlo * span))
            best = hull_tangent(h, u, zp);
    }
    if (best.den > 0.0 && best.num >= w->rhi * best.den)
        return (float)w->hi;
    int own = last < near ? last : near;
    if (rise) { /* line_bounds: the steepest its own columns can rise */
        double g = -HUGE_VAL;
        for (int m = 0; m < own; ++m)
            g = rise[u + m] > g ? rise[u + m] : g;
        own = g + w->eps < w->rlo ? 0 : own;
    }
    if (own > 0 && d->nv >= 2 && v + own * d->r <= d->nv - 1)
        best = own_inside(f, d, u, v, own, zp, best);
    else
        for (int m = 0; m < own; ++m) { /* the cells from column u + m to u + m + 1 */
            piece p[2];
            const int n = pieces_of(f, d, u + m, v + m * d->r, p);
            for (int k = 0; k < n; ++k)
                best = piece_max(&p[k], m, zp, best);
        }
    if (!(best.den > 0.0) || best.num <= w->rlo * best.den)
        return (float)w->lo;
    if (best.num >= w->rhi * best.den)
        return (float)w->hi;
    const float g = (float)atan(best.num / best.den / d->unit); /* rise per column, then angle */
    return g < w->lo ? (float)w->lo : g > w->hi ? (float)w->hi : g;
}

/* Adds line k's surface points from column u to u + 1 (nearer than all
 * the hull holds): the crossings at u, a row crossing between, and each
 * concave piece's highest point (what a distant texel's tangent meets). */
static void hull_add_cell(const hfs_field *f, const sweep_dir *d, hull *h, int u, double y)
{
    if (u + 1 <= d->nu - 1) {
        piece p[2];
        const int n = pieces_of(f, d, u, y, p);
        for (int k = n - 1; k >= 0; --k) {
            const piece *q = &p[k];
            if (q->C < 0.0) {
                const double a = -q->B / (2.0 * q->C);
                if (a > q->lo && a < q->hi)
                    hull_add(h, u + a, q->A + (q->B + q->C * a) * a);
            }
            if (q->lo > 0.0)
                hull_add(h, u + q->lo, q->A + (q->B + q->C * q->lo) * q->lo);
        }
    }
    hull_add(h, u, crossing(f, d, u, y));
}

/* A window's rise per column on a column of `unit` world units: tan(a)
 * unit, or +-inf at +-pi/2 and beyond (nothing cut there). */
static double window_rise(double a, double unit)
{
    return a >= HFS_SWEEP_HALF_PI ? HUGE_VAL : a <= -HFS_SWEEP_HALF_PI ? -HUGE_VAL : tan(a) * unit;
}

/* Line k's band at column u, the rows its texels' own rays cross (at
 * most half a row aside of the line at y = k + r u: floor(y) - 2 ..
 * floor(y) + 3, in the field): its lowest and highest height, and the
 * largest differences along u (to column u + 1) and along v (to the next
 * row), world units, none below 0, and the largest along v either way.
 * None where no texel's ray and no hull point comes near. */
typedef struct band {
    double zmin, zmax, du, dv;
    double dv_abs; /* the largest |difference| along v */
} band;

static band band_column(const hfs_field *f, const sweep_dir *d, long k, int u)
{
    const double zs = f->zscale, y = (double)k + d->r * u;
    band b = {HUGE_VAL, -HUGE_VAL, 0.0, 0.0, 0.0};
    if (y < -1.5 || y > d->nv + 0.5)
        return b;
    const int fy = (int)floor(y); /* y is within the field's rows, give or take 2 */
    const int j0 = fy - 2 > 0 ? fy - 2 : 0, j1 = fy + 3 < d->nv - 1 ? fy + 3 : d->nv - 1;
    double prev = 0.0;
    for (int j = j0; j <= j1; ++j) {
        const double z = zs * f->z[texel_of(d, u, j)];
        b.zmin = z < b.zmin ? z : b.zmin;
        b.zmax = z > b.zmax ? z : b.zmax;
        if (j > j0) {
            b.dv = z - prev > b.dv ? z - prev : b.dv;
            b.dv_abs = fabs(z - prev) > b.dv_abs ? fabs(z - prev) : b.dv_abs;
        }
        if (u + 1 < d->nu) {
            const double rise = zs * f->z[texel_of(d, u + 1, j)] - z;
            b.du = rise > b.du ? rise : b.du;
        }
        prev = z;
    }
    return b;
}

/* What line k's texels can see below the window's bottom rlo (a rise per
 * column, > 0: a sun's disk above the horizontal), from bounds alone, in
 * one pass over its bands:
 *   - along its texels' own rays every chord, and the slope leaving the
 *     texel, rises at most g = du + r dv a column, the largest differences
 *     of the cells the rays cross (a cell's rise along the ray, z_u +
 *     r z_v, blends its edges' differences: its u differences, and its v
 *     differences at both its columns);
 *   - its hull's points (at least `near` columns from the texel that asks)
 *     rise at most zmax - zmin above it, the extremes of its bands
 *     (bilinear heights lie within their cell's corners), and at most g a
 *     column along the texel's ray plus the line's offset from it (at most
 *     half a row, dv_abs a row) over `near` columns.
 * Where a bound stays below rlo, with w->eps for the candidates' rounding
 * (their denominators are at least a column), that part cannot reach the
 * window: *use_hull / *own say whether each is still wanted.  A high sun's
 * lines skip both, and the result is the same as the whole search's.
 * rise[u] is g for the cells from column u to u + 1 alone: a texel's own
 * columns u .. u + m rise at most the largest of theirs. */
static void extent_decide(const gis_sweep_extent *e, double r, const sweep_window *w, int near,
                          int *use_hull, int *own)
{
    const double g = e->du + r * e->dv;
    *use_hull = !(e->zmax - e->zmin + w->eps < w->rlo * near ||
                  g + 0.5 * e->dv_abs / near + w->eps < w->rlo);
    *own = !(g + w->eps < w->rlo);
}

/* The decision above from line k's own bands, and each column's rise. */
static void line_bounds(const hfs_field *f, const sweep_dir *d, long k, const sweep_window *w,
                        int near, double *rise, int *use_hull, int *own)
{
    gis_sweep_extent e = {HUGE_VAL, -HUGE_VAL, 0.0, 0.0, 0.0};
    band b = band_column(f, d, k, 0);
    for (int u = 0; u < d->nu; ++u) {
        const band next = u + 1 < d->nu ? band_column(f, d, k, u + 1) : b;
        rise[u] = b.du + d->r * (next.dv > b.dv ? next.dv : b.dv);
        e.zmin = b.zmin < e.zmin ? b.zmin : e.zmin;
        e.zmax = b.zmax > e.zmax ? b.zmax : e.zmax;
        e.du = b.du > e.du ? b.du : e.du;
        e.dv = b.dv > e.dv ? b.dv : e.dv;
        e.dv_abs = b.dv_abs > e.dv_abs ? b.dv_abs : e.dv_abs;
        b = next;
    }
    extent_decide(&e, d->r, w, near, use_hull, own);
}

/* The lines of an azimuth's sweep: k0..k1 (v = k + r u), each walked from
 * the field's end. */
static void sweep_lines(const sweep_dir *d, long *k0, long *k1)
{
    *k0 = (long)floor(-d->r * (d->nu - 1)) - 1;
    *k1 = d->nv;
}

/* One azimuth's lines k in [ka, kb): each walked from the field's end.
 * Each texel is written by exactly one line (the one nearest its own),
 * so any split of the lines gives the same values.  eps: line_bounds'.
 * With blocks (a window above the horizontal) a line is first decided
 * from them, and only where they leave it open from its own bands: the
 * blocks' extent is never below the bands', so the two agree wherever
 * the blocks clear a line (gis_sweep_blocks.h). */
static void sweep_azimuth(const hfs_field *f, double phi, int near, double lo, double hi,
                          double eps, const gis_sweep_blocks *blocks, long ka, long kb, hull *h,
                          float *out)
{
    sweep_dir d;
    dir_make(&d, f, phi);
    const sweep_window w = {lo, hi, window_rise(lo, d.unit), window_rise(hi, d.unit), eps};
    const double r = d.r;
    for (long k = ka; k < kb; ++k) {
        int use_hull = 1, own = 1;
        const double *rise = NULL;
        if (w.rlo > 0.0 && blocks) {
            const gis_sweep_extent e = gis_sweep_blocks_line(blocks, &d.frame, k);
            extent_decide(&e, r, &w, near, &use_hull, &own);
        }
        if (w.rlo > 0.0 && (use_hull || own)) {
            line_bounds(f, &d, k, &w, near, h->rise, &use_hull, &own);
            rise = own ? h->rise : NULL; /* not the whole line's columns: maybe a texel's */
        }
        h->n = 0;
        h->ztop = -HUGE_VAL;
        for (int u = d.nu - 1; u >= 0; --u) {
            const int ui = u + near; /* the column that joins the hull now */
            if (use_hull && ui <= d.nu - 1) {
                const double y = (double)k + r * ui;
                if (y >= -EDGE_TOL && y <= d.nv - 1 + EDGE_TOL)
                    hull_add_cell(f, &d, h, ui, y);
            }
            /* the texel whose own line is nearest this one here: row
             * ceil(t), by truncation (towards zero: up for t < 0; t is
             * within the field's size of it, far inside a long; with
             * ceil this line took 2.2% of the horizon command's
             * instructions, 1.1% now) */
            const double t = (double)k + r * u - 0.5;
            long v = (long)t;
            v += t > (double)v;
            if (v < 0 || v > d.nv - 1)
                continue;
            out[texel_of(&d, u, (int)v)] =
                use_hull || own ? texel_horizon(f, &d, h, near, rise, u, (int)v, &w) : (float)w.lo;
        }
    }
}

typedef struct sweep_run {
    const hfs_field *f;
    const double *phi;
    double lo, hi, eps;
    int bands;   /* each azimuth's lines in this many parts */
    const gis_sweep_blocks *blocks; /* with a window above the horizontal, else NULL */
    float *out;
    hull *hulls; /* one per worker */
} sweep_run;

/* Part row % bands of azimuth row / bands, on worker `worker` (parallel.h:
 * each part one worker's). */
static void sweep_row(void *ctx, int row, int worker)
{
    const sweep_run *s = ctx;
    const int k = row / s->bands, b = row % s->bands;
    const size_t texels = (size_t)s->f->width * (size_t)s->f->height;
    sweep_dir d;
    dir_make(&d, s->f, s->phi[k]);
    long k0, k1;
    sweep_lines(&d, &k0, &k1);
    const long n = k1 + 1 - k0;
    sweep_azimuth(s->f, s->phi[k], GIS_SWEEP_NEAR, s->lo, s->hi, s->eps, s->blocks,
                  k0 + n * b / s->bands, k0 + n * (b + 1) / s->bands, &s->hulls[worker],
                  s->out + (size_t)k * texels);
}

int gis_sweep_horizons(const hfs_field *f, const double *phi, int n, int threads, float *out,
                       hfs_error *err)
{
    return gis_sweep_horizons_in(f, phi, n, threads, -HFS_SWEEP_HALF_PI, HFS_SWEEP_HALF_PI, out,
                                 err);
}

int gis_sweep_horizons_in(const hfs_field *f, const double *phi, int n, int threads, double lo,
                          double hi, float *out, hfs_error *err)
{
    if (!f || !f->z || f->width < 1 || f->height < 1 || !(f->dx > 0.0) || !phi || n < 0 || !out)
        return hfs_fail(err, HFS_E_INVALID, "sweep: a bad field or azimuths");
    if (!(lo >= -HFS_SWEEP_HALF_PI && lo <= hi && hi <= HFS_SWEEP_HALF_PI))
        return hfs_fail(err, HFS_E_INVALID, "sweep: a bad window [%g, %g]", lo, hi);
    for (int k = 0; k < n; ++k)
        if (!isfinite(phi[k]))
            return hfs_fail(err, HFS_E_INVALID, "sweep: azimuth %d is not finite", k);
    int workers = threads > 0 ? threads : hfs_parallel_default_threads();
    workers = workers < 1 ? 1 : workers;
    /* fewer azimuths than workers (a sun's one): each azimuth's lines in
     * parts, 4 a worker so that the short corner lines even out */
    const int bands = n >= workers || n == 0 ? 1 : (4 * workers + n - 1) / n;
    /* a line's hull holds at most 4 points a column: its crossing, a row's
     * and the tops of two bulging pieces (a concave profile keeps them all) */
    const size_t side = 4 * (size_t)(f->width > f->height ? f->width : f->height) + 4;
    hull *hulls = calloc((size_t)workers, sizeof *hulls);
    int rc = hulls ? HFS_OK : HFS_E_NOMEM;
    for (int w = 0; w < workers && !rc; ++w) {
        hulls[w].x = malloc(side * sizeof *hulls[w].x);
        hulls[w].z = malloc(side * sizeof *hulls[w].z);
        hulls[w].rise = malloc(side * sizeof *hulls[w].rise);
        rc = hulls[w].x && hulls[w].z && hulls[w].rise ? HFS_OK : HFS_E_NOMEM;
    }
    /* a window above the horizontal: the lines decided from blocks first */
    gis_sweep_blocks blocks = {0};
    if (!rc && lo > 0.0)
        rc = gis_sweep_blocks_make(&blocks, f, workers);
    if (!rc) {
        /* a candidate's rise is a difference of heights over at least a
         * column, rounded: far less than this on any field */
        const double zabs = lo > 0.0 ? gis_sweep_blocks_zabs(&blocks) : 0.0;
        sweep_run run = {.f = f, .phi = phi, .lo = lo, .hi = hi, .eps = 1e-9 * (1.0 + zabs),
                         .bands = bands, .blocks = lo > 0.0 ? &blocks : NULL, .out = out,
                         .hulls = hulls};
        hfs_parallel_rows(n * bands, workers, sweep_row, &run, NULL, NULL);
    } else {
        hfs_fail(err, rc, "sweep: out of memory for a %dx%d field", f->width, f->height);
    }
    for (int w = 0; hulls && w < workers; ++w)
        free(hulls[w].x), free(hulls[w].z), free(hulls[w].rise);
    free(hulls);
    gis_sweep_blocks_free(&blocks);
    return rc;
}
