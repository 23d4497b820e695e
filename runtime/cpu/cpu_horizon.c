/*
 * cpu_horizon.c — see cpu_horizon.h.
 */
#include "cpu_horizon.h"

#include "ray_bound.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>

#define HALF_PI 1.57079632679489661923

struct hfs_horizon_plan {
    const hfs_cpu_pyramid *p;
    int n_dirs, n_levels, w, h;
    size_t stride;
    double zs;                  /* zscale / dx: slope per height over distance */
    double *cs;                 /* n_dirs x (cos, sin), snapped */
    hfs_horizon_tap *taps;      /* n_dirs x n_levels */
};

/* Snaps a direction component that is zero in exact arithmetic. */
static double snap_unit(double c)
{
    return fabs(c) < 1e-12 ? 0.0 : c;
}

/* Splits an offset into integer part and fraction, snapping to an integer
 * when within 1e-9 texel of it. */
static void split_offset(double o, int *io, double *fo)
{
    const double r = nearbyint(o);
    if (fabs(o - r) < 1e-9)
        o = r;
    const double f = floor(o);
    *io = (int)f;
    *fo = o - f;
}

int hfs_horizon_plan_create(const hfs_cpu_pyramid *p, double dx, double zscale,
                            int offset, const double *phi, int n_dirs,
                            hfs_horizon_plan **out, hfs_error *err)
{
    *out = NULL;
    if (!p || n_dirs < 0 || (n_dirs > 0 && !phi))
        return hfs_fail(err, HFS_E_INVALID, "horizon plan: invalid arguments");
    if (!(dx > 0.0) || !(zscale >= 0.0) || !isfinite(dx) || !isfinite(zscale))
        return hfs_fail(err, HFS_E_INVALID, "horizon plan: dx=%g zscale=%g out of range", dx, zscale);
    if (offset < 0)
        return hfs_fail(err, HFS_E_INVALID, "horizon plan: level offset %d < 0", offset);
    const int n = hfs_cpu_pyramid_count(p), k = hfs_cpu_pyramid_k(p);
    if (hfs_pyramid_read_level(n, k, offset, 0) < hfs_cpu_pyramid_first_full(p))
        return hfs_fail(err, HFS_E_INVALID, "horizon plan: pyramid lacks the levels offset %d reads", offset);

    hfs_horizon_plan *hp = calloc(1, sizeof *hp);
    if (!hp)
        return hfs_fail(err, HFS_E_NOMEM, "horizon plan: out of memory");
    hp->p = p;
    hp->n_dirs = n_dirs;
    hp->n_levels = n;
    hp->w = hfs_cpu_pyramid_width(p);
    hp->h = hfs_cpu_pyramid_height(p);
    hp->stride = (size_t)hfs_cpu_pyramid_stride(p);
    hp->zs = zscale / dx;
    hp->cs = malloc(((size_t)n_dirs * 2 + 1) * sizeof *hp->cs);
    hp->taps = malloc(((size_t)n_dirs * (size_t)n + 1) * sizeof *hp->taps);
    if (!hp->cs || !hp->taps) {
        hfs_horizon_plan_destroy(hp);
        return hfs_fail(err, HFS_E_NOMEM, "horizon plan: out of memory");
    }
    for (int d = 0; d < n_dirs; ++d) {
        const double c = snap_unit(cos(phi[d])), s = snap_unit(sin(phi[d]));
        hp->cs[2 * d] = c;
        hp->cs[2 * d + 1] = s;
        for (int i = 0; i < n; ++i) {
            hfs_horizon_tap *t = &hp->taps[(size_t)d * (size_t)n + (size_t)i];
            const double dist = hfs_cpu_pyramid_spacing(p, i);
            t->read = hfs_pyramid_read_level(n, k, offset, i);
            split_offset(dist * c, &t->ix, &t->fx);
            split_offset(dist * s, &t->iy, &t->fy);
            t->inv_run = zscale / (dist * dx);
        }
    }
    *out = hp;
    return HFS_OK;
}

void hfs_horizon_plan_destroy(hfs_horizon_plan *hp)
{
    if (!hp)
        return;
    free(hp->taps);
    free(hp->cs);
    free(hp);
}

int hfs_horizon_plan_dirs(const hfs_horizon_plan *hp) { return hp->n_dirs; }
int hfs_horizon_plan_levels(const hfs_horizon_plan *hp) { return hp->n_levels; }

void hfs_horizon_plan_dir(const hfs_horizon_plan *hp, int dir, double *c, double *s)
{
    *c = hp->cs[2 * dir];
    *s = hp->cs[2 * dir + 1];
}

const hfs_horizon_tap *hfs_horizon_plan_taps(const hfs_horizon_plan *hp, int dir)
{
    return hp->taps + (size_t)dir * (size_t)hp->n_levels;
}

double hfs_horizon_floor(const double n[3], double c, double s)
{
    /* Elevation where s(phi, e) leaves the receiver's tangent plane:
     * N.s = (N.u) cos e + N_z sin e = 0  =>  e = atan2(-N.u, N_z).
     * (NS09's -asin(N.u) equals this only when N lies in the plane of u and
     * z; elsewhere it sits slightly above the plane.)  N_z > 0 always. */
    const double a = n[0] * c + n[1] * s;
    return atan2(-a, n[2]);
}

double hfs_horizon_floor_slope(const double n[3], double c, double s)
{
    return -(n[0] * c + n[1] * s) / n[2];
}

/* ---- in-grid ranges and the bilinear read ----------------------------------- */

/* Receivers x in [*lo, *hi] whose sample x + io + fo lies in [0, n-1]. */
static void ingrid_range(int io, double fo, int n, int *lo, int *hi)
{
    const int last = fo == 0.0 ? n - 1 : n - 2; /* largest allowed x + io */
    *lo = io < 0 ? -io : 0;
    const long h = (long)last - io;
    *hi = h > n - 1 ? n - 1 : (int)h;
}

/* Bilinear read at (x + fx, y + fy) of a padded level, given the address of
 * (x, y): the right/lower neighbours always exist thanks to the padding. */
static inline double tap_read(const double *r, size_t stride, double fx, double fy)
{
    const double top = r[0] + fx * (r[1] - r[0]);
    const double bot = r[stride] + fx * (r[stride + 1] - r[stride]);
    return top + fy * (bot - top);
}

/* ---- evaluation --------------------------------------------------------------- */

/* Tap t's slope seen from receiver (i, j) into *d; 0 (nothing written)
 * where its sample lies off the grid. */
static int tap_slope(const hfs_horizon_plan *hp, const hfs_horizon_tap *t, int i, int j,
                     double *d)
{
    int xlo, xhi, ylo, yhi;
    ingrid_range(t->ix, t->fx, hp->w, &xlo, &xhi);
    ingrid_range(t->iy, t->fy, hp->h, &ylo, &yhi);
    if (i < xlo || i > xhi || j < ylo || j > yhi)
        return 0;
    const double *r = hfs_cpu_pyramid_full(hp->p, t->read);
    const double v = tap_read(r + (size_t)(j + t->iy) * hp->stride + (size_t)(i + t->ix),
                              hp->stride, t->fx, t->fy);
    *d = (v - r[(size_t)j * hp->stride + (size_t)i]) * t->inv_run;
    return 1;
}

void hfs_horizon_point(const hfs_horizon_plan *hp, int dir, int i, int j,
                       double floor, double *env, double *key,
                       double *omega_levels)
{
    const hfs_horizon_tap *taps = hfs_horizon_plan_taps(hp, dir);
    const int n = hp->n_levels;
    double maxd = -DBL_MAX;
    double local[128];
    double *omega = omega_levels ? omega_levels : (n <= 128 ? local : NULL);
    for (int s = 0; s < n; ++s) {
        double o = floor, d;
        if (tap_slope(hp, &taps[s], i, j, &d)) {
            if (d > maxd)
                maxd = d;
            o = atan(d);
        }
        if (omega)
            omega[s] = o;
    }
    if (env)
        *env = hfs_horizon_env_from_maxd(maxd, floor);
    if (key) {
        if (omega) {
            *key = hfs_horizon_bspline_max(omega, n, 1, floor);
        } else {
            double *tmp = malloc((size_t)n * sizeof *tmp);
            if (!tmp) { /* only for absurd N > 128 without a caller buffer */
                *key = floor;
                return;
            }
            hfs_horizon_point(hp, dir, i, j, floor, NULL, key, tmp);
            free(tmp);
        }
    }
}

void hfs_horizon_row(const hfs_horizon_plan *hp, int dir, int j,
                     const double *floor, double *maxd, double *omega)
{
    const hfs_horizon_tap *taps = hfs_horizon_plan_taps(hp, dir);
    const int n = hp->n_levels, w = hp->w;
    const size_t stride = hp->stride;
    if (maxd)
        for (int x = 0; x < w; ++x)
            maxd[x] = -DBL_MAX;
    if (omega)
        for (int s = 0; s < n; ++s)
            for (int x = 0; x < w; ++x)
                omega[(size_t)s * (size_t)w + (size_t)x] = floor[x];

    for (int s = 0; s < n; ++s) {
        const hfs_horizon_tap *t = &taps[s];
        int xlo, xhi, ylo, yhi;
        ingrid_range(t->iy, t->fy, hp->h, &ylo, &yhi);
        if (j < ylo || j > yhi)
            continue;
        ingrid_range(t->ix, t->fx, w, &xlo, &xhi);
        if (xlo > xhi)
            continue;
        const double *r = hfs_cpu_pyramid_full(hp->p, t->read);
        const double *recv = r + (size_t)j * stride;
        const double *samp = r + (size_t)(j + t->iy) * stride;
        const double fx = t->fx, fy = t->fy, inv = t->inv_run;
        if (maxd) {
            for (int x = xlo; x <= xhi; ++x) {
                const double v = tap_read(samp + (x + t->ix), stride, fx, fy);
                const double d = (v - recv[x]) * inv;
                maxd[x] = d > maxd[x] ? d : maxd[x];
            }
        }
        if (omega) {
            double *o = omega + (size_t)s * (size_t)w;
            for (int x = xlo; x <= xhi; ++x) {
                const double v = tap_read(samp + (x + t->ix), stride, fx, fy);
                o[x] = atan((v - recv[x]) * inv);
            }
        }
    }
}

double hfs_horizon_env_from_maxd(double maxd, double floor)
{
    const double a = atan(maxd); /* atan(-DBL_MAX) = -pi/2 <= floor */
    double o = a > floor ? a : floor;
    return o > HALF_PI ? HALF_PI : (o < -HALF_PI ? -HALF_PI : o);
}

/* The distance factor 2^(u/k) of refining sample q of `refine` (k levels
 * per octave); gles_lib.frag hfs_refine_about spells the same. */
double hfs_horizon_refine_factor(int q, int refine, int k)
{
    return exp2((-1.0 + 2.0 * (q + 1) / (refine + 1)) / k);
}

/* The largest of `refine` slopes about scale s of receiver (i, j) in
 * direction dir (at d_s 2^(u/k), read from s's level like s itself,
 * off-grid ones skipped) and `best`; *dist (if not NULL) becomes the
 * distance of a refining sample that beats best by more than the
 * horizons' relative tie (HFS_HORIZON_TIE |best|), so that float and
 * double name the same sample where slopes tie.  (Not the absolute tie of
 * the field's height range: a border far below would move it,
 * test_metamorphic_pad.) */
static double refine_about(const hfs_horizon_plan *hp, int dir, int i, int j, int s, int refine,
                           double best, double *dist)
{
    const hfs_horizon_tap *t = hfs_horizon_plan_taps(hp, dir) + s;
    const double d0 = hfs_cpu_pyramid_spacing(hp->p, s);
    const int k = hfs_cpu_pyramid_k(hp->p);
    const double *r = hfs_cpu_pyramid_full(hp->p, t->read);
    const double h0 = r[(size_t)j * hp->stride + (size_t)i];
    for (int q = 0; q < refine; ++q) {
        const double f = hfs_horizon_refine_factor(q, refine, k);
        int ix, iy, xlo, xhi, ylo, yhi;
        double fx, fy;
        split_offset(d0 * f * hp->cs[2 * dir], &ix, &fx);
        split_offset(d0 * f * hp->cs[2 * dir + 1], &iy, &fy);
        ingrid_range(ix, fx, hp->w, &xlo, &xhi);
        ingrid_range(iy, fy, hp->h, &ylo, &yhi);
        if (i < xlo || i > xhi || j < ylo || j > yhi)
            continue;
        const double v = tap_read(r + (size_t)(j + iy) * hp->stride + (size_t)(i + ix),
                                  hp->stride, fx, fy);
        const double d = (v - h0) * t->inv_run / f;
        if (d > best) {
            if (dist && d > best + HFS_HORIZON_TIE * fabs(best))
                *dist = d0 * f;
            best = d;
        }
    }
    return best;
}

/* The slope of scale s's sample of receiver (i, j) in direction dir, whose
 * angle is o: tan(o), or, where tan(o) no longer holds the slope to the
 * horizons' tie (|slope| > 1e9: near +-pi/2 a double angle resolves
 * 2.2e-16, a relative 2.2e-16 |slope| of the slope; HFS_HORIZON_TIE is
 * 1e-5), the slope read again as hfs_horizon_point computed it.  The
 * scales are then told apart on fields of any relief, as the GLES passes
 * compare slopes (issue 36: at slopes beyond ~1e16 every near-vertical
 * scale tied, the finest won and the refinement went about the wrong
 * one; the sky broke the field's scale invariance). */
static double scale_slope(const hfs_horizon_plan *hp, int dir, int i, int j, int s, double o,
                          const double *floor_slope)
{
    const double sl = tan(o);
    double d;
    if (!(fabs(sl) > 1e9))
        return sl;
    if (!tap_slope(hp, hfs_horizon_plan_taps(hp, dir) + s, i, j, &d))
        return floor_slope ? *floor_slope : sl; /* no sample: the floor stands for it */
    return d;
}

double hfs_horizon_refined(const hfs_horizon_plan *hp, int dir, int i, int j,
                           const double *omega, size_t stride, double floor, int refine,
                           double tie, const double *seed, int skip)
{
    return hfs_horizon_refined_within(hp, dir, i, j, omega, stride, floor, refine, tie, seed,
                                      skip, 0);
}

double hfs_horizon_refined_within(const hfs_horizon_plan *hp, int dir, int i, int j,
                                  const double *omega, size_t stride, double floor, int refine,
                                  double tie, const double *seed, int skip, int coarsest)
{
    const int n = hp->n_levels - skip;
    int best_s = seed ? n - 1 : -1;
    /* the floor's slope, from the angle where its tan holds it (the same
     * bits as ever), else the plane's own (issue 36: at slopes ~1e20 the
     * saturated tan(floor) stood above every scale, and the seed led) */
    const double tfl = tan(floor);
    double best = -HALF_PI, best_slope = seed ? (fabs(tfl) > 1e9 ? *seed : tfl) : 0.0;
    for (int s = n - 1; s >= coarsest; --s) { /* fine to coarse; near-ties: the finest */
        const double o = omega[(size_t)s * stride];
        const double sl = scale_slope(hp, dir, i, j, s, o, seed);
        if (best_s < 0 || sl > best_slope + HFS_HORIZON_TIE * fabs(best_slope) + tie) {
            best_s = s;
            best_slope = sl;
        }
        best = o > best ? o : best;
    }
    if (best_s < 0) /* every scale skipped */
        return floor > HALF_PI ? HALF_PI : (floor < -HALF_PI ? -HALF_PI : floor);
    const double maxd = refine_about(hp, dir, i, j, best_s, refine, -DBL_MAX, NULL);
    const double a = atan(maxd); /* atan(-DBL_MAX) = -pi/2 */
    double o = a > best ? a : best;
    o = o > floor ? o : floor;
    return o > HALF_PI ? HALF_PI : (o < -HALF_PI ? -HALF_PI : o);
}

int hfs_horizon_occluder(const hfs_horizon_plan *hp, int dir, int i, int j,
                         const double *omega, size_t stride, int first, int coarsest, int refine,
                         double tie, double *slope, double *dist)
{
    double best = -1e30, ref = -1e30;
    int bi = first;
    *dist = 0.0;
    for (int s = first; s >= coarsest; --s) { /* fine to coarse, as env_horizons.frag */
        const double o = omega[(size_t)s * stride];
        if (!(o > HFS_HORIZON_OFF))
            break; /* off the grid: so is every farther scale */
        const double sl = scale_slope(hp, dir, i, j, s, o, NULL);
        if (sl > ref + HFS_HORIZON_TIE * fabs(ref) + tie) {
            ref = sl;
            bi = s;
        }
        if (sl > best) {
            /* the distance moves only past the tie (env_horizons.frag) */
            if (sl > best + HFS_HORIZON_TIE * fabs(best) + tie)
                *dist = hfs_cpu_pyramid_spacing(hp->p, s);
            best = sl;
        }
    }
    if (bi >= 0 && first >= 0)
        best = refine_about(hp, dir, i, j, bi, refine, best, dist);
    *slope = best;
    return *dist > 0.0;
}

double hfs_horizon_key_grid(const hfs_horizon_plan *hp, int dir, int i, int j,
                            const double *omega, double floor, int refine, double tie, int skip,
                            double gap_from, double *dist, int *seen)
{
    const double tfl = tan(floor);
    double best = -DBL_MAX, ref = 0.0;
    int bi = -1;
    *seen = 0;
    *dist = 0.0;
    for (int s = hp->n_levels - 1 - skip; s >= 0; --s) { /* fine to coarse */
        const int in_grid = omega[s] > HFS_HORIZON_OFF;
        const double sl = in_grid ? scale_slope(hp, dir, i, j, s, omega[s], NULL) : tfl;
        *seen |= in_grid;
        if (bi < 0 || sl > ref + HFS_HORIZON_TIE * fabs(ref) + tie) {
            ref = sl;
            bi = s;
        }
        best = sl > best ? sl : best;
        if (!in_grid)
            break;
    }
    if (bi < 0)
        return tfl;
    *dist = hfs_cpu_pyramid_spacing(hp->p, bi);
    best = refine_about(hp, dir, i, j, bi, refine, best, dist);
    /* and every band between the scales: no narrow occluder is stepped over */
    return hfs_horizon_gap(hp, dir, i, j, gap_from, tie, best, 1, dist, NULL);
}

double hfs_horizon_gap(const hfs_horizon_plan *hp, int dir, int i, int j, double t_first,
                       double tie, double best, int cells, double *dist, long *reads)
{
    return hfs_horizon_gap_along(hp, hp->cs[2 * dir], hp->cs[2 * dir + 1], i, j, t_first,
                                 HUGE_VAL, tie, best, cells, dist, reads);
}

double hfs_horizon_gap_along(const hfs_horizon_plan *hp, double c, double s, int i, int j,
                             double t_first, double t_last, double tie, double best, int cells,
                             double *dist, long *reads)
{
    const hfs_ray_bound_layout *L;
    const double *atlas = hfs_cpu_pyramid_bounds(hp->p, &L);
    const double *z = hfs_cpu_pyramid_full(hp->p, hp->n_levels - 1);
    return (cells ? hfs_ray_bound_search_cells : hfs_ray_bound_search)(
        L, atlas, z, hp->stride, i, j, c, s, t_first, t_last, hp->zs, tie, best, dist, reads);
}

double hfs_horizon_gap_from(const hfs_horizon_plan *hp, int dir, int i, int j, int ci, int cj,
                            double t_first, double tie, double slope, double *dist, double *rise)
{
    const hfs_ray_bound_layout *L;
    const double *atlas = hfs_cpu_pyramid_bounds(hp->p, &L);
    const double *z = hfs_cpu_pyramid_full(hp->p, hp->n_levels - 1);
    const double z0 = z[(size_t)cj * hp->stride + (size_t)ci];
    *rise = (z0 - z[(size_t)j * hp->stride + (size_t)i]) * hp->zs;
    /* the receiver's own occluder, seen from z0: a start no farther
     * crossing must beat by less than the tie */
    const double best = *dist > 0.0 ? slope - *rise / *dist : -1e30;
    return hfs_ray_bound_search_from(L, atlas, z, hp->stride, i, j, z0, hp->cs[2 * dir],
                                     hp->cs[2 * dir + 1], t_first, hp->zs, tie, best, dist);
}

double hfs_horizon_bspline_max(const double *omega, int n, size_t stride,
                               double floor)
{
    /* Weighted sums in difference form around one sample (exact for constant
     * input): knot t:      w_t + (w_{t-1} - w_t + w_{t+1} - w_t)/6
     *             midpoint: w_t + (w_{t-1} - w_t + 23(w_{t+1} - w_t)
     *                             + w_{t+2} - w_t)/48, indices clamped. */
    double best = floor;
    for (int t = 0; t < n; ++t) {
        const double wm = omega[(size_t)(t > 0 ? t - 1 : 0) * stride];
        const double w0 = omega[(size_t)t * stride];
        const double w1 = omega[(size_t)(t + 1 < n ? t + 1 : n - 1) * stride];
        const double knot = w0 + ((wm - w0) + (w1 - w0)) / 6.0;
        if (knot > best)
            best = knot;
        if (t + 1 < n) {
            const double w2 = omega[(size_t)(t + 2 < n ? t + 2 : n - 1) * stride];
            const double mid = w0 + ((wm - w0) + 23.0 * (w1 - w0) + (w2 - w0)) / 48.0;
            if (mid > best)
                best = mid;
        }
    }
    return best > HALF_PI ? HALF_PI : (best < -HALF_PI ? -HALF_PI : best);
}

/* ---- per-receiver directions (local lights, issue 4; additive) ------------------ */

struct hfs_horizon_scales {
    const hfs_cpu_pyramid *p;
    int n, w, h;
    size_t stride;
    double *dist;      /* d_s, texels */
    double *inv_run;   /* zscale / (d_s dx) */
    int *read;         /* level read */
};

int hfs_horizon_scales_create(const hfs_cpu_pyramid *p, double dx, double zscale,
                              int offset, hfs_horizon_scales **out, hfs_error *err)
{
    *out = NULL;
    if (!p)
        return hfs_fail(err, HFS_E_INVALID, "horizon scales: invalid arguments");
    if (!(dx > 0.0) || !(zscale >= 0.0) || !isfinite(dx) || !isfinite(zscale))
        return hfs_fail(err, HFS_E_INVALID, "horizon scales: dx=%g zscale=%g out of range", dx, zscale);
    if (offset < 0)
        return hfs_fail(err, HFS_E_INVALID, "horizon scales: level offset %d < 0", offset);
    const int n = hfs_cpu_pyramid_count(p), k = hfs_cpu_pyramid_k(p);
    if (hfs_pyramid_read_level(n, k, offset, 0) < hfs_cpu_pyramid_first_full(p))
        return hfs_fail(err, HFS_E_INVALID, "horizon scales: pyramid lacks the levels offset %d reads", offset);
    hfs_horizon_scales *hs = calloc(1, sizeof *hs);
    if (!hs)
        return hfs_fail(err, HFS_E_NOMEM, "horizon scales: out of memory");
    hs->p = p;
    hs->n = n;
    hs->w = hfs_cpu_pyramid_width(p);
    hs->h = hfs_cpu_pyramid_height(p);
    hs->stride = (size_t)hfs_cpu_pyramid_stride(p);
    hs->dist = malloc((size_t)n * sizeof *hs->dist);
    hs->inv_run = malloc((size_t)n * sizeof *hs->inv_run);
    hs->read = malloc((size_t)n * sizeof *hs->read);
    if (!hs->dist || !hs->inv_run || !hs->read) {
        hfs_horizon_scales_destroy(hs);
        return hfs_fail(err, HFS_E_NOMEM, "horizon scales: out of memory");
    }
    for (int i = 0; i < n; ++i) {
        const double dist = hfs_cpu_pyramid_spacing(p, i);
        hs->dist[i] = dist;
        hs->read[i] = hfs_pyramid_read_level(n, k, offset, i);
        hs->inv_run[i] = zscale / (dist * dx); /* the expression plans use */
    }
    *out = hs;
    return HFS_OK;
}

void hfs_horizon_scales_destroy(hfs_horizon_scales *hs)
{
    if (!hs)
        return;
    free(hs->dist);
    free(hs->inv_run);
    free(hs->read);
    free(hs);
}

int hfs_horizon_scales_count(const hfs_horizon_scales *hs) { return hs->n; }
double hfs_horizon_scales_dist(const hfs_horizon_scales *hs, int scale) { return hs->dist[scale]; }

void hfs_horizon_snap_dir(double phi, double *c, double *s)
{
    *c = snap_unit(cos(phi));
    *s = snap_unit(sin(phi));
}

void hfs_horizon_point_slopes(const hfs_horizon_scales *hs, int i, int j, double c,
                              double s, int s_lo, double *slope, unsigned char *in_grid)
{
    const size_t stride = hs->stride;
    for (int t = s_lo < 0 ? 0 : s_lo; t < hs->n; ++t) {
        int ix, iy, xlo, xhi, ylo, yhi;
        double fx, fy;
        split_offset(hs->dist[t] * c, &ix, &fx);
        split_offset(hs->dist[t] * s, &iy, &fy);
        ingrid_range(ix, fx, hs->w, &xlo, &xhi);
        ingrid_range(iy, fy, hs->h, &ylo, &yhi);
        if (i < xlo || i > xhi || j < ylo || j > yhi) {
            in_grid[t] = 0;
            slope[t] = 0.0;
            continue;
        }
        const double *r = hfs_cpu_pyramid_full(hs->p, hs->read[t]);
        const double v = tap_read(r + (size_t)(j + iy) * stride + (size_t)(i + ix), stride, fx, fy);
        slope[t] = (v - r[(size_t)j * stride + (size_t)i]) * hs->inv_run[t];
        in_grid[t] = 1;
    }
}
