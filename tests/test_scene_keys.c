/*
 * test_scene_keys.c — the table of scene keys (runtime/core/scene_keys.h) and its
 * three readers:
 *   - the table: names unique and found, ranges well formed, every default
 *     accepted by the parser, the quality defaults those of
 *     hfs_quality_defaults, every preset a hfs_quality_preset use;
 *   - the documents: every key of docs/SCENE.md's table and every flag of
 *     SPEC.md's command-line contract is in the table, and every key of the
 *     table has its row in docs/SCENE.md;
 *   - the parser and the renderer's validation agree: for every number of
 *     every key that becomes a library field, its bounds (and one ulp
 *     inside) are accepted by hfs_scene_set AND by hfs_validate_inputs (in
 *     library units: radians), and a value just outside each bound, or a
 *     non-finite one, is refused by both with one line naming the input;
 *     rows whose library field deliberately takes more (truth-azimuths)
 *     are checked against their own library range, which holds the scene's;
 *   - the knob actions of the input configuration accept exactly their
 *     number's range (0 excluded where they multiply).
 *
 * usage: test_scene_keys SCENE.md [SPEC.md]   (a missing SPEC.md: skipped)
 */
#include "check.h"
#include "input_config.h"
#include "scene.h"
#include "scene_keys.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- the table ------------------------------------------------------------------ */

static void check_table(void)
{
    for (int id = 0; id < HFS_SK_COUNT; ++id) {
        const hfs_scene_key *k = hfs_scene_key_get((hfs_scene_key_id)id);
        CHECK(k && k->name && k->arg && k->help && *k->help, "key %d: incomplete row", id);
        if (!k)
            continue;
        CHECK(hfs_scene_key_find(k->name) == id, "%s: not found by name", k->name);
        CHECK(hfs_scene_is_key(k->name), "%s: not a scene key", k->name);
        for (int i = 0; i < k->n; ++i) {
            const hfs_key_number *n = hfs_scene_key_number((hfs_scene_key_id)id, i);
            CHECK(n && n->range.lo <= n->range.hi, "%s: number %d: empty range", k->name, i);
            if (n && n->lib)
                CHECK(n->lib->lo <= n->range.lo && n->range.hi <= n->lib->hi,
                      "%s: the library's range does not hold the scene's", k->name);
        }
        CHECK((k->form == HFS_FORM_REALS || k->form == HFS_FORM_INT || k->form == HFS_FORM_SIZE) ==
                  (k->n > 0), "%s: numbers and form disagree", k->name);
        if (k->def) {
            hfs_scene s;
            hfs_error err = {{0}};
            hfs_scene_init(&s);
            CHECK(hfs_scene_set(&s, HFS_SOURCE_FLAG, k->name, k->def, "default", NULL, &err) == 0,
                  "%s: default '%s' refused: %s", k->name, k->def, err.msg);
        }
    }
    CHECK(hfs_scene_key_find("bogus") < 0 && !hfs_scene_key_get(HFS_SK_COUNT), "no such key");
    int n = 0;
    CHECK(hfs_scene_keys(&n) == hfs_scene_key_get(HFS_SK_HEIGHT) && n == HFS_SK_COUNT,
          "hfs_scene_keys is not the table");
}

/* Setting every default explicitly changes nothing the library sees. */
static void check_defaults(void)
{
    hfs_scene s;
    hfs_error err = {{0}};
    hfs_scene_init(&s);
    for (int id = 0; id < HFS_SK_COUNT; ++id) {
        const hfs_scene_key *k = hfs_scene_key_get((hfs_scene_key_id)id);
        if (k->def && id != HFS_SK_PRESET)
            hfs_scene_set(&s, HFS_SOURCE_FILE, k->name, k->def, "s.ini", NULL, &err);
    }
    hfs_quality q, want;
    hfs_scene_quality(&s, &q);
    hfs_quality_defaults(&want);
    CHECK(memcmp(&q, &want, sizeof q) == 0, "quality defaults of the table are not "
          "hfs_quality_defaults (k %d/%d, nphi-env %d/%d, threads %d/%d, truth %d/%d)", q.k,
          want.k, q.nphi_env, want.nphi_env, q.threads, want.threads, q.truth_azimuths,
          want.truth_azimuths);
    hfs_lighting l, lw;
    hfs_scene_lighting(&s, NULL, &l);
    hfs_lighting_defaults(&lw);
    CHECK(l.albedo == lw.albedo && l.env_rotate == lw.env_rotate, "lighting defaults");
    CHECK(s.dx == 1.0 && s.zscale == 1.0 && s.backend == HFS_BACKEND_GLES,
          "dx, zscale, backend defaults");

    const hfs_scene_key *p = hfs_scene_key_get(HFS_SK_PRESET);
    hfs_quality kiosk;
    CHECK(hfs_quality_preset(&kiosk, p->def) == 0 && memcmp(&kiosk, &want, sizeof kiosk) == 0,
          "the default preset is not the defaults");
    for (const char *w = p->arg; w; w = strchr(w, '|') ? strchr(w, '|') + 1 : NULL) {
        char use[32];
        snprintf(use, sizeof use, "%.*s", (int)strcspn(w, "|"), w);
        hfs_quality pq;
        CHECK(hfs_quality_preset(&pq, use) == 0, "preset word '%s' is no hfs_quality_preset", use);
    }
}

/* ---- the documents ------------------------------------------------------------ */

static char *read_all(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    char *buf = malloc(1 << 20);
    size_t n = buf ? fread(buf, 1, (1 << 20) - 1, f) : 0;
    fclose(f);
    if (buf)
        buf[n] = '\0';
    return buf;
}

/* docs/SCENE.md: rows "| `key` | VALUE | meaning |" of the key table. */
static void check_scene_md(const char *path)
{
    char *text = read_all(path);
    CHECK(text != NULL, "%s: cannot read", path);
    if (!text)
        return;
    int documented[HFS_SK_COUNT] = {0};
    for (char *line = strtok(text, "\n"); line; line = strtok(NULL, "\n")) {
        if (strncmp(line, "| `", 3) != 0)
            continue;
        char name[64];
        snprintf(name, sizeof name, "%.*s", (int)strcspn(line + 3, "`"), line + 3);
        const int id = hfs_scene_key_find(name);
        CHECK(id >= 0, "%s: key '%s' is not in the table", path, name);
        if (id >= 0)
            documented[id] = 1;
    }
    for (int id = 0; id < HFS_SK_COUNT; ++id)
        CHECK(documented[id], "%s: no row for key '%s'", path,
              hfs_scene_key_get((hfs_scene_key_id)id)->name);
    free(text);
}

/* SPEC.md: every "`--flag ...`" in the rows of the command-line table. */
static void check_spec_md(const char *path)
{
    char *text = read_all(path);
    if (!text) {
        printf("SKIP %s: not found\n", path);
        return;
    }
    int flags = 0;
    for (char *line = strtok(text, "\n"); line; line = strtok(NULL, "\n")) {
        if (strncmp(line, "| `--", 5) != 0)
            continue;
        for (char *p = strstr(line, "`--"); p; p = strstr(p + 1, "`--")) {
            char name[64];
            snprintf(name, sizeof name, "%.*s", (int)strcspn(p + 3, " `"), p + 3);
            CHECK(hfs_scene_key_find(name) >= 0, "%s: flag --%s is not a scene key", path, name);
            ++flags;
        }
    }
    CHECK(flags >= 15, "%s: only %d flags found in the command-line table", path, flags);
    free(text);
}

/* ---- parser against validator ---------------------------------------------------- */

#define W 8
#define H 6

typedef struct inputs {
    float z[65536 * W]; /* the longest side the size key accepts, by W */
    hfs_field f;
    hfs_lighting l;
    hfs_quality q;
} inputs;

static void valid_inputs(inputs *in)
{
    memset(in->z, 0, sizeof in->z);
    in->f = (hfs_field){.width = W, .height = H, .z = in->z, .dx = 1.0, .zscale = 1.0};
    hfs_lighting_defaults(&in->l);
    in->l.has_env = 1;
    in->l.env_sh[0][0] = in->l.env_sh[1][0] = in->l.env_sh[2][0] = 3.5449077;
    in->l.n_key = 1;
    in->l.key[0] = (hfs_key_light){.phi = 0.2, .elev = 0.3, .alpha = 0.05, .radiance = {1, 1, 1}};
    in->l.n_local = 1;
    in->l.local[0] = (hfs_local_light){.pos = {1, 2, 3}, .radius = 1, .radiance = {1, 1, 1}};
    hfs_quality_defaults(&in->q);
}

/* Puts x (scene units) into the library field number i of key id becomes;
 * 0 when that number has no library field. */
static int set_lib(inputs *in, hfs_scene_key_id id, int i, double x)
{
    const double v = hfs_key_to_lib(hfs_scene_key_number(id, i)->unit, x);
    int *count = NULL;
    switch (id) {
    case HFS_SK_SIZE: (i ? &in->f.height : &in->f.width)[0] = (int)v; return 1;
    case HFS_SK_DX: in->f.dx = v; return 1;
    case HFS_SK_ZSCALE: in->f.zscale = v; return 1;
    case HFS_SK_ENV_SH: in->l.env_sh[1][i] = v; return 1;
    case HFS_SK_ENV_ROTATE: in->l.env_rotate = v; return 1;
    case HFS_SK_ALBEDO: in->l.albedo = v; return 1;
    /* Glossy surfaces: albedo + specular <= 1 is a rule of its own (albedo 0
     * leaves specular's range alone), and gloss is checked only where there
     * is a lobe (specular > 0; validate.c check_gloss). */
    case HFS_SK_SPECULAR: in->l.albedo = 0.0, in->l.specular = v; return 1;
    case HFS_SK_GLOSS: in->l.albedo = 0.5, in->l.specular = 0.5, in->l.gloss = v; return 1;
    case HFS_SK_BOUNCES: count = &in->l.bounces; break;
    case HFS_SK_KEY:
        if (i < 3)
            (i == 0 ? &in->l.key[0].phi : i == 1 ? &in->l.key[0].elev : &in->l.key[0].alpha)[0] = v;
        else
            in->l.key[0].radiance[0] = in->l.key[0].radiance[2] = (float)v;
        return 1;
    case HFS_SK_LOCAL:
        if (i < 3)
            in->l.local[0].pos[i] = v;
        else if (i == 3)
            in->l.local[0].radius = v;
        else
            in->l.local[0].radiance[1] = (float)v;
        return 1;
    case HFS_SK_K: count = &in->q.k; break;
    case HFS_SK_OFFSET: count = &in->q.offset; break;
    case HFS_SK_NPHI_ENV: count = &in->q.nphi_env; break;
    case HFS_SK_NPHI_KEY: count = &in->q.nphi_key; break;
    case HFS_SK_NPHI_LOCAL: count = &in->q.nphi_local; break;
    case HFS_SK_REFINE: count = &in->q.refine; break;
    case HFS_SK_SPLIT: count = &in->q.split; break;
    case HFS_SK_FAR_FROM: count = &in->q.far_from; break;
    case HFS_SK_FAR_DIRS: count = &in->q.far_dirs; break;
    case HFS_SK_FAR_STEP: count = &in->q.far_step; break;
    case HFS_SK_NPHI_BOUNCE: count = &in->q.nphi_bounce; break;
    case HFS_SK_BOUNCE_REFINE: count = &in->q.bounce_refine; break;
    case HFS_SK_BOUNCE_SUBSAMPLE: count = &in->q.bounce_subsample; break;
    case HFS_SK_BOUNCE_NEAR: count = &in->q.bounce_near; break;
    case HFS_SK_SUBSAMPLE: count = &in->q.subsample; break;
    case HFS_SK_THREADS: count = &in->q.threads; break;
    case HFS_SK_TRUTH_AZIMUTHS: count = &in->q.truth_azimuths; break;
    case HFS_SK_TRUTH_SAMPLES: count = &in->q.truth_light_samples; break;
    default: return 0;
    }
    *count = v > INT_MAX ? INT_MAX : v < INT_MIN ? INT_MIN : (int)v;
    return 1;
}

/* A valid value of every number of key id, as text with number i = x. */
static void value_text(hfs_scene_key_id id, int i, double x, char *buf, size_t size)
{
    const hfs_scene_key *k = hfs_scene_key_get(id);
    size_t used = 0;
    buf[0] = '\0';
    for (int j = 0; j < k->n && used < size; ++j) {
        const hfs_key_range *r = &hfs_scene_key_number(id, j)->range;
        double v = j == i ? x : r->lo_open || r->lo == -DBL_MAX ? (r->hi < 1.0 ? r->hi : 1.0)
                                                                 : r->lo;
        if (k->form == HFS_FORM_INT && j != i && k->pow2)
            v = 2.0;
        const char *sep = j == 0 ? "" : k->form == HFS_FORM_SIZE ? "x" : ",";
        if (!isfinite(v))
            used += (size_t)snprintf(buf + used, size - used, "%s%s", sep, v > 0 ? "inf" : "-inf");
        else if (k->form == HFS_FORM_REALS)
            used += (size_t)snprintf(buf + used, size - used, "%s%.17g", sep, v);
        else
            used += (size_t)snprintf(buf + used, size - used, "%s%.0f", sep, v);
    }
}

/* Whether the parser accepts number i of key id = x; the message when not. */
static int parser_accepts(hfs_scene_key_id id, int i, double x, hfs_error *err)
{
    char text[1024], where[64];
    hfs_scene s;
    value_text(id, i, x, text, sizeof text);
    hfs_scene_init(&s);
    snprintf(where, sizeof where, "--%s", hfs_scene_key_get(id)->name);
    return hfs_scene_set(&s, HFS_SOURCE_FLAG, hfs_scene_key_get(id)->name, text, where, NULL,
                         err) == 0;
}

static int library_accepts(hfs_scene_key_id id, int i, double x, hfs_error *err)
{
    static inputs in;
    valid_inputs(&in);
    if (!set_lib(&in, id, i, x))
        return -1;
    return hfs_validate_inputs(&in.f, &in.l, &in.q, err) == 0;
}

/* One value: both accept it, or (outside) both refuse it with one line. */
static void agree(hfs_scene_key_id id, int i, double x, int inside, int lib_only)
{
    const char *name = hfs_scene_key_get(id)->name;
    hfs_error pe = {{0}}, le = {{0}};
    const int lib = library_accepts(id, i, x, &le);
    if (!lib_only) {
        const int parsed = parser_accepts(id, i, x, &pe);
        CHECK(parsed == inside, "%s[%d] = %.17g: parser %s it (%s)", name, i, x,
              parsed ? "accepts" : "refuses", pe.msg);
        if (!parsed)
            CHECK(strstr(pe.msg, name) && !strchr(pe.msg, '\n'), "%s: parser message '%s'", name,
                  pe.msg);
    }
    if (lib < 0)
        return;
    CHECK(lib == inside, "%s[%d] = %.17g: hfs_validate_inputs %s it (%s)", name, i, x,
          lib ? "accepts" : "refuses", le.msg);
    if (!lib)
        CHECK(le.msg[0] && !strchr(le.msg, '\n'), "%s: library message '%s'", name, le.msg);
}

/* A step just past bound b (relative 1e-6: beyond a float's rounding). */
static double past(double b, int up, int integer)
{
    if (integer)
        return b + (up ? 1.0 : -1.0);
    const double step = fmax(fabs(b) * 1e-6, 1e-12);
    return up ? b + step : b - step;
}

static void check_bounds(hfs_scene_key_id id, int i)
{
    const hfs_scene_key *k = hfs_scene_key_get(id);
    const hfs_key_number *n = hfs_scene_key_number(id, i);
    const int integer = k->form != HFS_FORM_REALS;
    const hfs_key_range r = n->range;
    for (int side = 0; side < 2; ++side) {
        const double b = side ? r.hi : r.lo;
        if (b == DBL_MAX || b == -DBL_MAX) { /* no bound: only finite */
            if (!integer)
                agree(id, i, side ? INFINITY : -INFINITY, 0, 0);
            continue;
        }
        const int closed = side || !r.lo_open;
        if (closed) {
            agree(id, i, b, 1, 0);
            if (!integer) /* one ulp inside (no subnormal: strtod calls it ERANGE) */
                agree(id, i, b == 0.0 ? (side ? -1e-300 : 1e-300)
                                      : nextafter(b, side ? -INFINITY : INFINITY), 1, 0);
        }
        const double out = closed ? past(b, side, integer) : b;
        /* A row with a library range of its own: outside the scene's only. */
        if (!n->lib)
            agree(id, i, out, 0, 0);
        else
            CHECK(!parser_accepts(id, i, out, &(hfs_error){{0}}), "%s: %.17g accepted", k->name,
                  out);
    }
    if (n->lib) { /* the library's own bounds */
        agree(id, i, n->lib->lo, 1, 1);
        agree(id, i, n->lib->hi, 1, 1);
        agree(id, i, past(n->lib->lo, 0, integer), 0, 1);
        agree(id, i, past(n->lib->hi, 1, integer), 0, 1);
    }
}

static void check_agreement(void)
{
    for (int id = 0; id < HFS_SK_COUNT; ++id) {
        const hfs_scene_key *k = hfs_scene_key_get((hfs_scene_key_id)id);
        for (int i = 0; i < k->n; ++i)
            check_bounds((hfs_scene_key_id)id, i);
    }
    /* subsample: only the powers of two, in both. */
    agree(HFS_SK_SUBSAMPLE, 0, 3.0, 0, 0);
    /* The conversion is the parser's: 90 degrees is exactly the library's pi/2. */
    CHECK(hfs_scene_key_lib_range(HFS_SK_KEY, 1).hi == 3.14159265358979323846 / 2,
          "90 degrees is not pi/2 in the library");
    hfs_scene s;
    hfs_error err = {{0}};
    hfs_lighting l;
    hfs_scene_init(&s);
    hfs_scene_set(&s, HFS_SOURCE_FLAG, "key", "-3600,90,89,1", "--key", NULL, &err);
    hfs_scene_lighting(&s, NULL, &l);
    CHECK(l.key[0].phi == hfs_scene_key_lib_range(HFS_SK_KEY, 0).lo &&
              l.key[0].elev == hfs_scene_key_lib_range(HFS_SK_KEY, 1).hi &&
              l.key[0].alpha == hfs_scene_key_lib_range(HFS_SK_KEY, 2).hi,
          "hfs_scene_lighting converts otherwise than the library's ranges");
}

/* env-lights, a word or a count: both ends of the count accepted (the
 * documented maximum is HFS_MAX_KEY_LIGHTS), one past each end and
 * non-numbers refused in one line naming the key. */
static void check_env_lights(void)
{
    char v[32];
    const struct { int n; int ok; } counts[] = {{1, 1}, {HFS_MAX_KEY_LIGHTS, 1}, {0, 0},
                                                 {HFS_MAX_KEY_LIGHTS + 1, 0}, {-1, 0}};
    for (size_t i = 0; i < sizeof counts / sizeof counts[0]; ++i) {
        hfs_scene s;
        hfs_error err = {{0}};
        hfs_scene_init(&s);
        snprintf(v, sizeof v, "%d", counts[i].n);
        const int ok = !hfs_scene_set(&s, HFS_SOURCE_FLAG, "env-lights", v, "--env-lights", NULL,
                                      &err);
        CHECK(ok == counts[i].ok, "env-lights %s: %s", v, ok ? "accepted" : err.msg);
        CHECK(!ok || s.env_lights == counts[i].n, "env-lights %s: stored as %d", v, s.env_lights);
        CHECK(ok || (strstr(err.msg, "env-lights") && !strchr(err.msg, '\n')),
              "env-lights %s: message '%s'", v, err.msg);
    }
    const char *words[][2] = {{"auto", "-1"}, {"off", "0"}, {"2x", ""}, {"", ""}, {"AUTO", ""}};
    for (size_t i = 0; i < sizeof words / sizeof words[0]; ++i) {
        hfs_scene s;
        hfs_error err = {{0}};
        hfs_scene_init(&s);
        const int ok = !hfs_scene_set(&s, HFS_SOURCE_FLAG, "env-lights", words[i][0],
                                      "--env-lights", NULL, &err);
        CHECK(ok == (words[i][1][0] != '\0'), "env-lights '%s': %s", words[i][0],
              ok ? "accepted" : err.msg);
        CHECK(!ok || s.env_lights == atoi(words[i][1]), "env-lights '%s': stored as %d",
              words[i][0], s.env_lights);
    }
}

/* ---- knob limits ------------------------------------------------------------------- */

static void check_actions(void)
{
    for (int a = HFS_ACTION_NONE + 1; a < HFS_ACTION_COUNT; ++a) {
        const hfs_action_info *info = hfs_action_get((hfs_action)a);
        if (!info->continuous)
            continue;
        if (info->key == HFS_SK_COUNT) { /* the kiosk's own state (the 3-D view's camera) */
            const hfs_key_range r = hfs_action_range(info);
            CHECK(r.lo == info->min && r.hi == info->max && !r.lo_open,
                  "%s: the kiosk's own value does not accept exactly its default [min, max]",
                  info->name);
            continue;
        }
        const hfs_key_number *n = hfs_scene_key_number(info->key, info->number);
        CHECK(n != NULL, "%s: no scene number", info->name);
        if (!n)
            continue;
        const hfs_key_range r = hfs_action_range(info);
        CHECK(r.lo == n->range.lo && r.hi == n->range.hi &&
                  r.lo_open == (n->range.lo_open || (info->multiplicative && r.lo == 0.0)),
              "%s: limits are not those of %s", info->name,
              hfs_scene_key_get(info->key)->name);
        CHECK(hfs_key_in_range(&r, info->min) && hfs_key_in_range(&r, info->max),
              "%s: default min/max outside what it accepts", info->name);
    }
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: test_scene_keys SCENE.md [SPEC.md]\n");
        return 2;
    }
    check_table();
    check_defaults();
    check_scene_md(argv[1]);
    if (argc > 2)
        check_spec_md(argv[2]);
    check_agreement();
    check_env_lights();
    check_actions();
    printf("%s: %ld checks, %d failure(s)\n", failures ? "FAIL" : "PASS", checks, failures);
    return failures ? 1 : 0;
}
