/*
 * test_display_headless.c — the "headless" display and the dispatch by name
 * (label "unit"):
 *   - numbered PNGs ("display_headless_%03d.png" in the working directory)
 *     decode back to the presented pixels, and capture returns them;
 *   - a fixed canvas shows the picture scaled 2x by nearest neighbour, and
 *     a letterboxed one has black bars;
 *   - refusals: unknown name (exact message), bad sizes, a pattern without
 *     or with a wrong conversion, a picture without pixels, capture before
 *     any present; x11 with DISPLAY unset gives its one-line reason;
 *     hfs_png_write_rgba8's own refusals.
 */
#include "display.h"
#include "hfs_io.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "test_display_util.h"

enum { W = 9, H = 6 };

static void make_picture(uint8_t *px, int seed)
{
    for (int k = 0; k < W * H * 4; ++k)
        px[k] = (uint8_t)(k * 37 + seed * 101);
}

static void check_files(void)
{
    hfs_display_opts o = {.out_pattern = "display_headless_%03d.png"};
    hfs_display *d = NULL;
    hfs_error err = {""};
    uint8_t pic[W * H * 4];
    CHECK(hfs_display_open("headless", &o, &d, &err) == 0, "%s", err.msg);
    if (!d)
        return;
    CHECK(!strcmp(hfs_display_name(d), "headless"), "name");
    CHECK(hfs_display_fd(d) == -1 && hfs_display_handle_events(d) == 0, "events");
    uint8_t *cap = NULL;
    int cw = 0, ch = 0;
    CHECK(hfs_display_capture(d, &cap, &cw, &ch, &err) == HFS_E_INVALID && !cap,
          "capture before present");
    for (int f = 0; f < 3; ++f) {
        make_picture(pic, f);
        CHECK(hfs_display_present(d, pic, W, H, &err) == 0, "%s", err.msg);
        char path[64];
        snprintf(path, sizeof path, "display_headless_%03d.png", f);
        int pw = 0, ph = 0;
        uint8_t *back = read_png_rgba(path, &pw, &ph);
        CHECK(back && pw == W && ph == H, "%s not written or wrong size", path);
        for (int k = 0; back && k < W * H * 4; ++k)
            CHECK(back[k] == (k % 4 == 3 ? 255 : pic[k]), "%s byte %d: %u != %u", path, k,
                  back[k], pic[k]);
        free(back);
    }
    int w = 0, h = 0;
    hfs_display_size(d, &w, &h);
    CHECK(w == W && h == H, "size %dx%d", w, h);
    CHECK(hfs_display_capture(d, &cap, &cw, &ch, &err) == 0 && cw == W && ch == H, "%s",
          err.msg);
    for (int k = 0; cap && k < W * H * 4; ++k)
        CHECK(cap[k] == (k % 4 == 3 ? 255 : pic[k]), "capture byte %d", k);
    free(cap);
    CHECK(hfs_display_present(d, NULL, W, H, &err) == HFS_E_INVALID, "NULL pixels");
    CHECK(hfs_display_present(d, pic, 0, H, &err) == HFS_E_INVALID, "zero width");
    CHECK(!strncmp(err.msg, "display headless: ", 18), "no prefix: %s", err.msg);
    hfs_display_close(d);
}

static void check_canvas(void)
{
    hfs_display_opts o = {.width = 2 * W, .height = 2 * H};
    hfs_display *d = NULL;
    hfs_error err = {""};
    uint8_t pic[W * H * 4], want[4 * W * H * 4];
    make_picture(pic, 5);
    CHECK(hfs_display_open("headless", &o, &d, &err) == 0, "%s", err.msg);
    if (!d)
        return;
    CHECK(hfs_display_present(d, pic, W, H, &err) == 0, "%s", err.msg);
    uint8_t *cap = NULL;
    int cw = 0, ch = 0;
    CHECK(hfs_display_capture(d, &cap, &cw, &ch, &err) == 0 && cw == 2 * W && ch == 2 * H,
          "capture %dx%d", cw, ch);
    scale_nearest(pic, W, H, 2, want);
    long n = 0;
    CHECK(cap && max_rgb_diff(cap, want, 2 * W, 2 * H, &n) == 0, "2x canvas differs (%ld)", n);
    free(cap);
    hfs_display_close(d);

    /* 9x6 on 9x12: letterbox, 3 black rows above and below. */
    o.width = W;
    o.height = 2 * H;
    CHECK(hfs_display_open("headless", &o, &d, &err) == 0, "%s", err.msg);
    if (!d)
        return;
    CHECK(hfs_display_present(d, pic, W, H, &err) == 0, "%s", err.msg);
    CHECK(hfs_display_capture(d, &cap, &cw, &ch, &err) == 0, "%s", err.msg);
    for (int y = 0; cap && y < ch; ++y)
        for (int x = 0; x < cw; ++x) {
            const uint8_t *p = cap + ((size_t)y * (size_t)cw + (size_t)x) * 4;
            if (y < 3 || y >= 9)
                CHECK(!p[0] && !p[1] && !p[2] && p[3] == 255, "bar pixel (%d,%d)", x, y);
            else
                CHECK(!memcmp(p, pic + ((size_t)(y - 3) * W + (size_t)x) * 4, 3),
                      "picture pixel (%d,%d)", x, y);
        }
    free(cap);
    hfs_display_close(d);
}

static void check_refusals(void)
{
    hfs_display *d = (hfs_display *)&d; /* must be reset to NULL */
    hfs_error err = {""};
    CHECK(hfs_display_open("foo", NULL, &d, &err) == HFS_E_INVALID && !d, "unknown name");
    CHECK(!strcmp(err.msg, "display \"foo\": unknown (known: kms, x11, headless)"), "%s",
          err.msg);
    CHECK(hfs_display_open(NULL, NULL, &d, &err) == HFS_E_INVALID, "NULL name");
    hfs_display_opts o = {.width = 10, .height = 0};
    CHECK(hfs_display_open("headless", &o, &d, &err) == HFS_E_INVALID, "width only");
    o.width = -1;
    o.height = 5;
    CHECK(hfs_display_open("headless", &o, &d, &err) == HFS_E_INVALID, "negative size");
    hfs_display_opts p = {.out_pattern = "frame.png"};
    CHECK(hfs_display_open("headless", &p, &d, &err) == HFS_E_INVALID && !d, "no conversion");
    CHECK(strstr(err.msg, "frame.png") != NULL, "%s", err.msg);
    p.out_pattern = "frame-%s.png";
    CHECK(hfs_display_open("headless", &p, &d, &err) == HFS_E_INVALID, "%%s accepted");
    p.out_pattern = "frame-%d-%d.png";
    CHECK(hfs_display_open("headless", &p, &d, &err) == HFS_E_INVALID, "two conversions");
    p.out_pattern = "100%%-%05d.png";
    CHECK(hfs_display_open("headless", &p, &d, &err) == 0, "%%%% refused: %s", err.msg);
    hfs_display_close(d);
    p.out_pattern = "no-such-dir/f%d.png";
    CHECK(hfs_display_open("headless", &p, &d, &err) == 0, "%s", err.msg);
    uint8_t px[4] = {1, 2, 3, 4};
    CHECK(hfs_display_present(d, px, 1, 1, &err) == HFS_E_IO, "write into a missing dir");
    CHECK(!strncmp(err.msg, "display headless: no-such-dir/f0.png", 36), "%s", err.msg);
    hfs_display_close(d);
    hfs_display_close(NULL);

    /* The RGBA writer headless uses (runtime/io) refuses before creating
     * anything. */
    CHECK(hfs_png_write_rgba8("", 1, 1, px, &err) == HFS_E_INVALID, "empty path");
    CHECK(hfs_png_write_rgba8("x.png", 0, 1, px, &err) == HFS_E_INVALID, "zero width");
    CHECK(hfs_png_write_rgba8("x.png", 1, 1, NULL, &err) == HFS_E_INVALID, "no pixels");
    CHECK(hfs_png_write_rgba8("x.png", 1, 100000, px, &err) == HFS_E_INVALID, "huge");
    CHECK(access("x.png", F_OK) != 0, "file left behind by a refusal");

    /* x11 without DISPLAY: one line, non-zero, no object. */
    unsetenv("DISPLAY");
    d = NULL;
    int rc = hfs_display_open("x11", NULL, &d, &err);
    printf("x11 without DISPLAY: %d \"%s\"\n", rc, err.msg);
    CHECK(rc < 0 && !d, "x11 opened without DISPLAY");
    CHECK(rc == HFS_E_UNSUPPORTED || !strcmp(err.msg, "display x11: cannot open X display "
                                                      "(DISPLAY unset)"), "%s", err.msg);
    setenv("DISPLAY", ":9999", 1);
    rc = hfs_display_open("x11", NULL, &d, &err);
    printf("x11 on :9999: %d \"%s\"\n", rc, err.msg);
    CHECK(rc < 0 && !d && strchr(err.msg, '\n') == NULL, "x11 on :9999");
    CHECK(rc == HFS_E_UNSUPPORTED || strstr(err.msg, "':9999'"), "%s", err.msg);
}

int main(void)
{
    check_files();
    check_canvas();
    check_refusals();
    if (failures)
        fprintf(stderr, "%d check(s) failed\n", failures);
    return failures ? 1 : 0;
}
