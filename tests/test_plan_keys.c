/*
 * test_plan_keys.c — every scene key through the frame planner (issue 35,
 * "keys the planner forgets"): the test walks the table of scene keys
 * (runtime/core/scene_keys.c) and, for each key a render reads, changes it
 * on a KEPT renderer (one renderer for the whole walk, which rendered the
 * row's base scene just before) and compares what it renders with what a
 * FRESH renderer (made for that scene alone) renders, bit for bit: the lit
 * image, the 3-D view (with the scene's objects), the lit texture
 * (hfs_renderer_render_texture, GLES, read in the test's own EGL context)
 * and point queries.  Each row's base after the previous row's change is
 * checked the same way (the change undone).  The changes are
 * tests/plan_keys_rows.h; a key of the table with no row there (and no
 * reason that no render reads it) fails the test by name, so a key added
 * later is covered or named.  A change must show in some output on the
 * backends its row names, so that every row tests a cache.
 *
 *   test_plan_keys gles|cpu [KEY | every N]   (KEY: that key's rows only;
 *                                              every N: rows 0, N, 2N, ...)
 *
 * The field is 16x16 and the view 32x24: every row renders on fresh
 * renderers too, and on llvmpipe each fresh renderer compiles its shaders
 * anew (LLVM: most of the GLES run's ~8 s of CPU; the CPU run ~3 s).
 *
 * GLES: 77 without a GLES context of any kind (gl_test.h).
 */
#include "gl_app.h"
#include "hfs_io.h"
#include "scene.h"
#include "scene_keys.h"
#include "scene_load.h"
#include "sky_gen.h"
#include "terrain_gen.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "check.h"
#include "plan_keys_rows.h"

#define PI 3.14159265358979323846
#define N 16
#define PK_LINES 32
#define PK_POINTS 6

static char dir[64];
static gl_app app;
static int gles;

/* "dir/NAME" for "@NAME"; else value itself.  Four buffers rotate. */
static const char *expand(const char *value)
{
    static char buf[4][160];
    static int k;
    if (value[0] != '@')
        return value;
    k = (k + 1) % 4;
    snprintf(buf[k], sizeof buf[k], "%s/%s", dir, value + 1);
    return buf[k];
}

typedef struct pk_scene {
    int n;
    pk_set line[PK_LINES];
} pk_scene;

/* The assignments made: each key's lines replaced by its sets'. */
static void scene_put(pk_scene *s, const pk_set *sets, int n)
{
    for (int i = 0; i < n && sets[i].key; ++i) {
        int first = 1;
        for (int j = 0; j < i; ++j)
            first &= strcmp(sets[j].key, sets[i].key) != 0;
        int kept = 0;
        for (int j = 0; j < s->n; ++j)
            if (!first || strcmp(s->line[j].key, sets[i].key))
                s->line[kept++] = s->line[j];
        s->n = kept;
        CHECK(!sets[i].value || s->n < PK_LINES, "more than %d lines in a scene", PK_LINES);
        if (sets[i].value && s->n < PK_LINES)
            s->line[s->n++] = sets[i];
    }
}

static int scene_load(const pk_scene *ps, hfs_scene *s, hfs_scene_inputs *in)
{
    hfs_error err = {""};
    hfs_scene_init(s);
    int rc = 0;
    for (int i = 0; i < ps->n && !rc; ++i)
        rc = hfs_scene_set(s, HFS_SOURCE_FILE, ps->line[i].key, expand(ps->line[i].value),
                           "plan_keys", NULL, &err);
    if (!rc)
        rc = hfs_scene_inputs_load(s, in, &err);
    CHECK(!rc, "scene: %s", err.msg);
    return rc;
}

/* What a renderer made of a scene. */
typedef struct pk_out {
    int w, h, vw, vh, n_vis, noted;
    float *img, *lit, *view, *tex; /* tex: GLES only */
    float vis[PK_POINTS * HFS_MAX_KEY_LIGHTS];
    char ran[256];                 /* the passes of the scene's first frame */
} pk_out;

static void out_free(pk_out *o)
{
    free(o->img), free(o->lit), free(o->view), free(o->tex);
    memset(o, 0, sizeof *o);
}

/* A perspective view that sees terrain, objects and sky. */
static void view_of(const hfs_scene *s, const hfs_field *f, hfs_view *v)
{
    hfs_view_defaults(v, f);
    v->mode = HFS_VIEW_PERSPECTIVE;
    v->azimuth = 30.0 * PI / 180.0, v->elevation = 35.0 * PI / 180.0;
    v->fov = 50.0 * PI / 180.0;
    v->exaggeration = 1.5;
    v->width = 32, v->height = 24;
    v->objects = s->objects, v->n_objects = s->n_objects;
    hfs_view_frame(v, f);
}

/* Points over the footprint, some above the terrain and some below. */
static void points_of(const hfs_field *f, double *xyz)
{
    float lo = f->z[0], hi = f->z[0];
    for (int i = 1; i < f->width * f->height; ++i)
        lo = fminf(lo, f->z[i]), hi = fmaxf(hi, f->z[i]);
    for (int p = 0; p < PK_POINTS; ++p) {
        xyz[3 * p] = (0.15 + 0.14 * p) * (f->width - 1) * f->dx;
        xyz[3 * p + 1] = (0.8 - 0.12 * p) * (f->height - 1) * f->dx;
        xyz[3 * p + 2] = f->zscale * (lo + (0.3 + 0.12 * p) * (hi - lo));
    }
}

static float *take(hfs_image *im)
{
    float *p = im->rgb;
    im->rgb = NULL;
    return p;
}

/* The passes of r's last frame, if it is the scene's first. */
static void note(const hfs_renderer *r, pk_out *o)
{
    if (!o->noted)
        gl_test_ran(r, o->ran, sizeof o->ran);
    o->noted = 1;
}

/* The four outputs: the view (and the lit image it renders) first or last
 * (view_last), the lit texture, the image, point queries.  A view frame
 * right after another keeps the view unless the planner sees a change: a
 * kept renderer's base ends with the view and its change begins with it,
 * so that a stale view shows. */
static int render_all(hfs_renderer *r, const hfs_scene *s, const hfs_scene_inputs *in,
                      int view_last, pk_out *o)
{
    const hfs_field *f = &in->field;
    const hfs_lighting *l = &in->lighting;
    const hfs_quality *q = &in->quality;
    hfs_error err = {""};
    hfs_view v;
    view_of(s, f, &v);
    hfs_image lit = {0}, view = {0}, img = {0};
    memset(o, 0, sizeof *o);
    o->w = f->width, o->h = f->height, o->vw = v.width, o->vh = v.height;
    int rc = hfs_image_alloc(&lit, f->width, f->height, &err) ||
             hfs_image_alloc(&view, v.width, v.height, &err) ||
             hfs_image_alloc(&img, f->width, f->height, &err);
    if (!rc && !view_last && !(rc = hfs_renderer_render_view(r, f, l, q, &v, &lit, &view, &err)))
        note(r, o);
    if (!rc && gles) {
        hfs_lit_texture t;
        o->tex = malloc((size_t)f->width * f->height * 4 * sizeof *o->tex);
        rc = o->tex ? hfs_renderer_render_texture(r, f, l, q, NULL, &t, &err)
                    : hfs_fail(&err, HFS_E_NOMEM, "no memory");
        if (!rc && !(rc = gl_app_read(&app, &t, o->tex, &err)))
            note(r, o);
    }
    if (!rc && !(rc = hfs_renderer_render(r, f, l, q, &img, NULL, NULL, &err)))
        note(r, o);
    double xyz[3 * PK_POINTS];
    points_of(f, xyz);
    o->n_vis = PK_POINTS * l->n_key;
    if (!rc)
        rc = hfs_renderer_query_points(r, f, l, q, xyz, PK_POINTS, o->vis, &err);
    if (!rc && view_last)
        rc = hfs_renderer_render_view(r, f, l, q, &v, &lit, &view, &err);
    o->lit = take(&lit), o->view = take(&view), o->img = take(&img);
    CHECK(!rc, "render: %s", err.msg);
    return rc;
}

/* 1 when the two hold the same values; else says where they differ. */
static int same(const float *a, const float *b, size_t n, const char *what, const char *row)
{
    if (!a || !b)
        return a == b;
    size_t bad = 0, first = 0;
    for (size_t i = 0; i < n; ++i)
        if (memcmp(&a[i], &b[i], sizeof *a) && bad++ == 0)
            first = i;
    if (bad && row)
        CHECK(0, "%s: the %s differs from a fresh renderer's at %zu of %zu values (first at "
              "%zu: kept %.9g, fresh %.9g)", row, what, bad, n, first, a[first], b[first]);
    return bad == 0;
}

/* Kept against fresh (row names the case; NULL: only tells whether all
 * outputs are equal). */
static int compare(const pk_out *a, const pk_out *b, const char *row)
{
    if (a->w != b->w || a->h != b->h || a->n_vis != b->n_vis) {
        if (row)
            CHECK(0, "%s: %dx%d, %d visibilities; fresh %dx%d, %d", row, a->w, a->h, a->n_vis,
                  b->w, b->h, b->n_vis);
        return 0;
    }
    const size_t px = (size_t)a->w * a->h;
    int eq = same(a->img, b->img, px * 3, "image", row);
    eq &= same(a->lit, b->lit, px * 3, "view's lit image", row);
    eq &= same(a->view, b->view, (size_t)a->vw * a->vh * 3, "3-D view", row);
    eq &= same(a->tex, b->tex, px * 4, "lit texture", row);
    eq &= same(a->vis, b->vis, (size_t)a->n_vis, "point queries", row);
    if (!eq && row)
        fprintf(stderr, "  %s: the kept renderer's first frame ran: %s\n", row,
                a->ran[0] ? a->ran : "(nothing)");
    return eq;
}

static hfs_renderer *renderer(void)
{
    const hfs_renderer_desc d = gles ? (hfs_renderer_desc){.backend = HFS_BACKEND_GLES,
                                                           .egl_display = app.dpy,
                                                           .egl_share_context = app.ctx}
                                     : (hfs_renderer_desc){.backend = HFS_BACKEND_CPU};
    return gl_test_renderer(&d);
}

/* The scene on the kept renderer (its view last when it is a row's base)
 * and on a fresh one (the fresh outputs into *fresh; cached: already
 * there); kept_ran: the passes of the kept renderer's first frame of it
 * (256 bytes). */
static int step(hfs_renderer *kept, const pk_scene *ps, pk_out *fresh, int cached, int base,
                const char *row, char *kept_ran)
{
    hfs_scene s;
    hfs_scene_inputs in = {0};
    if (scene_load(ps, &s, &in))
        return 1;
    pk_out k;
    int rc = render_all(kept, &s, &in, base, &k);
    snprintf(kept_ran, 256, "%s", k.ran);
    if (!rc && !cached) {
        hfs_renderer *r = renderer();
        rc = render_all(r, &s, &in, 0, fresh);
        hfs_renderer_destroy(r);
    }
    if (!rc)
        compare(&k, fresh, row);
    out_free(&k);
    hfs_scene_inputs_free(&in);
    return rc;
}

/* Fresh renderers' outputs of the rows' bases, kept: rows share bases
 * (the common one, the map's, the colour sky's, ...). */
#define PK_BASES 8
typedef struct pk_bases {
    int n;
    pk_scene scene[PK_BASES];
    pk_out out[PK_BASES];
} pk_bases;

static int scene_same(const pk_scene *a, const pk_scene *b)
{
    int same = a->n == b->n;
    for (int i = 0; same && i < a->n; ++i)
        same = !strcmp(a->line[i].key, b->line[i].key) &&
               !strcmp(a->line[i].value, b->line[i].value);
    return same;
}

/* The slot of base b in the cache (*cached: its outputs are there). */
static pk_out *base_slot(pk_bases *c, const pk_scene *b, int *cached)
{
    for (int i = 0; i < c->n; ++i)
        if (scene_same(&c->scene[i], b)) {
            *cached = 1;
            return &c->out[i];
        }
    *cached = 0;
    const int i = c->n < PK_BASES ? c->n++ : PK_BASES - 1;
    out_free(&c->out[i]);
    c->scene[i] = *b;
    return &c->out[i];
}

/* One row: its base (the last change undone), then its change. */
static void run_row(hfs_renderer *kept, const pk_row *row, pk_bases *bases)
{
    pk_scene b = {0}, c;
    scene_put(&b, pk_base, (int)(sizeof pk_base / sizeof pk_base[0]));
    scene_put(&b, row->base, PK_SETS);
    c = b;
    scene_put(&c, row->to, PK_SETS);
    char what[200], ran[256];
    int cached;
    pk_out changed = {0}, *fb = base_slot(bases, &b, &cached);
    snprintf(what, sizeof what, "%s = %.24s: back to its base", row->key, row->to[0].value);
    if (step(kept, &b, fb, cached, 1, what, ran)) {
        bases->scene[fb - bases->out].n = -1; /* nothing there: matches no scene */
        return;
    }
    snprintf(what, sizeof what, "%s = %.24s", row->key, row->to[0].value);
    if (!step(kept, &c, &changed, 0, 0, what, ran)) {
        const unsigned mine = gles ? PK_GLES : PK_CPU;
        CHECK(!(row->shows & mine) || !compare(fb, &changed, NULL),
              "%s: the change shows in no output; pick a value that matters", what);
        printf("%-40s kept renderer ran: %s\n", what, ran[0] ? ran : "(nothing)");
    }
    out_free(&changed);
}

/* Every key of the table has rows, or a reason no render reads it; every
 * row changes a key of the table. */
static void check_table(void)
{
    const int nr = (int)(sizeof pk_rows / sizeof pk_rows[0]);
    const int nu = (int)(sizeof pk_unread / sizeof pk_unread[0]);
    for (int id = 0; id < HFS_SK_COUNT; ++id) {
        const char *name = hfs_scene_key_get((hfs_scene_key_id)id)->name;
        int rows = 0;
        for (int i = 0; i < nr; ++i)
            rows += !strcmp(pk_rows[i].key, name);
        for (int i = 0; i < nu; ++i)
            rows += !strcmp(pk_unread[i].key, name);
        CHECK(rows > 0, "scene key '%s' has no changed value in tests/plan_keys_rows.h (nor "
              "a reason that no render reads it): add a row", name);
    }
    for (int i = 0; i < nr; ++i)
        CHECK(hfs_scene_key_find(pk_rows[i].key) >= 0 && pk_rows[i].to[0].key &&
                  !strcmp(pk_rows[i].to[0].key, pk_rows[i].key),
              "row %d (%s) changes no key of the table", i, pk_rows[i].key);
}

/* The files the rows name: two raw fields, two skies with a sun, an
 * albedo map, an objects file. */
static int fixtures(void)
{
    hfs_error err = {""};
    float z[N * N], z2[N * N];
    hfs_terrain_cones(z, N, N);
    hfs_terrain_eggtray(z2, N, N);
    for (int i = 0; i < N * N; ++i) /* cones 7.7 high: shadows on a small field */
        z[i] *= 3.0f, z2[i] *= 4.0f;
    z[5 * N + 7] = z[11 * N + 3] = z[13 * N + 12] = 3.0f; /* for nodata = 3 */
    FILE *fp = fopen(expand("@h1.f32"), "wb");
    int rc = !fp || fwrite(z, sizeof z, 1, fp) != 1;
    rc |= fp && fclose(fp) != 0;
    fp = fopen(expand("@h2.f32"), "wb");
    rc |= !fp || fwrite(z2, sizeof z2, 1, fp) != 1;
    rc |= fp && fclose(fp) != 0;
    hfs_image sky = {0}, alb = {0};
    rc = rc || hfs_image_alloc(&sky, 64, 32, &err) || hfs_image_alloc(&alb, N, N, &err);
    for (int k = 0; k < 2 && !rc; ++k) {
        hfs_sky_desc d;
        hfs_sky_defaults(&d, 64, 32);
        d.n_disks = 1;
        d.disk[0] = (hfs_sky_disk){80.0 + 120.0 * k, 40.0 - 10.0 * k, 1.5, {1, 1, 1}};
        double e[1][3];
        rc = hfs_sky_render(&d, sky.rgb, e);
        hfs_sky_set_share(&d, 0, 0.6, sky.rgb, e);
        rc = rc || hfs_pfm_write(expand(k ? "@sky2.pfm" : "@sky1.pfm"), &sky, 0, &err);
    }
    for (int i = 0; !rc && i < N * N * 3; ++i)
        alb.rgb[i] = 0.2f + 0.7f * (float)((i * 7) % 11) / 10.0f;
    rc = rc || hfs_pfm_write(expand("@alb.pfm"), &alb, 0, &err);
    fp = rc ? NULL : fopen(expand("@obj.txt"), "w");
    rc = rc || !fp || fputs("pin = 12,12,5,1.5\nbox = 3,3,0,2,2,3\n", fp) < 0;
    rc |= fp && fclose(fp) != 0;
    hfs_image_free(&sky);
    hfs_image_free(&alb);
    CHECK(!rc, "fixtures in %s: %s", dir, err.msg[0] ? err.msg : "cannot write");
    return rc;
}

/* Which rows to run: argv[2] a key (its rows), or "every N" (rows 0, N,
 * 2N, ...: the sanitizer build's subset), or none (all). */
static int wanted(int argc, char **argv, size_t i)
{
    if (argc > 3 && !strcmp(argv[2], "every"))
        return i % (size_t)(atoi(argv[3]) > 0 ? atoi(argv[3]) : 1) == 0;
    return argc < 3 || !strcmp(argv[2], pk_rows[i].key);
}

int main(int argc, char **argv)
{
    if (argc < 2 || (strcmp(argv[1], "gles") && strcmp(argv[1], "cpu"))) {
        fprintf(stderr, "usage: test_plan_keys gles|cpu [KEY | every N]\n");
        return 2;
    }
    gles = !strcmp(argv[1], "gles");
    check_table();
    snprintf(dir, sizeof dir, "/tmp/plan_keys_XXXXXX");
    if (!mkdtemp(dir) || fixtures())
        return 1;
    if (gles)
        gl_app_make(&app);
    const clock_t t0 = clock();
    hfs_renderer *kept = renderer();
    static pk_bases bases;
    int rows = 0;
    for (size_t i = 0; i < sizeof pk_rows / sizeof pk_rows[0]; ++i)
        if (wanted(argc, argv, i)) {
            run_row(kept, &pk_rows[i], &bases);
            rows++;
        }
    hfs_renderer_destroy(kept);
    for (int i = 0; i < bases.n; ++i)
        out_free(&bases.out[i]);
    if (gles)
        gl_app_free(&app);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", dir);
    printf("plan keys (%s): %d rows, %ld checks, %d failures, %.1f s CPU\n", argv[1], rows,
           checks, failures, (double)(clock() - t0) / CLOCKS_PER_SEC);
    return failures ? 1 : 0;
}
