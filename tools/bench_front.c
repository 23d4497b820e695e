/*
 * bench_front.c — see bench_front.h.
 */
#include "bench_front.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>

const char *const bench_use_names[USE_COUNT] = {"kiosk", "panel", "headless"};

/* a dominates b: no worse in both, better in one. */
static int dominates(double ta, double ea, double tb, double eb)
{
    return ta <= tb && ea <= eb && (ta < tb || ea < eb);
}

void bench_mark_fronts(bench_result *res, int n_res, int n_scenes)
{
    for (int s = 0; s < n_scenes; ++s)
        for (int i = 0; i < n_res; ++i) {
            bench_result *a = &res[i];
            if (a->scene != s)
                continue;
            a->pareto = a->ok;
            for (int j = 0; j < n_res && a->pareto; ++j) {
                const bench_result *b = &res[j];
                if (j != i && b->ok && b->scene == s &&
                    dominates(b->frame_ms, b->mean_abs, a->frame_ms, a->mean_abs))
                    a->pareto = 0;
            }
        }
}

/* The fastest of the candidates (cand[p]), 5% ties going to the more
 * accurate; -1 if there is none. */
static int fastest_of(const int *cand, int n_points, const double *t, const double *e)
{
    double fastest = HUGE_VAL;
    for (int p = 0; p < n_points; ++p)
        if (cand[p] && t[p] < fastest)
            fastest = t[p];
    int pick = -1;
    for (int p = 0; p < n_points; ++p)
        if (cand[p] && t[p] <= fastest * (1.0 + BENCH_TIE) && (pick < 0 || e[p] < e[pick]))
            pick = p;
    return pick;
}

/* The kiosk's: the fastest setting the product can run (ok[p]) that meets
 * the accuracy target within the budget; -1 if none does. */
static int kiosk_target(const int *ok, int n_points, const double *t, const double *e,
                        const double *p99, const bench_budget *b, int *cand)
{
    if (!(b->kiosk_err > 0.0) || !(b->kiosk_p99 > 0.0))
        return -1;
    for (int p = 0; p < n_points; ++p)
        cand[p] = ok[p] && t[p] <= b->kiosk_ms * BENCH_TIME_MARGIN && e[p] <= b->kiosk_err &&
                  p99[p] <= b->kiosk_p99;
    return fastest_of(cand, n_points, t, e);
}

/* The rules of bench_front.h, made robust to timing noise (shared machines
 * vary +-10% run to run; errors do not vary): a budget counts with a
 * BENCH_TIME_MARGIN of headroom, and between settings whose error (panel,
 * kiosk without a target) or time (kiosk, headless) is within BENCH_TIE of
 * the best candidate's, the faster (panel) or the more accurate (kiosk,
 * headless) wins.  cand: scratch for n_points flags. */
static void pick_uses(bench_picks *picks, int n_points, const double *t, const double *e,
                      const double *p99, const int *ok, const bench_budget *b, int *cand)
{
    const double lim[2] = {b->kiosk_ms * BENCH_TIME_MARGIN, b->panel_ms * BENCH_TIME_MARGIN};
    for (int u = 0; u < USE_COUNT; ++u)
        picks->point[u] = -1;
    picks->point[USE_KIOSK] = kiosk_target(ok, n_points, t, e, p99, b, cand);
    for (int u = USE_KIOSK; u <= USE_PANEL; ++u) {
        if (picks->point[u] >= 0)
            continue;
        double best = HUGE_VAL;
        for (int p = 0; p < n_points; ++p)
            if (picks->front[p] && t[p] <= lim[u] && e[p] < best)
                best = e[p];
        for (int p = 0; p < n_points; ++p)
            if (picks->front[p] && t[p] <= lim[u] && e[p] <= best * (1.0 + BENCH_TIE) &&
                (picks->point[u] < 0 || t[p] < t[picks->point[u]]))
                picks->point[u] = p;
    }
    for (int p = 0; p < n_points; ++p)
        cand[p] = picks->front[p] && e[p] <= b->headless_err;
    picks->point[USE_HEADLESS] = fastest_of(cand, n_points, t, e);
}

/* A setting the product can run: GLES, and not fp32 (EXT_color_buffer_float
 * is outside the product's profile: the sweep measures fp32 for comparison
 * only; with the same error it can still time a few % faster by noise and
 * win a tie). */
static int product(const bench_point *pt)
{
    return pt->backend != HFS_BACKEND_CPU && pt->q.precision != HFS_PRECISION_FP32;
}

int bench_pick(const bench_result *res, int n_res, int n_scenes, const bench_point *pts,
               int n_points, const bench_budget *b, bench_picks *picks)
{
    memset(picks, 0, sizeof *picks);
    double *t = calloc((size_t)n_points, sizeof *t), *e = calloc((size_t)n_points, sizeof *e);
    double *p99 = calloc((size_t)n_points, sizeof *p99);
    int *seen = calloc((size_t)n_points, sizeof *seen);
    int *ok = calloc((size_t)n_points, sizeof *ok), *cand = calloc((size_t)n_points, sizeof *cand);
    picks->front = calloc((size_t)n_points, sizeof *picks->front);
    if (!t || !e || !p99 || !seen || !ok || !cand || !picks->front) {
        free(t), free(e), free(p99), free(seen), free(ok), free(cand), free(picks->front);
        picks->front = NULL;
        return HFS_E_NOMEM;
    }
    /* A setting's worst case over the scenes; it counts only if it ran on
     * every scene. */
    for (int i = 0; i < n_res; ++i) {
        const bench_result *r = &res[i];
        if (!r->ok)
            continue;
        seen[r->point]++;
        t[r->point] = fmax(t[r->point], r->frame_ms);
        e[r->point] = fmax(e[r->point], r->mean_abs);
        p99[r->point] = fmax(p99[r->point], r->p99_abs);
    }
    for (int p = 0; p < n_points; ++p)
        ok[p] = seen[p] == n_scenes && product(&pts[p]);
    for (int p = 0; p < n_points; ++p) {
        picks->front[p] = ok[p];
        for (int q = 0; q < n_points && picks->front[p]; ++q)
            if (q != p && ok[q] && dominates(t[q], e[q], t[p], e[p]))
                picks->front[p] = 0;
    }
    pick_uses(picks, n_points, t, e, p99, ok, b, cand);
    for (int u = 0; u < USE_COUNT; ++u)
        if (picks->point[u] >= 0) {
            picks->worst_ms[u] = t[picks->point[u]];
            picks->worst_mean[u] = e[picks->point[u]];
            picks->worst_p99[u] = p99[picks->point[u]];
        }
    free(t), free(e), free(p99), free(seen), free(ok), free(cand);
    return HFS_OK;
}

static const char *uses_of(const bench_picks *picks, int point, char *buf, size_t cap)
{
    buf[0] = '\0';
    for (int u = 0; u < USE_COUNT; ++u)
        if (picks->point[u] == point) {
            const size_t n = strlen(buf);
            snprintf(buf + n, cap - n, "%s%s", n ? "+" : "", bench_use_names[u]);
        }
    return buf;
}

int bench_write_csv(const char *path, const bench_result *res, int n_res,
                    const char *const *scene_names, const char *lights, int size,
                    const bench_point *pts, const bench_picks *picks, hfs_error *err)
{
    char tmp[4200];
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    FILE *f = fopen(tmp, "w");
    if (!f)
        return hfs_fail(err, HFS_E_IO, "%s: cannot write: %s", path, strerror(errno));
    fprintf(f, "scene,size,lights,backend,k,offset,nphi_env,nphi_key,nphi_local,local_swath,"
               "subsample,precision,visibility,frame_ms,gpu_ms,pyramid_ms,env_ms,key_ms,"
               "local_ms,shade_ms,texture_bytes,mean_abs,rmse,p99_abs,max_abs,nonfinite,"
               "default,pareto,all_scenes_front,use,note,setting\n");
    for (int i = 0; i < n_res; ++i) {
        const bench_result *r = &res[i];
        const bench_point *p = &pts[r->point];
        const hfs_quality *q = &p->q;
        char uses[64];
        fprintf(f, "%s,%d,%s,%s,%d,%d,%d,%d,%d,%s,%d,%s,%s,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,"
                   "%zu,%.4e,%.4e,%.4e,%.4e,%ld,%d,%d,%d,%s,%s,%s\n",
                scene_names[r->scene], size, lights,
                p->backend == HFS_BACKEND_CPU ? "cpu" : "gles", q->k, q->offset, q->nphi_env,
                q->nphi_key, q->nphi_local, q->local_full_swath ? "full" : "partial",
                q->subsample, q->precision == HFS_PRECISION_FP32 ? "fp32" : "fp16",
                q->visibility == HFS_VIS_WEDGE_TABLE ? "wedge"
                : q->visibility == HFS_VIS_SLICE   ? "slice"
                                                   : "legendre",
                r->frame_ms,
                r->gpu_ms, r->pyramid_ms, r->env_ms, r->key_ms, r->local_ms, r->shade_ms,
                r->texture_bytes, r->mean_abs, r->rmse, r->p99_abs, r->max_abs, r->nonfinite,
                p->is_default, r->pareto, picks->front ? picks->front[r->point] : 0,
                uses_of(picks, r->point, uses, sizeof uses), r->ok ? "" : r->note, p->label);
    }
    const int bad = ferror(f);
    if (fclose(f) != 0 || bad || rename(tmp, path) != 0) {
        remove(tmp);
        return hfs_fail(err, HFS_E_IO, "%s: write failed: %s", path, strerror(errno));
    }
    return HFS_OK;
}

/* gnuplot: all settings grey, the scene's front as a line, the defaults as
 * a ring, the picks labelled; log-log (time ms, mean abs error). */
static int plot_scene(const char *dir, const char *scene, int s, const bench_result *res,
                      int n_res, const char *lights, int size, const bench_point *pts,
                      const bench_picks *picks, hfs_error *err)
{
    char dat[4200];
    snprintf(dat, sizeof dat, "%s/%s.dat", dir, scene);
    FILE *f = fopen(dat, "w");
    if (!f)
        return hfs_fail(err, HFS_E_IO, "%s: cannot write: %s", dat, strerror(errno));
    /* Blocks (gnuplot "index"), written only when not empty (gnuplot 5.4
     * crashes on a labels block of NaN): all settings, the front in time
     * order, the defaults, the picks with their use as a label. */
    int block = 0, idx[4] = {-1, -1, -1, -1}, n = 0;
    for (int i = 0; i < n_res; ++i)
        if (res[i].scene == s && res[i].ok) {
            fprintf(f, "%.4f %.6e\n", res[i].frame_ms, res[i].mean_abs);
            ++n;
        }
    if (n) {
        fprintf(f, "\n\n");
        idx[0] = block++;
    }
    n = 0;
    for (int last = -1;;) { /* the front in time order, without sorting a copy */
        int next = -1;
        for (int i = 0; i < n_res; ++i)
            if (res[i].scene == s && res[i].pareto &&
                (last < 0 || res[i].frame_ms > res[last].frame_ms ||
                 (res[i].frame_ms == res[last].frame_ms && i > last)) &&
                (next < 0 || res[i].frame_ms < res[next].frame_ms))
                next = i;
        if (next < 0)
            break;
        fprintf(f, "%.4f %.6e\n", res[next].frame_ms, res[next].mean_abs);
        last = next;
        ++n;
    }
    if (n) {
        fprintf(f, "\n\n");
        idx[1] = block++;
    }
    n = 0;
    for (int i = 0; i < n_res; ++i)
        if (res[i].scene == s && res[i].ok && pts[res[i].point].is_default) {
            fprintf(f, "%.4f %.6e\n", res[i].frame_ms, res[i].mean_abs);
            ++n;
        }
    if (n) {
        fprintf(f, "\n\n");
        idx[2] = block++;
    }
    n = 0;
    for (int i = 0; i < n_res; ++i) {
        char uses[64];
        if (res[i].scene == s && res[i].ok && *uses_of(picks, res[i].point, uses, sizeof uses)) {
            fprintf(f, "%.4f %.6e \"%s\"\n", res[i].frame_ms, res[i].mean_abs, uses);
            ++n;
        }
    }
    if (n)
        idx[3] = block++;
    fclose(f);
    if (idx[0] < 0)
        return HFS_OK; /* nothing measured on this scene */

    FILE *gp = popen("gnuplot", "w");
    if (!gp)
        return hfs_fail(err, HFS_E_IO, "gnuplot: cannot run: %s", strerror(errno));
    for (int t = 0; t < 2; ++t) {
        fprintf(gp, t == 0 ? "set terminal pngcairo size 800,560 font ',10'\n"
                           : "set terminal svg size 800,560 font 'sans,10'\n");
        fprintf(gp, "set output '%s/%s.%s'\n", dir, scene, t == 0 ? "png" : "svg");
        fprintf(gp, "set title '%s %dx%d, %s: mean abs error vs full-frame time' noenhanced\n"
                    "set xlabel 'frame time, ms (median)'\nset ylabel 'mean abs error / "
                    "unshadowed max'\nset logscale xy\nset grid\nset key top right\n",
                scene, size, size, lights);
        fprintf(gp, "plot '%s' index %d using 1:2 with points pt 7 ps 0.6 lc rgb '#b0b0b0' "
                    "title 'settings'", dat, idx[0]);
        if (idx[1] >= 0)
            fprintf(gp, ", '' index %d using 1:2 with linespoints pt 7 ps 0.8 lw 2 "
                        "lc rgb '#1f77b4' title 'Pareto front'", idx[1]);
        if (idx[2] >= 0)
            fprintf(gp, ", '' index %d using 1:2 with points pt 6 ps 2.5 lw 2 lc rgb '#d62728' "
                        "title 'library defaults'", idx[2]);
        if (idx[3] >= 0)
            fprintf(gp, ", '' index %d using 1:2:3 with labels offset 0,1.2 font ',9' "
                        "tc rgb '#2ca02c' notitle, '' index %d using 1:2 with points pt 5 ps 1.2 "
                        "lc rgb '#2ca02c' title 'picked per use'", idx[3], idx[3]);
        fprintf(gp, "\nunset output\n");
    }
    const int rc = pclose(gp);
    if (rc != 0 && WIFEXITED(rc) && WEXITSTATUS(rc) == 127)
        return hfs_fail(err, HFS_E_IO, "--plots: gnuplot is not installed (apt install "
                        "gnuplot-nox)");
    if (rc != 0)
        return hfs_fail(err, HFS_E_IO, "gnuplot failed (status %d) on %s", rc, dat);
    return HFS_OK;
}

int bench_plot(const char *dir, const bench_result *res, int n_res,
               const char *const *scene_names, int n_scenes, const char *lights, int size,
               const bench_point *pts, const bench_picks *picks, hfs_error *err)
{
    if (mkdir(dir, 0777) != 0 && errno != EEXIST)
        return hfs_fail(err, HFS_E_IO, "%s: cannot create: %s", dir, strerror(errno));
    for (int s = 0; s < n_scenes; ++s) {
        int rc = plot_scene(dir, scene_names[s], s, res, n_res, lights, size, pts, picks, err);
        if (rc)
            return rc;
    }
    return HFS_OK;
}
