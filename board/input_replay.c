/*
 * input_replay.c — the scripted input source (input_replay.h).
 *
 * The file is read and checked whole at creation, so a bad script fails
 * before the kiosk starts rather than in the middle of a demo.  Numbers are
 * checked by their characters before strtod/strtol see them: strtod would
 * otherwise accept "inf", "nan" and "0x1p3", and strtol leading blanks.
 */
#include "file_input.h"
#include "input_replay.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define REPLAY_FILE_MAX (16 << 20)
#define REPLAY_LINE_MAX 255
#define REPLAY_EVENTS_MAX 1000000
#define REPLAY_MS_MAX 1e9   /* 11.6 days; keeps start + offset far from overflow */
#define REPLAY_TURN_MAX 10000

typedef struct replay {
    hfs_input_source base;   /* first: the source header (input.h) */
    hfs_input_event *events; /* t_ns absolute, file order          */
    int n, cap;
    int next;                /* first event not read yet           */
} replay;

static const hfs_input_source_ops replay_ops;

static replay *as_replay(hfs_input_source *src)
{
    return src && src->ops == &replay_ops ? (replay *)src : NULL;
}

/* ---- the source ops -------------------------------------------------- */

static int replay_fd(hfs_input_source *src)
{
    (void)src;
    return -1;
}

static int64_t replay_deadline(hfs_input_source *src)
{
    const replay *r = (const replay *)src;
    return r->next < r->n ? r->events[r->next].t_ns : INT64_MAX;
}

static int replay_read(hfs_input_source *src, int64_t now_ns, hfs_input_event *out, int max,
                       hfs_error *err)
{
    (void)err;
    replay *r = (replay *)src;
    int got = 0;
    while (got < max && r->next < r->n && r->events[r->next].t_ns <= now_ns)
        out[got++] = r->events[r->next++];
    return got;
}

static int replay_reopen(hfs_input_source *src, hfs_error *err)
{
    (void)src;
    (void)err;
    return HFS_OK;
}

static void replay_destroy(hfs_input_source *src)
{
    replay *r = (replay *)src;
    free(r->events);
    free(r);
}

static const hfs_input_source_ops replay_ops = {
    .kind = "replay",
    .fd = replay_fd,
    .deadline_ns = replay_deadline,
    .read = replay_read,
    .reopen = replay_reopen,
    .destroy = replay_destroy,
};

int hfs_replay_source_finished(hfs_input_source *src)
{
    const replay *r = as_replay(src);
    return r ? r->next >= r->n : -1;
}

int hfs_replay_source_count(hfs_input_source *src)
{
    const replay *r = as_replay(src);
    return r ? r->n : -1;
}

/* ---- parsing --------------------------------------------------------- */

static int only_chars(const char *s, const char *allowed)
{
    return *s && strspn(s, allowed) == strlen(s);
}

static int valid_name(const char *s)
{
    return strlen(s) < HFS_CONTROL_NAME_MAX &&
           only_chars(s, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-.");
}

/* Milliseconds as "123", "12.5", ".5": digits and at most one point. */
static int parse_ms(const char *s, double *out)
{
    const char *dot = strchr(s, '.');
    if (!only_chars(s, "0123456789.") || (dot && strchr(dot + 1, '.')) || !strcmp(s, "."))
        return -1;
    char *end;
    errno = 0;
    const double x = strtod(s, &end);
    if (*end || errno == ERANGE || !isfinite(x) || x > REPLAY_MS_MAX)
        return -1;
    *out = x;
    return 0;
}

static int parse_turn(const char *s, int *out)
{
    const char *digits = (*s == '+' || *s == '-') ? s + 1 : s;
    if (!only_chars(digits, "0123456789"))
        return -1;
    char *end;
    errno = 0;
    const long x = strtol(s, &end, 10);
    if (*end || errno == ERANGE || x == 0 || x < -REPLAY_TURN_MAX || x > REPLAY_TURN_MAX)
        return -1;
    *out = (int)x;
    return 0;
}

static int push(replay *r, const hfs_input_event *ev)
{
    if (r->n == r->cap) {
        const int cap = r->cap ? 2 * r->cap : 64;
        hfs_input_event *grown = realloc(r->events, (size_t)cap * sizeof *grown);
        if (!grown)
            return -1;
        r->events = grown;
        r->cap = cap;
    }
    r->events[r->n++] = *ev;
    return 0;
}

/* One line (NUL-terminated, comment and all).  *last_ns: the previous
 * event's time, for the order check. */
static int parse_line(replay *r, char *line, const char *path, int lineno, int64_t start_ns,
                      int64_t *last_ns, hfs_error *err)
{
    char *hash = strchr(line, '#');
    if (hash)
        *hash = '\0';
    char *save = NULL;
    char *tok[5];
    int n = 0;
    for (char *t = strtok_r(line, " \t\r", &save); t; t = strtok_r(NULL, " \t\r", &save)) {
        if (n == 4)
            return hfs_fail(err, HFS_E_FORMAT, "%s:%d: unexpected '%s' after the event", path,
                            lineno, t);
        tok[n++] = t;
    }
    if (n == 0)
        return HFS_OK;
    if (n < 3)
        return hfs_fail(err, HFS_E_FORMAT, "%s:%d: expected 'TIME_MS CONTROL turn N|press|"
                        "release'", path, lineno);

    double ms;
    if (parse_ms(tok[0], &ms))
        return hfs_fail(err, HFS_E_FORMAT, "%s:%d: time '%s' is not a number of milliseconds "
                        "in [0, %.0f]", path, lineno, tok[0], REPLAY_MS_MAX);
    const int64_t t_ns = start_ns + llround(ms * 1e6);
    if (r->n > 0 && t_ns < *last_ns)
        return hfs_fail(err, HFS_E_FORMAT, "%s:%d: time %s ms goes backwards", path, lineno,
                        tok[0]);
    if (!valid_name(tok[1]))
        return hfs_fail(err, HFS_E_FORMAT, "%s:%d: '%s' is not a control name (1 to %d "
                        "letters, digits, '_', '-', '.')", path, lineno, tok[1],
                        HFS_CONTROL_NAME_MAX - 1);

    hfs_input_event ev;
    memset(&ev, 0, sizeof ev);
    ev.t_ns = t_ns;
    snprintf(ev.control, sizeof ev.control, "%s", tok[1]);
    if (!strcmp(tok[2], "turn")) {
        if (n != 4 || parse_turn(tok[3], &ev.delta))
            return hfs_fail(err, HFS_E_FORMAT, "%s:%d: turn needs a non-zero integer of "
                            "detents in [-%d, %d]", path, lineno, REPLAY_TURN_MAX,
                            REPLAY_TURN_MAX);
        ev.kind = HFS_INPUT_TURN;
    } else if (!strcmp(tok[2], "press") || !strcmp(tok[2], "release")) {
        if (n != 3)
            return hfs_fail(err, HFS_E_FORMAT, "%s:%d: unexpected '%s' after %s", path, lineno,
                            tok[3], tok[2]);
        ev.kind = tok[2][0] == 'p' ? HFS_INPUT_PRESS : HFS_INPUT_RELEASE;
    } else {
        return hfs_fail(err, HFS_E_FORMAT, "%s:%d: unknown event '%s' (turn, press, release)",
                        path, lineno, tok[2]);
    }
    if (r->n >= REPLAY_EVENTS_MAX)
        return hfs_fail(err, HFS_E_FORMAT, "%s:%d: more than %d events", path, lineno,
                        REPLAY_EVENTS_MAX);
    if (push(r, &ev))
        return hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", path);
    *last_ns = t_ns;
    return HFS_OK;
}

static int parse_text(replay *r, char *text, size_t size, const char *path, int64_t start_ns,
                      hfs_error *err)
{
    int64_t last_ns = 0;
    int lineno = 0;
    char *p = text;
    while (p < text + size) {
        char *nl = memchr(p, '\n', (size_t)(text + size - p));
        char *end = nl ? nl : text + size;
        lineno++;
        if (end - p > REPLAY_LINE_MAX)
            return hfs_fail(err, HFS_E_FORMAT, "%s:%d: line longer than %d characters", path,
                            lineno, REPLAY_LINE_MAX);
        *end = '\0';
        int rc = parse_line(r, p, path, lineno, start_ns, &last_ns, err);
        if (rc)
            return rc;
        p = end + 1;
    }
    return HFS_OK;
}

/* ---- creation -------------------------------------------------------- */

static int read_text(const char *path, char **text, size_t *size, hfs_error *err)
{
    return hfs_read_text_file(path, "replay file", REPLAY_FILE_MAX, text, size, err);
}

int hfs_replay_source_create(const char *path, int64_t start_ns, hfs_input_source **out,
                             hfs_error *err)
{
    *out = NULL;
    if (start_ns < 0 || start_ns > INT64_MAX - (int64_t)(REPLAY_MS_MAX * 1e6))
        return hfs_fail(err, HFS_E_INVALID, "%s: start time %lld ns out of range", path,
                        (long long)start_ns);
    char *text = NULL;
    size_t size = 0;
    int rc = read_text(path, &text, &size, err);
    if (rc)
        return rc;
    replay *r = calloc(1, sizeof *r);
    if (!r) {
        rc = hfs_fail(err, HFS_E_NOMEM, "%s: out of memory", path);
        goto err_text;
    }
    r->base.ops = &replay_ops;
    snprintf(r->base.name, sizeof r->base.name, "replay %s", path);
    rc = parse_text(r, text, size, path, start_ns, err);
    if (rc)
        goto err_replay;
    free(text);
    *out = &r->base;
    return HFS_OK;

err_replay:
    replay_destroy(&r->base);
err_text:
    free(text);
    return rc;
}
