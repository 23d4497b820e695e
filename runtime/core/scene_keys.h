/*
 * scene_keys.h — the scene keys, one table: for every key a scene file or a
 * command-line flag may set (SPEC.md "Command-line contract"; docs/SCENE.md
 * is this table in prose) its name, the form of its value, the unit and
 * accepted range of each number in it, its default and its help line.
 *
 * One table, three readers, so that a range is written once:
 *   - the scene parser (runtime/scene/scene.c) checks every value with
 *     hfs_scene_key_check;
 *   - the kiosk's input configuration (board/input_config.c) takes the
 *     limits of each knob action from the number the action edits;
 *   - the renderer's validation (hfs_validate_inputs, runtime/renderer/validate.c)
 *     checks the library field a number becomes with
 *     hfs_scene_key_check_lib, in the library's units: the scene speaks
 *     degrees, the library radians, and hfs_scene_key_lib_range is the one
 *     place that converts a range.
 * A number's library field takes the same range (converted) unless its row
 * says otherwise (hfs_key_number.lib, with the reason at the row).
 *
 * Part of hfs_core: libc and libm only, no state.  Messages are one line.
 */
#ifndef HFS_SCENE_KEYS_H
#define HFS_SCENE_KEYS_H

#include <stddef.h>

#include "hfshade.h"

/* In the order `hfshade keys` lists them. */
typedef enum hfs_scene_key_id {
    HFS_SK_HEIGHT, HFS_SK_SIZE, HFS_SK_DX, HFS_SK_ZSCALE, HFS_SK_NODATA, HFS_SK_ENV_SH,
    HFS_SK_ENV_SH_R, HFS_SK_ENV_SH_G, HFS_SK_ENV_SH_B, HFS_SK_ENV_MAP, HFS_SK_ENV_ROTATE, HFS_SK_ENV_LIGHTS, HFS_SK_KEY, HFS_SK_LOCAL, HFS_SK_ALBEDO, HFS_SK_ALBEDO_MAP, HFS_SK_BOUNCES, HFS_SK_K,
    HFS_SK_OFFSET, HFS_SK_NPHI_ENV, HFS_SK_NPHI_KEY, HFS_SK_REFINE, HFS_SK_SPLIT, HFS_SK_FAR_FROM,
    HFS_SK_FAR_DIRS, HFS_SK_FAR_STEP, HFS_SK_NPHI_BOUNCE,
    HFS_SK_BOUNCE_REFINE, HFS_SK_BOUNCE_SUBSAMPLE, HFS_SK_BOUNCE_NEAR, HFS_SK_NPHI_LOCAL,
    HFS_SK_SUBSAMPLE,
    HFS_SK_PRECISION, HFS_SK_BACKEND, HFS_SK_CONTEXT, HFS_SK_VISIBILITY, HFS_SK_THREADS,
    HFS_SK_TRUTH_AZIMUTHS, HFS_SK_TRUTH_SAMPLES, HFS_SK_LOCAL_SWATH, HFS_SK_PRESET,
    HFS_SK_SPECULAR, HFS_SK_GLOSS, HFS_SK_VIEW_DIR, HFS_SK_TRUTH_ENV,
    HFS_SK_AZIMUTH_CONVENTION, HFS_SK_ENV_SHADE, HFS_SK_PIN, HFS_SK_BOX, HFS_SK_POINT,
    HFS_SK_OBJECTS,
    HFS_SK_COUNT
} hfs_scene_key_id;

typedef enum hfs_key_form {
    HFS_FORM_PATH,     /* a file name (relative to the scene file)             */
    HFS_FORM_SIZE,     /* WxH, two decimal integers                            */
    HFS_FORM_REALS,    /* n finite numbers separated by commas                 */
    HFS_FORM_INT,      /* one decimal integer                                  */
    HFS_FORM_WORD      /* one of the words of `arg` ("fp16|fp32")              */
} hfs_key_form;

typedef enum hfs_key_unit {
    HFS_UNIT_NONE,     /* a pure number (albedo, a scale)                      */
    HFS_UNIT_COUNT,    /* a count (levels, samples, threads)                   */
    HFS_UNIT_TEXELS,   /* grid points                                          */
    HFS_UNIT_HEIGHT,   /* a value of the height file                           */
    HFS_UNIT_WORLD,    /* world units, those of dx                             */
    HFS_UNIT_DEGREES,  /* an angle: degrees here, RADIANS in the library       */
    HFS_UNIT_RADIANCE  /* linear radiance (a float in the library)             */
} hfs_key_unit;

/* [lo, hi], or (lo, hi] when lo_open; hi is always included.  -DBL_MAX and
 * DBL_MAX stand for "no bound" (the number need only be finite). */
typedef struct hfs_key_range {
    double lo, hi;
    int lo_open;
} hfs_key_range;

typedef struct hfs_key_number {
    const char *what;          /* its name in messages ("elevation"); NULL:
                                  the key's name says it (k, albedo)         */
    hfs_key_unit unit;
    hfs_key_range range;       /* accepted, in unit                          */
    const hfs_key_range *lib;  /* NULL: the library field takes range (in
                                  library units); else the library's own     */
} hfs_key_number;

#define HFS_KEY_MAX_NUMBERS 6

typedef struct hfs_scene_key {
    const char *name;          /* as in a scene file; the flag without "--"  */
    const char *arg;           /* the value's form in help texts             */
    hfs_key_form form;
    int n;                     /* numbers in the value (REALS, INT, SIZE)    */
    int repeatable;            /* each one adds a light or an object         */
    int pow2;                  /* INT: only the powers of two in range       */
    hfs_key_number num[HFS_KEY_MAX_NUMBERS]; /* env-sh: num[0] for all 16    */
    const char *def;           /* the default, written as a value; NULL: none */
    const char *help;
} hfs_scene_key;

/* Object keys (pin, box, point): an optional R,G,B albedo (each in [0, 1])
 * may follow their n numbers. */
static inline int hfs_scene_key_has_colour(hfs_scene_key_id id)
{
    return id == HFS_SK_PIN || id == HFS_SK_BOX || id == HFS_SK_POINT;
}

/* The row of id; NULL when id is out of range. */
const hfs_scene_key *hfs_scene_key_get(hfs_scene_key_id id);
/* The id of the key called name (no "--"), or -1. */
int hfs_scene_key_find(const char *name);
/* Number i of key id (env-sh: any i < 16 gives num[0]); NULL if none. */
const hfs_key_number *hfs_scene_key_number(hfs_scene_key_id id, int i);

/* Whether x lies in r (NaN never does). */
int hfs_key_in_range(const hfs_key_range *r, double x);
/* The range number i of key id has as a library field: the row's lib range
 * if it has one, else its range with degrees converted to radians
 * (x * pi / 180, as hfs_key_to_lib converts values). */
hfs_key_range hfs_scene_key_lib_range(hfs_scene_key_id id, int i);
/* A value of unit u in library units (degrees to radians; else x). */
double hfs_key_to_lib(hfs_key_unit u, double x);

/* Checks number i of key id.  Scene units: the message is "WHERE: KEY:
 * WHAT X is out of range [LO, HI]" (where: "scene.ini:7" or "--k").
 * Library units: "WHO: WHAT X is out of range [LO, HI]" (who: "dx", "key
 * light 2").  0 or HFS_E_INVALID. */
int hfs_scene_key_check(hfs_scene_key_id id, int i, double x, const char *where,
                        hfs_error *err);
int hfs_scene_key_check_lib(hfs_scene_key_id id, int i, double x, const char *who,
                            hfs_error *err);

/* An INT key's value test beyond its range: pow2 keys take only the powers
 * of two in range.  1 if allowed. */
int hfs_scene_key_int_allowed(const hfs_scene_key *k, long x);
/* "1, 2, 4": the values a pow2 key allows. */
void hfs_scene_key_allowed_text(const hfs_scene_key *k, char *buf, size_t size);

/* WORD keys: the index of value among the words of k->arg, or -1; and the
 * words for a message ("fp16 or fp32", "gles, cpu or truth"). */
int hfs_scene_key_word(const hfs_scene_key *k, const char *value);
void hfs_scene_key_words_text(const hfs_scene_key *k, char *buf, size_t size);

/* "[1e-09, 1e+12]", "(0, 89]", "[0, inf)", "(-inf, inf)"; counts of unit u
 * exactly ("[1, 1048576]"). */
void hfs_key_range_text(const hfs_key_range *r, hfs_key_unit u, char *buf, size_t size);
/* "deg", "world units", ...; "" for HFS_UNIT_NONE and HFS_UNIT_COUNT. */
const char *hfs_key_unit_name(hfs_key_unit u);

#endif /* HFS_SCENE_KEYS_H */
