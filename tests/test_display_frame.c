/*
 * test_display_frame.c — the display's pure parts (label "unit"):
 *   - frame_image: the picture equals the PNG writer's bytes for the same
 *     render (clamp and Reinhard, exposure), in the same row order (row
 *     j = 0 at the top, SPEC), alpha 255; bad inputs are refused without
 *     writing.
 *   - overlay: the exact pixels of a digit at scale 1 and 2, the box, and
 *     clipping at every edge (ASan checks the writes); the kiosk's label
 *     readable on a white and on a black frame (contrast ratios).
 *   - the fit of a picture on a screen (1:1, integer, letterbox, pillarbox).
 * Run from the build directory (writes display_frame_*.png there).
 */
#include "display_backend.h"
#include "frame_image.h"
#include "overlay.h"

#include <math.h>
#include <string.h>

#include "check.h"
#include "test_display_util.h"

static void check_frame_vs_png(const hfs_png_opts *o, const char *path)
{
    enum { W = 7, H = 5 };
    hfs_image img = {0};
    hfs_error err = {""};
    CHECK(hfs_image_alloc(&img, W, H, &err) == 0, "%s", err.msg);
    /* Every regime of the mapping: negative, 0, the linear toe of the sRGB
     * curve, mid-tones, 1 and beyond, large. */
    for (int k = 0; k < W * H * 3; ++k)
        img.rgb[k] = (float)(k % 11 == 0 ? -0.25 : 0.0021 * pow(1.37, k % 29) - 0.001 * (k % 3));
    img.rgb[5] = 0.0f;
    img.rgb[6] = 1.0f;
    img.rgb[7] = 1e6f;

    uint8_t frame[W * H * 4];
    CHECK(hfs_frame_to_rgba8(&img, o, frame, &err) == 0, "%s", err.msg);
    CHECK(hfs_png_write(path, &img, o, &err) == 0, "%s", err.msg);
    int pw = 0, ph = 0;
    uint8_t *png = read_png_rgba(path, &pw, &ph);
    CHECK(png && pw == W && ph == H, "%s: cannot read back", path);
    for (int j = 0; png && j < H; ++j)
        for (int i = 0; i < W; ++i) {
            const uint8_t *f = frame + ((size_t)j * W + (size_t)i) * 4;
            const uint8_t *p = png + ((size_t)j * W + (size_t)i) * 4;
            CHECK(!memcmp(f, p, 3), "texel (%d,%d): frame %u,%u,%u png %u,%u,%u", i, j, f[0],
                  f[1], f[2], p[0], p[1], p[2]);
            CHECK(f[3] == 255, "alpha %u", f[3]);
        }
    free(png);
    hfs_image_free(&img);
}

static void check_frame_errors(void)
{
    hfs_image img = {0};
    hfs_error err = {""};
    uint8_t out[2 * 2 * 4], before[sizeof out];
    hfs_image_alloc(&img, 2, 2, &err);
    memset(img.rgb, 0, 12 * sizeof(float));
    memset(out, 0x5a, sizeof out);
    memcpy(before, out, sizeof out);
    img.rgb[7] = NAN;
    CHECK(hfs_frame_to_rgba8(&img, NULL, out, &err) == HFS_E_INVALID, "NaN accepted");
    CHECK(strstr(err.msg, "(0, 1)") != NULL, "NaN not located: %s", err.msg);
    img.rgb[7] = 0.0f;
    hfs_png_opts o = {.exposure = -1.0};
    CHECK(hfs_frame_to_rgba8(&img, &o, out, &err) == HFS_E_INVALID, "negative exposure");
    o.exposure = INFINITY;
    CHECK(hfs_frame_to_rgba8(&img, &o, out, &err) == HFS_E_INVALID, "infinite exposure");
    o.exposure = 1.0;
    o.tonemap = (hfs_tonemap)7;
    CHECK(hfs_frame_to_rgba8(&img, &o, out, &err) == HFS_E_INVALID, "bad tone map");
    CHECK(!memcmp(out, before, sizeof out), "output written on failure");
    CHECK(hfs_frame_to_rgba8(NULL, NULL, out, &err) == HFS_E_INVALID, "NULL image");
    CHECK(hfs_frame_to_rgba8(&img, NULL, NULL, &err) == HFS_E_INVALID, "NULL output");
    hfs_image_free(&img);
}

/* The '1' glyph of the font, as it must appear (bit 4 = left). */
static const char *const one_rows[7] = {
    "..#..",
    ".##..",
    "..#..",
    "..#..",
    "..#..",
    "..#..",
    ".###.",
};

static void check_overlay_digit(int scale)
{
    enum { W = 24, H = 24 };
    uint8_t px[W * H * 4];
    const uint8_t fg[4] = {255, 255, 255, 255}, bg[4] = {0, 0, 0, 255};
    memset(px, 100, sizeof px);
    const int x0 = 3, y0 = 2;
    hfs_overlay_text(px, W, H, x0, y0, scale, "1", fg, bg);
    int bw, bh;
    hfs_overlay_text_size("1", scale, &bw, &bh);
    CHECK(bw == 7 * scale && bh == 9 * scale, "box %dx%d at scale %d", bw, bh, scale);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const uint8_t *p = px + ((size_t)y * W + (size_t)x) * 4;
            int in_box = x >= x0 && x < x0 + bw && y >= y0 && y < y0 + bh;
            int gx = (x - x0) / scale - 1, gy = (y - y0) / scale - 1;
            int on = in_box && gx >= 0 && gx < 5 && gy >= 0 && gy < 7 &&
                     one_rows[gy][gx] == '#';
            uint8_t want = on ? 255 : in_box ? 0 : 100;
            CHECK(p[0] == want && p[1] == want && p[2] == want,
                  "scale %d pixel (%d,%d) = %u, want %u", scale, x, y, p[0], want);
        }
    uint8_t rows[7];
    CHECK(hfs_overlay_glyph('1', rows) == 1, "'1' missing");
    CHECK(rows[0] == 0x04 && rows[1] == 0x0C && rows[6] == 0x0E, "'1' rows changed");
    CHECK(hfs_overlay_glyph('\x01', rows) == 0, "control character claimed");
    uint8_t q[7];
    hfs_overlay_glyph('?', q);
    CHECK(!memcmp(rows, q, 7), "unknown character is not drawn as '?'");
}

static void check_overlay_clipping(void)
{
    enum { W = 10, H = 6 };
    /* Guard bytes around the picture catch writes outside it even without
     * ASan. */
    uint8_t buf[(W * H + 8) * 4];
    uint8_t *px = buf + 16;
    const uint8_t fg[4] = {255, 0, 0, 255}, bg[4] = {0, 0, 255, 128};
    const char *text = "12.3 ms 7/9 100% :";
    static const int pos[][2] = {{-50, -3}, {-7, 2}, {8, -8}, {9, 5}, {0, 0},
                                 {-2147483647, 0}, {2147483647, 2147483647}, {3, -20}};
    for (size_t t = 0; t < sizeof pos / sizeof pos[0]; ++t)
        for (int scale = 0; scale <= 3; ++scale) {
            memset(buf, 0xee, sizeof buf);
            memset(px, 10, (size_t)W * H * 4);
            hfs_overlay_text(px, W, H, pos[t][0], pos[t][1], scale, text, fg, bg);
            for (int k = 0; k < 16; ++k)
                CHECK(buf[k] == 0xee && buf[sizeof buf - 1 - k] == 0xee,
                      "write outside the picture at (%d,%d) scale %d", pos[t][0], pos[t][1],
                      scale);
        }
    /* Half-transparent box: 50% blue over grey 10. */
    memset(px, 10, (size_t)W * H * 4);
    hfs_overlay_text(px, W, H, 0, 0, 1, " ", fg, bg);
    CHECK(px[0] == 5 && px[1] == 5 && px[2] == 133, "blend gave %u,%u,%u", px[0], px[1], px[2]);
    int w = -1, h = -1;
    hfs_overlay_text_size("", 2, &w, &h);
    CHECK(w == 0 && h == 0, "empty text has size %dx%d", w, h);
}

/* WCAG 2 contrast ratio of two sRGB byte triples. */
static double wcag_luminance(const uint8_t *p)
{
    double y = 0.0;
    static const double wt[3] = {0.2126, 0.7152, 0.0722};
    for (int k = 0; k < 3; ++k) {
        const double c = p[k] / 255.0;
        y += wt[k] * (c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4));
    }
    return y;
}

static double contrast(const uint8_t *a, const uint8_t *b)
{
    const double la = wcag_luminance(a), lb = wcag_luminance(b);
    return (fmax(la, lb) + 0.05) / (fmin(la, lb) + 0.05);
}

/* The kiosk's label (hfs_overlay_label) on an all-white and an all-black
 * frame, scales 1 and 2: every text pixel (white) against every backing
 * pixel of its box (the rest of the box) by at least WCAG AA's 4.5:1, and
 * against its four neighbours that are not text (the ring a reader's eye
 * separates the glyph by) by at least AAA's 7:1.  Measured: 6.4:1 and
 * 21:1 on white (the box alone would give the ring 6.4:1), 21:1 and 21:1
 * on black. */
static void check_overlay_contrast(void)
{
    enum { W = 200, H = 24 };
    static uint8_t px[W * H * 4];
    const char *text = "12.3 ms 7/9 passes kiosk";
    for (int frame = 0; frame < 2; ++frame)
        for (int scale = 1; scale <= 2; ++scale) {
            memset(px, frame ? 0 : 255, sizeof px);
            hfs_overlay_label(px, W, H, 2, 2, scale, text);
            int bw, bh, n_text = 0;
            hfs_overlay_text_size(text, scale, &bw, &bh);
            double backing = 1e9, ring = 1e9;
            for (int y = 2; y < 2 + bh && y < H; ++y)
                for (int x = 2; x < 2 + bw && x < W; ++x) {
                    const uint8_t *p = px + 4 * (y * W + x);
                    if (p[0] != 255 || p[1] != 255 || p[2] != 255)
                        continue;
                    ++n_text;
                    static const int nb[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
                    for (int k = 0; k < 4; ++k) {
                        const uint8_t *q = px + 4 * ((y + nb[k][1]) * W + x + nb[k][0]);
                        if (q[0] != 255 || q[1] != 255 || q[2] != 255)
                            ring = fmin(ring, contrast(p, q));
                    }
                }
            const uint8_t white[3] = {255, 255, 255};
            for (int y = 2; y < 2 + bh && y < H; ++y)
                for (int x = 2; x < 2 + bw && x < W; ++x) {
                    const uint8_t *p = px + 4 * (y * W + x);
                    if (p[0] != 255 || p[1] != 255 || p[2] != 255)
                        backing = fmin(backing, contrast(white, p));
                }
            printf("overlay on %s, scale %d: %d text pixels, backing %.1f:1, ring %.1f:1\n",
                   frame ? "black" : "white", scale, n_text, backing, ring);
            CHECK(n_text > 100 && backing >= 4.5 && ring >= 7.0, "overlay on %s, scale %d: %d "
                  "text pixels, backing %.2f:1 (want >= 4.5), ring %.2f:1 (want >= 7)",
                  frame ? "black" : "white", scale, n_text, backing, ring);
        }
}

static void check_fit(void)
{
    hfs_display_fit f = hfs_display_fit_rect(64, 48, 64, 48);
    CHECK(f.x == 0 && f.y == 0 && f.w == 64 && f.h == 48 && f.nearest, "1:1");
    f = hfs_display_fit_rect(64, 48, 128, 96);
    CHECK(f.x == 0 && f.y == 0 && f.w == 128 && f.h == 96 && f.nearest, "2x");
    f = hfs_display_fit_rect(64, 48, 100, 100);
    CHECK(f.x == 0 && f.y == 12 && f.w == 100 && f.h == 75 && !f.nearest,
          "letterbox %d,%d %dx%d", f.x, f.y, f.w, f.h);
    f = hfs_display_fit_rect(256, 256, 1920, 1080);
    CHECK(f.x == 420 && f.y == 0 && f.w == 1080 && f.h == 1080 && !f.nearest,
          "pillarbox %d,%d %dx%d", f.x, f.y, f.w, f.h);
    f = hfs_display_fit_rect(256, 256, 800, 600);
    CHECK(f.w == 600 && f.h == 600 && f.x == 100 && !f.nearest, "800x600");
    f = hfs_display_fit_rect(100, 1, 10, 10);
    CHECK(f.w == 10 && f.h == 1, "thin picture keeps a row: %dx%d", f.w, f.h);
}

/* The kiosk's exposure over time (hfs_exposure_smooth): a step of the
 * scene's brightness by 6 stops, up and down, at 60, 24 and 7 frames a
 * second with jittered frame times: every step moves towards the target,
 * never past it, and is where continuous smoothing would be at that time,
 * 1 - exp(-t / tau) of the step, whatever the frame times (63% after one
 * time constant, 0.5 s); within 1/64 stop after 3.5 s; and a knob turned through
 * alternating bright and dark frames (+-3 stops each frame) moves the
 * exposure by less than half a stop a frame (no pumping). */
static void check_exposure_smoothing(void)
{
    static const double rates[3] = {60.0, 24.0, 7.0};
    for (int r = 0; r < 3; ++r)
        for (int dir = -1; dir <= 1; dir += 2) {
            const double target = 6.0 * dir, tau = HFS_KIOSK_EXPOSURE_TAU;
            double ev = 0.0, t = 0.0;
            unsigned seed = 12345u + (unsigned)r;
            while (t < 3.5) {
                seed = seed * 1103515245u + 12345u;
                const double dt = (0.5 + (seed >> 16) % 1000 / 1000.0) / rates[r];
                const double next = hfs_exposure_smooth(ev, target, dt, tau);
                CHECK(dir * (next - ev) > 0.0 && dir * (target - next) >= 0.0,
                      "%g fps: step %g -> %g towards %g", rates[r], ev, next, target);
                ev = next;
                t += dt;
                CHECK(fabs(ev / target - (1.0 - exp(-t / tau))) < 1e-9,
                      "%g fps: %.4f of the step at %.3f s", rates[r], ev / target, t);
            }
            CHECK(fabs(target - ev) < 1.0 / 64.0, "%g fps: %g stops off after 3.5 s", rates[r],
                  target - ev);
        }
    double ev = 0.0;
    for (int k = 0; k < 120; ++k) {
        const double next = hfs_exposure_smooth(ev, k % 2 ? 3.0 : -3.0, 1.0 / 60.0, 0.5);
        CHECK(fabs(next - ev) < 0.5, "pumping: frame %d moved %g stops", k, next - ev);
        ev = next;
    }
    CHECK(hfs_exposure_smooth(1.0, 5.0, 0.0, 0.5) == 1.0, "dt 0 moved the exposure");
}

int main(void)
{
    hfs_png_opts clamp = {.exposure = 0.0, .tonemap = HFS_TONEMAP_CLAMP};
    hfs_png_opts reinhard = {.exposure = 1.7, .tonemap = HFS_TONEMAP_REINHARD};
    hfs_png_opts bright = {.exposure = 3.0, .tonemap = HFS_TONEMAP_CLAMP};
    check_frame_vs_png(NULL, "display_frame_default.png");
    check_frame_vs_png(&clamp, "display_frame_clamp.png");
    check_frame_vs_png(&reinhard, "display_frame_reinhard.png");
    check_frame_vs_png(&bright, "display_frame_bright.png");
    hfs_png_opts hue = {.exposure = 9.0, .tonemap = HFS_TONEMAP_HUE};
    check_frame_vs_png(&hue, "display_frame_hue.png");
    check_frame_errors();
    check_exposure_smoothing();
    check_overlay_digit(1);
    check_overlay_digit(2);
    check_overlay_clipping();
    check_overlay_contrast();
    check_fit();
    if (failures)
        fprintf(stderr, "%d check(s) failed\n", failures);
    return failures ? 1 : 0;
}
