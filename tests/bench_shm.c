/*
 * bench_shm.c — shadow height maps against the truth's exact rays (not a
 * test; prints a Markdown row; tools/bench_shm.sh runs it on the benchmark
 * scenes, BENCHMARKS.md "Shadow height maps").
 *
 *   bench_shm NAME [backends=cpu,gles] [points=2000] [spread=0.02]
 *             KEY=VALUE...   (scene keys: height=, dx=, zscale=, one key=,
 *                             truth-samples=)
 *
 * The points lie near the key light's shadow edges (shm_points.h: within
 * spread times the field's world height range of the centre's shadow
 * height, where that is as far above the ground).  For each backend: the
 * mean |visible fraction - truth's| over the points, the points on the
 * other side of one half than the truth, and the median wall time of 5
 * queries (the maps built each time: what a moved light costs; a GLES
 * renderer made once, its first query not timed).
 */
#include "hfshade.h"
#include "median.h"
#include "scene.h"
#include "scene_load.h"
#include "shm_points.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e3 + 1e-6 * ts.tv_nsec;
}

static void die(const char *what, const hfs_error *err)
{
    fprintf(stderr, "bench_shm: %s: %s\n", what, err ? err->msg : "failed");
    exit(1);
}

/* Visibility of the points on backend b into vis; returns the median ms. */
static double query(hfs_backend b, const hfs_scene_inputs *in, const double *xyz, int n,
                    float *vis, int runs)
{
    hfs_renderer_desc d = {.backend = b};
    hfs_renderer *r = NULL;
    hfs_error err = {""};
    if (hfs_renderer_create(&d, &r, &err))
        die("create", &err);
    double ms[5];
    for (int k = -1; k < runs; ++k) {
        const double t0 = now_ms();
        if (hfs_renderer_query_points(r, &in->field, &in->lighting, &in->quality, xyz, n, vis,
                                      &err))
            die("query", &err);
        if (k >= 0)
            ms[k] = now_ms() - t0;
    }
    hfs_renderer_destroy(r);
    return hfs_median(ms, runs);
}

int main(int argc, char **argv)
{
    if (argc < 2)
        die("usage: bench_shm NAME [backends=cpu,gles] [points=N] [spread=F] KEY=VALUE...", NULL);
    char backends[64] = "cpu";
    int n = 2000;
    double spread = 0.02;
    hfs_scene s;
    hfs_scene_init(&s);
    hfs_error err = {""};
    for (int i = 2; i < argc; ++i) {
        const char *eq = strchr(argv[i], '=');
        if (!eq)
            die(argv[i], NULL);
        const size_t len = (size_t)(eq - argv[i]);
        if (!strncmp(argv[i], "backends", len))
            snprintf(backends, sizeof backends, "%s", eq + 1);
        else if (!strncmp(argv[i], "points", len))
            n = atoi(eq + 1);
        else if (!strncmp(argv[i], "spread", len))
            spread = atof(eq + 1);
        else {
            char key[64];
            snprintf(key, sizeof key, "%.*s", (int)len, argv[i]);
            if (hfs_scene_set(&s, HFS_SOURCE_FLAG, key, eq + 1, "bench_shm", ".", &err))
                die(key, &err);
        }
    }
    hfs_scene_inputs in;
    if (hfs_scene_inputs_load(&s, &in, &err))
        die("scene", &err);
    if (in.lighting.n_key != 1 || n < 1)
        die("give one key light and points >= 1", NULL);
    double lo, hi;
    hfs_field_range(&in.field, &lo, &hi);
    double *xyz = malloc(sizeof(double) * 3 * (size_t)n);
    float *vt = malloc(sizeof(float) * (size_t)n), *v = malloc(sizeof(float) * (size_t)n);
    if (!xyz || !vt || !v ||
        shm_edge_points(&in.field, &in.lighting.key[0], n, spread * in.field.zscale * (hi - lo),
                        12345, xyz))
        die("no shadow edges to test in this scene", NULL);
    const double tt = query(HFS_BACKEND_TRUTH, &in, xyz, n, vt, 1);
    int partial = 0;
    for (int i = 0; i < n; ++i)
        partial += vt[i] > 0.0f && vt[i] < 1.0f;
    for (char *b = strtok(backends, ","); b; b = strtok(NULL, ",")) {
        const hfs_backend be = !strcmp(b, "gles") ? HFS_BACKEND_GLES : HFS_BACKEND_CPU;
        const double ms = query(be, &in, xyz, n, v, 5);
        double mean = 0.0;
        int wrong = 0;
        for (int i = 0; i < n; ++i) {
            mean += fabs((double)v[i] - vt[i]) / n;
            wrong += (v[i] > 0.5f) != (vt[i] > 0.5f);
        }
        printf("| %s %dx%d | %s | %d (%d in a penumbra) | %.4f | %.2f%% | %.1f | %.1f |\n",
               argv[1], in.field.width, in.field.height, b, n, partial, mean,
               100.0 * wrong / n, ms, tt / 1e3);
    }
    free(xyz), free(vt), free(v);
    hfs_scene_inputs_free(&in);
    return 0;
}
