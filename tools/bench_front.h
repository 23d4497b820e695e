/*
 * bench_front.h — what hfbench makes of its measurements: the Pareto front
 * of error against time per scene, the same over all scenes together (a
 * setting's worst time and worst error over the scenes), the settings picked
 * from that front for each use, and the outputs (CSV, gnuplot plots).
 *
 * Uses (each a rule over the all-scenes front, GLES fp16 settings only:
 * the uses run the product, and fp32 is outside its profile; budgets are
 * options):
 *   kiosk     the fastest setting that meets the kiosk's accuracy target
 *             (worst mean error <= kiosk_err, worst p99 <= kiosk_p99;
 *             defaults 0.01 and 0.10, issue 15's bounds for the product
 *             defaults under sky + sun) within the kiosk budget (default
 *             100 ms: 10 frames/s while the terrain changes; light-only
 *             frames cost far less); where none meets the target, the most
 *             accurate setting within the budget.  Not restricted to the
 *             front: the target's p99 can exclude a setting that dominates
 *             on time and mean;
 *   panel     the most accurate setting within the panel budget (default
 *             500 ms: a preview looked at closely, updated on demand);
 *   headless  the fastest setting whose worst mean error is at most the
 *             headless bound (default 0.03 of the unshadowed maximum).
 * Against timing noise: a budget counts with BENCH_TIME_MARGIN of headroom
 * (a pick 2% under its budget would flip from run to run), and settings
 * within BENCH_TIE of the best candidate's error (panel, kiosk without a
 * target) or time (kiosk, headless) tie: the faster (panel) or more
 * accurate (kiosk, headless) of them is picked.
 */
#ifndef HFS_BENCH_FRONT_H
#define HFS_BENCH_FRONT_H

#include "bench_sweep.h"

#include <stddef.h>

typedef struct bench_result {
    int scene, point;        /* indices into the run's scenes and points */
    int ok;                  /* 0: the point failed (message in note)    */
    double frame_ms, gpu_ms; /* medians over the timed frames            */
    double pyramid_ms, env_ms, key_ms, local_ms, shade_ms;
    size_t texture_bytes;
    double mean_abs, rmse, p99_abs, max_abs;
    long nonfinite;
    int pareto;              /* on its scene's front                     */
    char note[160];
} bench_result;

#define BENCH_TIME_MARGIN 0.9 /* a frame fits a budget B if it takes <= 0.9 B */
#define BENCH_TIE 0.05         /* relative: errors or times this close tie */

typedef struct bench_budget {
    double kiosk_ms, panel_ms, headless_err;
    double kiosk_err, kiosk_p99; /* the kiosk's accuracy target (0: none) */
} bench_budget;

enum { USE_KIOSK, USE_PANEL, USE_HEADLESS, USE_COUNT };

typedef struct bench_picks {
    int point[USE_COUNT];    /* -1: no setting meets the rule            */
    double worst_ms[USE_COUNT], worst_mean[USE_COUNT], worst_p99[USE_COUNT];
    int *front;              /* per point: on the all-scenes front (GLES
                                settings measured on every scene)        */
} bench_picks;

extern const char *const bench_use_names[USE_COUNT];

/* Marks results[i].pareto per scene (on frame_ms, mean_abs). */
void bench_mark_fronts(bench_result *res, int n_res, int n_scenes);

/* The all-scenes front and the picks; picks->front allocated (free it). */
int bench_pick(const bench_result *res, int n_res, int n_scenes, const bench_point *pts,
               int n_points, const bench_budget *b, bench_picks *picks);

/* CSV, one row per result (header first). */
int bench_write_csv(const char *path, const bench_result *res, int n_res,
                    const char *const *scene_names, const char *lights, int size,
                    const bench_point *pts, const bench_picks *picks, hfs_error *err);

/* One plot per scene, DIR/<scene>.png and .svg, through gnuplot. */
int bench_plot(const char *dir, const bench_result *res, int n_res,
               const char *const *scene_names, int n_scenes, const char *lights, int size,
               const bench_point *pts, const bench_picks *picks, hfs_error *err);

#endif /* HFS_BENCH_FRONT_H */
