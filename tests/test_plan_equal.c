/*
 * test_plan_equal.c — correctness of the frame planner (issue 6): a seeded
 * random sequence of scene edits (heights, dx/zscale, environment rotation
 * and tint, key and local lights moved (also within a key's sampled swath, and
 * local lights beyond the terrain's shadow range), resized, re-tinted, switched off and
 * on, added and removed, albedo, quality settings including precision and
 * the visibility path, the timing level: level 2's counting passes
 * overwrite the visibility targets), and after each edit the
 * frame of a renderer that plans (keeps what the edit did not invalidate)
 * must equal, bit for bit, the frame of a renderer made to recompute
 * everything (hfs_renderer_invalidate before each frame).
 *
 *   test_plan_equal [EDITS] [SEED] [SIZE]     (defaults 2000 1 24)
 *
 * Prints the edit kinds' counts and the first mismatch (edit number, kind,
 * texel).  No GLES context of any kind: exit 77 (gl_test.h).
 */
#include "hfshade.h"
#include "terrain_gen.h"
#include "gl_test.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

static uint64_t rng_state;

static uint32_t rnd(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return (uint32_t)(rng_state >> 11);
}

static double uni(double lo, double hi)
{
    return lo + (hi - lo) * (rnd() / 4294967296.0);
}

static int pick(int n)
{
    return (int)(rnd() % (uint32_t)n);
}

enum edit_kind { E_HEIGHTS, E_SCALE, E_ENV_ROTATE, E_ENV_TINT, E_ENV_TOGGLE, E_KEY_MOVE,
                 E_KEY_NUDGE, E_KEY_RADIANCE, E_KEY_TOGGLE, E_KEY_COUNT, E_LOCAL_MOVE,
                 E_LOCAL_RADIANCE, E_LOCAL_TOGGLE, E_LOCAL_COUNT, E_ALBEDO, E_QUALITY, E_NONE,
                 E_KINDS };
static const char *const kind_names[E_KINDS] = {
    "heights", "dx/zscale", "env rotate", "env tint", "env on/off", "key move", "key nudge",
    "key radiance", "key on/off", "key count", "local move", "local radiance", "local on/off",
    "local count", "albedo", "quality", "nothing"};

typedef struct world {
    int n, timing;
    float *z;
    hfs_field f;
    hfs_lighting l;
    hfs_quality q;
} world;

static void key_random(hfs_key_light *k)
{
    k->phi = uni(0, 2 * PI);
    k->elev = uni(0.05, 1.3);
    k->alpha = uni(0.01, 0.1);
    for (int c = 0; c < 3; ++c)
        k->radiance[c] = (float)uni(5, 50);
    k->disabled = 0;
}

static void local_random(hfs_local_light *p, int n)
{
    p->pos[0] = uni(0, n - 1);
    p->pos[1] = uni(0, n - 1);
    p->pos[2] = uni(1, 0.4 * n);
    p->radius = uni(0.3, 2.0);
    for (int c = 0; c < 3; ++c)
        p->radiance[c] = (float)uni(1, 20);
    p->disabled = 0;
}

static int apply_edit(world *w, int kind)
{
    hfs_lighting *l = &w->l;
    switch (kind) {
    case E_HEIGHTS: { /* a bump or a dent in a random rectangle */
        const int x0 = pick(w->n), y0 = pick(w->n), rw = 1 + pick(6), rh = 1 + pick(6);
        const float d = (float)uni(-2, 2);
        for (int j = y0; j < y0 + rh && j < w->n; ++j)
            for (int i = x0; i < x0 + rw && i < w->n; ++i)
                w->z[(size_t)j * w->n + i] = fmaxf(0.0f, w->z[(size_t)j * w->n + i] + d);
        return 1;
    }
    case E_SCALE:
        if (pick(2))
            w->f.dx = uni(0.5, 2.0);
        else
            w->f.zscale = uni(0.3, 2.0);
        return 1;
    case E_ENV_ROTATE:
        l->env_rotate = uni(-PI, PI);
        return l->has_env;
    case E_ENV_TINT: {
        const int c = pick(3);
        const double s = uni(0.5, 1.5);
        for (int k = 0; k < HFS_SH_COEFFS; ++k)
            l->env_sh[c][k] *= s;
        return l->has_env;
    }
    case E_ENV_TOGGLE:
        l->has_env = !l->has_env;
        return 1;
    case E_KEY_MOVE:
        if (!l->n_key)
            return 0;
        key_random(&l->key[pick(l->n_key)]);
        return 1;
    case E_KEY_NUDGE: { /* small moves: within or just out of the swath */
        if (!l->n_key)
            return 0;
        hfs_key_light *k = &l->key[pick(l->n_key)];
        k->phi += uni(-0.02, 0.02);
        k->elev = fmin(1.4, fmax(0.02, k->elev + uni(-0.01, 0.01)));
        return 1;
    }
    case E_KEY_RADIANCE:
        if (!l->n_key)
            return 0;
        l->key[pick(l->n_key)].radiance[pick(3)] = (float)(pick(5) ? uni(1, 60) : 0.0);
        return 1;
    case E_KEY_TOGGLE:
        if (!l->n_key)
            return 0;
        l->key[pick(l->n_key)].disabled ^= 1;
        return 1;
    case E_KEY_COUNT:
        if (l->n_key < 3 && (l->n_key == 0 || pick(2)))
            key_random(&l->key[l->n_key++]);
        else
            --l->n_key;
        return 1;
    case E_LOCAL_MOVE: {
        if (!l->n_local)
            return 0;
        hfs_local_light *p = &l->local[pick(l->n_local)];
        switch (pick(3)) {
        case 0: p->pos[pick(3)] += uni(-2, 2); break;
        case 1: p->radius = uni(0.2, 2.5); break;
        /* Up beyond the terrain's shadow range (no ratios) and back. */
        default: p->pos[2] = pick(2) ? uni(2.0 * w->n, 8.0 * w->n) : uni(1, 0.4 * w->n); break;
        }
        return 1;
    }
    case E_LOCAL_RADIANCE:
        if (!l->n_local)
            return 0;
        l->local[pick(l->n_local)].radiance[pick(3)] = (float)(pick(5) ? uni(0.5, 30) : 0.0);
        return 1;
    case E_LOCAL_TOGGLE:
        if (!l->n_local)
            return 0;
        l->local[pick(l->n_local)].disabled ^= 1;
        return 1;
    case E_LOCAL_COUNT:
        if (l->n_local < 4 && (l->n_local == 0 || pick(2)))
            local_random(&l->local[l->n_local++], w->n);
        else
            --l->n_local;
        return 1;
    case E_ALBEDO:
        l->albedo = uni(0.1, 1.0);
        return 1;
    case E_QUALITY:
        switch (pick(9)) {
        case 0: w->q.subsample = 1 << pick(3); break;
        case 1: w->q.k = 2 + 2 * pick(2); break;
        case 2: w->q.nphi_env = 8 << pick(2); break;
        case 3: w->q.nphi_key = 2 + pick(3); break;
        case 4: w->q.offset = 1 + pick(3); break;
        case 5:
            w->q.precision = pick(2) ? HFS_PRECISION_FP32 : HFS_PRECISION_FP16;
            break;
        case 6:
            w->q.visibility = pick(2) ? HFS_VIS_WEDGE_TABLE : HFS_VIS_LEGENDRE;
            break;
        case 7: w->timing = pick(3); break; /* level 2 overwrites the grids with counts */
        default: w->q.local_full_swath = pick(2); break;
        }
        return 1;
    default:
        return 1;
    }
}

static hfs_renderer *make_renderer(void)
{
    return gl_test_gles();
}

int main(int argc, char **argv)
{
    const int edits = argc > 1 ? atoi(argv[1]) : 2000;
    rng_state = 0x9e3779b97f4a7c15ull ^ (uint64_t)(argc > 2 ? strtoull(argv[2], NULL, 10) : 1);
    const int n = argc > 3 ? atoi(argv[3]) : 24;
    if (edits < 1 || n < 4 || n > 512) {
        fprintf(stderr, "usage: test_plan_equal [EDITS >= 1] [SEED] [SIZE 4..512]\n");
        return 2;
    }
    world w;
    memset(&w, 0, sizeof w);
    w.n = n;
    w.z = malloc((size_t)n * n * sizeof *w.z);
    if (!w.z)
        return 1;
    hfs_terrain_cones(w.z, n, n);
    w.f = (hfs_field){.width = n, .height = n, .z = w.z, .dx = 1.0, .zscale = 1.0};
    hfs_lighting_defaults(&w.l);
    w.l.has_env = 1;
    w.l.albedo = 0.8;
    for (int c = 0; c < 3; ++c) {
        w.l.env_sh[c][0] = 1.0 + 0.1 * c;
        w.l.env_sh[c][2] = 0.5; /* brighter to +z */
        w.l.env_sh[c][3] = 0.2; /* and to +x */
    }
    key_random(&w.l.key[w.l.n_key++]);
    local_random(&w.l.local[w.l.n_local++], n);
    hfs_quality_defaults(&w.q);

    hfs_renderer *planned = make_renderer(), *fresh = make_renderer();
    hfs_image a = {0}, b = {0};
    hfs_error err;
    if (hfs_image_alloc(&a, n, n, &err) || hfs_image_alloc(&b, n, n, &err))
        return 1;
    int counts[E_KINDS] = {0}, failed = 0, done = 0;
    for (int e = 0; e <= edits && !failed; ++e) {
        int kind = E_NONE;
        if (e > 0)
            do
                kind = pick(E_KINDS);
            while (!apply_edit(&w, kind));
        ++counts[kind];
        hfs_renderer_invalidate(fresh);
        hfs_renderer_set_timing(planned, w.timing);
        const int ra = hfs_renderer_render(planned, &w.f, &w.l, &w.q, &a, NULL, NULL, &err);
        if (ra) {
            printf("FAIL: edit %d (%s): planned render: %s\n", e, kind_names[kind], err.msg);
            failed = 1;
            break;
        }
        if (hfs_renderer_render(fresh, &w.f, &w.l, &w.q, &b, NULL, NULL, &err)) {
            printf("FAIL: edit %d (%s): fresh render: %s\n", e, kind_names[kind], err.msg);
            failed = 1;
            break;
        }
        for (size_t i = 0; i < (size_t)n * n * 3; ++i)
            if (memcmp(&a.rgb[i], &b.rgb[i], sizeof(float)) != 0) {
                printf("FAIL: edit %d (%s): texel (%zu, %zu) channel %zu: planned %.9g, "
                       "from scratch %.9g\n", e, kind_names[kind], i / 3 % n, i / 3 / n, i % 3,
                       a.rgb[i], b.rgb[i]);
                failed = 1;
                break;
            }
        ++done;
    }
    printf("%d frames after random edits (%dx%d):", done, n, n);
    for (int k = 0; k < E_KINDS; ++k)
        printf(" %s %d%s", kind_names[k], counts[k], k + 1 < E_KINDS ? "," : "\n");
    printf("planned == from scratch, bit for bit: %s\n", failed ? "NO" : "yes");
    hfs_image_free(&a);
    hfs_image_free(&b);
    hfs_renderer_destroy(planned);
    hfs_renderer_destroy(fresh);
    free(w.z);
    return failed ? 1 : 0;
}
