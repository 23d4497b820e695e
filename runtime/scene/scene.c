/*
 * scene.c — the scene keys: one table, one setter for file and flags.
 *
 * Invariants: every key in key_table is accepted identically from a scene
 * file and from the command line; every value is range-checked here, so the
 * renderer only ever sees valid scenes.
 */
#include "scene.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef enum key_id {
    K_HEIGHT, K_SIZE, K_DX, K_ZSCALE, K_NODATA, K_ENV_SH, K_ENV_MAP,
    K_ENV_ROTATE, K_KEY, K_LOCAL, K_ALBEDO, K_K, K_OFFSET, K_NPHI_ENV,
    K_NPHI_KEY, K_NPHI_LOCAL, K_SUBSAMPLE, K_PRECISION, K_BACKEND, K_CONTEXT,
    K_VISIBILITY, K_THREADS, K_TRUTH_AZIMUTHS, K_TRUTH_SAMPLES, K_LOCAL_SWATH, K_PRESET, K_COUNT
} key_id;

static const hfs_scene_key_info key_table[K_COUNT] = {
    [K_HEIGHT] = {"height", "FILE", "height field: PNG16, PGM, PFM, ESRI .asc, raw f32 (with size)"},
    [K_SIZE] = {"size", "WxH", "size of a raw float32 height file"},
    [K_DX] = {"dx", "F", "texel spacing in world units (default 1; .asc: its cellsize)"},
    [K_ZSCALE] = {"zscale", "F", "vertical scale: world z = zscale * height (default 1)"},
    [K_NODATA] = {"nodata", "V", "height value that marks a hole, besides NaN/Inf"},
    [K_ENV_SH] = {"env-sh", "c0,...,c15", "grey environment as 16 SH coefficients"},
    [K_ENV_MAP] = {"env-map", "FILE", "environment as an equirect .hdr or .exr map"},
    [K_ENV_ROTATE] = {"env-rotate", "DEG", "rotate the environment about +z"},
    [K_KEY] = {"key", "PHI,ELEV,ALPHA,LE", "key (disk) light, degrees; repeatable"},
    [K_LOCAL] = {"local", "X,Y,Z,R,LE", "local spherical light, world units; repeatable"},
    [K_ALBEDO] = {"albedo", "F", "Lambertian albedo in [0,1] (default 1)"},
    [K_K] = {"k", "N", "pyramid level step, levels per octave (default 2)"},
    [K_OFFSET] = {"offset", "N", "pyramid level offset (default 3)"},
    [K_NPHI_ENV] = {"nphi-env", "N", "azimuth samples for the environment (default 16)"},
    [K_NPHI_KEY] = {"nphi-key", "N", "azimuth samples per key light (default 3)"},
    [K_NPHI_LOCAL] = {"nphi-local", "N", "azimuth samples per local light (default 16)"},
    [K_SUBSAMPLE] = {"subsample", "1|2|4", "visibility sub-sampling of the GLES path (default 2)"},
    [K_PRECISION] = {"precision", "fp16|fp32", "texture precision of the GLES path (default fp16)"},
    [K_BACKEND] = {"backend", "gles|cpu|truth", "renderer: GLES, CPU reference, ground truth"},
    [K_CONTEXT] = {"context", "surfaceless|osmesa|auto", "how the GLES context is made"},
    [K_VISIBILITY] = {"visibility", "legendre|wedge", "visibility to SH: NS09 Legendre or SN08 wedge tables"},
    [K_THREADS] = {"threads", "N", "CPU/truth worker threads (default: all cores)"},
    [K_TRUTH_AZIMUTHS] = {"truth-azimuths", "N", "ground truth: horizon azimuths (default 720)"},
    [K_TRUTH_SAMPLES] = {"truth-samples", "N", "ground truth: samples per light (default 256)"},
    [K_LOCAL_SWATH] = {"local-swath", "partial|full", "local lights: per-receiver partial swath (default) or full"},
    [K_PRESET] = {"preset", "kiosk|panel|headless", "quality settings per use (BENCHMARKS.md); other quality keys override it"},
};

const hfs_scene_key_info *hfs_scene_keys(int *count)
{
    *count = K_COUNT;
    return key_table;
}

static int find_key(const char *key)
{
    for (int i = 0; i < K_COUNT; ++i)
        if (strcmp(key_table[i].key, key) == 0)
            return i;
    return -1;
}

int hfs_scene_is_key(const char *key) { return find_key(key) >= 0; }

void hfs_scene_init(hfs_scene *s) { memset(s, 0, sizeof *s); }

/* Parses a comma-separated list of exactly n finite doubles. */
static int parse_doubles(const char *v, double *out, int n, const char *where,
                         const char *key, hfs_error *err)
{
    const char *p = v;
    for (int i = 0; i < n; ++i) {
        char *end;
        errno = 0;
        double x = strtod(p, &end);
        if (end == p || errno == ERANGE || !isfinite(x))
            return hfs_fail(err, HFS_E_INVALID, "%s: %s: '%s' is not %d finite number%s",
                            where, key, v, n, n > 1 ? "s separated by commas" : "");
        while (*end == ' ' || *end == '\t')
            ++end;
        if (i < n - 1) {
            if (*end != ',')
                return hfs_fail(err, HFS_E_INVALID, "%s: %s: expected %d comma-separated values in '%s'",
                                where, key, n, v);
            p = end + 1;
        } else if (*end != '\0') {
            return hfs_fail(err, HFS_E_INVALID, "%s: %s: expected %d value%s, got more in '%s'",
                            where, key, n, n > 1 ? "s" : "", v);
        }
        out[i] = x;
    }
    return HFS_OK;
}

/* "WxH", decimal digits only (sscanf's %d would skip blanks, take signs and,
 * worse, wrap 4294967298 to 2).  0 and the sides, -1 if not WxH, -2 if a
 * side exceeds max. */
static int parse_size(const char *v, long max, long *w, long *h)
{
    long side[2] = {0, 0};
    int big = 0;
    for (int i = 0; i < 2; ++i) {
        const char *start = v;
        for (; *v >= '0' && *v <= '9'; ++v) {
            if (side[i] > max)
                big = 1; /* keep scanning: "99999999999x2y" is not WxH */
            else
                side[i] = side[i] * 10 + (*v - '0');
        }
        if (v == start || *v != (i == 0 ? 'x' : '\0'))
            return -1;
        if (i == 0)
            ++v;
    }
    if (big || side[0] > max || side[1] > max)
        return -2;
    *w = side[0];
    *h = side[1];
    return 0;
}

static int parse_int(const char *v, int lo, int hi, int *out, const char *where,
                     const char *key, hfs_error *err)
{
    char *end;
    errno = 0;
    long x = strtol(v, &end, 10);
    if (end == v || *end != '\0' || errno == ERANGE)
        return hfs_fail(err, HFS_E_INVALID, "%s: %s: '%s' is not an integer", where, key, v);
    if (x < lo || x > hi)
        return hfs_fail(err, HFS_E_INVALID, "%s: %s: %ld is out of range [%d, %d]", where, key, x, lo, hi);
    *out = (int)x;
    return HFS_OK;
}

static int check_range(double x, double lo, double hi, int lo_open, const char *what,
                       const char *where, const char *key, hfs_error *err)
{
    if ((lo_open ? !(x > lo) : !(x >= lo)) || !(x <= hi))
        return hfs_fail(err, HFS_E_INVALID, "%s: %s: %s %g is out of range %c%g, %g]", where, key,
                        what, x, lo_open ? '(' : '[', lo, hi);
    return HFS_OK;
}

static int set_path(char *dst, const char *v, const char *base_dir, const char *where,
                    const char *key, hfs_error *err)
{
    if (!*v)
        return hfs_fail(err, HFS_E_INVALID, "%s: %s: empty path", where, key);
    int n;
    if (base_dir && *base_dir && v[0] != '/')
        n = snprintf(dst, HFS_PATH_MAX, "%s/%s", base_dir, v);
    else
        n = snprintf(dst, HFS_PATH_MAX, "%s", v);
    if (n < 0 || n >= HFS_PATH_MAX)
        return hfs_fail(err, HFS_E_INVALID, "%s: %s: path too long", where, key);
    return HFS_OK;
}

int hfs_scene_set(hfs_scene *s, hfs_scene_source src, const char *key,
                  const char *value, const char *where, const char *base_dir,
                  hfs_error *err)
{
    const int id = find_key(key);
    if (id < 0)
        return hfs_fail(err, HFS_E_INVALID, "%s: unknown key '%s'", where, key);
    const int repeatable = id == K_KEY || id == K_LOCAL;
    const unsigned long long bit = 1ull << id;
    if (!repeatable && (s->set_mask[src] & bit))
        return hfs_fail(err, HFS_E_INVALID, "%s: %s given twice", where, key);
    s->set_mask[src] |= bit;

    double d[5] = {0}; /* parse_doubles fills it on success */
    int rc = HFS_OK;
    hfs_quality *q = &s->quality;
    switch ((key_id)id) {
    case K_HEIGHT:
        return set_path(s->height, value, base_dir, where, key, err);
    case K_SIZE: {
        long w = 0, h = 0;
        const int r = parse_size(value, 65536, &w, &h);
        if (r == -1)
            return hfs_fail(err, HFS_E_INVALID, "%s: size: '%s' is not WxH", where, value);
        if (r == -2 || w < 2 || h < 2)
            return hfs_fail(err, HFS_E_INVALID, "%s: size: '%s' is out of range [2, 65536]", where,
                            value);
        s->raw_width = (int)w;
        s->raw_height = (int)h;
        return HFS_OK;
    }
    case K_DX:
        if ((rc = parse_doubles(value, d, 1, where, key, err)) ||
            (rc = check_range(d[0], 0.0, 1e9, 1, "spacing", where, key, err)))
            return rc;
        s->dx = d[0];
        s->dx_given = 1;
        return HFS_OK;
    case K_ZSCALE:
        if ((rc = parse_doubles(value, d, 1, where, key, err)) ||
            (rc = check_range(d[0], 0.0, 1e9, 0, "scale", where, key, err)))
            return rc;
        s->zscale = d[0];
        s->zscale_given = 1;
        return HFS_OK;
    case K_NODATA:
        if ((rc = parse_doubles(value, d, 1, where, key, err)))
            return rc;
        s->has_nodata = 1;
        s->nodata = d[0];
        return HFS_OK;
    case K_ENV_SH:
        if ((rc = parse_doubles(value, s->env_sh, HFS_SH_COEFFS, where, key, err)))
            return rc;
        s->has_env_sh = 1;
        return HFS_OK;
    case K_ENV_MAP:
        return set_path(s->env_map, value, base_dir, where, key, err);
    case K_ENV_ROTATE:
        if ((rc = parse_doubles(value, d, 1, where, key, err)) ||
            (rc = check_range(d[0], -36000.0, 36000.0, 0, "angle", where, key, err)))
            return rc;
        s->env_rotate_deg = d[0];
        return HFS_OK;
    case K_KEY:
        if ((rc = parse_doubles(value, d, 4, where, key, err)) ||
            (rc = check_range(d[1], -90.0, 90.0, 0, "elevation", where, key, err)) ||
            (rc = check_range(d[2], 0.0, 89.0, 1, "angular radius", where, key, err)) ||
            (rc = check_range(d[3], 0.0, 1e9, 0, "radiance", where, key, err)) ||
            (rc = check_range(d[0], -3600.0, 3600.0, 0, "azimuth", where, key, err)))
            return rc;
        if (src == HFS_SOURCE_FLAG && !s->key_from_flags) {
            s->key_from_flags = 1;
            s->n_key = 0; /* flags replace the file's key lights */
        }
        if (s->n_key >= HFS_MAX_KEY_LIGHTS)
            return hfs_fail(err, HFS_E_INVALID, "%s: key: more than %d key lights", where,
                            HFS_MAX_KEY_LIGHTS);
        s->key[s->n_key].phi = d[0];
        s->key[s->n_key].elev = d[1];
        s->key[s->n_key].alpha = d[2];
        s->key[s->n_key].le = d[3];
        s->n_key++;
        return HFS_OK;
    case K_LOCAL:
        if ((rc = parse_doubles(value, d, 5, where, key, err)) ||
            (rc = check_range(d[3], 0.0, 1e9, 0, "radius", where, key, err)) ||
            (rc = check_range(d[4], 0.0, 1e9, 0, "radiance", where, key, err)))
            return rc;
        for (int i = 0; i < 3; ++i)
            if ((rc = check_range(d[i], -1e9, 1e9, 0, "coordinate", where, key, err)))
                return rc;
        if (src == HFS_SOURCE_FLAG && !s->local_from_flags) {
            s->local_from_flags = 1;
            s->n_local = 0;
        }
        if (s->n_local >= HFS_MAX_LOCAL_LIGHTS)
            return hfs_fail(err, HFS_E_INVALID, "%s: local: more than %d local lights", where,
                            HFS_MAX_LOCAL_LIGHTS);
        s->local[s->n_local].x = d[0];
        s->local[s->n_local].y = d[1];
        s->local[s->n_local].z = d[2];
        s->local[s->n_local].r = d[3];
        s->local[s->n_local].le = d[4];
        s->n_local++;
        return HFS_OK;
    case K_ALBEDO:
        if ((rc = parse_doubles(value, d, 1, where, key, err)) ||
            (rc = check_range(d[0], 0.0, 1.0, 0, "albedo", where, key, err)))
            return rc;
        s->albedo = d[0];
        s->albedo_given = 1;
        return HFS_OK;
    case K_K:
        return parse_int(value, 1, 16, &q->k, where, key, err);
    case K_OFFSET:
        return parse_int(value, 0, 16, &q->offset, where, key, err);
    case K_NPHI_ENV:
        return parse_int(value, 3, 1024, &q->nphi_env, where, key, err);
    case K_NPHI_KEY:
        return parse_int(value, 1, 256, &q->nphi_key, where, key, err);
    case K_NPHI_LOCAL:
        return parse_int(value, 3, 1024, &q->nphi_local, where, key, err);
    case K_SUBSAMPLE:
        if ((rc = parse_int(value, 1, 4, &q->subsample, where, key, err)))
            return rc;
        if (q->subsample == 3)
            return hfs_fail(err, HFS_E_INVALID, "%s: subsample: 3 is not one of 1, 2, 4", where);
        return HFS_OK;
    case K_PRECISION:
        if (strcmp(value, "fp16") == 0)
            q->precision = HFS_PRECISION_FP16;
        else if (strcmp(value, "fp32") == 0)
            q->precision = HFS_PRECISION_FP32;
        else
            return hfs_fail(err, HFS_E_INVALID, "%s: precision: '%s' is not fp16 or fp32", where, value);
        return HFS_OK;
    case K_BACKEND:
        if (strcmp(value, "gles") == 0)
            s->backend = HFS_BACKEND_GLES;
        else if (strcmp(value, "cpu") == 0)
            s->backend = HFS_BACKEND_CPU;
        else if (strcmp(value, "truth") == 0)
            s->backend = HFS_BACKEND_TRUTH;
        else
            return hfs_fail(err, HFS_E_INVALID, "%s: backend: '%s' is not gles, cpu or truth", where, value);
        return HFS_OK;
    case K_CONTEXT:
        if (strcmp(value, "surfaceless") && strcmp(value, "osmesa") && strcmp(value, "auto"))
            return hfs_fail(err, HFS_E_INVALID, "%s: context: '%s' is not surfaceless, osmesa or auto",
                            where, value);
        snprintf(s->context, sizeof s->context, "%s", value);
        return HFS_OK;
    case K_VISIBILITY:
        if (strcmp(value, "legendre") == 0)
            q->visibility = HFS_VIS_LEGENDRE;
        else if (strcmp(value, "wedge") == 0)
            q->visibility = HFS_VIS_WEDGE_TABLE;
        else
            return hfs_fail(err, HFS_E_INVALID, "%s: visibility: '%s' is not legendre or wedge", where, value);
        return HFS_OK;
    case K_THREADS:
        return parse_int(value, 1, 64, &q->threads, where, key, err);
    case K_TRUTH_AZIMUTHS:
        return parse_int(value, 720, 100000, &q->truth_azimuths, where, key, err);
    case K_TRUTH_SAMPLES:
        return parse_int(value, 1, 1 << 20, &q->truth_light_samples, where, key, err);
    case K_LOCAL_SWATH:
        if (strcmp(value, "partial") == 0)
            q->local_full_swath = 0;
        else if (strcmp(value, "full") == 0)
            q->local_full_swath = 1;
        else
            return hfs_fail(err, HFS_E_INVALID, "%s: local-swath: '%s' is not partial or full", where, value);
        return HFS_OK;
    case K_PRESET: {
        hfs_quality probe;
        if (hfs_quality_preset(&probe, value) != HFS_OK || strlen(value) >= sizeof s->preset)
            return hfs_fail(err, HFS_E_INVALID, "%s: preset: '%s' is not kiosk, panel or "
                            "headless", where, value);
        snprintf(s->preset, sizeof s->preset, "%s", value);
        return HFS_OK;
    }
    case K_COUNT:
        break;
    }
    return hfs_fail(err, HFS_E_INVALID, "%s: unhandled key '%s'", where, key);
}

int hfs_scene_validate(const hfs_scene *s, hfs_error *err)
{
    if (!s->height[0])
        return hfs_fail(err, HFS_E_INVALID, "scene: no height field (give --height FILE)");
    if (s->has_env_sh && s->env_map[0])
        return hfs_fail(err, HFS_E_INVALID, "scene: both env-sh and env-map given; choose one");
    return HFS_OK;
}

void hfs_scene_lighting(const hfs_scene *s, const double (*env_sh)[HFS_SH_COEFFS],
                        hfs_lighting *l)
{
    const double deg = 3.14159265358979323846 / 180.0;
    hfs_lighting_defaults(l);
    if (env_sh) {
        l->has_env = 1;
        memcpy(l->env_sh, env_sh, sizeof l->env_sh);
    } else if (s->has_env_sh) {
        l->has_env = 1;
        for (int c = 0; c < 3; ++c)
            memcpy(l->env_sh[c], s->env_sh, sizeof s->env_sh);
    }
    l->env_rotate = s->env_rotate_deg * deg;
    l->n_key = s->n_key;
    for (int i = 0; i < s->n_key; ++i) {
        l->key[i].phi = s->key[i].phi * deg;
        l->key[i].elev = s->key[i].elev * deg;
        l->key[i].alpha = s->key[i].alpha * deg;
        for (int c = 0; c < 3; ++c)
            l->key[i].radiance[c] = (float)s->key[i].le;
    }
    l->n_local = s->n_local;
    for (int i = 0; i < s->n_local; ++i) {
        l->local[i].pos[0] = s->local[i].x;
        l->local[i].pos[1] = s->local[i].y;
        l->local[i].pos[2] = s->local[i].z;
        l->local[i].radius = s->local[i].r;
        for (int c = 0; c < 3; ++c)
            l->local[i].radiance[c] = (float)s->local[i].le;
    }
    l->albedo = s->albedo_given ? s->albedo : 1.0;
}

void hfs_scene_quality(const hfs_scene *s, hfs_quality *q)
{
    /* Defaults (or the preset's), then exactly the keys the user gave (0 can
     * be a real value, e.g. offset = 0). */
    const unsigned long long given = s->set_mask[0] | s->set_mask[1];
    const hfs_quality *g = &s->quality;
    /* The preset is read from s->preset, not from the "given" mask: the
     * kiosk's preset.next control (board/input_map.c) writes s->preset of a
     * scene that may never have named one. */
    if (!s->preset[0] || hfs_quality_preset(q, s->preset) != HFS_OK)
        hfs_quality_defaults(q);
#define TAKE(id, field) do { if (given & (1ull << (id))) q->field = g->field; } while (0)
    TAKE(K_K, k);
    TAKE(K_OFFSET, offset);
    TAKE(K_NPHI_ENV, nphi_env);
    TAKE(K_NPHI_KEY, nphi_key);
    TAKE(K_NPHI_LOCAL, nphi_local);
    TAKE(K_SUBSAMPLE, subsample);
    TAKE(K_PRECISION, precision);
    TAKE(K_VISIBILITY, visibility);
    TAKE(K_THREADS, threads);
    TAKE(K_TRUTH_AZIMUTHS, truth_azimuths);
    TAKE(K_TRUTH_SAMPLES, truth_light_samples);
    TAKE(K_LOCAL_SWATH, local_full_swath);
#undef TAKE
}
