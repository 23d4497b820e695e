/*
 * timing.h — per-pass GPU times of the GLES backend (hfs_timings): timer
 * queries (EXT_disjoint_timer_query) where the driver has them, else
 * glFinish around each pass and a monotonic clock.
 *
 * Times are kept per STAGE: a pass of the table (pass.h) names one stage or
 * a few (the terrain pass: upload, normals, decimate, reconstruct); the
 * stages of all passes, in table order, are the timing slots.
 */
#ifndef HFS_GLES_TIMING_H
#define HFS_GLES_TIMING_H

#include "gl_api.h"
#include "hfshade.h"

#define HFS_GLES_TIMING_SLOTS 20

typedef struct hfs_gles_timing {
    int level;             /* 0 off, 1 times, 2 times + fetch counts */
    int finish;            /* glFinish + clock even where timer queries exist */
    int have_queries;
    int use_queries;       /* this frame: queries (else finish + clock) */
    GLuint queries[2 * HFS_GLES_TIMING_SLOTS];
    int n_slots;
    const char *name[HFS_GLES_TIMING_SLOTS];
    double ms[HFS_GLES_TIMING_SLOTS], fetch[HFS_GLES_TIMING_SLOTS], t0[HFS_GLES_TIMING_SLOTS];
    int ran[HFS_GLES_TIMING_SLOTS], cached[HFS_GLES_TIMING_SLOTS];
} hfs_gles_timing;

/* Creates the queries (driver_has_queries: the driver exposes them). */
void hfs_gles_timing_init(hfs_gles_timing *t, const hfs_gl *gl, int driver_has_queries);
void hfs_gles_timing_free(hfs_gles_timing *t, const hfs_gl *gl);
/* A new frame: no slot ran, none cached, nothing measured. */
void hfs_gles_timing_reset(hfs_gles_timing *t);
/* Slot `s` runs between begin and end (marks it ran even when not timing). */
void hfs_gles_timing_begin(hfs_gles_timing *t, const hfs_gl *gl, int s);
void hfs_gles_timing_end(hfs_gles_timing *t, const hfs_gl *gl, int s);
/* The frame's capability profile allows timer queries (gl_caps.h): they
 * are used unless t->finish asks for the clock. */
void hfs_gles_timing_select(hfs_gles_timing *t, int timer_query_usable);
/* Reads back the queries of the slots that ran (no-op for the clock). */
void hfs_gles_timing_collect(hfs_gles_timing *t, const hfs_gl *gl);
/* The slots that ran or were cached, into out->pass (name, ms, fetches). */
void hfs_gles_timing_report(const hfs_gles_timing *t, hfs_timings *out);

double hfs_gles_now_ms(void);

#endif /* HFS_GLES_TIMING_H */
