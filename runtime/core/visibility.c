/*
 * visibility.c — see visibility.h.  All SH math (M_lin, NLP vectors,
 * wedge tables, z-rotation, mirroring) comes from sh.h; this file only lays
 * wedges out and sums them.
 */
#include "visibility.h"
#include "lights.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define HALF_PI 1.57079632679489661923
#define MLIN_N (HFS_SH_N * 2 * HFS_NLP_N)

/* ---- swath layout ----------------------------------------------------------- */

void hfs_swath_full(int n, hfs_swath *s)
{
    s->n = n < 1 ? 1 : n;
    s->full = 1;
    s->phi0 = 0.0;
    s->dphi = 2.0 * PI / s->n;
    s->elev_lo = -HALF_PI;
    s->elev_hi = HALF_PI;
}

void hfs_swath_key(double phi, double elev, double alpha, int nphi_key,
                   int nphi_env, hfs_swath *s)
{
    alpha = hfs_key_vis_alpha(alpha); /* lights.h: the window must not collapse */
    const double ratio = sin(alpha) / cos(elev); /* cos(elev) >= 0; /0 -> inf */
    const double lo = elev - alpha, hi = elev + alpha;
    if (fabs(elev) + alpha >= HALF_PI || !(ratio < 1.0)) {
        hfs_swath_full(nphi_key > nphi_env ? nphi_key : nphi_env, s);
    } else {
        /* The disk spans azimuths phi +- h.  Its samples sit on a lattice of
         * the circle, k d with d = 2 pi / N, N the largest "round" count
         * (1..4, then 4..7 times a power of two: consecutive ones differ
         * by at most 1.25x) whose spacing is not finer than the disk's own
         * 2h / nphi_key: then the samples (and so the horizons behind them)
         * stay the same while the light moves inside the sampled swath, or
         * while its elevation changes h a little (the frame planner keeps
         * them, runtime/gles/plan.h).  The swath is the run of lattice samples whose
         * wedges (+- d/2 about each) cover phi +- h: the spacing is within
         * 1.25x of 2h / nphi_key (1.5x at nphi_key = 1, where N = PI / h
         * >= 2 can fall between the counts 2 and 3), and the covering run
         * has 0.8 nphi_key to nphi_key + 1 samples, about as many as
         * centred ones. */
        const double h = asin(ratio);
        const int n_req = nphi_key < 1 ? 1 : nphi_key;
        const double n_max = PI * n_req / h; /* circle / (2h / nphi_key) */
        double n_lat = floor(n_max);
        if (n_max >= 5.0) {
            const double base = ldexp(1.0, (int)floor(log2(n_max / 4.0)));
            n_lat = 4.0 * base;
            for (int m = 5; m <= 7 && m * base <= n_max; ++m)
                n_lat = m * base;
        }
        if (n_lat < 1.0)
            n_lat = 1.0; /* a disk wider than the circle's half: 2 samples */
        const double d = 2.0 * PI / n_lat;
        const double phin = phi - 2.0 * PI * floor(phi / (2.0 * PI));
        const double k0 = floor((phin - h) / d + 0.5), k1 = ceil((phin + h) / d - 0.5);
        s->n = (int)(k1 - k0) + 1;
        s->full = 0;
        s->dphi = d;
        s->phi0 = k0 * d;
    }
    s->elev_lo = lo < -HALF_PI ? -HALF_PI : lo;
    s->elev_hi = hi > HALF_PI ? HALF_PI : hi;
}

double hfs_swath_phi(const hfs_swath *s, int j)
{
    return s->phi0 + j * s->dphi;
}

int hfs_swath_wedge_count(const hfs_swath *s)
{
    return s->full ? s->n : s->n + 1;
}

void hfs_swath_get_wedge(const hfs_swath *s, int w, hfs_swath_wedge *out)
{
    if (s->full) {
        out->start = hfs_swath_phi(s, w);
        out->extent = s->dphi;
        out->a = w;
        out->b = (w + 1) % s->n;
    } else if (w == 0) {
        out->start = s->phi0 - 0.5 * s->dphi;
        out->extent = 0.5 * s->dphi;
        out->a = -1;
        out->b = 0;
    } else if (w == s->n) {
        out->start = hfs_swath_phi(s, s->n - 1);
        out->extent = 0.5 * s->dphi;
        out->a = s->n - 1;
        out->b = -1;
    } else {
        out->start = hfs_swath_phi(s, w - 1);
        out->extent = s->dphi;
        out->a = w - 1;
        out->b = w;
    }
}

/* ---- visibility object --------------------------------------------------------- */

/* A sparse 16x16 linear map (a z-rotation, possibly after a mirror): at most
 * a few nonzeros per row, found by applying the library map to unit vectors. */
typedef struct sparse_map {
    int cnt[HFS_SH_N];
    int idx[HFS_SH_N][HFS_SH_N];
    double val[HFS_SH_N][HFS_SH_N];
} sparse_map;

struct hfs_visibility {
    hfs_swath swath;
    hfs_visibility_path path;
    int n_wedges;
    hfs_swath_wedge *wedges;
    double occ_top[HFS_NLP_N];     /* NLP occlusion of the step at pi/2 */
    /* Legendre */
    double m_int[MLIN_N], m_bnd[MLIN_N];  /* M_lin(dphi), M_lin(dphi/2) */
    double *c;                            /* n x 16x4 folded matrices */
    /* Wedge tables */
    hfs_wedge_tables *tables;
    sparse_map *place;                    /* per wedge: R(angle) [o mirror] */
};

/* Placement of wedge w in the table path: a start boundary wedge is the
 * mirrored table wedge rotated to its inner end (sample 0), every other wedge
 * the table wedge rotated to its start. */
static void table_placement(const hfs_swath_wedge *wd, double *angle, int *mirror)
{
    *mirror = wd->a < 0;
    *angle = wd->a < 0 ? wd->start + wd->extent : wd->start;
}

static void build_sparse(double angle, int mirror, sparse_map *m)
{
    double col[HFS_SH_N][HFS_SH_N]; /* col[k] = map(e_k) */
    for (int k = 0; k < HFS_SH_N; ++k) {
        double e[HFS_SH_N] = {0};
        e[k] = 1.0;
        if (mirror)
            hfs_sh_mirror_y(e, e);
        hfs_sh_rotate_z(e, angle, col[k]);
    }
    for (int r = 0; r < HFS_SH_N; ++r) {
        m->cnt[r] = 0;
        for (int k = 0; k < HFS_SH_N; ++k)
            if (col[k][r] != 0.0) {
                m->idx[r][m->cnt[r]] = k;
                m->val[r][m->cnt[r]] = col[k][r];
                m->cnt[r]++;
            }
    }
}

static void sparse_accumulate(const sparse_map *m, const double t[HFS_SH_N],
                              double V[HFS_SH_N])
{
    for (int r = 0; r < HFS_SH_N; ++r) {
        double s = 0.0;
        for (int q = 0; q < m->cnt[r]; ++q)
            s += m->val[r][q] * t[m->idx[r][q]];
        V[r] += s;
    }
}

int hfs_visibility_create(const hfs_swath *s, hfs_visibility_path path,
                          hfs_visibility **out, hfs_error *err)
{
    *out = NULL;
    if (!s || s->n < 1 || !(s->dphi > 0.0) || s->dphi > 2.0 * PI * (1.0 + 1e-12))
        return hfs_fail(err, HFS_E_INVALID, "visibility: invalid swath");
    hfs_visibility *v = calloc(1, sizeof *v);
    if (!v)
        goto err_nomem;
    v->swath = *s;
    v->path = path == HFS_VIS_WEDGE_TABLE ? HFS_VIS_WEDGE_TABLE : HFS_VIS_LEGENDRE;
    v->n_wedges = hfs_swath_wedge_count(s);
    v->wedges = malloc((size_t)v->n_wedges * sizeof *v->wedges);
    if (!v->wedges)
        goto err_nomem;
    for (int w = 0; w < v->n_wedges; ++w)
        hfs_swath_get_wedge(s, w, &v->wedges[w]);
    /* visible_band(omega, hi) = occlusion(hi) - occlusion(omega) */
    hfs_nlp_occlusion(s->elev_hi, v->occ_top);

    if (v->path == HFS_VIS_LEGENDRE) {
        hfs_wedge_mlin(s->dphi, v->m_int);
        hfs_wedge_mlin(0.5 * s->dphi, v->m_bnd);
        v->c = calloc((size_t)s->n * HFS_SH_N * HFS_NLP_N, sizeof *v->c);
        if (!v->c)
            goto err_nomem;
        for (int w = 0; w < v->n_wedges; ++w) {
            const hfs_swath_wedge *wd = &v->wedges[w];
            const double *m = (wd->a < 0 || wd->b < 0) ? v->m_bnd : v->m_int;
            for (int q = 0; q < 2; ++q) {
                const int j = q == 0 ? wd->a : wd->b;
                if (j < 0)
                    continue; /* fully blocked end: the zero vector */
                double *cj = v->c + (size_t)j * HFS_SH_N * HFS_NLP_N;
                for (int c = 0; c < HFS_NLP_N; ++c) {
                    double col[HFS_SH_N];
                    for (int r = 0; r < HFS_SH_N; ++r)
                        col[r] = m[r * 2 * HFS_NLP_N + 4 * q + c];
                    hfs_sh_rotate_z(col, wd->start, col);
                    for (int r = 0; r < HFS_SH_N; ++r)
                        cj[r * HFS_NLP_N + c] += col[r];
                }
            }
        }
    } else {
        v->tables = hfs_wedge_tables_create_ext(s->dphi, 0.5 * s->dphi, HFS_VIS_TABLE_SIZE);
        if (!v->tables) {
            const double dphi = s->dphi;
            hfs_visibility_destroy(v);
            return hfs_fail(err, HFS_E_NOMEM, "visibility: cannot build wedge tables for "
                            "dphi = %g (out of memory, or a swath too narrow)", dphi);
        }
        v->place = malloc((size_t)v->n_wedges * sizeof *v->place);
        if (!v->place)
            goto err_nomem;
        for (int w = 0; w < v->n_wedges; ++w) {
            double angle;
            int mirror;
            table_placement(&v->wedges[w], &angle, &mirror);
            build_sparse(angle, mirror, &v->place[w]);
        }
    }
    *out = v;
    return HFS_OK;

err_nomem:
    hfs_visibility_destroy(v);
    return hfs_fail(err, HFS_E_NOMEM, "visibility: out of memory");
}

void hfs_visibility_destroy(hfs_visibility *v)
{
    if (!v)
        return;
    hfs_wedge_tables_destroy(v->tables);
    free(v->place);
    free(v->c);
    free(v->wedges);
    free(v);
}

const hfs_swath *hfs_visibility_swath(const hfs_visibility *v) { return &v->swath; }
hfs_visibility_path hfs_visibility_get_path(const hfs_visibility *v) { return v->path; }

const double *hfs_visibility_sample_matrix(const hfs_visibility *v, int j)
{
    if (!v->c || j < 0 || j >= v->swath.n)
        return NULL;
    return v->c + (size_t)j * HFS_SH_N * HFS_NLP_N;
}

/* NLP vector of the visible band (max(omega, elev_lo), elev_hi]. */
static inline void visible_nlp(const hfs_visibility *v, double omega, double out[HFS_NLP_N])
{
    if (omega < v->swath.elev_lo)
        omega = v->swath.elev_lo;
    if (omega >= v->swath.elev_hi) {
        out[0] = out[1] = out[2] = out[3] = 0.0;
        return;
    }
    double occ[HFS_NLP_N];
    hfs_nlp_occlusion(omega, occ);
    for (int l = 0; l < HFS_NLP_N; ++l)
        out[l] = v->occ_top[l] - occ[l];
}

/* Table lookup of one wedge (canonical orientation, before placement). */
static void table_wedge(const hfs_visibility *v, const hfs_swath_wedge *wd,
                        const double *omega, double t[HFS_SH_N])
{
    if (wd->a < 0)
        hfs_wedge_boundary(v->tables, omega[wd->b], t);
    else if (wd->b < 0)
        hfs_wedge_boundary(v->tables, omega[wd->a], t);
    else
        hfs_wedge_interior(v->tables, omega[wd->a], omega[wd->b], t);
}

void hfs_visibility_eval(const hfs_visibility *v, const double *omega,
                         double V[HFS_SH_N])
{
    for (int k = 0; k < HFS_SH_N; ++k)
        V[k] = 0.0;
    if (v->path == HFS_VIS_LEGENDRE) {
        for (int j = 0; j < v->swath.n; ++j) {
            double nlp[HFS_NLP_N];
            visible_nlp(v, omega[j], nlp);
            const double *cj = v->c + (size_t)j * HFS_SH_N * HFS_NLP_N;
            for (int r = 0; r < HFS_SH_N; ++r) {
                const double *row = cj + r * HFS_NLP_N;
                V[r] += row[0] * nlp[0] + row[1] * nlp[1] + row[2] * nlp[2] + row[3] * nlp[3];
            }
        }
    } else {
        for (int w = 0; w < v->n_wedges; ++w) {
            double t[HFS_SH_N];
            table_wedge(v, &v->wedges[w], omega, t);
            sparse_accumulate(&v->place[w], t, V);
        }
    }
}

void hfs_visibility_eval_reference(const hfs_visibility *v, const double *omega,
                                   double V[HFS_SH_N])
{
    for (int k = 0; k < HFS_SH_N; ++k)
        V[k] = 0.0;
    for (int w = 0; w < v->n_wedges; ++w) {
        const hfs_swath_wedge *wd = &v->wedges[w];
        double t[HFS_SH_N];
        double angle = wd->start;
        if (v->path == HFS_VIS_LEGENDRE) {
            double x[2 * HFS_NLP_N] = {0};
            const double lo = v->swath.elev_lo, hi = v->swath.elev_hi;
            if (wd->a >= 0)
                hfs_nlp_visible_band(fmax(omega[wd->a], lo), hi, x);
            if (wd->b >= 0)
                hfs_nlp_visible_band(fmax(omega[wd->b], lo), hi, x + HFS_NLP_N);
            const double *m = (wd->a < 0 || wd->b < 0) ? v->m_bnd : v->m_int;
            for (int r = 0; r < HFS_SH_N; ++r) {
                double s = 0.0;
                for (int c = 0; c < 2 * HFS_NLP_N; ++c)
                    s += m[r * 2 * HFS_NLP_N + c] * x[c];
                t[r] = s;
            }
        } else {
            int mirror;
            table_wedge(v, wd, omega, t);
            table_placement(wd, &angle, &mirror);
            if (mirror)
                hfs_sh_mirror_y(t, t);
        }
        hfs_sh_rotate_z(t, angle, t);
        for (int k = 0; k < HFS_SH_N; ++k)
            V[k] += t[k];
    }
}
