/*
 * input_set.c — sources, their poll fds, losses and reopen back-off.
 *
 * Per source: lost (closed after HFS_E_IO), the time of the next reopen
 * attempt, the current back-off, and the last reopen failure message (to
 * log a new reason once, not every attempt).  Everything else is the
 * source's business.
 */
#include "input_set.h"

#include <stdlib.h>
#include <string.h>

#include "backoff.h"

typedef struct set_entry {
    hfs_input_source *src;
    hfs_backoff retry;      /* loss, reopen time, back-off (backoff.h) */
} set_entry;

struct hfs_input_set {
    hfs_input_log_fn log;
    void *log_user;
    int64_t retry_min_ns, retry_max_ns;
    int n;
    set_entry e[HFS_INPUT_SET_MAX];
};

static void say(hfs_input_set *s, const char *line)
{
    if (s->log)
        s->log(s->log_user, line);
}

int hfs_input_set_add(hfs_input_set *s, hfs_input_source *src, hfs_error *err)
{
    if (!src)
        return hfs_fail(err, HFS_E_INVALID, "input: no source to add");
    if (s->n == HFS_INPUT_SET_MAX) {
        int r = hfs_fail(err, HFS_E_INVALID, "input: too many sources (%d) for %s",
                         HFS_INPUT_SET_MAX, src->name);
        hfs_input_source_destroy(src);
        return r;
    }
    set_entry *e = &s->e[s->n++];
    memset(e, 0, sizeof *e);
    e->src = src;
    hfs_backoff_init(&e->retry, s->retry_min_ns, s->retry_max_ns);
    return HFS_OK;
}

/* Whether an earlier control already named this device (so its source
 * exists: one per chip / device path). */
static int seen_before(const hfs_input_config *cfg, int i)
{
    for (int j = 0; j < i; ++j)
        if (cfg->control[j].device == cfg->control[i].device &&
            strcmp(cfg->control[j].path, cfg->control[i].path) == 0)
            return 1;
    return 0;
}

int hfs_input_set_create(const hfs_input_set_desc *d, hfs_input_set **out, hfs_error *err)
{
    *out = NULL;
    if (!d || !d->config)
        return hfs_fail(err, HFS_E_INVALID, "input: no configuration");
    hfs_input_set *s = calloc(1, sizeof *s);
    if (!s)
        return hfs_fail(err, HFS_E_NOMEM, "input: out of memory");
    s->log = d->log;
    s->log_user = d->log_user;
    s->retry_min_ns = d->retry_min_ns;
    s->retry_max_ns = d->retry_max_ns;

    const hfs_input_config *cfg = d->config;
    int n_cfg = cfg->n_controls < HFS_MAX_CONTROLS ? cfg->n_controls : HFS_MAX_CONTROLS;
    for (int i = 0; i < n_cfg; ++i) {
        const hfs_control_config *c = &cfg->control[i];
        if (c->device == HFS_DEVICE_NONE || seen_before(cfg, i))
            continue;
        hfs_input_source *src = NULL;
        int r = c->device == HFS_DEVICE_GPIO
                    ? hfs_gpio_source_create(cfg, c->path, d->gpio_ops, &src, err)
                    : hfs_evdev_source_create(cfg, c->path, d->evdev_ops, &src, err);
        if (r >= 0)
            r = hfs_input_set_add(s, src, err);
        if (r < 0) {
            hfs_input_set_destroy(s);
            return r;
        }
    }
    *out = s;
    return HFS_OK;
}

void hfs_input_set_destroy(hfs_input_set *s)
{
    if (!s)
        return;
    for (int i = 0; i < s->n; ++i)
        hfs_input_source_destroy(s->e[i].src);
    free(s);
}

int hfs_input_set_count(const hfs_input_set *s)
{
    return s->n;
}

hfs_input_source *hfs_input_set_source(hfs_input_set *s, int i)
{
    return i >= 0 && i < s->n ? s->e[i].src : NULL;
}

int hfs_input_set_is_lost(const hfs_input_set *s, int i)
{
    return i >= 0 && i < s->n && s->e[i].retry.lost;
}

int hfs_input_set_pollfds(hfs_input_set *s, struct pollfd *fds, int max, int64_t *deadline_ns)
{
    int n = 0;
    int64_t t = INT64_MAX;
    for (int i = 0; i < s->n; ++i) {
        set_entry *e = &s->e[i];
        if (e->retry.lost) {
            if (e->retry.retry_at_ns < t)
                t = e->retry.retry_at_ns;
            continue;
        }
        int64_t d = hfs_input_source_deadline(e->src);
        if (d < t)
            t = d;
        int fd = hfs_input_source_fd(e->src);
        if (fd >= 0 && n < max) {
            fds[n].fd = fd;
            fds[n].events = POLLIN;
            fds[n].revents = 0;
            ++n;
        }
    }
    if (deadline_ns)
        *deadline_ns = t;
    return n;
}

static void lose(hfs_input_set *s, set_entry *e, int64_t now_ns, const char *msg)
{
    say(s, msg);
    /* Any read error counts as a loss: reopen closes whatever is left and
     * opens again, so a source that failed otherwise recovers the same way. */
    hfs_backoff_lose(&e->retry, now_ns);
}

static void try_reopen(hfs_input_set *s, set_entry *e, int64_t now_ns)
{
    hfs_error err = {{0}};
    if (hfs_input_source_reopen(e->src, &err) == HFS_OK) {
        char line[sizeof e->src->name + 8];
        memcpy(line, e->src->name, sizeof e->src->name);
        line[sizeof e->src->name - 1] = '\0';
        strcat(line, ": back");
        say(s, line);
        hfs_backoff_back(&e->retry);
        return;
    }
    /* Log a new reason once ("no such chip" -> "permission denied"). */
    if (hfs_backoff_failed(&e->retry, now_ns, err.msg))
        say(s, err.msg);
}

int hfs_input_set_dispatch(hfs_input_set *s, int64_t now_ns, hfs_input_event *out, int max)
{
    int n = 0;
    for (int i = 0; i < s->n; ++i) {
        set_entry *e = &s->e[i];
        if (e->retry.lost) {
            if (hfs_backoff_due(&e->retry, now_ns))
                try_reopen(s, e, now_ns);
            if (e->retry.lost)
                continue;
        }
        hfs_error err = {{0}};
        int r = hfs_input_source_read(e->src, now_ns, out + n, max - n, &err);
        if (r >= 0)
            n += r;
        else
            lose(s, e, now_ns, err.msg);
    }
    return n;
}
