/*
 * test_gles_fetch.c — the GLES renderer's timing report and fetch counts
 * (label "gl"; ctest test_gles_timing): timing levels 1 and 2 report every
 * pass, fetch counts and texture memory; on flat fields the env, key and
 * local passes' fetch counts equal a count made here from DESIGN.md,
 * exactly.  No GLES context of any kind: exit 77 (gl_test.h).
 */
#include "gles_render_util.h"

#include <stdlib.h>

static void flat_fetch_counts(hfs_renderer *r); /* exact counts on flat fields, below */

/* Timing levels: every pass named, times and memory reported, fetches
 * counted at level 2 (-1 at level 1 for env/key) and, on flat fields, equal
 * to an independent count (flat_fetch_counts: no sample is skipped by the
 * height bound there, so the count follows from the geometry alone). */
static int mode_timing(void)
{
    scene s;
    if (scene_make("dem", 64, HFS_DATA_DIR, &s))
        return 1;
    hfs_renderer *r = gles_or_skip(NULL);
    hfs_lighting l = scene_lighting(1, 1);
    hfs_quality q = quality("fp16", "legendre", 2);
    hfs_image img = {0};
    hfs_timings t;
    render(r, &s, &l, &q, &img);
    hfs_renderer_timings(r, &t);
    CHECK(t.n_passes == 0, "timing off: %d passes reported", t.n_passes);
    static const char *const names[] = {"upload", "decimate", "reconstruct", "env", "key",
                                        "transfer", "keyfactor", "shade", "readback"};
    const int n_names = (int)(sizeof names / sizeof names[0]);
    for (int level = 1; level <= 2; ++level) {
        hfs_renderer_set_timing(r, level);
        hfs_renderer_invalidate(r);
        render(r, &s, &l, &q, &img);
        hfs_renderer_timings(r, &t);
        printf("timing level %d (%s, %s): frame %.2f ms, passes %.2f ms, %zu texture bytes\n",
               level, t.method, t.device, t.frame_ms, t.gpu_ms, t.texture_bytes);
        CHECK(t.n_passes == n_names, "level %d: %d passes", level, t.n_passes);
        for (int p = 0; p < t.n_passes && p < n_names; ++p) {
            printf("  %-12s %8.3f ms %12.0f fetches\n", t.pass[p].name, t.pass[p].ms,
                   t.pass[p].fetches);
            CHECK(!strcmp(t.pass[p].name, names[p]), "pass %d is %s, want %s", p, t.pass[p].name,
                  names[p]);
            CHECK(t.pass[p].ms >= 0.0 && t.pass[p].ms < 60000.0, "%s: %g ms", t.pass[p].name,
                  t.pass[p].ms);
            if (level == 2 || (strcmp(names[p], "env") && strcmp(names[p], "key") &&
                               strcmp(names[p], "keyfactor")))
                CHECK(t.pass[p].fetches >= 0.0, "%s: fetches %g", names[p], t.pass[p].fetches);
            else
                CHECK(t.pass[p].fetches == -1.0, "%s at level 1: fetches %g", names[p],
                      t.pass[p].fetches);
            /* the key factor's counting twin: every texel reads its height
             * and its four neighbours' (the normal's central differences
             * and the one-sided slopes alike) and, per direction of the
             * swath, their four horizons (at least) */
            if (level == 2 && !strcmp(names[p], "keyfactor"))
                CHECK(t.pass[p].fetches >= 5.0 * s.f.width * s.f.height, "keyfactor: fetches %g",
                      t.pass[p].fetches);
            /* and no more than it needs: this light's texels search their
             * rays to the field's end, so the grid's receivers are not read
             * (109540 measured, 26.7 a texel, since the swath's rays are
             * searched at once as far as they are clear, DESIGN.md "The
             * swath's rays at once": 165265 when each direction searched
             * its own; since the normal and the
             * one-sided slopes share the neighbours' 4 reads: 181649 when
             * each read them; since normals are computed where they are
             * read: 169919 with a stored normal; since the
             * key lights solve every cell between crossings, DESIGN.md
             * "Every cell", the edge search's from where the near one
             * stopped; 119690 with the crossings alone; 136074 when the
             * receivers were read) */
            if (level == 2 && !strcmp(names[p], "keyfactor"))
                CHECK(t.pass[p].fetches <= 1.02 * 109540.0, "keyfactor: %g fetches > 1.02 x "
                      "109540", t.pass[p].fetches);
        }
        CHECK(t.texture_bytes > (size_t)64 * 64 * 4 * 10, "texture bytes %zu", t.texture_bytes);
        CHECK(t.frame_ms > 0.0 && t.gpu_ms > 0.0, "frame %g ms, passes %g ms", t.frame_ms,
              t.gpu_ms);
    }
    /* Level 2 destroyed the cached visibility; the next frame is still right. */
    hfs_image again = {0};
    hfs_renderer_set_timing(r, 0);
    render(r, &s, &l, &q, &again);
    hfs_renderer_invalidate(r);
    render(r, &s, &l, &q, &img);
    CHECK(bitequal(&img, &again), "frame after a counting frame differs");
    CHECK(hfs_renderer_set_timing(r, 3) == HFS_E_INVALID, "timing level 3 accepted");
    /* The slice path's split horizons: their far grid is the env pass's
     * "far" stage, counted at level 2 (-1 at level 1), and the frame after
     * the count is the frame before it. */
    hfs_quality qs = quality("fp16", "slice", 2);
    qs.split = 1;
    for (int level = 1; level <= 2; ++level) {
        hfs_renderer_set_timing(r, level);
        hfs_renderer_invalidate(r);
        render(r, &s, &l, &qs, &img);
        hfs_renderer_timings(r, &t);
        int far = -1;
        for (int p = 0; p < t.n_passes; ++p)
            far = strcmp(t.pass[p].name, "far") ? far : p;
        CHECK(far >= 0, "slice path with split horizons: no far stage timed");
        if (far >= 0)
            CHECK(level == 2 ? t.pass[far].fetches > 1000.0 : t.pass[far].fetches == -1.0,
                  "level %d: far stage fetches %g", level, t.pass[far].fetches);
    }
    hfs_renderer_set_timing(r, 0);
    render(r, &s, &l, &qs, &again);
    hfs_renderer_invalidate(r);
    render(r, &s, &l, &qs, &img);
    CHECK(bitequal(&img, &again), "slice frame after a counting frame differs");
    flat_fetch_counts(r);
    hfs_image_free(&img);
    hfs_image_free(&again);
    hfs_renderer_destroy(r);
    scene_free(&s);
    return failures ? 1 : 0;
}

/* ---- an independent count of the horizon passes' fetches ----------------------
 * Written from DESIGN.md alone ("Height pyramid", "Horizons", "Azimuth
 * swaths", "GLES path": "Visibility grid", the env / key / local passes),
 * not from the library's functions.  On a flat field every in-grid sample
 * is fetched: the environment's height bound skips a sample only when
 * (vmax - R_L(x)) / run <= the running max, and the plane's vmax sits a hair
 * (1e-5) above it while the running max starts at tan(floor) = 0.  So per
 * receiver of the visibility grid:
 *   env    4 (the normal's heights, hfs_normal_at) + NL (own height per
 *          read layer)
 *          + sum over the nphi_env directions of the in-grid scales
 *          (+ 4 per wedge on the wedge-table path: one table fetch each);
 *   key    per draw of up to 8 directions: 4 + NL, + the in-grid scales of
 *          each direction of the light's swath, + its gap search's reads
 *          ("Gap search", "Every cell": on a flat field no bound beats
 *          the flat max, so the walk never halves a run: fc_gap);
 *   local  per draw of up to 8 lights: 4 + NL; per light (receiver outside
 *          its sphere; full swath of nphi_local) the scales in-grid and not
 *          farther than the light's centre (the entry cut of a full swath;
 *          + 8 per wedge on the table path: V_k and V_open).
 * Scales: N = ceil(k log2 max(W, H)) + 1, distance d_i = 2^((N-1-i)/k),
 * i = N-1 (finest) down to 0, the first off-grid sample ends the direction
 * (distances grow and the grid is convex).  NL = N - min(k o, N - 1). */
static int fc_levels(int n, int k)
{
    /* smallest m with 2^m >= n^k, exactly (n^k < 2^63 for the sizes here) */
    unsigned long long p = 1;
    for (int i = 0; i < k; ++i)
        p *= (unsigned long long)n;
    int m = 0;
    while ((1ULL << m) < p)
        ++m;
    return m + 1;
}

/* DESIGN.md "Horizons", sample offsets: tiny components snap to 0, offsets
 * within 1e-9 texel of an integer to it; in-grid: 0 <= g + o <= size - 1. */
static int fc_in_grid(int gx, int gy, int w, int h, double d, double c, double s)
{
    double o[2] = {d * (fabs(c) < 1e-12 ? 0.0 : c), d * (fabs(s) < 1e-12 ? 0.0 : s)};
    const int g[2] = {gx, gy}, lim[2] = {w - 1, h - 1};
    for (int a = 0; a < 2; ++a) {
        if (fabs(o[a] - nearbyint(o[a])) <= 1e-9)
            o[a] = nearbyint(o[a]);
        if (g[a] + o[a] < 0.0 || g[a] + o[a] > lim[a])
            return 0;
    }
    return 1;
}

/* In-grid scales of one direction, fine to coarse from the near+1-th finest,
 * up to distance `cut`; *margin: the closest |d_i - cut| met (the GPU
 * compares in float). */
static long fc_scales_from(int gx, int gy, int w, int h, int n_lev, int k, double phi,
                           double cut, double *margin, int near)
{
    const double c = cos(phi), s = sin(phi);
    long n = 0;
    for (int i = n_lev - 1 - near; i >= 0; --i) {
        const double d = exp2((double)(n_lev - 1 - i) / k);
        if (margin && fabs(d - cut) < *margin)
            *margin = fabs(d - cut);
        if (!fc_in_grid(gx, gy, w, h, d, c, s) || d > cut)
            break;
        ++n;
    }
    return n;
}

/* In-grid refining samples (key_horizons.frag, env_horizons.frag) about
 * the scale at distance d0: on the flat field every slope ties, so the
 * refinement is about the finest scale searched. */
static long fc_refined(int gx, int gy, int w, int h, double d0, int refine, int k, double phi)
{
    long n = 0;
    for (int r = 0; r < refine; ++r) {
        const double f = exp2((-1.0 + 2.0 * (r + 1) / (refine + 1)) / k);
        n += fc_in_grid(gx, gy, w, h, d0 * f, cos(phi), sin(phi));
    }
    return n;
}

static long fc_scales(int gx, int gy, int w, int h, int n_lev, int k, double phi, double cut,
                      double *margin)
{
    return fc_scales_from(gx, gy, w, h, n_lev, k, phi, cut, margin, 0);
}

/* DESIGN.md "Every cell": the grid rows [v_lo, v_lo + n - 1] of the cells
 * a segment from crossing m over a1 crossings passes (its ends' minor
 * coordinates clamped to the grid, at least two rows). */
static void fc_rows(float q, float r, int nq, float m, float a1, int *v_lo, int *n)
{
    const float top = (float)(nq - 1);
    float ca = q + m * r, cb = q + (m + a1) * r;
    ca = ca < 0.0f ? 0.0f : (ca > top ? top : ca);
    cb = cb < 0.0f ? 0.0f : (cb > top ? top : cb);
    int lo = (int)floorf(fminf(ca, cb)), hi = (int)ceilf(fmaxf(ca, cb));
    lo = lo > nq - 2 ? nq - 2 : lo;
    hi = hi < lo + 1 ? lo + 1 : hi;
    *v_lo = lo;
    *n = hi - lo + 1;
}

/* A segment's reads: the rows of its two columns (crossings m and m + 1),
 * less those of the column the segment before kept (*ku, rows *kv ..
 * *kv + *kn - 1), which then becomes the far one; a1 = 0 (the last
 * crossing alone): its own column's rows, which it then keeps. */
static long fc_segment(float q, float r, int nq, long m, float a1, long *ku, int *kv, int *kn)
{
    int v0, n;
    fc_rows(q, r, nq, (float)m, a1, &v0, &n);
    long reads = a1 > 0.0f ? n : 0; /* the far column */
    for (int k = 0; k < n; ++k)
        reads += !(m == *ku && v0 + k >= *kv && v0 + k < *kv + *kn);
    *ku = a1 > 0.0f ? m + 1 : m, *kv = v0, *kn = n;
    return reads;
}

/* DESIGN.md "Horizons", gap search, and "Every cell" (the key lights'
 * search), on a flat field: the crossings m of the direction's major axis
 * from the first at distance >= t_first to the last on the grid (the minor
 * coordinate within 1e-3 of it): the stretch from t_first to its first
 * crossing bounded (one fetch) where t_first lies past crossing 1 and off
 * the crossings, the first crossing evaluated with the
 * cells on to the next (a segment: both columns' rows; the last crossing
 * alone: its column's, mostly kept), then runs of 2, 4, 8 ... crossings (clipped at the
 * last), one bound fetch each, then the cells past the last crossing to
 * where the ray leaves the grid (a segment). */
static long fc_gap(int gx, int gy, int w, int h, double phi, double t_first)
{
    double c = cos(phi), s = sin(phi);
    c = fabs(c) < 1e-12 ? 0.0 : c;
    s = fabs(s) < 1e-12 ? 0.0 : s;
    const int xm = fabs(c) >= fabs(s);
    const double ma = fabs(xm ? c : s), r = (xm ? s : c) / ma;
    const int p = xm ? gx : gy, q = xm ? gy : gx, nq = xm ? h : w;
    const long side = (xm ? c : s) >= 0.0 ? (xm ? w : h) - 1 - p : p;
    long last = side;
    const double lim = r > 0.0 ? (nq - 1 - q + 1e-3) / r : r < 0.0 ? (q + 1e-3) / -r : 1e9;
    if (lim < last)
        last = (long)floor(lim);
    long m = (long)ceil(t_first * ma - 1e-4), n = 0, ku = -1;
    m = m < 1 ? 1 : m;
    const long m_first = m;
    /* the cells' rows as the shaders find them, in single precision: a
     * segment's end within a float's rounding of a grid line is on it */
    const float fr = (float)((float)(xm ? s : c) / (float)ma);
    float u_end = (float)side;
    if (fr != 0.0f)
        u_end = fminf(u_end, fr > 0.0f ? (float)(nq - 1 - q) / fr : (float)q / -fr);
    /* the stretch from t_first to its first crossing: one bound fetch,
     * which on a flat field cannot beat the start */
    const float u0 = (float)t_first * (float)ma;
    n += m_first >= 2 && (float)m_first - u0 > 1e-4f && u_end > u0;
    int l = 0, kv = 0, kn = 0;
    while (m <= last) {
        if (l == 0) {
            n += fc_segment((float)q, fr, nq, m, m < last ? 1.0f : 0.0f, &ku, &kv, &kn);
            ++m, l = 1;
        } else {
            n += 1;
            m = (m + (1L << l) - 1 < last ? m + (1L << l) - 1 : last) + 1;
            ++l;
        }
    }
    if (last >= m_first && u_end - (float)last > 0.0f)
        n += fc_segment((float)q, fr, nq, last, fminf(u_end - (float)last, 1.0f), &ku, &kv, &kn);
    return n;
}

/* DESIGN.md "Azimuth swaths": the key light's sample azimuths. */
static int fc_key_swath(const hfs_key_light *kl, int nphi_key, int nphi_env, double *phi,
                        int *full)
{
    const double h_ratio = sin(kl->alpha) / cos(kl->elev);
    *full = fabs(kl->elev) + kl->alpha >= PI / 2 || !(h_ratio < 1.0);
    if (*full) {
        const int n = nphi_key > nphi_env ? nphi_key : nphi_env;
        for (int j = 0; j < n; ++j)
            phi[j] = 2.0 * PI * j / n;
        return n;
    }
    const double h = asin(h_ratio);
    /* the largest round count (1..4, then 4..7 times a power of two) whose
     * spacing 2 pi / N is not finer than 2h / nphi_key */
    int lat = 1;
    for (int base = 1; base <= 1 << 20; base *= 2)
        for (int m = base == 1 ? 1 : 4; m <= 7; ++m)
            if (m * base >= lat && 2.0 * PI / (m * base) >= 2.0 * h / nphi_key)
                lat = m * base;
    const double d = 2.0 * PI / lat;
    const double p = fmod(fmod(kl->phi, 2.0 * PI) + 2.0 * PI, 2.0 * PI);
    /* the run of lattice samples whose wedges (+- d/2) cover p +- h */
    const double k0 = floor((p - h) / d + 0.5), k1 = ceil((p + h) / d - 0.5);
    int n = 0;
    for (double kk = k0; kk <= k1; kk += 1.0)
        phi[n++] = kk * d;
    return n;
}

/* DESIGN.md "Key lights on the 2x2 grid", "Sharp edges on the grid": on a
 * sub-sampled grid a partial swath's finest scales within 0.5 / sin(half
 * its extent) texels (at least one), and one octave more per doubling of
 * the step (at most all but the coarsest), are the factor pass's, a full
 * swath's finest; none at subsample 1. */
static int fc_key_near(int sub, int n_lev, int k, int full, int ns, const double *phi)
{
    if (sub == 1 || n_lev < 2)
        return 0;
    if (full)
        return 1;
    const double span = 0.5 * (phi[ns - 1] - phi[0]);
    int near = 1;
    while (near < n_lev - 1 && sin(span) * exp2((double)near / k) <= 0.5 * (1.0 + 1e-12))
        ++near;
    near += sub == 4 ? 2 * k : k;
    return near < n_lev - 1 ? near : n_lev - 1;
}

typedef struct fc_counts {
    double env, key, local, margin;
} fc_counts;

static fc_counts fc_expect(int w, int h, const hfs_quality *q, const hfs_lighting *l, double z0)
{
    fc_counts e = {0.0, 0.0, 0.0, 1e300};
    const int n = w > h ? w : h, k = q->k, sub = q->subsample;
    const int n_lev = fc_levels(n, k);
    const int lmin = k * q->offset < n_lev - 1 ? k * q->offset : n_lev - 1;
    const int nl = n_lev - lmin;
    const int tables = q->visibility == HFS_VIS_WEDGE_TABLE;
    const int vw = (w - 1 + sub - 1) / sub + 1, vh = (h - 1 + sub - 1) / sub + 1;
    static double phi[4096];
    for (int b = 0; b < vh; ++b)
        for (int a = 0; a < vw; ++a) {
            const int gx = a * sub < w - 1 ? a * sub : w - 1;
            const int gy = b * sub < h - 1 ? b * sub : h - 1;
            if (l->has_env) {
                e.env += 4 + nl + (tables ? 4 * q->nphi_env : 0);
                for (int j = 0; j < q->nphi_env; ++j) {
                    const double phi_j = 2.0 * PI * j / q->nphi_env;
                    e.env += fc_scales(gx, gy, w, h, n_lev, k, phi_j, 1e300, NULL) +
                             fc_refined(gx, gy, w, h, 1.0, q->refine, k, phi_j);
                }
            }
            for (int kq = 0; kq < l->n_key; ++kq) {
                int full;
                const int ns = fc_key_swath(&l->key[kq], q->nphi_key, q->nphi_env, phi, &full);
                /* on a sub-sampled grid a swath with a centre is searched
                 * whole by the factor pass's texels: no grid draw
                 * (key_setup.h hfs_key_near_make) */
                if (sub > 1 && n_lev >= 2 && !full)
                    continue;
                /* four directions a draw; on a sub-sampled grid the
                 * finest scales are the factor pass's */
                e.key += (double)((ns + 3) / 4) * (4 + nl);
                const int near = fc_key_near(sub, n_lev, k, full, ns, phi);
                const int top = n_lev - 1 - near;
                for (int j = 0; j < ns; ++j) {
                    e.key += fc_scales_from(gx, gy, w, h, n_lev, k, phi[j], 1e300, NULL, near);
                    if (top >= 0)
                        e.key += fc_refined(gx, gy, w, h, exp2((double)(n_lev - 1 - top) / k),
                                            q->refine, k, phi[j]);
                    if (q->refine > 0) /* from where the grid's scales start */
                        e.key += fc_gap(gx, gy, w, h, phi[j], exp2((double)near / k));
                }
            }
            if (l->n_local > 0)
                e.local += (double)((l->n_local + 7) / 8) * (4 + nl);
            for (int li = 0; li < l->n_local; ++li) {
                const hfs_local_light *ll = &l->local[li];
                const double v[3] = {ll->pos[0] - gx, ll->pos[1] - gy,
                                     ll->pos[2] - (z0 + 1e-4)};
                const double rho2 = v[0] * v[0] + v[1] * v[1];
                if (rho2 - ll->radius * ll->radius + v[2] * v[2] <= 0.0)
                    continue; /* inside the sphere: no horizons */
                if (ll->radius >= sqrt(rho2))
                    e.margin = -1.0; /* surrounded: exact windows, not counted here */
                const double dist = sqrt(rho2 + v[2] * v[2]);
                e.local += tables ? 8.0 * q->nphi_local : 0.0;
                for (int j = 0; j < q->nphi_local; ++j)
                    e.local += fc_scales(gx, gy, w, h, n_lev, k, 2.0 * PI * j / q->nphi_local,
                                         dist, &e.margin);
            }
        }
    return e;
}

static double pass_fetches(const hfs_timings *t, const char *name)
{
    for (int p = 0; p < t->n_passes; ++p)
        if (!strcmp(t->pass[p].name, name))
            return t->pass[p].fetches;
    return -2.0;
}

/* Timing level 2 on flat fields against fc_expect, exactly: sizes (square,
 * non-square with a clamped last receiver), subsample 1, 2, 4, both
 * visibility paths, the default quality and one away from it; lights: the
 * sky, the test's key light (partial swath), a key light over the zenith
 * (full swath), two local lights on the full swath (dx = zscale = 1: texel
 * units are world units; no receiver surrounded by or inside a sphere). */
static void flat_fetch_counts(hfs_renderer *r)
{
    static const int sizes[][2] = {{64, 64}, {45, 30}};
    for (int si = 0; si < 2; ++si)
        for (int qi = 0; qi < 2; ++qi)
            for (int p = 0; p < 2; ++p)
                for (int sub = 1; sub <= 4; sub *= 2) {
                    if (qi == 1 && (si == 0 || sub == 2))
                        continue; /* the other quality: on the non-square field */
                    const int w = sizes[si][0], h = sizes[si][1];
                    scene s;
                    memset(&s, 0, sizeof s);
                    s.z = calloc((size_t)w * h, sizeof *s.z);
                    if (!s.z)
                        return;
                    for (size_t i = 0; i < (size_t)w * h; ++i)
                        s.z[i] = 3.25f;
                    s.f = (hfs_field){.width = w, .height = h, .z = s.z, .dx = 1.0, .zscale = 1.0};
                    hfs_lighting l = scene_lighting(1, 1);
                    l.n_key = 2;
                    l.key[1] = l.key[0];
                    l.key[1].elev = 80.0 * PI / 180.0;
                    l.key[1].alpha = 12.0 * PI / 180.0; /* covers the zenith */
                    /* Both reach below the plane's top: a light the
                     * terrain cannot shadow ("open", lights.h) gets no
                     * ratios and no pass. */
                    static const double loc[2][4] = {{20.5, 13.5, 3.25 + 0.3, 0.5},
                                                     {-5.3, 17.2, 3.25 + 0.6, 1.0}};
                    l.n_local = 2;
                    for (int i = 0; i < 2; ++i) {
                        for (int c = 0; c < 3; ++c) {
                            l.local[i].pos[c] = loc[i][c];
                            l.local[i].radiance[c] = 20.0f;
                        }
                        l.local[i].radius = loc[i][3];
                    }
                    hfs_quality q = quality("fp16", p ? "tables" : "legendre", sub);
                    q.local_full_swath = 1;
                    if (qi == 1) {
                        q.k = 3;
                        q.offset = 1;
                        q.nphi_env = 24;
                        q.nphi_key = 5;
                        q.nphi_local = 12;
                    }
                    hfs_image img = {0};
                    hfs_timings t;
                    hfs_renderer_set_timing(r, 2);
                    if (!render(r, &s, &l, &q, &img) && !hfs_renderer_timings(r, &t)) {
                        const fc_counts e = fc_expect(w, h, &q, &l, 3.25);
                        const double env = pass_fetches(&t, "env"), key = pass_fetches(&t, "key"),
                                     local = pass_fetches(&t, "local");
                        printf("flat %dx%d k%d o%d nphi %d/%d/%d %s sub %d: fetches env %.0f "
                               "(count %.0f) key %.0f (%.0f) local %.0f (%.0f); closest cut "
                               "%.2e\n", w, h, q.k, q.offset, q.nphi_env, q.nphi_key,
                               q.nphi_local, p ? "tables" : "legendre", sub, env, e.env, key,
                               e.key, local, e.local, e.margin);
                        /* the local cut compares d_i with the distance in
                         * float: the scene keeps them well apart (and no
                         * receiver is surrounded by a light, margin -1) */
                        CHECK(e.margin > 1e-4, "a local cut within %.1e of a scale", e.margin);
                        CHECK(env == e.env, "flat %dx%d sub %d %s: env fetches %.0f, count %.0f",
                              w, h, sub, p ? "tables" : "legendre", env, e.env);
                        CHECK(key == e.key, "flat %dx%d sub %d %s: key fetches %.0f, count %.0f",
                              w, h, sub, p ? "tables" : "legendre", key, e.key);
                        CHECK(local == e.local, "flat %dx%d sub %d %s: local fetches %.0f, count "
                              "%.0f", w, h, sub, p ? "tables" : "legendre", local, e.local);
                    }
                    hfs_renderer_set_timing(r, 0);
                    hfs_image_free(&img);
                    free(s.z);
                }
}

int main(void)
{
    setvbuf(stdout, NULL, _IONBF, 0);
    return mode_timing();
}
