/*
 * bench_env — timings and temporal stability of the environment map
 * decomposition (runtime/envmap/env_decompose.h; BENCHMARKS.md "Environment map
 * decomposition").
 *
 *   bench_env time W H [RUNS] [THREADS]   a synthetic sky (gradient + a
 *       0.5-degree sun holding 80% of the energy, tools/sky_gen.h) of W x H,
 *       decomposed RUNS times (default 9) from a fresh copy; prints the
 *       median, min and max milliseconds and the peak resident memory.
 *   bench_env file MAP [RUNS]             the same for a map file.
 *   bench_env gloss MAP S [RUNS]          the glossy table of a map file for
 *       Phong exponent S (runtime/core/env_gloss.h, issue 36), built RUNS
 *       times (default 9): median, min and max milliseconds.
 *   bench_env track [FRAMES]              a 256x128 probe sequence: the sun
 *       moving 0.25 degree a frame across a noisy gradient sky, beside a
 *       weak window whose share wanders about the 2% threshold; decomposed
 *       frame by frame without and with the tracker (hfs_env_track); prints
 *       the largest frame-to-frame jump of the sun light's direction and
 *       energy, the identity switches and the light count changes.
 */
#include "cli_usage.h"
#include "env_decompose.h"
#include "env_gloss.h"
#include "hfs_io.h"
#include "median.h"
#include "sh.h"
#include "sky_gen.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

static long peak_rss_mib(void)
{
    struct rusage u;
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss / 1024;
}

static int time_map(const float *map, int w, int h, int runs, int threads)
{
    const size_t n = (size_t)w * h * 3;
    float *work = malloc(n * sizeof *work);
    double *t = malloc((size_t)runs * sizeof *t);
    if (!work || !t) {
        fprintf(stderr, "bench_env: out of memory\n");
        return 1;
    }
    hfs_env_decompose_opts o;
    hfs_env_decompose_defaults(&o);
    o.threads = threads;
    hfs_env_decomp d;
    for (int r = 0; r < runs; ++r) {
        memcpy(work, map, n * sizeof *work);
        hfs_error err = {{0}};
        const double t0 = now_ms();
        if (hfs_env_decompose(work, w, h, &o, "map", &d, &err)) {
            fprintf(stderr, "bench_env: %s\n", err.msg);
            return 1;
        }
        t[r] = now_ms() - t0;
    }
    double lo = t[0], hi = t[0];
    for (int r = 1; r < runs; ++r)
        lo = fmin(lo, t[r]), hi = fmax(hi, t[r]);
    printf("%dx%d: %d lights, median %.2f ms (min %.2f, max %.2f, %d runs, threads %d), "
           "peak RSS %ld MiB\n", w, h, d.n_lights, hfs_median(t, runs), lo, hi, runs, threads,
           peak_rss_mib());
    for (int k = 0; k < d.n_lights; ++k)
        printf("  light %d: phi %.3f elev %.3f alpha %.3f deg, share %.4f\n", k,
               d.light[k].phi / DEG, d.light[k].elev / DEG, d.light[k].alpha / DEG,
               d.light[k].share);
    free(work);
    free(t);
    return 0;
}

static float *sun_sky(int w, int h, double phi, double elev, double noise, unsigned seed,
                      double sun_share, double window_share)
{
    hfs_sky_desc s;
    hfs_sky_defaults(&s, w, h);
    s.noise = noise;
    s.seed = seed;
    s.n_disks = window_share > 0.0 ? 2 : 1;
    s.disk[0] = (hfs_sky_disk){phi, elev, 0.25, {1.0f, 0.95f, 0.9f}};
    s.disk[1] = (hfs_sky_disk){300, 15, 4, {1.0f, 1.0f, 1.0f}};
    float *m = malloc((size_t)w * h * 3 * sizeof *m);
    double e[2][3];
    if (!m || hfs_sky_render(&s, m, e)) {
        free(m);
        return NULL;
    }
    hfs_sky_set_share(&s, 0, sun_share, m, e);
    if (window_share > 0.0)
        hfs_sky_set_share(&s, 1, window_share, m, e);
    return m;
}

typedef struct track_stats {
    double max_dir_jump, max_energy_jump;
    int id_switches, count_changes;
} track_stats;

/* The light nearest the sun's true direction: its index, or -1. */
static int sun_light(const hfs_env_decomp *d, double phi, double elev)
{
    int best = -1;
    double bc = cos(5.0 * DEG);
    for (int k = 0; k < d->n_lights; ++k) {
        const double c = cos(d->light[k].elev) * cos(elev) * cos(d->light[k].phi - phi) +
                         sin(d->light[k].elev) * sin(elev);
        if (c > bc)
            bc = c, best = k;
    }
    return best;
}

static void track_step(track_stats *s, const hfs_env_decomp *prev, const hfs_env_decomp *cur,
                       double phi, double elev, int tracked)
{
    const int a = sun_light(prev, phi, elev), b = sun_light(cur, phi, elev);
    if (prev->n_lights != cur->n_lights)
        s->count_changes++;
    if (a < 0 || b < 0) {
        s->id_switches++;
        return;
    }
    /* Identity: the tracker's id, or without it the light's index. */
    if (tracked ? prev->light[a].id != cur->light[b].id : a != b)
        s->id_switches++;
    const hfs_env_light *p = &prev->light[a], *q = &cur->light[b];
    const double c = cos(p->elev) * cos(q->elev) * cos(p->phi - q->phi) +
                     sin(p->elev) * sin(q->elev);
    s->max_dir_jump = fmax(s->max_dir_jump, acos(fmin(1.0, c)) / DEG);
    const double ep = p->energy[0] + p->energy[1] + p->energy[2];
    const double eq = q->energy[0] + q->energy[1] + q->energy[2];
    s->max_energy_jump = fmax(s->max_energy_jump, fabs(eq - ep) / ep);
}

static int track(int frames)
{
    const int w = 256, h = 128;
    for (int tracked = 0; tracked < 2; ++tracked) {
        hfs_env_tracker t;
        hfs_env_tracker_init(&t, NULL);
        if (getenv("BENCH_ENV_GAIN"))
            sscanf(getenv("BENCH_ENV_GAIN"), "%lf,%lf", &t.gain, &t.vel_gain);
        hfs_env_decomp prev = {0}, cur = {0}; /* prev read from the second frame on */
        track_stats s = {0, 0, 0, 0};
        double worst_ms = 0.0, *ms = malloc((size_t)frames * sizeof *ms);
        int nmin = 99, nmax = 0;
        if (!ms)
            return 1;
        for (int f = 0; f < frames; ++f) {
            const double phi = 100.0 + 0.25 * f, elev = 30.0 + 0.1 * f;
            const double window = 0.025 * (1.0 + 0.25 * sin(f * 0.7));
            float *m = sun_sky(w, h, phi, elev, 0.05, (unsigned)f + 1, 0.6, window);
            hfs_error err = {{0}};
            const double t0 = now_ms();
            const int rc = tracked ? hfs_env_track(&t, m, w, h, "frame", &cur, &err)
                                   : hfs_env_decompose(m, w, h, NULL, "frame", &cur, &err);
            ms[f] = now_ms() - t0;
            worst_ms = fmax(worst_ms, ms[f]);
            free(m);
            if (rc) {
                fprintf(stderr, "bench_env: %s\n", err.msg);
                return 1;
            }
            nmin = cur.n_lights < nmin ? cur.n_lights : nmin;
            nmax = cur.n_lights > nmax ? cur.n_lights : nmax;
            if (f > 0)
                track_step(&s, &prev, &cur, phi * DEG, elev * DEG, tracked);
            prev = cur;
        }
        printf("%s: %d frames 256x128, sun light: max direction jump %.3f deg, max energy "
               "jump %.2f%%, identity switches %d, light count changes %d (%d..%d "
               "lights), frame median %.2f ms, slowest %.2f ms\n",
               tracked ? "tracked" : "untracked", frames, s.max_dir_jump, 100.0 * s.max_energy_jump, s.id_switches,
               s.count_changes, nmin, nmax, hfs_median(ms, frames), worst_ms);
        free(ms);
    }
    return 0;
}

static void usage(FILE *to)
{
    fprintf(to, "usage: bench_env time W H [RUNS] [THREADS] | file MAP [RUNS] | gloss MAP S "
                "[RUNS] | track [FRAMES]\n");
}

/* argv[i] as a whole number in [lo, hi], DEF when absent; -1 after the message. */
static int count_arg(int argc, char **argv, int i, const char *what, int lo, int hi, int def,
                     int *out)
{
    *out = def;
    if (i >= argc)
        return 0;
    long x;
    if (hfs_cli_long(argv[i], lo, hi, &x)) {
        hfs_usage_error("bench_env", "%s %s: '%s' is not a whole number in [%d, %d]", argv[1],
                        what, argv[i], lo, hi);
        return -1;
    }
    *out = (int)x;
    return 0;
}

static int time_synthetic(int argc, char **argv)
{
    int w, h, runs, threads;
    if (argc < 4)
        return hfs_usage_error("bench_env", "time: needs W H");
    if (count_arg(argc, argv, 2, "W", 1, 16384, 0, &w) ||
        count_arg(argc, argv, 3, "H", 1, 16384, 0, &h) ||
        count_arg(argc, argv, 4, "RUNS", 1, 100000, 9, &runs) ||
        count_arg(argc, argv, 5, "THREADS", 0, 1024, 0, &threads))
        return HFS_EXIT_USAGE;
    float *m = sun_sky(w, h, 135, 35, 0.0, 1, 0.8, 0.0);
    if (!m) {
        fprintf(stderr, "bench_env: out of memory for %dx%d\n", w, h);
        return 1;
    }
    const int rc = time_map(m, w, h, runs, threads);
    free(m);
    return rc;
}

static int time_file(int argc, char **argv)
{
    int runs;
    if (argc < 3)
        return hfs_usage_error("bench_env", "file: needs MAP");
    if (count_arg(argc, argv, 3, "RUNS", 1, 100000, 9, &runs))
        return HFS_EXIT_USAGE;
    hfs_envmap em;
    hfs_error err = {{0}};
    if (hfs_envmap_load(argv[2], &em, &err)) {
        fprintf(stderr, "bench_env: %s\n", err.msg);
        return 1;
    }
    const int rc = time_map(em.rgb, em.width, em.height, runs, 0);
    hfs_envmap_free(&em);
    return rc;
}

/* bench_env gloss MAP S [RUNS]: hfs_env_gloss_build's time. */
static int time_gloss(int argc, char **argv)
{
    int s, runs;
    if (argc < 4)
        return hfs_usage_error("bench_env", "gloss: needs MAP S");
    if (count_arg(argc, argv, 3, "S", 1, 10000, 32, &s) ||
        count_arg(argc, argv, 4, "RUNS", 1, 100000, 9, &runs))
        return HFS_EXIT_USAGE;
    hfs_envmap em;
    hfs_error err = {{0}};
    float *table = malloc(HFS_ENV_GLOSS_FLOATS * sizeof *table);
    double *t = malloc((size_t)runs * sizeof *t);
    if (!table || !t || hfs_envmap_load(argv[2], &em, &err)) {
        fprintf(stderr, "bench_env: %s\n", table && t ? err.msg : "out of memory");
        free(table), free(t);
        return 1;
    }
    double sh[3][HFS_SH_COEFFS];
    hfs_sh_project_equirect(em.rgb, em.width, em.height, sh);
    int rc = 0;
    for (int r = 0; r < runs && !rc; ++r) {
        const double t0 = now_ms();
        rc = hfs_env_gloss_build(em.rgb, em.width, em.height, (const double(*)[HFS_SH_COEFFS])sh,
                                 s, table, &err);
        t[r] = now_ms() - t0;
    }
    if (rc)
        fprintf(stderr, "bench_env: %s\n", err.msg);
    else {
        double lo = t[0], hi = t[0];
        for (int r = 1; r < runs; ++r)
            lo = fmin(lo, t[r]), hi = fmax(hi, t[r]);
        printf("%dx%d, S %d: the glossy table in median %.2f ms (min %.2f, max %.2f, %d runs), "
               "largest |D_g| %.4g\n", em.width, em.height, s, hfs_median(t, runs), lo, hi, runs,
               hfs_env_gloss_max(table));
    }
    hfs_envmap_free(&em);
    free(table), free(t);
    return rc ? 1 : 0;
}

int main(int argc, char **argv)
{
    if (argc < 2)
        return hfs_usage_error("bench_env", "no mode given (time, file or track)");
    const char *m = argv[1];
    if (hfs_is_help(m)) {
        usage(stdout);
        return 0;
    }
    const int most = !strcmp(m, "time")    ? 6
                     : !strcmp(m, "file")  ? 4
                     : !strcmp(m, "gloss") ? 5
                     : !strcmp(m, "track") ? 3
                                           : 0;
    if (!most)
        return hfs_usage_error("bench_env", "'%s' is not a mode (time, file, gloss or track)", m);
    if (argc > most)
        return hfs_usage_error("bench_env", "%s: %s: unexpected argument", m, argv[most]);
    if (!strcmp(m, "time"))
        return time_synthetic(argc, argv);
    if (!strcmp(m, "file"))
        return time_file(argc, argv);
    if (!strcmp(m, "gloss"))
        return time_gloss(argc, argv);
    int frames;
    if (count_arg(argc, argv, 2, "FRAMES", 2, 1000000, 200, &frames))
        return HFS_EXIT_USAGE;
    return track(frames);
}
