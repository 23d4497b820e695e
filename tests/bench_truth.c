/*
 * bench_truth.c — wall-clock cost of the ground truth on a synthetic terrain
 * (not a test; prints timings).
 *
 *   bench_truth SIZE [env|key|local] [AZIMUTHS|SAMPLES] [THREADS]
 *
 * Terrain: 6 octaves of value noise (deterministic), relief about SIZE/6
 * texels, dx = 1, zscale = 1: hills and valleys with slopes up to ~45 deg,
 * so horizons are neither trivially flat nor everywhere steep.
 *   env:   SH sky (c0 = sqrt(4 pi) plus a sun-ward gradient), AZIMUTHS (720)
 *   key:   one key light at 25 deg elevation, alpha 0.05, SAMPLES (256)
 *   local: one sphere light above the middle, SAMPLES (256)
 */
#include "backends.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define PI 3.14159265358979323846

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static double lattice(uint32_t x, uint32_t y, uint32_t octave)
{
    uint64_t h = (uint64_t)x * 0x9e3779b97f4a7c15ULL ^ (uint64_t)y * 0xc2b2ae3d27d4eb4fULL ^
                 (uint64_t)octave * 0x165667b19e3779f9ULL;
    h ^= h >> 31;
    h *= 0xbf58476d1ce4e5b9ULL;
    h ^= h >> 29;
    return (double)(h >> 11) / 9007199254740992.0;
}

static float *terrain(int n)
{
    float *z = malloc((size_t)n * n * sizeof *z);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            double v = 0.0, amp = n / 6.0, period = n / 2.0;
            for (int o = 0; o < 6; ++o) {
                const double x = i / period, y = j / period;
                const uint32_t x0 = (uint32_t)x, y0 = (uint32_t)y;
                const double fx = x - x0, fy = y - y0;
                const double sx = fx * fx * (3 - 2 * fx), sy = fy * fy * (3 - 2 * fy);
                const double a = lattice(x0, y0, o), b = lattice(x0 + 1, y0, o);
                const double c = lattice(x0, y0 + 1, o), d = lattice(x0 + 1, y0 + 1, o);
                v += amp * ((a * (1 - sx) + b * sx) * (1 - sy) + (c * (1 - sx) + d * sx) * sy);
                amp *= 0.5;
                period *= 0.5;
                if (period < 1.0)
                    break;
            }
            z[(size_t)j * n + i] = (float)v;
        }
    return z;
}

int main(int argc, char **argv)
{
    const int n = argc > 1 ? atoi(argv[1]) : 64;
    const char *mode = argc > 2 ? argv[2] : "env";
    const int count = argc > 3 ? atoi(argv[3]) : 0;
    const int threads = argc > 4 ? atoi(argv[4]) : 0;
    if (n < 2) {
        fprintf(stderr, "usage: bench_truth SIZE [env|key|local] [AZIMUTHS|SAMPLES] [THREADS]\n");
        return 2;
    }
    float *z = terrain(n);
    const hfs_field f = {n, n, z, 1.0, 1.0};
    hfs_lighting l;
    hfs_lighting_defaults(&l);
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.threads = threads;
    if (!strcmp(mode, "env")) {
        l.has_env = 1;
        for (int c = 0; c < 3; ++c) {
            l.env_sh[c][0] = sqrt(4.0 * PI);
            l.env_sh[c][2] = 0.8; /* brighter toward the zenith */
            l.env_sh[c][3] = 0.5; /* and toward +x */
        }
        if (count > 0)
            q.truth_azimuths = count;
    } else if (!strcmp(mode, "key")) {
        l.n_key = 1;
        l.key[0] = (hfs_key_light){.phi = 0.7, .elev = 25 * PI / 180, .alpha = 0.05,
                                   .radiance = {1, 1, 1}};
        if (count > 0)
            q.truth_light_samples = count;
    } else if (!strcmp(mode, "local")) {
        l.n_local = 1;
        l.local[0] = (hfs_local_light){.pos = {n / 2.0, n / 2.0, n / 3.0}, .radius = n / 40.0,
                                       .radiance = {1, 1, 1}};
        if (count > 0)
            q.truth_light_samples = count;
    } else {
        fprintf(stderr, "bench_truth: unknown mode '%s'\n", mode);
        return 2;
    }
    hfs_image img;
    hfs_error err;
    if (hfs_image_alloc(&img, n, n, &err) != HFS_OK) {
        fprintf(stderr, "bench_truth: %s\n", err.msg);
        return 1;
    }
    const double t0 = now();
    const int rc = hfs_truth_render(&f, &l, &q, &img, NULL, NULL, &err);
    const double t1 = now();
    if (rc != HFS_OK) {
        fprintf(stderr, "bench_truth: %s\n", err.msg);
        return 1;
    }
    double mean = 0.0;
    for (int k = 0; k < n * n; ++k)
        mean += img.rgb[3 * k];
    printf("truth %dx%d %s (%s %d, %d threads): %.2f s, mean Lo %.5f\n", n, n, mode,
           strcmp(mode, "env") ? "samples" : "azimuths",
           strcmp(mode, "env") ? q.truth_light_samples : q.truth_azimuths,
           threads ? threads : 0, t1 - t0, mean / (n * n));
    hfs_image_free(&img);
    free(z);
    return 0;
}
