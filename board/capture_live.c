/*
 * capture_live.c — see capture_live.h.
 */
#define _GNU_SOURCE
#include "capture_live.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "backoff.h"
#include "camera_sky.h"
#include "capture_record.h"
#include "depth_heights.h"

#define SERIAL_BASE (1ULL << 62)

struct hfs_capture_live {
    char name[48];                 /* the section's NAME                      */
    hfs_capture *cap;
    int replay;
    hfs_depth_heights *dh;         /* role = heights                          */
    hfs_camsky *sky;               /* role = environment                      */
    hfs_capture_recorder *rec;
    hfs_backoff retry;
    hfs_capture_log_fn log;
    void *log_user;
    char last_warning[800];
    char record_failure[600];      /* why the recording stopped, or ""       */
    uint64_t serial;
    uint32_t seq;
    int64_t t_ns, cpu_ns;
};

static int64_t thread_cpu_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (int64_t)ts.tv_sec * 1000000000LL + ts.tv_nsec;
}

static void say(hfs_capture_live *l, int warning, const char *line)
{
    if (l->log)
        l->log(l->log_user, warning, line);
}

static void warn_once(hfs_capture_live *l, const char *msg)
{
    if (strcmp(msg, l->last_warning)) {
        say(l, 1, msg);
        snprintf(l->last_warning, sizeof l->last_warning, "%s", msg);
    }
}

/* The source's tap: every good frame it delivers into the recording. */
static void record(void *user, const hfs_capture_frame *f)
{
    hfs_capture_live *l = user;
    hfs_error err = {{0}};
    if (l->rec && hfs_capture_record_frame(l->rec, f, &err)) {
        warn_once(l, err.msg);
        snprintf(l->record_failure, sizeof l->record_failure, "%s", err.msg);
        hfs_capture_record_close(l->rec, NULL);
        l->rec = NULL; /* the recording stops, the display goes on */
    }
}

static int open_source(const hfs_capture_live_desc *d, hfs_capture **out, hfs_error *err)
{
    const hfs_capture_config *c = d->config;
    if (c->replay[0]) {
        const int rc = hfs_capture_replay_open(c->replay, d->start_ns, c->loop, out, err);
        if (!rc && c->pace_shown)
            hfs_capture_replay_pace_shown(*out);
        return rc;
    }
    hfs_v4l2_desc v = {.path = c->device, .format = c->format, .width = c->width,
                       .height = c->height, .fps = c->fps, .buffers = c->buffers,
                       .ops = d->ops};
    return hfs_v4l2_open(&v, out, err);
}

/* The conversion the role needs: depth to heights, or frames to lighting. */
static int convert_open(hfs_capture_live *l, const hfs_capture_live_desc *d, hfs_error *err)
{
    const hfs_capture_config *c = d->config;
    if (c->role == HFS_ROLE_ENVIRONMENT)
        return hfs_camsky_create(&c->env, hfs_camsky_max_lights(c->env.env_lights,
                                                                d->scene_env_lights,
                                                                d->scene_keys),
                                 &l->sky, err);
    hfs_depth_params p = c->depth;
    if (p.grid_w == 0) {
        p.grid_w = d->grid_w;
        p.grid_h = d->grid_h;
    }
    return hfs_depth_heights_create(&p, &l->dh, err);
}

int hfs_capture_live_open(const hfs_capture_live_desc *d, hfs_capture_live **out,
                          hfs_error *err)
{
    *out = NULL;
    const hfs_capture_config *c = d->config;
    hfs_capture_live *l = calloc(1, sizeof *l);
    if (!l)
        return hfs_fail(err, HFS_E_NOMEM, "capture: out of memory");
    snprintf(l->name, sizeof l->name, "%s", c->name);
    l->replay = c->replay[0] != 0;
    l->log = d->log;
    l->log_user = d->log_user;
    hfs_backoff_init(&l->retry, d->retry_min_ns, d->retry_max_ns);
    int rc = convert_open(l, d, err);
    if (rc) {
        hfs_error e = *err;
        hfs_fail(err, rc, "%s:%d: [capture %s]: %s", d->config_path ? d->config_path : "config",
                 c->config_line, c->name, e.msg);
    }
    if (!rc && d->record_dir)
        rc = hfs_capture_record_open(d->record_dir, &l->rec, err);
    if (!rc)
        rc = open_source(d, &l->cap, err);
    if (!rc && l->rec) {
        l->cap->tap = record;
        l->cap->tap_user = l;
    }
    if (rc) {
        hfs_capture_live_close(l, NULL);
        return rc;
    }
    *out = l;
    return HFS_OK;
}

int hfs_capture_live_close(hfs_capture_live *l, hfs_error *err)
{
    if (!l)
        return HFS_OK;
    hfs_capture_destroy(l->cap);
    hfs_depth_heights_destroy(l->dh);
    hfs_camsky_destroy(l->sky);
    int rc = hfs_capture_record_close(l->rec, err);
    if (!rc && l->record_failure[0])
        rc = hfs_fail(err, HFS_E_IO, "%s (the recording is incomplete)", l->record_failure);
    free(l);
    return rc;
}

int hfs_capture_live_pollfd(hfs_capture_live *l, struct pollfd *fd, int64_t *deadline)
{
    if (!l)
        return 0;
    if (l->retry.lost) {
        if (l->retry.retry_at_ns < *deadline)
            *deadline = l->retry.retry_at_ns;
        return 0;
    }
    const int64_t t = hfs_capture_deadline(l->cap);
    if (t < *deadline)
        *deadline = t;
    const int f = hfs_capture_fd(l->cap);
    if (f < 0)
        return 0;
    *fd = (struct pollfd){.fd = f, .events = POLLIN};
    return 1;
}

/* A frame converted.  1 when the heights changed. */
static int take(hfs_capture_live *l, const hfs_capture_frame *f)
{
    hfs_error err = {{0}};
    int r = hfs_capture_frame_check(f, l->cap->name, &err);
    if (!r && l->sky)
        r = hfs_camsky_push(l->sky, f, &err) ? -1 : 1; /* the lighting changes every frame */
    else if (!r && f->format != HFS_PIX_Z16 && f->format != HFS_PIX_Y16)
        r = hfs_fail(&err, HFS_E_FORMAT, "%s: %s frames are not depth", l->cap->name,
                     hfs_pixfmt_name(f->format));
    else if (!r)
        r = hfs_depth_heights_push(l->dh, f->data, f->width, f->height, f->stride, &err);
    if (r < 0) {
        char msg[700];
        snprintf(msg, sizeof msg, "capture %s: frame %u: %s", l->name, f->sequence, err.msg);
        warn_once(l, msg);
        return 0;
    }
    l->t_ns = f->t_ns;
    l->seq = f->sequence;
    return r;
}

static void try_reopen(hfs_capture_live *l, int64_t now_ns)
{
    hfs_error err = {{0}};
    if (hfs_capture_reopen(l->cap, &err) == HFS_OK) {
        char line[400];
        snprintf(line, sizeof line, "%s: back", l->cap->name);
        say(l, 0, line);
        hfs_backoff_back(&l->retry);
    } else if (hfs_backoff_failed(&l->retry, now_ns, err.msg)) {
        say(l, 1, err.msg);
    }
}

int hfs_capture_live_drain(hfs_capture_live *l, int64_t now_ns)
{
    if (!l)
        return 0;
    const int64_t cpu0 = thread_cpu_ns();
    if (hfs_backoff_due(&l->retry, now_ns))
        try_reopen(l, now_ns);
    if (l->retry.lost)
        return 0;
    hfs_error err = {{0}};
    hfs_capture_frame f;
    const int r = hfs_capture_next(l->cap, now_ns, &f, &err);
    int changed = 0;
    if (r == HFS_E_IO) { /* unplugged: the last heights stay */
        char line[600];
        snprintf(line, sizeof line, "%s (showing the last frame; retrying)", err.msg);
        say(l, 1, line);
        hfs_capture_close(l->cap);
        hfs_backoff_lose(&l->retry, now_ns);
    } else if (r < 0) {
        warn_once(l, err.msg);
    } else if (r > 0 && take(l, &f)) {
        l->serial = l->serial ? l->serial + 1 : SERIAL_BASE;
        changed = 1;
    }
    l->cpu_ns = thread_cpu_ns() - cpu0;
    return changed;
}

const float *hfs_capture_live_heights(const hfs_capture_live *l, int *width, int *height,
                                      uint64_t *serial)
{
    *width = *height = 0;
    *serial = l->serial;
    if (!l->dh)
        return NULL;
    hfs_depth_heights_grid(l->dh, width, height);
    return l->serial ? hfs_depth_heights_z(l->dh) : NULL;
}

const hfs_camsky_out *hfs_capture_live_sky(const hfs_capture_live *l, uint64_t *serial)
{
    *serial = l->serial;
    return l->sky ? hfs_camsky_get(l->sky) : NULL;
}

void hfs_capture_live_stats_get(const hfs_capture_live *l, hfs_capture_live_stats *s)
{
    memset(s, 0, sizeof *s);
    s->name = l->name;
    s->sequence = l->seq;
    s->t_ns = l->t_ns;
    s->cpu_ns = l->cpu_ns;
    s->frames = l->cap->frames;
    s->dropped = l->cap->dropped;
    s->superseded = l->cap->superseded;
    s->lost = l->retry.lost;
    s->finished = l->cap->finished;
    s->replay = l->replay;
}
