/*
 * input_config.c — the input configuration file (input_config.h), parsed by
 * libinih; docs/INPUT.md is the reference for every key.
 *
 * Line numbers.  Debian's inih gives no line to the handler, so we feed it
 * through ini_parse_stream with our own line reader, which counts lines and
 * remembers where each [section] header is.  The reader also strips leading
 * blanks: inih would otherwise read an indented line as the continuation of
 * the previous value, and "  step = 2" would silently become part of it.
 *
 * Checks happen in two places: a value's syntax and range at its own line;
 * what depends on the whole section (the action's defaults, which keys make
 * sense for it, min < max) when the section ends, at the line of the key
 * concerned.  The first error wins and parsing stops there.
 */
#include "file_input.h"
#include "input_config.h"

#include <ini.h>
#include <libevdev/libevdev.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define CONFIG_FILE_MAX (1 << 20)
#define CONFIG_LINE_MAX 190   /* inih's line buffer is 200 with the newline */
#define GPIO_LINE_MAX 65535

/* ---- keys ------------------------------------------------------------ */

typedef enum key_id {
    K_GPIO, K_EVDEV, K_STEPS, K_ACTIVE_LOW, K_DEBOUNCE, K_ACTION, K_LIGHT,
    K_STEP, K_ACCEL, K_ACCEL_MS, K_MIN, K_MAX, K_WRAP, K_COUNT
} key_id;

static const char *const key_names[K_COUNT] = {
    [K_GPIO] = "gpio", [K_EVDEV] = "evdev", [K_STEPS] = "steps_per_detent",
    [K_ACTIVE_LOW] = "active_low", [K_DEBOUNCE] = "debounce_ms",
    [K_ACTION] = "action", [K_LIGHT] = "light", [K_STEP] = "step",
    [K_ACCEL] = "accel", [K_ACCEL_MS] = "accel_ms", [K_MIN] = "min",
    [K_MAX] = "max", [K_WRAP] = "wrap",
};

/* ---- parser state ---------------------------------------------------- */

typedef struct parse_ctx {
    const char *path;
    hfs_input_config *cfg;

    /* The line reader. */
    const char *next;       /* start of the next line in the text          */
    int line;               /* number of the line last handed to inih      */
    int header_line;        /* line of the last [section] header           */
    int header_seq;         /* headers seen so far                         */
    int header_keys;        /* keys seen since that header                 */

    /* The section being read. */
    int section_seq;        /* header_seq of the current control, 0: none  */
    hfs_control_config *cur;
    int key_line[K_COUNT];  /* where each key of the section was, 0: not   */

    int in_capture;         /* the current section is a [capture NAME]     */

    int failed;
    int fail_line;          /* reader's line when the error was found      */
    hfs_error first;
} parse_ctx;

static int fail_at(parse_ctx *c, int line, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static int fail_at(parse_ctx *c, int line, const char *fmt, ...)
{
    if (c->failed)
        return 0;
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    hfs_fail(&c->first, HFS_E_FORMAT, "%s:%d: %s", c->path, line, msg);
    c->failed = 1;
    c->fail_line = c->line;
    return 0;
}

/* ---- values ---------------------------------------------------------- */

static int parse_long(const char *v, long lo, long hi, long *out)
{
    char *end;
    errno = 0;
    const long x = strtol(v, &end, 10);
    if (end == v || *end != '\0' || errno == ERANGE || x < lo || x > hi)
        return -1;
    *out = x;
    return 0;
}

static int parse_double(const char *v, double *out)
{
    char *end;
    errno = 0;
    const double x = strtod(v, &end);
    if (end == v || *end != '\0' || errno == ERANGE || !isfinite(x))
        return -1;
    *out = x;
    return 0;
}

static int parse_bool(const char *v, int *out)
{
    static const char *const yes[] = {"yes", "true", "on", "1"};
    static const char *const no[] = {"no", "false", "off", "0"};
    for (int i = 0; i < 4; ++i) {
        if (!strcmp(v, yes[i]))
            return *out = 1, 0;
        if (!strcmp(v, no[i]))
            return *out = 0, 0;
    }
    return -1;
}

/* "DEVICE:REST" split at the last colon (a chip label may hold none, a
 * path none either; the part after it never does). */
static int split_device(const char *v, char *dev, size_t dev_size, const char **rest)
{
    const char *colon = strrchr(v, ':');
    if (!colon || colon == v || (size_t)(colon - v) >= dev_size)
        return -1;
    memcpy(dev, v, (size_t)(colon - v));
    dev[colon - v] = '\0';
    *rest = colon + 1;
    return 0;
}

static int set_gpio(parse_ctx *c, hfs_control_config *k, const char *v)
{
    const int knob = k->kind == HFS_CONTROL_KNOB;
    const char *want = knob ? "CHIP:A,B" : "CHIP:LINE";
    const char *lines;
    if (split_device(v, k->path, sizeof k->path, &lines))
        return fail_at(c, c->line, "gpio: '%s' is not %s", v, want);
    char buf[64];
    if (strlen(lines) >= sizeof buf)
        return fail_at(c, c->line, "gpio: '%s' is not %s", v, want);
    strcpy(buf, lines);
    char *comma = strchr(buf, ',');
    if (knob != (comma != NULL))
        return fail_at(c, c->line, "gpio: '%s' is not %s", v, want);
    if (comma)
        *comma = '\0';
    long a, b = 0;
    if (parse_long(buf, 0, GPIO_LINE_MAX, &a) ||
        (comma && parse_long(comma + 1, 0, GPIO_LINE_MAX, &b)))
        return fail_at(c, c->line, "gpio: line offsets in '%s' must be integers in [0, %d]",
                       v, GPIO_LINE_MAX);
    if (knob && a == b)
        return fail_at(c, c->line, "gpio: A and B are the same line (%ld)", a);
    k->device = HFS_DEVICE_GPIO;
    k->lines[0] = (int)a;
    k->lines[1] = (int)b;
    return 1;
}

static int set_evdev(parse_ctx *c, hfs_control_config *k, const char *v)
{
    const int knob = k->kind == HFS_CONTROL_KNOB;
    const char *code;
    if (split_device(v, k->path, sizeof k->path, &code) || !*code)
        return fail_at(c, c->line, "evdev: '%s' is not DEVICE:CODE (e.g. %s)", v,
                       knob ? "/dev/input/event0:REL_DIAL" : "/dev/input/event0:KEY_ENTER");
    const int type = libevdev_event_type_from_code_name(code);
    const int num = libevdev_event_code_from_code_name(code);
    if (type < 0 || num < 0)
        return fail_at(c, c->line, "evdev: unknown event code '%s'", code);
    if (knob ? (type != EV_REL && type != EV_ABS) : type != EV_KEY)
        return fail_at(c, c->line, "evdev: a %s needs %s, not %s", knob ? "knob" : "button",
                       knob ? "a REL_ or ABS_ code" : "a KEY_ or BTN_ code", code);
    k->device = HFS_DEVICE_EVDEV;
    k->evdev_type = type;
    k->evdev_code = num;
    return 1;
}

static int set_light(parse_ctx *c, hfs_control_config *k, const char *v)
{
    long n;
    if (!strcmp(v, "selected")) {
        k->light = -1;
        return 1;
    }
    /* The upper bound depends on the action; checked when the section ends. */
    if (parse_long(v, 0, HFS_MAX_LOCAL_LIGHTS - 1, &n))
        return fail_at(c, c->line, "light: '%s' is not 'selected' or an index in [0, %d]", v,
                       HFS_MAX_LOCAL_LIGHTS - 1);
    k->light = (int)n;
    return 1;
}

static int set_double(parse_ctx *c, const char *key, const char *v, double lo, double hi,
                      double *out)
{
    double x;
    if (parse_double(v, &x))
        return fail_at(c, c->line, "%s: '%s' is not a number", key, v);
    if (x < lo || x > hi)
        return fail_at(c, c->line, "%s: %g is out of range [%g, %g]", key, x, lo, hi);
    *out = x;
    return 1;
}

static int set_value(parse_ctx *c, hfs_control_config *k, key_id id, const char *v)
{
    long n;
    switch (id) {
    case K_GPIO:
    case K_EVDEV:
        if (c->key_line[id == K_GPIO ? K_EVDEV : K_GPIO])
            return fail_at(c, c->line, "gpio and evdev both given: a control is wired to "
                           "one device (or none, for replay)");
        return id == K_GPIO ? set_gpio(c, k, v) : set_evdev(c, k, v);
    case K_STEPS:
        if (parse_long(v, 1, 4, &n) || n == 3)
            return fail_at(c, c->line, "steps_per_detent: '%s' is not 1, 2 or 4", v);
        k->steps_per_detent = (int)n;
        return 1;
    case K_ACTIVE_LOW:
        if (parse_bool(v, &k->active_low))
            return fail_at(c, c->line, "active_low: '%s' is not yes or no", v);
        return 1;
    case K_DEBOUNCE:
        if (parse_long(v, 0, 1000, &n))
            return fail_at(c, c->line, "debounce_ms: '%s' is not an integer in [0, 1000]", v);
        k->debounce_ms = (int)n;
        return 1;
    case K_ACTION: {
        k->action = hfs_action_from_name(v);
        if (k->action == HFS_ACTION_NONE) {
            char known[400]; /* every action's name, ", "-separated */
            hfs_action_names(known, sizeof known);
            return fail_at(c, c->line, "unknown action '%s' (known: %s)", v, known);
        }
        return 1;
    }
    case K_LIGHT:
        return set_light(c, k, v);
    case K_STEP: /* the action's own range is checked at the section's end */
        return set_double(c, "step", v, 1e-9, 1e6, &k->step);
    case K_ACCEL:
        return set_double(c, "accel", v, 1.0, 100.0, &k->accel);
    case K_ACCEL_MS:
        return set_double(c, "accel_ms", v, 1.0, 10000.0, &k->accel_ms);
    case K_MIN:
        return set_double(c, "min", v, -1e9, 1e9, &k->min);
    case K_MAX:
        return set_double(c, "max", v, -1e9, 1e9, &k->max);
    case K_WRAP:
        if (parse_bool(v, &k->wrap))
            return fail_at(c, c->line, "wrap: '%s' is not yes or no", v);
        return 1;
    case K_COUNT:
        break;
    }
    return fail_at(c, c->line, "internal: unhandled key");
}

/* ---- sections -------------------------------------------------------- */

static int valid_name(const char *s)
{
    const size_t n = strlen(s);
    if (n == 0 || n >= HFS_CONTROL_NAME_MAX)
        return 0;
    for (size_t i = 0; i < n; ++i)
        if (!((s[i] >= 'a' && s[i] <= 'z') || (s[i] >= 'A' && s[i] <= 'Z') ||
              (s[i] >= '0' && s[i] <= '9') || s[i] == '_' || s[i] == '-' || s[i] == '.'))
            return 0;
    return 1;
}

static int begin_section(parse_ctx *c, const char *section)
{
    const int line = c->header_line;
    char type[16], name[64], extra[2];
    if (sscanf(section, "%15s %63s %1s", type, name, extra) != 2)
        return fail_at(c, line, "[%s]: sections are [knob NAME], [button NAME] or "
                       "[capture NAME]", section);
    hfs_control_kind kind;
    if (!strcmp(type, "capture")) {
        char msg[400];
        if (hfs_capture_config_begin(&c->cfg->captures, name, line, msg, sizeof msg))
            return fail_at(c, line, "%s", msg);
        c->in_capture = 1;
        c->section_seq = c->header_seq;
        return 1;
    }
    if (!strcmp(type, "knob"))
        kind = HFS_CONTROL_KNOB;
    else if (!strcmp(type, "button"))
        kind = HFS_CONTROL_BUTTON;
    else
        return fail_at(c, line, "[%s]: unknown section type '%s' (knob, button or capture)",
                       section, type);
    if (!valid_name(name))
        return fail_at(c, line, "[%s]: a control name has 1 to %d letters, digits, '_', "
                       "'-' or '.'", section, HFS_CONTROL_NAME_MAX - 1);
    const hfs_control_config *twin = hfs_input_config_find(c->cfg, name);
    if (twin)
        return fail_at(c, line, "control '%s' defined twice (first at line %d)", name,
                       twin->config_line);
    if (c->cfg->n_controls >= HFS_MAX_CONTROLS)
        return fail_at(c, line, "more than %d controls", HFS_MAX_CONTROLS);

    hfs_control_config *k = &c->cfg->control[c->cfg->n_controls++];
    memset(k, 0, sizeof *k);
    memcpy(k->name, name, strlen(name) + 1); /* valid_name: shorter than k->name */
    k->kind = kind;
    k->light = -1;
    k->config_line = line;
    c->cur = k;
    c->section_seq = c->header_seq;
    memset(c->key_line, 0, sizeof c->key_line);
    return 1;
}

/* A key given in a section where it means nothing is an error, not noise:
 * it is usually a typo for another section or a misunderstanding. */
static int reject_key(parse_ctx *c, key_id id, const char *why)
{
    if (!c->key_line[id])
        return 1;
    return fail_at(c, c->key_line[id], "%s: %s", key_names[id], why);
}

/* Everything that needs the whole section. */
static int end_section(parse_ctx *c)
{
    char msg[400];
    int at;
    if (c->in_capture && !c->failed) {
        c->in_capture = 0;
        at = hfs_capture_config_end(&c->cfg->captures, msg, sizeof msg);
        return at ? fail_at(c, at, "%s", msg) : 1;
    }
    hfs_control_config *k = c->cur;
    if (!k || c->failed)
        return !c->failed;
    c->cur = NULL;
    const char *kind = k->kind == HFS_CONTROL_KNOB ? "knob" : "button";
    if (!c->key_line[K_ACTION])
        return fail_at(c, k->config_line, "[%s %s]: no action", kind, k->name);
    const hfs_action_info *a = hfs_action_get(k->action);
    if (k->kind == HFS_CONTROL_KNOB ? !a->knob : !a->button)
        return fail_at(c, c->key_line[K_ACTION], "action %s needs a %s, '%s' is a %s", a->name,
                       a->knob ? "knob" : "button", k->name, kind);

    /* Wiring. */
    if (k->kind == HFS_CONTROL_KNOB) {
        if (!reject_key(c, K_ACTIVE_LOW, "applies to buttons") ||
            !reject_key(c, K_DEBOUNCE, "applies to buttons"))
            return 0;
        if (k->device != HFS_DEVICE_GPIO && !reject_key(c, K_STEPS, "applies to gpio knobs"))
            return 0;
    } else {
        if (!reject_key(c, K_STEPS, "applies to knobs"))
            return 0;
        if (k->device != HFS_DEVICE_GPIO &&
            (!reject_key(c, K_ACTIVE_LOW, "applies to gpio buttons") ||
             !reject_key(c, K_DEBOUNCE, "applies to gpio buttons")))
            return 0;
    }
    if (!k->steps_per_detent)
        k->steps_per_detent = 4;
    if (!c->key_line[K_DEBOUNCE])
        k->debounce_ms = 10;

    /* The light. */
    if (a->target == HFS_TARGET_NONE) {
        if (!reject_key(c, K_LIGHT, "this action has no light"))
            return 0;
    } else if (a->target == HFS_TARGET_KEY && k->light >= HFS_MAX_KEY_LIGHTS) {
        return fail_at(c, c->key_line[K_LIGHT], "light: %d is not a key light index in [0, %d]",
                       k->light, HFS_MAX_KEY_LIGHTS - 1);
    }

    /* The value's step and limits. */
    if (!a->continuous || k->kind == HFS_CONTROL_BUTTON) {
        static const key_id knob_keys[] = {K_STEP, K_ACCEL, K_ACCEL_MS, K_MIN, K_MAX, K_WRAP};
        for (size_t i = 0; i < sizeof knob_keys / sizeof knob_keys[0]; ++i)
            if (!reject_key(c, knob_keys[i], "does not apply to this action"))
                return 0;
        k->step = 1.0;
        k->accel = 1.0;
        k->wrap = a->wrap;
        return 1;
    }
    if (!c->key_line[K_STEP])
        k->step = a->step;
    else if (a->multiplicative && !(k->step > 1.0 && k->step <= 10.0))
        return fail_at(c, c->key_line[K_STEP], "step: %g: %s multiplies by step per detent, "
                       "which must be in (1, 10]", k->step, a->name);
    if (!c->key_line[K_ACCEL])
        k->accel = 1.0;
    if (!c->key_line[K_ACCEL_MS])
        k->accel_ms = 40.0;
    if (!c->key_line[K_WRAP])
        k->wrap = a->wrap;
    else if (k->wrap && a->multiplicative)
        return fail_at(c, c->key_line[K_WRAP], "wrap: %s cannot wrap (it multiplies)", a->name);
    if (!c->key_line[K_MIN])
        k->min = a->min;
    if (!c->key_line[K_MAX])
        k->max = a->max;
    const int limit_line = c->key_line[K_MAX] > c->key_line[K_MIN] ? c->key_line[K_MAX]
                                                                    : c->key_line[K_MIN];
    const hfs_key_range accepts = hfs_action_range(a);
    const int bad_lo = accepts.lo_open ? !(k->min > accepts.lo) : !(k->min >= accepts.lo);
    if (bad_lo || k->max > accepts.hi) {
        char range[80];
        hfs_key_range_text(&accepts, HFS_UNIT_NONE, range, sizeof range);
        return fail_at(c, limit_line, "min/max: [%g, %g] is outside what %s accepts, %s",
                       k->min, k->max, a->name, range);
    }
    if (!(k->min < k->max))
        return fail_at(c, limit_line, "min/max: min %g is not below max %g", k->min, k->max);
    return 1;
}

/* Two controls on one input would both fire; textual comparison of the
 * device names (two spellings of one chip are not caught). */
static int check_shared_wiring(parse_ctx *c)
{
    const hfs_input_config *cfg = c->cfg;
    for (int i = 0; i < cfg->n_controls; ++i) {
        const hfs_control_config *p = &cfg->control[i];
        if (p->device == HFS_DEVICE_NONE)
            continue;
        for (int j = 0; j < i; ++j) {
            const hfs_control_config *q = &cfg->control[j];
            if (q->device != p->device || strcmp(q->path, p->path))
                continue;
            if (p->device == HFS_DEVICE_EVDEV) {
                if (p->evdev_type == q->evdev_type && p->evdev_code == q->evdev_code)
                    return fail_at(c, p->config_line, "'%s' and '%s' read the same evdev code",
                                   q->name, p->name);
                continue;
            }
            const int np = p->kind == HFS_CONTROL_KNOB ? 2 : 1;
            const int nq = q->kind == HFS_CONTROL_KNOB ? 2 : 1;
            for (int x = 0; x < np; ++x)
                for (int y = 0; y < nq; ++y)
                    if (p->lines[x] == q->lines[y])
                        return fail_at(c, p->config_line, "gpio %s:%d used by both '%s' and '%s'",
                                       p->path, p->lines[x], q->name, p->name);
        }
    }
    return 1;
}

static int on_key(void *user, const char *section, const char *name, const char *value)
{
    parse_ctx *c = user;
    if (c->failed)
        return 0;
    c->header_keys++;
    if (c->header_seq == 0)
        return fail_at(c, c->line, "'%s' outside a [knob NAME] or [button NAME] section", name);
    if (c->section_seq != c->header_seq &&
        (!end_section(c) || !begin_section(c, section)))
        return 0;

    if (c->in_capture) {
        char msg[400];
        const int at = hfs_capture_config_key(&c->cfg->captures, name, value, c->line, msg,
                                              sizeof msg);
        return at ? fail_at(c, at, "%s", msg) : 1;
    }
    key_id id = K_COUNT;
    for (int i = 0; i < K_COUNT; ++i)
        if (!strcmp(name, key_names[i]))
            id = (key_id)i;
    if (id == K_COUNT)
        return fail_at(c, c->line, "unknown key '%s' (known: gpio, evdev, steps_per_detent, "
                       "active_low, debounce_ms, action, light, step, accel, accel_ms, min, "
                       "max, wrap)", name);
    if (c->key_line[id])
        return fail_at(c, c->line, "%s given twice (first at line %d)", name, c->key_line[id]);
    if (!*value)
        return fail_at(c, c->line, "%s: empty value", name);
    const int ok = set_value(c, c->cur, id, value);
    c->key_line[id] = c->line;
    return ok;
}

/* ---- the line reader ------------------------------------------------- */

static void note_header(parse_ctx *c, const char *line)
{
    if (*line != '[' || !strchr(line, ']'))
        return;
    if (c->header_seq > 0 && c->header_keys == 0)
        fail_at(c, c->header_line, "empty section");
    c->header_seq++;
    c->header_line = c->line;
    c->header_keys = 0;
}

/* inih's ini_reader: the next line into str (at most num - 1 chars). */
static char *read_line(char *str, int num, void *stream)
{
    parse_ctx *c = stream;
    if (c->failed || !*c->next)
        return NULL;
    const char *start = c->next;
    const char *end = strchr(start, '\n');
    if (!end)
        end = start + strlen(start);
    c->next = *end ? end + 1 : end;
    c->line++;
    while (start < end && (*start == ' ' || *start == '\t'))
        start++;
    size_t n = (size_t)(end - start);
    if (n > CONFIG_LINE_MAX || (int)n + 2 > num) {
        fail_at(c, c->line, "line longer than %d characters", CONFIG_LINE_MAX);
        return NULL;
    }
    memcpy(str, start, n);
    str[n] = '\n';
    str[n + 1] = '\0';
    note_header(c, str);
    return c->failed ? NULL : str;
}

/* ---- the file -------------------------------------------------------- */

static int read_text(const char *path, char **out, hfs_error *err)
{
    return hfs_read_text_file(path, "input configuration", CONFIG_FILE_MAX, out, NULL, err);
}

int hfs_input_config_load(const char *path, hfs_input_config *cfg, hfs_error *err)
{
    char *text = NULL;
    int rc = read_text(path, &text, err);
    if (rc)
        return rc;

    memset(cfg, 0, sizeof *cfg);
    parse_ctx c = {.path = path, .cfg = cfg, .next = text};
    const int bad_line = ini_parse_stream(read_line, &c, on_key, &c);
    free(text);
    if (bad_line < 0) {
        rc = hfs_fail(err, HFS_E_NOMEM, "%s: out of memory while parsing", path);
    } else if (bad_line > 0 && (!c.failed || bad_line < c.fail_line)) {
        /* inih goes on after an error; a syntax error before ours wins. */
        rc = hfs_fail(err, HFS_E_FORMAT, "%s:%d: syntax error (expected [knob NAME], "
                      "[button NAME] or key = value)", path, bad_line);
    } else {
        if (!c.failed && c.header_seq > 0 && c.header_keys == 0)
            fail_at(&c, c.header_line, "empty section");
        if (!c.failed && end_section(&c))
            check_shared_wiring(&c);
        if (!c.failed && cfg->n_controls == 0 && cfg->captures.n == 0)
            return hfs_fail(err, HFS_E_FORMAT, "%s: no [knob NAME], [button NAME] or "
                            "[capture NAME] sections", path);
        if (c.failed)
            rc = hfs_fail(err, HFS_E_FORMAT, "%s", c.first.msg);
    }
    if (rc)
        memset(cfg, 0, sizeof *cfg);
    return rc;
}

const hfs_control_config *hfs_input_config_find(const hfs_input_config *cfg, const char *name)
{
    for (int i = 0; i < cfg->n_controls; ++i)
        if (!strcmp(cfg->control[i].name, name))
            return &cfg->control[i];
    return NULL;
}
