/*
 * bench_bounce.c — indirect light against the ground truth (not a test;
 * prints a Markdown table; tools/bench_bounce.sh runs it on the benchmark
 * scenes, BENCHMARKS.md "Indirect light").
 *
 *   bench_bounce NAME KEY=VALUE...     (scene keys, e.g. height=f.pfm dx=1
 *                                       env-map=data/courtyard.exr
 *                                       key=336,15,2,1500 truth-samples=256)
 *
 * For bounces B = 0..3 it renders the truth and the CPU reference (wall
 * time of each) and prints, against the truth with B bounces: the whole
 * image's mean and p99 absolute error (fractions of the unshadowed
 * maximum, SPEC), and the indirect part alone (image(B) - image(0) of each
 * backend) as mean absolute error over the truth's largest indirect value.
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

/* Mean |(a - a0) - (t - t0)| over max(t - t0). */
static double indirect_error(const hfs_image *a, const hfs_image *a0, const hfs_image *t,
                             const hfs_image *t0)
{
    const size_t n = (size_t)a->width * a->height * 3;
    double sum = 0.0, tmax = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const double ti = (double)t->rgb[i] - t0->rgb[i];
        sum += fabs(((double)a->rgb[i] - a0->rgb[i]) - ti);
        tmax = fmax(tmax, ti);
    }
    return tmax > 0.0 ? sum / n / tmax : 0.0;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: bench_bounce NAME KEY=VALUE...\n");
        return 2;
    }
    hfs_scene s;
    hfs_scene_init(&s);
    hfs_error err = {""};
    for (int i = 2; i < argc; ++i) {
        char key[64];
        const char *eq = strchr(argv[i], '=');
        if (!eq || (size_t)(eq - argv[i]) >= sizeof key) {
            fprintf(stderr, "bench_bounce: '%s' is not KEY=VALUE\n", argv[i]);
            return 2;
        }
        memcpy(key, argv[i], (size_t)(eq - argv[i]));
        key[eq - argv[i]] = '\0';
        if (hfs_scene_set(&s, HFS_SOURCE_FLAG, key, eq + 1, "bench_bounce", ".", &err)) {
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
    hfs_image t[4], c[4], u;
    for (int b = 0; b < 4; ++b)
        hfs_image_alloc(&t[b], w, h, &err), hfs_image_alloc(&c[b], w, h, &err);
    hfs_image_alloc(&u, w, h, &err);
    hfs_render_unshadowed(&in.field, &in.lighting, &in.quality, &u, &err);
    const double norm = hfs_image_max(&u);
    for (int b = 0; b < 4; ++b) {
        const double tt = render(HFS_BACKEND_TRUTH, &in, b, &t[b]);
        const double tc = render(HFS_BACKEND_CPU, &in, b, &c[b]);
        hfs_metrics m;
        hfs_compare_images(&c[b], &t[b], norm, &m, &err);
        char ind[32] = "-";
        if (b > 0)
            snprintf(ind, sizeof ind, "%.2f%%", 100.0 * indirect_error(&c[b], &c[0], &t[b], &t[0]));
        printf("| %s | %d | %.3e | %.3e | %s | %.2f | %.2f |\n", argv[1], b, m.mean_abs,
               m.p99_abs, ind, tc, tt);
        fflush(stdout);
    }
    for (int b = 0; b < 4; ++b)
        hfs_image_free(&t[b]), hfs_image_free(&c[b]);
    hfs_image_free(&u);
    hfs_scene_inputs_free(&in);
    return 0;
}
