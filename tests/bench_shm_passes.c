/*
 * bench_shm_passes.c — a key light's shadow height maps against the
 * horizon path's key-light passes, side by side (issue 19's must-show: the
 * SHM's time at 256^2, 512^2 and 1024^2 against the horizon path; not a
 * test, prints a Markdown table; BENCHMARKS.md "Shadow height maps").
 *
 *   bench_shm_passes [ROUNDS] [SIZE...]   (defaults 5, 256 512 1024)
 *
 * Per size, a fractal field (relief 0.25, dx 1) under the demo's sun alone
 * (336/15 degrees, radius 2), each round timing in turn:
 *   horizons  a GLES frame with every pass rerun (hfs_renderer_invalidate),
 *             its "key" and "keyfactor" passes (timing level 1 by glFinish:
 *             the key light's horizons and its per-texel factor);
 *   gles shm  one point's query on GLES: the 5 layers' maps built (heights
 *             uploaded, the doubling passes, each map read back), wall time;
 *   cpu shm   the same query on the CPU reference (the 5 maps, O(W H) each).
 * Medians over the rounds.  Memory: the GLES frame's textures (all of a
 * key-only frame) and the SHM's own (2 RGBA targets on the GPU, the 5 maps
 * as floats on the host; 5 maps on the CPU).  No GLES context: exit 77.
 */
#include "gl_test.h"
#include "hfshade.h"
#include "median.h"
#include "terrain_gen.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define PI 3.14159265358979323846
#define MAX_ROUNDS 31

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e3 + 1e-6 * ts.tv_nsec;
}

static double key_passes_ms(const hfs_timings *t)
{
    double ms = 0.0;
    for (int i = 0; i < t->n_passes; ++i)
        if (!strcmp(t->pass[i].name, "key") || !strcmp(t->pass[i].name, "keyfactor"))
            ms += t->pass[i].ms;
    return ms;
}

static int size_row(hfs_renderer *g, hfs_renderer *c, int n, int rounds)
{
    float *z = malloc(sizeof(float) * n * n);
    if (!z || hfs_terrain_fractal(z, n, n, 1, 0.25)) {
        free(z);
        return 1;
    }
    const hfs_field f = {.width = n, .height = n, .z = z, .dx = 1.0, .zscale = 1.0};
    hfs_lighting l;
    hfs_lighting_defaults(&l);
    l.n_key = 1;
    l.key[0] = (hfs_key_light){.phi = 336.0 * PI / 180.0, .elev = 15.0 * PI / 180.0,
                               .alpha = 2.0 * PI / 180.0, .radiance = {1500, 1500, 1500}};
    hfs_quality q;
    hfs_quality_defaults(&q);
    hfs_image img = {0};
    hfs_error err = {""};
    const double p[3] = {0.5 * (n - 1), 0.5 * (n - 1), 1e6};
    float vis;
    double hz[MAX_ROUNDS], gs[MAX_ROUNDS], cs[MAX_ROUNDS];
    size_t bytes = 0;
    int rc = hfs_image_alloc(&img, n, n, &err);
    for (int k = -1; k < rounds && !rc; ++k) { /* the first: warm-up */
        hfs_renderer_invalidate(g);
        rc = hfs_renderer_render(g, &f, &l, &q, &img, NULL, NULL, &err);
        hfs_timings t;
        hfs_renderer_timings(g, &t);
        bytes = t.texture_bytes;
        double t0 = now_ms();
        rc |= hfs_renderer_query_points(g, &f, &l, &q, p, 1, &vis, &err);
        const double t1 = now_ms();
        rc |= hfs_renderer_query_points(c, &f, &l, &q, p, 1, &vis, &err);
        if (k >= 0)
            hz[k] = key_passes_ms(&t), gs[k] = t1 - t0, cs[k] = now_ms() - t1;
    }
    if (rc)
        fprintf(stderr, "bench_shm_passes: %s\n", err.msg);
    else
        printf("| %dx%d | %.1f | %.1f | %.1f | %.1f MiB | %.1f / %.1f MiB | %.1f MiB |\n", n, n,
               hfs_median(hz, rounds), hfs_median(gs, rounds), hfs_median(cs, rounds),
               bytes / 1048576.0, 16.0 * n * n / 1048576.0, 20.0 * n * n / 1048576.0,
               20.0 * n * n / 1048576.0);
    hfs_image_free(&img);
    free(z);
    return rc != 0;
}

int main(int argc, char **argv)
{
    const int rounds = argc > 1 ? atoi(argv[1]) : 5;
    if (rounds < 1 || rounds > MAX_ROUNDS) {
        fprintf(stderr, "usage: bench_shm_passes [ROUNDS 1..%d] [SIZE...]\n", MAX_ROUNDS);
        return 2;
    }
    hfs_renderer *g = gl_test_gles(), *c = NULL;
    hfs_renderer_desc cd = {.backend = HFS_BACKEND_CPU};
    hfs_error err = {""};
    if (hfs_renderer_create(&cd, &c, &err)) {
        fprintf(stderr, "bench_shm_passes: %s\n", err.msg);
        return 1;
    }
    hfs_renderer_set_timing(g, 1);
    hfs_renderer_set_timing_finish(g, 1);
    printf("| field | horizon path: key + keyfactor passes ms | gles shm (5 maps, read back) ms "
           "| cpu shm (5 maps) ms | gles frame textures | gles shm: GPU / host | cpu shm |\n");
    printf("|---|---|---|---|---|---|---|\n");
    static const int def[3] = {256, 512, 1024};
    int rc = 0;
    for (int i = 0; i < (argc > 2 ? argc - 2 : 3) && !rc; ++i)
        rc = size_row(g, c, argc > 2 ? atoi(argv[2 + i]) : def[i], rounds);
    hfs_renderer_destroy(g);
    hfs_renderer_destroy(c);
    return rc;
}
