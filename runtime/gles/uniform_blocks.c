/*
 * uniform_blocks.c — see uniform_blocks.h.
 */
#include "uniform_blocks.h"

#include "gl_util.h"
#include "sh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

/* ---- blocks -------------------------------------------------------------------- */

size_t hfs_gles_scales_vec4(void)
{
    return 1 + HFS_GLES_MAX_LEVELS;
}

void hfs_gles_pack_scales(const hfs_gles_layout *L, float *dst)
{
    memset(dst, 0, hfs_gles_scales_vec4() * 16);
    *(hfs_gles_scales_head *)dst = (hfs_gles_scales_head){.n_scales = L->n_levels};
    hfs_gles_scale *scale = (hfs_gles_scale *)(dst + 4);
    for (int i = 0; i < L->n_levels; ++i) {
        const double d = L->spacing[i];
        double inv = L->hscale * L->zscale / (d * L->dx);
        if (!(inv < 1e30))
            inv = 1e30;
        scale[i] = (hfs_gles_scale){.spacing = (float)d, .inv_run = (float)inv,
                                    .read_layer = (float)L->read_layer[i]};
    }
}

static double snap_unit(double c)
{
    return fabs(c) < 1e-12 ? 0.0 : c; /* cpu_horizon.c */
}

void hfs_gles_swath_dir(const hfs_swath *s, int j, double *c, double *sn)
{
    const double phi = hfs_swath_phi(s, j);
    *c = snap_unit(cos(phi));
    *sn = snap_unit(sin(phi));
}

size_t hfs_gles_swath_vec4(int n)
{
    return (sizeof(hfs_gles_swath_head) + (size_t)n * sizeof(hfs_gles_swath_sample) +
            (size_t)n * sizeof(hfs_gles_swath_matrix) +
            ((size_t)n + 1) * sizeof(hfs_gles_wedge_rot)) / 16;
}

hfs_gles_swath_block hfs_gles_swath_view(float *dst, int n)
{
    hfs_gles_swath_block b;
    b.head = (hfs_gles_swath_head *)dst;
    b.dir = (hfs_gles_swath_sample *)(b.head + 1);
    b.matrix = (hfs_gles_swath_matrix *)(b.dir + n);
    b.rot = (hfs_gles_wedge_rot *)(b.matrix + n);
    return b;
}

void hfs_gles_wedge_rot_set(hfs_gles_wedge_rot *r, double a, int mirror)
{
    for (int m = 1; m <= 3; ++m) {
        r->cos_ma[m - 1] = (float)cos(m * a);
        r->sin_ma[m - 1] = (float)sin(m * a);
    }
    r->mirror = (float)mirror;
}

/* The head and each sample's direction: the part of HfsSwath the Legendre,
 * wedge and slice layouts share. */
static void pack_head_dirs(const hfs_gles_layout *L, const hfs_swath *s,
                           const hfs_gles_swath_block *b)
{
    b->head->elev_lo = (float)s->elev_lo;
    b->head->elev_hi = (float)s->elev_hi;
    b->head->n = (float)s->n;
    b->head->full = (float)s->full;
    double occ[HFS_NLP_N];
    hfs_nlp_occlusion(s->elev_hi, occ);
    for (int c = 0; c < 4; ++c)
        b->head->occ_top[c] = (float)occ[c];
    for (int j = 0; j < s->n; ++j) {
        float cs[2];
        const hfs_swath one = {.n = 1, .full = s->full, .phi0 = hfs_swath_phi(s, j), .dphi = s->dphi};
        hfs_gles_swath_float_dirs(L, &one, cs);
        b->dir[j].cos = cs[0];
        b->dir[j].sin = cs[1];
    }
}

void hfs_gles_pack_swath(const hfs_gles_layout *L, const hfs_visibility *v, float *dst)
{
    const hfs_swath *s = hfs_visibility_swath(v);
    const int n = s->n;
    memset(dst, 0, hfs_gles_swath_vec4(n) * 4 * sizeof *dst);
    const hfs_gles_swath_block b = hfs_gles_swath_view(dst, n);
    pack_head_dirs(L, s, &b);
    for (int j = 0; j < n; ++j) {
        const double *m = hfs_visibility_sample_matrix(v, j);
        double frob = 0.0;
        if (m)
            for (int r = 0; r < HFS_SH_N; ++r)
                for (int q = 0; q < HFS_NLP_N; ++q) {
                    b.matrix[j].row[r][q] = (float)m[r * HFS_NLP_N + q];
                    frob += m[r * HFS_NLP_N + q] * m[r * HFS_NLP_N + q];
                }
        b.dir[j].c_norm = (float)sqrt(frob);
    }
    const int n_wedges = hfs_swath_wedge_count(s);
    for (int w = 0; w < n_wedges; ++w) {
        hfs_swath_wedge wd;
        hfs_swath_get_wedge(s, w, &wd);
        /* visibility.c table_placement: a start boundary wedge is the
         * mirrored table wedge rotated to its inner end. */
        const int mirror = wd.a < 0;
        hfs_gles_wedge_rot_set(&b.rot[w], mirror ? wd.start + wd.extent : wd.start, mirror);
    }
}

size_t hfs_gles_slices_vec4(int n)
{
    return (sizeof(hfs_gles_swath_head) + (size_t)n * sizeof(hfs_gles_swath_sample)) / 16 +
           HFS_SH_N + (size_t)n * 4;
}

/* The slope to the far edge of the texel's own cell in direction (c, s),
 * at t = 1 / max(|c|, |s|) texels (hfs_field_first_cell_slope), as weights
 * on the slopes to its 3 x 3 neighbourhood (differences over 1 texel),
 * row-major from (-1, -1); offsets split as the horizons' (cpu_horizon.c):
 * an axis exactly, so only one neighbour is read there.  The sample at
 * distance 1 lies between the cell's ends and never beats both. */
static void near_weights(double c, double s, float w[12])
{
    const double t = 1.0 / fmax(fabs(c), fabs(s));
    double o[2] = {c * t, s * t}, f[2];
    int io[2];
    for (int a = 0; a < 2; ++a) {
        const double r = nearbyint(o[a]);
        if (fabs(o[a] - r) < 1e-9)
            o[a] = r;
        io[a] = (int)floor(o[a]);
        f[a] = o[a] - floor(o[a]);
    }
    memset(w, 0, 12 * sizeof *w);
    for (int b = 0; b < 2; ++b)
        for (int a = 0; a < 2; ++a) {
            const double wt = (a ? f[0] : 1.0 - f[0]) * (b ? f[1] : 1.0 - f[1]);
            const int x = io[0] + a + 1, y = io[1] + b + 1;
            if (wt != 0.0) /* |c|, |s| <= 1: a weighted texel is in the 3 x 3 */
                w[3 * y + x] = (float)(wt / t);
        }
}

/* The profile terms each azimuthal factor's slots hold (uniform_blocks.h),
 * by |m|: 0 and 2 share one set. */
static const int slot_terms[4][4] = {{0, 2, 3, 6}, {1, 4, 5, -1}, {0, 2, 3, 6}, {1, 5, -1, -1}};

void hfs_gles_pack_dirs(const hfs_gles_layout *L, const hfs_swath *s, float *dst)
{
    memset(dst, 0, hfs_gles_slices_vec4(s->n) * 4 * sizeof *dst);
    const hfs_gles_swath_block b = hfs_gles_swath_view(dst, s->n);
    pack_head_dirs(L, s, &b);
}

void hfs_gles_pack_slices(const hfs_gles_layout *L, const hfs_visibility *v,
                          const hfs_slice_table *t, float *dst)
{
    const hfs_swath *s = hfs_visibility_swath(v);
    const int n = s->n;
    memset(dst, 0, hfs_gles_slices_vec4(n) * 4 * sizeof *dst);
    const hfs_gles_swath_block b = hfs_gles_swath_view(dst, n);
    pack_head_dirs(L, s, &b);
    double a[HFS_SH_N][HFS_SLICE_F];
    hfs_slice_profile(a);
    float *coef = (float *)(b.dir + n);
    for (int k = 0; k < HFS_SH_N; ++k) {
        const int m = abs(hfs_slice_order(k));
        for (int q = 0; q < 4; ++q)
            if (slot_terms[m][q] >= 0)
                coef[4 * k + q] = (float)(t->dphi * a[k][slot_terms[m][q]]);
    }
    float *nearw = coef + 4 * HFS_SH_N, *trig = nearw + 12 * (size_t)n;
    for (int j = 0; j < n; ++j) {
        near_weights(b.dir[j].cos, b.dir[j].sin, nearw + 12 * j);
        double c, sn; /* the slice's azimuthal factors, once per swath */
        hfs_gles_swath_dir(s, j, &c, &sn);
        const double c2 = c * c - sn * sn, s2 = 2.0 * c * sn;
        trig[4 * j] = (float)c2;
        trig[4 * j + 1] = (float)s2;
        trig[4 * j + 2] = (float)(c2 * c - s2 * sn);
        trig[4 * j + 3] = (float)(s2 * c + c2 * sn);
    }
}

/* ---- offsets -------------------------------------------------------------------- */

/* cpu_horizon.c split_offset. */
static void split_double(double o, int *io, int *frac_zero)
{
    const double r = nearbyint(o);
    if (fabs(o - r) < 1e-9)
        o = r;
    const double f = floor(o);
    *io = (int)f;
    *frac_zero = (o - f) == 0.0;
}

/* The shader's rule for one component, in float (volatile keeps the
 * compiler from contracting or widening).  Returns 0 when the sample lies
 * near the snapping threshold (within a factor 2 of the tolerance), where a
 * GPU whose float multiply or fused multiply-add differs by an ulp could
 * decide otherwise; else 1 with the class in *io, *frac_zero. */
static int split_float(float d, float u, int *io, int *frac_zero)
{
    volatile float o = d * u;
    const float r = floorf(o + 0.5f);
    volatile float tol = fabsf(o) * HFS_GLES_SNAP_REL;
    tol = tol + HFS_GLES_SNAP_ABS;
    const float dist = fabsf(o - r);
    if (dist > 0.5f * tol && dist < 2.0f * tol)
        return 0;
    const float sn = dist <= tol ? r : o;
    const float f = floorf(sn);
    *io = (int)f;
    *frac_zero = (sn - f) == 0.0f;
    return 1;
}

/* 1 if the float component uf classifies every scale like the CPU's u. */
static int component_ok(const hfs_gles_layout *L, double u, float uf)
{
    for (int i = 0; i < L->n_levels; ++i) {
        const double d = L->spacing[i];
        int io_d, fz_d, io_f, fz_f;
        split_double(d * u, &io_d, &fz_d);
        if (!split_float((float)d, uf, &io_f, &fz_f) || io_d != io_f || fz_d != fz_f)
            return 0;
    }
    return 1;
}

/* The float nearest to u, or a neighbour a few ulps away that component_ok
 * accepts (the direction moves by < 1e-5 relative: nothing a texture
 * coordinate can see).  *ok = 0 if none within 64 ulps does. */
static float float_component(const hfs_gles_layout *L, double u, int *ok)
{
    const float base = (float)u;
    *ok = 1;
    if (component_ok(L, u, base))
        return base;
    for (int k = 1; k <= 64; ++k) {
        float up = base, dn = base;
        for (int i = 0; i < k; ++i) {
            up = nextafterf(up, INFINITY);
            dn = nextafterf(dn, -INFINITY);
        }
        if (component_ok(L, u, up))
            return up;
        if (component_ok(L, u, dn))
            return dn;
    }
    *ok = 0;
    return base;
}

long hfs_gles_swath_float_dirs(const hfs_gles_layout *L, const hfs_swath *s, float *cs)
{
    long bad = 0;
    for (int j = 0; j < s->n; ++j) {
        double c, sn;
        hfs_gles_swath_dir(s, j, &c, &sn);
        int ok_c, ok_s;
        cs[2 * j] = float_component(L, c, &ok_c);
        cs[2 * j + 1] = float_component(L, sn, &ok_s);
        bad += !ok_c + !ok_s;
    }
    return bad;
}

long hfs_gles_offset_mismatches(const hfs_gles_layout *L, const hfs_swath *s)
{
    long bad = 0;
    for (int j = 0; j < s->n; ++j) {
        double c, sn;
        hfs_gles_swath_dir(s, j, &c, &sn);
        int ok_c, ok_s;
        const float fc = float_component(L, c, &ok_c), fs = float_component(L, sn, &ok_s);
        for (int i = 0; i < L->n_levels; ++i) {
            const double d = L->spacing[i];
            for (int comp = 0; comp < 2; ++comp) {
                int io_d, fz_d, io_f = 0, fz_f = 0;
                split_double(d * (comp ? sn : c), &io_d, &fz_d);
                const int sure = split_float((float)d, comp ? fs : fc, &io_f, &fz_f);
                bad += !sure || io_d != io_f || fz_d != fz_f;
            }
        }
    }
    return bad;
}

/* ---- key lights ------------------------------------------------------------------- */

/* The clamped cosine about N as SH: its (l, m) coefficient is k_l Y_lm(N)
 * (a zonal function rotated to N); k_l per band, k_3 = 0. */
static void cosine_band_factors(double kl[HFS_ZH_N])
{
    double zc[HFS_ZH_N], c[HFS_SH_N];
    hfs_zh_clamped_cosine(zc);
    hfs_sh_rotate_zonal(zc, 0.0, 0.0, 1.0, c);
    for (int l = 0; l < HFS_ZH_N; ++l)
        kl[l] = c[l * (l + 1)] / sqrt((2.0 * l + 1.0) / (4.0 * 3.14159265358979323846));
}

/* The Legendre path's per-direction weights w_j = C_j^T (H(N) * L) are
 * linear in the basis functions at the normal: the clamped cosine about N
 * is H_i(N) = k_l Y_i(N) (k_3 = 0), so w_j = sum_{i < 9} Y_i(N) A_j[i] with
 * A_j[i] = k_l(i) C_j^T (e_i * L), e_i the i-th unit coefficient vector.
 * Rows 0..8 of the light's matrices become A_j (rows 9..15 zero): the
 * factor pass needs no SH product per texel, and 9 terms per direction
 * instead of 16.  c_norm keeps |C_j|_F for the zero test of den. */
static void fold_key_matrices(const hfs_gles_key *k, const hfs_visibility *v, float *swath)
{
    const int n = hfs_visibility_swath(v)->n;
    const hfs_gles_swath_block b = hfs_gles_swath_view(swath, n);
    double kl[HFS_ZH_N];
    cosine_band_factors(kl);
    double pl[HFS_SH_N][HFS_SH_N]; /* pl[i] = e_i * L */
    for (int i = 0; i < HFS_SH_N; ++i) {
        double e[HFS_SH_N] = {0.0};
        e[i] = 1.0;
        hfs_sh_product(e, k->l_sh, pl[i]);
    }
    for (int j = 0; j < n; ++j) {
        const double *m = hfs_visibility_sample_matrix(v, j);
        for (int i = 0; i < HFS_SH_N; ++i) {
            const int l = i < 1 ? 0 : i < 4 ? 1 : i < 9 ? 2 : 3;
            for (int q = 0; q < HFS_NLP_N; ++q) {
                double a = 0.0;
                for (int r = 0; r < HFS_SH_N && l < 3; ++r)
                    a += m[r * HFS_NLP_N + q] * pl[i][r];
                b.matrix[j].row[i][q] = (float)(kl[l] * a);
            }
        }
    }
}

size_t hfs_gles_key_vec4(int n)
{
    return sizeof(hfs_gles_key_record) / 16 + hfs_gles_swath_vec4(n);
}

void hfs_gles_pack_key(const hfs_gles_layout *L, const hfs_gles_key *k, const hfs_visibility *v,
                       float *dst)
{
    const hfs_swath *s = hfs_visibility_swath(v);
    hfs_gles_key_record *rec = (hfs_gles_key_record *)dst;
    memset(rec, 0, sizeof *rec);
    rec->n = (float)s->n;
    rec->full = (float)s->full;
    rec->hz_layer = (float)k->hz_layer;
    rec->table_set = (float)k->table_set;
    for (int c = 0; c < 3; ++c) {
        rec->dir[c] = (float)k->dir[c];
        rec->le[c] = (float)k->le[c];
    }
    rec->alpha = (float)k->alpha;
    rec->l_norm = (float)k->l_norm;
    for (int c = 0; c < 16; ++c)
        rec->l_sh[c] = (float)k->l_sh[c];
    hfs_gles_pack_swath(L, v, (float *)(rec + 1));
    if (s->n > 0 && hfs_visibility_sample_matrix(v, 0))
        fold_key_matrices(k, v, (float *)(rec + 1));
}

void hfs_gles_env_occ_weights(const double l_env[3][HFS_SH_N], float out[3][16], double m[3])
{
    for (int c = 0; c < 3; ++c) {
        m[c] = 0.0;
        for (int k = 0; k < HFS_SH_N; ++k)
            m[c] += fabs(l_env[c][k]);
        for (int k = 0; k < 16; ++k)
            out[c][k] = k < HFS_SH_N && m[c] > 0.0 ? (float)(l_env[c][k] / m[c]) : 0.0f;
    }
}

void hfs_gles_cosine_transfer(float dst[16])
{
    double kl[HFS_ZH_N];
    cosine_band_factors(kl);
    for (int l = 0; l * l < HFS_SH_N; ++l)
        for (int m = -l; m <= l; ++m)
            dst[l * (l + 1) + m] = (float)kl[l];
}

void hfs_gles_open_transfer(float dst[16])
{
    /* The product at N = +z, where only the m = 0 coefficients are not 0;
     * a zonal function's (l, 0) coefficient at +z is k_l Y_l0(+z) with
     * Y_l0(+z) = sqrt((2l + 1) / 4 pi). */
    double zc[HFS_ZH_N], zh[HFS_ZH_N], c[HFS_SH_N], h[HFS_SH_N], t[HFS_SH_N];
    hfs_zh_clamped_cosine(zc);
    hfs_zh_cap(0.5 * 3.14159265358979323846, zh);
    hfs_sh_rotate_zonal(zc, 0.0, 0.0, 1.0, c);
    hfs_sh_rotate_zonal(zh, 0.0, 0.0, 1.0, h);
    hfs_sh_product(c, h, t);
    for (int l = 0; l * l < HFS_SH_N; ++l) {
        const double k = t[l * (l + 1)] / sqrt((2.0 * l + 1.0) / (4.0 * 3.14159265358979323846));
        for (int m = -l; m <= l; ++m)
            dst[l * (l + 1) + m] = (float)k;
    }
}
