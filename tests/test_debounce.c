/*
 * test_debounce.c — button debounce (board/debounce.h): clean presses,
 * bouncing contacts, glitches shorter than the settle time, late polls,
 * the queue's overflow rule and deadlines.  Times in ms for readability.
 */
#include "debounce.h"

#include <stdio.h>

#include "check.h"
#include "input.h"

#define MS(x) ((int64_t)((x) * 1000000.0))

/* Polls at now until nothing is left; writes kinds and times; returns how many. */
static int drain(hfs_debounce *d, int64_t now, int *kind, int64_t *t, int max)
{
    int n = 0;
    int64_t when;
    int k;
    while ((k = hfs_debounce_poll(d, now, &when)) != 0 && n < max) {
        kind[n] = k;
        t[n++] = when;
    }
    return n;
}

static void clean_press(void)
{
    hfs_debounce d;
    hfs_debounce_init(&d, MS(10), 0);
    int64_t t;
    CHECK(hfs_debounce_deadline(&d) == INT64_MAX, "idle deadline");
    hfs_debounce_edge(&d, 1, MS(100));
    CHECK(hfs_debounce_deadline(&d) == MS(110), "deadline after press edge");
    CHECK(hfs_debounce_poll(&d, MS(109.999), &t) == 0, "press before settle");
    CHECK(hfs_debounce_poll(&d, MS(110), &t) == HFS_INPUT_PRESS, "press at settle");
    CHECK(t == MS(100), "press time is the edge's");
    CHECK(hfs_debounce_poll(&d, MS(200), &t) == 0, "one press only");
    CHECK(hfs_debounce_deadline(&d) == INT64_MAX, "deadline after press");
    hfs_debounce_edge(&d, 0, MS(300));
    CHECK(hfs_debounce_poll(&d, MS(310), &t) == HFS_INPUT_RELEASE && t == MS(300), "release");
}

static void bounces(void)
{
    hfs_debounce d;
    hfs_debounce_init(&d, MS(10), 0);
    int kind[8];
    int64_t t[8];
    /* Press: five edges within 3 ms, ending down. */
    hfs_debounce_edge(&d, 1, MS(0));
    hfs_debounce_edge(&d, 0, MS(1));
    hfs_debounce_edge(&d, 1, MS(2));
    hfs_debounce_edge(&d, 0, MS(2.5));
    hfs_debounce_edge(&d, 1, MS(3));
    CHECK(drain(&d, MS(12.9), kind, t, 8) == 0, "bouncing press not confirmed early");
    CHECK(hfs_debounce_deadline(&d) == MS(13), "deadline follows the last bounce");
    CHECK(drain(&d, MS(13), kind, t, 8) == 1 && kind[0] == HFS_INPUT_PRESS && t[0] == MS(3),
          "one press, at the last bounce");
    /* Release: bounces, ending up. */
    hfs_debounce_edge(&d, 0, MS(500));
    hfs_debounce_edge(&d, 1, MS(500.2));
    hfs_debounce_edge(&d, 0, MS(501));
    hfs_debounce_edge(&d, 1, MS(504));
    hfs_debounce_edge(&d, 0, MS(505));
    const int n = drain(&d, MS(600), kind, t, 8);
    CHECK(n == 1 && kind[0] == HFS_INPUT_RELEASE && t[0] == MS(505), "one release");
}

static void glitches(void)
{
    hfs_debounce d;
    hfs_debounce_init(&d, MS(10), 0);
    int64_t t;
    hfs_debounce_edge(&d, 1, MS(0));
    hfs_debounce_edge(&d, 0, MS(9.9)); /* 9.9 ms < settle */
    CHECK(hfs_debounce_poll(&d, MS(50), &t) == 0, "glitch ignored");
    CHECK(hfs_debounce_deadline(&d) == INT64_MAX, "nothing pending after a glitch");
    /* A missed edge: the line reports the level it already had. */
    hfs_debounce_edge(&d, 0, MS(60));
    CHECK(hfs_debounce_poll(&d, MS(100), &t) == 0, "same-level edge gives nothing");
    /* Held at start-up: no event for the initial level. */
    hfs_debounce_init(&d, MS(10), 1);
    CHECK(hfs_debounce_poll(&d, MS(100), &t) == 0, "initial level is not an event");
    hfs_debounce_edge(&d, 0, MS(100));
    CHECK(hfs_debounce_poll(&d, MS(110), &t) == HFS_INPUT_RELEASE, "release of a held button");
}

static void late_poll(void)
{
    hfs_debounce d;
    hfs_debounce_init(&d, MS(10), 0);
    int kind[8];
    int64_t t[8];
    /* A 50 ms press fed as two edges before the first poll. */
    hfs_debounce_edge(&d, 1, MS(0));
    hfs_debounce_edge(&d, 0, MS(50));
    CHECK(hfs_debounce_deadline(&d) == MS(0), "queued event: deadline already due");
    const int n = drain(&d, MS(100), kind, t, 8);
    CHECK(n == 2 && kind[0] == HFS_INPUT_PRESS && t[0] == MS(0) &&
          kind[1] == HFS_INPUT_RELEASE && t[1] == MS(50), "late poll keeps the press");
}

static void overflow(void)
{
    hfs_debounce d;
    hfs_debounce_init(&d, MS(10), 0);
    int kind[8];
    int64_t t[8];
    /* Six 20 ms presses and releases, one poll: the queue (4) drops the
     * oldest pair, press@0 and release@20. */
    for (int i = 0; i < 6; ++i)
        hfs_debounce_edge(&d, i % 2 == 0, MS(20 * i));
    const int n = drain(&d, MS(200), kind, t, 8);
    CHECK(n == 4, "overflow: %d events", n);
    if (n == 4) {
        CHECK(kind[0] == HFS_INPUT_PRESS && t[0] == MS(40), "overflow 0");
        CHECK(kind[1] == HFS_INPUT_RELEASE && t[1] == MS(60), "overflow 1");
        CHECK(kind[2] == HFS_INPUT_PRESS && t[2] == MS(80), "overflow 2");
        CHECK(kind[3] == HFS_INPUT_RELEASE && t[3] == MS(100), "overflow 3");
    }
}

static void zero_settle(void)
{
    hfs_debounce d;
    hfs_debounce_init(&d, 0, 0);
    int64_t t;
    hfs_debounce_edge(&d, 1, MS(5));
    CHECK(hfs_debounce_deadline(&d) == MS(5), "settle 0: due at once");
    CHECK(hfs_debounce_poll(&d, MS(5), &t) == HFS_INPUT_PRESS && t == MS(5), "settle 0 press");
    /* Deadline saturates instead of overflowing. */
    hfs_debounce_init(&d, MS(10), 0);
    hfs_debounce_edge(&d, 1, INT64_MAX - 5);
    CHECK(hfs_debounce_deadline(&d) == INT64_MAX, "deadline saturates");
}

int main(void)
{
    clean_press();
    bounces();
    glitches();
    late_poll();
    overflow();
    zero_settle();
    if (failures)
        fprintf(stderr, "test_debounce: %d failure(s)\n", failures);
    return failures ? 1 : 0;
}
