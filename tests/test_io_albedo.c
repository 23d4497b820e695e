/*
 * test_io_albedo.c — hfs_albedo_load against files written here by libpng's
 * and our own writers:
 *   png8_srgb    8-bit RGB PNG: samples decoded by the sRGB curve (checked
 *                against the curve computed here), rows in file order
 *   png16_grey   16-bit grey PNG: linear, R = G = B
 *   pfm          "PF" and "Pf" maps as stored
 *   errors       a size other than the field's, a value above 1, a NaN, a
 *                negative value, a file that is no image: one line naming
 *                the file, *rgb NULL
 */
#include "hfs_io.h"
#include "test_util.h"

#include <math.h>
#include <png.h>
#include <stdint.h>

static double srgb_to_linear(double v)
{
    return v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4);
}

static void write_png(const char *path, int w, int h, png_uint_32 format, const void *px)
{
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    img.width = (png_uint_32)w;
    img.height = (png_uint_32)h;
    img.format = format;
    if (!png_image_write_to_file(&img, path, 0, px, 0, NULL)) {
        fprintf(stderr, "cannot write %s: %s\n", path, img.message);
        exit(1);
    }
}

static void test_png8_srgb(void)
{
    const int w = 5, h = 3;
    uint8_t px[5 * 3 * 3];
    for (int i = 0; i < w * h * 3; ++i)
        px[i] = (uint8_t)((i * 37 + 11) % 256);
    write_png(tpath("a8.png"), w, h, PNG_FORMAT_RGB, px);
    float *rgb = NULL;
    hfs_error err = {{0}};
    REQUIRE(hfs_albedo_load(tpath("a8.png"), w, h, &rgb, &err) == HFS_OK, "%s", err.msg);
    double worst = 0.0;
    for (int i = 0; i < w * h * 3; ++i)
        worst = fmax(worst, fabs(rgb[i] - srgb_to_linear(px[i] / 255.0)));
    free(rgb);
    /* libpng's 16-bit linear result: within a few 1/65535 of the curve */
    REQUIRE(worst < 1e-4, "8-bit sRGB PNG decoded %.2e from the sRGB curve", worst);
    printf("png8_srgb: 45 samples within %.1e of the sRGB curve\n", worst);
}

static void test_png16_grey(void)
{
    const int w = 4, h = 2;
    const uint16_t px[8] = {0, 65535, 32768, 1, 1000, 50000, 12345, 65534};
    write_png(tpath("g16.png"), w, h, PNG_FORMAT_LINEAR_Y, px);
    float *rgb = NULL;
    hfs_error err = {{0}};
    REQUIRE(hfs_albedo_load(tpath("g16.png"), w, h, &rgb, &err) == HFS_OK, "%s", err.msg);
    for (int i = 0; i < w * h; ++i)
        for (int c = 0; c < 3; ++c)
            CHECK(fabsf(rgb[3 * i + c] - px[i] / 65535.0f) < 1e-6f);
    free(rgb);
    printf("png16_grey: linear, R = G = B, file order\n");
}

static void write_pfm(const char *path, int w, int h, int colour, const float *v)
{
    char head[64];
    const int n = snprintf(head, sizeof head, "%s\n%d %d\n-1.0\n", colour ? "PF" : "Pf", w, h);
    const size_t bytes = (size_t)w * h * (colour ? 3 : 1) * sizeof(float);
    char *buf = malloc((size_t)n + bytes);
    memcpy(buf, head, (size_t)n);
    memcpy(buf + n, v, bytes); /* little-endian hosts only, as the scale says */
    write_bytes(path, buf, (size_t)n + bytes);
    free(buf);
}

static void test_pfm(void)
{
    const float c[2 * 2 * 3] = {0.f, 0.25f, 0.5f, 1.f, 0.75f, 0.125f,
                                0.3f, 0.6f, 0.9f, 0.1f, 0.2f, 0.4f};
    write_pfm(tpath("c.pfm"), 2, 2, 1, c);
    float *rgb = NULL;
    hfs_error err = {{0}};
    REQUIRE(hfs_albedo_load(tpath("c.pfm"), 2, 2, &rgb, &err) == HFS_OK, "%s", err.msg);
    CHECK(!memcmp(rgb, c, sizeof c));
    free(rgb);
    const float g[4] = {0.5f, 0.f, 1.f, 0.2f};
    write_pfm(tpath("g.pfm"), 2, 2, 0, g);
    REQUIRE(hfs_albedo_load(tpath("g.pfm"), 2, 2, &rgb, &err) == HFS_OK, "%s", err.msg);
    for (int i = 0; i < 4; ++i)
        CHECK(rgb[3 * i] == g[i] && rgb[3 * i + 1] == g[i] && rgb[3 * i + 2] == g[i]);
    free(rgb);
    printf("pfm: colour and grey as stored\n");
}

/* One bad file: an error naming it and containing `what`, *rgb NULL. */
static void expect_error(const char *path, int w, int h, const char *what)
{
    float *rgb = (float *)&rgb; /* must come back NULL */
    hfs_error err = {{0}};
    const int rc = hfs_albedo_load(path, w, h, &rgb, &err);
    REQUIRE(rc < 0 && rgb == NULL, "%s: rc %d", path, rc);
    REQUIRE(strstr(err.msg, path) && strstr(err.msg, what) && !strchr(err.msg, '\n'),
            "%s: message '%s' lacks '%s'", path, err.msg, what);
}

static void test_errors(void)
{
    const float ok[4 * 3] = {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f,
                             0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f};
    write_pfm(tpath("ok.pfm"), 2, 2, 1, ok);
    expect_error(tpath("ok.pfm"), 3, 2, "albedo map is 2x2, the heights are 3x2");
    float bad[4 * 3];
    memcpy(bad, ok, sizeof bad);
    bad[3 * 3 + 1] = 1.5f;
    write_pfm(tpath("big.pfm"), 2, 2, 1, bad);
    expect_error(tpath("big.pfm"), 2, 2, "texel (1, 1) G is 1.5, outside [0, 1]");
    bad[3 * 3 + 1] = NAN;
    write_pfm(tpath("nan.pfm"), 2, 2, 1, bad);
    expect_error(tpath("nan.pfm"), 2, 2, "is nan");
    bad[3 * 3 + 1] = -0.25f;
    write_pfm(tpath("neg.pfm"), 2, 2, 1, bad);
    expect_error(tpath("neg.pfm"), 2, 2, "is -0.25");
    write_bytes(tpath("junk.png"), "not an image at all", 19);
    expect_error(tpath("junk.png"), 2, 2, "junk.png");
    uint8_t px[3 * 3 * 3] = {0};
    write_png(tpath("s.png"), 3, 3, PNG_FORMAT_RGB, px);
    expect_error(tpath("s.png"), 4, 3, "albedo map is 3x3, the heights are 4x3");
    printf("errors: size, range, NaN, junk: one line naming the file\n");
}

int main(void)
{
    if (make_tmpdir("albedo"))
        return 1;
    test_png8_srgb();
    test_png16_grey();
    test_pfm();
    test_errors();
    rm_tmpdir();
    return finish_checks("test_io_albedo");
}
