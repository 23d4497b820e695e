/*
 * plan_keys_rows.h — test_plan_keys.c's scene: the common base, and per
 * scene key of runtime/core/scene_keys.c a change of it (a key may have
 * more rows: env-rotate on an SH sky and on a map).  A row's base is the
 * common one with its `base` assignments made (value NULL: the key left
 * out), for keys that need another key first (the colour channels instead
 * of env-sh, bounces for the bounce settings); its change is the `to`
 * assignments on that base.  An assignment replaces every line of its key
 * (a repeatable key's lines all at once, as a flag does), so "key" twice in
 * `to` is the new list of key lights.  "@NAME" is the file NAME the test
 * writes into its directory.
 *
 * `shows`: the backends on which the change must show in some output (a
 * change that shows nowhere tests no cache); threads and the truth's own
 * keys change nothing here, the GLES path's own settings nothing on the
 * CPU, and the kept and fresh renderers must still agree.
 */
#ifndef HFS_TESTS_PLAN_KEYS_ROWS_H
#define HFS_TESTS_PLAN_KEYS_ROWS_H

#include <stddef.h>

typedef struct pk_set {
    const char *key, *value;
} pk_set;

#define PK_SETS 4
#define PK_GLES 1u
#define PK_CPU 2u
#define PK_BOTH (PK_GLES | PK_CPU)

typedef struct pk_row {
    const char *key;
    pk_set base[PK_SETS];
    pk_set to[PK_SETS];
    unsigned shows;
} pk_row;

/* A grey sky with a vertical and a sideways gradient (rotation shows). */
#define PK_SH "2,0.3,0.8,0.4,0.05,-0.04,0.1,0.03,-0.02,0.01,0.02,-0.01,0.03,0.01,-0.02,0.01"
#define PK_SH2 "2.2,-0.2,0.7,0.1,0.05,-0.04,0.1,0.03,-0.02,0.01,0.02,-0.01,0.03,0.01,-0.02,0.01"
#define PK_SH_G "1.8,0.2,0.8,0.3,0,0,0,0,0,0,0,0,0,0,0,0"
#define PK_SH_B "2.4,0.1,0.9,0.2,0,0,0,0,0,0,0,0,0,0,0,0"

/* The common base: a 16x16 raw field (some heights exactly 3, for
 * nodata), a key light, a local light, an object of each kind; small, as
 * every row renders it and its change on fresh renderers too. */
static const pk_set pk_base[] = {
    {"height", "@h1.f32"}, {"size", "16x16"}, {"env-sh", PK_SH},
    {"key", "30,25,3,20"}, {"local", "8,8,3,1,30"},
    {"albedo", "0.8"}, {"pin", "5,5,3,1"}, {"box", "11,4,0.5,3,2,1.5"},
    {"point", "8,6,2,0.8"},
};

#define PK_COLOUR {"env-sh", NULL}, {"env-sh-r", PK_SH}, {"env-sh-g", PK_SH_G}, {"env-sh-b", PK_SH_B}
#define PK_MAP {"env-sh", NULL}, {"env-map", "@sky1.pfm"}
#define PK_GLOSSY {"specular", "0.2"}
/* Split horizons' far part within the small field (default: beyond 16). */
#define PK_FAR {"far-from", "4"}

static const pk_row pk_rows[] = {
    {"height", {{0}}, {{"height", "@h2.f32"}}, PK_BOTH},
    {"size", {{0}}, {{"size", "32x8"}}, PK_BOTH},
    {"dx", {{0}}, {{"dx", "1.25"}}, PK_BOTH},
    {"zscale", {{0}}, {{"zscale", "1.5"}}, PK_BOTH},
    {"nodata", {{0}}, {{"nodata", "3"}}, PK_BOTH},
    {"env-sh", {{0}}, {{"env-sh", PK_SH2}}, PK_BOTH},
    {"env-sh-r", {PK_COLOUR}, {{"env-sh-r", PK_SH2}}, PK_BOTH},
    {"env-sh-g", {PK_COLOUR}, {{"env-sh-g", PK_SH2}}, PK_BOTH},
    {"env-sh-b", {PK_COLOUR}, {{"env-sh-b", PK_SH2}}, PK_BOTH},
    {"env-map", {PK_MAP}, {{"env-map", "@sky2.pfm"}}, PK_BOTH},
    {"env-rotate", {{0}}, {{"env-rotate", "40"}}, PK_BOTH},
    {"env-rotate", {PK_MAP}, {{"env-rotate", "40"}}, PK_BOTH},
    {"env-lights", {PK_MAP}, {{"env-lights", "auto"}}, PK_BOTH},
    {"key", {{0}}, {{"key", "45,30,3,20"}, {"key", "200,50,4,10"}}, PK_BOTH},
    {"key", {{0}}, {{"key", "45,30,3,20"}}, PK_BOTH},
    {"local", {{0}}, {{"local", "6,8,3,1,30"}}, PK_BOTH},
    {"albedo", {{0}}, {{"albedo", "0.5"}}, PK_BOTH},
    {"albedo-map", {{0}}, {{"albedo-map", "@alb.pfm"}}, PK_BOTH},
    {"bounces", {{0}}, {{"bounces", "1"}}, PK_BOTH},
    {"k", {{0}}, {{"k", "3"}}, PK_BOTH},
    {"offset", {{0}}, {{"offset", "2"}}, PK_BOTH},
    {"nphi-env", {{0}}, {{"nphi-env", "16"}}, PK_BOTH},
    {"nphi-key", {{0}}, {{"nphi-key", "5"}}, PK_BOTH},
    {"refine", {{0}}, {{"refine", "1"}}, PK_BOTH},
    {"split", {{0}}, {{"split", "0"}}, PK_BOTH},
    {"far-from", {{0}}, {{"far-from", "6"}}, PK_BOTH},
    {"far-dirs", {PK_FAR}, {{"far-dirs", "3"}}, PK_BOTH},
    /* 7 and 5 make the same far grid on 16 texels (4 points a row): no
     * texture reallocated, only the planner can see the change. */
    {"far-step", {PK_FAR, {"far-step", "7"}}, {{"far-step", "5"}}, PK_BOTH},
    {"nphi-bounce", {{"bounces", "1"}}, {{"nphi-bounce", "6"}}, PK_BOTH},
    {"bounce-refine", {{"bounces", "1"}}, {{"bounce-refine", "3"}}, PK_BOTH},
    {"bounce-subsample", {{"bounces", "1"}}, {{"bounce-subsample", "2"}}, PK_GLES},
    {"bounce-near", {{"bounces", "1"}}, {{"bounce-near", "1"}}, PK_GLES},
    {"nphi-local", {{0}}, {{"nphi-local", "24"}}, PK_BOTH},
    {"subsample", {{0}}, {{"subsample", "4"}}, PK_GLES},
    {"precision", {{0}}, {{"precision", "fp32"}}, PK_GLES},
    {"visibility", {{0}}, {{"visibility", "wedge"}}, PK_BOTH},
    {"threads", {{0}}, {{"threads", "1"}}, 0},
    {"truth-azimuths", {{0}}, {{"truth-azimuths", "1440"}}, 0},
    {"truth-samples", {{0}}, {{"truth-samples", "64"}}, 0},
    {"local-swath", {{0}}, {{"local-swath", "full"}}, PK_BOTH},
    {"preset", {{0}}, {{"preset", "panel"}}, PK_BOTH},
    {"specular", {{0}}, {PK_GLOSSY}, PK_BOTH},
    {"gloss", {PK_GLOSSY}, {{"gloss", "8"}}, PK_BOTH},
    {"view-dir", {PK_GLOSSY}, {{"view-dir", "30,60"}}, PK_BOTH},
    {"truth-env", {PK_MAP}, {{"truth-env", "sh"}}, 0},
    {"azimuth-convention", {{0}}, {{"azimuth-convention", "compass"}}, PK_BOTH},
    {"env-shade", {PK_MAP}, {{"env-shade", "sh"}}, PK_BOTH},
    {"pin", {{0}}, {{"pin", "6,5,3,1"}}, PK_BOTH},
    {"box", {{0}}, {{"box", "11,4,0.5,3,2,2.5"}}, PK_BOTH},
    {"point", {{0}}, {{"point", "8,6,2,0.8,1,0.2,0.2"}}, PK_BOTH},
    {"objects", {{0}}, {{"objects", "@obj.txt"}}, PK_BOTH},
};

/* Keys no render reads, with the reason. */
static const pk_set pk_unread[] = {
    {"backend", "chooses the renderer's backend: a kept renderer keeps its own"},
    {"context", "how the GLES context is made, when the renderer is created"},
};

#endif /* HFS_TESTS_PLAN_KEYS_ROWS_H */
