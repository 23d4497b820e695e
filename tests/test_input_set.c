/*
 * test_input_set.c — the set: poll fds and deadlines, draining, losses,
 * reopen back-off, recovery reported once.
 *
 * A GPIO source on a scripted chip (input_gpio_fake) comes from the
 * configuration; a hand-made source with its own deadline is added as an
 * extra (as the kiosk adds the replay source).
 */
#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "input_gpio_fake.h"
#include "input_set.h"

#define MS (1000000LL)

/* ---- a hand-made source: one event at its deadline, can be "lost" ---- */
typedef struct tick_source {
    hfs_input_source base;
    int64_t next_ns;
    int gone, reopen_calls;
    int *destroyed;
} tick_source;

static int tick_fd(hfs_input_source *s) { (void)s; return -1; }
static int64_t tick_deadline(hfs_input_source *s) { return ((tick_source *)s)->next_ns; }
static int tick_read(hfs_input_source *src, int64_t now, hfs_input_event *out, int max,
                     hfs_error *err)
{
    tick_source *s = (tick_source *)src;
    if (s->gone)
        return hfs_fail(err, HFS_E_IO, "tick: gone");
    if (now < s->next_ns || max < 1)
        return 0;
    memset(out, 0, sizeof *out);
    out->t_ns = s->next_ns;
    out->kind = HFS_INPUT_PRESS;
    strcpy(out->control, "tick");
    s->next_ns = INT64_MAX;
    return 1;
}
static int tick_reopen(hfs_input_source *src, hfs_error *err)
{
    tick_source *s = (tick_source *)src;
    s->reopen_calls++;
    return s->gone ? hfs_fail(err, HFS_E_IO, "tick: still gone") : 0;
}
static void tick_destroy(hfs_input_source *src)
{
    tick_source *s = (tick_source *)src;
    (*s->destroyed)++;
    free(s);
}
static const hfs_input_source_ops tick_ops = {
    "tick", tick_fd, tick_deadline, tick_read, tick_reopen, tick_destroy};

static tick_source *tick_new(int64_t next, int *destroyed)
{
    tick_source *s = calloc(1, sizeof *s);
    s->base.ops = &tick_ops;
    strcpy(s->base.name, "tick");
    s->next_ns = next;
    s->destroyed = destroyed;
    return s;
}

/* ---- log capture ---- */
typedef struct log_lines {
    int n;
    char line[16][512];
} log_lines;

static void capture(void *user, const char *line)
{
    log_lines *l = user;
    if (l->n < 16)
        snprintf(l->line[l->n++], sizeof l->line[0], "%s", line);
}

static void make_config(hfs_input_config *cfg)
{
    memset(cfg, 0, sizeof *cfg);
    hfs_control_config *k = &cfg->control[cfg->n_controls++];
    strcpy(k->name, "sun");
    k->kind = HFS_CONTROL_KNOB;
    k->device = HFS_DEVICE_GPIO;
    strcpy(k->path, "gpiochip0");
    k->lines[0] = 3;
    k->lines[1] = 4;
    k->steps_per_detent = 1;
    hfs_control_config *b = &cfg->control[cfg->n_controls++];
    strcpy(b->name, "next");
    b->kind = HFS_CONTROL_BUTTON;
    b->device = HFS_DEVICE_GPIO;
    strcpy(b->path, "gpiochip0");
    b->lines[0] = 5;
    hfs_control_config *r = &cfg->control[cfg->n_controls++];
    strcpy(r->name, "scripted");
    r->kind = HFS_CONTROL_KNOB;    /* no device: replay only */
}

static void test_loss_and_backoff(void)
{
    fake_gpio f;
    fake_gpio_init(&f, "gpiochip0", "fake", 8);
    hfs_input_config cfg;
    make_config(&cfg);
    log_lines log = {0};
    hfs_input_set_desc d = {.config = &cfg, .log = capture, .log_user = &log,
                            .gpio_ops = &f.ops};
    hfs_input_set *set = NULL;
    hfs_error err = {{0}};
    int r = hfs_input_set_create(&d, &set, &err);
    CHECK(r == 0 && set, "create: %s", err.msg);
    if (!set)
        return;
    CHECK(hfs_input_set_count(set) == 1, "one source per chip: %d", hfs_input_set_count(set));
    int destroyed = 0;
    tick_source *tick = tick_new(500 * MS, &destroyed);
    CHECK(hfs_input_set_add(set, &tick->base, &err) == 0, "add");
    CHECK(hfs_input_set_count(set) == 2, "two sources");

    struct pollfd fds[HFS_INPUT_SET_MAX];
    int64_t deadline = 0;
    int nfds = hfs_input_set_pollfds(set, fds, HFS_INPUT_SET_MAX, &deadline);
    CHECK(nfds == 1 && fds[0].fd == f.pipe[0] && fds[0].events == POLLIN, "one fd: %d", nfds);
    CHECK(deadline == 500 * MS, "deadline from the tick source: %lld", (long long)deadline);

    hfs_input_event ev[16];
    int64_t t = 100 * MS;
    fake_gpio_set(&f, 3, 1, t);   /* steps_per_detent 1: one edge, one detent */
    int n = hfs_input_set_dispatch(set, t, ev, 16);
    CHECK(n == 1 && ev[0].kind == HFS_INPUT_TURN && strcmp(ev[0].control, "sun") == 0,
          "knob through the set: %d", n);
    n = hfs_input_set_dispatch(set, 500 * MS, ev, 16);
    CHECK(n == 1 && strcmp(ev[0].control, "tick") == 0, "deadline-driven source: %d", n);
    hfs_input_set_pollfds(set, fds, HFS_INPUT_SET_MAX, &deadline);
    CHECK(deadline == INT64_MAX, "idle");

    /* Unplug at t0: one line, source closed, retry at +100 ms. */
    int64_t t0 = 1000 * MS;
    fake_gpio_unplug(&f);
    n = hfs_input_set_dispatch(set, t0, ev, 16);
    CHECK(n == 0, "no events from a lost chip");
    CHECK(log.n == 1 && strcmp(log.line[0], "gpio gpiochip0: device removed (No such device)") == 0,
          "loss logged once: %d '%s'", log.n, log.line[0]);
    CHECK(hfs_input_set_is_lost(set, 0) && !hfs_input_set_is_lost(set, 1), "lost flag");
    CHECK(f.open_handles == 0, "closed");
    nfds = hfs_input_set_pollfds(set, fds, HFS_INPUT_SET_MAX, &deadline);
    CHECK(nfds == 0 && deadline == t0 + 100 * MS, "retry deadline +100 ms: %lld",
          (long long)(deadline - t0));
    n = hfs_input_set_dispatch(set, t0 + 50 * MS, ev, 16);
    CHECK(n == 0 && hfs_input_set_is_lost(set, 0), "not yet");

    /* Failing attempts double the wait up to 5 s, quietly. */
    int64_t expect_wait[] = {200, 400, 800, 1600, 3200, 5000, 5000};
    int64_t now = t0 + 100 * MS;
    for (int i = 0; i < 7; ++i) {
        hfs_input_set_dispatch(set, now, ev, 16);
        hfs_input_set_pollfds(set, fds, HFS_INPUT_SET_MAX, &deadline);
        CHECK(deadline - now == expect_wait[i] * MS, "attempt %d: next after %lld ms (want %lld)",
              i, (long long)((deadline - now) / MS), (long long)expect_wait[i]);
        now = deadline;
    }
    CHECK(log.n == 1, "retries are quiet: %d lines", log.n);

    /* A new reason is told once. */
    f.open_errno = EACCES;
    hfs_input_set_dispatch(set, now, ev, 16);
    hfs_input_set_pollfds(set, fds, HFS_INPUT_SET_MAX, &deadline);
    now = deadline;
    hfs_input_set_dispatch(set, now, ev, 16);
    hfs_input_set_pollfds(set, fds, HFS_INPUT_SET_MAX, &deadline);
    now = deadline;
    CHECK(log.n == 2 && strcmp(log.line[1], "gpio gpiochip0: permission denied") == 0,
          "new reason once: %d '%s'", log.n, log.n > 1 ? log.line[1] : "");

    /* Back: recovery told once, events flow, fd polled again. */
    f.open_errno = 0;
    fake_gpio_plug(&f);
    f.level[3] = 1;
    n = hfs_input_set_dispatch(set, now - 1, ev, 16);
    CHECK(hfs_input_set_is_lost(set, 0), "no attempt before the deadline");
    n = hfs_input_set_dispatch(set, now, ev, 16);
    CHECK(!hfs_input_set_is_lost(set, 0), "reopened at the deadline");
    CHECK(log.n == 3 && strcmp(log.line[2], "gpio gpiochip0: back") == 0, "recovery: '%s'",
          log.n > 2 ? log.line[2] : "");
    nfds = hfs_input_set_pollfds(set, fds, HFS_INPUT_SET_MAX, &deadline);
    CHECK(nfds == 1 && deadline == INT64_MAX, "polled again");
    fake_gpio_set(&f, 3, 0, now + MS);
    n = hfs_input_set_dispatch(set, now + MS, ev, 16);
    CHECK(n == 1 && ev[0].kind == HFS_INPUT_TURN && ev[0].t_ns == now + MS, "events again");

    /* A second loss starts the back-off from 100 ms again. */
    fake_gpio_unplug(&f);
    hfs_input_set_dispatch(set, now + 2 * MS, ev, 16);
    hfs_input_set_pollfds(set, fds, HFS_INPUT_SET_MAX, &deadline);
    CHECK(deadline == now + 102 * MS, "back-off reset");
    fake_gpio_plug(&f);

    /* The extra source lost and back too. */
    tick->gone = 1;
    tick->next_ns = 0;
    n = hfs_input_set_dispatch(set, now + 102 * MS, ev, 16);  /* gpio back, tick lost */
    CHECK(hfs_input_set_is_lost(set, 1) && !hfs_input_set_is_lost(set, 0), "tick lost");
    CHECK(strcmp(log.line[log.n - 1], "tick: gone") == 0, "tick loss logged: '%s'",
          log.line[log.n - 1]);
    tick->gone = 0;
    tick->next_ns = INT64_MAX;
    n = hfs_input_set_dispatch(set, now + 300 * MS, ev, 16);
    CHECK(!hfs_input_set_is_lost(set, 1) && strcmp(log.line[log.n - 1], "tick: back") == 0,
          "tick back: '%s'", log.line[log.n - 1]);

    hfs_input_set_destroy(set);
    CHECK(destroyed == 1, "extra source destroyed with the set");
    CHECK(f.open_handles == 0, "chip closed");
    fake_gpio_fini(&f);
}

static void test_create_errors(void)
{
    fake_gpio f;
    fake_gpio_init(&f, "gpiochip1", "fake", 8);   /* not the configured chip */
    hfs_input_config cfg;
    make_config(&cfg);
    hfs_input_set_desc d = {.config = &cfg, .gpio_ops = &f.ops};
    hfs_input_set *set = (hfs_input_set *)1;
    hfs_error err = {{0}};
    int r = hfs_input_set_create(&d, &set, &err);
    CHECK(r == HFS_E_IO && set == NULL && strcmp(err.msg, "gpio gpiochip0: no such chip") == 0,
          "missing chip at start: %d '%s'", r, err.msg);
    hfs_input_set_destroy(NULL);

    /* Replay-only configuration: an empty set is fine. */
    hfs_input_config empty = {0};
    d.config = &empty;
    r = hfs_input_set_create(&d, &set, &err);
    CHECK(r == 0 && hfs_input_set_count(set) == 0, "empty set");
    int64_t deadline = 0;
    struct pollfd fds[1];
    CHECK(hfs_input_set_pollfds(set, fds, 1, &deadline) == 0 && deadline == INT64_MAX,
          "nothing to poll");
    int destroyed = 0;
    for (int i = 0; i < HFS_INPUT_SET_MAX; ++i)
        hfs_input_set_add(set, &tick_new(INT64_MAX, &destroyed)->base, &err);
    r = hfs_input_set_add(set, &tick_new(INT64_MAX, &destroyed)->base, &err);
    CHECK(r == HFS_E_INVALID && destroyed == 1, "full set refuses and destroys: %d", r);
    hfs_input_set_destroy(set);
    CHECK(destroyed == HFS_INPUT_SET_MAX + 1, "all destroyed");
    fake_gpio_fini(&f);
}

int main(void)
{
    test_loss_and_backoff();
    test_create_errors();
    if (failures)
        fprintf(stderr, "test_input_set: %d failure(s)\n", failures);
    return failures ? 1 : 0;
}
