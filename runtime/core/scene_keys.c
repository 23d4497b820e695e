/*
 * scene_keys.c — the table of scene keys and the range checks made from it
 * (scene_keys.h).
 *
 * Invariants: a number's range is written here and nowhere else; the
 * library's range of a field is this range converted to library units (or
 * the row's `lib` range, where the library deliberately accepts more), so a
 * value the scene accepts is never refused by hfs_validate_inputs, and a
 * value just outside is refused by both (tests/test_scene_keys.c).
 * Defaults of the quality keys are those of hfs_quality_defaults (the
 * "kiosk" preset); the same test pins them.
 */
#include "scene_keys.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define ANY {-DBL_MAX, DBL_MAX, 0}            /* any finite number            */
#define NONNEG {0.0, DBL_MAX, 0}              /* any finite number >= 0       */
#define RADIANCE {"radiance", HFS_UNIT_RADIANCE, {0.0, FLT_MAX, 0}, NULL} /* a float */
/* 16 SH coefficients of an environment channel (env-sh, env-sh-r/g/b). */
#define SH_KEY(name, help)                                                       \
    {name, "c0,...,c15", HFS_FORM_REALS, HFS_SH_COEFFS, 0, 0,                    \
     {{"coefficient", HFS_UNIT_RADIANCE, ANY, NULL}}, NULL, help}

/* The ground truth's horizons: SPEC's checks assume >= 720 azimuths, which
 * is what a scene may ask for; tests run a coarser truth through the
 * library (test_sh_oracle: 180). */
static const hfs_key_range truth_azimuths_lib = {1.0, 100000.0, 0};

static const hfs_scene_key keys[HFS_SK_COUNT] = {
    [HFS_SK_HEIGHT] = {"height", "FILE", HFS_FORM_PATH, 0, 0, 0, {{0}}, NULL,
                       "height field: PNG16, PGM, PFM, ESRI .asc, raw f32 (with size)"},
    /* Also the library's field size (hfs_field width, height). */
    [HFS_SK_SIZE] = {"size", "WxH", HFS_FORM_SIZE, 2, 0, 0,
                     {{"width", HFS_UNIT_TEXELS, {2, 65536, 0}, NULL},
                      {"height", HFS_UNIT_TEXELS, {2, 65536, 0}, NULL}},
                     NULL, "size of a raw float32 height file"},
    /* Wide but bounded: every product of heights, scales and spacings stays
     * far from double overflow and underflow. */
    [HFS_SK_DX] = {"dx", "F", HFS_FORM_REALS, 1, 0, 0,
                   {{"spacing", HFS_UNIT_WORLD, {1e-9, 1e12, 0}, NULL}}, "1",
                   "texel spacing in world units (.asc: its cellsize)"},
    [HFS_SK_ZSCALE] = {"zscale", "F", HFS_FORM_REALS, 1, 0, 0,
                       {{"scale", HFS_UNIT_NONE, {0.0, 1e12, 0}, NULL}}, "1",
                       "vertical scale: world z = zscale * height"},
    [HFS_SK_NODATA] = {"nodata", "V", HFS_FORM_REALS, 1, 0, 0,
                       {{NULL, HFS_UNIT_HEIGHT, ANY, NULL}}, NULL,
                       "height value that marks a hole, besides NaN/Inf"},
    [HFS_SK_ENV_SH] = SH_KEY("env-sh", "grey environment as 16 SH coefficients"),
    /* The environment in colour, one channel a key (16 numbers fit a scene
     * file's line; 48 would not): all three or none, instead of env-sh. */
    [HFS_SK_ENV_SH_R] = SH_KEY("env-sh-r",
                               "environment in colour: the red channel's 16 SH coefficients"),
    [HFS_SK_ENV_SH_G] = SH_KEY("env-sh-g", "environment in colour: the green channel's"),
    [HFS_SK_ENV_SH_B] = SH_KEY("env-sh-b", "environment in colour: the blue channel's"),
    [HFS_SK_ENV_MAP] = {"env-map", "FILE", HFS_FORM_PATH, 0, 0, 0, {{0}}, NULL,
                        "environment as an equirect .hdr, .exr or .pfm map"},
    [HFS_SK_ENV_ROTATE] = {"env-rotate", "DEG", HFS_FORM_REALS, 1, 0, 0,
                           {{"angle", HFS_UNIT_DEGREES, {-36000.0, 36000.0, 0}, NULL}}, "0",
                           "rotate the environment about +z"},
    /* auto|off|N: parsed by the scene (scene.c set_env_lights); N in
     * 1..HFS_MAX_KEY_LIGHTS. */
    [HFS_SK_ENV_LIGHTS] = {"env-lights", "auto|off|N", HFS_FORM_WORD, 0, 0, 0, {{0}}, "off",
                           "env-map's bright regions as key lights (auto: up to 4) + residual"},
    [HFS_SK_KEY] = {"key", "PHI,ELEV,ALPHA,LE", HFS_FORM_REALS, 4, 1, 0,
                    {{"azimuth", HFS_UNIT_DEGREES, {-3600.0, 3600.0, 0}, NULL},
                     {"elevation", HFS_UNIT_DEGREES, {-90.0, 90.0, 0}, NULL},
                     {"angular radius", HFS_UNIT_DEGREES, {0.0, 89.0, 1}, NULL},
                     RADIANCE},
                    NULL, "key (disk) light, degrees; repeatable"},
    [HFS_SK_LOCAL] = {"local", "X,Y,Z,R,LE", HFS_FORM_REALS, 5, 1, 0,
                      {{"coordinate", HFS_UNIT_WORLD, ANY, NULL},
                       {"coordinate", HFS_UNIT_WORLD, ANY, NULL},
                       {"coordinate", HFS_UNIT_WORLD, ANY, NULL},
                       {"radius", HFS_UNIT_WORLD, NONNEG, NULL},
                       RADIANCE},
                      NULL, "local spherical light, world units; repeatable"},
    [HFS_SK_ALBEDO] = {"albedo", "F", HFS_FORM_REALS, 1, 0, 0,
                       {{NULL, HFS_UNIT_NONE, {0.0, 1.0, 0}, NULL}}, "1",
                       "Lambertian albedo"},
    [HFS_SK_BOUNCES] = {"bounces", "N", HFS_FORM_INT, 1, 0, 0,
                        {{NULL, HFS_UNIT_COUNT, {0, 3, 0}, NULL}}, "0",
                        "indirect diffuse bounces"},
    [HFS_SK_ALBEDO_MAP] = {"albedo-map", "FILE", HFS_FORM_PATH, 0, 0, 0, {{0}}, NULL,
                           "per-texel RGB albedo times --albedo: PNG, PFM, .exr, .hdr, the heights' size"},
    [HFS_SK_K] = {"k", "N", HFS_FORM_INT, 1, 0, 0,
                  {{NULL, HFS_UNIT_COUNT, {1, 16, 0}, NULL}}, "2",
                  "pyramid level step, levels per octave"},
    [HFS_SK_OFFSET] = {"offset", "N", HFS_FORM_INT, 1, 0, 0,
                       {{NULL, HFS_UNIT_COUNT, {0, 16, 0}, NULL}}, "8",
                       "pyramid level offset"},
    [HFS_SK_NPHI_ENV] = {"nphi-env", "N", HFS_FORM_INT, 1, 0, 0,
                         {{NULL, HFS_UNIT_COUNT, {3, 1024, 0}, NULL}}, "12",
                         "azimuth samples for the environment"},
    [HFS_SK_NPHI_KEY] = {"nphi-key", "N", HFS_FORM_INT, 1, 0, 0,
                         {{NULL, HFS_UNIT_COUNT, {1, 256, 0}, NULL}}, "3",
                         "azimuth samples per key light"},
    [HFS_SK_REFINE] = {"refine", "N", HFS_FORM_INT, 1, 0, 0,
                       {{NULL, HFS_UNIT_COUNT, {0, 16, 0}, NULL}}, "4",
                       "samples refining each environment and key-light horizon between "
                       "scales (0: the seeds')"},
    [HFS_SK_SPLIT] = {"split", "0|1", HFS_FORM_INT, 1, 0, 0,
                      {{NULL, HFS_UNIT_COUNT, {0, 1, 0}, NULL}}, "1",
                      "split horizons: the environment's far ones from a coarser grid at "
                      "more azimuths (0: one horizon per direction)"},
    [HFS_SK_FAR_FROM] = {"far-from", "N", HFS_FORM_INT, 1, 0, 0,
                         {{NULL, HFS_UNIT_TEXELS, {0, 4096, 0}, NULL}}, "0",
                         "split horizons' far part beyond N texels (0: 8, 16, 16 at subsample "
                         "1, 2, 4)"},
    [HFS_SK_FAR_DIRS] = {"far-dirs", "N", HFS_FORM_INT, 1, 0, 0,
                         {{NULL, HFS_UNIT_COUNT, {0, 8, 0}, NULL}}, "0",
                         "far sub-directions per environment direction (0: 3, 2, 2)"},
    [HFS_SK_FAR_STEP] = {"far-step", "N", HFS_FORM_INT, 1, 0, 0,
                         {{NULL, HFS_UNIT_COUNT, {0, 64, 0}, NULL}}, "0",
                         "the far grid's step, texels (0: 2, 8, 16)"},
    [HFS_SK_NPHI_BOUNCE] = {"nphi-bounce", "N", HFS_FORM_INT, 1, 0, 0,
                            {{NULL, HFS_UNIT_COUNT, {1, 1024, 0}, NULL}}, "12",
                            "azimuths the bounces gather along: the largest divisor of "
                            "nphi-env not above N, every (nphi-env / that)-th of its directions"},
    [HFS_SK_BOUNCE_REFINE] = {"bounce-refine", "N", HFS_FORM_INT, 1, 0, 0,
                              {{NULL, HFS_UNIT_COUNT, {0, 16, 0}, NULL}}, "1",
                              "samples after each scale of the bounces' walk"},
    [HFS_SK_BOUNCE_SUBSAMPLE] = {"bounce-subsample", "1|2|4|8", HFS_FORM_INT, 1, 0, 1,
                                 {{NULL, HFS_UNIT_COUNT, {1, 8, 0}, NULL}}, "4",
                                 "grid step of the GLES path's bounce gather (at least subsample's)"},
    [HFS_SK_BOUNCE_NEAR] = {"bounce-near", "N", HFS_FORM_INT, 1, 0, 0,
                            {{NULL, HFS_UNIT_COUNT, {0, 16, 0}, NULL}}, "2",
                            "texels of each texel's bounce gather taken at the texel on a "
                            "sub-sampled bounce grid (GLES; 0: all on the grid)"},
    [HFS_SK_NPHI_LOCAL] = {"nphi-local", "N", HFS_FORM_INT, 1, 0, 0,
                           {{NULL, HFS_UNIT_COUNT, {3, 1024, 0}, NULL}}, "16",
                           "azimuth samples per local light"},
    [HFS_SK_SUBSAMPLE] = {"subsample", "1|2|4", HFS_FORM_INT, 1, 0, 1,
                          {{NULL, HFS_UNIT_COUNT, {1, 4, 0}, NULL}}, "2",
                          "visibility sub-sampling of the GLES path"},
    [HFS_SK_PRECISION] = {"precision", "fp16|fp32", HFS_FORM_WORD, 0, 0, 0, {{0}}, "fp16",
                          "texture precision of the GLES path"},
    [HFS_SK_BACKEND] = {"backend", "gles|cpu|truth", HFS_FORM_WORD, 0, 0, 0, {{0}}, "gles",
                        "renderer: GLES, CPU reference, ground truth"},
    [HFS_SK_CONTEXT] = {"context", "surfaceless|osmesa|auto", HFS_FORM_WORD, 0, 0, 0, {{0}},
                        "surfaceless", "how the GLES context is made"},
    [HFS_SK_VISIBILITY] = {"visibility", "legendre|wedge|slice", HFS_FORM_WORD, 0, 0, 0, {{0}},
                           "slice", "visibility to SH: NS09 Legendre, SN08 wedge tables, "
                           "or exact slice lighting"},
    /* 0: as many as the machine has cores (at most 64, hfs_parallel). */
    [HFS_SK_THREADS] = {"threads", "N", HFS_FORM_INT, 1, 0, 0,
                        {{NULL, HFS_UNIT_COUNT, {0, 64, 0}, NULL}}, "0",
                        "CPU/truth worker threads, 0: all cores"},
    [HFS_SK_TRUTH_AZIMUTHS] = {"truth-azimuths", "N", HFS_FORM_INT, 1, 0, 0,
                               {{NULL, HFS_UNIT_COUNT, {720, 100000, 0}, &truth_azimuths_lib}},
                               "720", "ground truth: horizon azimuths"},
    [HFS_SK_TRUTH_SAMPLES] = {"truth-samples", "N", HFS_FORM_INT, 1, 0, 0,
                              {{NULL, HFS_UNIT_COUNT, {1, 1 << 20, 0}, NULL}}, "256",
                              "ground truth: samples per light, and rays per texel per bounce"},
    [HFS_SK_LOCAL_SWATH] = {"local-swath", "partial|full", HFS_FORM_WORD, 0, 0, 0, {{0}},
                            "partial", "local lights: per-receiver partial swath or full"},
    [HFS_SK_PRESET] = {"preset", "kiosk|panel|headless", HFS_FORM_WORD, 0, 0, 0, {{0}}, "kiosk",
                       "quality settings per use (BENCHMARKS.md); other quality keys override it"},
    /* Glossy surfaces (DESIGN.md "Glossy surfaces"); albedo + specular <= 1
     * is checked with the lighting (hfs_validate_lighting). */
    [HFS_SK_SPECULAR] = {"specular", "F", HFS_FORM_REALS, 1, 0, 0,
                         {{NULL, HFS_UNIT_NONE, {0.0, 1.0, 0}, NULL}}, "0",
                         "specular albedo of the Phong lobe (0: diffuse only)"},
    [HFS_SK_GLOSS] = {"gloss", "S", HFS_FORM_REALS, 1, 0, 0,
                      {{NULL, HFS_UNIT_NONE, {1.0, 10000.0, 0}, NULL}}, "32",
                      "Phong exponent of the specular lobe"},
    /* The library takes a unit vector (hfs_lighting.view_dir): no field per
     * number, its own check in renderer.c. */
    [HFS_SK_VIEW_DIR] = {"view-dir", "AZ,EL", HFS_FORM_REALS, 2, 0, 0,
                         {{"azimuth", HFS_UNIT_DEGREES, {-3600.0, 3600.0, 0}, NULL},
                          {"elevation", HFS_UNIT_DEGREES, {0.0, 90.0, 1}, NULL}},
                         "0,90", "direction towards the viewer of glossy grid dumps, degrees"},
    [HFS_SK_TRUTH_ENV] = {"truth-env", "map|sh", HFS_FORM_WORD, 0, 0, 0, {{0}}, "map",
                          "ground truth of an env-map: the map itself, or its SH projection"},
    [HFS_SK_AZIMUTH_CONVENTION] = {"azimuth-convention", "spec|compass", HFS_FORM_WORD, 0, 0, 0,
                                   {{0}}, "spec",
                                   "how key, view-dir and --camera azimuths read: SPEC's "
                                   "(from +x toward +y) or compass (clockwise from north, "
                                   "= 90 + SPEC's on a north-up field)"},
    /* Objects above the field (hfshade.h hfs_object; drawn in the 3-D view). */
    [HFS_SK_PIN] = {"pin", "X,Y,H,W[,R,G,B]", HFS_FORM_REALS, 4, 1, 0,
                    {{"coordinate", HFS_UNIT_WORLD, NONNEG, NULL},
                     {"coordinate", HFS_UNIT_WORLD, NONNEG, NULL},
                     {"height", HFS_UNIT_WORLD, {0.0, 1e12, 1}, NULL},
                     {"width", HFS_UNIT_WORLD, {0.0, 1e12, 1}, NULL}},
                    NULL, "a vertical post standing on the surface at (X, Y), world units, "
                    "albedo R,G,B (default 0.8 grey); repeatable"},
    [HFS_SK_BOX] = {"box", "X,Y,Z,W,D,H[,R,G,B]", HFS_FORM_REALS, 6, 1, 0,
                    {{"coordinate", HFS_UNIT_WORLD, NONNEG, NULL},
                     {"coordinate", HFS_UNIT_WORLD, NONNEG, NULL},
                     {"height above the surface", HFS_UNIT_WORLD, {0.0, 1e12, 0}, NULL},
                     {"width", HFS_UNIT_WORLD, {0.0, 1e12, 1}, NULL},
                     {"depth", HFS_UNIT_WORLD, {0.0, 1e12, 1}, NULL},
                     {"height", HFS_UNIT_WORLD, {0.0, 1e12, 1}, NULL}},
                    NULL, "an axis-aligned box centred on (X, Y), its bottom Z above the "
                    "surface, W x D x H, world units; repeatable"},
    [HFS_SK_POINT] = {"point", "X,Y,Z,S[,R,G,B]", HFS_FORM_REALS, 4, 1, 0,
                      {{"coordinate", HFS_UNIT_WORLD, NONNEG, NULL},
                       {"coordinate", HFS_UNIT_WORLD, NONNEG, NULL},
                       {"height above the surface", HFS_UNIT_WORLD, {0.0, 1e12, 0}, NULL},
                       {"size", HFS_UNIT_WORLD, {0.0, 1e12, 1}, NULL}},
                      NULL, "a marker: a cube of side S centred Z above the surface at (X, Y); "
                      "repeatable"},
    [HFS_SK_OBJECTS] = {"objects", "FILE", HFS_FORM_PATH, 0, 0, 0, {{0}}, NULL,
                        "objects from a file: one pin, box or point line (KEY = VALUE, as "
                        "here) per object, # comments"},
    [HFS_SK_ENV_SHADE] = {"env-shade", "map|sh", HFS_FORM_WORD, 0, 0, 0, {{0}}, "map",
                          "how the cpu and gles backends light an env-map: from the map "
                          "itself (open sky and occluded slices), or through its SH only"},
};

const hfs_scene_key *hfs_scene_key_get(hfs_scene_key_id id)
{
    return (int)id >= 0 && id < HFS_SK_COUNT ? &keys[id] : NULL;
}

int hfs_scene_key_find(const char *name)
{
    for (int i = 0; i < HFS_SK_COUNT; ++i)
        if (!strcmp(keys[i].name, name))
            return i;
    return -1;
}

const hfs_key_number *hfs_scene_key_number(hfs_scene_key_id id, int i)
{
    const hfs_scene_key *k = hfs_scene_key_get(id);
    if (!k || i < 0 || i >= k->n)
        return NULL;
    return &k->num[k->n > HFS_KEY_MAX_NUMBERS ? 0 : i];
}

int hfs_key_in_range(const hfs_key_range *r, double x)
{
    return (r->lo_open ? x > r->lo : x >= r->lo) && x <= r->hi;
}

double hfs_key_to_lib(hfs_key_unit u, double x)
{
    return u == HFS_UNIT_DEGREES ? x * (3.14159265358979323846 / 180.0) : x;
}

/* A bound in library units; "no bound" stays what it is. */
static double bound_to_lib(hfs_key_unit u, double x)
{
    return x == DBL_MAX || x == -DBL_MAX ? x : hfs_key_to_lib(u, x);
}

hfs_key_range hfs_scene_key_lib_range(hfs_scene_key_id id, int i)
{
    const hfs_key_number *n = hfs_scene_key_number(id, i);
    if (!n)
        return (hfs_key_range){DBL_MAX, -DBL_MAX, 0}; /* holds nothing */
    if (n->lib)
        return *n->lib;
    return (hfs_key_range){bound_to_lib(n->unit, n->range.lo), bound_to_lib(n->unit, n->range.hi),
                           n->range.lo_open};
}

/* Counts print exactly ("1048576"), the rest as %g. */
static void number_text(double x, int exact, char *buf, size_t size)
{
    if (exact && fabs(x) < 9e15 && x == (double)(long long)x)
        snprintf(buf, size, "%lld", (long long)x);
    else
        snprintf(buf, size, "%g", x);
}

static int exact_unit(hfs_key_unit u) { return u == HFS_UNIT_COUNT || u == HFS_UNIT_TEXELS; }

static void range_text(const hfs_key_range *r, int exact, char *buf, size_t size)
{
    char lo[32] = "(-inf", hi[32] = "inf)";
    if (r->lo != -DBL_MAX) {
        lo[0] = r->lo_open ? '(' : '[';
        number_text(r->lo, exact, lo + 1, sizeof lo - 1);
    }
    if (r->hi != DBL_MAX) {
        number_text(r->hi, exact, hi, sizeof hi - 1);
        strcat(hi, "]");
    }
    snprintf(buf, size, "%s, %s", lo, hi);
}

void hfs_key_range_text(const hfs_key_range *r, hfs_key_unit u, char *buf, size_t size)
{
    range_text(r, exact_unit(u), buf, size);
}

/* "PREFIX: WHAT X is out of range [LO, HI]SUFFIX" */
static int out_of_range(const char *prefix, const hfs_key_number *n, const hfs_key_range *r,
                        double x, const char *suffix, hfs_error *err)
{
    char xs[32], rs[80];
    number_text(x, exact_unit(n->unit), xs, sizeof xs);
    range_text(r, exact_unit(n->unit), rs, sizeof rs);
    return hfs_fail(err, HFS_E_INVALID, "%s: %s%s%s is out of range %s%s", prefix,
                    n->what ? n->what : "", n->what ? " " : "", xs, rs, suffix);
}

int hfs_scene_key_check(hfs_scene_key_id id, int i, double x, const char *where,
                        hfs_error *err)
{
    const hfs_key_number *n = hfs_scene_key_number(id, i);
    if (!n)
        return hfs_fail(err, HFS_E_INVALID, "%s: no number %d in key %d", where, i, (int)id);
    if (hfs_key_in_range(&n->range, x))
        return HFS_OK;
    char prefix[160];
    snprintf(prefix, sizeof prefix, "%s: %s", where, keys[id].name);
    return out_of_range(prefix, n, &n->range, x, "", err);
}

int hfs_scene_key_check_lib(hfs_scene_key_id id, int i, double x, const char *who,
                            hfs_error *err)
{
    const hfs_key_number *n = hfs_scene_key_number(id, i);
    if (!n)
        return hfs_fail(err, HFS_E_INVALID, "%s: no number %d in key %d", who, i, (int)id);
    const hfs_key_range r = hfs_scene_key_lib_range(id, i);
    if (hfs_key_in_range(&r, x))
        return HFS_OK;
    return out_of_range(who, n, &r, x, n->unit == HFS_UNIT_DEGREES && !n->lib ? " (radians)" : "",
                        err);
}

int hfs_scene_key_int_allowed(const hfs_scene_key *k, long x)
{
    return !k->pow2 || (x > 0 && (x & (x - 1)) == 0);
}

void hfs_scene_key_allowed_text(const hfs_scene_key *k, char *buf, size_t size)
{
    size_t used = 0;
    buf[0] = '\0';
    for (long x = 1; x <= (long)k->num[0].range.hi && used < size; x *= 2)
        if (x >= (long)k->num[0].range.lo)
            used += (size_t)snprintf(buf + used, size - used, "%s%ld", used ? ", " : "", x);
}

/* The i-th word of k->arg: its start and length; 0 when there is none. */
static size_t word_at(const hfs_scene_key *k, int i, const char **start)
{
    const char *p = k->arg;
    *start = "";
    for (; i > 0 && p; --i) {
        p = strchr(p, '|');
        p = p ? p + 1 : NULL;
    }
    if (!p)
        return 0;
    *start = p;
    const char *bar = strchr(p, '|');
    return bar ? (size_t)(bar - p) : strlen(p);
}

int hfs_scene_key_word(const hfs_scene_key *k, const char *value)
{
    const char *w;
    size_t len;
    for (int i = 0; k->form == HFS_FORM_WORD && (len = word_at(k, i, &w)) > 0; ++i)
        if (strlen(value) == len && !strncmp(value, w, len))
            return i;
    return -1;
}

void hfs_scene_key_words_text(const hfs_scene_key *k, char *buf, size_t size)
{
    const char *w;
    size_t len, used = 0;
    int n = 0;
    while (word_at(k, n, &w) > 0)
        ++n;
    buf[0] = '\0';
    for (int i = 0; i < n && used < size; ++i) {
        len = word_at(k, i, &w);
        used += (size_t)snprintf(buf + used, size - used, "%s%.*s",
                                 i == 0 ? "" : i == n - 1 ? " or " : ", ", (int)len, w);
    }
}

const char *hfs_key_unit_name(hfs_key_unit u)
{
    switch (u) {
    case HFS_UNIT_TEXELS: return "texels";
    case HFS_UNIT_HEIGHT: return "height units";
    case HFS_UNIT_WORLD: return "world units";
    case HFS_UNIT_DEGREES: return "degrees";
    case HFS_UNIT_RADIANCE: return "radiance";
    case HFS_UNIT_NONE:
    case HFS_UNIT_COUNT: break;
    }
    return "";
}
