/*
 * hfbench — run time against error (issue 5): sweeps quality settings over
 * scenes, and for each (scene, setting) measures the median full-frame time
 * (GPU passes and total), texture memory, and SPEC's four error metrics
 * against the ground truth (cached on disk by scene hash, bench_truth.h).
 * Writes a CSV, optional plots (error against time per scene with the
 * Pareto front, the library's defaults and the settings picked per use,
 * through gnuplot), and prints the picks (bench_front.h says how each use
 * picks from the all-scenes front).
 *
 *   hfbench -o OUT.csv [--plots DIR] [--scenes cones,fractal,dem] [--size 256]
 *           [--lights sky+sun|sky|sun|local] [--bounces B] [--grid "key=v1,v2 ..."]...
 *           [--frames 3] [--cache DIR] [--data DIR] [--truth-samples 1024]
 *           [--truth-env map|sh] [--kiosk-ms 100] [--kiosk-err 0.01] [--kiosk-p99 0.1] [--panel-ms 500]
 *           [--headless-err 0.03] [--quiet]
 *
 * Without --grid the default sweep (DEFAULT_GRIDS below) is measured.  A
 * frame is a full frame: the renderer's caches are invalidated before each,
 * so every pass runs; one warm-up frame (whose image is the one compared)
 * precedes the timed ones.  A progress bar goes to a terminal's stderr.
 * --truth-env: the truth of the environment map's SH projection, the
 * renderers' input (default: the front measures each setting's own error,
 * and the presets come from it), or of the map itself (what a render loses
 * against the sky, projection included; the scene key truth-env).
 */
#include "bench_front.h"
#include "bench_scene.h"
#include "bench_sweep.h"
#include "bench_truth.h"
#include "cli_usage.h"
#include "median.h"
#include "scene_keys.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifndef HFS_DATA_DIR
#define HFS_DATA_DIR "data"
#endif

#define MAX_SCENES 16

/* The default sweep: the settings that move time and error most, on a grid
 * around the library's defaults (the exact slice path: its error falls
 * with finer horizons, k and offset, and hardly with more environment
 * directions, BENCHMARKS.md "Exact slice lighting"; offsets up to 8, where
 * every scale within 256 texels reads the input itself and a 256^2 field
 * needs no pyramid passes), plus the precision and the seeds' Legendre and
 * wedge-table paths at the defaults, and k = 3 on its own grid. */
static const char *const DEFAULT_GRIDS[] = {
    "k=2,4,8 offset=3,5,8 nphi-env=12,16,32 nphi-key=3,5 subsample=1,2,4",
    "precision=fp32", "visibility=wedge", "visibility=legendre",
    "k=3 offset=5,6,8 nphi-env=12,16 nphi-key=3,5 subsample=1,2", NULL};

typedef struct options {
    const char *out_csv, *plots, *lights, *cache, *data;
    char scenes[MAX_SCENES][32];
    int n_scenes, size, frames, truth_samples, quiet;
    int bounces;             /* --bounces: every scene's (and its truth's) */
    int truth_env_sh;        /* --truth-env sh (default): the truth of the map's SH */
    const char *grids[32];
    int n_grids;
    bench_budget budget;
} options;

static void usage(FILE *to)
{
    fprintf(to,
            "usage: hfbench -o OUT.csv [--plots DIR] [--scenes a,b,c] [--size N] [--lights "
            "sky+sun|sky|sun|local] [--bounces B]\n"
            "               [--grid \"key=v1,v2 ...\"]... [--frames N] [--cache DIR] [--data DIR]\n"
            "               [--truth-samples N] [--truth-env map|sh] [--kiosk-ms MS] [--kiosk-err E] [--kiosk-p99 E]\n"
            "               [--panel-ms MS] [--headless-err E] [--quiet]\n");
}

/* The budget a flag sets (bench_front.h bench_budget), or NULL. */
static double *budget_field(bench_budget *b, const char *flag)
{
    const struct {
        const char *flag;
        double *field;
    } t[] = {{"--kiosk-ms", &b->kiosk_ms},     {"--kiosk-err", &b->kiosk_err},
             {"--kiosk-p99", &b->kiosk_p99},   {"--panel-ms", &b->panel_ms},
             {"--headless-err", &b->headless_err}};
    for (size_t i = 0; i < sizeof t / sizeof t[0]; ++i)
        if (!strcmp(flag, t[i].flag))
            return t[i].field;
    return NULL;
}

static int parse_number(const char *flag, const char *v, double lo, double hi, double *out)
{
    if (hfs_cli_real(v, lo, hi, out)) {
        hfs_usage_error("hfbench", "%s: '%s' is not a number in [%g, %g]", flag, v, lo, hi);
        return -1;
    }
    return 0;
}

/* 1 if A is a flag that takes a value. */
static int is_flag(const char *a)
{
    static const char *const flags[] = {"-o",      "--plots",  "--scenes",    "--lights",
                                        "--cache", "--data",   "--grid",      "--size",
                                        "--bounces", "--frames", "--truth-env", "--truth-samples"};
    for (size_t k = 0; k < sizeof flags / sizeof flags[0]; ++k)
        if (!strcmp(a, flags[k]))
            return 1;
    bench_budget b;
    return budget_field(&b, a) != NULL;
}

/* The whole-number option A and its range, or NULL. */
static int *int_flag(options *o, const char *a, double *lo, double *hi)
{
    /* --bounces, --truth-samples: the scene key's range */
    const hfs_key_range *b = &hfs_scene_key_number(HFS_SK_BOUNCES, 0)->range;
    const hfs_key_range *t = &hfs_scene_key_number(HFS_SK_TRUTH_SAMPLES, 0)->range;
    const struct {
        const char *flag;
        int *field;
        double lo, hi;
    } f[] = {{"--size", &o->size, 2, 16384},
             {"--frames", &o->frames, 1, 1000},
             {"--bounces", &o->bounces, b->lo, b->hi},
             {"--truth-samples", &o->truth_samples, t->lo, t->hi}};
    for (size_t k = 0; k < sizeof f / sizeof f[0]; ++k)
        if (!strcmp(a, f[k].flag)) {
            *lo = f[k].lo, *hi = f[k].hi;
            return f[k].field;
        }
    return NULL;
}

/* Flag A with value V; non-zero after a one-line message. */
static int parse_value(options *o, const char *a, const char *v, const char **scenes)
{
    double x = 0.0, lo, hi;
    int *n;
    if (!strcmp(a, "-o"))
        o->out_csv = v;
    else if (!strcmp(a, "--plots"))
        o->plots = v;
    else if (!strcmp(a, "--scenes"))
        *scenes = v;
    else if (!strcmp(a, "--cache"))
        o->cache = v;
    else if (!strcmp(a, "--data"))
        o->data = v;
    else if (!strcmp(a, "--lights")) {
        if (strcmp(v, "sky+sun") && strcmp(v, "sky") && strcmp(v, "sun") && strcmp(v, "local"))
            return hfs_usage_error("hfbench", "--lights: '%s' is not sky+sun, sky, sun or local",
                                   v);
        o->lights = v;
    } else if (!strcmp(a, "--grid")) {
        if (o->n_grids == 31)
            return hfs_usage_error("hfbench", "--grid: at most 31");
        o->grids[o->n_grids++] = v;
    } else if (!strcmp(a, "--truth-env")) {
        if (strcmp(v, "map") && strcmp(v, "sh"))
            return hfs_usage_error("hfbench", "--truth-env: '%s' is not map or sh", v);
        o->truth_env_sh = !strcmp(v, "sh");
    } else if ((n = int_flag(o, a, &lo, &hi))) {
        if (parse_number(a, v, lo, hi, &x))
            return -1;
        *n = (int)x;
    } else if (budget_field(&o->budget, a)) {
        return parse_number(a, v, 0, 1e9, budget_field(&o->budget, a));
    } else {
        return hfs_usage_error("hfbench", "%s: unknown option", a);
    }
    return 0;
}

/* --scenes into o->scenes; -1 after a one-line message. */
static int split_scenes(options *o, const char *scenes)
{
    char buf[1024];
    snprintf(buf, sizeof buf, "%s", scenes);
    char *save = NULL;
    for (char *t = strtok_r(buf, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        if (o->n_scenes == MAX_SCENES || strlen(t) >= sizeof o->scenes[0]) {
            hfs_usage_error("hfbench", "--scenes: too many or too long names");
            return -1;
        }
        snprintf(o->scenes[o->n_scenes++], sizeof o->scenes[0], "%s", t);
    }
    if (!o->n_scenes) {
        hfs_usage_error("hfbench", "--scenes: '%s' names no scene", scenes);
        return -1;
    }
    return 0;
}

static int parse_args(int argc, char **argv, options *o)
{
    memset(o, 0, sizeof *o);
    o->lights = "sky+sun";
    o->cache = "bench-cache";
    o->data = HFS_DATA_DIR;
    o->size = 256;
    o->frames = 3;
    o->truth_samples = 1024;
    o->truth_env_sh = 1; /* the front measures the renderers against their own input */
    o->budget = (bench_budget){.kiosk_ms = 100.0, .panel_ms = 500.0, .headless_err = 0.03,
                               .kiosk_err = 0.01, .kiosk_p99 = 0.10};
    const char *scenes = "cones,fractal,dem";
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        if (!strcmp(a, "--quiet")) {
            o->quiet = 1;
        } else if (hfs_is_help(a)) {
            usage(stdout);
            exit(0);
        } else if (a[0] != '-') {
            hfs_usage_error("hfbench", "%s: unexpected argument", a);
            return -1;
        } else if (!is_flag(a)) {
            hfs_usage_error("hfbench", "%s: unknown option", a);
            return -1;
        } else if (i + 1 >= argc) {
            hfs_usage_error("hfbench", "%s: missing value", a);
            return -1;
        } else if (parse_value(o, a, argv[++i], &scenes)) {
            return -1;
        }
    }
    if (!o->out_csv) {
        hfs_usage_error("hfbench", "no output file (-o OUT.csv)");
        return -1;
    }
    if (split_scenes(o, scenes))
        return -1;
    if (!o->n_grids)
        for (int g = 0; DEFAULT_GRIDS[g]; ++g)
            o->grids[o->n_grids++] = DEFAULT_GRIDS[g];
    return 0;
}

static void progress(const options *o, int done, int total, const char *what)
{
    if (o->quiet || !isatty(STDERR_FILENO))
        return;
    const int width = 30, fill = total ? done * width / total : width;
    fprintf(stderr, "\r%4d/%d [%.*s%.*s] %-60.60s", done, total, fill,
            "##############################", width - fill, "..............................",
            what);
    if (done == total)
        fputc('\n', stderr);
    fflush(stderr);
}


enum { T_FRAME, T_GPU, T_PYRAMID, T_ENV, T_KEY, T_LOCAL, T_SHADE, T_COUNT };

/* Warm-up frame into img, then `frames` full frames; medians into r. */
static int measure(hfs_renderer *rd, const bench_scene *sc, const hfs_quality *q, int frames,
                   hfs_image *img, bench_result *r, hfs_error *err)
{
    double *v = calloc((size_t)T_COUNT * frames, sizeof *v);
    if (!v)
        return hfs_fail(err, HFS_E_NOMEM, "out of memory");
    int rc = hfs_renderer_set_timing(rd, 1);
    for (int f = -1; f < frames && !rc; ++f) {
        hfs_renderer_invalidate(rd);
        rc = hfs_renderer_render(rd, &sc->field, &sc->lighting, q, img, NULL, NULL, err);
        if (rc || f < 0)
            continue;
        hfs_timings t;
        hfs_renderer_timings(rd, &t);
        double *row = v + (size_t)f;
        row[T_FRAME * frames] = t.frame_ms;
        row[T_GPU * frames] = t.gpu_ms;
        for (int p = 0; p < t.n_passes; ++p) {
            const char *n = t.pass[p].name;
            const double ms = t.pass[p].ms > 0.0 ? t.pass[p].ms : 0.0;
            if (!strcmp(n, "decimate") || !strcmp(n, "reconstruct"))
                row[T_PYRAMID * frames] += ms;
            else if (!strcmp(n, "env"))
                row[T_ENV * frames] += ms;
            else if (!strcmp(n, "key"))
                row[T_KEY * frames] += ms;
            else if (!strcmp(n, "local"))
                row[T_LOCAL * frames] += ms;
            else if (!strcmp(n, "transfer") || !strcmp(n, "keyfactor") || !strcmp(n, "shade"))
                row[T_SHADE * frames] += ms; /* the full-resolution passes */
        }
        r->texture_bytes = t.texture_bytes;
    }
    if (!rc) {
        r->frame_ms = hfs_median(v + (size_t)T_FRAME * frames, frames);
        r->gpu_ms = hfs_median(v + (size_t)T_GPU * frames, frames);
        r->pyramid_ms = hfs_median(v + (size_t)T_PYRAMID * frames, frames);
        r->env_ms = hfs_median(v + (size_t)T_ENV * frames, frames);
        r->key_ms = hfs_median(v + (size_t)T_KEY * frames, frames);
        r->local_ms = hfs_median(v + (size_t)T_LOCAL * frames, frames);
        r->shade_ms = hfs_median(v + (size_t)T_SHADE * frames, frames);
    }
    free(v);
    return rc;
}

typedef struct run {
    options o;
    bench_sweep sweep;
    bench_scene scenes[MAX_SCENES];
    hfs_image truth[MAX_SCENES];
    double norm[MAX_SCENES];
    hfs_renderer *gles, *cpu;
    bench_result *res;
    int n_res;
} run;

static int prepare_scene(run *R, int s, hfs_error *err)
{
    const options *o = &R->o;
    int rc = bench_scene_make(o->scenes[s], o->size, o->lights, o->data, &R->scenes[s], err);
    if (rc)
        return rc;
    R->scenes[s].lighting.bounces = o->bounces; /* the truth's too: error against their sum */
    const bench_scene *sc = &R->scenes[s];
    hfs_quality tq;
    hfs_quality_defaults(&tq);
    tq.truth_light_samples = o->truth_samples;
    char what[96];
    snprintf(what, sizeof what, "%s: ground truth", sc->name);
    progress(o, 0, R->sweep.n * o->n_scenes, what);
    int cached = 0;
    double secs = 0.0;
    hfs_lighting tl = sc->lighting;
    if (o->truth_env_sh)
        tl.env_map = NULL; /* the truth of env_sh */
    if ((rc = bench_truth_get(o->cache, &sc->field, &tl, &tq, &R->truth[s], &cached, &secs,
                              err)))
        return rc;
    if (!o->quiet)
        fprintf(stderr, "%s%s %dx%d %s: truth %s (%.1f s)\n",
                isatty(STDERR_FILENO) ? "\r" : "", sc->name, o->size, o->size, o->lights,
                cached ? "from the cache" : "rendered", secs);
    hfs_image un = {0};
    if ((rc = hfs_image_alloc(&un, o->size, o->size, err)) ||
        (rc = hfs_render_unshadowed(&sc->field, &sc->lighting, &tq, &un, err))) {
        hfs_image_free(&un);
        return rc;
    }
    R->norm[s] = hfs_image_max(&un);
    hfs_image_free(&un);
    return HFS_OK;
}

static hfs_renderer *renderer_for(run *R, hfs_backend b, hfs_error *err)
{
    hfs_renderer **slot = b == HFS_BACKEND_CPU ? &R->cpu : &R->gles;
    if (!*slot) {
        hfs_renderer_desc d = {.backend = b};
        if (hfs_renderer_create(&d, slot, err))
            return NULL;
    }
    return *slot;
}

static void measure_all(run *R)
{
    const options *o = &R->o;
    const int total = R->sweep.n * o->n_scenes;
    hfs_image img = {0};
    for (int s = 0; s < o->n_scenes; ++s)
        for (int p = 0; p < R->sweep.n; ++p) {
            const bench_point *pt = &R->sweep.pts[p];
            bench_result *r = &R->res[R->n_res++];
            memset(r, 0, sizeof *r);
            r->scene = s;
            r->point = p;
            char what[256];
            snprintf(what, sizeof what, "%s %s", o->scenes[s], pt->label);
            progress(o, R->n_res - 1, total, what);
            hfs_error err = {{0}};
            hfs_renderer *rd = renderer_for(R, pt->backend, &err);
            int rc = rd ? HFS_OK : HFS_E_CONTEXT;
            if (!rc && !img.rgb)
                rc = hfs_image_alloc(&img, o->size, o->size, &err);
            if (!rc)
                rc = measure(rd, &R->scenes[s], &pt->q, o->frames, &img, r, &err);
            hfs_metrics m;
            if (!rc)
                rc = hfs_compare_images(&img, &R->truth[s], R->norm[s], &m, &err);
            if (rc) {
                snprintf(r->note, sizeof r->note, "%.159s", err.msg);
                for (char *c = r->note; *c; ++c)
                    *c = *c == ',' || *c == '\n' ? ';' : *c;
                if (!o->quiet)
                    fprintf(stderr, "\n%s: %s\n", what, err.msg);
                continue;
            }
            r->ok = 1;
            r->mean_abs = m.mean_abs;
            r->rmse = m.rmse;
            r->p99_abs = m.p99_abs;
            r->max_abs = m.max_abs;
            r->nonfinite = m.nonfinite;
        }
    progress(o, total, total, "done");
    hfs_image_free(&img);
}

static void print_summary(const run *R, const bench_picks *pk)
{
    const options *o = &R->o;
    printf("| use | rule | setting | worst frame ms | worst mean abs | worst p99 abs |\n");
    printf("|---|---|---|---|---|---|\n");
    /* bench_front.h: the budgets with their margin, ties within BENCH_TIE. */
    const char *rules[USE_COUNT] = {"most accurate (5%% ties: faster), frame <= %g ms",
                                    "most accurate (5%% ties: faster), frame <= %g ms",
                                    "fastest (5%% ties: more accurate), mean <= %g"};
    const double lim[USE_COUNT] = {o->budget.kiosk_ms * BENCH_TIME_MARGIN,
                                   o->budget.panel_ms * BENCH_TIME_MARGIN, o->budget.headless_err};
    for (int u = 0; u < USE_COUNT; ++u) {
        char rule[160];
        if (u == USE_KIOSK && o->budget.kiosk_err > 0.0 && o->budget.kiosk_p99 > 0.0)
            snprintf(rule, sizeof rule, "fastest (5%% ties: more accurate) with mean <= %g and "
                     "p99 <= %g, frame <= %g ms (none: most accurate)", o->budget.kiosk_err,
                     o->budget.kiosk_p99, lim[u]);
        else
            snprintf(rule, sizeof rule, rules[u], lim[u]);
        if (pk->point[u] < 0)
            printf("| %s | %s | (none meets the rule) | | | |\n", bench_use_names[u], rule);
        else
            printf("| %s | %s | %s | %.1f | %.3e | %.3e |\n", bench_use_names[u], rule,
                   R->sweep.pts[pk->point[u]].label, pk->worst_ms[u], pk->worst_mean[u],
                   pk->worst_p99[u]);
    }
    printf("\n| scene | setting | frame ms | GPU ms | texture MiB | mean abs | RMSE | p99 abs | "
           "max abs | front |\n|---|---|---|---|---|---|---|---|---|---|\n");
    for (int i = 0; i < R->n_res; ++i) {
        const bench_result *r = &R->res[i];
        const bench_point *p = &R->sweep.pts[r->point];
        int picked = 0;
        for (int u = 0; u < USE_COUNT; ++u)
            picked |= pk->point[u] == r->point;
        if (!r->ok || !(p->is_default || picked))
            continue;
        printf("| %s | %s%s | %.1f | %.1f | %.2f | %.3e | %.3e | %.3e | %.3e | %s |\n",
               o->scenes[r->scene], p->label, p->is_default ? " (defaults)" : "", r->frame_ms,
               r->gpu_ms, r->texture_bytes / 1048576.0, r->mean_abs, r->rmse, r->p99_abs,
               r->max_abs, r->pareto ? "yes" : "no");
    }
}

int main(int argc, char **argv)
{
    run R;
    memset(&R, 0, sizeof R);
    if (parse_args(argc, argv, &R.o))
        return HFS_EXIT_USAGE;
    const options *o = &R.o;
    hfs_error err = {{0}};
    int rc = HFS_OK;
    for (int g = 0; g < o->n_grids && !rc; ++g)
        rc = bench_sweep_add_grid(&R.sweep, o->grids[g], &err);
    for (int s = 0; s < o->n_scenes && !rc; ++s)
        rc = prepare_scene(&R, s, &err);
    if (!rc && !(R.res = calloc((size_t)R.sweep.n * o->n_scenes, sizeof *R.res)))
        rc = hfs_fail(&err, HFS_E_NOMEM, "out of memory");
    bench_picks pk = {0};
    if (!rc) {
        if (!o->quiet)
            fprintf(stderr, "%d settings x %d scenes, %d timed frames each\n", R.sweep.n,
                    o->n_scenes, o->frames);
        measure_all(&R);
        bench_mark_fronts(R.res, R.n_res, o->n_scenes);
        if (bench_pick(R.res, R.n_res, o->n_scenes, R.sweep.pts, R.sweep.n, &o->budget, &pk))
            rc = hfs_fail(&err, HFS_E_NOMEM, "out of memory");
    }
    const char *names[MAX_SCENES];
    for (int s = 0; s < o->n_scenes; ++s)
        names[s] = o->scenes[s];
    char lights[48]; /* "sky+sun", "sky+sun+1b" with one bounce */
    snprintf(lights, sizeof lights, o->bounces ? "%s+%db" : "%s", o->lights, o->bounces);
    if (!rc)
        rc = bench_write_csv(o->out_csv, R.res, R.n_res, names, lights, o->size,
                             R.sweep.pts, &pk, &err);
    if (!rc && o->plots)
        rc = bench_plot(o->plots, R.res, R.n_res, names, o->n_scenes, lights, o->size,
                        R.sweep.pts, &pk, &err);
    if (!rc)
        print_summary(&R, &pk);
    int failed = 0;
    for (int i = 0; i < R.n_res; ++i)
        failed += !R.res[i].ok;
    free(pk.front);
    free(R.res);
    hfs_renderer_destroy(R.gles);
    hfs_renderer_destroy(R.cpu);
    for (int s = 0; s < MAX_SCENES; ++s) {
        bench_scene_free(&R.scenes[s]);
        hfs_image_free(&R.truth[s]);
    }
    bench_sweep_free(&R.sweep);
    if (rc) {
        fprintf(stderr, "hfbench: %s\n", err.msg);
        return 1;
    }
    if (failed)
        fprintf(stderr, "hfbench: %d of %d points failed (see the CSV's note column)\n", failed,
                R.n_res);
    return failed ? 1 : 0;
}
