/*
 * cpu_bounce.c — see cpu_bounce.h.
 */
#include "cpu_bounce.h"

#include "cpu_far_grid.h"
#include "cpu_horizon.h"
#include "cpu_pyramid.h"
#include "field_geom.h"
#include "gloss.h"
#include "lights.h"
#include "parallel.h"
#include "pyramid_layout.h"
#include "slice_light.h"
#include "split_horizon.h"
#include "visibility.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define HFS_BOUNCE_MAX_REFINE 16 /* the refine key's range */

typedef struct bounce_ctx {
    const hfs_field *f;
    const hfs_lighting *l;
    const hfs_cpu_pyramid *pyr;
    const hfs_horizon_plan *plan;
    int n_dirs, n_levels, k, refine; /* refine: the walk's samples after each scale */
    int direct_refine;    /* the direct light's horizons' (q->refine) */
    int stride;           /* the bounces' directions: every stride-th of the plan's */
    double dphi;
    double tie;           /* hfs_horizon_tie_slope, as the direct light's */
    int capped;           /* bands stop at the direct horizon (hfs_bounce_capped) */
    hfs_split split;      /* the direct light's split horizons (split.on: far) */
    hfs_cpu_far *far;     /* their far grid, as the direct light's; NULL: one horizon */
    double step[HFS_BOUNCE_MAX_REFINE + 1]; /* 2^(q / ((refine + 1) k)): samples per scale */
    hfs_gloss gloss;      /* glossy receivers: the lobe's weight of each band too */
    double *omega;        /* per worker: n_levels angles */
    const float *prev;    /* Lo_{b-1} */
    float *cur;           /* Lo_b */
} bounce_ctx;

/* One slice's sums at a receiver: the cosine's weights (a = N.d, nz =
 * N_z) and, glossy, the lobe's (slice_light.h hfs_lobe_slice). */
typedef struct slice_sums {
    double a, nz;
    int k;                          /* the slice's sub-horizons (0: no cap) */
    double cap[HFS_SPLIT_MAX_K];    /* their elevations, at least the tangent plane's */
    double s_cap[HFS_SPLIT_MAX_K];  /* hfs_slice_cosine at each */
    int glossy;
    hfs_lobe_slice ls;
    double acc[3];  /* sum Lo_{b-1} W_cos */
    double gacc[3]; /* sum Lo_{b-1} W_lobe */
    double last[3]; /* the last band's radiance */
} slice_sums;

/* Adds the band (top, e] lit by radiance lo, clipped to each of the
 * slice's sub-horizons (hfs_split_band: the mean of the parts below
 * them); e = HUGE_VAL: up to each sub-horizon. */
static void add_band(slice_sums *ss, double top, double e, const double lo[3])
{
    const double s_e = e < HUGE_VAL ? hfs_slice_cosine(ss->a, ss->nz, e) : -HUGE_VAL;
    const double wgt = hfs_split_band(ss->s_cap, ss->k, hfs_slice_cosine(ss->a, ss->nz, top), s_e);
    double wg = 0.0;
    if (ss->glossy && !ss->k)
        wg = hfs_lobe_slice_band(&ss->ls, top, e);
    for (int h = 0; ss->glossy && h < ss->k; ++h)
        if (ss->cap[h] > top)
            wg += hfs_lobe_slice_band(&ss->ls, top, fmin(e, ss->cap[h])) / ss->k;
    for (int c = 0; c < 3; ++c) {
        ss->acc[c] += lo[c] * wgt;
        ss->gacc[c] += lo[c] * wg;
    }
}

/* The band (top, e] cast by the sample at (gx, gy), when e rises above
 * top: its radiance (kept in ss->last) into the sums; returns the new
 * top. */
static double cast(const bounce_ctx *b, slice_sums *ss, double top, double e, double gx,
                   double gy)
{
    if (!(e > top))
        return top;
    hfs_rgb_bilinear(b->prev, b->f->width, b->f->height, gx, gy, ss->last);
    add_band(ss, top, e, ss->last);
    return e;
}

/* The slope a sample must exceed to rise above slope t by more than the
 * horizons' tie (cpu_horizon.h; GLES hfs_scale_takes_over). */
static double rise_over(const bounce_ctx *b, double t)
{
    return t + HFS_HORIZON_TIE * fabs(t) + b->tie;
}

/* The sample at distance dist (texels) along (c, s) from receiver (i, j),
 * read from level `read` as the horizons read it (h0: the receiver's value
 * there): its slope into *slope and its grid position; 0 when it lies off
 * the grid. */
static int sample(const bounce_ctx *b, int read, double h0, int i, int j, double c, double s,
                  double dist, double *slope, double *gx, double *gy)
{
    const hfs_field *f = b->f;
    *gx = i + dist * c, *gy = j + dist * s;
    const double slack = 1e-9 * (1.0 + dist); /* the plans snap offsets as fine */
    if (*gx < -slack || *gy < -slack || *gx > f->width - 1.0 + slack ||
        *gy > f->height - 1.0 + slack)
        return 0;
    const double dz = hfs_cpu_pyramid_sample(b->pyr, read, *gx, *gy) - h0;
    *slope = dz * f->zscale / (dist * f->dx);
    return 1;
}

/* The direct light's horizons of slice d at (i, j) (cpu_render.c: the
 * refined scales and the own cell; with split horizons the near part and
 * each sub-direction's far occluder at the texel's far place pl) into
 * ss->cap, each at least the tangent plane top0, and their
 * hfs_slice_cosine into ss->s_cap: the bands stop there, so that the
 * light a receiver gathers and the sky it sees never overlap (with albedo
 * <= 1 nothing exceeds the unshadowed maximum).  Returns the highest. */
static double direct_horizons(const bounce_ctx *b, double *omega, int d, int i, int j,
                              const double n[3], double c, double s, double first_cell,
                              const hfs_cpu_far_place *pl, double top0, slice_sums *ss)
{
    const double fl = hfs_horizon_floor(n, c, s), fls = hfs_horizon_floor_slope(n, c, s);
    hfs_horizon_point(b->plan, d, i, j, fl, NULL, NULL, omega);
    const double e =
        b->far ? hfs_horizon_refined_within(b->plan, d, i, j, omega, 1, fl, b->split.near_refine,
                                            b->tie, &fls, b->n_levels > 1,
                                            hfs_cpu_far_coarsest_near(b->far))
               : hfs_horizon_refined(b->plan, d, i, j, omega, 1, fl, b->direct_refine, b->tie,
                                     &fls, b->n_levels > 1);
    const double om = fmax(e, atan(first_cell));
    double fs[HFS_SPLIT_MAX_K] = {-1e30};
    ss->k = b->far ? b->split.k : 1;
    if (b->far)
        hfs_cpu_far_slopes(b->far, pl, d, n, fs);
    double top = top0;
    for (int h = 0; h < ss->k; ++h) { /* cpu_render.c sub_horizons */
        const double x = fmax(om, atan(fs[h]));
        ss->cap[h] = x > top0 ? x : top0;
        ss->s_cap[h] = hfs_slice_cosine(ss->a, ss->nz, ss->cap[h]);
        top = fmax(top, ss->cap[h]);
    }
    return top;
}

/* sum_bands Lo_{b-1} W over slice d at receiver (i, j) into ss (its
 * normal's and R's weights set): the receiver's own
 * cell, then each scale's sample and `refine` more between it and the next
 * (the spacing the refined horizons reach about their max), nearest first;
 * each scale's group casts one band up to its highest sample, lit at the
 * first sample that rose (bounce_gather.frag walk_scales says why) by more
 * than the horizons' tie: a rise of a rounding error must not pick the
 * light, or scaling the world would move it (test_metamorphic). */
static void slice_gather(const bounce_ctx *b, double *omega, int d, int i, int j,
                         const double n[3], const double r[3], const hfs_cpu_far_place *pl,
                         slice_sums *ss)
{
    double c, s;
    hfs_horizon_plan_dir(b->plan, d, &c, &s);
    const double a = n[0] * c + n[1] * s;
    ss->a = a, ss->nz = n[2];
    if (ss->glossy)
        hfs_lobe_slice_init(&ss->ls, r, n, c, s, b->gloss.s);
    for (int k = 0; k < 3; ++k)
        ss->last[k] = 0.0;
    double top = atan2(-a, n[2]); /* the tangent plane */
    const double top0 = top;
    double near, far;
    const double m1 = hfs_field_first_cell(b->f, i, j, c, s, &near, &far);
    ss->k = 0;
    const double cap =
        b->capped ? direct_horizons(b, omega, d, i, j, n, c, s, m1, pl, top0, ss) : 0.5 * PI;
    /* The receiver's own cell, where the bilinear surface along the ray is
     * z(t) = t (near + (far - near) t / tc) (issue 36): a ray below the
     * near end's slope meets it at once, so that part of the band takes
     * the receiver's own radiance (in a pit, its own dark walls, not the
     * lit rim beyond); the rest, up to the far edge's slope (a twisted
     * cell), the radiance where the ray at the part's middle elevation
     * meets it, t = tc (u - near) / (far - near).  Each part only where it
     * rises by more than the horizons' tie, as a scale's group below: a
     * part of a rounding error's width must not pick the light that fills
     * the rest (scaling the world would move it, test_metamorphic). */
    const double tc = 1.0 / fmax(fabs(c), fabs(s));
    if (m1 > -DBL_MAX) {
        if (near > rise_over(b, tan(top)))
            top = cast(b, ss, top, fmin(atan(near), cap), i, j);
        const double e = fmin(atan(far), cap);
        if (far > rise_over(b, fmax(near, tan(top))) && e > top) {
            const double u = tan(0.5 * (top + e));
            const double t = fmin(fmax(tc * (u - near) / (far - near), 0.0), tc);
            top = cast(b, ss, top, e, i + c * t, j + s * t);
        }
    }
    const hfs_horizon_tap *taps = hfs_horizon_plan_taps(b->plan, d);
    /* Once the top reaches the cap nothing farther can cast a band. */
    for (int sc = b->n_levels - 1; sc >= 0 && top < cap; --sc) {
        const double d0 = hfs_cpu_pyramid_spacing(b->pyr, sc);
        const double h0 = hfs_cpu_pyramid_sample(b->pyr, taps[sc].read, i, j);
        const double rise = rise_over(b, tan(top));
        double best = top, at[2] = {0.0, 0.0}, clear[2] = {0.0, 0.0};
        int off = 0, cleared = 0;
        for (int q = 0; q <= b->refine && !off; ++q) {
            double sl, gx, gy;
            if ((off = !sample(b, taps[sc].read, h0, i, j, c, s, d0 * b->step[q], &sl, &gx, &gy)))
                break;
            if (!cleared && sl > rise)
                clear[0] = gx, clear[1] = gy, cleared = 1;
            const double e = atan(sl);
            if (e > best) {
                if (best == top)
                    at[0] = gx, at[1] = gy;
                best = e;
            }
        }
        if (cleared) /* a rise within the tie is rounding: it must not pick the light */
            at[0] = clear[0], at[1] = clear[1];
        /* ... nor cast a band of a rounding error's width, whose light
         * would fill the rest where the walk stops (issue 36: the own
         * cell's is the receiver's own, the next scale's first sample at
         * its far edge). */
        if (cleared)
            top = cast(b, ss, top, fmin(best, cap), at[0], at[1]);
        if (off)
            break; /* the grid is convex: every farther sample is off too */
    }
    /* Capped: the terrain reaches the direct horizons, which the sparser
     * walk may not (a peak between its samples): the last band's radiance
     * fills the rest up to each. */
    if (b->capped && top > top0 && top < cap)
        add_band(ss, top, HUGE_VAL, ss->last);
}

static void bounce_row(void *ctx, int j, int worker)
{
    const bounce_ctx *b = ctx;
    const hfs_field *f = b->f;
    double *omega = b->omega + (size_t)worker * (size_t)b->n_levels;
    for (int i = 0; i < f->width; ++i) {
        double n[3], r[3] = {0.0, 0.0, 1.0};
        hfs_field_normal(f, i, j, n);
        const double pw[3] = {i * f->dx, j * f->dx, hfs_field_z(f, i, j)};
        const double nr = b->gloss.on ? hfs_gloss_reflect(&b->gloss, pw, n, r) : 0.0;
        slice_sums ss = {.glossy = nr > 0.0};
        hfs_cpu_far_place pl; /* split horizons: once per texel */
        if (b->far)
            hfs_cpu_far_place_of(b->far, i, j, &pl);
        for (int d = 0; d < b->n_dirs; d += b->stride)
            slice_gather(b, omega, d, i, j, n, r, &pl, &ss);
        const size_t p = 3 * ((size_t)j * (size_t)f->width + (size_t)i);
        for (int c = 0; c < 3; ++c) {
            const double rho = b->l->albedo * (b->l->albedo_map ? b->l->albedo_map[p + c] : 1.0);
            const double gl = b->gloss.ks * b->gloss.norm * b->dphi * ss.gacc[c];
            b->cur[p + c] = (float)(rho / PI * b->dphi * ss.acc[c] + gl);
        }
    }
}

static int make_plan(const hfs_field *f, const hfs_quality *q, hfs_cpu_pyramid **pyr,
                     hfs_horizon_plan **plan, hfs_error *err)
{
    const int n_levels = hfs_pyramid_level_count(f->width, f->height, q->k);
    int rc = hfs_cpu_pyramid_create(f, q->k, hfs_pyramid_read_level(n_levels, q->k, q->offset, 0),
                                    q->threads, pyr, err);
    if (rc)
        return rc;
    hfs_swath sw;
    hfs_swath_full(q->nphi_env, &sw);
    double *phi = malloc((size_t)sw.n * sizeof *phi);
    if (!phi)
        return hfs_fail(err, HFS_E_NOMEM, "backend cpu: out of memory for the bounces");
    for (int d = 0; d < sw.n; ++d)
        phi[d] = hfs_swath_phi(&sw, d);
    rc = hfs_horizon_plan_create(*pyr, f->dx, f->zscale, q->offset, phi, sw.n, plan, err);
    free(phi);
    return rc;
}

int hfs_cpu_bounces(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                    int bounces, float *out, hfs_progress_fn progress, void *user,
                    hfs_error *err)
{
    const size_t n = (size_t)f->width * (size_t)f->height * 3;
    const int threads = q->threads > 0 ? q->threads : hfs_parallel_default_threads();
    hfs_cpu_pyramid *pyr = NULL;
    hfs_horizon_plan *plan = NULL;
    float *prev = malloc(n * sizeof *prev), *cur = malloc(n * sizeof *cur);
    const int nb = hfs_bounce_dirs(q);
    bounce_ctx b = {.f = f, .l = l, .dphi = 2.0 * PI / nb, .k = q->k,
                    .stride = q->nphi_env / nb, .capped = hfs_bounce_capped(l, q),
                    .direct_refine = q->refine,
                    .refine = q->bounce_refine < HFS_BOUNCE_MAX_REFINE ? q->bounce_refine
                                                                       : HFS_BOUNCE_MAX_REFINE};
    for (int k = 0; k <= b.refine; ++k)
        b.step[k] = exp2((double)k / ((b.refine + 1) * b.k));
    hfs_gloss_make(l, &b.gloss);
    int rc = (!prev || !cur) ? hfs_fail(err, HFS_E_NOMEM, "backend cpu: out of memory for "
                                        "the bounces")
                             : make_plan(f, q, &pyr, &plan, err);
    if (!rc) {
        b.pyr = pyr, b.plan = plan, b.n_dirs = hfs_horizon_plan_dirs(plan);
        b.n_levels = hfs_horizon_plan_levels(plan);
        double lo, hi;
        hfs_field_range(f, &lo, &hi);
        b.tie = hfs_horizon_tie_slope(0.5 * hi - 0.5 * lo, f->zscale, f->dx);
        b.omega = malloc((size_t)threads * (size_t)b.n_levels * sizeof *b.omega);
        if (!b.omega)
            rc = hfs_fail(err, HFS_E_NOMEM, "backend cpu: out of memory for the bounces");
    }
    /* Split horizons: the direct light's far grid (cpu_render_setup.c),
     * computed again from the same pyramid and rules. */
    hfs_split_make(q, &b.split);
    if (!rc && b.capped && b.split.on) {
        hfs_swath env;
        hfs_swath_full(q->nphi_env, &env);
        rc = hfs_cpu_far_create(f, pyr, q, &b.split, &env, b.tie, threads, &b.far, err);
    }
    if (!rc)
        memcpy(prev, out, n * sizeof *prev);
    for (int k = 1; k <= bounces && !rc; ++k) {
        b.prev = prev, b.cur = cur;
        hfs_parallel_rows(f->height, threads, bounce_row, &b, k == bounces ? progress : NULL,
                          user);
        for (size_t i = 0; i < n; ++i)
            out[i] += cur[i];
        float *t = prev;
        prev = cur;
        cur = t;
    }
    free(b.omega);
    hfs_cpu_far_destroy(b.far);
    hfs_horizon_plan_destroy(plan);
    hfs_cpu_pyramid_destroy(pyr);
    free(prev);
    free(cur);
    return rc;
}
