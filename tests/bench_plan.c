/*
 * bench_plan.c — what the frame planner saves on realistic sequences
 * (issue 6): each sequence is rendered twice in one run, by a renderer that
 * plans (keeps what an edit did not invalidate) and by one made to
 * recompute everything each frame (hfs_renderer_invalidate), alternating
 * frame by frame so that both see the same machine load.  Prints a Markdown
 * row per sequence: median frame time with and without the planner, their
 * ratio, and the passes the planned frames ran.
 *
 *   bench_plan [--frames N] [--size N] [--only NAME] [--passes 1]
 *              [--visibility legendre|wedge|slice] [--env-map FILE]
 *              (defaults 30, 512, 0, legendre, none)
 * --passes 1 also prints, per sequence, where a planned frame's time goes:
 * the median time of each pass it ran (timing level 1 by glFinish + clock,
 * hfs_renderer_set_timing_finish: llvmpipe's timer queries miss deferred
 * work; waiting for each pass makes that run's frames a little longer).
 *
 * Sequences (N frames each, after one warm-up frame):
 *   env-rotate   a knob turning the environment at 60 Hz (6 degrees a frame)
 *                over a still fractal terrain, sky + a key light;
 *   key-sweep    a key light sweeping across the sky (3 degrees a frame in
 *                azimuth, elevation rising), sky present;
 *   local-move   one of four local lights moving over a panel (size/2);
 *   terrain      an animated height field: a bump moving over the terrain
 *                every frame (dynamic terrain), sky + key light;
 *   lights-sweep two key lights sweeping and two local lights moving over
 *                still terrain, every frame (sky present): four visibility
 *                passes stale each frame;
 *   key-dim      env-rotate's terrain and key light without the sky, the
 *                key light dimming every frame: the planned frame is the
 *                shading pass and readback without the environment's part
 *                (beside env-rotate, what that part costs);
 *   envmap-rotate (with --env-map FILE) env-rotate with the map shaded
 *                from the map itself (env-shade = map: its open-sky table
 *                and, on the slice path, the map's occlusion pass) instead
 *                of the SH sky.
 * A third renderer amortizes (hfs_renderer_set_amortize 1: one visibility
 * pass a frame, NS09 section 7) and is timed alongside; its column is its
 * median frame time (its frames lag the edits by up to K - 1 frames, K the
 * visibility passes an edit makes stale).
 * No GLES context of any kind: exit 77 (gl_test.h).
 */
#include "env_open.h"
#include "hfs_io.h"
#include "hfshade.h"
#include "sh.h"
#include "terrain_gen.h"
#include "median.h"
#include "gl_test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define PI 3.14159265358979323846

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}


typedef struct seq {
    const char *name;
    int n;               /* field side */
    float *z, *z0;
    hfs_field f;
    hfs_lighting l;
    hfs_quality q;
    float open[HFS_ENV_OPEN_FLOATS]; /* envmap-rotate: the map's open sky */
} seq;

/* --env-map: the map envmap-rotate shades from. */
static hfs_envmap env_map;

/* The map as the scene layer lights it with env-shade = map. */
static int map_sky(seq *s)
{
    hfs_lighting *l = &s->l;
    hfs_error err = {""};
    l->has_env = 1;
    hfs_sh_project_equirect(env_map.rgb, env_map.width, env_map.height, l->env_sh);
    if (hfs_env_open_build(env_map.rgb, env_map.width, env_map.height,
                           (const double(*)[HFS_SH_COEFFS])l->env_sh, s->open, &err)) {
        fprintf(stderr, "bench_plan: %s\n", err.msg);
        return -1;
    }
    l->env_map = l->env_shade_map = env_map.rgb;
    l->env_map_width = env_map.width, l->env_map_height = env_map.height;
    l->env_open = s->open;
    return 0;
}

static void sky(hfs_lighting *l)
{
    l->has_env = 1;
    for (int c = 0; c < 3; ++c) {
        l->env_sh[c][0] = 2.5 - 0.2 * c;
        l->env_sh[c][2] = 1.0;  /* brighter to +z */
        l->env_sh[c][3] = 0.4;  /* and to +x: rotation shows */
        l->env_sh[c][8] = 0.2;
    }
}

/* --visibility: the path every sequence renders with. */
static hfs_visibility_path vis_path = HFS_VIS_LEGENDRE;

static int setup(seq *s, const char *name, int n)
{
    memset(s, 0, sizeof *s);
    s->name = name;
    s->n = n;
    s->z = malloc((size_t)n * n * sizeof *s->z);
    s->z0 = malloc((size_t)n * n * sizeof *s->z0);
    if (!s->z || !s->z0)
        return -1;
    hfs_lighting_defaults(&s->l);
    s->l.albedo = 0.8;
    hfs_quality_defaults(&s->q);
    s->q.visibility = vis_path;
    if (!strcmp(name, "local-move")) {
        hfs_terrain_panel(s->z, n, n);
        const double f = n / 128.0;
        const double set[4][4] = {{48, 48, 7, 1.5}, {80, 20, 6, 1}, {20, 80, 9, 2}, {100, 100, 8, 1}};
        s->l.n_local = 4;
        for (int i = 0; i < 4; ++i)
            s->l.local[i] = (hfs_local_light){.pos = {set[i][0] * f, set[i][1] * f, set[i][2] * f},
                                              .radius = set[i][3] * f,
                                              .radiance = {40, 40, 40}};
    } else {
        if (hfs_terrain_fractal(s->z, n, n, 1, 0.25))
            return -1;
        if (!strcmp(name, "envmap-rotate")) {
            if (map_sky(s))
                return -1;
        } else if (strcmp(name, "key-dim")) {
            sky(&s->l);
        }
        s->l.n_key = 1;
        s->l.key[0] = (hfs_key_light){.phi = 5.86, .elev = 0.26, .alpha = 0.035,
                                      .radiance = {150, 140, 125}};
        if (!strcmp(name, "lights-sweep")) {
            s->l.n_key = 2;
            s->l.key[1] = (hfs_key_light){.phi = 2.0, .elev = 0.5, .alpha = 0.05,
                                          .radiance = {60, 60, 70}};
            s->l.n_local = 2;
            for (int i = 0; i < 2; ++i)
                s->l.local[i] = (hfs_local_light){.pos = {n * (0.3 + 0.4 * i), n * 0.5, n * 0.1},
                                                  .radius = n / 64.0,
                                                  .radiance = {400, 380, 350}};
        }
    }
    memcpy(s->z0, s->z, (size_t)n * n * sizeof *s->z);
    s->f = (hfs_field){.width = n, .height = n, .z = s->z, .dx = 1.0, .zscale = 1.0};
    return 0;
}

/* Frame t's edit. */
static void edit(seq *s, int t)
{
    if (!strcmp(s->name, "env-rotate") || !strcmp(s->name, "envmap-rotate")) {
        s->l.env_rotate = fmod(t * 6.0, 360.0) * PI / 180.0;
    } else if (!strcmp(s->name, "key-sweep")) {
        s->l.key[0].phi = fmod(0.5 + t * 3.0 * PI / 180.0, 2 * PI);
        s->l.key[0].elev = 0.15 + 0.01 * t;
    } else if (!strcmp(s->name, "key-dim")) {
        for (int c = 0; c < 3; ++c)
            s->l.key[0].radiance[c] = (float)(150.0 - 2.0 * t);
    } else if (!strcmp(s->name, "lights-sweep")) {
        s->l.key[0].phi = fmod(0.5 + t * 3.0 * PI / 180.0, 2 * PI);
        s->l.key[1].phi = fmod(2.0 - t * 2.0 * PI / 180.0 + 2 * PI, 2 * PI);
        s->l.local[0].pos[0] = s->n * (0.3 + 0.005 * t);
        s->l.local[1].pos[1] = s->n * (0.5 - 0.004 * t);
    } else if (!strcmp(s->name, "local-move")) {
        const double f = s->n / 128.0;
        s->l.local[0].pos[0] = (30 + 2.0 * t) * f;
        s->l.local[0].pos[1] = (40 + 1.0 * t) * f;
    } else { /* terrain: a bump moving along the diagonal */
        memcpy(s->z, s->z0, (size_t)s->n * s->n * sizeof *s->z);
        const int n = s->n, cx = (t * 7) % n, cy = (t * 5) % n, r = n / 16;
        for (int j = cy - r; j <= cy + r; ++j)
            for (int i = cx - r; i <= cx + r; ++i)
                if (i >= 0 && j >= 0 && i < n && j < n) {
                    const double d = hypot(i - cx, j - cy) / r;
                    if (d < 1)
                        s->z[(size_t)j * n + i] += (float)(0.3 * r * (1 - d * d));
                }
    }
}

int main(int argc, char **argv)
{
    static const char *const paths[] = {"legendre", "wedge", "slice"};
    hfs_error err = {""};
    int frames = 30, size = 512, passes_too = 0;
    const char *only = NULL;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!strcmp(argv[i], "--frames"))
            frames = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--size"))
            size = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--only"))
            only = argv[i + 1];
        else if (!strcmp(argv[i], "--passes"))
            passes_too = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--env-map") && hfs_envmap_load(argv[i + 1], &env_map, &err)) {
            fprintf(stderr, "bench_plan: %s\n", err.msg);
            return 2;
        }
        else if (!strcmp(argv[i], "--visibility")) {
            vis_path = 0;
            for (int p = 0; p < 3; ++p)
                if (!strcmp(argv[i + 1], paths[p]))
                    vis_path = p == 0 ? HFS_VIS_LEGENDRE
                                      : p == 1 ? HFS_VIS_WEDGE_TABLE : HFS_VIS_SLICE;
        }
    }
    if (!vis_path) {
        fprintf(stderr, "bench_plan: --visibility is legendre, wedge or slice\n");
        return 2;
    }
    if (frames < 1 || size < 16 || size > 2048) {
        fprintf(stderr, "usage: bench_plan [--frames N >= 1] [--size 16..2048] [--only NAME] "
                        "[--passes 0|1]\n");
        return 2;
    }
    hfs_renderer *planned = gl_test_gles(), *full = gl_test_gles(), *amort = gl_test_gles();
    if (passes_too) {
        hfs_renderer_set_timing(planned, 1);
        hfs_renderer_set_timing_finish(planned, 1);
    }
    hfs_renderer_set_amortize(amort, 1);
    static const char *const names[] = {"env-rotate", "key-sweep", "local-move", "terrain",
                                        "lights-sweep", "key-dim", "envmap-rotate"};
    printf("| sequence | field | frames | planned ms (median) | full ms (median) | full / "
           "planned | amortized ms (median) | passes run per planned frame (total over the "
           "frames) |\n");
    printf("|---|---|---|---|---|---|---|---|\n");
    int rc = 0;
    for (size_t k = 0; k < sizeof names / sizeof names[0] && !rc; ++k) {
        if ((only && strcmp(only, names[k])) || (!env_map.rgb && !strcmp(names[k], "envmap-rotate")))
            continue;
        seq s;
        const int n = !strcmp(names[k], "local-move") ? size / 2 : size;
        if (setup(&s, names[k], n)) {
            rc = 1;
            break;
        }
        hfs_image img = {0};
        double *tp = calloc((size_t)frames, sizeof *tp), *tf = calloc((size_t)frames, sizeof *tf);
        double *ta = calloc((size_t)frames, sizeof *ta);
        char passes[16][24] = {{0}};
        int counts[16] = {0}, np = 0;
        /* Per-pass GPU times of the planned frames (--passes), by name. */
        char tnames[HFS_MAX_PASSES][16] = {{0}};
        double *tms = calloc((size_t)frames * HFS_MAX_PASSES, sizeof *tms);
        int ntn = 0;
        if (!tp || !tf || !ta || hfs_image_alloc(&img, n, n, &err)) {
            rc = 1;
        } else {
            for (int t = -1; t < frames && !rc; ++t) {
                edit(&s, t + 1);
                double t0 = now_ms();
                rc |= hfs_renderer_render(planned, &s.f, &s.l, &s.q, &img, NULL, NULL, &err);
                const double t1 = now_ms();
                hfs_renderer_invalidate(full);
                rc |= hfs_renderer_render(full, &s.f, &s.l, &s.q, &img, NULL, NULL, &err);
                const double t2 = now_ms();
                rc |= hfs_renderer_render(amort, &s.f, &s.l, &s.q, &img, NULL, NULL, &err);
                const double t3 = now_ms();
                if (t < 0)
                    continue; /* warm-up: programs compiled, caches filled */
                tp[t] = t1 - t0;
                tf[t] = t2 - t1;
                ta[t] = t3 - t2;
                if (passes_too) {
                    hfs_timings tm;
                    hfs_renderer_timings(planned, &tm);
                    for (int i = 0; i < tm.n_passes && tms; ++i) {
                        if (tm.pass[i].cached)
                            continue;
                        int j = 0;
                        while (j < ntn && strcmp(tnames[j], tm.pass[i].name))
                            ++j;
                        if (j == ntn && ntn < HFS_MAX_PASSES)
                            snprintf(tnames[ntn++], sizeof tnames[0], "%s", tm.pass[i].name);
                        if (j < HFS_MAX_PASSES)
                            tms[(size_t)j * frames + t] = tm.pass[i].ms;
                    }
                }
                hfs_frame_report rep;
                hfs_renderer_frame_report(planned, &rep);
                for (int i = 0; i < rep.n_steps; ++i) {
                    if (!rep.step[i].ran)
                        continue;
                    int j = 0;
                    while (j < np && strcmp(passes[j], rep.step[i].pass))
                        ++j;
                    if (j == np && np < 16)
                        snprintf(passes[np++], sizeof passes[0], "%s", rep.step[i].pass);
                    if (j < 16)
                        ++counts[j];
                }
            }
            if (rc) {
                fprintf(stderr, "bench_plan: %s: %s\n", names[k], err.msg);
                break;
            }
            const double mp = hfs_median(tp, frames), mf = hfs_median(tf, frames);
            char ran[256] = "";
            for (int j = 0; j < np; ++j) {
                char one[48];
                snprintf(one, sizeof one, "%s%s %d", j ? ", " : "", passes[j], counts[j]);
                strncat(ran, one, sizeof ran - strlen(ran) - 1);
            }
            printf("| %s | %dx%d | %d | %.2f | %.2f | %.1fx | %.2f | %s |\n", names[k], n, n,
                   frames, mp, mf, mf / mp, hfs_median(ta, frames), np ? ran : "none");
            for (int j = 0; j < ntn && tms; ++j)
                printf("    %s: planned frames' %s pass, median %.2f ms\n", names[k], tnames[j],
                       hfs_median(tms + (size_t)j * frames, frames));
            fflush(stdout);
        }
        hfs_image_free(&img);
        free(tms);
        free(ta);
        free(tp);
        free(tf);
        free(s.z);
        free(s.z0);
    }
    hfs_renderer_destroy(planned);
    hfs_renderer_destroy(full);
    hfs_renderer_destroy(amort);
    hfs_envmap_free(&env_map);
    return rc ? 1 : 0;
}
