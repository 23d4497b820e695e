/*
 * cpu_local.c — see cpu_local.h and DESIGN.md "Local lights".
 *
 * Work per row (one worker):
 *   full mode (HFS_LOCAL_SWATH_FULL, or the wedge-table path): the per-scale
 *     horizons of the row in the nphi_local fixed azimuths, once for all local
 *     lights (hfs_horizon_row), with cos/sin of every angle for the distance
 *     test;
 *   partial mode: nothing shared but the normal and H(N); each (receiver,
 *     light, sample) reads only the scales that can lie in front of the light
 *     (d_s dx <= u + g, the far end of the sphere's section by the sample's
 *     half-plane) and skips the entry test where it cannot fail
 *     (d_s dx < u - g).
 * Per receiver: H(N) once; per light the view, E_cap, m = H * L, the swath, and
 * per sample: window, floor, horizons with the distance test, B-spline max,
 * then (Legendre) the NLP bands contracted against g_k = sum_r m_r A_k[r] E[r]
 * (so num and den cost 4 MACs each per sample and V is never formed), or
 * (wedge tables) V and V_open from the full swath's table object.
 */
#include "cpu_local.h"
#include "cpu_local_priv.h"
#include "pyramid_layout.h"
#include "gloss.h"

#include "local_geometry.h"

#include "cpu_horizon.h"
#include "visibility.h"
#include "field_geom.h"
#include "lights.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define HALF_PI 1.57079632679489661923

/* ---- options ------------------------------------------------------------------ */

void hfs_cpu_local_options_default(hfs_cpu_local_options *o)
{
    o->swath = HFS_LOCAL_SWATH_PARTIAL;
}

/* ---- renderer ---------------------------------------------------------------------------- */


static void free_scratch(local_scratch *s)
{
    free(s->om);
    free(s->co);
    free(s->si);
    free(s->floors);
    free(s->slope);
    free(s->in_grid);
    free(s->lv_omega);
    free(s->om_k);
    free(s->fl_k);
}

void hfs_cpu_local_destroy(hfs_cpu_local *lc)
{
    if (!lc)
        return;
    if (lc->scratch)
        for (int t = 0; t < lc->threads; ++t)
            free_scratch(&lc->scratch[t]);
    free(lc->scratch);
    hfs_horizon_scales_destroy(lc->scales);
    hfs_horizon_plan_destroy(lc->plan);
    hfs_visibility_destroy(lc->tables);
    free(lc->dist_world);
    free(lc->full_cs);
    free(lc->full_A);
    free(lc->grid);
    free(lc);
}

/* The local lights that contribute, with their radiance and whether they
 * lie beyond the terrain's shadow range. */
static void take_sources(hfs_cpu_local *lc, const hfs_field *f, const hfs_lighting *l)
{
    hfs_field_extent ext;
    hfs_field_extent_make(f, &ext);
    for (int i = 0; i < l->n_local && i < HFS_MAX_LOCAL_LIGHTS; ++i) {
        if (!hfs_local_light_contributes(&l->local[i]))
            continue;
        local_src *s = &lc->src[lc->n_src++];
        s->light = l->local[i];
        s->open = hfs_local_light_open(&ext, &l->local[i]);
        for (int ch = 0; ch < 3; ++ch)
            s->le[ch] = l->local[i].radiance[ch];
    }
}

/* The horizon scales and their world distances, the full swath's nphi
 * directions (snapped, with their SH weights), and what the row pass and
 * the wedge-table path read in those directions. */
static int make_directions(hfs_cpu_local *lc, const hfs_field *f, const hfs_quality *q,
                           const hfs_cpu_pyramid *p, hfs_error *err)
{
    int rc;
    if ((rc = hfs_horizon_scales_create(p, f->dx, f->zscale, q->offset, &lc->scales, err)))
        return rc;
    const int n = hfs_horizon_scales_count(lc->scales);
    lc->n_levels = n;
    lc->dist_world = malloc((size_t)n * sizeof *lc->dist_world);
    const int nphi = lc->nphi;
    lc->full.n = nphi;
    lc->full.full = 1;
    lc->full.phi0 = 0.0;
    lc->full.dphi = 2.0 * PI / nphi;
    lc->full_cs = malloc((size_t)nphi * 2 * sizeof *lc->full_cs);
    lc->full_A = malloc((size_t)nphi * HFS_SH_N * sizeof *lc->full_A);
    double *phi = malloc((size_t)nphi * sizeof *phi);
    if (!lc->dist_world || !lc->full_cs || !lc->full_A || !phi) {
        free(phi);
        return hfs_fail(err, HFS_E_NOMEM, "backend cpu: out of memory");
    }
    for (int s = 0; s < n; ++s)
        lc->dist_world[s] = hfs_horizon_scales_dist(lc->scales, s) * f->dx;
    for (int k = 0; k < nphi; ++k) {
        phi[k] = lc->full.phi0 + k * lc->full.dphi;
        hfs_horizon_snap_dir(phi[k], &lc->full_cs[2 * k], &lc->full_cs[2 * k + 1]);
        hfs_local_sample_weights(&lc->full, k, lc->full_A + (size_t)k * HFS_SH_N);
    }
    if (lc->row_pass)
        rc = hfs_horizon_plan_create(p, f->dx, f->zscale, q->offset, phi, nphi, &lc->plan, err);
    free(phi);
    if (rc)
        return rc;
    if (lc->path == HFS_VIS_WEDGE_TABLE) {
        hfs_swath sw;
        hfs_swath_full(nphi, &sw);
        return hfs_visibility_create(&sw, HFS_VIS_WEDGE_TABLE, &lc->tables, err);
    }
    return HFS_OK;
}

/* Each worker's scratch: the row pass's horizons (full mode or tables)
 * and the per-sample arrays. */
static int alloc_scratch(hfs_cpu_local *lc, hfs_error *err)
{
    lc->scratch = calloc((size_t)lc->threads, sizeof *lc->scratch);
    if (!lc->scratch)
        return hfs_fail(err, HFS_E_NOMEM, "backend cpu: out of memory");
    const size_t w = (size_t)lc->w, nn = (size_t)lc->n_levels, np = (size_t)lc->nphi;
    for (int t = 0; t < lc->threads; ++t) {
        local_scratch *s = &lc->scratch[t];
        if (lc->row_pass) {
            s->om = malloc(np * nn * w * sizeof *s->om);
            s->co = malloc(np * nn * w * sizeof *s->co);
            s->si = malloc(np * nn * w * sizeof *s->si);
            s->floors = malloc(np * w * sizeof *s->floors);
            if (!s->om || !s->co || !s->si || !s->floors)
                return hfs_fail(err, HFS_E_NOMEM, "backend cpu: out of memory for local-light "
                                "horizons (%d workers)", lc->threads);
        }
        s->slope = malloc(nn * sizeof *s->slope);
        s->in_grid = malloc(nn * sizeof *s->in_grid);
        s->lv_omega = malloc(nn * sizeof *s->lv_omega);
        s->om_k = malloc(np * sizeof *s->om_k);
        s->fl_k = malloc(np * sizeof *s->fl_k);
        if (!s->slope || !s->in_grid || !s->lv_omega || !s->om_k || !s->fl_k)
            return hfs_fail(err, HFS_E_NOMEM, "backend cpu: out of memory");
    }
    return HFS_OK;
}

int hfs_cpu_local_create(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                         const hfs_cpu_local_options *opt, const hfs_cpu_pyramid *p,
                         int threads, hfs_cpu_local **out, hfs_error *err)
{
    *out = NULL;
    hfs_cpu_local_options o;
    hfs_cpu_local_options_default(&o);
    if (opt)
        o = *opt;
    int n_src = 0;
    for (int i = 0; i < l->n_local && i < HFS_MAX_LOCAL_LIGHTS; ++i)
        n_src += hfs_local_light_contributes(&l->local[i]);
    if (n_src == 0 || !(l->albedo > 0.0))
        return HFS_OK;
    if (q->nphi_local < 1 || threads < 1)
        return hfs_fail(err, HFS_E_INVALID, "backend cpu: nphi_local=%d out of range", q->nphi_local);

    hfs_cpu_local *lc = calloc(1, sizeof *lc);
    if (!lc)
        return hfs_fail(err, HFS_E_NOMEM, "backend cpu: out of memory");
    lc->f = f;
    lc->w = f->width;
    lc->h = f->height;
    lc->nphi = q->nphi_local;
    lc->threads = threads;
    lc->mode = o.swath == HFS_LOCAL_SWATH_FULL ? HFS_LOCAL_SWATH_FULL : HFS_LOCAL_SWATH_PARTIAL;
    lc->path = q->visibility == HFS_VIS_WEDGE_TABLE ? HFS_VIS_WEDGE_TABLE : HFS_VIS_LEGENDRE;
    lc->row_pass = lc->mode == HFS_LOCAL_SWATH_FULL || lc->path == HFS_VIS_WEDGE_TABLE;
    lc->rho = l->albedo;
    hfs_gloss_make(l, &lc->gloss);
    hfs_zh_clamped_cosine(lc->h_zonal);
    hfs_wedge_elevation_moments(lc->E);
    take_sources(lc, f, l);
    lc->rb_atlas = hfs_cpu_pyramid_bounds(p, &lc->rb);
    lc->rb_z = hfs_cpu_pyramid_full(p, hfs_cpu_pyramid_count(p) - 1);
    lc->rb_stride = (size_t)hfs_cpu_pyramid_stride(p);
    int rc = make_directions(lc, f, q, p, err);
    if (!rc)
        rc = alloc_scratch(lc, err);
    if (rc) {
        hfs_cpu_local_destroy(lc);
        return rc;
    }
    *out = lc;
    return HFS_OK;
}

/* Full mode: per-scale horizons of row j in the fixed directions, with the
 * cos/sin of each angle (shared by every light). */
static void row_pass(const hfs_cpu_local *lc, local_scratch *s, int j, const double *normals)
{
    const size_t w = (size_t)lc->w, n = (size_t)lc->n_levels;
    for (int d = 0; d < lc->nphi; ++d) {
        const double c = lc->full_cs[2 * d], sn = lc->full_cs[2 * d + 1];
        double *fl = s->floors + (size_t)d * w;
        for (size_t x = 0; x < w; ++x)
            fl[x] = hfs_horizon_floor(normals + 3 * x, c, sn);
        double *om = s->om + (size_t)d * n * w;
        hfs_horizon_row(lc->plan, d, j, fl, NULL, om);
        double *co = s->co + (size_t)d * n * w, *si = s->si + (size_t)d * n * w;
        for (size_t k = 0; k < n * w; ++k) {
            co[k] = cos(om[k]);
            si[k] = sin(om[k]);
        }
    }
}

/* Elevation clamped into [lo, hi] as (cos, sin): the ray whose entry distance
 * decides whether a scale lies in front of the light. */
typedef struct clamp_trig {
    double lo, hi;
    int have_lo, have_hi;
    double clo, slo, chi, shi;
} clamp_trig;

static void clamp_dir(clamp_trig *ct, double om, double ce_om, double se_om, double *ce,
                      double *se)
{
    if (om < ct->lo) {
        if (!ct->have_lo) {
            ct->clo = cos(ct->lo);
            ct->slo = sin(ct->lo);
            ct->have_lo = 1;
        }
        *ce = ct->clo;
        *se = ct->slo;
    } else if (om > ct->hi) {
        if (!ct->have_hi) {
            ct->chi = cos(ct->hi);
            ct->shi = sin(ct->hi);
            ct->have_hi = 1;
        }
        *ce = ct->chi;
        *se = ct->shi;
    } else {
        *ce = ce_om;
        *se = se_om;
    }
}

/* NLP vector of the visible band (max(omega, lo), hi]. */
static void band(double omega, double lo, double hi, double out[HFS_NLP_N])
{
    hfs_nlp_visible_band(omega > lo ? omega : lo, hi, out);
}

/* Per-scale horizon angles of sample k (direction c, sn) at receiver
 * (i, j), cut at the light: a scale whose horizon point lies beyond the
 * light's entry into the receiver's view counts as the floor. */
static void scale_angles(const hfs_cpu_local *lc, local_scratch *s, const hfs_local_view *lv,
                         clamp_trig *ct, int use_rows, int i, int j, int k, double c,
                         double sn, double floor, double t_near, int k_lo, double *om)
{
    const int nl = lc->n_levels;
    if (use_rows) {
        const size_t base = (size_t)k * nl * lc->w + (size_t)i;
        for (int t = 0; t < nl; ++t) {
            const size_t at = base + (size_t)t * lc->w;
            const double o = s->om[at];
            double ce, se;
            if (t < k_lo) {
                om[t] = floor;
                continue;
            }
            if (lc->dist_world[t] < t_near) {
                om[t] = o;
                continue;
            }
            clamp_dir(ct, o, s->co[at], s->si[at], &ce, &se);
            om[t] = lc->dist_world[t] <= hfs_local_entry_distance(lv, c, sn, ce, se) ? o
                                                                                     : floor;
        }
    } else {
        for (int t = 0; t < k_lo; ++t)
            om[t] = floor;
        hfs_horizon_point_slopes(lc->scales, i, j, c, sn, k_lo, s->slope, s->in_grid);
        for (int t = k_lo; t < nl; ++t) {
            if (!s->in_grid[t]) {
                om[t] = floor;
                continue;
            }
            const double dd = s->slope[t], o = atan(dd);
            if (lc->dist_world[t] < t_near) {
                om[t] = o;
                continue;
            }
            const double ce_o = 1.0 / sqrt(1.0 + dd * dd), se_o = dd * ce_o;
            double ce, se;
            clamp_dir(ct, o, ce_o, se_o, &ce, &se);
            om[t] = lc->dist_world[t] <= hfs_local_entry_distance(lv, c, sn, ce, se) ? o
                                                                                     : floor;
        }
    }
}

/* Sample (c, sn)'s own ray from receiver (i, j) (issue 36 item 1, as the
 * key lights search theirs): the receiver's own cell and every crossing and
 * cell of the bilinear surface out to t_last texels, where the sphere's
 * section by the sample's half-plane can begin, so every occluder searched
 * lies in front of the light; the scales' samples alone step over a narrow
 * one.  The largest of `start` and their slopes, as an angle.  GLES:
 * local_visibility.frag ray_horizon. */
static double ray_horizon(const hfs_cpu_local *lc, int i, int j, double c, double sn,
                          double t_last, double start)
{
    double dist = 0.0;
    const double t = hfs_ray_bound_search_cells(lc->rb, lc->rb_atlas, lc->rb_z, lc->rb_stride, i,
                                                j, c, sn, 0.0, t_last,
                                                lc->f->zscale / lc->f->dx, 0.0, start, &dist,
                                                NULL);
    return atan(fmax(t, hfs_field_first_cell_slope(lc->f, i, j, c, sn)));
}

/* Legendre path, sample k: g = sum_r m_r A_k[r] E[r], then 4-dots with the
 * visible and the open band, added to sums (num, den, den_scale). */
static void legendre_sums(const hfs_cpu_local *lc, const hfs_local_swath *sw,
                          const hfs_local_hat *hats, const double m[HFS_SH_N], int k, double c,
                          double sn, double omega, double floor, const clamp_trig *ct,
                          double sums[3])
{
    double a_loc[HFS_SH_N];
    const double *A = a_loc;
    if (sw->full)
        A = lc->full_A + (size_t)k * HFS_SH_N;
    else
        hfs_local_weights_at(c, sn, hfs_local_sample_hat(sw, hats, k), a_loc); /* snapped: < 1e-12 off */
    double g[HFS_NLP_N] = {0.0, 0.0, 0.0, 0.0};
    for (int r = 0; r < HFS_SH_N; ++r) {
        const double wr = m[r] * A[r];
        const double *e = lc->E + r * HFS_NLP_N;
        g[0] += wr * e[0];
        g[1] += wr * e[1];
        g[2] += wr * e[2];
        g[3] += wr * e[3];
    }
    double vb[HFS_NLP_N], ob[HFS_NLP_N];
    band(omega, ct->lo, ct->hi, vb);
    band(floor, ct->lo, ct->hi, ob);
    for (int q = 0; q < HFS_NLP_N; ++q) {
        sums[0] += g[q] * vb[q];
        sums[1] += g[q] * ob[q];
        sums[2] += fabs(g[q] * ob[q]);
    }
}

/* The ratio form's visible fraction (DESIGN.md "Local lights"). */
static double visible_ratio(double num, double den, double den_scale)
{
    if (num == den)
        return 1.0; /* no horizon above its floor: the unshadowed value */
    if (den > 1e-12 * den_scale)
        return fmin(1.0, fmax(0.0, num / den));
    return 0.0;
}

/* Adds w Le to the glossy term sp (NULL: not glossy). */
static void add_spec(double *sp, double w, const local_src *src)
{
    for (int ch = 0; sp && ch < 3; ++ch)
        sp[ch] += w * src->le[ch];
}

/* One light at one receiver: adds to lo[3] and, when glossy (r: R with
 * N.R = nr > 0), to sp[3] (may be NULL). */
/* The visible fraction of the light's cap as seen from receiver (i, j)
 * (normal n, H(N) hn): the swath's samples, each with its window, floor
 * and horizons, summed in the Legendre bands or through the wedge tables,
 * in the ratio form (num / den). */
double hfs_cpu_local_cap_ratio(const hfs_cpu_local *lc, local_scratch *s,
                               const hfs_local_view *lv, int i, int j, const double n[3],
                               const double hn[HFS_SH_N], int rows)
{
    double zh[HFS_ZH_N], l_sh[HFS_SH_N], m[HFS_SH_N];
    hfs_zh_cap(lv->alpha, zh);
    hfs_sh_rotate_zonal(zh, lv->dir[0], lv->dir[1], lv->dir[2], l_sh);
    hfs_sh_product(hn, l_sh, m);

    hfs_local_swath sw;
    hfs_local_swath_make(lv, lc->nphi, lc->mode, lc->path, &sw);
    const int use_rows = sw.full && lc->row_pass && rows; /* rows: row j's pass ran */
    /* Every sample meets the cap when the swath is partial or the light covers
     * every azimuth: exact per-sample windows.  Otherwise the key-light
     * window (a full swath around a light that does not surround). */
    const int exact_window = !sw.full || lv->surround;
    double glo = lv->elev_l - lv->alpha, ghi = lv->elev_l + lv->alpha;
    glo = glo < -HALF_PI ? -HALF_PI : glo;
    ghi = ghi > HALF_PI ? HALF_PI : ghi;
    /* Farthest horizontal distance that can lie in front of the light: an
     * entry point (on the sphere: <= rho_h + r) or a closest approach (<= d). */
    const double reach = exact_window ? fmin(lv->d, lv->rho_h + lv->r) : lv->d;
    const int nl = lc->n_levels;
    int s_lo = 0; /* first scale within reach (distances fall with the index) */
    while (s_lo < nl && lc->dist_world[s_lo] > reach)
        ++s_lo;

    hfs_local_hat hats[3];
    if (!sw.full)
        hfs_local_swath_hats(&sw, hats);
    double num = 0.0, den = 0.0, den_scale = 0.0;
    for (int k = 0; k < sw.n; ++k) {
        double c, sn;
        const double phi = sw.phi0 + k * sw.dphi;
        if (sw.full) {
            c = lc->full_cs[2 * k];
            sn = lc->full_cs[2 * k + 1];
        } else {
            hfs_horizon_snap_dir(phi, &c, &sn);
        }
        clamp_trig ct = {0};
        int has_window = 1;
        if (exact_window)
            has_window = hfs_local_cap_window(lv, c, sn, &ct.lo, &ct.hi);
        else
            ct.lo = glo, ct.hi = ghi;
        const int tables = lc->path == HFS_VIS_WEDGE_TABLE;
        if (!has_window) {
            if (!tables)
                continue; /* empty band: contributes 0 to num and den */
            ct.lo = glo;  /* tables have no window; it only orients the */
            ct.hi = ghi;  /* distance test below                          */
        }
        const double floor = use_rows ? s->floors[(size_t)k * lc->w + i]
                                      : hfs_horizon_floor(n, c, sn);
        /* With an exact window every ray tested enters the sphere, at a
         * point of the sphere's section by this azimuth's half-plane, whose
         * horizontal extent is [u - g, u + g]: scales nearer than u - g
         * certainly count, scales beyond u + g certainly do not (the same
         * decisions as the entry test, made without it). */
        double t_near = -1.0;
        int k_lo = s_lo;
        if (exact_window) {
            const double u = c * lv->v[0] + sn * lv->v[1], wp = -sn * lv->v[0] + c * lv->v[1];
            const double g = sqrt(fmax(0.0, lv->r * lv->r - wp * wp));
            t_near = u - g;
            while (k_lo < nl && lc->dist_world[k_lo] > u + g)
                ++k_lo;
        }
        double *om = s->lv_omega;
        scale_angles(lc, s, lv, &ct, use_rows, i, j, k, c, sn, floor, t_near, k_lo, om);
        double omega = hfs_horizon_bspline_max(om, nl, 1, floor);
        /* the ray itself, where the light's section lies past the own cell,
         * searched from what the scales found (tables count every
         * elevation; the Legendre bands none below lo, none at all from hi) */
        if (exact_window && t_near >= HFS_LOCAL_RAY_FROM * lc->f->dx && (tables || omega < ct.hi))
            omega = fmax(omega, ray_horizon(lc, i, j, c, sn, t_near / lc->f->dx,
                                            tan(tables ? omega : fmax(omega, ct.lo))));
        if (tables) {
            s->om_k[k] = omega;
            s->fl_k[k] = floor;
            continue;
        }
        double sums[3] = {num, den, den_scale};
        legendre_sums(lc, &sw, hats, m, k, c, sn, omega, floor, &ct, sums);
        num = sums[0], den = sums[1], den_scale = sums[2];
    }
    if (lc->path == HFS_VIS_WEDGE_TABLE) {
        double vk[HFS_SH_N], vo[HFS_SH_N];
        hfs_visibility_eval(lc->tables, s->om_k, vk);
        hfs_visibility_eval(lc->tables, s->fl_k, vo);
        num = hfs_sh_dot(vk, m);
        den = hfs_sh_dot(vo, m);
        den_scale = sqrt(hfs_sh_dot(m, m) * hfs_sh_dot(vo, vo));
    }
    return visible_ratio(num, den, den_scale);
}

/* Light q's fraction at texel (i, j): the grid's, read bilinearly
 * (shade.frag local_lights), clamped to [0, 1]. */
static double grid_ratio_at(const hfs_cpu_local *lc, int q, int i, int j)
{
    int a0, b0;
    double tx, ty;
    hfs_grid_axis(i, lc->sub, lc->w, &a0, &tx);
    hfs_grid_axis(j, lc->sub, lc->h, &b0, &ty);
    const int a1 = a0 + 1 < lc->gw ? a0 + 1 : a0, b1 = b0 + 1 < lc->gh ? b0 + 1 : b0;
    const double *g = lc->grid + (size_t)q * lc->gh * lc->gw;
    const double r = (g[(size_t)b0 * lc->gw + a0] * (1.0 - tx) + g[(size_t)b0 * lc->gw + a1] * tx) *
                         (1.0 - ty) +
                     (g[(size_t)b1 * lc->gw + a0] * (1.0 - tx) + g[(size_t)b1 * lc->gw + a1] * tx) * ty;
    return fmin(1.0, fmax(0.0, r));
}

static void shade(const hfs_cpu_local *lc, local_scratch *s, const local_src *src, int i,
                  int j, const double p[3], const double n[3], const double hn[HFS_SH_N],
                  const double r[3], double nr, double lo[3], double *sp)
{
    hfs_local_view lv;
    hfs_local_view_make(&src->light, p, &lv);
    if (lv.inside) {
        /* E = pi over the whole sphere, nothing in between (SPEC); the lobe
         * times the cosine integrates to at most 1: ks Le (exact at R = N). */
        for (int ch = 0; ch < 3; ++ch)
            lo[ch] += lc->rho * src->le[ch];
        add_spec(sp, nr > 0.0 ? lc->gloss.ks : 0.0, src);
        return;
    }
    /* The glossy term's weight per unit E_cap ratio: the lobe at the centre. */
    const double gl = nr > 0.0 ? lc->gloss.ks * hfs_gloss_lobe(&lc->gloss, r, lv.dir) : 0.0;
    const double cos_beta = n[0] * lv.dir[0] + n[1] * lv.dir[1] + n[2] * lv.dir[2];
    const double e_cap = hfs_cap_irradiance(cos_beta, lv.alpha);
    if (!(e_cap > 0.0))
        return;
    if (src->open) { /* nothing can shadow it: the unshadowed value */
        for (int ch = 0; ch < 3; ++ch)
            lo[ch] += lc->rho / PI * e_cap * src->le[ch];
        add_spec(sp, gl * e_cap, src);
        return;
    }

    const double ratio = lc->grid ? grid_ratio_at(lc, (int)(src - lc->src), i, j)
                                  : hfs_cpu_local_cap_ratio(lc, s, &lv, i, j, n, hn, 1);
    const double scale = lc->rho / PI * e_cap * ratio;
    for (int ch = 0; ch < 3; ++ch)
        lo[ch] += scale * src->le[ch];
    add_spec(sp, gl * e_cap * ratio, src);
}

void hfs_cpu_local_row(const hfs_cpu_local *lc, int worker, int j, const double *normals,
                       double *lo_row, double *sp_row)
{
    local_scratch *s = &lc->scratch[worker];
    const hfs_field *f = lc->f;
    for (int x = 0; x < 3 * lc->w; ++x)
        lo_row[x] = 0.0;
    for (int x = 0; sp_row && x < 3 * lc->w; ++x)
        sp_row[x] = 0.0;
    if (lc->row_pass && !lc->grid)
        row_pass(lc, s, j, normals);
    for (int i = 0; i < lc->w; ++i) {
        const double *n = normals + 3 * i;
        const double p[3] = {i * f->dx, j * f->dx, hfs_field_lifted_z(f, i, j)};
        double hn[HFS_SH_N];
        hfs_sh_rotate_zonal(lc->h_zonal, n[0], n[1], n[2], hn);
        double r[3];
        const double nr = sp_row ? hfs_gloss_reflect(&lc->gloss, p, n, r) : 0.0;
        for (int q = 0; q < lc->n_src; ++q)
            shade(lc, s, &lc->src[q], i, j, p, n, hn, r, nr, lo_row + 3 * i,
                  sp_row ? sp_row + 3 * i : NULL);
    }
}
