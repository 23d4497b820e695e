/*
 * scene.h — a scene as the user describes it: SPEC.md's command-line keys,
 * from a scene file (INI, parsed by libinih) and/or command-line flags.
 *
 * One setter, hfs_scene_set(), applies "key = value" for both sources, so the
 * scene file and the flags accept exactly the same keys with the same syntax
 * and ranges (the key is the flag without its leading "--").  The keys, their
 * ranges and defaults are the table of runtime/core/scene_keys.h.  Flags are
 * applied after the file and override it; a repeatable key (key, local) given
 * on the command line replaces the file's list instead of appending to it.
 *
 * Scene file format (docs/SCENE.md has the full reference):
 *     # comment            ; comment
 *     height = terrain.png        (relative paths: relative to the file)
 *     dx = 30
 *     key = 135,35,4,3            (phi, elevation, alpha in degrees; radiance)
 *     key = 300,60,10,1           (repeatable)
 *     key = 300,60,10,1,0.9,0.8   (in colour: R,G,B instead of one radiance)
 * No sections.  Unknown keys, sections, duplicate single-valued keys and
 * out-of-range values are errors naming the file and line.
 *
 * Angles are degrees here (as on the command line); hfs_scene_lighting()
 * converts to the library's radians.
 */
#ifndef HFS_SCENE_H
#define HFS_SCENE_H

#include "hfshade.h"
#include "scene_keys.h"

#define HFS_PATH_MAX 4096

typedef enum hfs_scene_source {
    HFS_SOURCE_FILE = 0,
    HFS_SOURCE_FLAG = 1
} hfs_scene_source;

typedef struct hfs_scene {
    /* Height field. */
    char height[HFS_PATH_MAX];
    int raw_width, raw_height;       /* --size WxH for raw float32          */
    double dx, zscale;               /* 0 = not given (defaults 1, 1)       */
    int dx_given, zscale_given;
    int has_nodata;
    double nodata;

    /* Environment: SH (grey, or per channel with env-sh-r/g/b) or a map
     * file, not both. */
    int has_env_sh;
    double env_sh[HFS_SH_COEFFS];
    int env_sh_rgb_mask;             /* env-sh-r/g/b given: bits 1, 2, 4    */
    double env_sh_rgb[3][HFS_SH_COEFFS];
    char env_map[HFS_PATH_MAX];
    double env_rotate_deg;
    int azimuth_compass;             /* azimuth-convention = compass: the
                                        azimuths read are clockwise from
                                        north (SPEC phi = compass - 90)   */
    int truth_env_sh;                /* truth-env = sh: the truth integrates
                                        the map's SH, not the map            */
    int env_shade_sh;                /* env-shade = sh: the cpu and gles
                                        backends light an env-map through its
                                        SH only (env_open, env_shade_map NULL) */
    int env_lights;                  /* env-lights: 0 off (default), -1
                                        auto, N: at most N lights          */

    /* Lights, angles in degrees. */
    int n_key;
    /* radiance = le * tint: `key = PHI,ELEV,ALPHA,LE` is grey (tint 1,1,1);
     * `key = PHI,ELEV,ALPHA,R,G,B` sets le = max(R,G,B), tint = RGB / le,
     * so the kiosk's radiance knob (le) scales the colour; a tint of
     * zeros (a key set by code, not parsed) is grey. */
    struct { double phi, elev, alpha, le, tint[3]; } key[HFS_MAX_KEY_LIGHTS];
    int n_local;
    struct { double x, y, z, r, le; } local[HFS_MAX_LOCAL_LIGHTS];
    /* Objects (pin, box, point keys and objects files, in order), world
     * units; drawn in the 3-D view (hfs_view objects). */
    int n_objects;
    hfs_object objects[HFS_MAX_OBJECTS];

    double albedo;                   /* 0 = not given (default 1)           */
    int albedo_given;
    char albedo_map[HFS_PATH_MAX];   /* "" = none                           */
    int bounces;                     /* indirect bounces, 0 = not given     */
    double specular, gloss;          /* glossy surfaces, when given         */
    int specular_given, gloss_given;
    double view_az, view_el;         /* view-dir, degrees, when given       */
    int view_given;

    hfs_quality quality;             /* values of the quality keys given    */
    char preset[16];                 /* "" or a hfs_quality_preset() use    */
    hfs_backend backend;
    char context[64];                /* "" = default (surfaceless)          */

    /* Internal bookkeeping: which single-valued keys were set by which
     * source, and whether a flag already replaced the file's lights. */
    unsigned long long set_mask[2];
    int key_from_flags, local_from_flags;
} hfs_scene;

/* Zeroes *s (all keys "not given"). */
void hfs_scene_init(hfs_scene *s);

/* Applies one key.  where names the origin for messages ("scene.ini:12" or
 * "--k").  base_dir, if non-NULL, resolves relative paths (scene files).
 * The objects key reads its file here (scene_ini.c).  Returns 0 or
 * HFS_E_INVALID with a one-line message. */
int hfs_scene_set(hfs_scene *s, hfs_scene_source src, const char *key,
                  const char *value, const char *where, const char *base_dir,
                  hfs_error *err);
/* hfs_scene_set without reading a file (scene.c): the objects key's path,
 * resolved and checked, is written to objects_file for the caller to read
 * (else objects_file is ""). */
int hfs_scene_apply_key(hfs_scene *s, hfs_scene_source src, const char *key,
                        const char *value, const char *where, const char *base_dir,
                        char objects_file[HFS_PATH_MAX], hfs_error *err);

/* Reads a scene file (INI).  Errors name the file and line. */
int hfs_scene_load_file(hfs_scene *s, const char *path, hfs_error *err);
/* Reads an objects file (scene key objects): pin, box and point lines in
 * the scene file's syntax, appended to s->objects. */
int hfs_scene_load_objects(hfs_scene *s, const char *path, hfs_error *err);

/* True if key (without "--") is a scene key. */
int hfs_scene_is_key(const char *key);

/* Checks cross-key consistency (height given, one of env-sh, env-sh-r/g/b
 * (all three) and env-map, env-lights
 * only with env-map, raw size given for raw files) after all sources are
 * applied. */
int hfs_scene_validate(const hfs_scene *s, hfs_error *err);

/* Fills the library's lighting and quality from the scene (radians, RGB).
 * env_sh: if the scene uses an environment map, the caller passes its SH
 * projection here (3 x 16), else NULL. */
/* An azimuth as the scene reads it (degrees; azimuth-convention) in SPEC's
 * convention: compass - 90 (SPEC "Azimuths for map users"). */
double hfs_scene_spec_azimuth(const hfs_scene *s, double degrees);

void hfs_scene_lighting(const hfs_scene *s, const double (*env_sh)[HFS_SH_COEFFS],
                        hfs_lighting *l);
void hfs_scene_quality(const hfs_scene *s, hfs_quality *q);

/* The table of scene keys (scene_keys.h: name, value form, units, ranges,
 * default, help), for help texts; prints nothing. */
typedef hfs_scene_key hfs_scene_key_info;
const hfs_scene_key_info *hfs_scene_keys(int *count);

#endif /* HFS_SCENE_H */
