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
 *
 *   bench_shm NAME uniform=1 [points=N] [spread=F] KEY=VALUE...
 * Issue 19's must-show: points uniform over the footprint, each a random
 * height within spread times the relief above the ground (default 0.1),
 * classified shadowed / lit (visible fraction below / above one half)
 * against the truth's exact rays, leaving out the points within one texel
 * of a shadow edge: those whose truth classification changes at one of
 * the four points one texel away at the same height.  Prints the share of
 * the others each backend classifies wrong, and the mean |v - truth| over
 * all points (the soft edge's error).
 *
 *   bench_shm NAME terrain=1 KEY=VALUE...
 * The SHM as a key-light path for the terrain itself (issue 19 item 3):
 * the key light alone, albedo 1, the truth's image against the CPU
 * reference's (its horizon path) and against rho/pi Le E_cap(N.d, alpha)
 * times the SHM's visible fraction at every texel's point (lifted 1e-4 dx,
 * as SPEC's receivers); SPEC's mean and p99 over the unshadowed maximum,
 * and the wall time of each (the SHM's: the query of every texel).
 */
#include "field_geom.h"
#include "hfshade.h"
#include "lights.h"
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

static double render(hfs_backend b, const hfs_scene_inputs *in, hfs_image *out)
{
    hfs_renderer_desc d = {.backend = b};
    hfs_renderer *r = NULL;
    hfs_error err = {""};
    const double t0 = now_ms();
    if (hfs_renderer_create(&d, &r, &err) ||
        hfs_renderer_render(r, &in->field, &in->lighting, &in->quality, out, NULL, NULL, &err))
        die("render", &err);
    hfs_renderer_destroy(r);
    return now_ms() - t0;
}

/* The key light's Lo from the SHM's visible fraction at every texel. */
static double shm_image(const hfs_scene_inputs *in, hfs_image *out)
{
    const hfs_field *f = &in->field;
    const hfs_key_light *k = &in->lighting.key[0];
    const size_t n = (size_t)f->width * (size_t)f->height;
    double *xyz = malloc(3 * n * sizeof *xyz);
    float *vis = malloc(n * sizeof *vis);
    if (!xyz || !vis)
        die("out of memory", NULL);
    for (int j = 0; j < f->height; ++j)
        for (int i = 0; i < f->width; ++i) {
            double *p = xyz + 3 * ((size_t)j * (size_t)f->width + (size_t)i);
            p[0] = i * f->dx, p[1] = j * f->dx, p[2] = hfs_field_z(f, i, j) + 1e-4 * f->dx;
        }
    const double ms = query(HFS_BACKEND_CPU, in, xyz, (int)n, vis, 1);
    double d[3];
    hfs_dir(k->phi, k->elev, d);
    for (int j = 0; j < f->height; ++j)
        for (int i = 0; i < f->width; ++i) {
            double nn[3];
            hfs_field_normal(f, i, j, nn);
            const size_t p = (size_t)j * (size_t)f->width + (size_t)i;
            const double e = hfs_cap_irradiance(nn[0] * d[0] + nn[1] * d[1] + nn[2] * d[2],
                                                k->alpha) * vis[p];
            for (int c = 0; c < 3; ++c)
                out->rgb[3 * p + (size_t)c] =
                    (float)(in->lighting.albedo / 3.14159265358979323846 * k->radiance[c] * e);
        }
    free(xyz), free(vis);
    return ms;
}

/* uniform=1: classification outside a one-texel band around the edges. */
static void uniform(const char *name, hfs_scene_inputs *in, int n, double spread,
                    const char *backends)
{
    const hfs_field *f = &in->field;
    double lo, hi;
    hfs_field_range(f, &lo, &hi);
    const double rise = spread * f->zscale * (hi - lo);
    double *xyz = malloc(sizeof(double) * 15 * (size_t)n); /* each point, then its 4 */
    float *vt = malloc(sizeof(float) * 5 * (size_t)n), *v = malloc(sizeof(float) * (size_t)n);
    if (!xyz || !vt || !v)
        die("out of memory", NULL);
    unsigned seed = 4242u;
    const double off[5][2] = {{0, 0}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (int i = 0; i < n; ++i) {
        double u[3];
        for (int c = 0; c < 3; ++c) {
            seed = seed * 1103515245u + 12345u;
            u[c] = ((seed >> 8) & 0xffff) / 65535.0;
        }
        const double x = 1.0 + (f->width - 3) * u[0], y = 1.0 + (f->height - 3) * u[1];
        double g;
        hfs_field_bilinear(f, x, y, &g);
        for (int k = 0; k < 5; ++k) {
            double *p = xyz + 3 * ((size_t)k * (size_t)n + (size_t)i);
            p[0] = (x + off[k][0]) * f->dx, p[1] = (y + off[k][1]) * f->dx;
            p[2] = g + 1e-4 * f->dx + rise * u[2];
        }
    }
    query(HFS_BACKEND_TRUTH, in, xyz, 5 * n, vt, 1);
    int outside = 0, shadowed = 0;
    for (int i = 0; i < n; ++i) {
        int band = 0;
        for (int k = 1; k < 5; ++k)
            band |= (vt[(size_t)k * n + i] > 0.5f) != (vt[i] > 0.5f);
        outside += !band;
        shadowed += vt[i] <= 0.5f;
    }
    char list[64];
    snprintf(list, sizeof list, "%s", backends);
    for (char *b = strtok(list, ","); b; b = strtok(NULL, ",")) {
        const hfs_backend be = !strcmp(b, "gles") ? HFS_BACKEND_GLES : HFS_BACKEND_CPU;
        query(be, in, xyz, n, v, 1);
        int wrong = 0;
        double mean = 0.0;
        for (int i = 0; i < n; ++i) {
            int band = 0;
            for (int k = 1; k < 5; ++k)
                band |= (vt[(size_t)k * n + i] > 0.5f) != (vt[i] > 0.5f);
            wrong += !band && (v[i] > 0.5f) != (vt[i] > 0.5f);
            mean += fabs((double)v[i] - vt[i]) / n;
        }
        printf("| %s %dx%d | %s | %d (%d shadowed, %d outside the band) | %.3f%% | %.4f |\n",
               name, f->width, f->height, b, n, shadowed, outside, 100.0 * wrong / outside,
               mean);
    }
    free(xyz), free(vt), free(v);
}

/* terrain=1: the key light alone, truth vs horizon path vs SHM. */
static void terrain(const char *name, hfs_scene_inputs *in)
{
    in->lighting.has_env = 0, in->lighting.n_local = 0;
    hfs_image t = {0}, c = {0}, s = {0}, u = {0};
    hfs_error err = {""};
    const int w = in->field.width, h = in->field.height;
    if (hfs_image_alloc(&t, w, h, &err) || hfs_image_alloc(&c, w, h, &err) ||
        hfs_image_alloc(&s, w, h, &err) || hfs_image_alloc(&u, w, h, &err) ||
        hfs_render_unshadowed(&in->field, &in->lighting, &in->quality, &u, &err))
        die("images", &err);
    const double tt = render(HFS_BACKEND_TRUTH, in, &t), tc = render(HFS_BACKEND_CPU, in, &c);
    const double ts = shm_image(in, &s);
    const double norm = hfs_image_max(&u);
    hfs_metrics mc, ms;
    if (hfs_compare_images(&c, &t, norm, &mc, &err) || hfs_compare_images(&s, &t, norm, &ms, &err))
        die("compare", &err);
    printf("| %s %dx%d | horizons (cpu) | %.3e | %.3e | %.0f |\n", name, w, h, mc.mean_abs,
           mc.p99_abs, tc);
    printf("| %s %dx%d | shm (cpu) | %.3e | %.3e | %.0f |\n", name, w, h, ms.mean_abs,
           ms.p99_abs, ts);
    printf("| %s %dx%d | truth | - | - | %.0f |\n", name, w, h, tt);
    hfs_image_free(&t), hfs_image_free(&c), hfs_image_free(&s), hfs_image_free(&u);
}

int main(int argc, char **argv)
{
    if (argc < 2)
        die("usage: bench_shm NAME [backends=cpu,gles] [points=N] [spread=F] KEY=VALUE...", NULL);
    char backends[64] = "cpu";
    int n = 2000, terrain_mode = 0, uniform_mode = 0;
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
        else if (!strncmp(argv[i], "terrain", len))
            terrain_mode = atoi(eq + 1);
        else if (!strncmp(argv[i], "uniform", len))
            uniform_mode = atoi(eq + 1);
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
    if (terrain_mode || uniform_mode) {
        if (terrain_mode)
            terrain(argv[1], &in);
        else
            uniform(argv[1], &in, n, spread == 0.02 ? 0.1 : spread, backends);
        hfs_scene_inputs_free(&in);
        return 0;
    }
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
