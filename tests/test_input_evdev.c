/*
 * test_input_evdev.c — the evdev source against a scripted libevdev table.
 *
 * umockdev (test_input_evdev_umockdev) runs the real libevdev on an
 * emulated node but cannot make a read fail with ENODEV nor make the node
 * vanish under an open fd, so losses, reopen and the resync bookkeeping are
 * checked here: REL/ABS/KEY mapping with timestamps, ABS wrap, autorepeat
 * ignored, SYN_DROPPED resync (also across a full event array), device loss
 * -> HFS_E_IO naming the device, reopen failing while gone and working
 * when back, configuration errors, and the real libevdev table on paths
 * that are not input devices.
 */
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "input_evdev.h"

#define PATH "/dev/input/event3"

typedef struct fake_entry {
    int ret;                    /* HFS_EVDEV_EVENT or HFS_EVDEV_SYNC       */
    struct input_event ev;
} fake_entry;

typedef struct fake_evdev {
    hfs_evdev_ops ops;
    int present, open_errno;
    int open_handles;
    int abs_value;              /* ABS_WHEEL's state, 0..24               */
    fake_entry script[64];
    int pos, n;
} fake_evdev;


static void *fake_open(void *ctx, const char *path, int *mono)
{
    fake_evdev *f = ctx;
    if (f->open_errno || !f->present || strcmp(path, PATH) != 0) {
        errno = f->open_errno ? f->open_errno : ENOENT;
        return NULL;
    }
    *mono = 1;
    f->open_handles++;
    return f;
}

static int fake_fd(void *h) { (void)h; return 42; }

static int fake_has_code(void *h, unsigned type, unsigned code)
{
    (void)h;
    return (type == EV_REL && (code == REL_X || code == REL_Y)) ||
           (type == EV_ABS && code == ABS_WHEEL) ||
           (type == EV_KEY && (code == KEY_ENTER || code == KEY_A));
}

static int fake_abs_info(void *h, unsigned code, int *min, int *max, int *value)
{
    fake_evdev *f = h;
    if (code != ABS_WHEEL)
        return -EINVAL;
    *min = 0;
    *max = 24;
    *value = f->abs_value;
    return 0;
}

static int fake_next(void *h, int sync, struct input_event *ev)
{
    fake_evdev *f = h;
    if (!f->present)
        return -ENODEV;
    if (f->pos == f->n)
        return -EAGAIN;
    fake_entry *e = &f->script[f->pos];
    /* Sync mode sees only the resync's entries (ret SYNC after the
     * SYN_DROPPED); normal mode never sees them. */
    int is_sync_payload = e->ret == HFS_EVDEV_SYNC && e->ev.type != EV_SYN;
    if (sync != is_sync_payload)
        return -EAGAIN;
    f->pos++;
    *ev = e->ev;
    if (e->ev.type == EV_ABS)
        f->abs_value = e->ev.value;
    return e->ret;
}

static void fake_close(void *h)
{
    ((fake_evdev *)h)->open_handles--;
}

static void push(fake_evdev *f, int ret, int type, int code, int value, long sec, long usec)
{
    fake_entry *e = &f->script[f->n++];
    memset(e, 0, sizeof *e);
    e->ret = ret;
    e->ev.type = (unsigned short)type;
    e->ev.code = (unsigned short)code;
    e->ev.value = value;
    e->ev.input_event_sec = sec;
    e->ev.input_event_usec = usec;
}

static void fake_init(fake_evdev *f)
{
    memset(f, 0, sizeof *f);
    f->present = 1;
    f->abs_value = 5;
    f->ops.name = "fake";
    f->ops.ctx = f;
    f->ops.open = fake_open;
    f->ops.fd = fake_fd;
    f->ops.has_code = fake_has_code;
    f->ops.abs_info = fake_abs_info;
    f->ops.next_event = fake_next;
    f->ops.code_name = hfs_evdev_ops_libevdev()->code_name;
    f->ops.close = fake_close;
}

static hfs_control_config *add(hfs_input_config *cfg, const char *name, hfs_control_kind kind,
                               const char *path, int type, int code)
{
    hfs_control_config *c = &cfg->control[cfg->n_controls++];
    memset(c, 0, sizeof *c);
    snprintf(c->name, sizeof c->name, "%s", name);
    c->kind = kind;
    c->device = HFS_DEVICE_EVDEV;
    snprintf(c->path, sizeof c->path, "%s", path);
    c->evdev_type = type;
    c->evdev_code = code;
    return c;
}

static void make_config(hfs_input_config *cfg)
{
    memset(cfg, 0, sizeof *cfg);
    add(cfg, "dial", HFS_CONTROL_KNOB, PATH, EV_REL, REL_X);
    add(cfg, "wheel", HFS_CONTROL_KNOB, PATH, EV_ABS, ABS_WHEEL);
    add(cfg, "ok", HFS_CONTROL_BUTTON, PATH, EV_KEY, KEY_ENTER);
    add(cfg, "elsewhere", HFS_CONTROL_BUTTON, "/dev/input/event4", EV_KEY, KEY_UP);
}

#define T(sec, usec) ((int64_t)(sec) * 1000000000 + (int64_t)(usec) * 1000)

static int expect(const hfs_input_event *e, hfs_input_kind kind, int delta, const char *control,
                  int64_t t)
{
    return e->kind == kind && e->delta == delta && strcmp(e->control, control) == 0 &&
           e->t_ns == t;
}

static void test_events(void)
{
    fake_evdev f;
    fake_init(&f);
    hfs_input_config cfg;
    make_config(&cfg);
    hfs_input_source *s = NULL;
    hfs_error err = {{0}};
    int r = hfs_evdev_source_create(&cfg, PATH, &f.ops, &s, &err);
    CHECK(r == 0 && s, "create: %d %s", r, err.msg);
    if (!s)
        return;
    CHECK(strcmp(s->name, "evdev " PATH) == 0 && strcmp(s->ops->kind, "evdev") == 0, "name");
    CHECK(hfs_input_source_fd(s) == 42, "fd");
    CHECK(hfs_evdev_source_monotonic(s), "monotonic clock accepted");
    CHECK(hfs_input_source_deadline(s) == INT64_MAX, "no deadline");

    push(&f, 0, EV_REL, REL_X, 1, 10, 1);
    push(&f, 0, EV_SYN, SYN_REPORT, 0, 10, 1);
    push(&f, 0, EV_REL, REL_X, -2, 10, 500000);
    push(&f, 0, EV_REL, REL_Y, 3, 10, 500000);      /* not configured */
    push(&f, 0, EV_ABS, ABS_WHEEL, 6, 11, 0);       /* 5 -> 6: +1 */
    push(&f, 0, EV_ABS, ABS_WHEEL, 4, 11, 1);       /* -2 */
    push(&f, 0, EV_ABS, ABS_WHEEL, 0, 11, 2);       /* -4 */
    push(&f, 0, EV_ABS, ABS_WHEEL, 23, 11, 3);      /* wrap: -1 */
    push(&f, 0, EV_ABS, ABS_WHEEL, 0, 11, 4);       /* wrap: +1 */
    push(&f, 0, EV_KEY, KEY_ENTER, 1, 12, 0);
    push(&f, 0, EV_KEY, KEY_ENTER, 2, 12, 250000);  /* autorepeat */
    push(&f, 0, EV_KEY, KEY_A, 1, 12, 300000);      /* not configured */
    push(&f, 0, EV_KEY, KEY_ENTER, 0, 12, 400000);
    hfs_input_event ev[32];
    int n = hfs_input_source_read(s, 0, ev, 32, &err);
    CHECK(n == 9, "9 events, got %d", n);
    if (n == 9) {
        CHECK(expect(&ev[0], HFS_INPUT_TURN, 1, "dial", T(10, 1)), "rel +1");
        CHECK(expect(&ev[1], HFS_INPUT_TURN, -2, "dial", T(10, 500000)), "rel -2");
        CHECK(expect(&ev[2], HFS_INPUT_TURN, 1, "wheel", T(11, 0)), "abs +1");
        CHECK(expect(&ev[3], HFS_INPUT_TURN, -2, "wheel", T(11, 1)), "abs -2");
        CHECK(expect(&ev[4], HFS_INPUT_TURN, -4, "wheel", T(11, 2)), "abs -4");
        CHECK(expect(&ev[5], HFS_INPUT_TURN, -1, "wheel", T(11, 3)), "abs wrap down: %d",
              ev[5].delta);
        CHECK(expect(&ev[6], HFS_INPUT_TURN, 1, "wheel", T(11, 4)), "abs wrap up: %d",
              ev[6].delta);
        CHECK(expect(&ev[7], HFS_INPUT_PRESS, 0, "ok", T(12, 0)), "press");
        CHECK(expect(&ev[8], HFS_INPUT_RELEASE, 0, "ok", T(12, 400000)), "release");
    }

    /* SYN_DROPPED: the resync reports the key released and the wheel moved
     * (0 -> 3); an array of one slot makes it span several reads. */
    push(&f, 0, EV_KEY, KEY_ENTER, 1, 13, 0);
    push(&f, HFS_EVDEV_SYNC, EV_SYN, SYN_DROPPED, 0, 13, 5);
    push(&f, HFS_EVDEV_SYNC, EV_KEY, KEY_ENTER, 0, 13, 5);
    push(&f, HFS_EVDEV_SYNC, EV_ABS, ABS_WHEEL, 3, 13, 5);
    push(&f, HFS_EVDEV_SYNC, EV_SYN, SYN_REPORT, 0, 13, 5);
    push(&f, 0, EV_REL, REL_X, 1, 14, 0);
    hfs_input_event all[8];
    int total = 0;
    for (int i = 0; i < 10 && total < 8; ++i) {
        n = hfs_input_source_read(s, 0, ev, 1, &err);
        CHECK(n >= 0, "read: %s", err.msg);
        if (n == 1)
            all[total++] = ev[0];
        if (n == 0)
            break;
        CHECK(hfs_input_source_deadline(s) == INT64_MIN, "full array: deadline now");
    }
    CHECK(total == 4, "press, synced release, synced turn, turn: %d", total);
    if (total == 4) {
        CHECK(expect(&all[0], HFS_INPUT_PRESS, 0, "ok", T(13, 0)), "press before the drop");
        CHECK(expect(&all[1], HFS_INPUT_RELEASE, 0, "ok", T(13, 5)), "release from resync");
        CHECK(expect(&all[2], HFS_INPUT_TURN, 3, "wheel", T(13, 5)), "turn from resync: %d",
              all[2].delta);
        CHECK(expect(&all[3], HFS_INPUT_TURN, 1, "dial", T(14, 0)), "normal reading after");
    }
    CHECK(hfs_input_source_deadline(s) == INT64_MAX, "caught up");

    /* Unplugged. */
    f.present = 0;
    r = hfs_input_source_read(s, 0, ev, 8, &err);
    CHECK(r == HFS_E_IO && strcmp(err.msg, "evdev " PATH ": device removed (No such device)") == 0,
          "loss: %d '%s'", r, err.msg);
    CHECK(hfs_input_source_fd(s) == -1 && f.open_handles == 0, "closed on loss");
    r = hfs_input_source_reopen(s, &err);
    CHECK(r == HFS_E_IO && strcmp(err.msg, "evdev " PATH ": no such device") == 0,
          "reopen while gone: '%s'", err.msg);
    f.present = 1;
    f.open_errno = EACCES;
    r = hfs_input_source_reopen(s, &err);
    CHECK(r == HFS_E_IO && strcmp(err.msg, "evdev " PATH ": permission denied") == 0,
          "reopen denied: '%s'", err.msg);
    f.open_errno = 0;
    f.abs_value = 20;       /* the wheel moved while away: no event for it */
    r = hfs_input_source_reopen(s, &err);
    CHECK(r == 0 && f.open_handles == 1, "reopen: %d %s", r, err.msg);
    push(&f, 0, EV_ABS, ABS_WHEEL, 21, 20, 0);
    n = hfs_input_source_read(s, 0, ev, 8, &err);
    CHECK(n == 1 && expect(&ev[0], HFS_INPUT_TURN, 1, "wheel", T(20, 0)),
          "events flow again, from the state at reopen: n %d", n);
    hfs_input_source_destroy(s);
    CHECK(f.open_handles == 0, "destroy closes");
}

static void expect_error(hfs_input_config *cfg, const char *path, const hfs_evdev_ops *ops,
                         int code, const char *msg)
{
    hfs_input_source *s = (hfs_input_source *)1;
    hfs_error err = {{0}};
    int r = hfs_evdev_source_create(cfg, path, ops, &s, &err);
    CHECK(r == code && s == NULL, "%s: %d (want %d) '%s'", path, r, code, err.msg);
    CHECK(strcmp(err.msg, msg) == 0, "message '%s' (want '%s')", err.msg, msg);
}

static void test_errors(void)
{
    fake_evdev f;
    fake_init(&f);
    hfs_input_config cfg;
    make_config(&cfg);
    add(&cfg, "x", HFS_CONTROL_KNOB, PATH, EV_REL, REL_DIAL);
    expect_error(&cfg, PATH, &f.ops, HFS_E_INVALID,
                 "evdev " PATH ": the device has no REL_DIAL (control 'x')");
    CHECK(f.open_handles == 0, "closed after a failed check");
    make_config(&cfg);
    add(&cfg, "k", HFS_CONTROL_KNOB, PATH, EV_KEY, KEY_A);
    expect_error(&cfg, PATH, &f.ops, HFS_E_INVALID,
                 "evdev " PATH ": knob 'k' needs an EV_REL or EV_ABS code, not EV_KEY");
    make_config(&cfg);
    add(&cfg, "b", HFS_CONTROL_BUTTON, PATH, EV_REL, REL_Y);
    expect_error(&cfg, PATH, &f.ops, HFS_E_INVALID,
                 "evdev " PATH ": button 'b' needs an EV_KEY code, not EV_REL");
    make_config(&cfg);
    add(&cfg, "again", HFS_CONTROL_BUTTON, PATH, EV_KEY, KEY_ENTER);
    expect_error(&cfg, PATH, &f.ops, HFS_E_INVALID,
                 "evdev " PATH ": KEY_ENTER is used by both 'ok' and 'again'");
    make_config(&cfg);
    expect_error(&cfg, "/dev/input/event9", &f.ops, HFS_E_INVALID,
                 "evdev /dev/input/event9: no control uses this device");

    /* The real libevdev table. */
    make_config(&cfg);
    add(&cfg, "gone", HFS_CONTROL_BUTTON, "/nonexistent/event99", EV_KEY, KEY_A);
    expect_error(&cfg, "/nonexistent/event99", NULL, HFS_E_IO,
                 "evdev /nonexistent/event99: no such device");
    add(&cfg, "null", HFS_CONTROL_BUTTON, "/dev/null", EV_KEY, KEY_A);
    expect_error(&cfg, "/dev/null", NULL, HFS_E_IO, "evdev /dev/null: not an input device");
}

int main(void)
{
    test_events();
    test_errors();
    if (failures)
        fprintf(stderr, "test_input_evdev: %d failure(s)\n", failures);
    return failures ? 1 : 0;
}
