/*
 * test_env_shade.c — an environment map shaded from the map itself
 * (env-shade = map: hfs_lighting env_open, env_shade_map; runtime/
 * env_open.h, env_map_slices.h; DESIGN.md "Shading from the map itself"),
 * against the truth of the map (every bound below is the measurement on
 * Mesa 22.3.6 llvmpipe / x86-64 plus the margin stated beside it):
 *   constant  a constant map's open-sky table is ~0 (its SH holds it)
 *   flat      a flat field: the CPU equals the map's truth (the zenith is
 *             a node of the table; nothing is occluded)
 *   tilted    a plane at 35 degrees, open: only the table's bilinear
 *             lookup between nodes is left
 *   accuracy  the fractal under a map with sharp structure near the
 *             horizon: the map-shaded CPU at most half the error of the
 *             SH-shaded one against the map's truth (issue 17's measure)
 *   rotate    a sky turned by 90 degrees equals the map rolled by a
 *             quarter of its columns (wedges and table nodes map onto
 *             themselves)
 *   invalid   env_shade_map without env_open: HFS_E_INVALID, one line
 *   gles      (skipped with 77 without a context) GLES against the CPU at
 *             subsample 1 fp16; at the 2x2 default map- against SH-shaded,
 *             both against the map's truth; a turned sky on a kept
 *             renderer reruns the map's occlusion and the shading only, bit
 *             for bit a fresh renderer's frame
 */
#include "gl_test.h"
#include "test_gles_scenes.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "env_map_test.h"
#include "env_open.h"
#include "sh.h"

#define N 48
#define MW 256
#define MH 128
#define PI 3.14159265358979323846

/* A sky with structure order 4 cannot hold: a gradient, a bright opening
 * low in the east, a lit wall in the west-south-west, a dark band. */
static float *make_map(void)
{
    float *m = malloc((size_t)MW * MH * 3 * sizeof *m);
    for (int v = 0; v < MH; ++v)
        for (int u = 0; u < MW; ++u) {
            const double phi = 360.0 * (u + 0.5) / MW, e = 90.0 - 180.0 * (v + 0.5) / MH;
            double l = 0.3 + 0.5 * fmax(0.0, sin(e * PI / 180.0));
            if (phi > 40.0 && phi < 80.0 && e > 0.0 && e < 25.0)
                l += 3.0;
            if (phi > 200.0 && phi < 230.0 && e > 5.0 && e < 40.0)
                l += 1.5;
            if (e > 45.0 && e < 52.0)
                l *= 0.2;
            float *p = m + 3 * ((size_t)v * MW + u);
            p[0] = (float)(l * 1.1), p[1] = (float)l, p[2] = (float)(l * (0.8 + 0.004 * e));
        }
    return m;
}

/* The map's lighting (env_map_test.h); with_map: env-shade = map. */
static void make_lighting(shaded *s, const float *map, double rot, int with_map)
{
    env_map_lighting(&s->l, map, MW, MH, rot, s->open, with_map);
}

#define render env_map_render

/* Mean and max of |a - b| over b's largest value. */
static void errors(const hfs_image *a, const hfs_image *b, double *mean, double *max)
{
    const size_t n = (size_t)a->width * a->height * 3;
    double s = 0.0, m = 0.0, norm = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const double d = fabs((double)a->rgb[i] - b->rgb[i]);
        s += d, m = fmax(m, d), norm = fmax(norm, b->rgb[i]);
    }
    *mean = s / n / norm, *max = m / norm;
}

static void check_constant(void)
{
    float *m = malloc((size_t)MW * MH * 3 * sizeof *m);
    for (int i = 0; i < MW * MH * 3; ++i)
        m[i] = 2.0f;
    shaded s;
    make_lighting(&s, m, 0.0, 1);
    const double d = hfs_env_open_max(s.open);
    /* Measured 8.2e-4 of L: the SH projection's pixel-centre rule over
     * 128 rows (the table corrects it); bound 2x. */
#define CONSTANT_BOUND 1.6e-3
    CHECK(d <= CONSTANT_BOUND * 2.0, "constant map: |D| up to %.2e of L", d / 2.0);
    printf("constant: the open-sky table up to %.2e of L (bound %.1e)\n", d / 2.0, CONSTANT_BOUND);
    free(m);
}

/* A plane z = t x (t = 0: flat). */
static void plane(hfs_field *f, float *z, double t)
{
    for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i)
            z[j * N + i] = (float)(t * i);
    f->width = f->height = N, f->dx = 1.0, f->zscale = 1.0, f->z = z;
}

static void check_planes(const float *map)
{
    static float z[N * N];
    hfs_field f;
    shaded s;
    make_lighting(&s, map, 0.3, 1);
    const hfs_quality q = env_map_quality();
    /* flat: measured 0 (bit for bit); tilted 35 degrees (normals between
     * nodes): 1.5e-5 mean, 1.7e-5 max; bounds 1e-6 and 2x. */
    const double tilt[2] = {0.0, tan(35.0 * PI / 180.0)};
    const double bound_mean[2] = {1e-6, 3e-5}, bound_max[2] = {1e-6, 3.4e-5};
    for (int k = 0; k < 2; ++k) {
        plane(&f, z, tilt[k]);
        hfs_image c = {0}, t = {0};
        int rc = render(HFS_BACKEND_CPU, &f, &s.l, &q, &c) | render(HFS_BACKEND_TRUTH, &f, &s.l, &q, &t);
        double mean, max;
        errors(&c, &t, &mean, &max);
        CHECK(!rc && mean <= bound_mean[k] && max <= bound_max[k],
              "%s: cpu vs the map's truth mean %.2e max %.2e", k ? "tilted" : "flat", mean, max);
        printf("%s: cpu against the map's truth: mean %.2e, max %.2e (bounds %.1e, %.1e)\n",
               k ? "tilted" : "flat", mean, max, bound_mean[k], bound_max[k]);
        hfs_image_free(&c), hfs_image_free(&t);
    }
}

/* The map-shaded CPU against the map's truth (fractal25 48^2), over the
 * truth's largest value: measured by `build/tests/test_env_shade` mean
 * 4.112e-3, p99 2.528e-2 against the exact truth (issue 36, session 16;
 * at 2156b87, against the march truth, which was too bright: 3.883e-3,
 * 2.270e-2); bounds 1.2x. */
#define ACCURACY_MEAN 4.94e-3
#define ACCURACY_P99 3.04e-2

static void check_accuracy(const scene *sc, const float *map, hfs_image *truth)
{
    const hfs_quality q = env_map_quality();
    hfs_image a = {0}, b = {0};
    int rc = env_map_truth_and_cpu(&sc->f, map, 0.3, make_lighting, &q, truth, &a, &b);
    double ma, xa, mb, xb;
    errors(&a, truth, &ma, &xa);
    errors(&b, truth, &mb, &xb);
    /* Measured: map 4.11e-3, SH 1.37e-2 (0.30x). */
    CHECK(!rc && ma <= 0.5 * mb, "accuracy: map-shaded %.2e not half the SH's %.2e", ma, mb);
    printf("accuracy: fractal against the map's truth: map-shaded mean %.2e (max %.2e), SH-shaded "
           "%.2e (max %.2e): %.2fx (bound 0.5x)\n", ma, xa, mb, xb, ma / mb);
    /* Drift (issue 35): the ratio to the SH-shaded error above lets the
     * map-shaded error grow 1.6x; its mean and p99 are bounded at 1.2x
     * their measurement (ACCURACY_*).  Slice wedges twice as wide move
     * them 1.197x and 1.187x (at 2156b87), just inside: test_drift_rules_map_slices
     * checks the wedges themselves. */
    hfs_metrics m = {0};
    hfs_error err = {""};
    CHECK(hfs_compare_images(&a, truth, hfs_image_max(truth), &m, &err) == HFS_OK, "%s", err.msg);
    CHECK(m.mean_abs <= ACCURACY_MEAN && m.p99_abs <= ACCURACY_P99,
          "accuracy: map-shaded mean %.3e (bound %.3e), p99 %.3e (bound %.3e)", m.mean_abs,
          ACCURACY_MEAN, m.p99_abs, ACCURACY_P99);
    printf("accuracy: map-shaded mean %.3e (bound %.3e), p99 %.3e (bound %.3e)\n", m.mean_abs,
           ACCURACY_MEAN, m.p99_abs, ACCURACY_P99);
    hfs_image_free(&a), hfs_image_free(&b);
}

static void check_rotate(const scene *sc, const float *map)
{
    const hfs_quality q = env_map_quality();
    int rc;
    const double max = env_map_turn_error(&sc->f, map, MW, MH, make_lighting, &q, &rc);
    /* Measured 0 (bit for bit); allowed: float rounding of cos, sin
     * (pi/2) and of the two SH projections. */
    CHECK(!rc && max <= 1e-6, "rotate: turned sky vs rolled map max %.2e", max);
    printf("rotate: a sky turned by 90 degrees = the map rolled, max %.2e (bound 1e-6)\n", max);
}

static void check_invalid(const scene *sc, const float *map)
{
    shaded s;
    make_lighting(&s, map, 0.0, 1);
    s.l.env_open = NULL;
    hfs_error err = {""};
    CHECK(hfs_validate_lighting(&s.l, &err) == HFS_E_INVALID && strstr(err.msg, "env-shade-map") &&
          !strchr(err.msg, '\n'), "shade map without its table: '%s'", err.msg);
    (void)sc;
    printf("invalid: %s\n", err.msg);
}

/* GLES against the CPU at subsample 1 (fp16, map-shaded): measured
 * 4.6e-5 mean; bound 2x.  At the 2x2 default against the map's truth the
 * map-shaded error measured 0.55x the SH-shaded one: at 48^2 the fractal's
 * texel-scale relief makes the grid's interpolated horizons weigh more
 * than at 256^2 (0.32x there, BENCHMARKS.md "Shading from the map
 * itself"); bound 0.7x. */
#define GLES_SUB1_BOUND 9.2e-5
#define GLES_2X2_RATIO 0.7
/* fp16 against fp32, map-shaded at 2x2: measured 4.7e-5 mean; bound 2x
 * (issue 15 asks 2e-3). */
#define GLES_FP16_BOUND 9.4e-5

/* A map-shaded frame keeps no transfer targets (the shading reads the
 * map's occlusion instead): the SH-shaded frame after it on the same
 * renderer, its sky unchanged, makes the sky occlusion's (pass_env_sky_
 * occlusion.c: an RGBA and an RG target, at fp16 12 bytes a texel, less the
 * map's occlusion target it no longer needs, 8), and equals a fresh
 * renderer's frame bit for bit. */
static void check_gles_sh_after_map(const scene *sc, const shaded *map, const shaded *sh,
                                const hfs_quality *q)
{
    char ran[256];
    const int same = env_map_kept_is_fresh(&sc->f, &map->l, &sh->l, q, NULL, ran, sizeof ran);
    CHECK(same && strstr(ran, "sky occlusion"), "SH after map: ran '%s', %s", ran,
          same ? "equal" : "not a fresh frame");
    hfs_renderer *r = gl_test_gles();
    hfs_error err = {""};
    hfs_image x = {0};
    hfs_timings t;
    hfs_image_alloc(&x, sc->f.width, sc->f.height, &err);
    hfs_renderer_set_timing(r, 1);
    int rc = hfs_renderer_render(r, &sc->f, &map->l, q, &x, NULL, NULL, &err);
    hfs_renderer_timings(r, &t);
    const double bytes_map = (double)t.texture_bytes;
    rc |= hfs_renderer_render(r, &sc->f, &sh->l, q, &x, NULL, NULL, &err);
    hfs_renderer_timings(r, &t);
    const double grew = (double)t.texture_bytes - bytes_map, texels = (double)N * N;
    CHECK(!rc && grew == 4.0 * texels, "SH after map: textures grew %.0f bytes, want %.0f "
          "(the sky occlusion made on demand, the map's occlusion freed)", grew, 4.0 * texels);
    printf("gles: textures %.0f bytes map-shaded, +%.0f for the SH-shaded frame's sky occlusion\n",
           bytes_map, grew);
    hfs_image_free(&x);
    hfs_renderer_destroy(r);
}

/* A renderer that saw the sky turn keeps the grid's horizons: a second
 * turn runs the map's occlusion alone (and the shading, the read-back). */
static void check_second_turn(const scene *sc, const shaded *s, hfs_quality q)
{
    hfs_renderer *r = gl_test_gles();
    hfs_error err = {""};
    hfs_image x = {0};
    hfs_image_alloc(&x, sc->f.width, sc->f.height, &err);
    hfs_lighting l = s->l;
    int rc = hfs_renderer_render(r, &sc->f, &l, &q, &x, NULL, NULL, &err);
    l.env_rotate = 1.1;
    rc |= hfs_renderer_render(r, &sc->f, &l, &q, &x, NULL, NULL, &err);
    l.env_rotate = 1.7;
    rc |= hfs_renderer_render(r, &sc->f, &l, &q, &x, NULL, NULL, &err);
    char ran[256];
    gl_test_ran(r, ran, sizeof ran);
    CHECK(!rc && !strcmp(ran, "map occlusion shade readback "),
          "second turn: ran '%s', want the map's occlusion, shade and readback", ran);
    printf("gles: a second turn runs '%s'\n", ran);
    hfs_image_free(&x);
    hfs_renderer_destroy(r);
}

static void check_gles(const scene *sc, const float *map, const hfs_image *truth)
{
    shaded s, sh;
    make_lighting(&s, map, 0.3, 1);
    make_lighting(&sh, map, 0.3, 0);
    hfs_quality q = env_map_quality();
    q.subsample = 1;
    hfs_image g = {0}, c = {0};
    int rc = render(HFS_BACKEND_GLES, &sc->f, &s.l, &q, &g) | render(HFS_BACKEND_CPU, &sc->f, &s.l, &q, &c);
    double mean, max, mean_sh;
    errors(&g, &c, &mean, &max);
    CHECK(!rc && mean <= GLES_SUB1_BOUND, "gles sub 1 vs cpu: mean %.2e > %.1e", mean,
          GLES_SUB1_BOUND);
    printf("gles: subsample 1 against the cpu, mean %.2e, max %.2e (bound %.1e)\n", mean, max,
           GLES_SUB1_BOUND);
    hfs_image_free(&g), hfs_image_free(&c);
    q.subsample = 2;
    rc = render(HFS_BACKEND_GLES, &sc->f, &s.l, &q, &g) | render(HFS_BACKEND_GLES, &sc->f, &sh.l, &q, &c);
    errors(&g, truth, &mean, &max);
    errors(&c, truth, &mean_sh, &max);
    CHECK(!rc && mean <= GLES_2X2_RATIO * mean_sh, "gles 2x2: map-shaded %.2e, SH-shaded %.2e",
          mean, mean_sh);
    printf("gles: 2x2 against the map's truth, map-shaded mean %.2e, SH-shaded %.2e: %.2fx "
           "(bound %.1fx)\n", mean, mean_sh, mean / mean_sh, GLES_2X2_RATIO);
    hfs_image_free(&g), hfs_image_free(&c);
    /* fp16 tables and targets against fp32 at the default. */
    q.precision = HFS_PRECISION_FP32;
    rc = render(HFS_BACKEND_GLES, &sc->f, &s.l, &q, &c);
    q.precision = HFS_PRECISION_FP16;
    rc |= render(HFS_BACKEND_GLES, &sc->f, &s.l, &q, &g);
    errors(&g, &c, &mean, &max);
    CHECK(!rc && mean <= GLES_FP16_BOUND, "gles fp16 vs fp32: mean %.2e > %.1e", mean,
          GLES_FP16_BOUND);
    printf("gles: fp16 against fp32 (2x2), mean %.2e, max %.2e (bound %.1e)\n", mean, max,
           GLES_FP16_BOUND);
    hfs_image_free(&g), hfs_image_free(&c);
    /* A turned sky on a kept renderer. */
    shaded turned = s;
    turned.l.env_rotate = 1.1;
    char ran[256];
    const int same = env_map_kept_is_fresh(&sc->f, &s.l, &turned.l, &q, NULL, ran, sizeof ran);
    /* the grid's horizons, freed after the first frame (gles_frame.c
     * grid_release), made anew by the env pass for the map's occlusion */
    CHECK(!strcmp(ran, "env map occlusion shade readback "),
          "turned sky: ran '%s', want the env pass, the map's occlusion, shade and readback",
          ran);
    check_second_turn(sc, &s, q);
    CHECK(same, "turned sky: the planned frame differs from a fresh one");
    printf("gles: a turned sky runs '%s', bit for bit a fresh frame\n", ran);
    check_gles_sh_after_map(sc, &s, &sh, &q);
}

int main(int argc, char **argv)
{
    scene sc;
    if (scene_make("fractal25", N, NULL, &sc))
        return 1;
    float *map = make_map();
    hfs_image truth = {0};
    check_constant();
    check_planes(map);
    check_accuracy(&sc, map, &truth);
    check_rotate(&sc, map);
    check_invalid(&sc, map);
    if (argc > 1 && !strcmp(argv[1], "gles"))
        check_gles(&sc, map, &truth);
    hfs_image_free(&truth);
    free(map);
    scene_free(&sc);
    printf("test_env_shade: %s\n", failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
