/*
 * test_input_replay.c — the scripted source (board/input_replay.h): when
 * events come out (start + TIME_MS, never early, with their own time, in
 * file order, max per call), its deadline and fd, the end, and bad files
 * (each tests/data/input/bad_replay_*.txt says on line 1 what is wrong).
 * Argument: the data directory.
 */
#include "input_replay.h"

#include <stdio.h>
#include <string.h>

#include "check.h"

#define MS(x) ((int64_t)((x) * 1000000.0))
#define START ((int64_t)5000000000)

static const char *data_dir;

static void timing(void)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/replay_ok.txt", data_dir);
    hfs_input_source *src = NULL;
    hfs_error err = {{0}};
    CHECK(hfs_replay_source_create(path, START, &src, &err) == 0, "create: %s", err.msg);
    if (!src)
        return;
    hfs_input_event ev[8];
    CHECK(!strcmp(src->ops->kind, "replay"), "kind");
    CHECK(!strncmp(src->name, "replay ", 7), "name '%s'", src->name);
    CHECK(hfs_replay_source_count(src) == 5, "5 events");
    CHECK(hfs_input_source_fd(src) == -1, "no fd");
    CHECK(hfs_input_source_deadline(src) == START, "first deadline");
    CHECK(hfs_input_source_read(src, START - 1, ev, 8, &err) == 0, "nothing before start");
    CHECK(hfs_input_source_read(src, START, ev, 8, &err) == 1 && ev[0].t_ns == START &&
              ev[0].kind == HFS_INPUT_TURN && ev[0].delta == 1 && !strcmp(ev[0].control, "az"),
          "event 1 at start");
    CHECK(hfs_input_source_deadline(src) == START + MS(10), "deadline: event 2");
    CHECK(hfs_input_source_read(src, START + MS(20), ev, 1, &err) == 1 &&
              ev[0].t_ns == START + MS(10) && ev[0].delta == -2,
          "max = 1: event 2 only, with its own time");
    CHECK(hfs_input_source_deadline(src) == START + MS(10), "event 3 due at the same time");
    CHECK(hfs_input_source_read(src, START + MS(20), ev, 8, &err) == 1 &&
              ev[0].kind == HFS_INPUT_PRESS && !strcmp(ev[0].control, "next"),
          "event 3");
    CHECK(hfs_input_source_read(src, START + MS(25.4), ev, 8, &err) == 0, "25.4 ms: nothing");
    CHECK(hfs_input_source_deadline(src) == START + MS(25.5), "fractional deadline");
    CHECK(hfs_replay_source_finished(src) == 0, "not finished");
    CHECK(hfs_input_source_read(src, START + MS(5000), ev, 8, &err) == 2 &&
              ev[0].kind == HFS_INPUT_RELEASE && ev[0].t_ns == START + MS(25.5) &&
              ev[1].delta == 3 && ev[1].t_ns == START + MS(1000),
          "the last two together");
    CHECK(hfs_replay_source_finished(src) == 1, "finished");
    CHECK(hfs_input_source_deadline(src) == INT64_MAX, "no deadline after the end");
    CHECK(hfs_input_source_fd(src) == -1, "no fd after the end");
    CHECK(hfs_input_source_read(src, INT64_MAX, ev, 8, &err) == 0, "nothing after the end");
    CHECK(hfs_input_source_reopen(src, &err) == 0, "reopen is harmless");
    hfs_input_source_destroy(src);
    hfs_input_source_destroy(NULL);

    /* A start time that would overflow. */
    src = (hfs_input_source *)1;
    CHECK(hfs_replay_source_create(path, INT64_MAX - 5, &src, &err) == HFS_E_INVALID &&
              src == NULL,
          "start out of range: %s", err.msg);
}

typedef struct bad_case {
    const char *file;
    int code;
    const char *expect; /* the message after "PATH" */
} bad_case;

static const bad_case bad[] = {
    {"bad_replay_backwards.txt", HFS_E_FORMAT, ":3: time 9.5 ms goes backwards"},
    {"bad_replay_verb.txt", HFS_E_FORMAT, ":2: unknown event 'twist' (turn, press, release)"},
    {"bad_replay_zero.txt", HFS_E_FORMAT, ":2: turn needs a non-zero integer of detents in "
     "[-10000, 10000]"},
    {"bad_replay_count.txt", HFS_E_FORMAT, ":2: turn needs a non-zero integer of detents in "
     "[-10000, 10000]"},
    {"bad_replay_overflow.txt", HFS_E_FORMAT, ":2: turn needs a non-zero integer of detents "
     "in [-10000, 10000]"},
    {"bad_replay_nocount.txt", HFS_E_FORMAT, ":2: turn needs a non-zero integer of detents "
     "in [-10000, 10000]"},
    {"bad_replay_nan.txt", HFS_E_FORMAT, ":2: time 'nan' is not a number of milliseconds in "
     "[0, 1000000000]"},
    {"bad_replay_negative.txt", HFS_E_FORMAT, ":2: time '-1' is not a number of milliseconds "
     "in [0, 1000000000]"},
    {"bad_replay_exponent.txt", HFS_E_FORMAT, ":2: time '1e3' is not a number of "
     "milliseconds in [0, 1000000000]"},
    {"bad_replay_late.txt", HFS_E_FORMAT, ":2: time '1000000001' is not a number of "
     "milliseconds in [0, 1000000000]"},
    {"bad_replay_extra.txt", HFS_E_FORMAT, ":2: unexpected 'now' after press"},
    {"bad_replay_short.txt", HFS_E_FORMAT, ":2: expected 'TIME_MS CONTROL turn "
     "N|press|release'"},
    {"bad_replay_name.txt", HFS_E_FORMAT, ":2: 'a/z' is not a control name (1 to 31 letters, "
     "digits, '_', '-', '.')"},
    {"bad_replay_tokens.txt", HFS_E_FORMAT, ":2: unexpected '2' after the event"},
    {"bad_replay_long.txt", HFS_E_FORMAT, ":2: line longer than 255 characters"},
    {"missing.txt", HFS_E_IO, ": cannot open replay file: No such file or directory"},
};

static void broken(void)
{
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        char path[1024], want[2048];
        snprintf(path, sizeof path, "%s/%s", data_dir, bad[i].file);
        snprintf(want, sizeof want, "%s%s", path, bad[i].expect);
        hfs_input_source *src = NULL;
        hfs_error err = {{0}};
        const int rc = hfs_replay_source_create(path, 0, &src, &err);
        CHECK(rc == bad[i].code, "%s: returned %d (%s)", bad[i].file, rc, err.msg);
        CHECK(!strcmp(err.msg, want), "%s:\n  got  '%s'\n  want '%s'", bad[i].file, err.msg,
              want);
        CHECK(src == NULL, "%s: no source on failure", bad[i].file);
        hfs_input_source_destroy(src);
    }
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: test_input_replay DATA_DIR\n");
        return 2;
    }
    data_dir = argv[1];
    timing();
    broken();
    if (failures)
        fprintf(stderr, "test_input_replay: %d failure(s)\n", failures);
    return failures ? 1 : 0;
}
