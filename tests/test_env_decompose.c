/*
 * test_env_decompose.c — the environment map decomposition (issue 17,
 * runtime/envmap/env_decompose.h) on synthetic skies with known disks
 * (tools/sky_gen.h): directions, radii and energies recovered; energy of
 * lights + residual equal to the map's integral; the 0/360 seam and the
 * poles; black, constant, gradient-only and 1x1 maps (no lights); NaN, Inf
 * and negative texels (one-line errors, map untouched); determinism across
 * thread counts; the tracker's identities on a moving sun, the frame at
 * which a faded one is dropped; 400 maps of odd sizes (1..97 x 1..61) and
 * hostile content (hot texels of 1e30 on zeros, 1e-30 noise): finite
 * lights within the budget and energy kept.
 * Every bound is the value measured when the test was written plus the
 * margin stated beside it.
 */
#include "check.h"
#include "env_decompose.h"
#include "sky_gen.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)

static int verbose;

static float *sky(const hfs_sky_desc *d, double (*energy)[3])
{
    float *m = malloc((size_t)d->width * d->height * 3 * sizeof *m);
    if (!m || hfs_sky_render(d, m, energy)) {
        fprintf(stderr, "sky: out of memory\n");
        exit(1);
    }
    return m;
}

/* Independent integral of a map (per channel, double, row by row). */
static void integral(const float *m, int w, int h, double out[3])
{
    out[0] = out[1] = out[2] = 0.0;
    for (int j = 0; j < h; ++j) {
        const double dom = 2.0 * PI / w * (sin(0.5 * PI - PI * j / h) -
                                           sin(0.5 * PI - PI * (j + 1.0) / h));
        for (int i = 0; i < w; ++i)
            for (int c = 0; c < 3; ++c)
                out[c] += m[((size_t)j * w + i) * 3 + c] * dom;
    }
}

static double angle_deg(double p1, double e1, double p2, double e2)
{
    const double c = cos(e1) * cos(e2) * cos(p1 - p2) + sin(e1) * sin(e2);
    return acos(fmax(-1.0, fmin(1.0, c))) / DEG;
}

/* Lights + residual against the map's integral, relative, worst channel. */
static double energy_gap(const hfs_env_decomp *d, const double map[3])
{
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) {
        double s = d->residual_energy[c];
        for (int k = 0; k < d->n_lights; ++k)
            s += d->light[k].energy[c];
        if (map[c] > 0.0)
            worst = fmax(worst, fabs(s - map[c]) / map[c]);
    }
    return worst;
}

static int decompose(float *m, int w, int h, const hfs_env_decompose_opts *o,
                     hfs_env_decomp *d)
{
    hfs_error err = {{0}};
    const int rc = hfs_env_decompose(m, w, h, o, "test", d, &err);
    if (rc)
        fprintf(stderr, "decompose: %s\n", err.msg);
    if (verbose)
        for (int k = 0; k < d->n_lights; ++k)
            fprintf(stderr, "  light %d: phi %.4f elev %.4f alpha %.4f deg, E %.6g %.6g %.6g, "
                    "share %.4f\n", k, d->light[k].phi / DEG, d->light[k].elev / DEG,
                    d->light[k].alpha / DEG, d->light[k].energy[0], d->light[k].energy[1],
                    d->light[k].energy[2], d->light[k].share);
    return rc;
}

/* A disk of sky desc k found among d's lights: its index or -1. */
static int find(const hfs_env_decomp *d, const hfs_sky_disk *k)
{
    int best = -1;
    double ba = 1e9;
    for (int i = 0; i < d->n_lights; ++i) {
        const double a = angle_deg(d->light[i].phi, d->light[i].elev, k->phi * DEG, k->elev * DEG);
        if (a < ba)
            ba = a, best = i;
    }
    return ba < 2.0 * k->radius + 1.0 ? best : -1;
}

/* Disks on a gradient sky: each recovered within the given bounds. */
static void check_disks(const char *what, hfs_sky_desc *s, int expect_lights, double dir_frac,
                        double rad_rel, double en_rel)
{
    double e[HFS_SKY_MAX_DISKS][3], map[3];
    float *m = sky(s, e);
    integral(m, s->width, s->height, map);
    hfs_env_decomp d;
    if (verbose)
        fprintf(stderr, "%s:\n", what);
    CHECK(!decompose(m, s->width, s->height, NULL, &d), "%s: decomposes", what);
    CHECK(d.n_lights == expect_lights, "%s: %d lights, expected %d", what, d.n_lights,
          expect_lights);
    for (int k = 0; k < s->n_disks; ++k) {
        const hfs_sky_disk *dk = &s->disk[k];
        const int i = find(&d, dk);
        CHECK(i >= 0, "%s: disk %d (%g, %g) not found", what, k, dk->phi, dk->elev);
        if (i < 0)
            continue;
        const hfs_env_light *l = &d.light[i];
        const double a = angle_deg(l->phi, l->elev, dk->phi * DEG, dk->elev * DEG);
        CHECK(a <= dir_frac * dk->radius, "%s: disk %d direction off by %.4f deg (bound %.4f)",
              what, k, a, dir_frac * dk->radius);
        const double rr = fabs(l->alpha / DEG - dk->radius) / dk->radius;
        CHECK(rr <= rad_rel, "%s: disk %d radius %.4f deg, true %.4f (rel %.4f > %.4f)", what, k,
              l->alpha / DEG, dk->radius, rr, rad_rel);
        for (int c = 0; c < 3; ++c) {
            const double er = fabs(l->energy[c] - e[k][c]) / e[k][c];
            if (verbose)
                fprintf(stderr, "  disk %d channel %d: energy rel error %.5f, radius %.4f, "
                        "direction %.4f radii\n", k, c, er, rr, a / dk->radius);
            CHECK(er <= en_rel, "%s: disk %d energy[%d] %.6g, true %.6g (rel %.4f > %.4f)", what,
                  k, c, l->energy[c], e[k][c], er, en_rel);
        }
    }
    /* Float precision: the map's texels are floats summed in double. */
    const double gap = energy_gap(&d, map);
    CHECK(gap < 1e-6, "%s: lights + residual differ from the map's integral by %.3g", what, gap);
    if (verbose)
        fprintf(stderr, "  energy gap %.3g\n", gap);
    free(m);
}

static void test_recovery(void)
{
    hfs_sky_desc s;
    hfs_sky_defaults(&s, 512, 256);
    s.n_disks = 2;
    s.disk[0] = (hfs_sky_disk){60, 30, 4, {60, 50, 40}};
    s.disk[1] = (hfs_sky_disk){200, 10, 8, {12, 12, 14}};
    /* Measured over all the cases below (-v): directions within 0.006
     * radius, radii within 2.4%, energies within 0.9%; bounds 0.1 radius,
     * 5%, 3%.  Lights + residual = the map within 1e-8 (bound 1e-6). */
    check_disks("two disks", &s, 2, 0.1, 0.05, 0.03);

    hfs_sky_defaults(&s, 512, 256);
    s.n_disks = 1;
    s.disk[0] = (hfs_sky_disk){359.5, 20, 3, {80, 80, 80}};
    check_disks("seam", &s, 1, 0.1, 0.05, 0.03);
    s.disk[0] = (hfs_sky_disk){0.5, -25, 3, {80, 80, 80}};
    check_disks("seam, other side", &s, 1, 0.1, 0.05, 0.03);
    s.disk[0] = (hfs_sky_disk){123, 87, 4, {80, 80, 80}};
    check_disks("near the zenith", &s, 1, 0.1, 0.05, 0.03);
    s.disk[0] = (hfs_sky_disk){10, 90, 4, {80, 80, 80}};
    check_disks("at the zenith", &s, 1, 0.1, 0.05, 0.03);
    s.disk[0] = (hfs_sky_disk){250, -90, 5, {80, 80, 80}};
    check_disks("at the nadir", &s, 1, 0.1, 0.05, 0.03);
}

/* Maps without a dominant light: no lights, the residual is the map. */
static void check_no_lights(const char *what, float *m, int w, int h)
{
    double map[3];
    integral(m, w, h, map);
    float *copy = malloc((size_t)w * h * 3 * sizeof *copy);
    memcpy(copy, m, (size_t)w * h * 3 * sizeof *copy);
    hfs_env_decomp d;
    CHECK(!decompose(m, w, h, NULL, &d), "%s: decomposes", what);
    CHECK(d.n_lights == 0, "%s: %d lights, expected none", what, d.n_lights);
    CHECK(!memcmp(copy, m, (size_t)w * h * 3 * sizeof *copy), "%s: map changed", what);
    for (int c = 0; c < 3; ++c)
        CHECK(fabs(d.residual_energy[c] - map[c]) <= 1e-6 * fabs(map[c]) + 1e-12,
              "%s: residual energy %.9g, map %.9g", what, d.residual_energy[c], map[c]);
    free(copy);
}

static void test_no_lights(void)
{
    const int w = 256, h = 128;
    float *m = calloc((size_t)w * h * 3, sizeof *m);
    check_no_lights("black", m, w, h);
    for (size_t k = 0; k < (size_t)w * h * 3; ++k)
        m[k] = 2.5f;
    check_no_lights("constant", m, w, h);
    free(m);
    hfs_sky_desc s;
    hfs_sky_defaults(&s, w, h);
    m = sky(&s, NULL);
    check_no_lights("gradient sky", m, w, h);
    free(m);
    s.noise = 0.3; /* 30% texel noise: no light either */
    m = sky(&s, NULL);
    check_no_lights("noisy gradient sky", m, w, h);
    free(m);
    float one[3] = {1.0f, 2.0f, 3.0f};
    check_no_lights("1x1", one, 1, 1);
    float two[6] = {0.0f, 0.0f, 0.0f, 100.0f, 100.0f, 100.0f};
    check_no_lights("2x1", two, 2, 1);
}

static void test_bad_texels(void)
{
    static const struct { float v; const char *msg; } cases[] = {
        {NAN, "bad.pfm: texel (5, 3) G is NaN"},
        {INFINITY, "bad.pfm: texel (5, 3) G is infinite"},
        {-0.5f, "bad.pfm: texel (5, 3) G is -0.5, below -0.01 x the map's mean radiance 0.98"},
    };
    const int w = 16, h = 8;
    float m[16 * 8 * 3], copy[16 * 8 * 3];
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        for (int k = 0; k < w * h * 3; ++k)
            m[k] = 1.0f;
        m[(3 * w + 5) * 3 + 1] = cases[c].v;
        if (c < 2) /* a later negative texel: NaN and Inf are named first */
            m[(1 * w + 9) * 3 + 2] = -5.0f;
        memcpy(copy, m, sizeof m);
        hfs_env_decomp d;
        hfs_error err = {{0}};
        const int rc = hfs_env_decompose(m, w, h, NULL, "bad.pfm", &d, &err);
        CHECK(rc == HFS_E_INVALID, "bad texel %zu: rc %d", c, rc);
        CHECK(!strncmp(err.msg, cases[c].msg, strlen(cases[c].msg)), "bad texel %zu: '%s', expected '%s'", c, err.msg,
              cases[c].msg);
        CHECK(!memcmp(m, copy, sizeof m), "bad texel %zu: map changed", c);
        CHECK(d.n_lights == 0, "bad texel %zu: lights", c);
    }
    /* Lossy EXR's small negatives (-0.6% of the mean in data/courtyard.exr)
     * are kept: -0.009 on a map of mean 1 decomposes, and stays. */
    for (int k = 0; k < w * h * 3; ++k)
        m[k] = 1.0f;
    m[(3 * w + 5) * 3 + 1] = -0.009f;
    hfs_env_decomp dn;
    hfs_error en = {{0}};
    CHECK(!hfs_env_decompose(m, w, h, NULL, "neg.pfm", &dn, &en) && dn.n_lights == 0 &&
              m[(3 * w + 5) * 3 + 1] == -0.009f, "small negative: '%s'", en.msg);
    hfs_env_decompose_opts o;
    hfs_env_decompose_defaults(&o);
    o.max_lights = 9;
    hfs_env_decomp d;
    hfs_error err = {{0}};
    CHECK(hfs_env_decompose(m, w, h, &o, "x", &d, &err) == HFS_E_INVALID &&
              !strcmp(err.msg, "x: max lights 9 is out of range [0, 8]"), "max lights: '%s'",
          err.msg);
    CHECK(hfs_env_decompose(m, 0, h, NULL, "x", &d, &err) == HFS_E_INVALID, "0 wide");
}

/* A w x h sky (s) whose one disk holds the share of its energy. */
static float *one_sun(int w, int h, hfs_sky_disk disk, double share, hfs_sky_desc *s)
{
    hfs_sky_defaults(s, w, h);
    s->n_disks = 1;
    s->disk[0] = disk;
    double e[1][3];
    float *m = sky(s, e);
    hfs_sky_set_share(s, 0, share, m, e);
    return m;
}

/* The demo's must-show sky: a 0.5-degree sun holding 80% of the energy. */
static void test_sun(int w, int h, double dir_px, double share_abs)
{
    hfs_sky_desc s;
    float *m = one_sun(w, h, (hfs_sky_disk){135, 35, 0.25, {1, 0.95, 0.9}}, 0.8, &s);
    double map[3];
    integral(m, w, h, map);
    hfs_env_decomp d;
    if (verbose)
        fprintf(stderr, "sun %dx%d:\n", w, h);
    CHECK(!decompose(m, w, h, NULL, &d), "sun %dx%d: decomposes", w, h);
    CHECK(d.n_lights == 1, "sun %dx%d: %d lights", w, h, d.n_lights);
    if (d.n_lights >= 1) {
        const double a = angle_deg(d.light[0].phi, d.light[0].elev, 135 * DEG, 35 * DEG);
        const double px = 180.0 / h;
        CHECK(a <= dir_px * px, "sun %dx%d: off by %.4f deg (bound %.4f)", w, h, a, dir_px * px);
        CHECK(fabs(d.light[0].share - 0.8) <= share_abs, "sun %dx%d: share %.4f", w, h,
              d.light[0].share);
    }
    const double gap = energy_gap(&d, map);
    CHECK(gap < 1e-6, "sun %dx%d: energy gap %.3g", w, h, gap);
    free(m);
}

/* Same map, 1 or 2 threads: the same lights and residual, bit for bit. */
static void test_determinism(void)
{
    hfs_sky_desc s;
    hfs_sky_defaults(&s, 640, 320);
    s.noise = 0.1;
    s.n_disks = 3;
    s.disk[0] = (hfs_sky_disk){10, 40, 1, {400, 390, 380}};
    s.disk[1] = (hfs_sky_disk){300, 5, 6, {20, 15, 10}};
    s.disk[2] = (hfs_sky_disk){180, 60, 2, {60, 60, 70}};
    float *a = sky(&s, NULL), *b = sky(&s, NULL);
    hfs_env_decompose_opts o;
    hfs_env_decompose_defaults(&o);
    hfs_env_decomp da, db;
    o.threads = 1;
    CHECK(!decompose(a, 640, 320, &o, &da), "determinism: 1 thread");
    o.threads = 2;
    CHECK(!decompose(b, 640, 320, &o, &db), "determinism: 2 threads");
    CHECK(!memcmp(&da, &db, sizeof da), "determinism: lights or SH differ");
    CHECK(!memcmp(a, b, sizeof(float) * 640 * 320 * 3), "determinism: residuals differ");
    CHECK(da.n_lights == 3, "determinism: %d lights of 3", da.n_lights);
    free(a);
    free(b);
}

/* Frames skipped by a slow consumer: the sun 12 degrees on from where the
 * tracker saw it, past its search window.  It keeps its identity (without
 * env_track.c's reacquire it vanished and came back as a new light, after
 * the appear hysteresis). */
static void test_tracking_skip(void)
{
    const int w = 256, h = 128;
    hfs_env_tracker t;
    hfs_env_tracker_init(&t, NULL);
    int id = -1;
    for (int f = 0; f < 6; ++f) {
        hfs_sky_desc s;
        hfs_sky_defaults(&s, w, h);
        s.seed = (unsigned)f + 1;
        s.n_disks = 1;
        const double az = 100.0 + (f < 5 ? 0.25 * f : 12.0);
        s.disk[0] = (hfs_sky_disk){az, 30, 0.25, {1, 0.95f, 0.9f}};
        double e[2][3];
        float *m = sky(&s, e);
        hfs_sky_set_share(&s, 0, 0.6, m, e);
        hfs_env_decomp d;
        hfs_error err = {{0}};
        CHECK(!hfs_env_track(&t, m, w, h, "frame", &d, &err), "skip %d: %s", f, err.msg);
        const int k = find(&d, &s.disk[0]);
        CHECK(k >= 0, "skip %d: the sun at %.1f deg not found", f, az);
        if (k >= 0 && id < 0)
            id = d.light[k].id;
        if (k >= 0)
            CHECK(d.light[k].id == id, "skip %d: sun id %d, was %d", f, d.light[k].id, id);
        free(m);
    }
}

/* The vanish rule (env_decompose.h): a tracked light below vanish_share
 * for vanish_frames frames in a row is dropped.  A sun tracked from frame
 * 0 falls to a tenth of vanish_share at frame 3: it is still reported (its
 * identity kept, found where it was) in frames 3, 4, 5, the third weak one
 * its last, and not from frame 6 (too weak to come back as a new light).
 * Exact frames: one frame late or early fails. */
static void test_tracking_vanish(void)
{
    const int w = 128, h = 64, weak_from = 3;
    hfs_env_tracker t;
    hfs_env_tracker_init(&t, NULL);
    const int last = weak_from + t.vanish_frames - 1;
    int id = -1;
    for (int f = 0; f <= last + 2; ++f) {
        hfs_sky_desc s;
        float *m = one_sun(w, h, (hfs_sky_disk){100, 30, 1.5, {1, 1, 1}},
                           f < weak_from ? 0.6 : 0.1 * t.vanish_share, &s);
        hfs_env_decomp d;
        hfs_error err = {{0}};
        CHECK(!hfs_env_track(&t, m, w, h, "frame", &d, &err), "vanish %d: %s", f, err.msg);
        const int k = find(&d, &s.disk[0]);
        if (f == 0 && k >= 0)
            id = d.light[k].id;
        CHECK((k >= 0) == (f <= last), "vanish: frame %d: the sun %s (weak from frame %d, "
              "reported up to frame %d)", f, k >= 0 ? "reported" : "not reported", weak_from,
              last);
        CHECK(k < 0 || d.light[k].id == id, "vanish: frame %d: id %d, was %d", f,
              k >= 0 ? d.light[k].id : 0, id);
        CHECK(f <= last || t.n == 0, "vanish: frame %d: %d lights still tracked", f, t.n);
        free(m);
    }
}

/* A 256x128 probe: the sun moving 0.25 deg a frame on a noisy sky beside a
 * window whose share wanders about the threshold (as bench_env track). */
static void test_tracking(void)
{
    const int w = 256, h = 128, frames = 40;
    hfs_env_tracker t;
    hfs_env_tracker_init(&t, NULL);
    int sun_id = -1, counts[2] = {99, 0};
    double max_jump = 0.0, last[2] = {0, 0};
    for (int f = 0; f < frames; ++f) {
        hfs_sky_desc s;
        hfs_sky_defaults(&s, w, h);
        s.noise = 0.05;
        s.seed = (unsigned)f + 1;
        s.n_disks = 2;
        s.disk[0] = (hfs_sky_disk){100 + 0.25 * f, 30 + 0.1 * f, 0.25, {1, 0.95f, 0.9f}};
        s.disk[1] = (hfs_sky_disk){300, 15, 4, {1, 1, 1}};
        double e[2][3], map[3];
        float *m = sky(&s, e);
        hfs_sky_set_share(&s, 0, 0.6, m, e);
        hfs_sky_set_share(&s, 1, 0.025 * (1.0 + 0.25 * sin(f * 0.7)), m, e);
        integral(m, w, h, map);
        hfs_env_decomp d;
        hfs_error err = {{0}};
        CHECK(!hfs_env_track(&t, m, w, h, "frame", &d, &err), "track %d: %s", f, err.msg);
        const int k = find(&d, &s.disk[0]);
        CHECK(k >= 0, "track %d: no sun", f);
        if (k >= 0) {
            if (sun_id < 0)
                sun_id = d.light[k].id;
            CHECK(d.light[k].id == sun_id, "track %d: sun id %d, was %d", f, d.light[k].id, sun_id);
            if (f > 0)
                max_jump = fmax(max_jump, angle_deg(d.light[k].phi, d.light[k].elev, last[0],
                                                    last[1]));
            last[0] = d.light[k].phi;
            last[1] = d.light[k].elev;
        }
        counts[0] = d.n_lights < counts[0] ? d.n_lights : counts[0];
        counts[1] = d.n_lights > counts[1] ? d.n_lights : counts[1];
        const double gap = energy_gap(&d, map);
        CHECK(gap < 1e-6, "track %d: energy gap %.3g", f, gap);
        free(m);
    }
    /* Measured: 2 lights in every frame (untracked: 1 or 2, bench_env
     * track), sun jumps up to 0.45 deg a frame (untracked 0.88: texel
     * centre to texel centre).  Bound 0.6 deg. */
    CHECK(counts[0] == counts[1], "tracking: light count varies %d..%d", counts[0], counts[1]);
    CHECK(max_jump < 0.6, "tracking: sun jumps %.3f deg", max_jump);
    if (verbose)
        fprintf(stderr, "tracking: %d..%d lights, max jump %.3f deg\n", counts[0], counts[1],
                max_jump);
}

/* Odd sizes and hostile content (a few huge texels on zeros, tiny values,
 * thin rows and columns): finite lights within the budget, energy kept. */
static void test_odd_maps(void)
{
    unsigned x = 12345u;
    int bad = 0;
    for (int t = 0; t < 400; ++t) {
        x = x * 1664525u + 1013904223u;
        const int w = 1 + (int)(x >> 8) % 97, h = 1 + (int)(x >> 20) % 61;
        float *m = calloc((size_t)w * h * 3, sizeof *m);
        const int kind = t % 4;
        for (int k = 0; k < w * h * 3; ++k) {
            x = x * 1664525u + 1013904223u;
            const double u = (x >> 8) / 16777216.0;
            m[k] = kind == 0 ? (float)u : kind == 1 ? (u > 0.995 ? 1e30f : 0.0f)
                   : kind == 2 ? (float)(u * 1e-30) : (float)(u * u * u * u * 1e4);
        }
        double map[3];
        integral(m, w, h, map);
        hfs_env_decomp d;
        hfs_error err = {{0}};
        if (hfs_env_decompose(m, w, h, NULL, "odd", &d, &err)) {
            CHECK(0, "odd %dx%d kind %d: %s", w, h, kind, err.msg);
            free(m);
            continue;
        }
        int ok = d.n_lights >= 0 && d.n_lights <= 4;
        for (int k = 0; k < d.n_lights; ++k)
            for (int c = 0; c < 3; ++c)
                ok = ok && isfinite(d.light[k].radiance[c]) && d.light[k].radiance[c] >= 0.0f &&
                     d.light[k].alpha > 0.0 && d.light[k].alpha <= 89.0 * DEG + 1e-12;
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < HFS_SH_COEFFS; ++k)
                ok = ok && isfinite(d.residual_sh[c][k]);
        const double gap = energy_gap(&d, map);
        ok = ok && gap < 1e-6;
        if (!ok && bad++ < 5)
            fprintf(stderr, "odd %dx%d kind %d: %d lights, gap %.3g\n", w, h, kind, d.n_lights,
                    gap);
        free(m);
    }
    CHECK(bad == 0, "odd maps: %d of 400 bad", bad);
}

int main(int argc, char **argv)
{
    verbose = argc > 1 && !strcmp(argv[1], "-v");
    test_recovery();
    test_no_lights();
    test_bad_texels();
    /* Measured (-v): 2048x1024 off by 0.007 texel, 256x128 by 0.39 texel
     * (the sun is sub-texel there: its texel's centre is all the map
     * knows); shares 0.8000 both.  Bounds: 0.05 and 0.5 texel, 0.02. */
    test_sun(2048, 1024, 0.05, 0.02);
    test_sun(256, 128, 0.5, 0.02);
    test_determinism();
    test_tracking();
    test_tracking_skip();
    test_tracking_vanish();
    test_odd_maps();
    printf("test_env_decompose: %ld checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
