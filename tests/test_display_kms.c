/*
 * test_display_kms.c — the "kms" display (label "gl").
 *
 *   nodev   Where no /dev/dri/card* exists (this development machine, CI
 *           containers): opening "kms" fails with HFS_E_CONTEXT and the one
 *           line "display kms: no DRM device with a connected connector
 *           (/dev/dri: none)", an explicit missing device names itself, and
 *           nothing leaks (ASan).  Skipped (77) where a card exists.
 *   smoke   Real KMS: opens the first connected connector, presents 120
 *           frames (a moving bar; each waits for its page flip, so about
 *           two seconds at 60 Hz), checks the frame rate is plausible, and
 *           closes (the console comes back).  Skipped (77) without a card,
 *           or when the display cannot be had here (no master: a display
 *           server is running), with the reason.
 */
#include "display.h"

#include <glob.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "check.h"

#define SKIP 77

static int have_cards(void)
{
    glob_t g;
    int n = glob("/dev/dri/card*", 0, NULL, &g) == 0 ? (int)g.gl_pathc : 0;
    globfree(&g);
    return n;
}

static int mode_nodev(void)
{
    if (have_cards()) {
        printf("SKIP: /dev/dri/card* exists here; the no-device path is not testable\n");
        return SKIP;
    }
    hfs_display *d = (hfs_display *)&d;
    hfs_error err = {""};
    int rc = hfs_display_open("kms", NULL, &d, &err);
    printf("kms: %d \"%s\"\n", rc, err.msg);
    if (rc == HFS_E_UNSUPPORTED) {
        CHECK(!strcmp(err.msg, "display kms: not built (configure with libdrm-dev and "
                               "libgbm-dev installed)"), "%s", err.msg);
        return failures ? 1 : 0;
    }
    CHECK(rc == HFS_E_CONTEXT && d == NULL, "rc %d", rc);
    CHECK(!strcmp(err.msg, "display kms: no DRM device with a connected connector "
                           "(/dev/dri: none)"), "%s", err.msg);
    hfs_display_opts o = {.device = "/dev/dri/card0"};
    rc = hfs_display_open("kms", &o, &d, &err);
    printf("kms /dev/dri/card0: %d \"%s\"\n", rc, err.msg);
    CHECK(rc == HFS_E_CONTEXT && d == NULL, "rc %d", rc);
    CHECK(!strcmp(err.msg, "display kms: /dev/dri/card0: No such file or directory"), "%s",
          err.msg);
    return failures ? 1 : 0;
}

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + t.tv_nsec * 1e-9;
}

static int mode_smoke(void)
{
    if (!have_cards()) {
        printf("SKIP: no /dev/dri/card* here (no KMS device; run on the board)\n");
        return SKIP;
    }
    hfs_display *d = NULL;
    hfs_error err = {""};
    int rc = hfs_display_open("kms", NULL, &d, &err);
    if (rc) {
        printf("SKIP: %s\n", err.msg);
        return SKIP;
    }
    int w = 0, h = 0;
    hfs_display_size(d, &w, &h);
    printf("kms: %dx%d\n", w, h);
    CHECK(w > 0 && h > 0, "size %dx%d", w, h);
    enum { PW = 160, PH = 90, FRAMES = 120 };
    static uint8_t pic[PW * PH * 4];
    uint8_t *cap = NULL;
    int cw, ch;
    CHECK(hfs_display_capture(d, &cap, &cw, &ch, &err) == HFS_E_UNSUPPORTED, "capture");
    double t0 = now_s();
    for (int f = 0; f < FRAMES && !failures; ++f) {
        for (int k = 0; k < PW * PH; ++k) {
            int x = k % PW;
            uint8_t v = (uint8_t)(abs(x - (f * 4) % PW) < 8 ? 255 : 40);
            pic[4 * k] = v;
            pic[4 * k + 1] = (uint8_t)(k / PW * 255 / PH);
            pic[4 * k + 2] = 90;
            pic[4 * k + 3] = 255;
        }
        CHECK(hfs_display_present(d, pic, PW, PH, &err) == 0, "frame %d: %s", f, err.msg);
    }
    double hz = (FRAMES - 1) / (now_s() - t0);
    printf("kms: %.1f frames per second (page flips)\n", hz);
    /* A flip per vblank: 24..240 Hz covers every panel; much faster means
     * the wait for the flip event does not work. */
    CHECK(hz > 20 && hz < 250, "implausible flip rate %.1f Hz", hz);
    hfs_display_close(d);
    return failures ? 1 : 0;
}

int main(int argc, char **argv)
{
    setvbuf(stdout, NULL, _IONBF, 0);
    const char *mode = argc > 1 ? argv[1] : "nodev";
    if (!strcmp(mode, "nodev"))
        return mode_nodev();
    if (!strcmp(mode, "smoke"))
        return mode_smoke();
    fprintf(stderr, "usage: %s nodev|smoke\n", argv[0]);
    return 2;
}
