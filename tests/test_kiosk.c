/*
 * test_kiosk.c — hfshade-kiosk end to end, headless (board/KIOSK.md).
 *
 *   test_kiosk replay  KIOSK HFGEN   scripted knobs move the key light: the
 *                                    last frame equals, byte for byte, a
 *                                    direct render with the light where the
 *                                    script and the configuration's step and
 *                                    limits put it; one frame per batch of
 *                                    events that changed something, none
 *                                    for a turn past a limit
 *   test_kiosk signals KIOSK HFGEN   SIGHUP reloads an edited scene (the
 *                                    next frame is the new scene's); a
 *                                    broken scene on SIGHUP is one "<3>"
 *                                    journal line and the kiosk goes on,
 *                                    as for a check process that crashes;
 *                                    SIGTERM: exit 0, stats complete
 *   test_kiosk idle    KIOSK HFGEN   3 s without events: no frame, < 5% of
 *                                    one core
 *   test_kiosk example KIOSK DEMO.ini KIOSK.ini REPLAY.txt
 *                                    the shipped example configuration
 *                                    drives the demo scene (--no-devices)
 * Exit 77 only when no GLES context of any kind can be made here (gl_test.h).
 */
#define _GNU_SOURCE /* prlimit */
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "check.h"
#include "frame_image.h"
#include "kiosk_harness.h"
#include "scene_load.h"

/* The scene of the tests: 48x48 cones under a dim uniform sky and a key
 * light at phi 30, elevation 20 (degrees). */
static void make_scene(const char *hfgen, const char *key)
{
    char *const gen[] = {(char *)hfgen, "cones", "--size", "48x48", "-o",
                         (char *)kh_path("cones.pfm"), NULL};
    pid_t pid = kh_spawn(gen, kh_path("hfgen.log"));
    int st = pid > 0 ? kh_wait(pid, 60) : -1;
    if (st == -1 || !WIFEXITED(st) || WEXITSTATUS(st) != 0) {
        fprintf(stderr, "hfgen failed\n");
        exit(1);
    }
    char text[256];
    snprintf(text, sizeof text,
             "height = cones.pfm\n"
             "env-sh = 1.0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0\n"
             "key = %s\n",
             key);
    kh_write(kh_path("scene.ini"), text);
}

/* Compares frame file with a direct render of the scene (key light moved
 * to phi/elev unless NAN).  1 when equal byte for byte. */
static int frame_is(const char *frame, double phi, double elev)
{
    int w = 0, h = 0, dw = 0, dh = 0, no_gl = 0;
    uint8_t *got = kh_png_rgba(frame, &w, &h);
    uint8_t *want = kh_direct_frame(kh_path("scene.ini"), phi, elev, &dw, &dh, &no_gl);
    int same = got && want && w == dw && h == dh && !memcmp(got, want, (size_t)w * h * 4);
    if (got && want && !same && w == dw && h == dh) {
        int diff = 0, worst = 0;
        for (size_t i = 0; i < (size_t)w * h * 4; ++i) {
            const int d = abs(got[i] - want[i]);
            diff += d != 0;
            worst = d > worst ? d : worst;
        }
        fprintf(stderr, "%s: %d bytes differ (max %d/255) from the direct render\n", frame,
                diff, worst);
    }
    free(got);
    free(want);
    return same;
}

static int frames_equal(const char *a, const char *b)
{
    int w1, h1, w2, h2;
    uint8_t *x = kh_png_rgba(a, &w1, &h1), *y = kh_png_rgba(b, &w2, &h2);
    const int same = x && y && w1 == w2 && h1 == h2 && !memcmp(x, y, (size_t)w1 * h1 * 4);
    free(x);
    free(y);
    return same;
}

static int exited_ok(int st)
{
    return st != -1 && WIFEXITED(st) && WEXITSTATUS(st) == 0;
}

static void dump(const char *path)
{
    char *s = kh_read(path);
    fprintf(stderr, "---- %s\n%s----\n", path, s ? s : "(unreadable)\n");
    free(s);
}

/* ---- 3-D view ---------------------------------------------------------------- */

/* A button turns the 3-D view on, knobs turn the camera: the frame after
 * the button and the last frame are the library's views from those
 * cameras, byte for byte (board/KIOSK.md), and a camera move runs the view
 * pass alone (the stats' passes column). */
static void view(const char *kiosk, const char *hfgen)
{
    make_scene(hfgen, "30,20,3,100");
    kh_write(kh_path("c.ini"), "[button v]\naction = view.toggle\n"
                               "[knob caz]\naction = camera.azimuth\n"
                               "[knob czoom]\naction = camera.zoom\n");
    kh_write(kh_path("r.txt"), "100 v press\n"
                               "350 caz turn 4      # 250 + 20 = 270\n"
                               "600 czoom turn -2   # 1.1^-2\n");
    char *const argv[] = {(char *)kiosk, (char *)kh_path("scene.ini"), "--input",
                          (char *)kh_path("c.ini"), "--replay", (char *)kh_path("r.txt"),
                          "--display", "headless", "--exposure", "0", "--size", "96x64", "--out",
                          (char *)kh_path("f-%02d.png"), "--stats", (char *)kh_path("stats.txt"),
                          "--exit-after-replay", NULL};
    pid_t pid = kh_spawn(argv, kh_path("err.txt"));
    const int st = pid > 0 ? kh_wait(pid, 120) : -1;
    CHECK(exited_ok(st), "view run: status %d", st);
    const int frames = kh_count_lines(kh_path("stats.txt"), "frame ");
    CHECK(frames == 4, "%d frames, want 4 (the first, then one per event)", frames);
    const struct { const char *file; double az, zoom; } shown[2] = {
        {"f-01.png", 250.0, 1.0}, {"f-03.png", 270.0, 1.0 / (1.1 * 1.1)}};
    for (int k = 0; k < 2; ++k) {
        int w = 0, h = 0, no_gl = 0;
        uint8_t *got = kh_png_rgba(kh_path(shown[k].file), &w, &h);
        uint8_t *want = kh_direct_view(kh_path("scene.ini"), shown[k].az, 38.0, shown[k].zoom, 96,
                                       64, &no_gl);
        CHECK(got && want && w == 96 && h == 64 && !memcmp(got, want, (size_t)96 * 64 * 4),
              "%s (%dx%d) != the library's view from azimuth %g, elevation 38, zoom %g",
              shown[k].file, w, h, shown[k].az, shown[k].zoom);
        free(got);
        free(want);
    }
    /* "frame N T RENDER_MS PASSES_RAN ...": the camera moves (frames 2, 3)
     * ran one pass, the view. */
    char *s = kh_read(kh_path("stats.txt"));
    int ran[4] = {-1, -1, -1, -1};
    for (char *line = s; line && *line; line = strchr(line, '\n') ? strchr(line, '\n') + 1 : NULL) {
        int n, r;
        long long t;
        double ms;
        if (sscanf(line, "frame %d %lld %lf %d", &n, &t, &ms, &r) == 4 && n >= 0 && n < 4)
            ran[n] = r;
    }
    free(s);
    CHECK(ran[2] == 1 && ran[3] == 1, "camera moves ran %d and %d passes, want 1 (the view)",
          ran[2], ran[3]);
    if (failures) {
        dump(kh_path("err.txt"));
        dump(kh_path("stats.txt"));
    }
}

/* ---- replay ------------------------------------------------------------------ */

static const char *const config =
    "[knob az]\naction = key.azimuth\nstep = 2\n"            /* wraps in [0, 360) */
    "[knob el]\naction = key.elevation\nstep = 1\nmin = 5\nmax = 90\n"
    "[button ov]\naction = overlay.toggle\n";

/* Each line with the value it implies.  Times 250 ms apart so that each
 * event is usually its own batch; the checks hold however they batch. */
static const char *const script =
    "100  az turn 5      # phi 30 + 10 = 40\n"
    "350  el turn -3     # elev 20 - 3 = 17\n"
    "600  az turn -25    # phi 40 - 50 = -10 -> wraps to 350\n"
    "850  el turn 200    # elev 217 -> clamped to 90\n"
    "1100 el turn 1      # at the limit: no change, no frame\n"
    "1350 el turn -30    # elev 60\n"
    "1350 az turn 3      # phi 356, same time: same frame\n";

/* amortize: with --amortize 1 frames without events follow until the
 * image has caught up (one visibility pass a frame); the last frame must
 * still be the direct render. */
static void replay(const char *kiosk, const char *hfgen, int amortize)
{
    make_scene(hfgen, "30,20,3,100");
    kh_write(kh_path("c.ini"), config);
    kh_write(kh_path("r.txt"), script);
    char *const argv[] = {(char *)kiosk, (char *)kh_path("scene.ini"), "--input",
                          (char *)kh_path("c.ini"), "--replay", (char *)kh_path("r.txt"),
                          "--display", "headless", "--exposure", "0", "--out", (char *)kh_path("f-%02d.png"),
                          "--stats", (char *)kh_path("stats.txt"), "--exit-after-replay",
                          amortize ? "--amortize" : NULL, "1", NULL};
    pid_t pid = kh_spawn(argv, kh_path("err.txt"));
    const int st = pid > 0 ? kh_wait(pid, 120) : -1;
    CHECK(exited_ok(st), "replay run: status %d", st);

    /* Frames: the first one, then one per batch that changed something. */
    const int frames = kh_count_lines(kh_path("stats.txt"), "frame ");
    int files = 0;
    char name[32];
    for (int i = 0; i < 20; ++i) {
        snprintf(name, sizeof name, "f-%02d.png", i);
        files += access(kh_path(name), F_OK) == 0;
    }
    CHECK(frames >= 2 && files == frames, "%d frame files, %d frame lines", files, frames);
    CHECK(kh_count_lines(kh_path("stats.txt"), "event ") == 7, "7 event lines");

    /* Every changing event is shown by a frame, the clamped one changed
     * nothing, and each frame after the first shows at least one event. */
    char *s = kh_read(kh_path("stats.txt"));
    int shown_by[20] = {0}, changed = 0, unchanged = 0, lost = 0;
    for (char *line = s; line && *line; line = strchr(line, '\n') ? strchr(line, '\n') + 1 : NULL) {
        long long te, tp, lat;
        int frame, ch;
        if (sscanf(line, "event %lld %lld %lld %d %d", &te, &tp, &lat, &frame, &ch) != 5)
            continue;
        changed += ch;
        unchanged += !ch;
        if (ch && (frame < 1 || lat < 0))
            ++lost;
        if (frame >= 0 && frame < 20)
            shown_by[frame]++;
    }
    free(s);
    CHECK(changed == 6 && unchanged == 1 && lost == 0,
          "events: %d changed, %d unchanged, %d changed but never shown", changed, unchanged,
          lost);
    for (int f = 1; f < frames && f < 20 && !amortize; ++f)
        CHECK(shown_by[f] > 0, "frame %d shows no event (a frame without input)", f);

    snprintf(name, sizeof name, "f-%02d.png", frames - 1);
    CHECK(frame_is(kh_path("f-00.png"), NAN, NAN), "first frame != direct render");
    CHECK(frame_is(kh_path(name), 356, 60), "last frame != direct render at phi 356, elev 60");
    CHECK(!frames_equal(kh_path("f-00.png"), kh_path(name)), "the light did not move");
    CHECK(kh_count_lines(kh_path("stats.txt"), "exit ") == 1, "stats: no exit line");
    if (failures) {
        dump(kh_path("err.txt"));
        dump(kh_path("stats.txt"));
    }
}

/* ---- signals ----------------------------------------------------------------- */

/* The kiosk log's lines that start a reload check, and all the others. */
static int checking_lines(void)
{
    return kh_count_lines(kh_path("err.txt"), "<6>SIGHUP: checking ");
}

static int outcome_lines(void)
{
    return kh_count_lines(kh_path("err.txt"), "") - checking_lines();
}

/* The state letter of process pid in /proc/PID/stat (R, S, T stopped, Z
 * a zombie, ...), 0 when there is no such process. */
static char proc_state(pid_t pid)
{
    char path[64], buf[512];
    snprintf(path, sizeof path, "/proc/%d/stat", (int)pid);
    FILE *f = fopen(path, "r");
    if (!f)
        return 0;
    const size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    const char *p = strrchr(buf, ')'); /* the name may hold spaces and parentheses */
    return p && p[1] == ' ' ? p[2] : 0;
}

/* The process the n-th (from 1) "SIGHUP: checking ... in process PID"
 * line of the kiosk's log names, or -1. */
static pid_t check_pid(int n)
{
    char *log = kh_read(kh_path("err.txt"));
    const char *p = log;
    for (int i = 0; p && i < n; ++i)
        if ((p = strstr(p, "SIGHUP: checking ")) != NULL)
            p += 17;
    const char *in = p ? strstr(p, " in process ") : NULL;
    const pid_t pid = in ? (pid_t)atoi(in + 12) : -1;
    free(log);
    return pid > 0 ? pid : -1;
}

/* A reload check that crashes (killed by SIGABRT, as a failed assertion
 * in a driver would; not SIGSEGV, which AddressSanitizer builds catch and
 * turn into an exit status) is a failed check, not a passed one: one
 * "<3>reload failed" line saying what killed it, the running scene kept.
 * The check process the kiosk names is held (SIGSTOP, seen stopped in
 * /proc) before it can end, sent SIGABRT and let go (SIGCONT); one that
 * ended first (a fast machine) is tried again with another SIGHUP. */
static void crashed_check(pid_t pid)
{
    kh_write(kh_path("c.ini"), config); /* the configuration mended */
    for (int attempt = 0; attempt < 5; ++attempt) {
        const int n = checking_lines() + 1, failed = kh_count_lines(kh_path("err.txt"),
                                                                     "<3>reload failed");
        const int reloads = kh_count_lines(kh_path("stats.txt"), "reload ");
        kill(pid, SIGHUP);
        if (!kh_wait_lines(pid, kh_path("err.txt"), "<6>SIGHUP: checking ", n, 60)) {
            CHECK(0, "crashed check: no 'checking' line");
            return;
        }
        const pid_t c = check_pid(n);
        int held = c > 0 && kill(c, SIGSTOP) == 0;
        for (int i = 0; held && i < 400 && proc_state(c) != 'T' && proc_state(c) != 'Z' &&
                        proc_state(c) != 0; ++i)
            kh_sleep(0.005);
        held = held && proc_state(c) == 'T';
        if (held) {
            const struct rlimit no_core = {0, 0}; /* no core file of a GL process */
            prlimit(c, RLIMIT_CORE, &no_core, NULL);
            kill(c, SIGABRT);
            kill(c, SIGCONT);
        }
        CHECK(kh_wait_lines(pid, kh_path("stats.txt"), "reload ", reloads + 1, 60),
              "crashed check: no reload line");
        if (!held)
            continue;
        char *err = kh_read(kh_path("err.txt"));
        const char *last = err ? strstr(err, "SIGHUP: checking") : NULL;
        for (int i = 1; last && i < n; ++i)
            last = strstr(last + 1, "SIGHUP: checking");
        printf("crashed check (process %d, attempt %d): %s", (int)c, attempt + 1,
               last ? strchr(last, '\n') + 1 : "");
        CHECK(kh_count_lines(kh_path("err.txt"), "<3>reload failed") == failed + 1 && last &&
                  strstr(last, "died of Aborted") && !strstr(last, "reloaded"),
              "a check killed by SIGABRT: not one '<3>reload failed ... died of' line");
        free(err);
        CHECK(kill(pid, 0) == 0 && waitpid(pid, NULL, WNOHANG) == 0, "died on a crashed check");
        return;
    }
    CHECK(0, "crashed check: the check ended before it could be held, 5 times");
}

static void signals(const char *kiosk, const char *hfgen)
{
    make_scene(hfgen, "30,20,3,100");
    /* Pretend stderr is the journal: its dev:inode in JOURNAL_STREAM. */
    kh_write(kh_path("err.txt"), "");
    struct stat stt;
    if (stat(kh_path("err.txt"), &stt) == 0) {
        char js[64];
        snprintf(js, sizeof js, "%llu:%llu", (unsigned long long)stt.st_dev,
                 (unsigned long long)stt.st_ino);
        setenv("JOURNAL_STREAM", js, 1);
    }
    kh_write(kh_path("c.ini"), config);
    char *const argv[] = {(char *)kiosk, (char *)kh_path("scene.ini"), "--input",
                          (char *)kh_path("c.ini"), "--display", "headless", "--exposure", "0", "--out",
                          (char *)kh_path("f-%02d.png"), "--stats", (char *)kh_path("stats.txt"),
                          NULL};
    pid_t pid = kh_spawn(argv, kh_path("err.txt"));
    unsetenv("JOURNAL_STREAM");
    if (pid < 0) {
        CHECK(0, "spawn");
        return;
    }
    CHECK(kh_wait_lines(pid, kh_path("stats.txt"), "frame ", 1, 60), "no first frame");

    /* An edited scene: the key light elsewhere. */
    make_scene(hfgen, "120,45,3,100");
    kill(pid, SIGHUP);
    CHECK(kh_wait_lines(pid, kh_path("stats.txt"), "frame ", 2, 60), "no frame after SIGHUP");
    CHECK(frame_is(kh_path("f-01.png"), NAN, NAN), "frame after SIGHUP != the edited scene");
    CHECK(kh_count_lines(kh_path("err.txt"), "<6>reloaded ") == 1, "no <6>reloaded line");

    /* A broken scene: one error line, the kiosk keeps running.  Each SIGHUP
     * also says, when its check starts, which process checks (the event
     * hostile.sh's term_during_reload_check waits on): one such line per
     * SIGHUP, and one line for the outcome. */
    CHECK(checking_lines() == 1, "SIGHUP: %d 'checking' lines, want 1", checking_lines());
    const int lines_before = outcome_lines();
    kh_write(kh_path("scene.ini"), "height = cones.pfm\nk = 99\n");
    kill(pid, SIGHUP);
    CHECK(kh_wait_lines(pid, kh_path("stats.txt"), "reload ", 2, 60), "second reload not seen");
    kh_sleep(0.2);
    CHECK(kill(pid, 0) == 0 && waitpid(pid, NULL, WNOHANG) == 0, "died on a broken scene");
    CHECK(outcome_lines() == lines_before + 1, "broken scene: %d lines logged, want 1",
          outcome_lines() - lines_before);
    CHECK(checking_lines() == 2, "second SIGHUP: %d 'checking' lines, want 2", checking_lines());
    CHECK(kh_count_lines(kh_path("err.txt"), "<3>reload failed") == 1 &&
              kh_count_lines(kh_path("err.txt"), "") > 0,
          "no <3>reload failed line");
    char *err = kh_read(kh_path("err.txt"));
    CHECK(err && strstr(err, "scene.ini:2: k: 99"), "the error names the file and line");
    free(err);
    CHECK(kh_count_lines(kh_path("stats.txt"), "frame ") == 2, "a frame for a failed reload");

    /* The scene mended, the configuration broken: one line again. */
    make_scene(hfgen, "120,45,3,100");
    kh_write(kh_path("c.ini"), "[knob az]\naction = key.azimuth\nstep = 2x\n");
    kill(pid, SIGHUP);
    CHECK(kh_wait_lines(pid, kh_path("stats.txt"), "reload ", 3, 60), "third reload not seen");
    CHECK(kh_count_lines(kh_path("err.txt"), "<3>reload failed") == 2 &&
              outcome_lines() == lines_before + 2 && checking_lines() == 3,
          "broken configuration: not one <3> line");
    err = kh_read(kh_path("err.txt"));
    CHECK(err && strstr(err, "c.ini:3: step: '2x' is not a number"),
          "the error names the configuration's line");
    free(err);
    CHECK(kill(pid, 0) == 0 && waitpid(pid, NULL, WNOHANG) == 0, "died on a broken config");
    crashed_check(pid);

    kill(pid, SIGTERM);
    const int st = kh_wait(pid, 60);
    CHECK(exited_ok(st), "SIGTERM: status %d", st);
    CHECK(kh_count_lines(kh_path("stats.txt"), "exit ") == 1, "stats: no exit line");
    int w, h;
    uint8_t *px = kh_png_rgba(kh_path("f-01.png"), &w, &h);
    CHECK(px != NULL, "f-01.png unreadable");
    free(px);
    if (failures) {
        dump(kh_path("err.txt"));
        dump(kh_path("stats.txt"));
    }
}

/* ---- idle --------------------------------------------------------------------- */

static void idle(const char *kiosk, const char *hfgen)
{
    make_scene(hfgen, "30,20,3,100");
    kh_write(kh_path("c.ini"), config);
    char *const argv[] = {(char *)kiosk, (char *)kh_path("scene.ini"), "--input",
                          (char *)kh_path("c.ini"), "--display", "headless", "--exposure", "0", "--stats",
                          (char *)kh_path("stats.txt"), NULL};
    pid_t pid = kh_spawn(argv, kh_path("err.txt"));
    if (pid < 0) {
        CHECK(0, "spawn");
        return;
    }
    CHECK(kh_wait_lines(pid, kh_path("stats.txt"), "frame ", 1, 60), "no first frame");
    kh_sleep(3.0);
    kill(pid, SIGTERM);
    CHECK(exited_ok(kh_wait(pid, 60)), "SIGTERM: bad exit");
    char *s = kh_read(kh_path("stats.txt"));
    long long t0 = 0, c0 = 0, t1 = 0, c1 = 0;
    int frames = -1;
    const char *f = s ? strstr(s, "\nframe 0 ") : NULL;
    const char *e = s ? strstr(s, "\nexit ") : NULL;
    double ms;
    int ran, tot, ev;
    if (!f || sscanf(f, "\nframe 0 %lld %lf %d %d %d %lld", &t0, &ms, &ran, &tot, &ev, &c0) != 6 ||
        !e || sscanf(e, "\nexit %lld %lld %d", &t1, &c1, &frames) != 3) {
        CHECK(0, "stats unreadable");
    } else {
        const double cpu = (double)(c1 - c0) / 1e6, wall = (double)(t1 - t0) / 1e9;
        printf("idle: %.3f s CPU in %.2f s = %.2f%% of one core, %d frame(s)\n", cpu, wall,
               100.0 * cpu / wall, frames);
        CHECK(wall > 2.5, "idle period %.2f s", wall);
        CHECK(cpu < 0.05 * wall, "idle CPU %.2f%% of one core (limit 5%%)", 100.0 * cpu / wall);
        CHECK(frames == 1, "%d frames while idle, want only the first", frames);
    }
    free(s);
    if (failures)
        dump(kh_path("err.txt"));
}

/* ---- the shipped example ------------------------------------------------------ */

static void example(const char *kiosk, const char *scene, const char *cfg, const char *script_path)
{
    char *const argv[] = {(char *)kiosk, (char *)scene, "--input", (char *)cfg, "--no-devices",
                          "--replay", (char *)script_path, "--display", "headless", "--exposure", "0", "--overlay",
                          "--out", (char *)kh_path("f-%02d.png"), "--stats",
                          (char *)kh_path("stats.txt"), "--exit-after-replay", NULL};
    pid_t pid = kh_spawn(argv, kh_path("err.txt"));
    const int st = pid > 0 ? kh_wait(pid, 300) : -1;
    CHECK(exited_ok(st), "example run: status %d", st);
    CHECK(kh_count_lines(kh_path("stats.txt"), "frame ") >= 2, "no frame after the first");
    CHECK(kh_count_lines(kh_path("stats.txt"), "event ") >= 1, "no event");
    /* Every control of the script exists in the example: no warnings. */
    CHECK(kh_count_lines(kh_path("err.txt"), "") == 2, "log: %d lines, want start + end",
          kh_count_lines(kh_path("err.txt"), ""));
    CHECK(!frames_equal(kh_path("f-00.png"), kh_path("f-01.png")), "the knobs changed nothing");
    if (failures) {
        dump(kh_path("err.txt"));
        dump(kh_path("stats.txt"));
    }
}

/* A field larger than any display's side (2100 x 40 > HFS_DISPLAY_MAX_SIDE)
 * is shown shrunk by an integer factor (2: 1050 x 20), averaged in linear
 * light, instead of failing its first frame; the picture equals the
 * library's render shrunk the same way (CPU backend: no GL needed). */
static void large(const char *kiosk, const char *hfgen)
{
    char *const gen[] = {(char *)hfgen, "cones", "--size", "2100x40", "-o",
                         (char *)kh_path("wide.pfm"), NULL};
    pid_t pid = kh_spawn(gen, kh_path("hfgen.log"));
    int st = pid > 0 ? kh_wait(pid, 60) : -1;
    CHECK(st != -1 && WIFEXITED(st) && WEXITSTATUS(st) == 0, "hfgen failed");
    kh_write(kh_path("wide.ini"), "height = wide.pfm\nbackend = cpu\n"
                                  "env-sh = 1.0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0\n"
                                  "key = 30,20,2,5\n");
    kh_write(kh_path("empty.txt"), "");
    char *const argv[] = {(char *)kiosk, (char *)kh_path("wide.ini"), "--display", "headless", "--exposure", "0",
                          "--replay", (char *)kh_path("empty.txt"), "--exit-after-replay",
                          "--out", (char *)kh_path("w-%02d.png"), NULL};
    pid = kh_spawn(argv, kh_path("err.txt"));
    st = pid > 0 ? kh_wait(pid, 120) : -1;
    CHECK(exited_ok(st), "2100x40 field: status %d", st);
    int w = 0, h = 0;
    uint8_t *shown = kh_png_rgba(kh_path("w-00.png"), &w, &h);
    CHECK(shown && w == 1050 && h == 20, "picture %dx%d, want 1050x20", w, h);

    hfs_error err = {{0}};
    hfs_scene sc;
    hfs_scene_inputs in;
    memset(&in, 0, sizeof in);
    hfs_renderer *r = NULL;
    hfs_image img = {0}, small = {0};
    uint8_t *want = malloc((size_t)1050 * 20 * 4);
    hfs_scene_init(&sc);
    const int ok = want && !hfs_scene_load_file(&sc, kh_path("wide.ini"), &err) &&
                   !hfs_scene_inputs_load(&sc, &in, &err) &&
                   !hfs_renderer_create(&(hfs_renderer_desc){.backend = HFS_BACKEND_CPU}, &r,
                                        &err) &&
                   !hfs_image_alloc(&img, 2100, 40, &err) &&
                   !hfs_image_alloc(&small, 1050, 20, &err) &&
                   !hfs_renderer_render(r, &in.field, &in.lighting, &in.quality, &img, NULL,
                                        NULL, &err);
    CHECK(ok, "direct render: %s", err.msg);
    if (ok && shown && w == 1050 && h == 20) {
        hfs_image_shrink(&img, 2, &small);
        CHECK(!hfs_frame_to_rgba8(&small, &KH_PICTURE, want, &err) &&
                  !memcmp(want, shown, (size_t)1050 * 20 * 4),
              "the kiosk's shrunk picture differs from the library's render shrunk");
    }
    free(want);
    free(shown);
    hfs_image_free(&img);
    hfs_image_free(&small);
    hfs_renderer_destroy(r);
    hfs_scene_inputs_free(&in);
    if (failures)
        dump(kh_path("err.txt"));
}

int main(int argc, char **argv)
{
    if (argc < 4) {
        fprintf(stderr, "usage: test_kiosk replay|signals|idle KIOSK HFGEN\n"
                        "       test_kiosk example KIOSK SCENE CONFIG REPLAY\n");
        return 2;
    }
    if (strcmp(argv[1], "large")) /* the CPU backend's test needs no GL */
        kh_require_gl();
    if (!kh_tmpdir("hfs_kiosk")) {
        perror("mkdtemp");
        return 1;
    }
    const char *mode = argv[1];
    if (!strcmp(mode, "replay"))
        replay(argv[2], argv[3], 0);
    else if (!strcmp(mode, "view"))
        view(argv[2], argv[3]);
    else if (!strcmp(mode, "amortize"))
        replay(argv[2], argv[3], 1);
    else if (!strcmp(mode, "signals"))
        signals(argv[2], argv[3]);
    else if (!strcmp(mode, "idle"))
        idle(argv[2], argv[3]);
    else if (!strcmp(mode, "large"))
        large(argv[2], argv[3]);
    else if (!strcmp(mode, "example") && argc == 6)
        example(argv[2], argv[3], argv[4], argv[5]);
    else {
        fprintf(stderr, "test_kiosk: unknown mode %s\n", mode);
        return 2;
    }
    kh_rm_tmpdir();
    if (failures)
        fprintf(stderr, "test_kiosk %s: %d failure(s)\n", mode, failures);
    else
        printf("test_kiosk %s: all checks passed\n", mode);
    return failures ? 1 : 0;
}
