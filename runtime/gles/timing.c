/*
 * timing.c — see timing.h.
 */
#include "timing.h"

#include <stdio.h>
#include <string.h>
#include <time.h>

double hfs_gles_now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

void hfs_gles_timing_init(hfs_gles_timing *t, const hfs_gl *gl, int driver_has_queries)
{
    if (driver_has_queries) {
        gl->GenQueries(2 * HFS_GLES_TIMING_SLOTS, t->queries);
        t->have_queries = 1;
    }
}

void hfs_gles_timing_free(hfs_gles_timing *t, const hfs_gl *gl)
{
    if (t->have_queries)
        gl->DeleteQueries(2 * HFS_GLES_TIMING_SLOTS, t->queries);
    t->have_queries = 0;
}

void hfs_gles_timing_reset(hfs_gles_timing *t)
{
    memset(t->ms, 0, sizeof t->ms);
    memset(t->fetch, 0, sizeof t->fetch);
    memset(t->ran, 0, sizeof t->ran);
    memset(t->cached, 0, sizeof t->cached);
}

void hfs_gles_timing_select(hfs_gles_timing *t, int timer_query_usable)
{
    t->use_queries = t->have_queries && timer_query_usable && !t->finish;
}

void hfs_gles_timing_begin(hfs_gles_timing *t, const hfs_gl *gl, int s)
{
    t->ran[s] = 1;
    if (!t->level)
        return;
    if (t->use_queries) {
        gl->QueryCounter(t->queries[2 * s], GL_TIMESTAMP_EXT);
    } else {
        gl->Finish();
        t->t0[s] = hfs_gles_now_ms();
    }
}

void hfs_gles_timing_end(hfs_gles_timing *t, const hfs_gl *gl, int s)
{
    if (!t->level)
        return;
    if (t->use_queries) {
        gl->QueryCounter(t->queries[2 * s + 1], GL_TIMESTAMP_EXT);
    } else {
        gl->Finish();
        t->ms[s] += hfs_gles_now_ms() - t->t0[s];
    }
}

void hfs_gles_timing_collect(hfs_gles_timing *t, const hfs_gl *gl)
{
    if (!t->level || !t->use_queries)
        return;
    for (int s = 0; s < t->n_slots; ++s) {
        if (!t->ran[s])
            continue;
        GLuint64 t0 = 0, t1 = 0;
        gl->GetQueryObjectui64v(t->queries[2 * s], GL_QUERY_RESULT, &t0);
        gl->GetQueryObjectui64v(t->queries[2 * s + 1], GL_QUERY_RESULT, &t1);
        t->ms[s] = t1 > t0 ? (double)(t1 - t0) * 1e-6 : 0.0;
    }
    if (gl->is_es) {
        GLint disjoint = 0;
        gl->GetIntegerv(GL_GPU_DISJOINT_EXT, &disjoint);
        if (disjoint)
            for (int s = 0; s < t->n_slots; ++s)
                t->ms[s] = -1.0; /* unreliable: the GPU was disjoint */
    }
    for (int i = 0; i < 8 && gl->GetError() != GL_NO_ERROR; ++i)
        ;
}

void hfs_gles_timing_report(const hfs_gles_timing *t, hfs_timings *out)
{
    for (int s = 0; s < t->n_slots; ++s) {
        if (!t->ran[s] && !t->cached[s])
            continue;
        hfs_pass_time *pt = &out->pass[out->n_passes++];
        snprintf(pt->name, sizeof pt->name, "%s", t->name[s]);
        pt->ms = t->ran[s] ? t->ms[s] : 0.0;
        pt->fetches = t->ran[s] ? t->fetch[s] : 0.0;
        pt->cached = !t->ran[s];
        out->gpu_ms += pt->ms > 0.0 ? pt->ms : 0.0;
    }
}
