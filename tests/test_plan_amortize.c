/*
 * test_plan_amortize.c — amortization (NS09 section 7,
 * hfs_renderer_set_amortize): with a budget of one visibility pass a frame,
 * a seeded random sequence of light edits over a still terrain (environment
 * rotated, key lights moved, local lights moved, added, switched), and
 * after each edit frames are rendered with no further edit until the report
 * says nothing waits.  Checked after every edit:
 *   - no frame runs more than one visibility pass (env, key i, local i);
 *   - the frames converge within K frames, K the visibility passes stale
 *     (at most 1 + keys + local lights here), i.e. the latency is bounded;
 *   - the converged image equals a from-scratch frame bit for bit;
 *   - a change of heights runs everything in its own frame (nothing waits).
 *   test_plan_amortize [EDITS] [SEED]      (defaults 300 1)
 * No GLES context of any kind: exit 77 (gl_test.h).
 */
#include "hfshade.h"
#include "terrain_gen.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "gl_test.h"
#include "plan_scene.h"

#define N 24

static unsigned seed = 1;

static double uni(double a, double b)
{
    seed = seed * 1664525u + 1013904223u;
    return a + (b - a) * ((seed >> 8) * (1.0 / 16777216.0));
}

/* Visibility passes the last frame ran. */
static int visibility_runs(const hfs_frame_report *r)
{
    int n = 0;
    for (int i = 0; i < r->n_steps; ++i) {
        const char *p = r->step[i].pass;
        const int key = !strncmp(p, "key ", 4) && !strstr(p, "factor");
        n += r->step[i].ran && (!strcmp(p, "env") || key || !strncmp(p, "local ", 6));
    }
    return n;
}

int main(int argc, char **argv)
{
    const int edits = argc > 1 ? atoi(argv[1]) : 300;
    seed = argc > 2 ? (unsigned)atoi(argv[2]) : 1u;
    hfs_error err;
    hfs_renderer *am = gl_test_gles(), *fresh = gl_test_gles();
    CHECK(hfs_renderer_set_amortize(am, -1) == HFS_E_INVALID, "negative budget accepted");
    hfs_renderer_set_amortize(am, 1);
    float z[N * N];
    hfs_terrain_cones(z, N, N);
    hfs_field f = {.width = N, .height = N, .z = z, .dx = 1.0, .zscale = 1.0};
    hfs_lighting l;
    plan_scene_lighting(&l, N, 1);
    hfs_quality q;
    hfs_quality_defaults(&q);
    hfs_image a = {0}, b = {0};
    if (hfs_image_alloc(&a, N, N, &err) || hfs_image_alloc(&b, N, N, &err))
        return 1;
    int worst_frames = 0, waited_total = 0, height_edits = 0;
    for (int e = 0; e <= edits && !failures; ++e) {
        const int kind = e == 0 ? -1 : (int)uni(0, 6);
        switch (kind) {
        case 0: l.env_rotate = uni(0, 6.28); break;
        case 1: {
            hfs_key_light *k = &l.key[(int)uni(0, 2)];
            k->phi = uni(0, 6.28);
            k->elev = uni(0.1, 1.2);
            break;
        }
        case 2: { /* several lights at once: several passes wait */
            l.key[0].phi += uni(-1, 1);
            l.key[1].phi += uni(-1, 1);
            l.local[0].pos[0] = uni(0, N - 1);
            l.local[1].pos[1] = uni(0, N - 1);
            break;
        }
        case 3: l.local[(int)uni(0, 2)].pos[(int)uni(0, 3)] += uni(-3, 3); break;
        case 4: l.local[(int)uni(0, 2)].radiance[(int)uni(0, 3)] = (float)uni(1, 30); break;
        default:
            z[(int)uni(0, N * N)] += (float)uni(-1, 1);
            ++height_edits;
            break;
        }
        for (int i = 0; i < 2; ++i)
            l.local[i].pos[2] = fmax(l.local[i].pos[2], 0.5);
        /* Frames with no further edit until nothing waits. */
        int frames = 0;
        hfs_frame_report rep;
        do {
            if (hfs_renderer_render(am, &f, &l, &q, &a, NULL, NULL, &err)) {
                CHECK(0, "edit %d: render: %s", e, err.msg);
                break;
            }
            hfs_renderer_frame_report(am, &rep);
            ++frames;
            if (e > 0 && kind != 5 && visibility_runs(&rep) > 1) {
                CHECK(0, "edit %d (kind %d), frame %d: %d visibility passes", e, kind, frames,
                      visibility_runs(&rep));
                for (int i = 0; i < rep.n_steps; ++i)
                    printf("  %-14s %d %s\n", rep.step[i].pass, rep.step[i].ran,
                           rep.step[i].reason);
            }
            if (kind == 5 && frames == 1)
                CHECK(rep.n_deferred == 0, "edit %d: heights changed but %d passes waited", e,
                      rep.n_deferred);
        } while (rep.n_deferred > 0 && frames < 20);
        const int bound = 1 + l.n_key + l.n_local;
        CHECK(frames <= bound, "edit %d (kind %d): %d frames to converge (bound %d)", e, kind,
              frames, bound);
        worst_frames = frames > worst_frames ? frames : worst_frames;
        waited_total += frames - 1;
        hfs_renderer_invalidate(fresh);
        if (hfs_renderer_render(fresh, &f, &l, &q, &b, NULL, NULL, &err) == 0)
            CHECK(!memcmp(a.rgb, b.rgb, (size_t)N * N * 3 * sizeof(float)),
                  "edit %d (kind %d): converged frame differs from scratch", e, kind);
    }
    printf("%d edits (%d of the heights): at most %d frames to converge, %d extra frames in "
           "all; converged == from scratch: %s\n",
           edits, height_edits, worst_frames, waited_total, failures ? "NO" : "yes");
    CHECK(waited_total > 0, "amortization never deferred a pass (the test would prove nothing)");
    hfs_image_free(&a);
    hfs_image_free(&b);
    hfs_renderer_destroy(am);
    hfs_renderer_destroy(fresh);
    return failures ? 1 : 0;
}
