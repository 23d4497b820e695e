/*
 * test_plan_cases.c — the frame planner's decisions on the cases issue 6
 * names, through the public report (hfs_renderer_frame_report): which
 * passes ran after each edit.
 *   - nothing changed: no pass at all (the image handed out again);
 *   - environment rotated or re-tinted, a light's radiance, the albedo:
 *     shading and readback only (from the sky's second change: the first
 *     makes the renderer keep the transfer);
 *   - a key light moved: its own key pass, shading; the other key's pass
 *     and the environment are kept;
 *   - a key light moved within the swath already sampled: its horizons are
 *     kept, only its factor and the shading run;
 *   - a local light moved: its own local pass, shading (the other local
 *     light's ratios are kept);
 *   - a local light beyond the terrain's shadow range: no local pass;
 *   - a light switched off (or given radiance 0): no pass for it;
 *   - heights changed: everything.
 * Each planned image also equals a from-scratch one (test_plan_equal does
 * that at random).  No GLES context of any kind: exit 77 (gl_test.h).
 */
#include "visibility.h"
#include "hfshade.h"
#include "terrain_gen.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "gl_test.h"
#include "plan_scene.h"

#define N 32

static hfs_renderer *planned, *fresh;
static hfs_image a, b;

static int ran(const hfs_frame_report *r, const char *pass)
{
    for (int i = 0; i < r->n_steps; ++i)
        if (!strcmp(r->step[i].pass, pass))
            return r->step[i].ran;
    return 0;
}

/* Renders, checks against a from-scratch frame, and returns the set of
 * passes that ran as "name name ...". */
static const char *frame(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                         hfs_frame_report *rep)
{
    static char list[512];
    hfs_error err;
    if (hfs_renderer_render(planned, f, l, q, &a, NULL, NULL, &err)) {
        CHECK(0, "render: %s", err.msg);
        return "";
    }
    hfs_renderer_frame_report(planned, rep);
    hfs_renderer_invalidate(fresh);
    if (hfs_renderer_render(fresh, f, l, q, &b, NULL, NULL, &err) == 0)
        CHECK(!memcmp(a.rgb, b.rgb, (size_t)N * N * 3 * sizeof(float)),
              "planned image differs from scratch");
    else
        CHECK(0, "render from scratch: %s", err.msg);
    list[0] = '\0';
    for (int i = 0; i < rep->n_steps; ++i)
        if (rep->step[i].ran) {
            strncat(list, rep->step[i].pass, sizeof list - strlen(list) - 2);
            strcat(list, " ");
        }
    return list;
}

/* Two azimuths of key light k, found by stepping it forward: at the first
 * its swath has n samples, at the second n + 1 with the same origin and
 * spacing (the disk's far edge crossed into the next lattice wedge).  The
 * planner must see the added sample: the horizons of a swath that grew are
 * not the kept ones.  1 when found within two lattice spacings. */
static int swath_growth(const hfs_key_light *k, const hfs_quality *q, double *phi_a,
                        double *phi_b)
{
    hfs_swath prev, s;
    hfs_swath_key(k->phi, k->elev, k->alpha, q->nphi_key, q->nphi_env, &prev);
    const double step = prev.dphi / 512.0;
    for (int i = 1; i <= 1024; ++i) {
        const double phi = k->phi + i * step;
        hfs_swath_key(phi, k->elev, k->alpha, q->nphi_key, q->nphi_env, &s);
        if (s.phi0 == prev.phi0 && s.dphi == prev.dphi && s.n == prev.n + 1 && !s.full) {
            *phi_a = phi - step;
            *phi_b = phi;
            return 1;
        }
        prev = s;
    }
    return 0;
}

#define EXPECT(what, want)                                                                     \
    do {                                                                                       \
        hfs_frame_report rep;                                                                  \
        const char *got = frame(&f, &l, &q, &rep);                                             \
        printf("%-28s ran: %s\n", what, *got ? got : "(nothing)");                           \
        CHECK(!strcmp(got, want), "%s: ran '%s', want '%s'", what, got, want);                 \
    } while (0)

int main(void)
{
    hfs_error err;
    planned = gl_test_gles();
    fresh = gl_test_gles();
    float z[N * N];
    hfs_terrain_cones(z, N, N);
    hfs_field f = {.width = N, .height = N, .z = z, .dx = 1.0, .zscale = 1.0};
    hfs_lighting l;
    plan_scene_lighting(&l, N, 0);
    hfs_quality q;
    hfs_quality_defaults(&q);
    if (hfs_image_alloc(&a, N, N, &err) || hfs_image_alloc(&b, N, N, &err))
        return 1;

    EXPECT("first frame",
           "terrain env key 0 key 1 local 0 local 1 sky occlusion key 0 factor key 1 factor "
           "shade readback ");
    EXPECT("nothing changed", "");
    /* The sky's first change makes the renderer keep the transfer (the
     * sky occlusion depends on the sky): test_gles_sky_occlusion.c.  The
     * grid's horizons the transfer reads were freed after the frames
     * before (gles_frame.c grid_release): made anew by the env pass.  From
     * then on the renderer keeps both: the next changes cost the shading. */
    l.env_rotate = 0.7;
    EXPECT("environment rotated", "env transfer shade readback ");
    for (int c = 0; c < 3; ++c)
        l.env_sh[c][0] *= 1.1;
    EXPECT("environment re-tinted", "shade readback ");
    l.key[1].radiance[0] = 14;
    EXPECT("key radiance", "shade readback ");
    l.local[0].radiance[2] = 12;
    EXPECT("local radiance", "shade readback ");
    l.albedo = 0.5;
    EXPECT("albedo", "shade readback ");
    l.key[0].phi += 0.3;
    EXPECT("key 0 moved", "key 0 key 0 factor shade readback ");
    l.key[0].phi += 0.002; /* inside its sampled swath (lattice 2 pi / 256) */
    EXPECT("key 0 nudged in its swath", "key 0 factor shade readback ");
    l.key[0].elev += 0.002;
    EXPECT("key 0 a little higher", "key 0 factor shade readback ");
    double phi_a = 0.0, phi_b = 0.0;
    CHECK(swath_growth(&l.key[0], &q, &phi_a, &phi_b), "no swath growth found");
    /* The edge may lie in the swath the light has now, or past a change
     * of it on the way (which set of samples depends on nphi_key). */
    hfs_swath now, edge;
    hfs_swath_key(l.key[0].phi, l.key[0].elev, l.key[0].alpha, q.nphi_key, q.nphi_env, &now);
    hfs_swath_key(phi_a, l.key[0].elev, l.key[0].alpha, q.nphi_key, q.nphi_env, &edge);
    const int same = now.phi0 == edge.phi0 && now.dphi == edge.dphi && now.n == edge.n &&
                     now.full == edge.full;
    l.key[0].phi = phi_a;
    EXPECT("key 0 to a swath's edge",
           same ? "key 0 factor shade readback " : "key 0 key 0 factor shade readback ");
    l.key[0].phi = phi_b;
    EXPECT("key 0 swath one sample more", "key 0 key 0 factor shade readback ");
    l.local[0].pos[0] = 12;
    EXPECT("local 0 moved", "local 0 shade readback ");
    l.local[1].pos[2] = 400; /* far above: the terrain cannot shadow it */
    EXPECT("local 1 out of shadow range", "shade readback ");
    l.local[1].pos[2] = 6;
    EXPECT("local 1 back down", "local 1 shade readback ");
    l.key[1].disabled = 1;
    l.local[0].radiance[0] = l.local[0].radiance[1] = l.local[0].radiance[2] = 0;
    /* local 1 is now the only local light, in slot 0: its ratios move */
    EXPECT("key 1 off, local 0 dark", "local 0 shade readback ");
    l.key[0].phi += 0.2; /* key 0 is now the only key: its pass runs, no other */
    EXPECT("key 0 moved again", "key 0 key 0 factor shade readback ");
    z[5 * N + 7] += 1.0f;
    EXPECT("heights changed",
           "terrain env key 0 local 0 transfer key 0 factor shade readback ");
    EXPECT("nothing changed again", "");

    hfs_frame_report rep;
    hfs_renderer_frame_report(planned, &rep);
    CHECK(rep.n_ran == 0 && rep.n_steps > 0 && !ran(&rep, "shade") &&
              strstr(rep.step[rep.n_steps - 1].reason, "cached"),
          "report of a frame without work");
    hfs_image_free(&a);
    hfs_image_free(&b);
    hfs_renderer_destroy(planned);
    hfs_renderer_destroy(fresh);
    printf("plan cases: %s\n", failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
