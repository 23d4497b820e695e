/*
 * test_io_write.c — writers: PFM bytes exactly as SPEC says (header, little
 * endian, first row written = j 0, Pf luminance exact for grey), the 8-bit
 * sRGB PNG read back with libpng (tone map, exposure, sRGB chunk, row order),
 * and atomicity: refused input or an impossible path leaves neither a
 * partial file nor a temporary, and never damages an existing file.
 */
#include "hfs_io.h"
#include "test_util.h"

#include <dirent.h>
#include <math.h>
#include <png.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static float get_le32(const unsigned char *b)
{
    uint32_t u = (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
    float f;
    memcpy(&f, &u, 4);
    return f;
}

/* Counts entries of tmpdir whose name contains ".tmp-". */
static int count_temporaries(void)
{
    DIR *d = opendir(tmpdir);
    struct dirent *e;
    int n = 0;
    if (!d)
        return -1;
    while ((e = readdir(d)))
        if (strstr(e->d_name, ".tmp-"))
            ++n;
    closedir(d);
    return n;
}

static void test_pfm(void)
{
    hfs_image img;
    hfs_error err;
    unsigned char *b;
    size_t n;

    CHECK(hfs_image_alloc(&img, 3, 2, &err) == 0);
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 3; ++i)
            for (int c = 0; c < 3; ++c)
                img.rgb[(j * 3 + i) * 3 + c] = (float)(100 * j + 10 * i + c) + 0.125f;

    /* RGB. */
    CHECK(hfs_pfm_write(tpath("rgb.pfm"), &img, 0, &err) == 0);
    b = read_all(tpath("rgb.pfm"), &n);
    CHECK(b != NULL);
    if (b) {
        const char *hdr = "PF\n3 2\n-1.0\n";
        size_t hl = strlen(hdr);
        CHECK(n == hl + 3 * 2 * 3 * 4);
        CHECK(memcmp(b, hdr, hl) == 0);
        /* First row written is j = 0; little endian. */
        for (int k = 0; k < 18 && n == hl + 72; ++k)
            CHECK(get_le32(b + hl + 4 * k) == img.rgb[k]);
        free(b);
    }

    /* Grey: luminance, exact when R = G = B. */
    for (int k = 0; k < 6; ++k)
        img.rgb[3 * k] = img.rgb[3 * k + 1] = img.rgb[3 * k + 2] = 0.1f * (float)k + 1e-3f;
    img.rgb[3 * 5] = 1.0f, img.rgb[3 * 5 + 1] = 0.0f, img.rgb[3 * 5 + 2] = 0.0f;
    CHECK(hfs_pfm_write(tpath("grey.pfm"), &img, 1, &err) == 0);
    b = read_all(tpath("grey.pfm"), &n);
    if (b) {
        const char *hdr = "Pf\n3 2\n-1.0\n";
        size_t hl = strlen(hdr);
        CHECK(n == hl + 6 * 4);
        CHECK(memcmp(b, hdr, hl) == 0);
        for (int k = 0; k < 5 && n == hl + 24; ++k)
            CHECK(get_le32(b + hl + 4 * k) == img.rgb[3 * k]);
        CHECK(n == hl + 24 && get_le32(b + hl + 20) == 0.2126f);
        free(b);
    }
    hfs_image_free(&img);
}

typedef struct png_back {
    int w, h, depth, ctype, srgb;
    unsigned char px[64 * 3];
} png_back;

static int read_png(const char *path, png_back *out)
{
    FILE *f = fopen(path, "rb");
    png_structp png;
    png_infop info;
    int intent;
    if (!f)
        return -1;
    png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        fclose(f);
        return -1;
    }
    png_init_io(png, f);
    png_read_info(png, info);
    out->w = (int)png_get_image_width(png, info);
    out->h = (int)png_get_image_height(png, info);
    out->depth = png_get_bit_depth(png, info);
    out->ctype = png_get_color_type(png, info);
    out->srgb = png_get_sRGB(png, info, &intent) != 0;
    if (out->w * out->h * 3 <= (int)sizeof out->px)
        for (int j = 0; j < out->h; ++j)
            png_read_row(png, out->px + j * out->w * 3, NULL);
    png_destroy_read_struct(&png, &info, NULL);
    fclose(f);
    return 0;
}

static unsigned srgb8(double x)
{
    x = x < 0 ? 0 : x > 1 ? 1 : x;
    x = x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1 / 2.4) - 0.055;
    return (unsigned)lrint(255 * x);
}

static void test_png(void)
{
    static const float vals[6] = {0.0f, 1.0f, 0.5f, 0.002f, -4.0f, 7.0f};
    hfs_image img;
    hfs_error err;
    hfs_png_opts o;
    png_back pb;

    CHECK(hfs_image_alloc(&img, 2, 3, &err) == 0);
    for (int k = 0; k < 6; ++k)
        for (int c = 0; c < 3; ++c)
            img.rgb[3 * k + c] = vals[k] * (c == 1 ? 0.5f : 1.0f);

    /* Defaults: clamp, exposure 1; top row = j 0. */
    CHECK(hfs_png_write(tpath("a.png"), &img, NULL, &err) == 0);
    CHECK(read_png(tpath("a.png"), &pb) == 0);
    CHECK(pb.w == 2 && pb.h == 3 && pb.depth == 8 && pb.ctype == PNG_COLOR_TYPE_RGB && pb.srgb);
    for (int k = 0; k < 6; ++k) {
        CHECK(pb.px[3 * k] == srgb8(vals[k]));
        CHECK(pb.px[3 * k + 1] == srgb8(vals[k] * 0.5));
    }
    CHECK(pb.px[0] == 0 && pb.px[3] == 255 && pb.px[6] == 188);

    /* Exposure and Reinhard. */
    memset(&o, 0, sizeof o);
    o.exposure = 2.0;
    o.tonemap = HFS_TONEMAP_REINHARD;
    CHECK(hfs_png_write(tpath("b.png"), &img, &o, &err) == 0);
    CHECK(read_png(tpath("b.png"), &pb) == 0);
    for (int k = 0; k < 6; ++k) {
        double x = 2.0 * vals[k];
        CHECK(pb.px[3 * k] == srgb8(x > 0 ? x / (1 + x) : 0));
    }

    /* The hue-keeping curve (hfs_io.h HFS_TONEMAP_HUE): each pixel is the
     * encoded bytes of its own channels scaled by one factor. */
    o.exposure = 2.0;
    o.tonemap = HFS_TONEMAP_HUE;
    CHECK(hfs_png_write(tpath("h.png"), &img, &o, &err) == 0);
    CHECK(read_png(tpath("h.png"), &pb) == 0);
    for (int k = 0; k < 6; ++k) {
        unsigned char want[3];
        hfs_srgb8_encode_rgb(img.rgb + 3 * k, 2.0, HFS_TONEMAP_HUE, want);
        CHECK(pb.px[3 * k] == want[0] && pb.px[3 * k + 1] == want[1] &&
              pb.px[3 * k + 2] == want[2]);
    }
    CHECK(pb.px[3 * 5] < 255 && pb.px[3 * 5] > 250); /* 14: on the shoulder, not clipped */

    /* Bad options. */
    o.exposure = -1.0;
    CHECK(hfs_png_write(tpath("c.png"), &img, &o, &err) == HFS_E_INVALID);
    o.exposure = 1.0;
    o.tonemap = (hfs_tonemap)7;
    CHECK(hfs_png_write(tpath("c.png"), &img, &o, &err) == HFS_E_INVALID);
    CHECK(access(tpath("c.png"), F_OK) != 0);
    hfs_image_free(&img);
}

/* The curve itself: ratios kept (hue and saturation), never above 1,
 * monotone in brightness, middle grey where the header says, white only at
 * the white point; and the automatic exposure's median. */
static void test_tonemap_hue(void)
{
    static const double colours[][3] = {{0.25, 0.5, 1.0}, {1.0, 0.2, 0.05}, {0.3, 0.3, 0.3},
                                        {0.0, 1.0, 0.001}};
    for (size_t c = 0; c < sizeof colours / sizeof colours[0]; ++c) {
        double prev = -1.0;
        for (double k = 1.0 / 64; k < 4096.0; k *= 1.5) {
            const double in[3] = {k * colours[c][0], k * colours[c][1], k * colours[c][2]};
            double out[3];
            hfs_tonemap_rgb(in, HFS_TONEMAP_HUE, out);
            const double n = fmax(out[0], fmax(out[1], out[2]));
            const double top = fmax(colours[c][0], fmax(colours[c][1], colours[c][2]));
            /* Rising strictly up to the white point, 1 (to rounding) from it on. */
            CHECK(n <= 1.0 + 1e-15 &&
                  (k * top < 16.0 ? n > prev : fabs(n - 1.0) <= 1e-15));
            prev = n;
            for (int ch = 0; ch < 3; ++ch) /* the same ratio as the input's */
                CHECK(fabs(out[ch] - n * colours[c][ch] / top) <= 1e-12);
        }
    }
    const double grey[3] = {0.18, 0.18, 0.18}, neg[3] = {-1.0, 2.0, -3.0};
    double out[3];
    hfs_tonemap_rgb(grey, HFS_TONEMAP_HUE, out);
    CHECK(fabs(out[0] - 0.18 * (1 + 0.18 / 256) / 1.18) < 1e-12);
    CHECK(hfs_srgb8_encode(0.18f, 1.0, HFS_TONEMAP_HUE) == 109);
    CHECK(hfs_srgb8_encode(8.0f, 1.0, HFS_TONEMAP_HUE) < 255);
    CHECK(hfs_srgb8_encode(16.0f, 1.0, HFS_TONEMAP_HUE) == 255);
    hfs_tonemap_rgb(neg, HFS_TONEMAP_HUE, out);
    CHECK(out[0] == 0.0 && out[2] == 0.0 && out[1] > 0.0);

    /* Median luminance to 0.18: 99 pixels at luminance 2, one glint at
     * 1e6 and black ones (metering nothing) do not move it. */
    hfs_image img;
    hfs_error err;
    CHECK(hfs_image_alloc(&img, 20, 10, &err) == 0);
    for (int k = 0; k < 200; ++k)
        for (int ch = 0; ch < 3; ++ch)
            img.rgb[3 * k + ch] = k < 99 ? 2.0f : k == 99 ? 1e6f : 0.0f;
    CHECK(fabs(hfs_exposure_auto(&img) - 0.09) < 1e-6);
    for (int k = 0; k < 600; ++k)
        img.rgb[k] = 0.0f;
    CHECK(hfs_exposure_auto(&img) == 1.0); /* all black: no change */
    hfs_image_free(&img);
}

/* hfs_pfm_read_image: the inverse of the PFM writers, NaN/Inf kept. */
static void test_pfm_read(void)
{
    hfs_image img, back;
    hfs_error err;
    float grey[6] = {1.5f, -2.0f, 0.0f, 1e-20f, 3e20f, 7.0f};
    unsigned char buf[128];
    int n;

    CHECK(hfs_image_alloc(&img, 3, 2, &err) == 0);
    for (int k = 0; k < 18; ++k)
        img.rgb[k] = (float)k * 0.37f - 2.0f;
    CHECK(hfs_pfm_write(tpath("rt.pfm"), &img, 0, &err) == 0);
    CHECK(hfs_pfm_read_image(tpath("rt.pfm"), &back, &err) == 0);
    CHECK(back.width == 3 && back.height == 2 && back.rgb &&
          memcmp(back.rgb, img.rgb, 18 * sizeof(float)) == 0);
    hfs_image_free(&back);

    CHECK(hfs_pfm_write_grey(tpath("g.pfm"), 3, 2, grey, &err) == 0);
    CHECK(hfs_pfm_read_image(tpath("g.pfm"), &back, &err) == 0);
    for (int k = 0; back.rgb && k < 6; ++k)
        CHECK(back.rgb[3 * k] == grey[k] && back.rgb[3 * k + 1] == grey[k] &&
              back.rgb[3 * k + 2] == grey[k]);
    hfs_image_free(&back);

    /* Big-endian 1x1 colour with NaN and Inf: returned as stored. */
    n = sprintf((char *)buf, "PF\n1 1\n1.0\n");
    memcpy(buf + n, "\x7f\xc0\x00\x00\x7f\x80\x00\x00\x3f\x80\x00\x00", 12);
    {
        FILE *f = fopen(tpath("be.pfm"), "wb");
        CHECK(f && fwrite(buf, 1, (size_t)n + 12, f) == (size_t)n + 12);
        if (f)
            fclose(f);
    }
    CHECK(hfs_pfm_read_image(tpath("be.pfm"), &back, &err) == 0);
    CHECK(back.rgb && isnan(back.rgb[0]) && isinf(back.rgb[1]) && back.rgb[2] == 1.0f);
    hfs_image_free(&back);

    /* Every proper prefix fails cleanly, output zeroed. */
    {
        size_t len;
        unsigned char *b = read_all(tpath("rt.pfm"), &len);
        for (size_t k = 0; b && k < len; ++k) {
            FILE *f = fopen(tpath("cut.pfm"), "wb");
            if (f) {
                if (k)
                    CHECK(fwrite(b, 1, k, f) == k);
                fclose(f);
            }
            memset(&back, 0x5a, sizeof back);
            CHECK(hfs_pfm_read_image(tpath("cut.pfm"), &back, &err) < 0);
            CHECK(back.rgb == NULL && back.width == 0 && strstr(err.msg, tpath("cut.pfm")) == err.msg);
        }
        free(b);
    }
    CHECK(hfs_pfm_read_image(tpath("missing.pfm"), &back, &err) == HFS_E_IO);
    CHECK(hfs_pfm_read_image(NULL, &back, &err) == HFS_E_INVALID);
    hfs_image_free(&img);
}

static void test_atomic(void)
{
    hfs_image img;
    hfs_error err;
    unsigned char *b;
    size_t n, n0;
    float grey[4] = {1, 2, 3, 4};

    CHECK(hfs_image_alloc(&img, 2, 2, &err) == 0);
    CHECK(hfs_pfm_write(tpath("keep.pfm"), &img, 1, &err) == 0);
    b = read_all(tpath("keep.pfm"), &n0);
    free(b);

    /* A NaN is refused before anything is created; the old file survives. */
    img.rgb[5] = NAN;
    CHECK(hfs_pfm_write(tpath("keep.pfm"), &img, 1, &err) == HFS_E_INVALID);
    CHECK(strstr(err.msg, tpath("keep.pfm")) == err.msg);
    CHECK(hfs_png_write(tpath("keep.pfm"), &img, NULL, &err) == HFS_E_INVALID);
    b = read_all(tpath("keep.pfm"), &n);
    CHECK(b && n == n0);
    free(b);
    img.rgb[5] = INFINITY;
    CHECK(hfs_pfm_write(tpath("inf.pfm"), &img, 0, &err) == HFS_E_INVALID);
    CHECK(access(tpath("inf.pfm"), F_OK) != 0);
    img.rgb[5] = 0.0f;

    /* Directory that does not exist: error naming the path, nothing left. */
    CHECK(hfs_pfm_write(tpath("no/such/dir.pfm"), &img, 0, &err) == HFS_E_IO);
    CHECK(strstr(err.msg, "no/such/dir.pfm") != NULL);
    CHECK(hfs_png_write(tpath("no/such/dir.png"), &img, NULL, &err) == HFS_E_IO);

    /* Target is a directory: rename fails after a complete temporary was
     * written; the temporary must be gone. */
    CHECK(mkdir(tpath("adir.pfm"), 0777) == 0);
    CHECK(hfs_pfm_write(tpath("adir.pfm"), &img, 0, &err) == HFS_E_IO);
    CHECK(hfs_png_write(tpath("adir.pfm"), &img, NULL, &err) == HFS_E_IO);
    CHECK(hfs_png16_write_grey(tpath("adir.pfm"), 2, 2, grey, &err) == HFS_E_IO);
    CHECK(strstr(err.msg, "adir.pfm") != NULL && strchr(err.msg, '\n') == NULL);
    CHECK(count_temporaries() == 0);

    /* 16-bit PNG range and NaN refusal. */
    grey[2] = 65536.0f;
    CHECK(hfs_png16_write_grey(tpath("r.png"), 2, 2, grey, &err) == HFS_E_INVALID);
    grey[2] = -0.6f;
    CHECK(hfs_png16_write_grey(tpath("r.png"), 2, 2, grey, &err) == HFS_E_INVALID);
    grey[2] = NAN;
    CHECK(hfs_png16_write_grey(tpath("r.png"), 2, 2, grey, &err) == HFS_E_INVALID);
    CHECK(hfs_pfm_write_grey(tpath("r.pfm"), 2, 2, grey, &err) == HFS_E_INVALID);
    CHECK(access(tpath("r.png"), F_OK) != 0 && access(tpath("r.pfm"), F_OK) != 0);

    /* Empty and missing arguments. */
    CHECK(hfs_pfm_write(tpath("e.pfm"), NULL, 0, &err) == HFS_E_INVALID);
    CHECK(hfs_pfm_write("", &img, 0, &err) == HFS_E_INVALID);
    CHECK(hfs_png_write(NULL, &img, NULL, NULL) == HFS_E_INVALID);

    /* Overwrite an existing file atomically with new content. */
    grey[2] = 3.0f;
    CHECK(hfs_pfm_write_grey(tpath("keep.pfm"), 2, 2, grey, &err) == 0);
    b = read_all(tpath("keep.pfm"), &n);
    CHECK(b && n == strlen("Pf\n2 2\n-1.0\n") + 16 && get_le32(b + n - 4) == 4.0f);
    free(b);
    CHECK(count_temporaries() == 0);
    hfs_image_free(&img);
}

int main(void)
{
    if (make_tmpdir("io_write") != 0)
        return 1;
    test_pfm();
    test_png();
    test_tonemap_hue();
    test_pfm_read();
    test_atomic();
    rm_tmpdir();
    return finish_checks("test_io_write");
}
