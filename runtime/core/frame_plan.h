/*
 * frame_plan.h — the frame planner (issue 6): which passes a frame must run,
 * and why each one runs or is skipped.
 *
 * A renderer describes its frame once, as a graph of NODES and PASSES:
 *   - input nodes: what a caller can edit (the heights, groups of settings,
 *     each light's geometry and its radiance, the albedo, ...);
 *   - product nodes: what passes write (the pyramid, visibility grids, the
 *     per-texel transfer, per-light factors, the output);
 *   - passes, in an order where every pass comes after the passes writing
 *     what it reads, each reading nodes and writing products.
 * Each frame the renderer says which inputs CHANGED since the last frame
 * (with a reason, e.g. "key 1 left its swath"), and which products it
 * NEEDS (e.g. no key factors when there is no key light).  The planner then
 *   - marks DIRTY every changed input and, in pass order, every product
 *     written by a pass that reads something dirty (so an edit marks
 *     exactly what depends on it, transitively);
 *   - marks NEEDED the needed products and, backwards, what the passes
 *     writing them read;
 *   - runs a pass when it writes a needed product that is dirty or was
 *     never computed (or was dropped), and skips it otherwise, with the
 *     reason either way.
 * The planner holds no GPU state: it only decides; the renderer runs the
 * passes and reports each one done (its products become valid).
 *
 * Amortization (NS09 section 7, off unless asked for): passes marked
 * DEFERRABLE (the expensive visibility passes) whose products hold an
 * earlier result may wait: hfs_plan_frame_amortized runs at most `budget`
 * of them a frame, the ones waiting longest first, and the others keep
 * their (outdated) products for this frame and run in later ones.  What
 * reads a waiting product is not rerun for it until it is recomputed.  So a
 * change reaches the image in full after up to ceil(K / budget) frames, K
 * the deferrable passes it made stale; with no further edits the frames
 * converge to the unamortized image, bit for bit.
 */
#ifndef HFS_FRAME_PLAN_H
#define HFS_FRAME_PLAN_H

#include <stdint.h>

#define HFS_PLAN_MAX_NODES 128
#define HFS_PLAN_MAX_PASSES 64
#define HFS_PLAN_NAME 24
#define HFS_PLAN_REASON 96

typedef struct hfs_plan_set {
    uint64_t w[HFS_PLAN_MAX_NODES / 64];
} hfs_plan_set;

typedef struct hfs_plan_pass {
    char name[HFS_PLAN_NAME];
    hfs_plan_set reads, writes;
} hfs_plan_pass;

/* One pass's fate in a frame. */
typedef struct hfs_plan_step {
    int pass;
    int run;                       /* 1: run it; 0: skipped              */
    char reason[HFS_PLAN_REASON];  /* why (e.g. "heights changed",
                                      "cached: nothing it reads changed",
                                      "not needed")                      */
} hfs_plan_step;

typedef struct hfs_plan {
    int n_nodes, n_passes;
    char node[HFS_PLAN_MAX_NODES][HFS_PLAN_NAME];
    int is_input[HFS_PLAN_MAX_NODES];
    hfs_plan_pass pass[HFS_PLAN_MAX_PASSES];
    hfs_plan_set valid;            /* products computed and still current */
    hfs_plan_set filled;           /* products holding some result (maybe
                                      outdated): computed since the last drop */
    int deferrable[HFS_PLAN_MAX_PASSES];
    int waited[HFS_PLAN_MAX_PASSES]; /* frames a deferrable pass has waited */
    hfs_plan_set changed;          /* inputs changed since the last frame  */
    char why[HFS_PLAN_MAX_NODES][HFS_PLAN_REASON]; /* per changed input   */
} hfs_plan;

static inline void hfs_plan_set_add(hfs_plan_set *s, int node)
{
    s->w[node / 64] |= (uint64_t)1 << (node % 64);
}

static inline int hfs_plan_set_has(const hfs_plan_set *s, int node)
{
    return (int)((s->w[node / 64] >> (node % 64)) & 1u);
}

void hfs_plan_init(hfs_plan *p);

/* Declares a node; returns its id, or -1 when the table is full. */
int hfs_plan_input(hfs_plan *p, const char *name);
int hfs_plan_product(hfs_plan *p, const char *name);

/* Declares a pass reading `reads` and writing `writes` (node ids, lists
 * ended by -1).  Returns its id, or -1 when the table is full. */
int hfs_plan_pass_add(hfs_plan *p, const char *name, const int *reads, const int *writes);

/* Replaces what pass `pass` reads (ids ended by -1): for a pass whose
 * inputs depend on the scene, e.g. the final shading reads the factors of
 * the lights present only. */
void hfs_plan_pass_reads(hfs_plan *p, int pass, const int *reads);

/* Input `node` changed since the last frame; `reason` says how (kept for
 * the report; the first reason of a frame wins). */
void hfs_plan_change(hfs_plan *p, int node, const char *reason);

/* Forgets every product (e.g. after a failed frame or a context loss), or
 * one product (its storage was overwritten or reallocated). */
void hfs_plan_drop_all(hfs_plan *p);
void hfs_plan_drop(hfs_plan *p, int product);

/* Plans the frame: one step per pass, in pass order, into steps[0..n_passes).
 * Returns the number of passes to run.  Clears the changed inputs. */
int hfs_plan_frame(hfs_plan *p, const hfs_plan_set *needed, hfs_plan_step *steps);

/* The same with amortization (see above): at most `budget` (>= 1)
 * deferrable passes run; a deferred pass's step says "deferred
 * (amortized): ...".  *deferred (may be NULL) receives how many passes wait
 * for a later frame: the caller renders again while it is not 0. */
int hfs_plan_frame_amortized(hfs_plan *p, const hfs_plan_set *needed, int budget,
                             hfs_plan_step *steps, int *deferred);

/* Marks pass `pass` deferrable (or not). */
void hfs_plan_set_deferrable(hfs_plan *p, int pass, int yes);

/* The renderer ran pass `pass` successfully: its products are valid. */
void hfs_plan_done(hfs_plan *p, int pass);

#endif /* HFS_FRAME_PLAN_H */
