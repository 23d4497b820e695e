/*
 * test_gles_plan_diff.c — the GLES frame plan's input diff, without a GL
 * context (runtime/gles/plan.h): every field of the frame signature, changed
 * alone after a frame whose passes all ran, must run exactly the passes that
 * read it (and what reads their products), and nothing else.
 *
 * The key-light swath is compared field by field, sample count included: a
 * swath that grows by one sample at the same origin and spacing (the disk's
 * far edge crossing into the next lattice wedge, or a small elevation change
 * widening it) has horizons the kept ones lack, so its key pass must run
 * (issue 12: the planner must see it; the end-to-end case is in
 * test_plan_cases).
 */
#include "plan.h"

#include <stdio.h>
#include <string.h>

#include "check.h"

/* A signature with an environment, two key lights and two local lights. */
static hfs_gles_frame_sig base_sig(void)
{
    hfs_gles_frame_sig s;
    memset(&s, 0, sizeof s);
    s.sub = 2, s.vw = 17, s.vh = 17;
    s.has_env = 1, s.nphi_env = 16, s.vis_path = 0, s.hz_refine = 4;
    s.l_env[0][0] = s.l_env[1][0] = s.l_env[2][0] = 1.0;
    s.rho_pi = 1.0 / 3.14159;
    s.n_keys = 2;
    for (int i = 0; i < 2; ++i) {
        s.key[i].swath = (hfs_swath){.n = 3, .full = 0, .phi0 = 0.49 + i, .dphi = 0.0327,
                                     .elev_lo = 0.36, .elev_hi = 0.44};
        s.key[i].hz_layer = 2 * i;
        s.key[i].dir[0] = 0.9, s.key[i].dir[2] = 0.4;
        s.key[i].alpha = 0.04;
        s.key[i].le[0] = s.key[i].le[1] = s.key[i].le[2] = 20.0;
    }
    s.n_local = 2, s.nphi_local = 8;
    for (int i = 0; i < 2; ++i) {
        s.local[i].pos[0] = 4.0 + i, s.local[i].pos[2] = 5.0;
        s.local[i].radius = 1.0;
        s.local[i].le[0] = 30.0f;
    }
    return s;
}

/* Plans now after a frame of base: the passes that run, as "name name ". */
static const char *ran_after(const hfs_gles_frame_sig *now)
{
    static char list[512];
    static hfs_gles_plan gp;
    hfs_error err;
    CHECK(hfs_gles_plan_init(&gp, &err) == HFS_OK, "plan init: %s", err.msg);
    const hfs_gles_frame_sig base = base_sig();
    hfs_gles_plan_frame(&gp, &base, "first frame");
    for (int k = 0; k < HFS_PASS_COUNT; ++k)
        for (int i = 0; i < HFS_GLES_PLAN_INSTANCES; ++i)
            if (gp.run[k][i])
                hfs_gles_plan_done(&gp, (hfs_gles_pass_id)k, i);
    hfs_gles_plan_frame(&gp, now, NULL);
    list[0] = '\0';
    for (int k = 0; k < HFS_PASS_COUNT; ++k)
        for (int i = 0; i < HFS_GLES_PLAN_INSTANCES; ++i)
            if (gp.run[k][i]) {
                strncat(list, gp.p.pass[gp.pass[k][i]].name, sizeof list - strlen(list) - 2);
                strcat(list, " ");
            }
    return list;
}

#define EXPECT(what, edit, want)                                                       \
    do {                                                                               \
        hfs_gles_frame_sig s = base_sig();                                             \
        edit;                                                                          \
        const char *got = ran_after(&s);                                               \
        printf("%-34s ran: %s\n", what, *got ? got : "(nothing)");                   \
        CHECK(!strcmp(got, want), "%s: ran '%s', want '%s'", what, got, want);         \
    } while (0)

int main(void)
{
    const char *key0 = "key 0 key 0 factor shade readback ";
    const char *key0_factor = "key 0 factor shade readback ";
    const char *shade = "shade readback ";
    EXPECT("nothing changed", (void)0, "");
    /* The swath, field by field. */
    EXPECT("key 0 swath: one sample more", s.key[0].swath.n++, key0);
    EXPECT("key 0 swath: one sample less", s.key[0].swath.n--, key0);
    EXPECT("key 0 swath: origin", s.key[0].swath.phi0 += s.key[0].swath.dphi, key0);
    EXPECT("key 0 swath: spacing", s.key[0].swath.dphi *= 1.25, key0);
    EXPECT("key 0 swath: full", s.key[0].swath.full = 1, key0);
    EXPECT("key 0 horizon layer", s.key[0].hz_layer = 4, key0);
    EXPECT("key 1 swath: one sample more", s.key[1].swath.n++,
           "key 1 key 1 factor shade readback ");
    /* What only the factor reads. */
    EXPECT("key 0 window low edge", s.key[0].swath.elev_lo += 0.01, key0_factor);
    EXPECT("key 0 window high edge", s.key[0].swath.elev_hi -= 0.01, key0_factor);
    EXPECT("key 0 direction", s.key[0].dir[1] = 0.01, key0_factor);
    EXPECT("key 0 size", s.key[0].alpha = 0.05, key0_factor);
    /* What only the shading reads. */
    EXPECT("key 0 radiance", s.key[0].le[1] = 5.0, shade);
    EXPECT("environment light", s.l_env[2][3] = 0.5, shade);
    EXPECT("albedo", s.rho_pi = 0.2, shade);
    EXPECT("albedo map given", (s.albedo_map = 1, s.albedo_gen = 1), shade);
    EXPECT("albedo map contents", s.albedo_gen = 7, shade);
    EXPECT("local radiance", s.local[1].le[2] = 3.0f, shade);
    /* Local lights, the environment's settings, the grid. */
    EXPECT("local 1 moved", s.local[1].pos[1] = 2.0, "local 1 shade readback ");
    EXPECT("local 0 resized", s.local[0].radius = 2.0, "local 0 shade readback ");
    EXPECT("local 0 out of shadow range", s.local[0].open = 1, shade);
    EXPECT("local settings", s.nphi_local = 16, "local 0 local 1 shade readback ");
    EXPECT("environment azimuths", s.nphi_env = 32, "env transfer shade readback ");
    /* refine: every env and key horizon's samples between scales (the
     * key factor reads the horizons; local lights have none). */
    EXPECT("horizon refinement", s.hz_refine = 1,
           "env key 0 key 1 transfer key 0 factor key 1 factor shade readback ");
    EXPECT("visibility path", s.vis_path = 1,
           "env key 0 key 1 local 0 local 1 transfer key 0 factor key 1 factor shade readback ");
    EXPECT("subsample", (s.sub = 1, s.vw = s.vh = 33),
           "env key 0 key 1 local 0 local 1 transfer key 0 factor key 1 factor shade readback ");
    EXPECT("key 1 removed", s.n_keys = 1, shade);
    printf("gles plan diff: %s\n", failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
