/*
 * test_gles_edits.c — local edits of the heights cost local work and
 * change nothing else (issue 38): after each of a seeded random sequence
 * of edits the frame of a kept renderer (which recomputes only what the
 * edit can reach, runtime/gles/edit_frame.h) must equal, bit for bit, the
 * frame of a renderer made to recompute everything (hfs_renderer_invalidate
 * before each frame); and the kept renderer must have taken the edit path
 * (its frame report's terrain step says "heights edited") for the edits
 * that keep the field's range, but one: a renderer that freed the grid's
 * horizons after its frames (the slice path's sky or map occlusion, no
 * bounces: gles_frame.c grid_release, issue 37) recomputes the frame of
 * its first change of the heights whole, and keeps them from then on.
 *
 *   test_gles_edits [EDITS] [SEED] [W] [H]      (defaults 40 1 72 56)
 *
 * Each scene of the table below takes the whole sequence: the product's
 * defaults (an SH sky and a key light), a low narrow sun (long shadows of
 * narrow features), the wedge-table path (the grid's horizons reach the
 * field's end: drawn whole), subsample 1 (the key reads its grid: drawn
 * whole), a local light and a bounce (drawn whole, fed by the regions),
 * fp32, a bounce alone, a local light with the sun and no sky and with the
 * sky and no sun, a wider sun, a level offset of 2 (the far scales read
 * filtered levels: the pyramid redrawn over the coarsest level's reach),
 * and the defaults on the CPU reference (which recomputes whole frames:
 * the same check, no edit path).  HFS_EDITS_SCENE=TEXT runs the scenes whose
 * name holds TEXT; HFS_EDITS_VERBOSE=1 says where a mismatch lies.
 * Edits: smooth bumps and dents anywhere (borders and corners too), one
 * place grown and shrunk again, a tall spike far from where the others are
 * and its removal, every height moved (a cold frame: the change covers
 * most of the field), one that moves the field's range (a cold frame), the
 * key light moved with and without an edit.
 * No GLES context of any kind: exit 77 (gl_test.h).
 */
#include "hfshade.h"
#include "terrain_gen.h"
#include "gl_test.h"
#include "test_rng.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

static int pick(int n)
{
    return (int)(urand() * n);
}

enum edit_kind { E_BUMP, E_DENT, E_GROW, E_SPIKE, E_WHOLE, E_RANGE, E_LIGHT, E_LIGHT_BUMP,
                 E_KINDS };
static const char *const kind_names[E_KINDS] = {"bump", "dent", "grow/shrink", "far spike",
                                                "every height", "range", "light", "light+bump"};

typedef struct world {
    int w, h;
    float *z, *prev; /* the heights, and before the edit */
    float lo, hi;   /* the pinned range: edits stay strictly inside */
    int gx, gy;     /* the grown and shrunk place */
    int sx, sy;     /* the spike, while it stands (sx < 0: none) */
    float s_was;
    hfs_field f;
    hfs_lighting l;
    hfs_quality q;
} world;

static float clampz(const world *w, double v)
{
    const double lo = w->lo + 1e-3, hi = w->hi - 1e-3;
    return (float)(v < lo ? lo : (v > hi ? hi : v));
}

/* A smooth bump of height d and radius r at (cx, cy) (a cosine bell). */
static void bump(world *w, int cx, int cy, int r, double d)
{
    for (int y = cy - r; y <= cy + r; ++y)
        for (int x = cx - r; x <= cx + r; ++x) {
            if (x < 0 || y < 0 || x >= w->w || y >= w->h ||
                (x == 0 && y == 0) || (x == w->w - 1 && y == w->h - 1)) /* pinned */
                continue;
            const double q = sqrt((double)(x - cx) * (x - cx) + (double)(y - cy) * (y - cy)) / r;
            if (q >= 1.0)
                continue;
            float *z = &w->z[(size_t)y * w->w + x];
            *z = clampz(w, *z + d * 0.5 * (1.0 + cos(PI * q)));
        }
}

/* Somewhere, a border or a corner a third of the time. */
static void place(const world *w, int *x, int *y)
{
    *x = pick(w->w);
    *y = pick(w->h);
    if (pick(3) == 0) {
        *x = pick(2) ? 0 : w->w - 1;
        if (pick(2))
            *y = pick(2) ? 0 : w->h - 1;
    }
}

static void key_move(world *w)
{
    hfs_key_light *k = &w->l.key[0];
    k->phi = fmod(k->phi + uni(-0.3, 0.3) + 2 * PI, 2 * PI);
    k->elev = fmin(1.2, fmax(0.05, k->elev + uni(-0.1, 0.1)));
}

/* Applies one edit; returns whether it keeps the field's range (it should
 * take the edit path). */
static int apply_edit(world *w, int kind)
{
    int x, y;
    const double relief = w->hi - w->lo;
    switch (kind) {
    case E_BUMP:
    case E_LIGHT_BUMP:
        place(w, &x, &y);
        bump(w, x, y, 1 + pick(8), uni(0.05, 0.4) * relief);
        if (kind == E_LIGHT_BUMP)
            key_move(w);
        return kind == E_BUMP;
    case E_DENT:
        place(w, &x, &y);
        bump(w, x, y, 1 + pick(8), -uni(0.05, 0.4) * relief);
        return 1;
    case E_GROW:
        bump(w, w->gx, w->gy, 2 + pick(4), uni(-0.3, 0.3) * relief);
        return 1;
    case E_SPIKE:
        if (w->sx < 0) { /* a one-texel spike nearly as tall as the field */
            w->sx = pick(w->w);
            w->sy = pick(w->h);
            w->s_was = w->z[(size_t)w->sy * w->w + w->sx];
            w->z[(size_t)w->sy * w->w + w->sx] = clampz(w, w->hi);
        } else { /* and gone again */
            w->z[(size_t)w->sy * w->w + w->sx] = w->s_was;
            w->sx = -1;
        }
        return 1;
    case E_WHOLE: /* over most of the field: a cold frame is cheaper (edit_frame.h) */
        for (int i = 1; i + 1 < w->w * w->h; ++i)
            w->z[i] = clampz(w, w->z[i] + uni(-0.01, 0.01) * relief);
        return 0;
    case E_RANGE: /* the highest height moves: every normalized height does */
        w->hi += (float)(0.05 * relief);
        w->z[0] = w->hi;
        return 0;
    default:
        key_move(w);
        return 0;
    }
}

typedef struct scene {
    const char *name;
    int env, key, local, bounces, subsample, tables, fp32;
    double elev, alpha;
    int offset; /* the pyramid's level offset; 0: the default */
    int cpu;    /* on the CPU reference (it recomputes every frame whole) */
} scene;

static const scene scenes[] = {
    {"defaults (sky + sun)", 1, 1, 0, 0, 0, 0, 0, 0.26, 0.035, 0, 0},
    {"low narrow sun", 0, 1, 0, 0, 0, 0, 0, 0.07, 0.004, 0, 0},
    {"wedge tables", 1, 1, 0, 0, 0, 1, 0, 0.4, 0.035, 0, 0},
    {"subsample 1", 1, 1, 0, 0, 1, 0, 0, 0.26, 0.035, 0, 0},
    {"local light + bounce", 1, 1, 1, 1, 0, 0, 0, 0.3, 0.05, 0, 0},
    {"fp32", 1, 1, 0, 0, 0, 0, 1, 0.2, 0.02, 0, 0},
    {"bounce", 1, 1, 0, 1, 0, 0, 0, 0.3, 0.05, 0, 0},
    {"sun + local light, no sky", 0, 1, 1, 0, 0, 0, 0, 0.3, 0.05, 0, 0},
    {"sky + local light", 1, 0, 1, 0, 0, 0, 0, 0.3, 0.05, 0, 0},
    {"wide sun", 1, 1, 0, 0, 0, 0, 0, 0.3, 0.05, 0, 0},
    {"filtered levels (offset 2)", 1, 1, 0, 0, 0, 0, 0, 0.2, 0.035, 2, 0},
    {"the CPU reference", 1, 1, 0, 0, 0, 0, 0, 0.26, 0.035, 0, 1},
};

static void world_scene(world *w, const scene *s)
{
    hfs_lighting_defaults(&w->l);
    w->l.albedo = 0.7;
    w->l.has_env = s->env;
    for (int c = 0; c < 3; ++c) {
        w->l.env_sh[c][0] = 1.0 + 0.1 * c;
        w->l.env_sh[c][2] = 0.5;
        w->l.env_sh[c][3] = 0.2;
    }
    if (s->key) {
        hfs_key_light *k = &w->l.key[w->l.n_key++];
        k->phi = 2.2;
        k->elev = s->elev;
        k->alpha = s->alpha;
        for (int c = 0; c < 3; ++c)
            k->radiance[c] = 40.0f;
    }
    if (s->local) {
        hfs_local_light *p = &w->l.local[w->l.n_local++];
        p->pos[0] = w->w * 0.3;
        p->pos[1] = w->h * 0.6;
        p->pos[2] = w->lo + 0.92 * (w->hi - w->lo); /* low: long shadows */
        p->radius = 1.0;
        for (int c = 0; c < 3; ++c)
            p->radiance[c] = 30.0f;
    }
    hfs_quality_defaults(&w->q);
    w->l.bounces = s->bounces;
    if (s->subsample)
        w->q.subsample = s->subsample;
    if (s->tables)
        w->q.visibility = HFS_VIS_WEDGE_TABLE;
    if (s->fp32)
        w->q.precision = HFS_PRECISION_FP32;
    if (s->offset)
        w->q.offset = s->offset;
}

static int world_heights(world *w, uint32_t seed)
{
    if (hfs_terrain_fractal(w->z, w->w, w->h, seed, 0.25))
        return -1;
    float lo = w->z[0], hi = w->z[0];
    for (int i = 0; i < w->w * w->h; ++i) {
        lo = fminf(lo, w->z[i]);
        hi = fmaxf(hi, w->z[i]);
    }
    /* pinned: the first texel the highest, the last the lowest */
    w->hi = hi + 0.2f * (hi - lo);
    w->lo = lo - 0.05f * (hi - lo);
    w->z[0] = w->hi;
    w->z[(size_t)w->w * w->h - 1] = w->lo;
    w->gx = w->w / 3;
    w->gy = w->h / 2;
    w->sx = -1;
    return 0;
}

/* One scene through the sequence; 0 when every frame matched. */
static int run_scene(world *w, const scene *s, int edits, uint32_t seed, int counts[E_KINDS],
                     int *edited, int *kept, int *first)
{
    rng_state = TEST_RNG_SEED ^ ((uint64_t)seed * 0x100000001b3ull); /* each scene alone */
    world_scene(w, s);
    if (world_heights(w, seed))
        return -1;
    const hfs_renderer_desc cpu = {.backend = HFS_BACKEND_CPU};
    hfs_renderer *planned = s->cpu ? gl_test_renderer(&cpu) : gl_test_gles();
    hfs_renderer *fresh = s->cpu ? gl_test_renderer(&cpu) : gl_test_gles();
    hfs_image a = {0}, b = {0};
    hfs_error err;
    int failed = 0;
    if (hfs_image_alloc(&a, w->w, w->h, &err) || hfs_image_alloc(&b, w->w, w->h, &err))
        return -1;
    /* the grid's horizons freed after each frame until the heights change
     * (gles_frame.c grid_release): the first change is a whole frame */
    const int frees = w->q.visibility == HFS_VIS_SLICE && w->l.has_env && w->l.bounces == 0;
    int changed = 0; /* the heights changed in an earlier frame */
    for (int e = 0; e <= edits && !failed; ++e) {
        int kind = -1, keeps = 0, whole = 0;
        if (e > 0) {
            kind = pick(E_KINDS);
            memcpy(w->prev, w->z, (size_t)w->w * w->h * sizeof *w->z);
            keeps = apply_edit(w, kind);
            /* an edit that changed no height (a bump on a pinned texel) is none */
            const int moved = memcmp(w->prev, w->z, (size_t)w->w * w->h * sizeof *w->z) != 0;
            keeps &= moved;
            /* the first change of the heights on a renderer that freed them */
            if (keeps && frees && !changed)
                keeps = 0, whole = 1;
            changed |= moved;
            ++counts[kind];
        }
        hfs_renderer_invalidate(fresh);
        if (hfs_renderer_render(planned, &w->f, &w->l, &w->q, &a, NULL, NULL, &err) ||
            hfs_renderer_render(fresh, &w->f, &w->l, &w->q, &b, NULL, NULL, &err)) {
            printf("FAIL: %s: edit %d: render: %s\n", s->name, e, err.msg);
            failed = 1;
            break;
        }
        if (whole && !s->cpu) { /* pinned: the memory's price, paid once */
            ++*first;
            if (gl_test_edited(planned)) {
                printf("FAIL: %s: edit %d: the first change took the edit path with the grid's "
                       "horizons freed\n", s->name, e);
                failed = 1;
            }
        }
        if (keeps && !s->cpu) {
            const int took = gl_test_edited(planned);
            ++*kept;
            *edited += took;
            if (!took && getenv("HFS_EDITS_VERBOSE"))
                printf("%s: edit %d (%s): a whole frame\n", s->name, e, kind_names[kind]);
        }
        if (getenv("HFS_EDITS_VERBOSE") && memcmp(a.rgb, b.rgb, (size_t)w->w * w->h * 3 * 4)) {
            int n = 0, x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
            for (int y = 0; y < w->h; ++y)
                for (int x = 0; x < w->w; ++x)
                    if (memcmp(&a.rgb[3 * (y * w->w + x)], &b.rgb[3 * (y * w->w + x)], 12)) {
                        ++n;
                        x0 = x < x0 ? x : x0, y0 = y < y0 ? y : y0;
                        x1 = x > x1 ? x : x1, y1 = y > y1 ? y : y1;
                    }
            int cx0 = 1 << 30, cy0 = 1 << 30, cx1 = -1, cy1 = -1;
            for (int y = 0; y < w->h; ++y)
                for (int x = 0; x < w->w; ++x)
                    if (w->prev[y * w->w + x] != w->z[y * w->w + x]) {
                        cx0 = x < cx0 ? x : cx0, cy0 = y < cy0 ? y : cy0;
                        cx1 = x > cx1 ? x : cx1, cy1 = y > cy1 ? y : cy1;
                    }
            printf("%d texels differ in (%d,%d)-(%d,%d); heights changed in (%d,%d)-(%d,%d)\n", n,
                   x0, y0, x1, y1, cx0, cy0, cx1, cy1);
        }
        for (size_t i = 0; i < (size_t)w->w * w->h * 3; ++i)
            if (memcmp(&a.rgb[i], &b.rgb[i], sizeof(float)) != 0) {
                printf("FAIL: %s: edit %d (%s): texel (%zu, %zu) channel %zu: edited %.9g, "
                       "from scratch %.9g\n", s->name, e, kind < 0 ? "none" : kind_names[kind],
                       i / 3 % (size_t)w->w, i / 3 / (size_t)w->w, i % 3, a.rgb[i], b.rgb[i]);
                failed = 1;
                break;
            }
    }
    hfs_image_free(&a);
    hfs_image_free(&b);
    hfs_renderer_destroy(planned);
    hfs_renderer_destroy(fresh);
    return failed;
}

int main(int argc, char **argv)
{
    const int edits = argc > 1 ? atoi(argv[1]) : 40;
    const uint64_t seed = argc > 2 ? strtoull(argv[2], NULL, 10) : 1;
    const int W = argc > 3 ? atoi(argv[3]) : 72, H = argc > 4 ? atoi(argv[4]) : 56;
    if (edits < 1 || W < 8 || H < 8 || W > 1024 || H > 1024) {
        fprintf(stderr, "usage: test_gles_edits [EDITS >= 1] [SEED] [W H: 8..1024]\n");
        return 2;
    }
    world w;
    memset(&w, 0, sizeof w);
    w.w = W, w.h = H;
    w.z = malloc((size_t)W * H * sizeof *w.z);
    w.prev = malloc((size_t)W * H * sizeof *w.prev);
    if (!w.z || !w.prev)
        return 1;
    w.f = (hfs_field){.width = W, .height = H, .z = w.z, .dx = 1.5, .zscale = 1.0};
    int counts[E_KINDS] = {0}, failed = 0, edited = 0, kept = 0, first = 0;
    const int n_scenes = (int)(sizeof scenes / sizeof scenes[0]);
    const char *only = getenv("HFS_EDITS_SCENE"); /* a scene's name, to debug one */
    for (int s = 0; s < n_scenes && !failed; ++s) {
        if (only && !strstr(scenes[s].name, only))
            continue;
        const int rc = run_scene(&w, &scenes[s], edits, (uint32_t)(seed * 16 + s), counts,
                                 &edited, &kept, &first);
        if (rc < 0) {
            printf("FAIL: %s: out of memory\n", scenes[s].name);
            failed = 1;
        }
        failed |= rc != 0;
    }
    printf("%d scenes x %d edits (%dx%d):", n_scenes, edits, W, H);
    for (int k = 0; k < E_KINDS; ++k)
        printf(" %s %d%s", kind_names[k], counts[k], k + 1 < E_KINDS ? "," : "\n");
    printf("edits that keep the range: %d, of them on the edit path: %d (and %d renderers' "
           "first, recomputed whole)\n", kept, edited, first);
    /* Every edit that keeps the range and comes alone takes the path. */
    if (!failed && edited != kept) {
        printf("FAIL: %d edits that keep the range recomputed the whole frame\n", kept - edited);
        failed = 1;
    }
    printf("edited == from scratch, bit for bit: %s\n", failed ? "NO" : "yes");
    free(w.z);
    free(w.prev);
    return failed ? 1 : 0;
}
