/*
 * kiosk_capture.c — a [capture NAME] section with role = heights in the
 * kiosk (docs/CAPTURE.md "In the kiosk"): its frames become the heights.
 *
 * The source (a V4L2 device or a recording) is polled with the knobs; each
 * wake-up takes the NEWEST frame (hfs_capture_next), records it when
 * --capture-record asks, converts it (depth_heights.h: plane, roi, filter,
 * holes) and, when the filter changed a height, points the world's field
 * at the new heights under a new serial, so the next frame renders them
 * (the GLES planner compares the heights themselves: it reruns the terrain
 * passes for changed heights even at the same address).  A lost device is
 * reported once and reopened with the knobs' back-off (backoff.h); the
 * last good heights stay on screen meanwhile.  A malformed frame is
 * skipped with a warning (one per distinct message).
 */
#define _GNU_SOURCE
#include "kiosk.h"

#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "capture_record.h"
#include "capture_v4l2.h"

#define SERIAL_BASE (1ULL << 62) /* never a scene load's serial (those count from 1) */

static int64_t thread_cpu_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (int64_t)ts.tv_sec * 1000000000LL + ts.tv_nsec;
}

static const hfs_capture_config *heights_config(const hfs_input_config *cfg)
{
    for (int i = 0; i < cfg->captures.n; ++i)
        if (cfg->captures.c[i].role == HFS_ROLE_HEIGHTS)
            return &cfg->captures.c[i];
    return NULL;
}

static int open_source(const hfs_capture_config *c, hfs_capture **out, hfs_error *err)
{
    if (c->replay[0])
        return hfs_capture_replay_open(c->replay, hfs_input_now_ns(), c->loop, out, err);
    hfs_v4l2_desc d = {.path = c->device, .format = c->format, .width = c->width,
                       .height = c->height, .fps = c->fps, .buffers = c->buffers};
    return hfs_v4l2_open(&d, out, err);
}

int kiosk_capture_open(kiosk *k, const kiosk_world *w, hfs_error *err)
{
    const hfs_capture_config *c = heights_config(&w->cfg);
    if (!c)
        return k->opt.capture_record
                   ? hfs_fail(err, HFS_E_INVALID, "--capture-record: %s has no [capture NAME] "
                              "section", k->opt.input_path ? k->opt.input_path : "no --input")
                   : HFS_OK;
    if (k->opt.no_devices && !c->replay[0])
        return HFS_OK; /* --no-devices: the camera is not opened either */
    kiosk_capture *kc = calloc(1, sizeof *kc);
    if (!kc)
        return hfs_fail(err, HFS_E_NOMEM, "capture: out of memory");
    k->capture = kc;
    kc->name = c->name;
    kc->replay = c->replay[0] != 0;
    hfs_backoff_init(&kc->retry, 0, 0);
    hfs_depth_params p = c->depth;
    if (p.grid_w == 0) { /* the scene's field size */
        p.grid_w = w->in.field.width;
        p.grid_h = w->in.field.height;
    }
    int rc = hfs_depth_heights_create(&p, &kc->dh, err);
    if (rc) {
        hfs_error e = *err;
        return hfs_fail(err, rc, "%s:%d: [capture %s]: %s", k->opt.input_path, c->config_line,
                        c->name, e.msg);
    }
    if (k->opt.capture_record &&
        (rc = hfs_capture_record_open(k->opt.capture_record, &kc->rec, err)))
        return rc;
    return open_source(c, &kc->cap, err);
}

void kiosk_capture_free(kiosk_capture *kc)
{
    if (!kc)
        return;
    hfs_capture_destroy(kc->cap);
    hfs_depth_heights_destroy(kc->dh);
    hfs_error err = {{0}};
    if (hfs_capture_record_close(kc->rec, &err))
        kiosk_log(KIOSK_ERR, "%s", err.msg);
    free(kc);
}

int kiosk_capture_pollfd(kiosk_capture *kc, struct pollfd *fd, int64_t *deadline)
{
    if (!kc)
        return 0;
    if (kc->retry.lost) {
        if (kc->retry.retry_at_ns < *deadline)
            *deadline = kc->retry.retry_at_ns;
        return 0;
    }
    const int64_t d = hfs_capture_deadline(kc->cap);
    if (d < *deadline)
        *deadline = d;
    const int f = hfs_capture_fd(kc->cap);
    if (f < 0)
        return 0;
    *fd = (struct pollfd){.fd = f, .events = POLLIN};
    return 1;
}

void kiosk_capture_apply(kiosk_capture *kc, kiosk_world *w)
{
    if (!kc || kc->serial == 0)
        return;
    w->in.field.z = hfs_depth_heights_z(kc->dh);
    w->in.field.width = kc->grid_w;
    w->in.field.height = kc->grid_h;
    w->in.serial = kc->serial;
}

static void warn_once(kiosk_capture *kc, const char *msg)
{
    if (strcmp(msg, kc->last_warning)) {
        kiosk_log(KIOSK_WARNING, "%s", msg);
        snprintf(kc->last_warning, sizeof kc->last_warning, "%s", msg);
    }
}

/* A frame: recorded, converted.  1 when the heights changed. */
static int take(kiosk_capture *kc, const hfs_capture_frame *f)
{
    hfs_error err = {{0}};
    if (kc->rec && hfs_capture_record_frame(kc->rec, f, &err)) {
        warn_once(kc, err.msg);
        hfs_capture_record_close(kc->rec, NULL);
        kc->rec = NULL; /* recording stops, the display goes on */
    }
    const int r = hfs_depth_heights_push(kc->dh, f->data, f->width, f->height, f->stride, &err);
    if (r < 0) {
        char msg[600];
        snprintf(msg, sizeof msg, "capture %s: frame %u: %s", kc->name, f->sequence, err.msg);
        warn_once(kc, msg);
        return 0;
    }
    kc->frame_t_ns = f->t_ns;
    kc->frame_seq = f->sequence;
    return r;
}

int kiosk_capture_drain(kiosk_capture *kc, kiosk_world *w)
{
    if (!kc)
        return 0;
    const int64_t cpu0 = thread_cpu_ns(), now = hfs_input_now_ns();
    hfs_error err = {{0}};
    if (hfs_backoff_due(&kc->retry, now)) {
        if (hfs_capture_reopen(kc->cap, &err) == HFS_OK) {
            kiosk_log(KIOSK_INFO, "%s: back", kc->cap->name);
            hfs_backoff_back(&kc->retry);
        } else if (hfs_backoff_failed(&kc->retry, now, err.msg)) {
            kiosk_log(KIOSK_WARNING, "%s", err.msg);
        }
    }
    if (kc->retry.lost)
        return 0;
    hfs_capture_frame f;
    const int r = hfs_capture_next(kc->cap, now, &f, &err);
    int changed = 0;
    if (r == HFS_E_IO) { /* unplugged: the last heights stay on screen */
        kiosk_log(KIOSK_WARNING, "%s (showing the last frame; retrying)", err.msg);
        hfs_capture_close(kc->cap);
        hfs_backoff_lose(&kc->retry, now);
    } else if (r < 0) {
        warn_once(kc, err.msg);
    } else if (r > 0 && take(kc, &f)) {
        kc->serial = kc->serial ? kc->serial + 1 : SERIAL_BASE;
        hfs_depth_heights_grid(kc->dh, &kc->grid_w, &kc->grid_h);
        kiosk_capture_apply(kc, w);
        changed = 1;
    }
    kc->cpu_ns = thread_cpu_ns() - cpu0;
    return changed;
}
