/*
 * test_gles_bench.c — measurement tool for the GLES renderer (not a test;
 * built as gles_bench): per-pass GPU times, fetch counts, texture memory,
 * and optionally the SPEC metrics against the CPU reference.
 *
 *   gles_bench [--scene NAME|FILE] [--size N] [--precision fp16|fp32]
 *              [--path legendre|tables|slice] [--subsample S] [--lights env|key|both]
 *              [--frames F] [--cold] [--count] [--compare] [--finish] [--k K] [--offset O]
 *              [--nphi-env N] [--nphi-key N] [--refine N] [--split 0|1] [--far-from N]
 *              [--far-dirs K] [--far-step G] [--context NAME] [--profile P]
 *              [--data DIR] [--dx F] [--zscale F] [--vs-fp32]
 *
 * Frames: the first frame compiles programs and is reported separately;
 * then F frames, each with the terrain unchanged (warm: only the key-light
 * passes and shading run) or, with --cold, with the cache invalidated (the
 * full frame: upload, pyramid, normals, env, key, shade).  Per pass the
 * median and the minimum over the F frames are printed (on a shared
 * machine the minimum is the better estimate of the uncontended cost).  --count adds counted fetches of the
 * horizon passes (timing level 2, one extra frame).  --compare: SPEC
 * metrics against the CPU reference; --vs-fp32: the fp16 frame against the
 * same renderer at --precision fp32 (the fp16 storage error alone).
 * --finish times each stage by glFinish and the clock even where timer
 * queries exist: a stage's host and driver work as well as its GPU time
 * (on a real GPU the difference shows what the host adds; the frame is
 * slower by the finishes).
 */
#include "backends.h"
#include "test_gles_scenes.h"
#include "gl_test.h"
#include "cli_usage.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifndef HFS_DATA_DIR
#define HFS_DATA_DIR "data"
#endif

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* CPU time of the whole process (all llvmpipe threads): on a shared machine
 * it is much less sensitive to contention than wall time. */
static double cpu_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

static double minimum(const double *v, int n)
{
    double m = v[0];
    for (int i = 1; i < n; ++i)
        m = v[i] < m ? v[i] : m;
    return m;
}

typedef struct bench_opts {
    const char *scene, *prec, *path, *lights, *context, *profile, *data;
    int n, sub, frames, cold, count, compare, vs32, finish;
    double dx, zscale;
    hfs_quality q;
} bench_opts;

#define PROG "gles_bench"

static void usage(FILE *to)
{
    fprintf(to, "usage: gles_bench [--scene NAME|FILE] [--size N] [--precision fp16|fp32]\n"
                "    [--path legendre|tables|slice] [--subsample S] [--lights env|key|both]\n"
                "    [--frames F] [--cold] [--count] [--compare] [--finish] [--k K] [--offset O]\n"
                "    [--nphi-env N] [--nphi-key N] [--refine N] [--split 0|1] [--far-from N]\n"
                "    [--far-dirs K] [--far-step G] [--context NAME] [--profile P]\n"
                "    [--data DIR] [--dx F] [--zscale F] [--vs-fp32]\n"
                "(the header of tests/test_gles_bench.c says what each does)\n");
}

/* V, one of NAMES ("a|b|c"), into *out; non-zero after the message. */
static int choice_arg(const char *a, const char *v, const char *names, const char **out)
{
    const size_t n = strlen(v);
    for (const char *p = names; *p;) {
        const size_t len = strcspn(p, "|");
        if (n && len == n && !strncmp(p, v, n)) {
            *out = v;
            return 0;
        }
        p += len + (p[len] == '|');
    }
    return hfs_usage_error(PROG, "%s: '%s' is not %s", a, v, names);
}

/* Flag A with value V; 1 when A takes no value or is unknown, 2 after a message. */
static int value_arg(bench_opts *o, const char *a, const char *v)
{
    const struct { const char *flag; int *field; long lo, hi; } ints[] = {
        {"--size", &o->n, 2, 16384},          {"--subsample", &o->sub, 1, 64},
        {"--frames", &o->frames, 1, 1000},    {"--k", &o->q.k, -1000000, 1000000},
        {"--offset", &o->q.offset, -1000000, 1000000},
        {"--nphi-env", &o->q.nphi_env, -1000000, 1000000},
        {"--nphi-key", &o->q.nphi_key, -1000000, 1000000},
        {"--refine", &o->q.refine, -1000000, 1000000}, {"--split", &o->q.split, 0, 1},
        {"--far-from", &o->q.far_from, -1000000, 1000000},
        {"--far-dirs", &o->q.far_dirs, -1000000, 1000000},
        {"--far-step", &o->q.far_step, -1000000, 1000000}};
    const struct { const char *flag; const char **field; const char *names; } strs[] = {
        {"--scene", &o->scene, NULL},     {"--context", &o->context, NULL},
        {"--profile", &o->profile, NULL}, {"--data", &o->data, NULL},
        {"--precision", &o->prec, "fp16|fp32"}, {"--path", &o->path, "legendre|tables|slice"},
        {"--lights", &o->lights, "env|key|both"}};
    for (size_t k = 0; k < sizeof ints / sizeof ints[0]; ++k) {
        if (strcmp(a, ints[k].flag))
            continue;
        long x = 0;
        if (!v || hfs_cli_long(v, ints[k].lo, ints[k].hi, &x))
            return v ? hfs_usage_error(PROG, "%s: '%s' is not a whole number in [%ld, %ld]", a, v,
                                       ints[k].lo, ints[k].hi)
                     : hfs_usage_error(PROG, "%s: missing value", a);
        *ints[k].field = (int)x;
        return 0;
    }
    for (size_t k = 0; k < sizeof strs / sizeof strs[0]; ++k)
        if (!strcmp(a, strs[k].flag)) {
            if (!v)
                return hfs_usage_error(PROG, "%s: missing value", a);
            if (strs[k].names)
                return choice_arg(a, v, strs[k].names, strs[k].field);
            *strs[k].field = v;
            return 0;
        }
    double *real = !strcmp(a, "--dx") ? &o->dx : !strcmp(a, "--zscale") ? &o->zscale : NULL;
    if (!real)
        return 1;
    if (!v)
        return hfs_usage_error(PROG, "%s: missing value", a);
    if (hfs_cli_real(v, 0.0, DBL_MAX, real) || !(*real > 0.0))
        return hfs_usage_error(PROG, "%s: '%s' is not a positive number", a, v);
    return 0;
}

/* 0, -1 after --help, HFS_EXIT_USAGE after a one-line message. */
static int parse_args(int argc, char **argv, bench_opts *o)
{
    *o = (bench_opts){"fractal25", "fp16", "legendre", "both", NULL, NULL, HFS_DATA_DIR,
                      256, 2, 5, 0, 0, 0, 0, 0, 0.0, 0.0, {0}};
    hfs_quality_defaults(&o->q);
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        int *flag = !strcmp(a, "--cold")      ? &o->cold
                    : !strcmp(a, "--count")   ? &o->count
                    : !strcmp(a, "--compare") ? &o->compare
                    : !strcmp(a, "--vs-fp32") ? &o->vs32
                    : !strcmp(a, "--finish")  ? &o->finish
                                              : NULL;
        if (hfs_is_help(a)) {
            usage(stdout);
            return -1;
        }
        if (flag) {
            *flag = 1;
            continue;
        }
        const int rc = value_arg(o, a, v);
        if (rc == 1)
            return hfs_usage_error(PROG, "%s: %s", a,
                                   a[0] == '-' ? "unknown option" : "unexpected argument");
        if (rc)
            return HFS_EXIT_USAGE;
        ++i;
    }
    return 0;
}

int main(int argc, char **argv)
{
    bench_opts o;
    const int parsed = parse_args(argc, argv, &o);
    if (parsed)
        return parsed < 0 ? 0 : parsed;
    const char *scene_name = o.scene, *prec = o.prec, *path = o.path, *lights = o.lights;
    const char *context = o.context, *profile = o.profile, *data = o.data;
    const int n = o.n, sub = o.sub, frames = o.frames, cold = o.cold, count = o.count;
    const int compare = o.compare, vs32 = o.vs32;
    const double dx = o.dx, zscale = o.zscale;
    hfs_quality q = o.q;
    q.precision = !strcmp(prec, "fp32") ? HFS_PRECISION_FP32 : HFS_PRECISION_FP16;
    q.visibility = !strcmp(path, "tables") ? HFS_VIS_WEDGE_TABLE
                 : !strcmp(path, "slice") ? HFS_VIS_SLICE : HFS_VIS_LEGENDRE;
    q.subsample = sub;
    scene s;
    if (scene_make(scene_name, n, data, &s))
        return 1;
    if (dx > 0.0)
        s.f.dx = dx;
    if (zscale > 0.0)
        s.f.zscale = zscale;
    hfs_lighting l = scene_lighting(strcmp(lights, "key") != 0, strcmp(lights, "env") != 0);

    hfs_renderer_desc d = {.backend = HFS_BACKEND_GLES, .context = context, .gl_profile = profile};
    hfs_renderer *r = NULL;
    hfs_error err;
    if (hfs_renderer_create(&d, &r, &err))
        gl_test_unavailable("gles_bench", &err);
    hfs_image img = {0};
    if (hfs_image_alloc(&img, s.f.width, s.f.height, &err))
        return 1;
    hfs_renderer_set_timing(r, 1);
    if (o.finish)
        hfs_renderer_set_timing_finish(r, 1);
    hfs_timings t;
    if (hfs_renderer_render(r, &s.f, &l, &q, &img, NULL, NULL, &err)) {
        fprintf(stderr, "gles_bench: %s\n", err.msg);
        return 1;
    }
    hfs_renderer_timings(r, &t);
    printf("device: %s; timing: %s\n", t.device, t.method);
    printf("scene %s %dx%d, %s, %s, subsample %d, lights %s, k %d offset %d, nphi %d/%d\n",
           scene_name, s.f.width, s.f.height, prec, path, sub, lights, q.k, q.offset, q.nphi_env,
           q.nphi_key);
    printf("first frame (compiles programs): %.1f ms wall\n", t.frame_ms);

    /* rows: the passes, then the sum, the wall, the process CPU and the
     * host's part (the wall less the passes, frame by frame) */
    double *ms = calloc((size_t)frames * (HFS_MAX_PASSES + 4), sizeof *ms);
    hfs_timings first = t;
    for (int f = 0; f < frames; ++f) {
        if (cold)
            hfs_renderer_invalidate(r);
        const double c0 = cpu_ms();
        if (hfs_renderer_render(r, &s.f, &l, &q, &img, NULL, NULL, &err)) {
            fprintf(stderr, "gles_bench: %s\n", err.msg);
            return 1;
        }
        ms[(size_t)(HFS_MAX_PASSES + 2) * frames + (size_t)f] = cpu_ms() - c0;
        hfs_renderer_timings(r, &t);
        for (int p = 0; p < t.n_passes && p < HFS_MAX_PASSES; ++p)
            ms[(size_t)p * frames + (size_t)f] = t.pass[p].ms;
        ms[(size_t)HFS_MAX_PASSES * frames + (size_t)f] = t.gpu_ms;
        ms[(size_t)(HFS_MAX_PASSES + 1) * frames + (size_t)f] = t.frame_ms;
        ms[(size_t)(HFS_MAX_PASSES + 3) * frames + (size_t)f] = t.frame_ms - t.gpu_ms;
    }
    printf("%s frames, %d:\n", cold ? "cold (cache invalidated)" : "warm (terrain cached)", frames);
    printf("  %-12s %9s %9s %14s %s\n", "pass", "median ms", "min ms", "fetches", "");
    for (int p = 0; p <= t.n_passes + 1; ++p) {
        const int row = p < t.n_passes ? p : HFS_MAX_PASSES + (p - t.n_passes);
        const double mn = minimum(ms + (size_t)row * frames, frames);
        const double md = median(ms + (size_t)row * frames, frames);
        if (p < t.n_passes)
            printf("  %-12s %9.2f %9.2f %14.0f %s\n", t.pass[p].name, md, mn, t.pass[p].fetches,
                   t.pass[p].cached ? "(cached)" : "");
        else if (p == t.n_passes)
            printf("  %-12s %9.2f %9.2f\n", "sum", md, mn);
        else
            printf("  %-12s %9.2f %9.2f   (%.1f frames/s median, %.1f best)\n", "frame wall", md,
                   mn, 1000.0 / md, 1000.0 / mn);
    }
    printf("  %-12s %9.2f %9.2f   (each frame's wall less its passes)\n", "host part",
           median(ms + (size_t)(HFS_MAX_PASSES + 3) * frames, frames),
           minimum(ms + (size_t)(HFS_MAX_PASSES + 3) * frames, frames));
    printf("  %-12s %9.2f %9.2f   (process CPU time, all threads)\n", "frame cpu",
           median(ms + (size_t)(HFS_MAX_PASSES + 2) * frames, frames),
           minimum(ms + (size_t)(HFS_MAX_PASSES + 2) * frames, frames));
    printf("  texture memory: %zu bytes (%.2f MiB)\n", t.texture_bytes,
           (double)t.texture_bytes / 1048576.0);
    (void)first;

    if (count) {
        hfs_renderer_set_timing(r, 2);
        hfs_renderer_invalidate(r);
        if (hfs_renderer_render(r, &s.f, &l, &q, &img, NULL, NULL, &err)) {
            fprintf(stderr, "gles_bench: %s\n", err.msg);
            return 1;
        }
        hfs_renderer_timings(r, &t);
        const int vw = (s.f.width - 1 + sub - 1) / sub + 1, vh = (s.f.height - 1 + sub - 1) / sub + 1;
        printf("counted fetches (receivers %dx%d):\n", vw, vh);
        double total = 0.0;
        for (int p = 0; p < t.n_passes; ++p) {
            total += t.pass[p].fetches > 0 ? t.pass[p].fetches : 0.0;
            printf("  %-12s %14.0f  (%.1f per receiver)\n", t.pass[p].name, t.pass[p].fetches,
                   t.pass[p].fetches / ((double)vw * vh));
        }
        printf("  %-12s %14.0f  -> %.1f ms at 125 M fetches/s\n", "total", total, total / 125e3);
        hfs_renderer_set_timing(r, 1);
    }

    if (compare) {
        hfs_renderer_desc dc = {.backend = HFS_BACKEND_CPU};
        hfs_renderer *rc = NULL;
        hfs_image ref = {0}, un = {0};
        hfs_metrics m;
        if (hfs_renderer_create(&dc, &rc, &err) || hfs_image_alloc(&ref, s.f.width, s.f.height, &err) ||
            hfs_image_alloc(&un, s.f.width, s.f.height, &err) ||
            hfs_renderer_render(rc, &s.f, &l, &q, &ref, NULL, NULL, &err) ||
            hfs_render_unshadowed(&s.f, &l, &q, &un, &err) ||
            hfs_compare_images(&img, &ref, hfs_image_max(&un), &m, &err)) {
            fprintf(stderr, "gles_bench: %s\n", err.msg);
            return 1;
        }
        printf("vs cpu: mean %.3e rmse %.3e p99 %.3e max %.3e nonfinite %ld\n", m.mean_abs, m.rmse,
               m.p99_abs, m.max_abs, m.nonfinite);
        hfs_image_free(&ref);
        hfs_image_free(&un);
        hfs_renderer_destroy(rc);
    }
    if (vs32) {
        hfs_quality q32 = q;
        q32.precision = HFS_PRECISION_FP32;
        hfs_image i32 = {0}, un = {0};
        hfs_metrics m;
        if (hfs_image_alloc(&i32, s.f.width, s.f.height, &err) ||
            hfs_image_alloc(&un, s.f.width, s.f.height, &err) ||
            hfs_renderer_render(r, &s.f, &l, &q32, &i32, NULL, NULL, &err) ||
            hfs_render_unshadowed(&s.f, &l, &q, &un, &err) ||
            hfs_compare_images(&img, &i32, hfs_image_max(&un), &m, &err)) {
            fprintf(stderr, "gles_bench: %s\n", err.msg);
            return 1;
        }
        hfs_gles_stats st;
        memset(&st, 0, sizeof st);
        printf("fp16 vs fp32 (gles): mean %.3e rmse %.3e p99 %.3e max %.3e nonfinite %ld\n",
               m.mean_abs, m.rmse, m.p99_abs, m.max_abs, m.nonfinite);
        hfs_image_free(&i32);
        hfs_image_free(&un);
    }
    free(ms);
    hfs_image_free(&img);
    hfs_renderer_destroy(r);
    scene_free(&s);
    return 0;
}
