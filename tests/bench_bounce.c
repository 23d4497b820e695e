/*
 * bench_bounce.c — indirect light against the ground truth (not a test;
 * prints a Markdown table; tools/bench_bounce.sh runs it on the benchmark
 * scenes, BENCHMARKS.md "Indirect light").
 *
 *   bench_bounce NAME [backends=cpu,gles] [max-bounces=3] KEY=VALUE...
 *                                      (scene keys, e.g. height=f.pfm dx=1
 *                                       env-map=data/courtyard.exr
 *                                       key=336,15,2,1500 truth-samples=256)
 *
 * For bounces B = 0..max-bounces it renders the truth and each backend
 * (default: cpu; wall time of each; a gles row times one frame from a new
 * renderer, shader compilation included: for frame costs use hfshade
 * render --time) and prints, against the truth with B bounces: the whole
 * image's mean and p99 absolute error (fractions of the unshadowed
 * maximum, SPEC), and the indirect part alone (image(B) - image(0) of each
 * backend) as mean absolute error over the truth's largest indirect value,
 * its 99th percentile and its mean signed error (bias) over the same.
 */
#include "hfshade.h"
#include "scene.h"
#include "scene_load.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static double render(hfs_backend b, hfs_scene_inputs *in, int bounces, hfs_image *out)
{
    hfs_renderer_desc d = {.backend = b};
    hfs_renderer *r = NULL;
    hfs_error err = {""};
    in->lighting.bounces = bounces;
    const double t0 = now();
    if (hfs_renderer_create(&d, &r, &err) ||
        hfs_renderer_render(r, &in->field, &in->lighting, &in->quality, out, NULL, NULL, &err)) {
        fprintf(stderr, "bench_bounce: %s\n", err.msg);
        exit(1);
    }
    hfs_renderer_destroy(r);
    return now() - t0;
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Mean |(a - a0) - (t - t0)| over max(t - t0), the mean of the
 * difference (its bias) and its 99th percentile (issue 36: the rough
 * ground's worst texels) over the same. */
static double indirect_error(const hfs_image *a, const hfs_image *a0, const hfs_image *t,
                             const hfs_image *t0, double *bias, double *p99)
{
    const size_t n = (size_t)a->width * a->height * 3;
    double sum = 0.0, sum_d = 0.0, tmax = 0.0;
    double *ad = malloc(n * sizeof *ad);
    for (size_t i = 0; i < n; ++i) {
        const double ti = (double)t->rgb[i] - t0->rgb[i];
        const double d = ((double)a->rgb[i] - a0->rgb[i]) - ti;
        sum += fabs(d);
        sum_d += d;
        tmax = fmax(tmax, ti);
        if (ad)
            ad[i] = fabs(d);
    }
    *p99 = 0.0;
    if (ad && n > 0) {
        qsort(ad, n, sizeof *ad, cmp_double);
        *p99 = tmax > 0.0 ? ad[(size_t)(0.99 * (double)(n - 1))] / tmax : 0.0;
    }
    free(ad);
    *bias = tmax > 0.0 ? sum_d / n / tmax : 0.0;
    return tmax > 0.0 ? sum / n / tmax : 0.0;
}

/* "cpu,gles" -> backends; returns how many (0: a bad name). */
static int parse_backends(const char *v, hfs_backend *out, int max)
{
    int n = 0;
    char buf[64];
    snprintf(buf, sizeof buf, "%s", v);
    for (char *t = strtok(buf, ","); t && n < max; t = strtok(NULL, ",")) {
        if (!strcmp(t, "cpu"))
            out[n++] = HFS_BACKEND_CPU;
        else if (!strcmp(t, "gles"))
            out[n++] = HFS_BACKEND_GLES;
        else
            return 0;
    }
    return n;
}

static void row(const char *scene, const char *be, int b, const hfs_image *c, const hfs_image *c0,
                const hfs_image *t, const hfs_image *t0, double norm, double tc, double tt)
{
    hfs_metrics m;
    hfs_error err = {""};
    hfs_compare_images(c, t, norm, &m, &err);
    char ind[64] = "- | - | -";
    double bias = 0.0, p99 = 0.0;
    if (b > 0) {
        const double e = indirect_error(c, c0, t, t0, &bias, &p99);
        snprintf(ind, sizeof ind, "%.2f%% | %.1f%% | %+.2f%%", 100.0 * e, 100.0 * p99,
                 100.0 * bias);
    }
    printf("| %s | %s | %d | %.3e | %.3e | %s | %.2f | %.2f |\n", scene, be, b, m.mean_abs,
           m.p99_abs, ind, tc, tt);
    fflush(stdout);
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: bench_bounce NAME [backends=cpu,gles] [max-bounces=N] KEY=VALUE...\n");
        return 2;
    }
    hfs_scene s;
    hfs_scene_init(&s);
    hfs_error err = {""};
    hfs_backend be[2] = {HFS_BACKEND_CPU};
    int n_be = 1, max_b = 3;
    for (int i = 2; i < argc; ++i) {
        char key[64];
        const char *eq = strchr(argv[i], '=');
        if (!eq || (size_t)(eq - argv[i]) >= sizeof key) {
            fprintf(stderr, "bench_bounce: '%s' is not KEY=VALUE\n", argv[i]);
            return 2;
        }
        memcpy(key, argv[i], (size_t)(eq - argv[i]));
        key[eq - argv[i]] = '\0';
        if (!strcmp(key, "backends")) {
            if (!(n_be = parse_backends(eq + 1, be, 2))) {
                fprintf(stderr, "bench_bounce: backends '%s': not cpu and/or gles\n", eq + 1);
                return 2;
            }
        } else if (!strcmp(key, "max-bounces")) {
            max_b = atoi(eq + 1);
            if (max_b < 0 || max_b > 3) {
                fprintf(stderr, "bench_bounce: max-bounces '%s': not in 0..3\n", eq + 1);
                return 2;
            }
        } else if (hfs_scene_set(&s, HFS_SOURCE_FLAG, key, eq + 1, "bench_bounce", ".", &err)) {
            fprintf(stderr, "bench_bounce: %s\n", err.msg);
            return 2;
        }
    }
    hfs_scene_inputs in;
    if (hfs_scene_inputs_load(&s, &in, &err)) {
        fprintf(stderr, "bench_bounce: %s\n", err.msg);
        return 1;
    }
    const int w = in.field.width, h = in.field.height;
    hfs_image t[4], c[2][4], u;
    for (int b = 0; b < 4; ++b)
        hfs_image_alloc(&t[b], w, h, &err), hfs_image_alloc(&c[0][b], w, h, &err),
            hfs_image_alloc(&c[1][b], w, h, &err);
    hfs_image_alloc(&u, w, h, &err);
    hfs_render_unshadowed(&in.field, &in.lighting, &in.quality, &u, &err);
    const double norm = hfs_image_max(&u);
    for (int b = 0; b <= max_b; ++b) {
        const double tt = render(HFS_BACKEND_TRUTH, &in, b, &t[b]);
        for (int k = 0; k < n_be; ++k) {
            const double tc = render(be[k], &in, b, &c[k][b]);
            row(argv[1], be[k] == HFS_BACKEND_GLES ? "gles" : "cpu", b, &c[k][b], &c[k][0], &t[b],
                &t[0], norm, tc, tt);
        }
    }
    for (int b = 0; b < 4; ++b)
        hfs_image_free(&t[b]), hfs_image_free(&c[0][b]), hfs_image_free(&c[1][b]);
    hfs_image_free(&u);
    hfs_scene_inputs_free(&in);
    return 0;
}
