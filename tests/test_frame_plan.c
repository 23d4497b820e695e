/*
 * test_frame_plan.c — the frame planner's decisions (runtime/core/frame_plan.h)
 * on a small graph shaped like the GLES renderer's: heights -> terrain ->
 * env visibility -> transfer; terrain + key geometry -> key horizons -> key
 * factor; compose reads the transfer, the env coefficients, the key factor
 * and radiance.  Each edit must run exactly the passes that depend on it,
 * with the edit named as the reason; nothing changed runs nothing.
 */
#include "frame_plan.h"

#include <stdio.h>
#include <string.h>

#include "check.h"

enum { TERRAIN, ENV, TRANSFER, KEY, KEYF, COMPOSE, NPASS };

typedef struct graph {
    hfs_plan p;
    int H, E, K, KR, T, V, X, KH, KF, O;
    hfs_plan_step steps[HFS_PLAN_MAX_PASSES];
} graph;

static void build(graph *g)
{
    hfs_plan *p = &g->p;
    hfs_plan_init(p);
    g->H = hfs_plan_input(p, "heights");
    g->E = hfs_plan_input(p, "env");
    g->K = hfs_plan_input(p, "key0 geometry");
    g->KR = hfs_plan_input(p, "key0 radiance");
    g->T = hfs_plan_product(p, "terrain");
    g->V = hfs_plan_product(p, "env visibility");
    g->X = hfs_plan_product(p, "transfer");
    g->KH = hfs_plan_product(p, "key0 horizons");
    g->KF = hfs_plan_product(p, "key0 factor");
    g->O = hfs_plan_product(p, "output");
    hfs_plan_pass_add(p, "terrain", (int[]){g->H, -1}, (int[]){g->T, -1});
    hfs_plan_pass_add(p, "env", (int[]){g->T, -1}, (int[]){g->V, -1});
    hfs_plan_pass_add(p, "transfer", (int[]){g->V, g->T, -1}, (int[]){g->X, -1});
    hfs_plan_pass_add(p, "key", (int[]){g->T, g->K, -1}, (int[]){g->KH, -1});
    hfs_plan_pass_add(p, "keyf", (int[]){g->KH, g->K, g->T, -1}, (int[]){g->KF, -1});
    hfs_plan_pass_add(p, "compose", (int[]){g->X, g->E, g->KF, g->KR, -1}, (int[]){g->O, -1});
}

/* Plans and "runs" a frame (amortized with a budget > 0, *deferred set);
 * returns the passes run as a bit mask. */
static unsigned frame_budget(graph *g, int budget, int *deferred)
{
    hfs_plan_set need = {{0}};
    hfs_plan_set_add(&need, g->O);
    if (budget > 0)
        hfs_plan_frame_amortized(&g->p, &need, budget, g->steps, deferred);
    else
        hfs_plan_frame(&g->p, &need, g->steps);
    unsigned mask = 0;
    for (int i = 0; i < g->p.n_passes; ++i)
        if (g->steps[i].run) {
            mask |= 1u << i;
            hfs_plan_done(&g->p, i);
        }
    return mask;
}

static unsigned frame(graph *g)
{
    return frame_budget(g, 0, NULL);
}

#define B(x) (1u << (x))

int main(void)
{
    graph g;
    build(&g);
    unsigned m = frame(&g);
    CHECK(m == (B(NPASS) - 1), "first frame runs everything: %x", m);
    CHECK(strstr(g.steps[TERRAIN].reason, "not computed"), "reason: %s", g.steps[TERRAIN].reason);
    CHECK(frame(&g) == 0, "nothing changed: nothing runs");
    CHECK(!strcmp(g.steps[COMPOSE].reason, "cached: nothing it reads changed"), "%s",
          g.steps[COMPOSE].reason);

    hfs_plan_change(&g.p, g.E, "env rotated");
    m = frame(&g);
    CHECK(m == B(COMPOSE), "env edit: compose only (%x)", m);
    CHECK(!strcmp(g.steps[COMPOSE].reason, "env rotated"), "%s", g.steps[COMPOSE].reason);

    hfs_plan_change(&g.p, g.KR, "key0 radiance changed");
    CHECK(frame(&g) == B(COMPOSE), "radiance: compose only");

    hfs_plan_change(&g.p, g.K, "key0 left its swath");
    m = frame(&g);
    CHECK(m == (B(KEY) | B(KEYF) | B(COMPOSE)), "key moved: key, keyf, compose (%x)", m);
    CHECK(!strcmp(g.steps[KEYF].reason, "key0 left its swath"), "%s", g.steps[KEYF].reason);

    hfs_plan_change(&g.p, g.H, "heights changed");
    hfs_plan_change(&g.p, g.E, "env rotated");
    m = frame(&g);
    CHECK(m == (B(NPASS) - 1), "heights: everything (%x)", m);
    CHECK(!strcmp(g.steps[ENV].reason, "heights changed"), "env reason: %s", g.steps[ENV].reason);

    /* No key light: compose stops reading the key factor; key passes are
     * not needed, and a key edit meanwhile costs nothing... */
    hfs_plan_pass_reads(&g.p, COMPOSE, (int[]){g.X, g.E, -1});
    hfs_plan_change(&g.p, g.K, "key0 moved");
    m = frame(&g);
    CHECK(m == 0, "key absent: key edit runs nothing (%x)", m);
    CHECK(!strcmp(g.steps[KEY].reason, "not needed"), "%s", g.steps[KEY].reason);
    /* ... but the key's products went stale: when it comes back they run. */
    hfs_plan_pass_reads(&g.p, COMPOSE, (int[]){g.X, g.E, g.KF, g.KR, -1});
    m = frame(&g);
    CHECK(m == (B(KEY) | B(KEYF) | B(COMPOSE)), "key back: key, keyf, compose (%x)", m);

    /* Amortization, one deferrable pass a frame (env and key): an edit of
     * both runs one, defers the other (whose readers wait for it), then
     * runs the other the next frame; nothing waits after that. */
    hfs_plan_set_deferrable(&g.p, ENV, 1);
    hfs_plan_set_deferrable(&g.p, KEY, 1);
    int waiting = -1;
    hfs_plan_change(&g.p, g.H, "heights changed");
    m = frame_budget(&g, 1, &waiting);
    /* (the key factor reads the heights too: it runs, on the old horizons) */
    CHECK(waiting == 1 && m == (B(TERRAIN) | B(ENV) | B(TRANSFER) | B(KEYF) | B(COMPOSE)),
          "amortized: env runs, key waits (%x, %d waiting)", m, waiting);
    CHECK(strstr(g.steps[KEY].reason, "deferred"), "key reason: %s", g.steps[KEY].reason);
    m = frame_budget(&g, 1, &waiting);
    CHECK(waiting == 0 && m == (B(KEY) | B(KEYF) | B(COMPOSE)),
          "amortized, next frame: the key and its readers (%x, %d waiting)", m, waiting);
    CHECK(frame_budget(&g, 1, &waiting) == 0 && waiting == 0, "amortized: then nothing");
    /* A pass whose product holds nothing cannot wait. */
    hfs_plan_drop(&g.p, g.KH);
    hfs_plan_change(&g.p, g.H, "heights changed");
    m = frame_budget(&g, 1, &waiting);
    CHECK(waiting == 0 && m == (B(NPASS) - 1), "empty product: no deferral (%x)", m);

    hfs_plan_drop_all(&g.p);
    CHECK(frame(&g) == (B(NPASS) - 1), "after drop_all: everything");
    printf("frame plan: %s\n", failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
