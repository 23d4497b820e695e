/*
 * frame_plan.c — see frame_plan.h.
 */
#include "frame_plan.h"

#include <stdio.h>
#include <string.h>

void hfs_plan_init(hfs_plan *p)
{
    memset(p, 0, sizeof *p);
}

static int node_add(hfs_plan *p, const char *name, int input)
{
    if (p->n_nodes == HFS_PLAN_MAX_NODES)
        return -1;
    const int id = p->n_nodes++;
    snprintf(p->node[id], sizeof p->node[id], "%s", name);
    p->is_input[id] = input;
    return id;
}

int hfs_plan_input(hfs_plan *p, const char *name)
{
    return node_add(p, name, 1);
}

int hfs_plan_product(hfs_plan *p, const char *name)
{
    return node_add(p, name, 0);
}

int hfs_plan_pass_add(hfs_plan *p, const char *name, const int *reads, const int *writes)
{
    if (p->n_passes == HFS_PLAN_MAX_PASSES)
        return -1;
    hfs_plan_pass *ps = &p->pass[p->n_passes];
    memset(ps, 0, sizeof *ps);
    snprintf(ps->name, sizeof ps->name, "%s", name);
    for (const int *r = reads; r && *r >= 0; ++r)
        hfs_plan_set_add(&ps->reads, *r);
    for (const int *w = writes; w && *w >= 0; ++w)
        hfs_plan_set_add(&ps->writes, *w);
    return p->n_passes++;
}

void hfs_plan_pass_reads(hfs_plan *p, int pass, const int *reads)
{
    if (pass < 0 || pass >= p->n_passes)
        return;
    memset(&p->pass[pass].reads, 0, sizeof p->pass[pass].reads);
    for (const int *r = reads; r && *r >= 0; ++r)
        hfs_plan_set_add(&p->pass[pass].reads, *r);
}

void hfs_plan_change(hfs_plan *p, int node, const char *reason)
{
    if (node < 0 || node >= p->n_nodes)
        return;
    if (!hfs_plan_set_has(&p->changed, node))
        snprintf(p->why[node], sizeof p->why[node], "%s", reason ? reason : p->node[node]);
    hfs_plan_set_add(&p->changed, node);
}

void hfs_plan_drop_all(hfs_plan *p)
{
    memset(&p->valid, 0, sizeof p->valid);
    memset(&p->filled, 0, sizeof p->filled);
}

void hfs_plan_drop(hfs_plan *p, int product)
{
    if (product >= 0 && product < p->n_nodes) {
        p->valid.w[product / 64] &= ~((uint64_t)1 << (product % 64));
        p->filled.w[product / 64] &= ~((uint64_t)1 << (product % 64));
    }
}

void hfs_plan_set_deferrable(hfs_plan *p, int pass, int yes)
{
    if (pass >= 0 && pass < p->n_passes)
        p->deferrable[pass] = yes != 0;
}

static int first_common(const hfs_plan *p, const hfs_plan_set *a, const hfs_plan_set *b)
{
    for (int n = 0; n < p->n_nodes; ++n)
        if (hfs_plan_set_has(a, n) && hfs_plan_set_has(b, n))
            return n;
    return -1;
}

/* The planner proper; passes with defer[i] set are skipped as "deferred":
 * their products keep their old contents, are not new for their readers
 * this frame, and stay invalid (so they run in a later frame). */
static int plan_frame(hfs_plan *p, const hfs_plan_set *needed, hfs_plan_step *steps,
                      const int *defer)
{
    /* Needed: backwards from what the output needs. */
    hfs_plan_set need = *needed;
    for (int i = p->n_passes - 1; i >= 0; --i)
        if (first_common(p, &p->pass[i].writes, &need) >= 0)
            for (int k = 0; k < HFS_PLAN_MAX_NODES / 64; ++k)
                need.w[k] |= p->pass[i].reads.w[k];

    /* Forward, in pass order: a pass that reads something dirty makes what
     * it writes dirty (needed or not); a needed pass runs when what it
     * writes is dirty or not valid, and then its products are new, so what
     * reads them is dirty too.  dirty_by: the node whose reason is told. */
    hfs_plan_set dirty = p->changed;
    int dirty_by[HFS_PLAN_MAX_NODES];
    for (int n = 0; n < p->n_nodes; ++n)
        dirty_by[n] = hfs_plan_set_has(&p->changed, n) ? n : -1;
    int runs = 0;
    for (int i = 0; i < p->n_passes; ++i) {
        hfs_plan_step *s = &steps[i];
        const hfs_plan_pass *ps = &p->pass[i];
        s->pass = i;
        s->run = 0;
        const int cause = first_common(p, &ps->reads, &dirty);
        int wanted = -1, stale = -1, missing = -1;
        for (int n = 0; n < p->n_nodes; ++n) {
            if (!hfs_plan_set_has(&ps->writes, n))
                continue;
            if (cause >= 0 && dirty_by[n] < 0) {
                hfs_plan_set_add(&dirty, n);
                dirty_by[n] = dirty_by[cause];
            }
            if (!hfs_plan_set_has(&need, n))
                continue;
            if (wanted < 0)
                wanted = n;
            if (stale < 0 && hfs_plan_set_has(&dirty, n))
                stale = n;
            if (missing < 0 && !hfs_plan_set_has(&p->valid, n))
                missing = n;
        }
        if (wanted < 0) {
            snprintf(s->reason, sizeof s->reason, "not needed");
            continue;
        }
        if (stale >= 0) {
            snprintf(s->reason, sizeof s->reason, "%s", p->why[dirty_by[stale]]);
        } else if (missing >= 0) {
            char why[HFS_PLAN_REASON];
            snprintf(why, sizeof why, "%s not computed yet", p->node[missing]);
            memcpy(p->why[missing], why, sizeof why);
            memcpy(s->reason, why, sizeof why);
            for (int n = 0; n < p->n_nodes; ++n) /* what reads it must follow */
                if (hfs_plan_set_has(&ps->writes, n) && dirty_by[n] < 0) {
                    hfs_plan_set_add(&dirty, n);
                    dirty_by[n] = missing;
                }
        } else {
            snprintf(s->reason, sizeof s->reason, "cached: nothing it reads changed");
            continue;
        }
        if (defer && defer[i]) {
            snprintf(s->reason, sizeof s->reason, "deferred (amortized): waited %d frame%s",
                     p->waited[i] + 1, p->waited[i] ? "s" : "");
            for (int n = 0; n < p->n_nodes; ++n)
                if (hfs_plan_set_has(&ps->writes, n)) {
                    /* Old contents, invalid: not new to readers now, rerun later. */
                    dirty.w[n / 64] &= ~((uint64_t)1 << (n % 64));
                    p->valid.w[n / 64] &= ~((uint64_t)1 << (n % 64));
                }
            continue;
        }
        s->run = 1;
        ++runs;
    }
    /* Every dirty product is invalid until a pass writing it is done: the
     * ones not recomputed this frame (not needed) stay invalid for later. */
    for (int n = 0; n < p->n_nodes; ++n)
        if (!p->is_input[n] && hfs_plan_set_has(&dirty, n))
            p->valid.w[n / 64] &= ~((uint64_t)1 << (n % 64));
    memset(&p->changed, 0, sizeof p->changed);
    return runs;
}

int hfs_plan_frame(hfs_plan *p, const hfs_plan_set *needed, hfs_plan_step *steps)
{
    return plan_frame(p, needed, steps, NULL);
}

int hfs_plan_frame_amortized(hfs_plan *p, const hfs_plan_set *needed, int budget,
                             hfs_plan_step *steps, int *deferred)
{
    /* Which deferrable passes would run, on a copy (planning changes p). */
    static const int none[HFS_PLAN_MAX_PASSES];
    hfs_plan dry = *p;
    plan_frame(&dry, needed, steps, NULL);
    int cand[HFS_PLAN_MAX_PASSES], n_cand = 0;
    for (int i = 0; i < p->n_passes; ++i) {
        if (!steps[i].run || !p->deferrable[i])
            continue;
        int filled = 1; /* a pass whose products hold nothing cannot wait */
        for (int k = 0; k < HFS_PLAN_MAX_NODES / 64; ++k)
            filled &= (p->pass[i].writes.w[k] & ~p->filled.w[k]) == 0;
        if (filled)
            cand[n_cand++] = i;
    }
    int defer[HFS_PLAN_MAX_PASSES];
    memcpy(defer, none, sizeof defer);
    /* Keep the budget's worth that waited longest (ties: pass order). */
    for (int c = 0; c < n_cand; ++c)
        defer[cand[c]] = 1;
    for (int kept = 0; kept < budget && kept < n_cand; ++kept) {
        int best = -1;
        for (int c = 0; c < n_cand; ++c)
            if (defer[cand[c]] && (best < 0 || p->waited[cand[c]] > p->waited[best]))
                best = cand[c];
        defer[best] = 0;
    }
    const int runs = plan_frame(p, needed, steps, defer);
    int waiting = 0;
    for (int i = 0; i < p->n_passes; ++i) {
        if (defer[i]) {
            ++p->waited[i];
            ++waiting;
        } else if (steps[i].run) {
            p->waited[i] = 0;
        }
    }
    if (deferred)
        *deferred = waiting;
    return runs;
}

void hfs_plan_done(hfs_plan *p, int pass)
{
    if (pass < 0 || pass >= p->n_passes)
        return;
    for (int k = 0; k < HFS_PLAN_MAX_NODES / 64; ++k) {
        p->valid.w[k] |= p->pass[pass].writes.w[k];
        p->filled.w[k] |= p->pass[pass].writes.w[k];
    }
}
