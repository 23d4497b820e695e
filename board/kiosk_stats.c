/*
 * kiosk_stats.c — the --stats file: what latency and idle CPU are computed
 * from (tools/bench_kiosk.sh, tests/test_kiosk.c).
 *
 * One record per line, fields separated by single spaces, times in
 * CLOCK_MONOTONIC nanoseconds (the clock of input event timestamps), CPU in
 * microseconds of user + system time of the whole process (getrusage
 * RUSAGE_SELF: every thread, llvmpipe's included):
 *
 *   start  T_NS CPU_US
 *   frame  N T_PRESENT_NS RENDER_MS PASSES_RAN PASSES_TOTAL EVENTS CPU_US
 *   event  T_EVENT_NS T_PRESENT_NS LATENCY_NS FRAME CHANGED CONTROL
 *   reload T_NS OK CPU_US
 *   capture SEQ T_FRAME_NS T_PRESENT_NS LATENCY_NS CPU_NS DROPPED SUPERSEDED
 *   sky    SEQ T_FRAME_NS T_PRESENT_NS LATENCY_NS CPU_NS DROPPED SUPERSEDED
 *          NLIGHTS [ID PHI_DEG ELEV_DEG]...
 *   map    N LEVEL X Y RENDERED CACHED BYTES BUDGET LEVEL_BYTES COARSE
 *   prefetch T_NS LEVEL TILE_MS CACHED BYTES
 *   exit   T_NS CPU_US FRAMES
 *
 * "map" follows the frame it describes when the kiosk shows a map
 * (kiosk_map.h): the level, the view's centre (texels of the field), the
 * tiles that frame rendered itself (0: every tile was lit ahead, or shown
 * from a coarser level), the tiles and bytes held, the budget, the levels'
 * bytes, the tiles shown from a coarser level.  "prefetch": a tile
 * rendered ahead of the view, its render time, the cache after it.
 * "frame" is written after hfs_display_present returned, then one "event"
 * line per input event of the batch that frame shows (CHANGED 1 when the
 * event edited the scene or the visible state).  Events of a batch that
 * changed nothing were not shown by any frame: T_PRESENT_NS, LATENCY_NS and
 * FRAME are -1.  Lines are flushed per frame, so a reader sees whole
 * records while the kiosk runs.
 *
 * A write that fails (a full disk, /dev/full) is never ignored: the first
 * failure is logged once with its reason, no further stats are written (the
 * display keeps running: stats are a measurement, not the product), and the
 * kiosk's exit status becomes 1 (kiosk_stats_close).
 */
#include "kiosk.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

struct kiosk_stats {
    FILE *f;
    char *path;
    int failed; /* a write failed: logged once, nothing more written */
};

/* Flushes and checks the stream; 0 while every write so far succeeded. */
static int check(kiosk_stats *s)
{
    if (s->failed)
        return -1;
    if (fflush(s->f) != 0 || ferror(s->f)) {
        kiosk_log(KIOSK_ERR, "%s: stats write failed: %s; no more stats are written", s->path,
                  strerror(errno ? errno : EIO));
        s->failed = 1;
        return -1;
    }
    return 0;
}

int64_t kiosk_cpu_us(void)
{
    struct rusage ru;
    if (getrusage(RUSAGE_SELF, &ru) != 0)
        return -1;
    return (int64_t)(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) * 1000000 +
           (int64_t)(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
}

kiosk_stats *kiosk_stats_open(const char *path, hfs_error *err)
{
    kiosk_stats *s = calloc(1, sizeof *s);
    if (!s) {
        hfs_fail(err, HFS_E_NOMEM, "out of memory");
        return NULL;
    }
    s->f = fopen(path, "w");
    s->path = strdup(path);
    if (!s->f || !s->path) {
        hfs_fail(err, HFS_E_IO, "%s: cannot write the stats file: %s", path, strerror(errno));
        if (s->f)
            fclose(s->f);
        free(s->path);
        free(s);
        return NULL;
    }
    fprintf(s->f,
            "# hfshade-kiosk stats: times CLOCK_MONOTONIC ns, cpu user+system us (getrusage)\n"
            "# start T_NS CPU_US\n"
            "# frame N T_PRESENT_NS RENDER_MS PASSES_RAN PASSES_TOTAL EVENTS CPU_US\n"
            "# event T_EVENT_NS T_PRESENT_NS LATENCY_NS FRAME CHANGED CONTROL\n"
            "# reload T_NS OK CPU_US\n"
            "# map N LEVEL X Y RENDERED CACHED BYTES BUDGET LEVEL_BYTES COARSE\n"
            "# prefetch T_NS LEVEL TILE_MS CACHED BYTES\n"
            "# exit T_NS CPU_US FRAMES\n");
    if (fflush(s->f) != 0 || ferror(s->f)) {
        hfs_fail(err, HFS_E_IO, "%s: cannot write the stats file: %s", path,
                 strerror(errno ? errno : EIO));
        fclose(s->f);
        free(s->path);
        free(s);
        return NULL;
    }
    return s;
}

void kiosk_stats_start(kiosk_stats *s)
{
    if (!s || s->failed)
        return;
    fprintf(s->f, "start %lld %lld\n", (long long)hfs_input_now_ns(), (long long)kiosk_cpu_us());
    check(s);
}

void kiosk_stats_frame(kiosk_stats *s, const kiosk_frame *f, int events)
{
    if (!s || s->failed)
        return;
    fprintf(s->f, "frame %d %lld %.3f %d %d %d %lld\n", f->presented - 1,
            (long long)f->present_ns, f->render_ms, f->passes_ran, f->passes_total, events,
            (long long)kiosk_cpu_us());
    if (!f->map)
        return;
    kiosk_map_stats m;
    kiosk_map_stats_get(f->map, &m);
    fprintf(s->f, "map %d %d %.1f %.1f %d %d %zu %zu %zu %d\n", f->presented - 1, m.level,
            m.x, m.y, m.rendered, m.cached, m.bytes, m.budget, m.level_bytes, m.coarse);
}

void kiosk_stats_prefetch(kiosk_stats *s, const kiosk_frame *f)
{
    if (!s || s->failed || !f->map)
        return;
    kiosk_map_stats m;
    kiosk_map_stats_get(f->map, &m);
    fprintf(s->f, "prefetch %lld %d %.3f %d %zu\n", (long long)hfs_input_now_ns(), m.level,
            m.last_tile_ms, m.cached, m.bytes);
}

void kiosk_stats_event(kiosk_stats *s, const hfs_input_event *ev, int changed,
                       const kiosk_frame *f, int shown)
{
    if (!s || s->failed)
        return;
    const long long present = shown ? (long long)f->present_ns : -1;
    const long long latency = shown ? (long long)(f->present_ns - ev->t_ns) : -1;
    fprintf(s->f, "event %lld %lld %lld %d %d %.*s\n", (long long)ev->t_ns, present, latency,
            shown ? f->presented - 1 : -1, changed, HFS_CONTROL_NAME_MAX, ev->control);
}

void kiosk_stats_reload(kiosk_stats *s, int ok)
{
    if (!s || s->failed)
        return;
    fprintf(s->f, "reload %lld %d %lld\n", (long long)hfs_input_now_ns(), ok,
            (long long)kiosk_cpu_us());
    check(s);
}

/* After the frame that showed a capture frame: its sequence number, its
 * capture time, the present time, the latency, the capture path's thread
 * CPU (read + record + convert + filter, ns), the frames dropped so far
 * (sequence gaps, malformed) and those superseded by a newer one so far. */
void kiosk_stats_capture(kiosk_stats *s, const hfs_capture_live *live, const kiosk_frame *f)
{
    if (!s || s->failed || !live)
        return;
    hfs_capture_live_stats cs;
    hfs_capture_live_stats_get(live, &cs);
    fprintf(s->f, "capture %u %lld %lld %lld %lld %ld %ld\n", cs.sequence, (long long)cs.t_ns,
            (long long)f->present_ns, (long long)(f->present_ns - cs.t_ns),
            (long long)cs.cpu_ns, cs.dropped, cs.superseded);
    check(s);
}

/* As "capture", for the environment camera, plus its lights. */
void kiosk_stats_sky(kiosk_stats *s, const hfs_capture_live *live, const kiosk_frame *f)
{
    if (!s || s->failed || !live)
        return;
    hfs_capture_live_stats cs;
    hfs_capture_live_stats_get(live, &cs);
    uint64_t serial;
    const hfs_camsky_out *o = hfs_capture_live_sky(live, &serial);
    fprintf(s->f, "sky %u %lld %lld %lld %lld %ld %ld %d", cs.sequence, (long long)cs.t_ns,
            (long long)f->present_ns, (long long)(f->present_ns - cs.t_ns),
            (long long)cs.cpu_ns, cs.dropped, cs.superseded, o ? o->n_keys : 0);
    for (int i = 0; o && i < o->n_keys; ++i)
        fprintf(s->f, " %d %.3f %.3f", o->ids[i], o->keys[i].phi * 57.29577951308232,
                o->keys[i].elev * 57.29577951308232);
    fputc('\n', s->f);
    check(s);
}

int kiosk_stats_close(kiosk_stats *s, int frames)
{
    if (!s)
        return 0;
    if (!s->failed)
        fprintf(s->f, "exit %lld %lld %d\n", (long long)hfs_input_now_ns(),
                (long long)kiosk_cpu_us(), frames);
    check(s);
    if (fclose(s->f) != 0 && !s->failed) {
        kiosk_log(KIOSK_ERR, "%s: stats write failed: %s", s->path, strerror(errno));
        s->failed = 1;
    }
    const int failed = s->failed;
    free(s->path);
    free(s);
    return failed ? -1 : 0;
}

void kiosk_stats_flush(kiosk_stats *s)
{
    if (s)
        check(s);
}
