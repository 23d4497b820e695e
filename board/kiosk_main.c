/*
 * kiosk_main.c — hfshade-kiosk: the board's program.  Renders a scene,
 * shows it on a display (kms on the board, x11 on a desk, headless for
 * tests and measurements) and lets knobs and buttons move the lights
 * (board/KIOSK.md).
 *
 * Start-up order, and why:
 *   1. block SIGHUP/SIGTERM/SIGINT and open the signalfd FIRST: the
 *      renderer's GL driver starts worker threads, which inherit the mask;
 *      a thread without it would take SIGTERM's default action (death
 *      without restoring the screen);
 *   2. load and check every input file (scene, configuration, replay) before
 *      touching a device, so a typo fails fast with one line and the screen
 *      is never grabbed for nothing;
 *   3. input devices, display, renderer; the first frame;
 *   4. the replay clock starts after the first frame, so scripted times are
 *      relative to a kiosk that is ready (latency runs then measure frames,
 *      not start-up).
 * Exit: 0 after SIGTERM/SIGINT, a close request or the end of a replay
 * (--exit-after-replay); 1 on an error (one line naming the input); 2 on a
 * usage error.  Teardown always closes the display (kms restores the CRTC).
 */
#define _GNU_SOURCE /* signalfd */
#ifdef HFS_HAVE_GDAL
#include "height_gdal.h"
#endif
#include "kiosk.h"

#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/signalfd.h>
#include <unistd.h>

#include "cli_usage.h"
#include "input_replay.h"

#define PROG "hfshade-kiosk"


static void usage(FILE *f)
{
    fprintf(f,
            "usage: hfshade-kiosk SCENE.ini [options]\n"
            "  --input CONFIG.ini    knobs and buttons (board/kiosk.ini); default: none\n"
            "  --replay EVENTS.txt   scripted input events (docs/INPUT.md \"Replay files\"),\n"
            "                        timed from the first frame\n"
            "  --display NAME        %s (default kms)\n"
            "  --size WxH            x11 window / headless canvas size (default: the field's)\n"
            "  --out PATTERN.png     headless: write each frame, e.g. frame-%%04d.png\n"
            "  --exposure auto|EV    exposure of the picture: auto (default; the lit terrain's\n"
            "                        median at middle grey, smoothed over 0.5 s) or stops\n"
            "                        (0 = radiance x 1), as hfshade render --exposure\n"
            "  --overlay             start with the frame-time overlay shown\n"
            "  --view                start in the 3-D view (a view.toggle button switches;\n"
            "                        camera.* knobs turn it; its size is --size or 800x480)\n"
            "  --no-devices          do not open the configured devices (replay, demos)\n"
            "  --exit-after-replay   exit 0 once the last replayed event is shown\n"
            "  --stats FILE          per frame and per input event: times, latency, CPU\n"
            "  --amortize N          at most N visibility passes a frame while the terrain\n"
            "                        is still; the rest follow in the next frames (NS09 7,\n"
            "                        docs/DESIGN.md \"Frame planner\"); default 0 = off\n"
            "  --capture-record DIR  write the capture's raw frames and times to DIR\n"
            "                        (docs/CAPTURE.md \"Recordings\")\n"
            "  --exit-after-capture  exit 0 once a replayed capture's last frame is shown\n"
            "  --readback            x11/kms: read each frame back and upload it, as before\n"
            "                        issue 20 (for comparison; default: the renderer shares\n"
            "                        the display's context and hands it a texture)\n"
            "  --check               load and check every input file, open nothing, exit\n"
            "  --help\n"
            "signals: SIGHUP reloads SCENE.ini and CONFIG.ini; SIGTERM/SIGINT exit cleanly\n",
            hfs_display_names());
}

/* 0: run; -1: --help was printed; HFS_EXIT_USAGE: a one-line error was. */
static int parse_args(kiosk_opts *o, int argc, char **argv)
{
    memset(o, 0, sizeof *o);
    o->display = "kms";
    o->exposure = 0.0; /* auto */
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        if (a[0] != '-') {
            if (o->scene_path)
                return hfs_usage_error(PROG, "%s: a second scene file", a);
            o->scene_path = a;
            continue;
        }
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage(stdout);
            return -1;
        }
        /* An option given twice is an error: the last one silently
         * winning hides a typo in a unit file. */
        for (int j = 1; j < i; ++j)
            if (!strcmp(argv[j], a))
                return hfs_usage_error(PROG, "%s: given twice (once is allowed)", a);
        int *flag = !strcmp(a, "--overlay")             ? &o->overlay
                    : !strcmp(a, "--view")              ? &o->view
                    : !strcmp(a, "--no-devices")        ? &o->no_devices
                    : !strcmp(a, "--exit-after-replay") ? &o->exit_after_replay
                    : !strcmp(a, "--check")             ? &o->check
                    : !strcmp(a, "--exit-after-capture") ? &o->exit_after_capture
                    : !strcmp(a, "--readback")          ? &o->readback
                                                        : NULL;
        if (flag) {
            *flag = 1;
            continue;
        }
        const char **val = !strcmp(a, "--input")     ? &o->input_path
                           : !strcmp(a, "--replay")  ? &o->replay_path
                           : !strcmp(a, "--display") ? &o->display
                           : !strcmp(a, "--out")     ? &o->out_pattern
                           : !strcmp(a, "--stats")   ? &o->stats_path
                           : !strcmp(a, "--capture-record") ? &o->capture_record
                                                     : NULL;
        const int numeric =
            !strcmp(a, "--size") || !strcmp(a, "--exposure") || !strcmp(a, "--amortize");
        if (!val && !numeric)
            return hfs_usage_error(PROG, "%s: unknown option", a);
        if (i + 1 >= argc)
            return hfs_usage_error(PROG, "%s: missing value", a);
        const char *v = argv[++i];
        if (val) {
            *val = v;
        } else if (!strcmp(a, "--amortize")) {
            char *end;
            const long n = strtol(v, &end, 10);
            if (end == v || *end || n < 0 || n > 64)
                return hfs_usage_error(PROG, "--amortize: '%s' is not a pass count 0..64", v);
            o->amortize = (int)n;
        } else if (!strcmp(a, "--size")) {
            char tail;
            if (sscanf(v, "%dx%d%c", &o->width, &o->height, &tail) != 2 || o->width < 1 ||
                o->height < 1 || o->width > 16384 || o->height > 16384)
                return hfs_usage_error(PROG, "--size: '%s' is not WxH (1..16384)", v);
        } else {
            char *end;
            const double ev = strcmp(v, "auto") ? strtod(v, &end) : 0.0;
            if (strcmp(v, "auto") && (end == v || *end || !(fabs(ev) <= 40.0)))
                return hfs_usage_error(PROG, "--exposure: '%s' is not auto or stops (EV) in "
                                       "[-40, 40]", v);
            o->exposure = strcmp(v, "auto") ? exp2(ev) : 0.0;
        }
    }
    if (!o->scene_path)
        return hfs_usage_error(PROG, "no scene file");
    if (o->exit_after_replay && !o->replay_path)
        return hfs_usage_error(PROG, "--exit-after-replay needs --replay");
    if (o->out_pattern && strcmp(o->display, "headless"))
        return hfs_usage_error(PROG, "--out is for --display headless");
    return 0;
}

/* Loads the replay once to check it (errors name the file and line) and
 * says how many events it holds; the source that runs is made later, when
 * its clock starts. */
static int check_replay(const char *path, int *count, hfs_error *err)
{
    hfs_input_source *src = NULL;
    int rc = hfs_replay_source_create(path, 0, &src, err);
    if (rc)
        return rc;
    *count = hfs_replay_source_count(src);
    hfs_input_source_destroy(src);
    return HFS_OK;
}

/* Returns non-zero when the stats file or the capture recording could not
 * be written in full. */
static int teardown(kiosk *k)
{
    const int stats_rc = kiosk_stats_close(k->stats, k->frame.presented);
    hfs_input_source_destroy(k->replay);
    hfs_input_set_destroy(k->inputs);
    hfs_error cerr = {{0}};
    int record_rc = hfs_capture_live_close(k->capture, &cerr); /* the recording's end */
    if (!record_rc)
        record_rc = hfs_capture_live_close(k->capture_env, &cerr);
    else
        hfs_capture_live_close(k->capture_env, NULL);
    if (record_rc)
        kiosk_log(KIOSK_ERR, "%s", cerr.msg);
    kiosk_frame_free(&k->frame);
    hfs_display_close(k->display); /* kms: gives the CRTC back as it was */
    kiosk_world_free(k->world);
    if (k->sigfd >= 0)
        close(k->sigfd);
    return stats_rc ? stats_rc : record_rc;
}

/* The stats file is the kiosk's one output: it must not be any of the
 * files it reads (a typo such as --stats kiosk.ini would truncate it). */
static int check_stats_path(const kiosk_opts *o, const hfs_scene *s, hfs_error *err)
{
    hfs_outputs *outs = NULL;
    int rc = hfs_outputs_create(&outs, err);
    const char *inputs[] = {o->scene_path, o->input_path, o->replay_path, s->height, s->env_map,
                            s->albedo_map};
    for (size_t i = 0; i < sizeof inputs / sizeof inputs[0] && !rc; ++i)
        rc = hfs_outputs_input(outs, inputs[i], err);
    if (!rc)
        rc = hfs_outputs_add(outs, o->stats_path, err);
    hfs_outputs_destroy(outs);
    return rc;
}

static int start(kiosk *k)
{
    const kiosk_opts *o = &k->opt;
    hfs_error err = {{0}};
    int replay_events = 0;
    /* Nothing is open yet that an exit would have to restore (the display
     * comes later): SIGTERM and SIGINT end the process at once while the
     * files load, however large (queued ones included), instead of waiting
     * in the signalfd until the loop reads it. */
    sigset_t term;
    sigemptyset(&term);
    sigaddset(&term, SIGTERM);
    sigaddset(&term, SIGINT);
    sigprocmask(SIG_UNBLOCK, &term, NULL);
    if (!(k->world = kiosk_world_load(o->scene_path, o->input_path, &err)) ||
        (o->replay_path && check_replay(o->replay_path, &replay_events, &err))) {
        kiosk_log(KIOSK_ERR, "%s", err.msg);
        return 1;
    }
    sigprocmask(SIG_BLOCK, &term, NULL);
    const kiosk_world *w = k->world;
    if (w->in.hm.holes > 0)
        kiosk_log(KIOSK_INFO, "%s: filled %ld hole%s (nodata)", w->scene.height, w->in.hm.holes,
                  w->in.hm.holes == 1 ? "" : "s");
    if (o->check) {
        /* The same admission check as a reload: one frame, off screen. */
        if (kiosk_frame_admit(NULL, 0, &w->scene, &w->in, &err)) {
            kiosk_log(KIOSK_ERR, "%s: %s", o->scene_path, err.msg);
            return 1;
        }
        printf("ok: scene %s (%dx%d, %d key, %d local light%s), input %s (%d controls), "
               "replay %s (%d events)\n",
               o->scene_path, w->in.field.width, w->in.field.height, w->scene.n_key,
               w->scene.n_local, w->scene.n_local == 1 ? "" : "s",
               o->input_path ? o->input_path : "none", w->cfg.n_controls,
               o->replay_path ? o->replay_path : "none", replay_events);
        return 0;
    }
    if (o->stats_path && (check_stats_path(o, &w->scene, &err) ||
                          !(k->stats = kiosk_stats_open(o->stats_path, &err)))) {
        kiosk_log(KIOSK_ERR, "%s", err.msg);
        return 1;
    }
    kiosk_stats_start(k->stats);

    hfs_display_opts dopts = {.width = o->width, .height = o->height,
                              .title = "hfshade", .out_pattern = o->out_pattern};
    /* Devices before the display: a missing knob must not grab the screen. */
    if (kiosk_inputs_create(k, &w->cfg, &k->inputs, &err)) {
        /* A device missing at start is an error (a typo must not look like
         * an unplugged knob); say which file named it. */
        kiosk_log(KIOSK_ERR, "%s: %s", o->input_path, err.msg);
        return 1;
    }
    /* A camera (or its recording): before the display, as the knobs. */
    if (kiosk_capture_open(k, w, &err)) {
        kiosk_log(KIOSK_ERR, "%s", err.msg);
        return 1;
    }
    hfs_capture_live_stats cs = {0}, ce = {0};
    if (k->capture)
        hfs_capture_live_stats_get(k->capture, &cs);
    if (k->capture_env)
        hfs_capture_live_stats_get(k->capture_env, &ce);
    if (o->exit_after_capture && !cs.replay && !ce.replay) {
        kiosk_log(KIOSK_ERR, "--exit-after-capture needs a [capture NAME] with replay = DIR");
        return 1;
    }
    int rc = hfs_display_open(o->display, &dopts, &k->display, &err);
    if (!rc)
        rc = kiosk_frame_init(&k->frame, &w->scene, o->exposure, o->readback ? NULL : k->display,
                              &err);
    if (!rc) {
        k->frame.amortize = o->amortize;
        hfs_renderer_set_amortize(k->frame.renderer, o->amortize);
    }
    if (rc) {
        kiosk_log(KIOSK_ERR, "%s", err.msg);
        return 1;
    }
    k->world->st.overlay = o->overlay;
    k->world->st.view = o->view;
    k->frame.view_w = o->width > 0 ? o->width : 800;
    k->frame.view_h = o->height > 0 ? o->height : 480;
    /* A field larger than the display becomes a map (kiosk_map.h): the
     * display's size is --size, or the screen's on KMS. */
    k->frame.map_w = o->width, k->frame.map_h = o->height;
    if (!(o->width > 0) && !strcmp(hfs_display_name(k->display), "kms"))
        hfs_display_size(k->display, &k->frame.map_w, &k->frame.map_h);
    if (kiosk_frame_map(&k->frame, &w->in, &k->world->st, k->frame.map_w, k->frame.map_h, 0,
                        &err)) {
        kiosk_log(KIOSK_ERR, "%s", err.msg);
        return 1;
    }
    if (kiosk_frame_show(&k->frame, &w->in, &w->st, w->scene.preset, k->display, &err)) {
        kiosk_log(KIOSK_ERR, "frame: %s", err.msg);
        return 1;
    }
    kiosk_stats_frame(k->stats, &k->frame, 0);
    kiosk_stats_flush(k->stats);
    if (o->replay_path &&
        hfs_replay_source_create(o->replay_path, hfs_input_now_ns(), &k->replay, &err)) {
        kiosk_log(KIOSK_ERR, "%s", err.msg);
        return 1;
    }
    kiosk_log(KIOSK_INFO,
              "started: scene %s %dx%d, input %s (%d controls, %d device source%s), "
              "replay %s, display %s, renderer %s%s, first frame %.1f ms",
              o->scene_path, w->in.field.width, w->in.field.height,
              o->input_path ? o->input_path : "none", w->cfg.n_controls,
              hfs_input_set_count(k->inputs), hfs_input_set_count(k->inputs) == 1 ? "" : "s",
              o->replay_path ? o->replay_path : "none", hfs_display_name(k->display),
              hfs_renderer_backend_name(k->frame.renderer),
              k->frame.shared ? " (sharing the display's context: frames as textures)" : "",
              k->frame.render_ms);
    return 0;
}

int main(int argc, char **argv)
{
#ifdef HFS_HAVE_GDAL
    hfs_gdal_register(); /* GeoTIFF, SRTM .hgt, VRT ... as scene heights */
#endif
    kiosk_log_init();
    kiosk k;
    memset(&k, 0, sizeof k);
    kiosk_check_init(&k.check);
    k.sigfd = -1;
    int rc = parse_args(&k.opt, argc, argv);
    if (rc)
        return rc < 0 ? 0 : rc;

    sigset_t sigs;
    sigemptyset(&sigs);
    sigaddset(&sigs, SIGHUP);
    sigaddset(&sigs, SIGTERM);
    sigaddset(&sigs, SIGINT);
    if (sigprocmask(SIG_BLOCK, &sigs, NULL) != 0 ||
        (k.sigfd = signalfd(-1, &sigs, SFD_NONBLOCK | SFD_CLOEXEC)) < 0) {
        kiosk_log(KIOSK_ERR, "signalfd: %s", strerror(errno));
        return 1;
    }

    rc = start(&k);
    if (!rc && !k.opt.check)
        rc = kiosk_run(&k);
    if (teardown(&k) && !rc)
        rc = 1; /* the stats it was asked for are incomplete (logged) */
    return rc;
}
