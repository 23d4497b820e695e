/*
 * kiosk_loop.c — the kiosk's frame loop.
 *
 * One thread, one poll: the signalfd (SIGHUP, SIGTERM, SIGINT), the
 * display's fd (x11), and the input devices' fds, with the earliest deadline
 * of any source (a debounce to confirm, a device to reopen, the next
 * replayed event) as the timeout.  Each wake-up:
 *
 *   1. signals: TERM/INT end the loop; HUP reloads scene + configuration;
 *   2. the display's events (a close request ends the loop);
 *   3. every pending input event is drained (all sources, until each has
 *      nothing more) and applied to the scene, in order;
 *   4. if anything changed: the lighting is recomputed (no file is read)
 *      and ONE frame is rendered and presented — so a batch of events is
 *      shown by the next frame, however many there were.
 *
 * Nothing changed, nothing drawn: with no event and no deadline the poll
 * has no timeout and the process sleeps (no timer, no spinning).  ppoll
 * takes the deadline in nanoseconds, so a replayed event is read when it is
 * due, not up to a millisecond later.
 */
#define _GNU_SOURCE /* ppoll */
#include "kiosk.h"

#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/signalfd.h>
#include <time.h>
#include <unistd.h>

#include "input_replay.h"

#define READ_CHUNK 64
/* Frames while the automatic exposure settles: at most 60 a second. */
#define KIOSK_SETTLE_NS 16666667LL

/* The events of one wake-up, kept for the stats lines written after the
 * frame that shows them. */
typedef struct batch {
    hfs_input_event *ev;
    int *changed;
    int n, cap;
    int any_change;
} batch;

typedef struct loop {
    batch b;
    hfs_scene saved;   /* the scene before this batch: restored if the
                          edited lighting is refused                      */
} loop;

static void input_log(void *user, const char *line)
{
    (void)user;
    const size_t n = strlen(line);
    const int back = n >= 6 && !strcmp(line + n - 6, ": back");
    kiosk_log(back ? KIOSK_INFO : KIOSK_WARNING, "%s", line);
}

int kiosk_inputs_create(const kiosk *k, const hfs_input_config *cfg, hfs_input_set **out,
                        hfs_error *err)
{
    hfs_input_set_desc d = {.config = cfg, .log = input_log};
    if (!k->opt.no_devices)
        return hfs_input_set_create(&d, out, err);
    /* --no-devices: the same controls, none wired, so the set opens
     * nothing and only the replay drives them. */
    hfs_input_config *bare = malloc(sizeof *bare);
    if (!bare)
        return hfs_fail(err, HFS_E_NOMEM, "out of memory");
    *bare = *cfg;
    for (int i = 0; i < bare->n_controls; ++i)
        bare->control[i].device = HFS_DEVICE_NONE;
    d.config = bare;
    const int rc = hfs_input_set_create(&d, out, err);
    free(bare);
    return rc;
}

/* ---- events ----------------------------------------------------------------- */

static void batch_push(batch *b, const hfs_input_event *ev, int changed)
{
    if (b->n == b->cap) {
        const int cap = b->cap ? 2 * b->cap : 256;
        hfs_input_event *e = realloc(b->ev, (size_t)cap * sizeof *e);
        if (e)
            b->ev = e;
        int *c = realloc(b->changed, (size_t)cap * sizeof *c);
        if (c)
            b->changed = c;
        if (!e || !c)
            return; /* the edit is applied; only its stats line is lost */
        b->cap = cap;
    }
    b->ev[b->n] = *ev;
    b->changed[b->n] = changed;
    b->n++;
}

static void apply_events(kiosk *k, batch *b, const hfs_input_event *ev, int n)
{
    kiosk_world *w = k->world;
    for (int i = 0; i < n; ++i) {
        hfs_error err = {{0}};
        int r = hfs_input_apply(&w->cfg, &w->st, &ev[i], &w->scene, &err);
        if (r < 0) {
            /* A replay naming a control the configuration lacks: say so,
             * skip the event, keep running. */
            kiosk_log(KIOSK_WARNING, "%s", err.msg);
            r = 0;
        }
        batch_push(b, &ev[i], r > 0);
        b->any_change |= r > 0;
    }
}

/* Reads every source until none has more: a fast spin gives many events
 * per wake-up and all of them go into this frame. */
static void drain(kiosk *k, batch *b)
{
    const int64_t now = hfs_input_now_ns();
    hfs_input_event ev[READ_CHUNK];
    int n;
    do {
        n = hfs_input_set_dispatch(k->inputs, now, ev, READ_CHUNK);
        apply_events(k, b, ev, n);
    } while (n == READ_CHUNK);
    if (!k->replay)
        return;
    do {
        hfs_error err = {{0}};
        n = hfs_input_source_read(k->replay, now, ev, READ_CHUNK, &err);
        if (n < 0) {
            kiosk_log(KIOSK_ERR, "%s", err.msg);
            break;
        }
        apply_events(k, b, ev, n);
    } while (n == READ_CHUNK);
}

static int show(kiosk *k, int events)
{
    hfs_error err = {{0}};
    kiosk_world *w = k->world;
    if (kiosk_frame_show(&k->frame, &w->in, &w->st, w->scene.preset, k->display, &err)) {
        kiosk_log(KIOSK_ERR, "frame: %s", err.msg);
        return -1;
    }
    kiosk_stats_frame(k->stats, &k->frame, events);
    return 0;
}

/* The capture lines of a frame that showed new heights or a new sky. */
static void capture_stats(kiosk *k, int heights, int sky)
{
    if (heights)
        kiosk_stats_capture(k->stats, k->capture, &k->frame);
    if (sky)
        kiosk_stats_sky(k->stats, k->capture_env, &k->frame);
}

/* One tile the map's view wants (none: nothing to do); one of the view's
 * own is shown at once.  A tile that fails is logged and the fetching
 * stops; the next frame renders what it lacks itself, and fails there if
 * it must.  -1: a frame could not be shown (fatal). */
static int prefetch(kiosk *k)
{
    if (!k->frame.prefetching)
        return 0;
    hfs_error err = {{0}};
    const int rc = kiosk_frame_prefetch(&k->frame, &k->world->in, &err);
    if (rc < 0) {
        kiosk_log(KIOSK_WARNING, "map: a tile ahead of the view: %s", err.msg);
        k->frame.prefetching = 0;
        return 0;
    }
    if (rc > 0)
        kiosk_stats_prefetch(k->stats, &k->frame);
    if (rc == 2 && show(k, 0)) /* a tile of the view, shown coarse until now */
        return -1;
    kiosk_stats_flush(k->stats);
    return 0;
}

/* Relight, render, present, then the stats of the batch.  -1: fatal.
 * heights: the capture brought new heights (no relight needed); sky: the
 * sky camera relit the world already. */
static int show_batch(kiosk *k, loop *l, int heights, int sky)
{
    batch *b = &l->b;
    int shown = 0;
    if ((heights || sky) && !b->any_change) {
        if (show(k, 0))
            return -1;
        capture_stats(k, heights, sky);
    } else if (!b->any_change && (k->frame.deferred > 0 || k->frame.settling)) {
        /* Amortizing: passes still wait for this scene; or the automatic
         * exposure still settles (kiosk_frame.c); no event to log. */
        if (show(k, 0))
            return -1;
    } else if (b->any_change) {
        hfs_error err = {{0}};
        if (kiosk_world_relight(k->world, &err)) {
            kiosk_log(KIOSK_ERR, "input: %s; edit undone", err.msg);
            k->world->scene = l->saved;
        } else {
            if (show(k, b->n))
                return -1;
            shown = 1;
            capture_stats(k, heights, sky);
        }
    }
    for (int i = 0; i < b->n; ++i)
        kiosk_stats_event(k->stats, &b->ev[i], b->changed[i], &k->frame, shown);
    kiosk_stats_flush(k->stats);
    b->n = 0;
    b->any_change = 0;
    return 0;
}

/* --exit-after-capture: every replayed capture has played to its end (a
 * device never ends). */
static int captures_finished(const kiosk *k)
{
    hfs_capture_live *c[2] = {k->capture, k->capture_env};
    int replays = 0, done = 0;
    for (int i = 0; i < 2; ++i) {
        hfs_capture_live_stats cs = {0};
        if (c[i])
            hfs_capture_live_stats_get(c[i], &cs);
        replays += cs.replay;
        done += cs.replay && cs.finished;
    }
    return replays > 0 && done == replays;
}

/* The end of --exit-after-capture, with what became of each replay's
 * frames: each was taken (then shown when it changed the heights or the
 * sky), superseded by a newer one that was due, or dropped (a gap in the
 * recording's sequence); a frame file that cannot be read is none of these
 * (its warning says so).  tests/kiosk_capture.sh checks the sum. */
static void log_captures_finished(const kiosk *k)
{
    hfs_capture_live *c[2] = {k->capture, k->capture_env};
    char line[400] = "";
    size_t len = 0;
    for (int i = 0; i < 2 && len < sizeof line; ++i) {
        hfs_capture_live_stats cs = {0};
        if (!c[i])
            continue;
        hfs_capture_live_stats_get(c[i], &cs);
        len += (size_t)snprintf(line + len, sizeof line - len, "%s%s: %ld taken, %ld superseded, "
                                "%ld dropped", len ? "; " : "", cs.name, cs.frames,
                                cs.superseded, cs.dropped);
    }
    kiosk_log(KIOSK_INFO, "capture replay finished (%s), exiting", line);
}

/* ---- reload ------------------------------------------------------------------- */

/* Whether two configurations open the same devices for the same controls
 * (then the running sources can stay: reopening GPIO lines the old set
 * still holds would fail with "busy"). */
static int same_wiring(const hfs_input_config *a, const hfs_input_config *b)
{
    if (a->n_controls != b->n_controls)
        return 0;
    for (int i = 0; i < a->n_controls; ++i) {
        const hfs_control_config *x = &a->control[i], *y = &b->control[i];
        if (strcmp(x->name, y->name) || x->kind != y->kind || x->device != y->device ||
            strcmp(x->path, y->path) || x->lines[0] != y->lines[0] ||
            x->lines[1] != y->lines[1] || x->active_low != y->active_low ||
            x->steps_per_detent != y->steps_per_detent || x->debounce_ms != y->debounce_ms ||
            x->evdev_type != y->evdev_type || x->evdev_code != y->evdev_code)
            return 0;
    }
    return 1;
}

static void reload_failed(kiosk *k, const hfs_error *err)
{
    kiosk_log(KIOSK_ERR, "reload failed, keeping the running scene and configuration: %s",
              err->msg);
    kiosk_stats_reload(k->stats, 0);
}

/* SIGHUP: a whole new world or none.  admitted: the check process
 * (kiosk_check.c) rendered the new scene's first frame already; else that
 * admission frame is rendered here.  Returns -1 only when the frame of the
 * new scene cannot be presented (fatal, as any present failure) or the
 * input set cannot even be rebuilt empty (out of memory). */
static int reload(kiosk *k, int admitted)
{
    hfs_error err = {{0}};
    kiosk_world *nw = kiosk_world_load(k->opt.scene_path, k->opt.input_path, &err);
    if (!nw) {
        reload_failed(k, &err);
        return 0;
    }
    hfs_renderer *r = NULL;
    if (kiosk_frame_renderer_for(&k->frame, &nw->scene, &r, &err)) {
        kiosk_world_free(nw);
        reload_failed(k, &err);
        return 0;
    }
    /* A scene that loads but that the renderer refuses (a limit of the
     * device, a swath the GLES path cannot hold) must not be swapped in:
     * its first frame is rendered here, off screen, before anything
     * changes. */
    if (!admitted && kiosk_frame_admit(r ? r : k->frame.renderer, k->frame.amortize,
                                       &nw->scene, &nw->in, &err)) {
        hfs_renderer_destroy(r);
        kiosk_world_free(nw);
        reload_failed(k, &err);
        return 0;
    }
    /* Last, because it cannot be undone cleanly: the old devices are closed
     * before the new ones open. */
    if (!same_wiring(&k->world->cfg, &nw->cfg)) {
        hfs_input_set_destroy(k->inputs);
        k->inputs = NULL;
        if (kiosk_inputs_create(k, &nw->cfg, &k->inputs, &err)) {
            hfs_renderer_destroy(r);
            kiosk_world_free(nw);
            reload_failed(k, &err);
            /* The old devices were open a moment ago: take them back. */
            if (kiosk_inputs_create(k, &k->world->cfg, &k->inputs, &err)) {
                kiosk_log(KIOSK_ERR, "input devices lost on reload: %s", err.msg);
                hfs_input_config none = {0};
                if (kiosk_inputs_create(k, &none, &k->inputs, &err))
                    return -1;
            }
            return 0;
        }
    }
    kiosk_frame_adopt(&k->frame, r, &nw->scene);
    /* Display choices, not the scene's: the overlay and the 3-D view. */
    const hfs_input_state *old = &k->world->st;
    nw->st.overlay = old->overlay;
    nw->st.view = old->view;
    nw->st.cam_azimuth = old->cam_azimuth, nw->st.cam_elevation = old->cam_elevation;
    nw->st.cam_zoom = old->cam_zoom;
    nw->st.map_levels = old->map_levels, nw->st.map_w = old->map_w, nw->st.map_h = old->map_h;
    nw->st.map_level = old->map_level, nw->st.map_x = old->map_x, nw->st.map_y = old->map_y;
    if (kiosk_frame_map(&k->frame, &nw->in, &nw->st, k->frame.map_w, k->frame.map_h, 1, &err)) {
        kiosk_log(KIOSK_ERR, "reload: %s", err.msg); /* shown whole instead, as before maps */
        nw->st.map_levels = 0;
    }
    kiosk_world_free(k->world);
    k->world = nw;
    kiosk_capture_apply(k->capture, k->world); /* the camera's heights, not the file's */
    kiosk_capture_sky_apply(k->capture_env, k->world); /* and its sky */
    kiosk_log(KIOSK_INFO, "reloaded %s%s%s", k->opt.scene_path,
              k->opt.input_path ? " and " : "", k->opt.input_path ? k->opt.input_path : "");
    kiosk_stats_reload(k->stats, 1);
    const int rc = show(k, 0);
    kiosk_stats_flush(k->stats);
    return rc;
}

/* SIGHUP: the check process starts (or, when one runs, will start again
 * when it ends: the files may have changed meanwhile).  Where no process
 * can be started, the reload is checked here, in the loop. */
static int request_reload(kiosk *k)
{
    if (k->check.pid > 0) {
        k->check.again = 1;
        return 0;
    }
    hfs_error err = {{0}};
    if (kiosk_check_start(&k->check, &k->opt, &err) == HFS_OK) {
        /* The event tests wait on (tests/hostile.sh): the loop goes on. */
        kiosk_log(KIOSK_INFO, "SIGHUP: checking %s in process %d", k->opt.scene_path,
                  (int)k->check.pid);
        return 0;
    }
    kiosk_log(KIOSK_WARNING, "%s; checking the reload in this process", err.msg);
    return reload(k, 0);
}

/* The check process wrote or ended: on its verdict, the reload. */
static int check_progress(kiosk *k)
{
    int ok = 0;
    char msg[512];
    if (!kiosk_check_poll(&k->check, &ok, msg, sizeof msg))
        return 0;
    int rc = 0;
    if (ok) {
        rc = reload(k, 1);
    } else {
        hfs_error err;
        snprintf(err.msg, sizeof err.msg, "%s", msg);
        reload_failed(k, &err);
    }
    if (!rc && k->check.again) {
        k->check.again = 0;
        rc = request_reload(k);
    }
    return rc;
}

/* ---- the loop ------------------------------------------------------------------ */

/* Reads every queued signal; the handlers' work happens here, in the loop. */
static void read_signals(kiosk *k, int *quit, int *reload_req)
{
    struct signalfd_siginfo si;
    while (read(k->sigfd, &si, sizeof si) == (ssize_t)sizeof si) {
        if (si.ssi_signo == SIGHUP) {
            *reload_req = 1;
        } else if (!*quit) {
            kiosk_log(KIOSK_INFO, "%s: exiting", strsignal((int)si.ssi_signo));
            *quit = 1;
        }
    }
}

static struct timespec *timeout_until(int64_t deadline_ns, struct timespec *ts)
{
    if (deadline_ns == INT64_MAX)
        return NULL; /* nothing due: sleep until an fd or a signal */
    int64_t wait = deadline_ns - hfs_input_now_ns();
    if (wait < 0)
        wait = 0;
    ts->tv_sec = (time_t)(wait / 1000000000);
    ts->tv_nsec = (long)(wait % 1000000000);
    return ts;
}

int kiosk_run(kiosk *k)
{
    loop *l = calloc(1, sizeof *l);
    if (!l) {
        kiosk_log(KIOSK_ERR, "out of memory");
        return 1;
    }
    int rc = 0;
    for (;;) {
        /* Checked before waiting: a replay with no events (or whose last
         * event was just shown) has nothing left to wake the poll. */
        if (k->opt.exit_after_replay && k->replay && hfs_replay_source_finished(k->replay) == 1 &&
            k->frame.deferred == 0) { /* amortizing: once the image has caught up */
            kiosk_log(KIOSK_INFO, "replay finished, exiting");
            break;
        }
        if (k->opt.exit_after_capture && captures_finished(k) && k->frame.deferred == 0) {
            log_captures_finished(k);
            break;
        }
        struct pollfd fds[5 + HFS_INPUT_SET_MAX]; /* + 2 cameras */
        int n = 0;
        fds[n++] = (struct pollfd){.fd = k->sigfd, .events = POLLIN};
        const int dfd = hfs_display_fd(k->display);
        if (dfd >= 0)
            fds[n++] = (struct pollfd){.fd = dfd, .events = POLLIN};
        const int check_at = k->check.fd >= 0 ? n : -1;
        if (check_at >= 0)
            fds[n++] = (struct pollfd){.fd = k->check.fd, .events = POLLIN};
        int64_t deadline = INT64_MAX;
        n += hfs_input_set_pollfds(k->inputs, fds + n, HFS_INPUT_SET_MAX, &deadline);
        n += hfs_capture_live_pollfd(k->capture, fds + n, &deadline);
        n += hfs_capture_live_pollfd(k->capture_env, fds + n, &deadline);
        if (k->replay) {
            const int64_t d = hfs_input_source_deadline(k->replay);
            deadline = d < deadline ? d : deadline;
        }
        if (k->frame.deferred > 0 || k->frame.prefetching) /* amortized passes or the map's */
            deadline = hfs_input_now_ns();                  /* tiles wait: at once          */
        else if (k->frame.settling && k->frame.present_ns + KIOSK_SETTLE_NS < deadline)
            deadline = k->frame.present_ns + KIOSK_SETTLE_NS; /* the exposure settles */
        struct timespec ts;
        if (ppoll(fds, (nfds_t)n, timeout_until(deadline, &ts), NULL) < 0 && errno != EINTR) {
            kiosk_log(KIOSK_ERR, "poll: %s", strerror(errno));
            rc = 1;
            break;
        }

        int quit = 0, reload_req = 0;
        if (fds[0].revents & POLLIN)
            read_signals(k, &quit, &reload_req);
        if (quit)
            break;
        if (hfs_display_handle_events(k->display)) {
            kiosk_log(KIOSK_INFO, "display %s: close requested, exiting",
                      hfs_display_name(k->display));
            break;
        }
        if (reload_req && request_reload(k)) {
            rc = 1;
            break;
        }
        if (check_at >= 0 && (fds[check_at].revents & (POLLIN | POLLHUP | POLLERR)) &&
            check_progress(k)) {
            rc = 1;
            break;
        }

        l->saved = k->world->scene;
        drain(k, &l->b);
        const int heights = kiosk_capture_drain(k->capture, k->world);
        const int sky = kiosk_capture_sky_drain(k->capture_env, k->world);
        const int presented = k->frame.presented;
        if (show_batch(k, l, heights, sky)) {
            rc = 1;
            break;
        }
        if (k->frame.presented == presented && prefetch(k)) { /* idle: a tile of the map */
            rc = 1;
            break;
        }
    }
    const int pid = (int)k->check.pid;
    if (kiosk_check_stop(&k->check)) /* a reload still being checked is dropped */
        kiosk_log(KIOSK_INFO, "the check in process %d was still running: stopped", pid);
    free(l->b.ev);
    free(l->b.changed);
    free(l);
    return rc;
}
