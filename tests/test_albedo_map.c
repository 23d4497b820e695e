/*
 * test_albedo_map.c — the per-texel albedo map (hfs_lighting albedo_map,
 * runtime/core/albedo.h) through the renderer API:
 *   cpu      the CPU reference, the truth and the unshadowed normalizer
 *            with a map equal, bit for bit, their output without it times
 *            the map (direct light is linear in the albedo)
 *   invalid  a value above 1, a negative one, a NaN: HFS_E_INVALID naming
 *            the texel, nothing written
 *   gles     (skipped with 77 without a context) GLES with the map against
 *            the CPU's with it (subsample 1, fp16: the fp16 albedo adds
 *            2^-11 of a value at most; bound below); a kept renderer whose
 *            map changes runs only the shading (and read-back), and its
 *            frame equals a fresh renderer's bit for bit; removing the map
 *            gives back the map-less frame bit for bit
 */
#include "gl_test.h"
#include "test_gles_scenes.h"

#include <math.h>
#include <string.h>

#include "check.h"

#define N 40

static float *make_map(int w, int h, unsigned seed)
{
    float *m = malloc((size_t)w * h * 3 * sizeof *m);
    for (int i = 0; i < w * h * 3; ++i) {
        seed = seed * 1664525u + 1013904223u;
        m[i] = (float)(seed >> 8) / 16777215.0f; /* [0, 1] */
    }
    return m;
}

static int render(hfs_renderer *r, const scene *s, const hfs_lighting *l, const hfs_quality *q,
                  hfs_image *out)
{
    hfs_error err = {""};
    const int rc = hfs_renderer_render(r, &s->f, l, q, out, NULL, NULL, &err);
    CHECK(rc == HFS_OK, "render: %s", err.msg);
    return rc;
}

static void check_linear(hfs_backend b, const char *name, const scene *s, const float *map)
{
    hfs_renderer_desc d = {.backend = b};
    hfs_renderer *r = NULL;
    hfs_error err = {""};
    CHECK(hfs_renderer_create(&d, &r, &err) == HFS_OK, "%s: %s", name, err.msg);
    hfs_lighting l = scene_lighting(1, 1);
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.truth_azimuths = 720, q.truth_light_samples = 16;
    hfs_image a, m;
    hfs_image_alloc(&a, N, N, &err);
    hfs_image_alloc(&m, N, N, &err);
    int rc = render(r, s, &l, &q, &a);
    l.albedo_map = map;
    rc |= render(r, s, &l, &q, &m);
    long diff = 0;
    for (int i = 0; i < N * N * 3 && !rc; ++i)
        diff += m.rgb[i] != a.rgb[i] * map[i];
    CHECK(!rc && diff == 0, "%s: %ld values not the map-less output times the map", name, diff);
    /* The normalizer, too. */
    l.albedo_map = NULL;
    CHECK(hfs_render_unshadowed(&s->f, &l, &q, &a, &err) == HFS_OK, "%s", err.msg);
    l.albedo_map = map;
    CHECK(hfs_render_unshadowed(&s->f, &l, &q, &m, &err) == HFS_OK, "%s", err.msg);
    diff = 0;
    for (int i = 0; i < N * N * 3; ++i)
        diff += m.rgb[i] != a.rgb[i] * map[i];
    CHECK(diff == 0, "unshadowed: %ld values not times the map", diff);
    printf("cpu: %s with the map = without it times the map, bit for bit\n", name);
    hfs_image_free(&a);
    hfs_image_free(&m);
    hfs_renderer_destroy(r);
}

static void check_invalid(const scene *s, float *map)
{
    hfs_renderer_desc d = {.backend = HFS_BACKEND_CPU};
    hfs_renderer *r = NULL;
    hfs_error err = {""};
    hfs_renderer_create(&d, &r, &err);
    hfs_lighting l = scene_lighting(1, 0);
    l.albedo_map = map;
    hfs_quality q;
    hfs_quality_defaults(&q);
    hfs_image out;
    hfs_image_alloc(&out, N, N, &err);
    const float bad[3] = {1.25f, -0.5f, NAN};
    const char *want[3] = {"texel (3, 2) B is 1.25", "texel (3, 2) B is -0.5", "is nan"};
    const size_t at = 3 * (2 * N + 3) + 2;
    for (int k = 0; k < 3; ++k) {
        const float keep = map[at];
        map[at] = bad[k];
        memset(out.rgb, 0x7f, sizeof(float) * 3);
        const int rc = hfs_renderer_render(r, &s->f, &l, &q, &out, NULL, NULL, &err);
        CHECK(rc == HFS_E_INVALID && strstr(err.msg, want[k]) && strstr(err.msg, "albedo map"),
              "bad map value %g: rc %d '%s'", bad[k], rc, err.msg);
        CHECK(out.rgb[0] != 0.0f, "an output written on a refused map");
        map[at] = keep;
    }
    printf("invalid: above 1, negative, NaN refused naming the texel\n");
    hfs_image_free(&out);
    hfs_renderer_destroy(r);
}

/* fp16 bound: the fractal's GLES-against-CPU bound at subsample 1
 * without a map (gles.cmake hfs_eq_fractal_fp16_*, 4e-4 mean of the
 * norm); the map's fp16 rounding adds at most 2^-11 of each value.
 * Measured here 6.1e-5 (Mesa 22.3.6 llvmpipe). */
#define GLES_MEAN_BOUND 4e-4

static void check_gles(const scene *s, const float *map, const float *map2)
{
    hfs_renderer *r = gl_test_gles(), *fresh = gl_test_gles(), *cpu = NULL;
    hfs_renderer_desc cd = {.backend = HFS_BACKEND_CPU};
    hfs_error err = {""};
    hfs_renderer_create(&cd, &cpu, &err);
    hfs_lighting l = scene_lighting(1, 1);
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.subsample = 1;
    hfs_image plain, a, b, c;
    hfs_image_alloc(&plain, N, N, &err), hfs_image_alloc(&a, N, N, &err);
    hfs_image_alloc(&b, N, N, &err), hfs_image_alloc(&c, N, N, &err);
    int rc = render(r, s, &l, &q, &plain);
    l.albedo_map = map;
    rc |= render(r, s, &l, &q, &a) | render(cpu, s, &l, &q, &c);
    char ran[256];
    gl_test_ran(r, ran, sizeof ran);
    CHECK(!strcmp(ran, "shade readback "), "map given: ran '%s', want shade and readback", ran);
    double sum = 0.0, norm = 0.0;
    for (int i = 0; i < N * N * 3; ++i) {
        sum += fabs(a.rgb[i] - c.rgb[i]);
        norm = fmax(norm, c.rgb[i]);
    }
    const double mean = sum / (N * N * 3) / norm;
    CHECK(!rc && mean <= GLES_MEAN_BOUND, "gles vs cpu with the map: mean %.2e > %.1e", mean,
          GLES_MEAN_BOUND);
    printf("gles: with the map against the cpu, mean %.2e of the max (bound %.1e)\n", mean,
           GLES_MEAN_BOUND);
    /* A new map on the kept renderer: only the shading, as a fresh frame. */
    l.albedo_map = map2;
    rc |= render(r, s, &l, &q, &a) | render(fresh, s, &l, &q, &b);
    CHECK(!rc && !memcmp(a.rgb, b.rgb, sizeof(float) * N * N * 3),
          "a changed map: planned frame differs from a fresh one");
    l.albedo_map = NULL;
    rc |= render(r, s, &l, &q, &a);
    CHECK(!rc && !memcmp(a.rgb, plain.rgb, sizeof(float) * N * N * 3),
          "the map removed: not the map-less frame");
    printf("gles: a changed map runs the shading only, bit for bit a fresh frame\n");
    hfs_image_free(&plain), hfs_image_free(&a), hfs_image_free(&b), hfs_image_free(&c);
    hfs_renderer_destroy(r), hfs_renderer_destroy(fresh), hfs_renderer_destroy(cpu);
}

int main(int argc, char **argv)
{
    (void)argc;
    scene s;
    if (scene_make("fractal25", N, NULL, &s))
        return 1;
    float *map = make_map(N, N, 12345u), *map2 = make_map(N, N, 777u);
    check_linear(HFS_BACKEND_CPU, "cpu", &s, map);
    check_linear(HFS_BACKEND_TRUTH, "truth", &s, map);
    check_invalid(&s, map);
    if (argc > 1 && !strcmp(argv[1], "gles"))
        check_gles(&s, map, map2);
    free(map);
    free(map2);
    scene_free(&s);
    printf("test_albedo_map: %s\n", failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
