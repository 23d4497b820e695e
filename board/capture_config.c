/*
 * capture_config.c — the keys of a [capture NAME] section
 * (capture_config.h); docs/CAPTURE.md is the reference.
 */
#include "capture_config.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef enum ckey {
    C_DEVICE, C_REPLAY, C_LOOP, C_PACE, C_FORMAT, C_SIZE, C_RATE, C_BUFFERS, C_ROLE, C_SCALE,
    C_MIN_DEPTH, C_MAX_DEPTH, C_PLANE, C_ROI, C_GRID, C_ZGAIN, C_WINDOW, C_GATE, C_HYST,
    C_JUMP, C_MAPPING, C_CENTER, C_RADIUS, C_FOV, C_ROTATE, C_HEMI, C_TRANSFER, C_EXPOSURE,
    C_ENV_SIZE, C_SMOOTHING, C_ENV_LIGHTS, C_COUNT
} ckey;

/* The keys of each role (the others are an error there). */
#define FIRST_DEPTH C_SCALE
#define LAST_DEPTH C_JUMP
#define FIRST_ENV C_MAPPING

static const char *const ckey_names[C_COUNT] = {
    "device", "replay", "loop", "pace", "format", "size", "rate", "buffers", "role", "depth_scale",
    "min_depth", "max_depth", "plane", "roi", "grid", "zgain", "window", "gate_mm",
    "hysteresis_mm", "jump_mm", "mapping", "center", "radius", "fov", "rotate", "hemisphere",
    "transfer", "exposure", "env_size", "smoothing", "env_lights"};

static int bad(int line, char *msg, size_t size, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

static int bad(int line, char *msg, size_t size, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, size, fmt, ap);
    va_end(ap);
    return line;
}

int hfs_capture_config_begin(hfs_capture_configs *cc, const char *name, int line, char *msg,
                             size_t size)
{
    if (strlen(name) >= sizeof cc->c[0].name)
        return bad(line, msg, size, "[capture %s]: name longer than %zu characters", name,
                   sizeof cc->c[0].name - 1);
    for (int i = 0; i < cc->n; ++i)
        if (!strcmp(cc->c[i].name, name))
            return bad(line, msg, size, "capture '%s' defined twice (first at line %d)", name,
                       cc->c[i].config_line);
    if (cc->n >= HFS_MAX_CAPTURES)
        return bad(line, msg, size, "more than %d captures", HFS_MAX_CAPTURES);
    hfs_capture_config *c = &cc->c[cc->n++];
    memset(c, 0, sizeof *c);
    snprintf(c->name, sizeof c->name, "%s", name);
    c->config_line = line;
    c->format = HFS_PIX_Z16;
    c->buffers = 4;
    c->role = HFS_ROLE_HEIGHTS;
    hfs_depth_params_defaults(&c->depth);
    c->depth.grid_w = c->depth.grid_h = 0;
    hfs_camenv_defaults(&c->env);
    memset(cc->key_line, 0, sizeof cc->key_line);
    return 0;
}

static int num(const char *v, double lo, double hi, double *out)
{
    char *end;
    errno = 0;
    const double x = strtod(v, &end);
    if (end == v || *end || errno == ERANGE || !isfinite(x) || x < lo || x > hi)
        return -1;
    *out = x;
    return 0;
}

static int size_of(const char *v, int *w, int *h)
{
    char tail;
    return sscanf(v, "%dx%d%c", w, h, &tail) == 2 && *w >= 1 && *h >= 1 && *w <= 16384 &&
                   *h <= 16384
               ? 0
               : -1;
}

static int yes_no(const char *v, int *out)
{
    if (!strcmp(v, "yes") || !strcmp(v, "true") || !strcmp(v, "on") || !strcmp(v, "1"))
        return *out = 1, 0;
    if (!strcmp(v, "no") || !strcmp(v, "false") || !strcmp(v, "off") || !strcmp(v, "0"))
        return *out = 0, 0;
    return -1;
}

static int set_plane(hfs_capture_config *c, const char *v)
{
    char tail[2];
    if (!strcmp(v, "auto")) {
        c->depth.plane_set = 0;
        return 0;
    }
    double *p = c->depth.plane;
    if (sscanf(v, "%lf %lf %lf %1s", &p[0], &p[1], &p[2], tail) != 3 || !isfinite(p[0]) ||
        !isfinite(p[1]) || !(p[2] > 0.0 && p[2] < 1e4))
        return -1;
    c->depth.plane_set = 1;
    return 0;
}

/* An environment key's value into p; -1 with msg when it is bad. */
static int set_env_key(hfs_camenv_params *p, ckey k, const char *v, char *msg, size_t size)
{
    const char *name = ckey_names[k];
    char tail[2];
    double x;
    int n;
    switch (k) {
    case C_MAPPING:
        p->mapping = !strcmp(v, "mirrorball") ? HFS_MAP_MIRRORBALL
                     : !strcmp(v, "fisheye")  ? HFS_MAP_FISHEYE
                     : !strcmp(v, "equirect") ? HFS_MAP_EQUIRECT : (hfs_camenv_mapping)-1;
        return (int)p->mapping < 0 ? (snprintf(msg, size, "mapping: '%s' is not mirrorball, "
                                               "fisheye or equirect", v), -1) : 0;
    case C_CENTER:
        if (sscanf(v, "%lf %lf %1s", &p->cx, &p->cy, tail) != 2 || !isfinite(p->cx) ||
            !isfinite(p->cy) || p->cx < 0 || p->cy < 0 || p->cx > 16384 || p->cy > 16384)
            return snprintf(msg, size, "center: '%s' is not X Y (pixels, 0..16384)", v), -1;
        p->has_center = 1;
        return 0;
    case C_HEMI:
        if (strcmp(v, "upper") && strcmp(v, "lower"))
            return snprintf(msg, size, "hemisphere: '%s' is not upper or lower", v), -1;
        p->lower = !strcmp(v, "lower");
        return 0;
    case C_TRANSFER:
        if (strcmp(v, "srgb") && strcmp(v, "linear"))
            return snprintf(msg, size, "transfer: '%s' is not srgb or linear", v), -1;
        p->linear = !strcmp(v, "linear");
        return 0;
    case C_ENV_SIZE:
        return size_of(v, &p->map_w, &p->map_h) || p->map_w < 16 || p->map_h < 8 ||
                       p->map_w > 4096 || p->map_h > 2048
                   ? (snprintf(msg, size, "env_size: '%s' is not WxH (16x8..4096x2048)", v), -1)
                   : 0;
    case C_ENV_LIGHTS:
        if (!strcmp(v, "off") || !strcmp(v, "auto"))
            return p->env_lights = !strcmp(v, "auto") ? -1 : 0, 0;
        if (sscanf(v, "%d%1s", &n, tail) != 1 || n < 0 || n > HFS_MAX_KEY_LIGHTS)
            return snprintf(msg, size, "env_lights: '%s' is not off, auto or 0..%d", v,
                            HFS_MAX_KEY_LIGHTS), -1;
        p->env_lights = n;
        return 0;
    default:
        break;
    }
    static const struct { ckey k; double lo, hi; const char *unit; } nums[] = {
        {C_RADIUS, 1, 16384, "pixels"}, {C_FOV, 1, 360, "degrees"},
        {C_ROTATE, -360, 360, "degrees"}, {C_EXPOSURE, 1e-6, 1e9, "radiance per unit code"},
        {C_SMOOTHING, 0, 60, "seconds"}};
    for (size_t i = 0; i < sizeof nums / sizeof nums[0]; ++i) {
        if (nums[i].k != k)
            continue;
        if (num(v, nums[i].lo, nums[i].hi, &x))
            return snprintf(msg, size, "%s: '%s' is not a number in [%g, %g] (%s)", name, v,
                            nums[i].lo, nums[i].hi, nums[i].unit), -1;
        double *dst[] = {[C_RADIUS] = &p->radius, [C_FOV] = &p->fov_deg,
                         [C_ROTATE] = &p->rotate_deg, [C_EXPOSURE] = &p->exposure,
                         [C_SMOOTHING] = &p->smoothing_s};
        *dst[k] = x;
        return 0;
    }
    return snprintf(msg, size, "internal: unhandled key"), -1;
}

/* The value of key k into c; -1 with msg when it is bad. */
static int set_key(hfs_capture_config *c, ckey k, const char *v, char *msg, size_t size)
{
    double x;
    int *r = c->depth.roi;
    char tail[2];
    switch (k) {
    case C_DEVICE:
    case C_REPLAY:
        if (strlen(v) >= sizeof c->device)
            return snprintf(msg, size, "%s: path too long", ckey_names[k]), -1;
        snprintf(k == C_DEVICE ? c->device : c->replay, sizeof c->device, "%s", v);
        return 0;
    case C_LOOP:
        return yes_no(v, &c->loop) ? (snprintf(msg, size, "loop: '%s' is not yes or no", v), -1)
                                   : 0;
    case C_PACE:
        if (strcmp(v, "time") && strcmp(v, "shown"))
            return snprintf(msg, size, "pace: '%s' is not time or shown", v), -1;
        c->pace_shown = !strcmp(v, "shown");
        return 0;
    case C_FORMAT:
        if (!(c->format = hfs_pixfmt_from_name(v)))
            return snprintf(msg, size, "format: '%s' is not Z16, Y16, GREY or YUYV", v), -1;
        return 0;
    case C_SIZE:
        return size_of(v, &c->width, &c->height)
                   ? (snprintf(msg, size, "size: '%s' is not WxH (1..16384)", v), -1) : 0;
    case C_GRID:
        return size_of(v, &c->depth.grid_w, &c->depth.grid_h) || c->depth.grid_w < 2 ||
                       c->depth.grid_h < 2 || c->depth.grid_w > 8192 || c->depth.grid_h > 8192
                   ? (snprintf(msg, size, "grid: '%s' is not WxH (2..8192)", v), -1) : 0;
    case C_RATE:
        if (num(v, 1, 1000, &x) || x != floor(x))
            return snprintf(msg, size, "rate: '%s' is not frames per second in [1, 1000]", v), -1;
        c->fps = (int)x;
        return 0;
    case C_BUFFERS:
        if (num(v, 2, 16, &x) || x != floor(x))
            return snprintf(msg, size, "buffers: '%s' is not an integer in [2, 16]", v), -1;
        c->buffers = (int)x;
        return 0;
    case C_ROLE:
        if (!strcmp(v, "heights"))
            return c->role = HFS_ROLE_HEIGHTS, 0;
        if (!strcmp(v, "environment"))
            return c->role = HFS_ROLE_ENVIRONMENT, 0;
        return snprintf(msg, size, "role: '%s' is not heights or environment", v), -1;
    case C_PLANE:
        return set_plane(c, v) ? (snprintf(msg, size, "plane: '%s' is not 'auto' or A B C "
                                           "(metres; C > 0)", v), -1) : 0;
    case C_ROI:
        if (sscanf(v, "%d %d %d %d %1s", &r[0], &r[1], &r[2], &r[3], tail) != 4 || r[0] < 0 ||
            r[1] < 0 || r[2] < 1 || r[3] < 1 || r[0] > 16384 || r[1] > 16384 || r[2] > 16384 ||
            r[3] > 16384)
            return snprintf(msg, size, "roi: '%s' is not X Y W H (pixels, W and H >= 1)", v), -1;
        return 0;
    case C_WINDOW:
        if (num(v, 1, HFS_DEPTH_WINDOW_MAX, &x) || x != floor(x))
            return snprintf(msg, size, "window: '%s' is not an integer in [1, %d]", v,
                            HFS_DEPTH_WINDOW_MAX), -1;
        c->depth.window = (int)x;
        return 0;
    default:
        if (k >= FIRST_ENV)
            return set_env_key(&c->env, k, v, msg, size);
        break;
    }
    /* The plain numbers. */
    static const struct { ckey k; double lo, hi, mul; const char *unit; } nums[] = {
        {C_SCALE, 1e-7, 0.1, 1, "metres per count"}, {C_MIN_DEPTH, 0, 100, 1, "metres"},
        {C_MAX_DEPTH, 0, 100, 1, "metres"}, {C_ZGAIN, 1e-6, 1e6, 1, "world units per metre"},
        {C_GATE, 0, 1000, 1e-3, "mm"}, {C_HYST, 0, 1000, 1e-3, "mm"},
        {C_JUMP, 0.001, 10000, 1e-3, "mm"}};
    for (size_t i = 0; i < sizeof nums / sizeof nums[0]; ++i) {
        if (nums[i].k != k)
            continue;
        if (num(v, nums[i].lo, nums[i].hi, &x))
            return snprintf(msg, size, "%s: '%s' is not a number in [%g, %g] (%s)",
                            ckey_names[k], v, nums[i].lo, nums[i].hi, nums[i].unit), -1;
        x *= nums[i].mul;
        double *dst[] = {[C_SCALE] = &c->depth.scale, [C_MIN_DEPTH] = &c->depth.min_depth,
                         [C_MAX_DEPTH] = &c->depth.max_depth, [C_ZGAIN] = &c->depth.zgain,
                         [C_GATE] = &c->depth.gate, [C_HYST] = &c->depth.hysteresis,
                         [C_JUMP] = &c->depth.jump};
        *dst[k] = x;
        return 0;
    }
    return snprintf(msg, size, "internal: unhandled key"), -1;
}

int hfs_capture_config_key(hfs_capture_configs *cc, const char *key, const char *value,
                           int line, char *msg, size_t size)
{
    hfs_capture_config *c = &cc->c[cc->n - 1];
    int k = 0;
    while (k < C_COUNT && strcmp(key, ckey_names[k]))
        ++k;
    if (k == C_COUNT) {
        char known[500] = "";
        for (int i = 0; i < C_COUNT; ++i)
            snprintf(known + strlen(known), sizeof known - strlen(known), "%s%s", i ? ", " : "",
                     ckey_names[i]);
        return bad(line, msg, size, "unknown capture key '%s' (known: %s)", key, known);
    }
    if (cc->key_line[k])
        return bad(line, msg, size, "%s given twice (first at line %d)", key, cc->key_line[k]);
    if (!*value)
        return bad(line, msg, size, "%s: empty value", key);
    cc->key_line[k] = line;
    return set_key(c, (ckey)k, value, msg, size) ? line : 0;
}

/* The checks of a role = environment section. */
static int end_environment(hfs_capture_configs *cc, char *msg, size_t size)
{
    hfs_capture_config *c = &cc->c[cc->n - 1];
    const int *kl = cc->key_line;
    const hfs_camenv_params *p = &c->env;
    for (int k = FIRST_DEPTH; k <= LAST_DEPTH; ++k)
        if (kl[k])
            return bad(kl[k], msg, size, "%s: applies to role = heights", ckey_names[k]);
    if (!kl[C_FORMAT])
        c->format = HFS_PIX_YUYV;
    if (c->format != HFS_PIX_YUYV && c->format != HFS_PIX_GREY)
        return bad(kl[C_FORMAT], msg, size, "format: role environment needs colour or grey "
                   "(YUYV or GREY), not %s", hfs_pixfmt_name(c->format));
    if (kl[C_FOV] && p->mapping != HFS_MAP_FISHEYE)
        return bad(kl[C_FOV], msg, size, "fov: applies to mapping = fisheye");
    const int circle = p->mapping != HFS_MAP_EQUIRECT;
    if (!circle && (kl[C_CENTER] || kl[C_RADIUS] || kl[C_HEMI]))
        return bad(kl[C_CENTER] ? kl[C_CENTER] : kl[C_RADIUS] ? kl[C_RADIUS] : kl[C_HEMI], msg,
                   size, "%s: applies to mapping = mirrorball or fisheye",
                   kl[C_CENTER] ? "center" : kl[C_RADIUS] ? "radius" : "hemisphere");
    if (circle && c->width > 0 && p->has_center && (p->cx > c->width || p->cy > c->height))
        return bad(kl[C_CENTER], msg, size, "center: %g %g is outside the %dx%d frame", p->cx,
                   p->cy, c->width, c->height);
    return 0;
}

int hfs_capture_config_end(hfs_capture_configs *cc, char *msg, size_t size)
{
    hfs_capture_config *c = &cc->c[cc->n - 1];
    const int *kl = cc->key_line;
    if (!!c->device[0] == !!c->replay[0])
        return bad(kl[C_REPLAY] ? kl[C_REPLAY] : c->config_line, msg, size,
                   "[capture %s]: give device = PATH or replay = DIR (one of them)", c->name);
    if (kl[C_LOOP] && !c->replay[0])
        return bad(kl[C_LOOP], msg, size, "loop: applies to replay");
    if (kl[C_PACE] && !c->replay[0])
        return bad(kl[C_PACE], msg, size, "pace: applies to replay");
    if (c->role == HFS_ROLE_ENVIRONMENT)
        return end_environment(cc, msg, size);
    for (int k = FIRST_ENV; k < C_COUNT; ++k)
        if (kl[k])
            return bad(kl[k], msg, size, "%s: applies to role = environment", ckey_names[k]);
    if (c->format != HFS_PIX_Z16 && c->format != HFS_PIX_Y16)
        return bad(kl[C_FORMAT], msg, size, "format: role heights needs depth (Z16 or Y16), "
                   "not %s", hfs_pixfmt_name(c->format));
    const hfs_depth_params *p = &c->depth;
    if (p->max_depth > 0.0 && p->max_depth <= p->min_depth)
        return bad(kl[C_MAX_DEPTH], msg, size, "max_depth: %g is not above min_depth %g",
                   p->max_depth, p->min_depth);
    if (c->width > 0 && p->roi[2] > 0 &&
        (p->roi[0] + p->roi[2] > c->width || p->roi[1] + p->roi[3] > c->height))
        return bad(kl[C_ROI], msg, size, "roi: %d %d %d %d is outside the %dx%d frame",
                   p->roi[0], p->roi[1], p->roi[2], p->roi[3], c->width, c->height);
    return 0;
}
