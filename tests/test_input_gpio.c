/*
 * test_input_gpio.c — the GPIO source against a scripted chip (no kernel).
 *
 * Knob edge sequences -> exactly the TURN events, stamped with the edge
 * that completed the detent; bouncing buttons -> one press, one release;
 * a full event array -> nothing lost; the chip unplugged -> HFS_E_IO with
 * one line naming it, reopen failing while gone and working when back,
 * events flowing again; open errors named; no handle left open.
 */
#include <errno.h>
#include <poll.h>
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "input_gpio.h"
#include "input_gpio_fake.h"

#define MS (1000000LL)

static hfs_control_config *add(hfs_input_config *cfg, const char *name, hfs_control_kind kind,
                               const char *chip, int l0, int l1)
{
    hfs_control_config *c = &cfg->control[cfg->n_controls++];
    memset(c, 0, sizeof *c);
    snprintf(c->name, sizeof c->name, "%s", name);
    c->kind = kind;
    c->device = HFS_DEVICE_GPIO;
    snprintf(c->path, sizeof c->path, "%s", chip);
    c->lines[0] = l0;
    c->lines[1] = l1;
    return c;
}

static void make_config(hfs_input_config *cfg, const char *chip)
{
    memset(cfg, 0, sizeof *cfg);
    add(cfg, "sun", HFS_CONTROL_KNOB, chip, 17, 18)->steps_per_detent = 4;
    hfs_control_config *b = add(cfg, "next", HFS_CONTROL_BUTTON, chip, 22, 0);
    b->active_low = 1;
    b->debounce_ms = 10;
    add(cfg, "other", HFS_CONTROL_KNOB, "gpiochip1", 1, 2); /* another chip: not ours */
    hfs_control_config *r = add(cfg, "replayed", HFS_CONTROL_KNOB, "", 0, 0);
    r->device = HFS_DEVICE_NONE;
}

/* One clockwise detent from rest A=B=1 (cycle 11 -> 01 -> 00 -> 10 -> 11). */
static int64_t turn_cw(fake_gpio *f, int64_t t)
{
    fake_gpio_set(f, 17, 0, t += MS);
    fake_gpio_set(f, 18, 0, t += MS);
    fake_gpio_set(f, 17, 1, t += MS);
    fake_gpio_set(f, 18, 1, t += MS);
    return t;
}

static int64_t turn_ccw(fake_gpio *f, int64_t t)
{
    fake_gpio_set(f, 18, 0, t += MS);
    fake_gpio_set(f, 17, 0, t += MS);
    fake_gpio_set(f, 18, 1, t += MS);
    fake_gpio_set(f, 17, 1, t += MS);
    return t;
}

static int readable(int fd)
{
    struct pollfd p = {.fd = fd, .events = POLLIN};
    return poll(&p, 1, 0) == 1 && (p.revents & POLLIN);
}

static int read_all(hfs_input_source *s, int64_t now, hfs_input_event *ev, int max)
{
    hfs_error err = {{0}};
    int n = hfs_input_source_read(s, now, ev, max, &err);
    CHECK(n >= 0, "read failed: %d %s", n, err.msg);
    return n;
}

static void test_knob_and_button(void)
{
    fake_gpio f;
    fake_gpio_init(&f, "gpiochip0", "fake-gpio", 32);
    f.level[17] = f.level[18] = 1;
    f.level[22] = 1;   /* active low: released */
    hfs_input_config cfg;
    make_config(&cfg, "gpiochip0");
    hfs_input_source *s = NULL;
    hfs_error err = {{0}};
    int r = hfs_gpio_source_create(&cfg, "gpiochip0", &f.ops, &s, &err);
    CHECK(r == 0 && s, "create: %d %s", r, err.msg);
    if (!s)
        return;
    CHECK(strcmp(s->name, "gpio gpiochip0") == 0, "name '%s'", s->name);
    CHECK(strcmp(s->ops->kind, "gpio") == 0, "kind");
    CHECK(f.requested[17] && f.requested[18] && f.requested[22] && !f.requested[1],
          "lines requested: 17 18 22 only");
    int fd = hfs_input_source_fd(s);
    CHECK(fd == f.pipe[0], "fd is the chip's");
    CHECK(hfs_input_source_deadline(s) == INT64_MAX, "idle deadline");
    CHECK(!readable(fd), "nothing to read yet");

    hfs_input_event ev[16];
    /* Clockwise, then counter-clockwise: exact events and timestamps. */
    int64_t t = 1000 * MS;
    int64_t t_cw = turn_cw(&f, t);
    CHECK(readable(fd), "edges make the fd readable");
    int n = read_all(s, t_cw, ev, 16);
    CHECK(n == 1, "one detent cw: %d events", n);
    CHECK(n >= 1 && ev[0].kind == HFS_INPUT_TURN && ev[0].delta == 1 && ev[0].t_ns == t_cw &&
              strcmp(ev[0].control, "sun") == 0,
          "cw: kind %d delta %d t %lld control %s", ev[0].kind, ev[0].delta,
          (long long)ev[0].t_ns, ev[0].control);
    CHECK(!readable(fd), "drained");
    int64_t t_ccw = turn_ccw(&f, t_cw + 50 * MS);
    n = read_all(s, t_ccw, ev, 16);
    CHECK(n == 1 && ev[0].delta == -1 && ev[0].t_ns == t_ccw, "ccw: n %d delta %d", n,
          n ? ev[0].delta : 0);

    /* Half a detent and back: nothing.  Contact bounce on A mid-detent:
     * still exactly one detent. */
    t = t_ccw + 50 * MS;
    fake_gpio_set(&f, 17, 0, t += MS);
    fake_gpio_set(&f, 18, 0, t += MS);
    fake_gpio_set(&f, 18, 1, t += MS);
    fake_gpio_set(&f, 17, 1, t += MS);
    n = read_all(s, t, ev, 16);
    CHECK(n == 0, "half a detent and back: %d events", n);
    fake_gpio_set(&f, 17, 0, t += MS);
    fake_gpio_set(&f, 17, 1, t += 100000);   /* bounce */
    fake_gpio_set(&f, 17, 0, t += 100000);
    fake_gpio_set(&f, 18, 0, t += MS);
    fake_gpio_set(&f, 17, 1, t += MS);
    fake_gpio_set(&f, 18, 1, t += MS);
    n = read_all(s, t, ev, 16);
    CHECK(n == 1 && ev[0].delta == 1 && ev[0].t_ns == t, "bounced detent: n %d", n);

    /* Three detents, an array of one: all three come, in order. */
    int64_t t1 = turn_cw(&f, t + 10 * MS);
    int64_t t2 = turn_cw(&f, t1);
    int64_t t3 = turn_cw(&f, t2);
    int64_t got[3] = {0, 0, 0};
    n = read_all(s, t3, ev, 1);
    CHECK(n == 1, "first of three");
    got[0] = ev[0].t_ns;
    CHECK(hfs_input_source_deadline(s) == INT64_MIN, "more waiting: deadline now");
    n = read_all(s, t3, ev, 1);
    got[1] = n == 1 ? ev[0].t_ns : 0;
    n = read_all(s, t3, ev, 1);
    got[2] = n == 1 ? ev[0].t_ns : 0;
    CHECK(got[0] == t1 && got[1] == t2 && got[2] == t3, "three detents in order: %lld %lld %lld",
          (long long)got[0], (long long)got[1], (long long)got[2]);
    n = read_all(s, t3, ev, 1);
    CHECK(n == 0, "then nothing");
    CHECK(hfs_input_source_deadline(s) == INT64_MAX, "idle again");

    /* Button (active low) bouncing down: one press, at the last edge,
     * reported only once stable for 10 ms. */
    t = t3 + 100 * MS;
    fake_gpio_set(&f, 22, 0, t);
    fake_gpio_set(&f, 22, 1, t + 1 * MS);
    fake_gpio_set(&f, 22, 0, t + 2 * MS);
    n = read_all(s, t + 5 * MS, ev, 16);
    CHECK(n == 0, "not settled yet: %d", n);
    CHECK(hfs_input_source_deadline(s) == t + 12 * MS, "deadline = last edge + 10 ms: %lld",
          (long long)(hfs_input_source_deadline(s) - t));
    n = read_all(s, t + 12 * MS, ev, 16);
    CHECK(n == 1 && ev[0].kind == HFS_INPUT_PRESS && ev[0].t_ns == t + 2 * MS &&
              strcmp(ev[0].control, "next") == 0,
          "press: n %d kind %d", n, n ? ev[0].kind : 0);
    n = read_all(s, t + 50 * MS, ev, 16);
    CHECK(n == 0, "one press only");
    /* Release with bounce, read long after: one release. */
    t += 200 * MS;
    fake_gpio_set(&f, 22, 1, t);
    fake_gpio_set(&f, 22, 0, t + MS / 2);
    fake_gpio_set(&f, 22, 1, t + MS);
    n = read_all(s, t + 100 * MS, ev, 16);
    CHECK(n == 1 && ev[0].kind == HFS_INPUT_RELEASE && ev[0].t_ns == t + MS, "release: n %d", n);
    /* A 3 ms glitch: nothing. */
    t += 200 * MS;
    fake_gpio_set(&f, 22, 0, t);
    fake_gpio_set(&f, 22, 1, t + 3 * MS);
    n = read_all(s, t + 100 * MS, ev, 16);
    CHECK(n == 0, "glitch ignored: %d", n);

    /* A press and release both completed within one read, read late. */
    t += 200 * MS;
    fake_gpio_set(&f, 22, 0, t);
    fake_gpio_set(&f, 22, 1, t + 40 * MS);
    n = read_all(s, t + 100 * MS, ev, 16);
    CHECK(n == 2 && ev[0].kind == HFS_INPUT_PRESS && ev[1].kind == HFS_INPUT_RELEASE &&
              ev[0].t_ns == t && ev[1].t_ns == t + 40 * MS,
          "press+release in one read: n %d", n);

    /* Unplugged: one line naming the chip, then closed. */
    fake_gpio_unplug(&f);
    CHECK(readable(fd), "unplug wakes the poll loop");
    memset(&err, 0, sizeof err);
    r = hfs_input_source_read(s, t, ev, 16, &err);
    CHECK(r == HFS_E_IO, "read after unplug: %d", r);
    CHECK(strcmp(err.msg, "gpio gpiochip0: device removed (No such device)") == 0, "msg '%s'",
          err.msg);
    CHECK(strchr(err.msg, '\n') == NULL, "one line");
    CHECK(hfs_input_source_fd(s) == -1, "closed: fd -1");
    CHECK(hfs_input_source_deadline(s) == INT64_MAX, "closed: no deadline");
    CHECK(f.open_handles == 0, "handle closed on loss");
    r = hfs_input_source_read(s, t, ev, 16, &err);
    CHECK(r == HFS_E_IO, "read while closed");
    r = hfs_input_source_reopen(s, &err);
    CHECK(r == HFS_E_IO && strcmp(err.msg, "gpio gpiochip0: no such chip") == 0,
          "reopen while gone: %d '%s'", r, err.msg);
    /* Back, with the knob resting at the other rest state (A=B=0) now. */
    fake_gpio_plug(&f);
    f.level[17] = f.level[18] = 0;
    r = hfs_input_source_reopen(s, &err);
    CHECK(r == 0, "reopen when back: %d %s", r, err.msg);
    CHECK(hfs_input_source_fd(s) == f.pipe[0] && f.open_handles == 1, "open again");
    t += 1000 * MS;
    fake_gpio_set(&f, 17, 1, t += MS);    /* 00 -> 10 -> 11 -> 01 -> 00: cw */
    fake_gpio_set(&f, 18, 1, t += MS);
    fake_gpio_set(&f, 17, 0, t += MS);
    fake_gpio_set(&f, 18, 0, t += MS);
    n = read_all(s, t, ev, 16);
    CHECK(n == 1 && ev[0].delta == 1 && ev[0].t_ns == t, "events flow again: n %d", n);

    hfs_input_source_destroy(s);
    CHECK(f.open_handles == 0, "destroy closes the chip");
    hfs_input_source_destroy(NULL);
    fake_gpio_fini(&f);
}

static void expect_create_error(fake_gpio *f, const char *chip, int code, const char *msg)
{
    hfs_input_config cfg;
    make_config(&cfg, chip);
    hfs_input_source *s = (hfs_input_source *)1;
    hfs_error err = {{0}};
    int r = hfs_gpio_source_create(&cfg, chip, &f->ops, &s, &err);
    CHECK(r == code && s == NULL, "%s: code %d (want %d)", chip, r, code);
    CHECK(strcmp(err.msg, msg) == 0, "message '%s' (want '%s')", err.msg, msg);
    hfs_input_source_destroy(s);
}

static void test_lookup_and_errors(void)
{
    fake_gpio f;
    fake_gpio_init(&f, "gpiochip0", "fake-gpio", 32);
    const char *names[] = {"gpiochip0", "fake-gpio", "/dev/gpiochip0"};
    for (int i = 0; i < 3; ++i) {
        hfs_input_config cfg;
        make_config(&cfg, names[i]);
        hfs_input_source *s = NULL;
        hfs_error err = {{0}};
        int r = hfs_gpio_source_create(&cfg, names[i], &f.ops, &s, &err);
        CHECK(r == 0, "chip by '%s': %s", names[i], err.msg);
        hfs_input_source_destroy(s);
    }
    expect_create_error(&f, "gpiochip7", HFS_E_IO, "gpio gpiochip7: no such chip");
    f.open_errno = EACCES;
    expect_create_error(&f, "gpiochip0", HFS_E_IO, "gpio gpiochip0: permission denied");
    f.open_errno = 0;
    f.busy_line = 18;
    expect_create_error(&f, "gpiochip0", HFS_E_IO,
                        "gpio gpiochip0: lines 17,18,22 busy (requested by another program)");
    f.busy_line = -1;
    f.n_lines = 20;
    expect_create_error(&f, "gpiochip0", HFS_E_IO,
                        "gpio gpiochip0: lines 17,18,22: no such line on this chip");
    f.n_lines = 32;
    CHECK(f.open_handles == 0, "failed creates leave nothing open (%d)", f.open_handles);

    /* Configuration problems, before any open. */
    hfs_input_config cfg;
    make_config(&cfg, "gpiochip0");
    add(&cfg, "clash", HFS_CONTROL_BUTTON, "gpiochip0", 18, 0);
    hfs_input_source *s = NULL;
    hfs_error err = {{0}};
    int r = hfs_gpio_source_create(&cfg, "gpiochip0", &f.ops, &s, &err);
    CHECK(r == HFS_E_INVALID &&
              strcmp(err.msg, "gpio gpiochip0: line 18 is used by both 'sun' and 'clash'") == 0,
          "line twice: %d '%s'", r, err.msg);
    r = hfs_gpio_source_create(&cfg, "gpiochip5", &f.ops, &s, &err);
    CHECK(r == HFS_E_INVALID &&
              strcmp(err.msg, "gpio gpiochip5: no control is wired to this chip") == 0,
          "no control: '%s'", err.msg);
    CHECK(f.opens == 5, "config errors open nothing (%d opens)", f.opens); /* 3 lookups + busy + bad line */
    fake_gpio_fini(&f);
}

/* With libgpiod but no chips (this CI machine) the real ops say so; where
 * libgpiod is missing they say "not built". */
static void test_real_ops_without_chip(void)
{
    hfs_input_config cfg;
    make_config(&cfg, "hfs-no-such-chip");
    hfs_input_source *s = NULL;
    hfs_error err = {{0}};
    int r = hfs_gpio_source_create(&cfg, "hfs-no-such-chip", NULL, &s, &err);
    if (hfs_gpio_available())
        CHECK(r == HFS_E_IO && strcmp(err.msg, "gpio hfs-no-such-chip: no such chip") == 0,
              "real ops, no chip: %d '%s'", r, err.msg);
    else
        CHECK(r == HFS_E_UNSUPPORTED, "not built: %d '%s'", r, err.msg);
    CHECK(s == NULL, "no source");
}

int main(void)
{
    test_knob_and_button();
    test_lookup_and_errors();
    test_real_ops_without_chip();
    if (failures)
        fprintf(stderr, "test_input_gpio: %d failure(s)\n", failures);
    return failures ? 1 : 0;
}
