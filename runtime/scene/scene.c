/*
 * scene.c — the scene keys: one setter for file and flags, driven by the
 * table of scene keys (runtime/core/scene_keys.h).  It reads no file: the
 * objects key's file is read by hfs_scene_set (scene_ini.c) on top of it,
 * so the INI reader depends on the setter and never the reverse.
 *
 * Invariants: every key in the table is accepted identically from a scene
 * file and from the command line; every number is range-checked here
 * against the table, whose ranges the renderer validates too (in library
 * units), so the renderer only ever sees valid scenes.  How a value is read
 * follows its key's form (path, size, numbers, integer, word); only where
 * it is stored is written per key.
 */
#include "scene.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const hfs_scene_key_info *hfs_scene_keys(int *count)
{
    *count = HFS_SK_COUNT;
    return hfs_scene_key_get(HFS_SK_HEIGHT);
}

int hfs_scene_is_key(const char *key) { return hfs_scene_key_find(key) >= 0; }

void hfs_scene_init(hfs_scene *s) { memset(s, 0, sizeof *s); }

/* ---- reading a value, by form ------------------------------------------------ */

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

/* Values of `key` in colour: PHI,ELEV,ALPHA,R,G,B (each of R, G, B in the
 * radiance's range). */
#define KEY_RGB_N 6

static int count_commas(const char *v)
{
    int n = 0;
    for (; *v; ++v)
        n += *v == ',';
    return n;
}

/* The key's numbers, each checked against its range; *n gets their count
 * (k->n, or KEY_RGB_N for a key light in colour). */
static int parse_reals(hfs_scene_key_id id, const char *v, double *out, int *n,
                       const char *where, hfs_error *err)
{
    const hfs_scene_key *k = hfs_scene_key_get(id);
    *n = id == HFS_SK_KEY && count_commas(v) == KEY_RGB_N - 1 ? KEY_RGB_N : k->n;
    if (hfs_scene_key_has_colour(id) && count_commas(v) == k->n + 2)
        *n = k->n + 3; /* an object's R,G,B albedo follows */
    else if (hfs_scene_key_has_colour(id) && count_commas(v) != k->n - 1)
        return hfs_fail(err, HFS_E_INVALID, "%s: %s: expected %d comma-separated values (%d "
                        "with R,G,B) in '%s'", where, k->name, k->n, k->n + 3, v);
    int rc = parse_doubles(v, out, *n, where, k->name, err);
    for (int i = 0; i < *n && !rc; ++i) {
        if (hfs_scene_key_has_colour(id) && i >= k->n) {
            if (!(out[i] >= 0.0 && out[i] <= 1.0))
                rc = hfs_fail(err, HFS_E_INVALID, "%s: %s: albedo %g is out of range [0, 1]",
                              where, k->name, out[i]);
            continue;
        }
        rc = hfs_scene_key_check(id, i < k->n ? i : k->n - 1, out[i], where, err);
    }
    return rc;
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

static int set_size(hfs_scene *s, const char *v, const char *where, hfs_error *err)
{
    const hfs_key_range *r = &hfs_scene_key_number(HFS_SK_SIZE, 0)->range;
    long w = 0, h = 0;
    const int rc = parse_size(v, (long)r->hi, &w, &h);
    if (rc == -1)
        return hfs_fail(err, HFS_E_INVALID, "%s: size: '%s' is not WxH", where, v);
    if (rc == -2 || !hfs_key_in_range(r, (double)w) || !hfs_key_in_range(r, (double)h))
        return hfs_fail(err, HFS_E_INVALID, "%s: size: '%s' is out of range [%ld, %ld]", where, v,
                        (long)r->lo, (long)r->hi);
    s->raw_width = (int)w;
    s->raw_height = (int)h;
    return HFS_OK;
}

static int parse_int(hfs_scene_key_id id, const char *v, int *out, const char *where,
                     hfs_error *err)
{
    const hfs_scene_key *k = hfs_scene_key_get(id);
    char *end;
    errno = 0;
    long x = strtol(v, &end, 10);
    if (end == v || *end != '\0' || errno == ERANGE)
        return hfs_fail(err, HFS_E_INVALID, "%s: %s: '%s' is not an integer", where, k->name, v);
    int rc = hfs_scene_key_check(id, 0, (double)x, where, err);
    if (rc)
        return rc;
    if (!hfs_scene_key_int_allowed(k, x)) {
        char allowed[64];
        hfs_scene_key_allowed_text(k, allowed, sizeof allowed);
        return hfs_fail(err, HFS_E_INVALID, "%s: %s: %ld is not one of %s", where, k->name, x,
                        allowed);
    }
    *out = (int)x;
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

/* ---- storing a value, by key ------------------------------------------------- */

/* The quality field an integer key sets. */
static int *int_field(hfs_scene *s, hfs_scene_key_id id)
{
    hfs_quality *q = &s->quality;
    switch (id) {
    case HFS_SK_K: return &q->k;
    case HFS_SK_OFFSET: return &q->offset;
    case HFS_SK_NPHI_ENV: return &q->nphi_env;
    case HFS_SK_NPHI_KEY: return &q->nphi_key;
    case HFS_SK_REFINE: return &q->refine;
    case HFS_SK_SPLIT: return &q->split;
    case HFS_SK_FAR_FROM: return &q->far_from;
    case HFS_SK_FAR_DIRS: return &q->far_dirs;
    case HFS_SK_FAR_STEP: return &q->far_step;
    case HFS_SK_NPHI_BOUNCE: return &q->nphi_bounce;
    case HFS_SK_BOUNCE_REFINE: return &q->bounce_refine;
    case HFS_SK_BOUNCE_SUBSAMPLE: return &q->bounce_subsample;
    case HFS_SK_BOUNCE_NEAR: return &q->bounce_near;
    case HFS_SK_NPHI_LOCAL: return &q->nphi_local;
    case HFS_SK_SUBSAMPLE: return &q->subsample;
    case HFS_SK_THREADS: return &q->threads;
    case HFS_SK_TRUTH_AZIMUTHS: return &q->truth_azimuths;
    case HFS_SK_TRUTH_SAMPLES: return &q->truth_light_samples;
    case HFS_SK_BOUNCES: return &s->bounces;
    default: return NULL;
    }
}

/* Word w (the index in the key's "a|b|c") of a WORD key. */
static void store_word(hfs_scene *s, hfs_scene_key_id id, int w, const char *value)
{
    static const hfs_backend backends[] = {HFS_BACKEND_GLES, HFS_BACKEND_CPU, HFS_BACKEND_TRUTH};
    switch (id) {
    case HFS_SK_PRECISION:
        s->quality.precision = w == 0 ? HFS_PRECISION_FP16 : HFS_PRECISION_FP32;
        break;
    case HFS_SK_BACKEND: s->backend = backends[w]; break;
    case HFS_SK_CONTEXT: snprintf(s->context, sizeof s->context, "%s", value); break;
    case HFS_SK_VISIBILITY:
        s->quality.visibility = w == 0 ? HFS_VIS_LEGENDRE
                                : w == 1 ? HFS_VIS_WEDGE_TABLE : HFS_VIS_SLICE;
        break;
    case HFS_SK_LOCAL_SWATH: s->quality.local_full_swath = w; break;
    case HFS_SK_PRESET: snprintf(s->preset, sizeof s->preset, "%s", value); break;
    case HFS_SK_TRUTH_ENV: s->truth_env_sh = w; break;
    case HFS_SK_AZIMUTH_CONVENTION: s->azimuth_compass = w; break;
    case HFS_SK_ENV_SHADE: s->env_shade_sh = w; break;
    default: break;
    }
}

/* The first light a flag gives replaces the file's lights of its kind. */
static int add_light(int src, int *from_flags, int *n, int max, const char *where,
                     const char *key, hfs_error *err)
{
    if (src == HFS_SOURCE_FLAG && !*from_flags) {
        *from_flags = 1;
        *n = 0;
    }
    if (*n >= max)
        return hfs_fail(err, HFS_E_INVALID, "%s: %s: more than %d %s lights", where, key, max, key);
    return HFS_OK;
}

/* An object from a pin, box or point key's numbers (hfs_object). */
static int add_object(hfs_scene *s, hfs_scene_key_id id, const double *d, int n,
                      const char *where, hfs_error *err)
{
    const hfs_scene_key *k = hfs_scene_key_get(id);
    if (s->n_objects >= HFS_MAX_OBJECTS)
        return hfs_fail(err, HFS_E_INVALID, "%s: %s: more than %d objects", where, k->name,
                        HFS_MAX_OBJECTS);
    hfs_object *o = &s->objects[s->n_objects++];
    memset(o, 0, sizeof *o);
    o->x = d[0], o->y = d[1];
    if (id == HFS_SK_PIN) {
        o->kind = HFS_OBJECT_PIN;
        o->size[2] = d[2], o->size[0] = d[3];
    } else if (id == HFS_SK_BOX) {
        o->kind = HFS_OBJECT_BOX;
        o->z = d[2], o->size[0] = d[3], o->size[1] = d[4], o->size[2] = d[5];
    } else {
        o->kind = HFS_OBJECT_POINT;
        o->z = d[2], o->size[0] = d[3];
    }
    for (int c = 0; c < 3; ++c)
        o->albedo[c] = (float)(n > k->n ? d[k->n + c] : 0.8);
    return HFS_OK;
}

/* Numbers d (n of them), already checked, of a REALS key. */
static int store_reals(hfs_scene *s, hfs_scene_source src, hfs_scene_key_id id, const double *d,
                       int n, const char *where, hfs_error *err)
{
    int rc = HFS_OK;
    switch (id) {
    case HFS_SK_DX: s->dx = d[0]; s->dx_given = 1; break;
    case HFS_SK_ZSCALE: s->zscale = d[0]; s->zscale_given = 1; break;
    case HFS_SK_NODATA: s->nodata = d[0]; s->has_nodata = 1; break;
    case HFS_SK_ENV_SH: memcpy(s->env_sh, d, sizeof s->env_sh); s->has_env_sh = 1; break;
    case HFS_SK_ENV_SH_R:
    case HFS_SK_ENV_SH_G:
    case HFS_SK_ENV_SH_B: {
        const int c = id - HFS_SK_ENV_SH_R;
        memcpy(s->env_sh_rgb[c], d, sizeof s->env_sh_rgb[c]);
        s->env_sh_rgb_mask |= 1 << c;
        break;
    }
    case HFS_SK_ENV_ROTATE: s->env_rotate_deg = d[0]; break;
    case HFS_SK_ALBEDO: s->albedo = d[0]; s->albedo_given = 1; break;
    case HFS_SK_SPECULAR: s->specular = d[0]; s->specular_given = 1; break;
    case HFS_SK_GLOSS: s->gloss = d[0]; s->gloss_given = 1; break;
    case HFS_SK_VIEW_DIR: s->view_az = d[0]; s->view_el = d[1]; s->view_given = 1; break;
    case HFS_SK_KEY:
        if ((rc = add_light(src, &s->key_from_flags, &s->n_key, HFS_MAX_KEY_LIGHTS, where, "key",
                            err)))
            break;
        s->key[s->n_key].phi = d[0];
        s->key[s->n_key].elev = d[1];
        s->key[s->n_key].alpha = d[2];
        s->key[s->n_key].le = d[3];
        s->key[s->n_key].tint[0] = s->key[s->n_key].tint[1] = s->key[s->n_key].tint[2] = 1.0;
        if (n == KEY_RGB_N) { /* colour: le the largest channel, tint the ratios */
            const double m = fmax(d[3], fmax(d[4], d[5]));
            s->key[s->n_key].le = m;
            for (int c = 0; c < 3 && m > 0.0; ++c)
                s->key[s->n_key].tint[c] = d[3 + c] / m;
        }
        s->n_key++;
        break;
    case HFS_SK_PIN:
    case HFS_SK_BOX:
    case HFS_SK_POINT:
        rc = add_object(s, id, d, n, where, err);
        break;
    case HFS_SK_LOCAL:
        if ((rc = add_light(src, &s->local_from_flags, &s->n_local, HFS_MAX_LOCAL_LIGHTS, where,
                            "local", err)))
            break;
        s->local[s->n_local].x = d[0];
        s->local[s->n_local].y = d[1];
        s->local[s->n_local].z = d[2];
        s->local[s->n_local].r = d[3];
        s->local[s->n_local].le = d[4];
        s->n_local++;
        break;
    default:
        rc = hfs_fail(err, HFS_E_INVALID, "%s: unhandled key '%s'", where,
                      hfs_scene_key_get(id)->name);
    }
    return rc;
}

/* env-lights = auto | off | N (1..HFS_MAX_KEY_LIGHTS). */
static int set_env_lights(hfs_scene *s, const char *v, const char *where, hfs_error *err)
{
    if (!strcmp(v, "auto") || !strcmp(v, "off")) {
        s->env_lights = v[0] == 'a' ? -1 : 0;
        return HFS_OK;
    }
    char *end;
    errno = 0;
    const long n = strtol(v, &end, 10);
    if (end == v || *end || errno || n < 1 || n > HFS_MAX_KEY_LIGHTS)
        return hfs_fail(err, HFS_E_INVALID, "%s: env-lights: '%s' is not auto, off or a count "
                        "in [1, %d]", where, v, HFS_MAX_KEY_LIGHTS);
    s->env_lights = (int)n;
    return HFS_OK;
}

static int set_word(hfs_scene *s, hfs_scene_key_id id, const char *value, const char *where,
                    hfs_error *err)
{
    const hfs_scene_key *k = hfs_scene_key_get(id);
    const int w = hfs_scene_key_word(k, value);
    if (w < 0) {
        char words[128];
        hfs_scene_key_words_text(k, words, sizeof words);
        return hfs_fail(err, HFS_E_INVALID, "%s: %s: '%s' is not %s", where, k->name, value, words);
    }
    store_word(s, id, w, value);
    return HFS_OK;
}

int hfs_scene_apply_key(hfs_scene *s, hfs_scene_source src, const char *key,
                        const char *value, const char *where, const char *base_dir,
                        char objects_file[HFS_PATH_MAX], hfs_error *err)
{
    objects_file[0] = '\0';
    const int found = hfs_scene_key_find(key);
    if (found < 0)
        return hfs_fail(err, HFS_E_INVALID, "%s: unknown key '%s'", where, key);
    const hfs_scene_key_id id = (hfs_scene_key_id)found;
    const hfs_scene_key *k = hfs_scene_key_get(id);
    const unsigned long long bit = 1ull << id;
    if (!k->repeatable && (s->set_mask[src] & bit))
        return hfs_fail(err, HFS_E_INVALID, "%s: %s given twice", where, key);
    s->set_mask[src] |= bit;

    double d[HFS_SH_COEFFS] = {0}; /* parse_reals fills it on success */
    int rc, n = 0;
    switch (k->form) {
    case HFS_FORM_PATH:
        if (id == HFS_SK_OBJECTS) /* read by the caller (hfs_scene_set) */
            return set_path(objects_file, value, base_dir, where, key, err);
        return set_path(id == HFS_SK_HEIGHT ? s->height
                        : id == HFS_SK_ENV_MAP ? s->env_map
                                               : s->albedo_map,
                        value, base_dir, where, key, err);
    case HFS_FORM_SIZE:
        return set_size(s, value, where, err);
    case HFS_FORM_REALS:
        if ((rc = parse_reals(id, value, d, &n, where, err)))
            return rc;
        return store_reals(s, src, id, d, n, where, err);
    case HFS_FORM_INT:
        return parse_int(id, value, int_field(s, id), where, err);
    case HFS_FORM_WORD:
        if (id == HFS_SK_ENV_LIGHTS)
            return set_env_lights(s, value, where, err);
        return set_word(s, id, value, where, err);
    }
    return hfs_fail(err, HFS_E_INVALID, "%s: unhandled key '%s'", where, key);
}

int hfs_scene_validate(const hfs_scene *s, hfs_error *err)
{
    if (!s->height[0])
        return hfs_fail(err, HFS_E_INVALID, "scene: no height field (give --height FILE)");
    if (s->has_env_sh && s->env_map[0])
        return hfs_fail(err, HFS_E_INVALID, "scene: both env-sh and env-map given; choose one");
    if (s->env_sh_rgb_mask && s->env_sh_rgb_mask != 7)
        return hfs_fail(err, HFS_E_INVALID, "scene: env-sh-r, env-sh-g and env-sh-b go together "
                        "(%s missing)", !(s->env_sh_rgb_mask & 1) ? "env-sh-r"
                        : !(s->env_sh_rgb_mask & 2) ? "env-sh-g" : "env-sh-b");
    if (s->env_sh_rgb_mask && (s->has_env_sh || s->env_map[0]))
        return hfs_fail(err, HFS_E_INVALID, "scene: env-sh-r/g/b and %s given; choose one",
                        s->has_env_sh ? "env-sh" : "env-map");
    if (s->env_lights && !s->env_map[0])
        return hfs_fail(err, HFS_E_INVALID, "scene: env-lights needs an env-map");
    return HFS_OK;
}

double hfs_scene_spec_azimuth(const hfs_scene *s, double degrees)
{
    return s->azimuth_compass ? degrees - 90.0 : degrees;
}

void hfs_scene_lighting(const hfs_scene *s, const double (*env_sh)[HFS_SH_COEFFS],
                        hfs_lighting *l)
{
    /* The scene speaks degrees, the library radians. */
#define RAD(x) hfs_key_to_lib(HFS_UNIT_DEGREES, (x))
    hfs_lighting_defaults(l);
    if (env_sh) {
        l->has_env = 1;
        memcpy(l->env_sh, env_sh, sizeof l->env_sh);
    } else if (s->has_env_sh) {
        l->has_env = 1;
        for (int c = 0; c < 3; ++c)
            memcpy(l->env_sh[c], s->env_sh, sizeof s->env_sh);
    } else if (s->env_sh_rgb_mask == 7) {
        l->has_env = 1;
        memcpy(l->env_sh, s->env_sh_rgb, sizeof s->env_sh_rgb);
    }
    l->env_rotate = RAD(s->env_rotate_deg);
    l->n_key = s->n_key;
    for (int i = 0; i < s->n_key; ++i) {
        l->key[i].phi = RAD(hfs_scene_spec_azimuth(s, s->key[i].phi));
        l->key[i].elev = RAD(s->key[i].elev);
        l->key[i].alpha = RAD(s->key[i].alpha);
        /* A tint of zeros: a key set without the parser (grey). */
        const double *t = s->key[i].tint;
        const int grey = t[0] == 0.0 && t[1] == 0.0 && t[2] == 0.0;
        for (int c = 0; c < 3; ++c)
            l->key[i].radiance[c] = (float)(s->key[i].le * (grey ? 1.0 : t[c]));
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
    if (s->albedo_given)
        l->albedo = s->albedo;
    l->bounces = s->bounces;
    if (s->specular_given)
        l->specular = s->specular;
    if (s->gloss_given)
        l->gloss = s->gloss;
    if (s->view_given) { /* SPEC's s(phi, e) */
        const double az = RAD(hfs_scene_spec_azimuth(s, s->view_az)), el = RAD(s->view_el);
        l->view_dir[0] = cos(az) * cos(el);
        l->view_dir[1] = sin(az) * cos(el);
        l->view_dir[2] = sin(el);
    }
#undef RAD
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
    TAKE(HFS_SK_K, k);
    TAKE(HFS_SK_OFFSET, offset);
    TAKE(HFS_SK_NPHI_ENV, nphi_env);
    TAKE(HFS_SK_NPHI_KEY, nphi_key);
    TAKE(HFS_SK_REFINE, refine);
    TAKE(HFS_SK_SPLIT, split);
    TAKE(HFS_SK_FAR_FROM, far_from);
    TAKE(HFS_SK_FAR_DIRS, far_dirs);
    TAKE(HFS_SK_FAR_STEP, far_step);
    TAKE(HFS_SK_NPHI_BOUNCE, nphi_bounce);
    TAKE(HFS_SK_BOUNCE_REFINE, bounce_refine);
    TAKE(HFS_SK_BOUNCE_SUBSAMPLE, bounce_subsample);
    TAKE(HFS_SK_BOUNCE_NEAR, bounce_near);
    TAKE(HFS_SK_NPHI_LOCAL, nphi_local);
    TAKE(HFS_SK_SUBSAMPLE, subsample);
    TAKE(HFS_SK_PRECISION, precision);
    TAKE(HFS_SK_VISIBILITY, visibility);
    TAKE(HFS_SK_THREADS, threads);
    TAKE(HFS_SK_TRUTH_AZIMUTHS, truth_azimuths);
    TAKE(HFS_SK_TRUTH_SAMPLES, truth_light_samples);
    TAKE(HFS_SK_LOCAL_SWATH, local_full_swath);
#undef TAKE
}
