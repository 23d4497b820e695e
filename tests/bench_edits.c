/*
 * bench_edits.c — what a local edit of the heights costs (issue 38),
 * through the public API: a field of gentle terrain (value-noise fBm,
 * Hurst 0.8, scaled so that its steepest slope is 40 degrees), an SH sky
 * and a 2-degree sun 25 degrees up, the product's defaults.  Rounds
 * alternate, so both kinds of frame see the same machine load:
 *   cold   hfs_renderer_invalidate, then a frame of the same heights;
 *   edit   a 32 x 32 smooth bump (a cosine bell, +-8 height units, kept
 *          inside the field's range) at a random place, the heights
 *          changed in place with a new serial, then a frame;
 *   whole  every height moved a little (inside the range), then a frame.
 * Each edited frame is compared with a cold frame of the same heights (a
 * second renderer), bit for bit.  Prints the medians, their ratios, the
 * share of edits that took the edit path (the frame report's "heights
 * edited") and whether every frame matched.
 *
 *   bench_edits [--size N] [--rounds R] [--seed S] [--passes 1] [--local 1]
 *               (defaults 512, 5, 1, 0, 0)
 * --local 1 adds a local light (radius 2, 20 above the field's highest
 * point, over (0.3, 0.6) of the field): its ratios are redrawn per edit too.
 * --passes 1 also prints the edited frames' median time per pass (glFinish +
 * clock: hfs_renderer_set_timing_finish), and the frames take a little
 * longer for it.
 *
 * No GLES context of any kind: exit 77 (gl_test.h).
 */
#include "hfshade.h"
#include "median.h"
#include "terrain_gen.h"
#include "gl_test.h"
#include "test_rng.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define PI 3.14159265358979323846

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

typedef struct bench {
    int n;
    float *z;
    float lo, hi;
    hfs_field f;
    hfs_lighting l;
    hfs_quality q;
    hfs_renderer *kept, *fresh;
    hfs_image a, b;
    uint64_t serial;
    int mismatches;
} bench;

/* Gentle terrain: fBm scaled to a steepest central-difference slope of
 * tan 40 degrees. */
static int terrain(bench *B, uint32_t seed)
{
    const int n = B->n;
    if (hfs_terrain_fbm(B->z, n, n, seed, 0.25, 0.8))
        return -1;
    double smax = 0.0;
    for (int y = 1; y + 1 < n; ++y)
        for (int x = 1; x + 1 < n; ++x) {
            const float *p = B->z + (size_t)y * n + x;
            const double gx = 0.5 * (p[1] - p[-1]), gy = 0.5 * (p[n] - p[-n]);
            smax = fmax(smax, sqrt(gx * gx + gy * gy));
        }
    const double s = smax > 0.0 ? tan(40.0 * PI / 180.0) / smax : 1.0;
    B->lo = B->hi = B->z[0] * (float)s;
    for (size_t i = 0; i < (size_t)n * n; ++i) {
        B->z[i] *= (float)s;
        B->lo = fminf(B->lo, B->z[i]);
        B->hi = fmaxf(B->hi, B->z[i]);
    }
    return 0;
}

static float inside(const bench *B, double v)
{
    const double lo = B->lo + 1e-3, hi = B->hi - 1e-3;
    return (float)(v < lo ? lo : (v > hi ? hi : v));
}

/* A 32 x 32 cosine bell of +-8 at a random place (inside the range: the
 * field's lowest and highest heights stay where they are). */
static void edit_bump(bench *B)
{
    const int n = B->n, r = 16;
    const int cx = (int)(urand() * n), cy = (int)(urand() * n);
    const double d = urand() < 0.5 ? 8.0 : -8.0;
    for (int y = cy - r; y < cy + r; ++y)
        for (int x = cx - r; x < cx + r; ++x) {
            if (x < 0 || y < 0 || x >= n || y >= n)
                continue;
            const double q = sqrt((double)(x - cx) * (x - cx) + (double)(y - cy) * (y - cy)) / r;
            float *z = &B->z[(size_t)y * n + x];
            if (q < 1.0 && *z > B->lo && *z < B->hi)
                *z = inside(B, *z + d * 0.5 * (1.0 + cos(PI * q)));
        }
}

static void edit_whole(bench *B)
{
    for (size_t i = 0; i < (size_t)B->n * B->n; ++i)
        if (B->z[i] > B->lo && B->z[i] < B->hi)
            B->z[i] = inside(B, B->z[i] + 0.01 * (urand() - 0.5));
}

/* A timed frame of the kept renderer (cold: invalidated first). */
static double frame(bench *B, int cold)
{
    hfs_error err;
    if (cold)
        hfs_renderer_invalidate(B->kept);
    else
        hfs_renderer_set_field_serial(B->kept, ++B->serial);
    const double t0 = now_ms();
    if (hfs_renderer_render(B->kept, &B->f, &B->l, &B->q, &B->a, NULL, NULL, &err)) {
        fprintf(stderr, "bench_edits: %s\n", err.msg);
        exit(1);
    }
    return now_ms() - t0;
}

/* The kept renderer's last image against a cold frame of the same heights. */
static void check(bench *B)
{
    hfs_error err;
    hfs_renderer_invalidate(B->fresh);
    if (hfs_renderer_render(B->fresh, &B->f, &B->l, &B->q, &B->b, NULL, NULL, &err)) {
        fprintf(stderr, "bench_edits: %s\n", err.msg);
        exit(1);
    }
    B->mismatches += memcmp(B->a.rgb, B->b.rgb, (size_t)B->n * B->n * 3 * sizeof(float)) != 0;
}

int main(int argc, char **argv)
{
    int n = 512, rounds = 5, passes = 0, local = 0;
    unsigned seed = 1;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!strcmp(argv[i], "--size"))
            n = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--rounds"))
            rounds = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--seed"))
            seed = (unsigned)atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--passes"))
            passes = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--local"))
            local = atoi(argv[i + 1]);
    }
    if (n < 64 || n > 8192 || rounds < 1 || rounds > 1000 || argc % 2 == 0) {
        fprintf(stderr, "usage: bench_edits [--size N 64..8192] [--rounds R] [--seed S]\n");
        return 2;
    }
    rng_state ^= seed;
    bench B;
    memset(&B, 0, sizeof B);
    B.n = n;
    B.z = malloc((size_t)n * n * sizeof *B.z);
    hfs_error err;
    if (!B.z || terrain(&B, seed) || hfs_image_alloc(&B.a, n, n, &err) ||
        hfs_image_alloc(&B.b, n, n, &err))
        return 1;
    B.f = (hfs_field){.width = n, .height = n, .z = B.z, .dx = 1.0, .zscale = 1.0};
    hfs_lighting_defaults(&B.l);
    B.l.has_env = 1;
    for (int c = 0; c < 3; ++c)
        B.l.env_sh[c][0] = 3.5449077; /* a uniform sky of radiance 1 */
    hfs_key_light *k = &B.l.key[B.l.n_key++];
    k->phi = 336.0 * PI / 180.0;
    k->elev = 25.0 * PI / 180.0;
    k->alpha = 1.0 * PI / 180.0;
    for (int c = 0; c < 3; ++c)
        k->radiance[c] = 1500.0f;
    if (local) {
        hfs_local_light *p = &B.l.local[B.l.n_local++];
        p->pos[0] = 0.3 * (n - 1);
        p->pos[1] = 0.6 * (n - 1);
        p->pos[2] = B.hi + 20.0;
        p->radius = 2.0;
        for (int c = 0; c < 3; ++c)
            p->radiance[c] = 300.0f;
    }
    hfs_quality_defaults(&B.q);
    B.kept = gl_test_gles();
    B.fresh = gl_test_gles();
    if (passes) {
        hfs_renderer_set_timing(B.kept, 1);
        hfs_renderer_set_timing_finish(B.kept, 1);
    }
    frame(&B, 1); /* programs compiled, textures made */
    double pass_ms[HFS_MAX_PASSES][64];
    hfs_timings t = {0};
    double *cold = malloc(sizeof(double) * rounds), *edit = malloc(sizeof(double) * rounds),
           *whole = malloc(sizeof(double) * rounds);
    if (!cold || !edit || !whole)
        return 1;
    int on_path = 0, whole_on_path = 0;
    for (int r = 0; r < rounds; ++r) {
        cold[r] = frame(&B, 1);
        edit_bump(&B);
        edit[r] = frame(&B, 0);
        on_path += gl_test_edited(B.kept);
        if (passes && r < 64 && !hfs_renderer_timings(B.kept, &t))
            for (int p = 0; p < t.n_passes; ++p)
                pass_ms[p][r] = t.pass[p].ms;
        check(&B);
        edit_whole(&B);
        whole[r] = frame(&B, 0);
        whole_on_path += gl_test_edited(B.kept);
        check(&B);
    }
    const double mc = hfs_median(cold, rounds), me = hfs_median(edit, rounds),
                 mw = hfs_median(whole, rounds);
    printf("| %d^2 | %.1f ms | %.1f ms (%.3fx) | %.1f ms (%.3fx) | %d/%d, %d/%d | %s |\n", n,
           mc, me, me / mc, mw, mw / mc, on_path, rounds, whole_on_path, rounds,
           B.mismatches ? "NO" : "yes");
    for (int p = 0; passes && p < t.n_passes; ++p)
        printf("  %-12s %8.2f ms\n", t.pass[p].name,
               hfs_median(pass_ms[p], rounds < 64 ? rounds : 64));
    printf("(size | cold frame | 32^2 bump edited | every height moved | on the edit path: "
           "bumps, whole | edited == cold, bit for bit)\n");
    hfs_renderer_destroy(B.kept);
    hfs_renderer_destroy(B.fresh);
    hfs_image_free(&B.a);
    hfs_image_free(&B.b);
    free(B.z);
    free(cold);
    free(edit);
    free(whole);
    return B.mismatches ? 1 : 0;
}
