/*
 * test_capture.c — the V4L2 capture source against the fake device
 * (capture_fake.h), hfs-capture-info's listing, device loss with the
 * shared back-off, and recordings played back.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <linux/videodev2.h>

#include "backoff.h"
#include "capture_fake.h"
#include "capture_live.h"
#include "capture_record.h"
#include "capture_synth.h"
#include "capture_v4l2.h"
#include "check.h"

static hfs_capture *open_fake(capture_fake *f, hfs_v4l2_ops *ops, int w, int h, hfs_error *err,
                              int *rc)
{
    *ops = capture_fake_ops(f);
    hfs_v4l2_desc d = {.path = "/dev/video7", .format = HFS_PIX_Z16, .width = w, .height = h,
                       .fps = 30, .buffers = 4, .ops = ops};
    hfs_capture *c = NULL;
    *rc = hfs_v4l2_open(&d, &c, err);
    return c;
}

static void fill_seq(void *user, uint8_t *dst, int w, int h, int stride, uint32_t seq)
{
    (void)user;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            dst[(size_t)y * stride + 2 * x] = (uint8_t)seq;
            dst[(size_t)y * stride + 2 * x + 1] = 3;
        }
}

static void count_tap(void *user, const hfs_capture_frame *f)
{
    (void)f;
    ++*(int *)user;
}

static void test_stream(void)
{
    capture_fake f;
    capture_fake_init(&f, "/dev/video7");
    f.fill = fill_seq;
    hfs_v4l2_ops ops;
    hfs_error err = {{0}};
    int rc;
    hfs_capture *c = open_fake(&f, &ops, 640, 480, &err, &rc);
    CHECK(rc == 0 && c, "open: %s", err.msg);
    if (!c)
        return;
    int w, h, stride, nb;
    size_t size;
    hfs_v4l2_format(c, &w, &h, &stride, &size, &nb);
    CHECK(w == 640 && h == 480 && stride == 1280 && nb == 4, "format %dx%d %d %d", w, h, stride,
          nb);
    CHECK(f.streaming && capture_fake_queued(&f) == 4, "all 4 buffers queued");
    hfs_capture_frame fr;
    CHECK(hfs_capture_next(c, 0, &fr, &err) == 0, "nothing yet: EAGAIN -> 0");
    CHECK(hfs_v4l2_wait(c, 0, &err) == 0, "poll: nothing ready");
    int tapped = 0;
    c->tap = count_tap, c->tap_user = &tapped;
    capture_fake_produce(&f, 3);
    CHECK(hfs_v4l2_wait(c, 0, &err) == 1, "poll: ready");
    CHECK(hfs_capture_next(c, 0, &fr, &err) == 1 && fr.sequence == 2, "newest of 3: seq %u",
          fr.sequence);
    CHECK(fr.data[0] == 2 && fr.data[1] == 3,
          "the newest buffer's bytes");
    /* The driver's timeval holds microseconds. */
    CHECK(fr.t_ns == (1000000000LL + 3 * 33333333LL) / 1000 * 1000, "monotonic timestamp %lld",
          (long long)fr.t_ns);
    CHECK(tapped == 3, "the tap saw all 3 (superseded ones too): %d", tapped);
    c->tap = NULL;
    CHECK(c->superseded == 2 && c->dropped == 0, "superseded %ld dropped %ld", c->superseded,
          c->dropped);
    CHECK(capture_fake_queued(&f) == 3, "the held buffer is not queued (%d)",
          capture_fake_queued(&f));
    capture_fake_produce(&f, 1);
    CHECK(hfs_capture_next(c, 0, &fr, &err) == 1 && fr.sequence == 3, "next frame seq 3");
    CHECK(capture_fake_queued(&f) == 3, "the old held buffer went back");
    f.skip_seq = 2; /* the driver dropped 2 frames */
    capture_fake_produce(&f, 1);
    CHECK(hfs_capture_next(c, 0, &fr, &err) == 1 && fr.sequence == 6 && c->dropped == 2,
          "gap: seq %u dropped %ld", fr.sequence, c->dropped);
    f.short_next = 1; /* a malformed frame: too few bytes */
    capture_fake_produce(&f, 1);
    CHECK(hfs_capture_next(c, 0, &fr, &err) == 0 && c->dropped == 3, "short frame dropped");
    f.not_monotonic = 1;
    capture_fake_produce(&f, 1);
    CHECK(hfs_capture_next(c, 0, &fr, &err) == 1 && fr.t_ns != f.t_of[0] &&
              fr.t_ns > 0, "non-monotonic timestamp replaced by the dequeue time");
    CHECK(f.bad_qbuf == 0, "never queued a buffer it did not hold (%ld)", f.bad_qbuf);
    hfs_capture_destroy(c);
    CHECK(f.open_fds == 0 && f.streamoffs >= 1 && f.maps == f.unmaps && f.maps == 4,
          "closed: streamoff, %ld maps %ld unmaps", f.maps, f.unmaps);
    capture_fake_free(&f);
}

/* ENODEV mid-stream: the kiosk's policy (backoff.h): lost once, reopen
 * attempts fail while gone (the same reason is not reported again), the
 * stream comes back. */
static void test_loss(void)
{
    capture_fake f;
    capture_fake_init(&f, "/dev/video7");
    hfs_v4l2_ops ops;
    hfs_error err = {{0}};
    int rc;
    hfs_capture *c = open_fake(&f, &ops, 0, 0, &err, &rc);
    if (!c)
        return;
    hfs_capture_frame fr;
    capture_fake_produce(&f, 1);
    CHECK(hfs_capture_next(c, 0, &fr, &err) == 1, "a frame before the loss");
    f.gone = 1;
    rc = hfs_capture_next(c, 0, &fr, &err);
    CHECK(rc == HFS_E_IO && strstr(err.msg, "video /dev/video7: VIDIOC_DQBUF: No such device"),
          "loss: %d %s", rc, err.msg);
    hfs_backoff b;
    hfs_backoff_init(&b, 0, 0);
    hfs_capture_close(c);
    hfs_backoff_lose(&b, 0);
    CHECK(f.open_fds == 0 && f.maps == f.unmaps, "released after the loss");
    int reports = 0;
    int64_t t = 0;
    for (int i = 0; i < 5; ++i) {
        t = b.retry_at_ns;
        CHECK(hfs_backoff_due(&b, t), "retry due");
        CHECK(hfs_capture_reopen(c, &err) == HFS_E_IO, "reopen while gone: %s", err.msg);
        reports += hfs_backoff_failed(&b, t, err.msg);
    }
    CHECK(reports == 0, "the same reason is not reported again (%d)", reports);
    CHECK(b.delay_ns == 3200000000LL, "back-off doubled to 3.2 s (%lld)", (long long)b.delay_ns);
    f.gone = 0;
    CHECK(hfs_capture_reopen(c, &err) == 0, "back: %s", err.msg);
    hfs_backoff_back(&b);
    capture_fake_produce(&f, 1);
    CHECK(hfs_capture_next(c, 0, &fr, &err) == 1, "frames again after the reopen");
    hfs_capture_destroy(c);
    CHECK(f.open_fds == 0 && f.maps == f.unmaps && f.opens == f.closes, "all closed");
    capture_fake_free(&f);
}

static void test_negotiation(void)
{
    capture_fake f;
    capture_fake_init(&f, "/dev/video7");
    f.force_w = 320, f.force_h = 240; /* the driver changes the size */
    hfs_v4l2_ops ops;
    hfs_error err = {{0}};
    int rc;
    hfs_capture *c = open_fake(&f, &ops, 640, 480, &err, &rc);
    CHECK(!c && strstr(err.msg, "asked for 640x480 Z16, the driver gives 320x240"),
          "size refused: %s", err.msg);
    CHECK(f.open_fds == 0, "closed after the refusal");
    c = open_fake(&f, &ops, 0, 0, &err, &rc);
    int w = 0, h = 0, stride = 0, nb = 0;
    size_t size = 0;
    if (c)
        hfs_v4l2_format(c, &w, &h, &stride, &size, &nb);
    CHECK(c && w == 320 && h == 240 && stride == 640, "no size asked: the driver's %dx%d", w, h);
    hfs_capture_destroy(c);
    f.force_w = f.force_h = 0;
    f.max_buffers = 3;
    c = open_fake(&f, &ops, 0, 0, &err, &rc);
    if (c)
        hfs_v4l2_format(c, &w, &h, &stride, &size, &nb);
    CHECK(c && nb == 3, "the granted count (3 of 4 asked): %d", nb);
    hfs_capture_destroy(c);
    f.caps = V4L2_CAP_VIDEO_CAPTURE; /* no streaming */
    c = open_fake(&f, &ops, 0, 0, &err, &rc);
    CHECK(!c && strstr(err.msg, "no streaming I/O"), "streaming required: %s", err.msg);
    hfs_v4l2_desc d = {.path = "/dev/video9", .format = HFS_PIX_Z16, .ops = &ops};
    CHECK(hfs_v4l2_open(&d, &c, &err) == HFS_E_IO &&
              !strcmp(err.msg, "video /dev/video9: No such file or directory"),
          "missing device: %s", err.msg);
    capture_fake_free(&f);
}

static void test_info(void)
{
    capture_fake f;
    capture_fake_init(&f, "/dev/video7");
    hfs_v4l2_ops ops = capture_fake_ops(&f);
    char *text = NULL;
    size_t len = 0;
    FILE *out = open_memstream(&text, &len);
    hfs_error err = {{0}};
    CHECK(hfs_v4l2_list("/dev/video7", &ops, out, &err) == 0, "list: %s", err.msg);
    fclose(out);
    CHECK(text && strstr(text, "card 'Fake Depth Camera'") && strstr(text, "capture, streaming"),
          "header");
    CHECK(text && strstr(text, "[0] 'Z16 ' (Z16, supported)"), "Z16 listed");
    CHECK(text && strstr(text, "[4] 'MJPG' (not supported by hfshade)"), "MJPG marked");
    CHECK(text && strstr(text, "Size: Discrete 320x240") &&
              strstr(text, "Interval: Discrete 0.033s (30.000 fps)"), "sizes and rates");
    CHECK(f.open_fds == 0, "closed after listing");
    free(text);
    capture_fake_free(&f);
}

static void test_replay(const char *tmp)
{
    char dir[512], path[600];
    snprintf(dir, sizeof dir, "%s/rec", tmp);
    hfs_synth_desc d;
    hfs_synth_defaults(&d);
    d.width = 32, d.height = 24, d.frames = 6;
    hfs_error err = {{0}};
    CHECK(hfs_synth_record(&d, dir, &err) == 0, "record: %s", err.msg);
    CHECK(hfs_synth_record(&d, dir, &err) == HFS_E_INVALID && strstr(err.msg, "already holds"),
          "no overwrite: %s", err.msg);
    hfs_capture *c = NULL;
    CHECK(hfs_capture_replay_open(dir, 100, 0, &c, &err) == 0, "replay: %s", err.msg);
    if (!c)
        return;
    hfs_capture_frame fr;
    CHECK(hfs_capture_deadline(c) == 100, "first frame due at the start");
    CHECK(hfs_capture_next(c, 99, &fr, &err) == 0, "not due yet");
    CHECK(hfs_capture_next(c, 100 + 70000000, &fr, &err) == 1 && fr.sequence == 2 &&
              c->superseded == 2 && fr.t_ns == 100 + 66666667, "newest due: %u", fr.sequence);
    uint16_t *depth = malloc(32 * 24 * 2);
    hfs_synth_frame(&d, 2, depth, NULL);
    CHECK(fr.width == 32 && fr.height == 24 && !memcmp(fr.data, depth, 32 * 24 * 2),
          "bytes as recorded");
    /* pace = shown: the frame due, never a newer one; the clock waited. */
    hfs_capture *p = NULL;
    CHECK(hfs_capture_replay_open(dir, 100, 0, &p, &err) == 0, "replay: %s", err.msg);
    if (p) {
        hfs_capture_replay_pace_shown(p);
        const int64_t late = 100 + 70000000;
        CHECK(hfs_capture_next(p, late, &fr, &err) == 1 && fr.sequence == 0 &&
                  p->superseded == 0 && fr.t_ns == late, "paced: frame %u at %lld", fr.sequence,
              (long long)fr.t_ns);
        CHECK(hfs_capture_deadline(p) == late + 33333333, "paced: next one interval later");
        CHECK(hfs_capture_next(p, INT64_MAX / 2, &fr, &err) == 1 && fr.sequence == 1 &&
                  p->superseded == 0 && !p->finished, "paced: frame %u", fr.sequence);
        hfs_capture_destroy(p);
    }
    snprintf(path, sizeof path, "%s/frame-000003.raw", dir);
    CHECK(truncate(path, 100) == 0, "truncate");
    CHECK(hfs_capture_next(c, 100 + 100000000, &fr, &err) == HFS_E_FORMAT &&
              strstr(err.msg, "frame-000003.raw: too short, a 32x24 Z16 frame is 1536 bytes"),
          "short frame file: %s", err.msg);
    CHECK(hfs_capture_next(c, INT64_MAX / 2, &fr, &err) == 1 && fr.sequence == 5 &&
              c->finished, "to the end");
    hfs_capture_destroy(c);
    snprintf(path, sizeof path, "%s/capture.txt", dir);
    FILE *fp = fopen(path, "a");
    fputs("frame 9 5 frame-000001.raw\n", fp);
    fclose(fp);
    CHECK(hfs_capture_replay_open(dir, 0, 0, &c, &err) == HFS_E_FORMAT &&
              strstr(err.msg, "capture.txt:10: time goes backwards"), "index: %s", err.msg);
    free(depth);
}

/* A flat floor 1 m away (1000 counts), with a 0.3 m block in the middle
 * when seq is odd. */
static void fill_block(void *user, uint8_t *dst, int w, int h, int stride, uint32_t seq)
{
    (void)user;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int block = (seq & 1) && abs(x - w / 2) < w / 4 && abs(y - h / 2) < h / 4;
            const unsigned c = block ? 700 : 1000;
            dst[(size_t)y * stride + 2 * x] = (uint8_t)(c & 0xff);
            dst[(size_t)y * stride + 2 * x + 1] = (uint8_t)(c >> 8);
        }
}

typedef struct log_lines {
    int n;
    char last[600];
} log_lines;

static void collect(void *user, int warning, const char *line)
{
    log_lines *l = user;
    (void)warning;
    l->n++;
    snprintf(l->last, sizeof l->last, "%s", line);
}

/* A heights camera on the fake device through the kiosk's capture path
 * (capture_live.h), its log lines collected; retries after 1 us, 2 us, ...
 * NULL on failure (counted). */
static hfs_capture_live *live_open(capture_fake *f, hfs_v4l2_ops *ops, log_lines *lines)
{
    *ops = capture_fake_ops(f);
    hfs_capture_configs cc = {0};
    char msg[300];
    hfs_capture_config_begin(&cc, "sand", 1, msg, sizeof msg);
    hfs_capture_config_key(&cc, "device", "/dev/video7", 2, msg, sizeof msg);
    hfs_capture_config_key(&cc, "window", "1", 3, msg, sizeof msg);
    hfs_capture_config_key(&cc, "plane", "0 0 1", 4, msg, sizeof msg);
    CHECK(hfs_capture_config_end(&cc, msg, sizeof msg) == 0, "config: %s", msg);
    hfs_capture_live_desc d = {.config = &cc.c[0], .grid_w = 32, .grid_h = 24, .ops = ops,
                               .log = collect, .log_user = lines, .retry_min_ns = 1000,
                               .retry_max_ns = 8000};
    hfs_capture_live *live = NULL;
    hfs_error err = {{0}};
    CHECK(hfs_capture_live_open(&d, &live, &err) == 0, "live: %s", err.msg);
    return live;
}

/* The kiosk's capture path (capture_live.h) against the fake device:
 * heights from frames, ENODEV mid-stream survived with the last heights
 * kept, one report, the back-off's reopen, frames again. */
static void test_live(void)
{
    capture_fake f;
    capture_fake_init(&f, "/dev/video7");
    f.fill = fill_block;
    hfs_v4l2_ops ops;
    log_lines lines = {0};
    hfs_capture_live *live = live_open(&f, &ops, &lines);
    if (!live)
        return;
    hfs_error err = {{0}};
    int w, h;
    uint64_t serial;
    CHECK(!hfs_capture_live_heights(live, &w, &h, &serial) && serial == 0, "none yet");
    capture_fake_produce(&f, 2); /* seq 0 flat, seq 1 with the block: the newest */
    CHECK(hfs_capture_live_drain(live, 0) == 1, "heights from a frame");
    const float *z = hfs_capture_live_heights(live, &w, &h, &serial);
    CHECK(z && w == 32 && h == 24 && fabsf(z[12 * 32 + 16] - 0.3f) < 1e-4f && fabsf(z[0]) < 1e-4f,
          "block 0.3 m, floor 0: %g %g", z ? z[12 * 32 + 16] : -1, z ? z[0] : -1);
    const uint64_t s1 = serial;
    f.gone = 1;
    CHECK(hfs_capture_live_drain(live, 10) == 0 && lines.n == 1 &&
              strstr(lines.last, "No such device (showing the last frame; retrying)"),
          "loss reported once: %d %s", lines.n, lines.last);
    z = hfs_capture_live_heights(live, &w, &h, &serial);
    CHECK(z && serial == s1 && fabsf(z[12 * 32 + 16] - 0.3f) < 1e-4f, "the last heights stay");
    const long opens = f.opens;
    hfs_capture_live_drain(live, 500); /* before the first retry (1000 ns) */
    CHECK(f.opens == opens, "no reopen before the back-off");
    for (int64_t t = 1010; t < 40000; t += 1000)
        hfs_capture_live_drain(live, t);
    CHECK(lines.n == 1, "the same reason is not reported again (%d lines)", lines.n);
    hfs_capture_live_stats st;
    hfs_capture_live_stats_get(live, &st);
    CHECK(st.lost && f.open_fds == 0, "lost, closed");
    f.gone = 0;
    hfs_capture_live_drain(live, 100000);
    CHECK(lines.n == 2 && !strcmp(lines.last, "video /dev/video7: back"), "back: %s",
          lines.last);
    capture_fake_produce(&f, 1); /* seq 2 (even): the flat floor */
    CHECK(hfs_capture_live_drain(live, 100001) == 1, "frames again");
    z = hfs_capture_live_heights(live, &w, &h, &serial);
    CHECK(z && serial == s1 + 1 && fabsf(z[12 * 32 + 16]) < 1e-4f, "new heights, new serial");
    CHECK(hfs_capture_live_close(live, &err) == 0, "close");
    CHECK(f.open_fds == 0 && f.maps == f.unmaps && f.bad_qbuf == 0, "all released");
    capture_fake_free(&f);
}

/* A device dying mid-stream with EIO on DQBUF (the kernel's other answer
 * for a device going away) and back with its sequence restarted at 0, as
 * real drivers count from STREAMON: one line, the last heights kept, the
 * back-off's reopen, and no frame counted dropped for the restart (the
 * unsigned gap 0 - 4 - 1 is 4294967291); a gap after it still counts. */
static void test_restart(void)
{
    capture_fake f;
    capture_fake_init(&f, "/dev/video7");
    f.fill = fill_block;
    f.seq_restarts = 1;
    hfs_v4l2_ops ops;
    log_lines lines = {0};
    hfs_capture_live *live = live_open(&f, &ops, &lines);
    if (!live)
        return;
    hfs_capture_live_stats st;
    for (int i = 0; i < 5; ++i) {
        capture_fake_produce(&f, 1);
        CHECK(hfs_capture_live_drain(live, 10 + i) == 1, "frame %d", i);
    }
    hfs_capture_live_stats_get(live, &st);
    CHECK(st.sequence == 4 && st.dropped == 0 && st.frames == 5, "seq %u dropped %ld frames %ld",
          st.sequence, st.dropped, st.frames);
    f.dqbuf_errno = EIO;
    capture_fake_produce(&f, 1);
    CHECK(hfs_capture_live_drain(live, 100) == 0 && lines.n == 1 &&
              !strcmp(lines.last, "video /dev/video7: VIDIOC_DQBUF: Input/output error "
                                  "(showing the last frame; retrying)"),
          "died mid-stream: %d lines, last '%s'", lines.n, lines.last);
    hfs_capture_live_stats_get(live, &st);
    CHECK(st.lost && f.open_fds == 0 && f.maps == f.unmaps, "lost, released");
    f.dqbuf_errno = 0;
    hfs_capture_live_drain(live, 100000);
    CHECK(lines.n == 2 && !strcmp(lines.last, "video /dev/video7: back"), "back: %s",
          lines.last);
    capture_fake_produce(&f, 1); /* seq 0, flat as seq 4 was: the heights stay */
    hfs_capture_live_drain(live, 100001);
    hfs_capture_live_stats_get(live, &st);
    CHECK(st.sequence == 0 && st.dropped == 0 && st.frames == 6,
          "after the restart: seq %u, dropped %ld (want 0), frames %ld", st.sequence, st.dropped,
          st.frames);
    f.skip_seq = 2;
    capture_fake_produce(&f, 1); /* seq 3: the block */
    CHECK(hfs_capture_live_drain(live, 100002) == 1, "new heights after a gap");
    hfs_capture_live_stats_get(live, &st);
    CHECK(st.sequence == 3 && st.dropped == 2, "gap after the restart: seq %u dropped %ld",
          st.sequence, st.dropped);
    hfs_error err = {{0}};
    CHECK(hfs_capture_live_close(live, &err) == 0, "close");
    CHECK(f.open_fds == 0 && f.maps == f.unmaps && f.bad_qbuf == 0, "all released");
    capture_fake_free(&f);
}

int main(void)
{
    char tmp[] = "/tmp/test_capture_XXXXXX";
    if (!mkdtemp(tmp))
        return 1;
    test_stream();
    test_loss();
    test_negotiation();
    test_info();
    test_live();
    test_restart();
    test_replay(tmp);
    char cmd[600];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmp);
    if (system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", tmp);
    printf("test_capture: %ld checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
