/*
 * hfstress — numerical stability under extremes (issue 5; docs/STRESS.md).
 *
 *   hfstress [--fast] [--case NAME[,NAME...]] [--backend LIST] [--list]
 *            [--subsample 1|2|4] [--lights env,key,local]
 *            [--visibility legendre|wedge|slice] [-v]
 *
 * Runs the cases of the table (hfstress_cases.c) on the backends cpu,
 * gles-fp16, gles-fp32 (gles-es32-* for fields beyond ES 3.0's 2048
 * textures) and, for tiny fields, truth, and checks per case and backend:
 *   finite   no NaN/Inf in the output (the renderer also refuses to return
 *            one: that would show as a render error);
 *   bound    -rho lneg <= out <= U + rho lneg per texel and channel, U the
 *            exact unshadowed image (hfs_render_unshadowed), lneg the
 *            environment's negative part (0 for a non-negative sky): worst
 *            violation / max U within the backend's tolerance;
 *   value    cases with a known answer (uniform sky on a flat field, inside
 *            a huge sphere, black lights): every output equals it;
 *   scale    dx, zscale, local positions and radii times s: the output
 *            equals the unscaled one (difference / max U);
 *   fp16     gles-fp16 against gles-fp32 within the derived bound.
 * Cases that must be refused (a 1-wide field, NaN heights) pass when every
 * backend and the unshadowed renderer return HFS_E_INVALID with one line;
 * a side beyond 2048 must be refused by the ES 3.0 profiles with
 * HFS_E_UNSUPPORTED naming GL_MAX_TEXTURE_SIZE (and renders under es32).
 *
 * One line per case and backend: PASS/FAIL, the measured numbers and
 * [their bounds] ("!" marks the one that failed); a summary; exit 1 on any
 * failure, 77 when nothing could run (no backend available), 2 on usage.
 * A GLES backend that cannot be made counts as a failure unless no GLES
 * context of any kind can be made here (runtime/gl/gl_require.h; HFS_REQUIRE_GL=1
 * makes that a failure too) or, for the es32 ones, the driver is below 3.2.
 * --fast is the CI subset (ctest label "stress").
 */
#include "hfstress.h"
#include "cli_usage.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { LIGHTS_ENV = 1, LIGHTS_KEY = 2, LIGHTS_LOCAL = 4, LIGHTS_ALL = 7 };

/* Tolerances per backend, in units of the frame's largest unshadowed value
 * (docs/STRESS.md "tolerances" says why each has its size). */
typedef struct tolerances {
    double bound;   /* worst bound violation (gles-fp16: + its fp16 bound) */
    double scale;   /* |out(s) - out(1)|                                   */
    double value;   /* relative error of a known answer                    */
} tolerances;

static const tolerances tol_cpu = {1e-6, 1e-6, 1e-12};   /* double, float output  */
static const tolerances tol_gles = {5e-5, 2e-5, 1e-5};   /* float arithmetic      */
static const tolerances tol_truth = {1e-3, 1e-6, 1e-12}; /* sampled light caps    */

static const tolerances *tol_of(int b)
{
    return b == BK_TRUTH ? &tol_truth : stress_backend_is_gles(b) ? &tol_gles : &tol_cpu;
}

typedef struct options {
    int fast, list, verbose;
    int want[BK_COUNT];
    int lights;          /* LIGHTS_* kept (diagnosis)                       */
    int subsample;       /* GLES grid step; 0: the product's default        */
    int visibility;      /* --visibility: every case on this path; 0: each
                            case's own                                       */
    const char *only[64];
    int n_only;
} options;

typedef struct runner {
    const options *o;
    stress_backends bk;
    int reported[BK_COUNT]; /* "SKIP backend" printed */
    int pass, fail;
} runner;

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* ---- command line ------------------------------------------------------------------ */

static void usage(FILE *to)
{
    fprintf(to, "usage: hfstress [--fast] [--case NAME[,NAME...]] [--backend LIST] [--list]\n"
                "                [--subsample 1|2|4] [--lights env,key,local]\n"
                "                [--visibility legendre|wedge|slice] [-v]\n"
                "  --fast       the CI subset (ctest label \"stress\")\n"
                "  --backend    comma-separated: cpu, gles (every GLES backend), gles-fp16,\n"
                "               gles-fp32, gles-es32-fp16, gles-es32-fp32, truth, all (default)\n"
                "  --subsample  GLES visibility grid step (default: the product's 2)\n"
                "  --lights     keep only these light kinds (diagnosis)\n"
                "  --visibility every case on this visibility path (default: each case's)\n"
                "  -v           also print where the worst bound violation is\n");
}

static int add_cases(options *o, const char *list)
{
    static char names[4096];
    static size_t used;
    const size_t len = strlen(list) + 1;
    if (used + len > sizeof names) {
        hfs_usage_error("hfstress", "--case: too many names");
        return -1;
    }
    char *copy = memcpy(names + used, list, len);
    used += len;
    for (char *save = NULL, *t = strtok_r(copy, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        if (!stress_case_find(t)) {
            hfs_usage_error("hfstress", "--case: unknown case '%s' (--list lists them)", t);
            return -1;
        }
        if (o->n_only == (int)(sizeof o->only / sizeof o->only[0])) {
            hfs_usage_error("hfstress", "--case: too many names");
            return -1;
        }
        o->only[o->n_only++] = t;
    }
    return 0;
}

/* --lights: a comma-separated list of env, key, local. */
static int parse_lights(const char *v, int *lights)
{
    static const char *const names[] = {"env", "key", "local"};
    static const int bits[] = {LIGHTS_ENV, LIGHTS_KEY, LIGHTS_LOCAL};
    *lights = 0;
    for (const char *p = v; *p;) {
        const size_t len = strcspn(p, ",");
        int found = 0;
        for (int k = 0; k < 3; ++k)
            if (len == strlen(names[k]) && !strncmp(p, names[k], len))
                *lights |= bits[k], found = 1;
        if (!found) {
            hfs_usage_error("hfstress", "--lights: '%.*s' is not env, key or local", (int)len, p);
            return -1;
        }
        p += len + (p[len] == ',');
    }
    if (!*lights)
        hfs_usage_error("hfstress", "--lights: empty list (env, key, local)");
    return *lights ? 0 : -1;
}

/* 1 if A is a flag that takes a value (it was given without one). */
static int is_valued(const char *a)
{
    static const char *const flags[] = {"--backend", "--case", "--subsample", "--visibility",
                                        "--lights"};
    for (size_t k = 0; k < sizeof flags / sizeof flags[0]; ++k)
        if (!strcmp(a, flags[k]))
            return 1;
    return 0;
}

static int parse_args(int argc, char **argv, options *o)
{
    memset(o, 0, sizeof *o);
    for (int b = 0; b < BK_COUNT; ++b)
        o->want[b] = 1;
    o->lights = LIGHTS_ALL;
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--fast")) {
            o->fast = 1;
        } else if (!strcmp(a, "--list")) {
            o->list = 1;
        } else if (!strcmp(a, "-v") || !strcmp(a, "--verbose")) {
            o->verbose = 1;
        } else if (!strcmp(a, "--backend") && v) {
            if (stress_backend_parse(v, o->want))
                return -1;
            ++i;
        } else if (!strcmp(a, "--case") && v) {
            if (add_cases(o, v))
                return -1;
            ++i;
        } else if (!strcmp(a, "--subsample") && v) {
            o->subsample = !strcmp(v, "1") ? 1 : !strcmp(v, "2") ? 2 : !strcmp(v, "4") ? 4 : 0;
            if (o->subsample != 1 && o->subsample != 2 && o->subsample != 4) {
                hfs_usage_error("hfstress", "--subsample: '%s' is not 1, 2 or 4", v);
                return -1;
            }
            ++i;
        } else if (!strcmp(a, "--visibility") && v) {
            o->visibility = !strcmp(v, "legendre") ? HFS_VIS_LEGENDRE
                            : !strcmp(v, "wedge")  ? HFS_VIS_WEDGE_TABLE
                            : !strcmp(v, "slice")  ? HFS_VIS_SLICE
                                                   : 0;
            if (!o->visibility) {
                hfs_usage_error("hfstress", "--visibility: '%s' is not legendre, wedge or slice",
                                v);
                return -1;
            }
            ++i;
        } else if (!strcmp(a, "--lights") && v) {
            if (parse_lights(v, &o->lights))
                return -1;
            ++i;
        } else if (hfs_is_help(a)) {
            usage(stdout);
            exit(0);
        } else {
            hfs_usage_error("hfstress", "%s: %s", a, is_valued(a) ? "missing value"
                                                   : a[0] == '-'  ? "unknown option"
                                                                  : "unexpected argument");
            return -1;
        }
    }
    return 0;
}

static int selected(const options *o, const stress_case *c)
{
    if (o->n_only == 0)
        return !o->fast || c->fast;
    for (int i = 0; i < o->n_only; ++i)
        if (!strcmp(o->only[i], c->name))
            return 1;
    return 0;
}

/* ---- reporting ------------------------------------------------------------------- */

typedef struct line {
    char text[1024];
    size_t len;
    int failed;
} line;

/* Appends a measurement to the line; ok = 0 marks it (and the line) failed. */
static void add(line *ln, int ok, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static void add(line *ln, int ok, const char *fmt, ...)
{
    if (!ok)
        ln->failed = 1;
    va_list ap;
    va_start(ap, fmt);
    if (ln->len < sizeof ln->text) {
        const int k = vsnprintf(ln->text + ln->len, sizeof ln->text - ln->len, fmt, ap);
        if (k > 0)
            ln->len = ln->len + (size_t)k < sizeof ln->text ? ln->len + (size_t)k : sizeof ln->text;
    }
    va_end(ap);
    if (!ok && ln->len + 2 < sizeof ln->text) {
        ln->text[ln->len++] = '!';
        ln->text[ln->len] = '\0';
    }
}

static void finish(runner *rn, const stress_case *c, const char *who, line *ln, double t0)
{
    printf("%s %-20s %-15s%s  [%.2f s]\n", ln->failed ? "FAIL" : "PASS", c->name, who, ln->text,
           now_s() - t0);
    fflush(stdout);
    if (ln->failed)
        rn->fail++;
    else
        rn->pass++;
}

/* ---- one case ---------------------------------------------------------------------- */

/* Builds case c at factor s with the light kinds of --lights only. */
static int build(const runner *rn, const stress_case *c, double s, stress_scene *sc, char *msg,
                 size_t n)
{
    if (stress_scene_build(c, s, sc, msg, n))
        return -1;
    if (!(rn->o->lights & LIGHTS_ENV)) {
        sc->l.has_env = 0;
        sc->lneg[0] = sc->lneg[1] = sc->lneg[2] = 0.0;
    }
    if (!(rn->o->lights & LIGHTS_KEY))
        sc->l.n_key = 0;
    if (!(rn->o->lights & LIGHTS_LOCAL))
        sc->l.n_local = 0;
    if (rn->o->visibility)
        sc->q.visibility = (hfs_visibility_path)rn->o->visibility;
    return 0;
}

static int too_big_for_es30(const stress_case *c)
{
    return c->w > STRESS_ES30_MAX_TEXTURE || c->h > STRESS_ES30_MAX_TEXTURE;
}

/* Whether backend b runs case c at all (and, if it wants to, is ready). */
static int runs(runner *rn, const stress_case *c, int b)
{
    if (!rn->o->want[b] || (b == BK_TRUTH && !c->truth))
        return 0;
    if ((b == BK_ES32_16 || b == BK_ES32_32) && !too_big_for_es30(c))
        return 0;
    if (!stress_backend_ready(&rn->bk, b)) {
        if (!rn->reported[b]) {
            printf("%s backend %s: %s\n", rn->bk.broken[b] ? "FAIL" : "SKIP",
                   stress_backend_name(b), rn->bk.why[b]);
            rn->fail += rn->bk.broken[b];
            rn->reported[b] = 1;
        }
        return 0;
    }
    return 1;
}

/* Renders a case that must be refused; passes on the expected status with a
 * one-line message that contains `needle` (NULL: any). */
static void expect_refusal(runner *rn, const stress_case *c, const stress_scene *sc, int b,
                           int status, const char *needle)
{
    const double t0 = now_s();
    line ln = {.len = 0};
    hfs_image img = {0};
    hfs_error err = {{0}};
    /* A 1-wide image cannot be allocated either: render into a 2x2 one; the
     * renderer must refuse the field before it looks at the output. */
    int rc = hfs_image_alloc(&img, sc->f.width < 2 ? 2 : sc->f.width,
                             sc->f.height < 2 ? 2 : sc->f.height, &err);
    if (!rc)
        rc = b < 0 ? hfs_render_unshadowed(&sc->f, &sc->l, &sc->q, &img, &err)
                   : stress_render(&rn->bk, b, sc, &img, &err);
    const int ok = rc == status && err.msg[0] && !strchr(err.msg, '\n') &&
                   (!needle || strstr(err.msg, needle));
    add(&ln, ok, "  refused (%s): %s", rc ? hfs_status_name(rc) : "not refused", err.msg);
    hfs_image_free(&img);
    finish(rn, c, b < 0 ? "unshadowed" : stress_backend_name(b), &ln, t0);
}

/* -v: where a difference check's worst texel is, and the two values. */
static void add_where(runner *rn, line *ln, const hfs_image *a, const hfs_image *b, size_t at)
{
    if (!rn->o->verbose || !a->rgb || !b->rgb)
        return;
    const size_t px = at / 3;
    add(ln, 1, " (at %zu,%zu ch %zu: %.9g vs %.9g)", px % (size_t)a->width,
        px / (size_t)a->width, at % 3, a->rgb[at], b->rgb[at]);
}

/* Every radiance of case c times r (STRESS_RADIANCE_SCALES): the image
 * divided by r must equal the unscaled one (keep) within the tolerance of
 * the geometric scales; a finite scaled scene must render. */
static void check_radiance_scales(runner *rn, const stress_case *c, int b, const hfs_image *keep,
                                  double umax, line *ln)
{
    static const double rs[] = STRESS_RADIANCE_SCALES;
    const tolerances *t = tol_of(b);
    for (size_t k = 0; k < sizeof rs / sizeof rs[0]; ++k) {
        const double r = rs[k];
        stress_scene sc;
        char msg[512];
        if (build(rn, c, 1.0, &sc, msg, sizeof msg)) {
            add(ln, 0, "  radiance x%g: %s", r, msg);
            continue;
        }
        for (int ch = 0; ch < 3; ++ch) {
            for (int i = 0; i < HFS_SH_COEFFS && sc.l.has_env; ++i)
                sc.l.env_sh[ch][i] *= r;
            for (int i = 0; i < sc.l.n_key; ++i)
                sc.l.key[i].radiance[ch] = (float)(sc.l.key[i].radiance[ch] * r);
            for (int i = 0; i < sc.l.n_local; ++i)
                sc.l.local[i].radiance[ch] = (float)(sc.l.local[i].radiance[ch] * r);
        }
        hfs_image img = {0};
        hfs_error err = {{0}};
        const int rc = stress_render(&rn->bk, b, &sc, &img, &err);
        if (rc) {
            add(ln, 0, "  radiance x%g: render failed (%s): %s", r, hfs_status_name(rc), err.msg);
        } else {
            for (size_t i = 0; i < (size_t)img.width * (size_t)img.height * 3; ++i)
                img.rgb[i] = (float)(img.rgb[i] / r);
            size_t at;
            const double d = stress_max_diff_at(&img, keep, umax, &at);
            add(ln, d <= t->scale, "  radiance x%g: %.1e [%.0e]", r, d, t->scale);
            add_where(rn, ln, &img, keep, at);
        }
        hfs_image_free(&img);
        stress_scene_free(&sc);
    }
}

/* Renders case c at every invariance factor on backend b and checks it;
 * keeps the s = 1 image in *keep for the fp16 comparison. */
static void run_backend(runner *rn, const stress_case *c, const stress_scene *sc, int b,
                        const hfs_image *un, double umax, const stress_fp16_terms *ft,
                        hfs_image *keep)
{
    const tolerances *t = tol_of(b);
    const double t0 = now_s();
    line ln = {.len = 0};
    hfs_error err = {{0}};
    int rc = stress_render(&rn->bk, b, sc, keep, &err);
    if (rc) {
        add(&ln, 0, "  render failed (%s): %s", hfs_status_name(rc), err.msg);
        hfs_image_free(keep);
        finish(rn, c, stress_backend_name(b), &ln, t0);
        return;
    }
    stress_bound bd;
    stress_check_bound(keep, un, umax, sc->lneg, sc->l.albedo, &bd);
    /* GLES: normals come from heights normalized to the relief (fp16 pairs
     * and fp32 alike), so E_cap and the unshadowed clamp see a normal off by
     * up to 2^-23 S; and gles-fp16 stores the environment's V in single
     * fp16, which shows where the renderer's own clamp (conservative for a
     * negative-lobed sky) is looser than this check's exact lneg. */
    double bound_tol = t->bound;
    if (stress_backend_is_gles(b))
        bound_tol += ft->normals + (stress_backend_fp32(b) ? 0.0 : ft->env);
    add(&ln, bd.nonfinite == 0, "  nonfinite %ld", bd.nonfinite);
    add(&ln, bd.over <= bound_tol, "  bound %.1e [%.1e]", bd.over, bound_tol);
    if (rn->o->verbose)
        add(&ln, 1, " (out in [%.6g, %.6g], max U %.6g)", bd.min_out, bd.max_out, umax);
    if (rn->o->verbose && bd.worst_x >= 0)
        add(&ln, 1, " (worst at %d,%d ch %d: out %.6g, U %.6g)", bd.worst_x, bd.worst_y, bd.worst_c,
            bd.worst_out, bd.worst_u);
    if (c->expect_value >= 0.0) {
        const double e = stress_const_err(keep, c->expect_value);
        add(&ln, e <= t->value, "  value %g: %.1e [%.0e]", c->expect_value, e, t->value);
    } else if (c->expect_value == STRESS_EXPECT_U) {
        /* Nothing occludes: every light's full unshadowed value. */
        const double e = stress_max_diff(keep, un, umax);
        add(&ln, e <= bound_tol, "  = U: %.1e [%.1e]", e, bound_tol);
    }
    for (int k = 0; k < STRESS_MAX_SCALES && c->scales[k] > 0.0; ++k) {
        const double s = c->scales[k];
        stress_scene scaled;
        char msg[512];
        if (build(rn, c, s, &scaled, msg, sizeof msg)) {
            add(&ln, 0, "  scale %g: %s", s, msg);
            continue;
        }
        hfs_image img = {0};
        rc = stress_render(&rn->bk, b, &scaled, &img, &err);
        if (rc) {
            add(&ln, 0, "  scale %g: render failed (%s): %s", s, hfs_status_name(rc), err.msg);
        } else {
            size_t at;
            const double d = stress_max_diff_at(&img, keep, umax, &at);
            add(&ln, d <= t->scale, "  scale %g: %.1e [%.0e]", s, d, t->scale);
            add_where(rn, &ln, &img, keep, at);
        }
        hfs_image_free(&img);
        stress_scene_free(&scaled);
    }
    if (c->radiance)
        check_radiance_scales(rn, c, b, keep, umax, &ln);
    finish(rn, c, stress_backend_name(b), &ln, t0);
}

static void compare_precisions(runner *rn, const stress_case *c, const char *who,
                               const hfs_image *fp16, const hfs_image *fp32, double umax,
                               const stress_fp16_terms *ft)
{
    const double t0 = now_s();
    line ln = {.len = 0};
    size_t at;
    const double d = stress_max_diff_at(fp16, fp32, umax, &at);
    add(&ln, d <= ft->total,
        "  max %.1e [%.1e = env %.1e + excess %.1e + heights %.1e + normals %.1e + pairs %.1e]", d,
        ft->total, ft->env, ft->excess, ft->heights, ft->normals, ft->pairs);
    add_where(rn, &ln, fp16, fp32, at);
    finish(rn, c, who, &ln, t0);
}

static void run_case(runner *rn, const stress_case *c)
{
    stress_scene sc;
    char msg[512];
    if (build(rn, c, 1.0, &sc, msg, sizeof msg)) {
        printf("FAIL %-20s %-15s  scene: %s\n", c->name, "-", msg);
        rn->fail++;
        return;
    }
    if (c->expect == EXPECT_REFUSE) {
        for (int b = 0; b < BK_COUNT; ++b)
            if (runs(rn, c, b))
                expect_refusal(rn, c, &sc, b, HFS_E_INVALID, NULL);
        if (rn->o->want[BK_CPU]) /* the unshadowed normalizer, on the CPU */
            expect_refusal(rn, c, &sc, -1, HFS_E_INVALID, NULL);
        stress_scene_free(&sc);
        return;
    }
    hfs_image un = {0}, img[BK_COUNT];
    memset(img, 0, sizeof img);
    hfs_error err = {{0}};
    if (hfs_image_alloc(&un, sc.f.width, sc.f.height, &err) ||
        hfs_render_unshadowed(&sc.f, &sc.l, &sc.q, &un, &err)) {
        printf("FAIL %-20s %-15s  unshadowed: %s\n", c->name, "-", err.msg);
        rn->fail++;
        hfs_image_free(&un);
        stress_scene_free(&sc);
        return;
    }
    const double umax = hfs_image_max(&un);
    stress_fp16_terms ft;
    stress_fp16_bound(&sc, umax, &ft);
    for (int b = 0; b < BK_COUNT; ++b) {
        if (!runs(rn, c, b))
            continue;
        if ((b == BK_GLES16 || b == BK_GLES32) && too_big_for_es30(c))
            expect_refusal(rn, c, &sc, b, HFS_E_UNSUPPORTED, "GL_MAX_TEXTURE_SIZE");
        else
            run_backend(rn, c, &sc, b, &un, umax, &ft, &img[b]);
    }
    if (img[BK_GLES16].rgb && img[BK_GLES32].rgb)
        compare_precisions(rn, c, "fp16-vs-fp32", &img[BK_GLES16], &img[BK_GLES32], umax, &ft);
    if (img[BK_ES32_16].rgb && img[BK_ES32_32].rgb)
        compare_precisions(rn, c, "es32 fp16-vs-32", &img[BK_ES32_16], &img[BK_ES32_32], umax, &ft);
    for (int b = 0; b < BK_COUNT; ++b)
        hfs_image_free(&img[b]);
    hfs_image_free(&un);
    stress_scene_free(&sc);
}

int main(int argc, char **argv)
{
    options o;
    if (parse_args(argc, argv, &o))
        return HFS_EXIT_USAGE;
    int n_cases;
    const stress_case *cases = stress_cases(&n_cases);
    if (o.list) {
        for (int i = 0; i < n_cases; ++i)
            printf("%-20s %s%s%s\n", cases[i].name, cases[i].fast ? "[fast] " : "",
                   cases[i].truth ? "[truth] " : "", cases[i].what);
        return 0;
    }
    runner rn;
    memset(&rn, 0, sizeof rn);
    rn.o = &o;
    rn.bk.subsample = o.subsample;
    const double t0 = now_s();
    int ran = 0;
    for (int i = 0; i < n_cases; ++i) {
        if (!selected(&o, &cases[i]))
            continue;
        run_case(&rn, &cases[i]);
        ran++;
    }
    stress_backends_close(&rn.bk);
    printf("hfstress: %d cases, %d checks passed, %d failed (%.1f s)\n", ran, rn.pass, rn.fail,
           now_s() - t0);
    if (rn.pass + rn.fail == 0) {
        printf("SKIP: nothing could run\n");
        return 77;
    }
    return rn.fail ? 1 : 0;
}
