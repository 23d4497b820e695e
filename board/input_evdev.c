/*
 * input_evdev.c — the evdev input source: input_event in, TURN/PRESS out.
 *
 * Reads through hfs_evdev_ops (libevdev, or a test fake).  Invariants:
 *   - h == NULL exactly when closed (after a loss): fd -1, deadline
 *     INT64_MAX, read fails until reopen;
 *   - `syncing` is set from the SYN_DROPPED that starts a resync until the
 *     sync read reports -EAGAIN, across read calls (the caller's array may
 *     fill mid-resync);
 *   - `behind` is set when a read stopped because the array was full:
 *     libevdev may hold events in its own queue, where poll() cannot see
 *     them, so the deadline says "now" until a read drains everything.
 */
#include "input_evdev.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct evdev_control {
    char name[HFS_CONTROL_NAME_MAX];
    hfs_control_kind kind;
    unsigned type, code;
    int abs_min, abs_max, abs_last;   /* EV_ABS knobs */
} evdev_control;

typedef struct evdev_source {
    hfs_input_source base;
    const hfs_evdev_ops *ops;
    void *h;
    int monotonic;
    int syncing;
    int64_t sync_t_ns;      /* the SYN_DROPPED's time, for resync events */
    int behind;
    char path[256];
    int n_controls;
    evdev_control ctl[HFS_MAX_CONTROLS];
} evdev_source;

static const char *type_name(unsigned type)
{
    switch (type) {
    case EV_KEY: return "EV_KEY";
    case EV_REL: return "EV_REL";
    case EV_ABS: return "EV_ABS";
    default: return "another event type";
    }
}

/* "REL_X", or "code 0x00" when the ops cannot name it. */
static const char *code_name(const evdev_source *s, unsigned type, unsigned code, char *buf,
                             size_t n)
{
    const char *name = s->ops->code_name ? s->ops->code_name(type, code) : NULL;
    if (name)
        return name;
    snprintf(buf, n, "%s code %u", type_name(type), code);
    return buf;
}

static void close_device(evdev_source *s)
{
    if (s->h)
        s->ops->close(s->h);
    s->h = NULL;
    s->syncing = s->behind = 0;
    s->monotonic = 0;
}

static int open_device(evdev_source *s, hfs_error *err)
{
    int mono = 0;
    errno = 0;
    void *h = s->ops->open(s->ops->ctx, s->path, &mono);
    if (!h) {
        int e = errno;
        switch (e) {
        case ENOENT:
            return hfs_fail(err, HFS_E_IO, "evdev %s: no such device", s->path);
        case EACCES: case EPERM:
            return hfs_fail(err, HFS_E_IO, "evdev %s: permission denied", s->path);
        case ENOTTY: case EINVAL:
            return hfs_fail(err, HFS_E_IO, "evdev %s: not an input device", s->path);
        default:
            return hfs_fail(err, HFS_E_IO, "evdev %s: cannot open (%s)", s->path,
                            strerror(e ? e : EIO));
        }
    }
    for (int c = 0; c < s->n_controls; ++c) {
        evdev_control *k = &s->ctl[c];
        char buf[48];
        if (!s->ops->has_code(h, k->type, k->code)) {
            s->ops->close(h);
            return hfs_fail(err, HFS_E_INVALID, "evdev %s: the device has no %s (control '%s')",
                            s->path, code_name(s, k->type, k->code, buf, sizeof buf), k->name);
        }
        if (k->type == EV_ABS) {
            int r = s->ops->abs_info(h, k->code, &k->abs_min, &k->abs_max, &k->abs_last);
            if (r < 0) {
                s->ops->close(h);
                return hfs_fail(err, HFS_E_IO, "evdev %s: cannot read %s (%s)", s->path,
                                code_name(s, k->type, k->code, buf, sizeof buf), strerror(-r));
            }
        }
    }
    s->h = h;
    s->monotonic = mono;
    s->syncing = s->behind = 0;
    return HFS_OK;
}

static int evdev_fd(hfs_input_source *src)
{
    evdev_source *s = (evdev_source *)src;
    return s->h ? s->ops->fd(s->h) : -1;
}

static int64_t evdev_deadline(hfs_input_source *src)
{
    evdev_source *s = (evdev_source *)src;
    return s->h && s->behind ? INT64_MIN : INT64_MAX;
}

/* The detents an absolute axis moved: the short way round if it wrapped. */
static int abs_delta(evdev_control *k, int value)
{
    long long d = (long long)value - k->abs_last;
    long long period = (long long)k->abs_max - k->abs_min;
    k->abs_last = value;
    if (period > 0) {
        if (d > period / 2)
            d -= period;
        else if (d < -(period / 2))
            d += period;
    }
    return (int)d;
}

static int64_t event_ns(const struct input_event *ev)
{
    return (int64_t)ev->input_event_sec * 1000000000 + (int64_t)ev->input_event_usec * 1000;
}

/* Turns one input_event into at most one hfs event; returns 1 if written. */
static int translate(evdev_source *s, const struct input_event *ev, hfs_input_event *out)
{
    for (int c = 0; c < s->n_controls; ++c) {
        evdev_control *k = &s->ctl[c];
        if (k->type != ev->type || k->code != ev->code)
            continue;
        int kind = 0, delta = 0;
        if (ev->type == EV_REL) {
            delta = ev->value;
            kind = delta ? HFS_INPUT_TURN : 0;
        } else if (ev->type == EV_ABS) {
            delta = abs_delta(k, ev->value);
            kind = delta ? HFS_INPUT_TURN : 0;
        } else if (ev->type == EV_KEY) {
            kind = ev->value == 1 ? HFS_INPUT_PRESS : ev->value == 0 ? HFS_INPUT_RELEASE : 0;
        }
        if (!kind)
            return 0;
        memset(out, 0, sizeof *out);
        /* libevdev stamps the events it makes up in a resync with 0: they
         * happened somewhere in the gap, reported at the SYN_DROPPED. */
        out->t_ns = s->syncing ? s->sync_t_ns : event_ns(ev);
        out->kind = (hfs_input_kind)kind;
        out->delta = delta;
        memcpy(out->control, k->name, sizeof out->control);
        return 1;
    }
    return 0;
}

static int evdev_read(hfs_input_source *src, int64_t now_ns, hfs_input_event *out, int max,
                      hfs_error *err)
{
    evdev_source *s = (evdev_source *)src;
    if (!s->h)
        return hfs_fail(err, HFS_E_IO, "evdev %s: closed after a loss (reopen first)", s->path);
    int n = 0;
    s->behind = 0;
    while (n < max) {
        struct input_event ev;
        int r = s->ops->next_event(s->h, s->syncing, &ev);
        if (r == -EAGAIN) {
            if (s->syncing) {       /* resync done: back to normal reading */
                s->syncing = 0;
                continue;
            }
            return n;
        }
        if (r < 0) {
            close_device(s);
            if (r == -ENODEV)
                return hfs_fail(err, HFS_E_IO, "evdev %s: device removed (%s)", s->path,
                                strerror(-r));
            return hfs_fail(err, HFS_E_IO, "evdev %s: read failed (%s)", s->path, strerror(-r));
        }
        if (r == HFS_EVDEV_SYNC && !s->syncing) {
            s->syncing = 1;         /* ev is the SYN_DROPPED itself */
            s->sync_t_ns = event_ns(&ev) ? event_ns(&ev) : now_ns;
            continue;
        }
        n += translate(s, &ev, &out[n]);
    }
    s->behind = 1;
    return n;
}

static int evdev_reopen(hfs_input_source *src, hfs_error *err)
{
    evdev_source *s = (evdev_source *)src;
    close_device(s);
    return open_device(s, err);
}

static void evdev_destroy(hfs_input_source *src)
{
    evdev_source *s = (evdev_source *)src;
    close_device(s);
    free(s);
}

static const hfs_input_source_ops evdev_source_ops = {
    .kind = "evdev",
    .fd = evdev_fd,
    .deadline_ns = evdev_deadline,
    .read = evdev_read,
    .reopen = evdev_reopen,
    .destroy = evdev_destroy,
};

int hfs_evdev_source_monotonic(const hfs_input_source *src)
{
    const evdev_source *s = (const evdev_source *)src;
    return s && s->base.ops == &evdev_source_ops && s->h && s->monotonic;
}

static int add_control(evdev_source *s, const hfs_control_config *c, hfs_error *err)
{
    if (c->evdev_type < 0 || c->evdev_code < 0)
        return hfs_fail(err, HFS_E_INVALID, "evdev %s: control '%s' has no event code", s->path,
                        c->name);
    unsigned type = (unsigned)c->evdev_type, code = (unsigned)c->evdev_code;
    if (c->kind == HFS_CONTROL_KNOB && type != EV_REL && type != EV_ABS)
        return hfs_fail(err, HFS_E_INVALID,
                        "evdev %s: knob '%s' needs an EV_REL or EV_ABS code, not %s", s->path,
                        c->name, type_name(type));
    if (c->kind == HFS_CONTROL_BUTTON && type != EV_KEY)
        return hfs_fail(err, HFS_E_INVALID, "evdev %s: button '%s' needs an EV_KEY code, not %s",
                        s->path, c->name, type_name(type));
    for (int i = 0; i < s->n_controls; ++i)
        if (s->ctl[i].type == type && s->ctl[i].code == code) {
            char buf[48];
            return hfs_fail(err, HFS_E_INVALID, "evdev %s: %s is used by both '%s' and '%s'",
                            s->path, code_name(s, type, code, buf, sizeof buf), s->ctl[i].name,
                            c->name);
        }
    evdev_control *k = &s->ctl[s->n_controls++];
    memcpy(k->name, c->name, sizeof k->name);
    k->name[sizeof k->name - 1] = '\0';
    k->kind = c->kind;
    k->type = type;
    k->code = code;
    return HFS_OK;
}

int hfs_evdev_source_create(const hfs_input_config *cfg, const char *path,
                            const hfs_evdev_ops *ops, hfs_input_source **out, hfs_error *err)
{
    *out = NULL;
    if (!cfg || !path || !path[0])
        return hfs_fail(err, HFS_E_INVALID, "evdev: no device path");
    if (strlen(path) >= sizeof(((evdev_source *)0)->path))
        return hfs_fail(err, HFS_E_INVALID, "evdev: device path too long");
    evdev_source *s = calloc(1, sizeof *s);
    if (!s)
        return hfs_fail(err, HFS_E_NOMEM, "evdev %s: out of memory", path);
    s->base.ops = &evdev_source_ops;
    s->ops = ops ? ops : hfs_evdev_ops_libevdev();
    strcpy(s->path, path);
    if (snprintf(s->base.name, sizeof s->base.name, "evdev %s", path) >= (int)sizeof s->base.name)
        s->base.name[sizeof s->base.name - 1] = '\0';

    int r = HFS_OK;
    int n_cfg = cfg->n_controls < HFS_MAX_CONTROLS ? cfg->n_controls : HFS_MAX_CONTROLS;
    for (int i = 0; i < n_cfg && r >= 0; ++i) {
        const hfs_control_config *c = &cfg->control[i];
        if (c->device == HFS_DEVICE_EVDEV && strcmp(c->path, path) == 0)
            r = add_control(s, c, err);
    }
    if (r >= 0 && s->n_controls == 0)
        r = hfs_fail(err, HFS_E_INVALID, "evdev %s: no control uses this device", path);
    if (r >= 0)
        r = open_device(s, err);
    if (r < 0) {
        free(s);
        return r;
    }
    *out = &s->base;
    return HFS_OK;
}
