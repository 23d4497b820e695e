/*
 * test_io_height.c — height field loaders: every format against files written
 * independently of our writers (bytes by hand, or libpng directly), the SPEC
 * row order (first row in the file = j = 0), nodata/holes through each
 * loader, format detection and the size guard.
 *
 * Files go to a private temporary directory (make_tmpdir in test_util.h:
 * /dev/shm when writable, else the working directory), removed at the end.
 * Exit 0 = pass, 1 = fail.
 */
#include "hfs_io.h"
#include "test_util.h"

#include <locale.h>
#include <math.h>
#include <png.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void put_le32(unsigned char *b, float f)
{
    uint32_t u;
    memcpy(&u, &f, 4);
    b[0] = (unsigned char)u, b[1] = (unsigned char)(u >> 8);
    b[2] = (unsigned char)(u >> 16), b[3] = (unsigned char)(u >> 24);
}

static void put_be32(unsigned char *b, float f)
{
    uint32_t u;
    memcpy(&u, &f, 4);
    b[3] = (unsigned char)u, b[2] = (unsigned char)(u >> 8);
    b[1] = (unsigned char)(u >> 16), b[0] = (unsigned char)(u >> 24);
}

static int load(const char *path, const hfs_height_load_opts *o, hfs_heightmap *hm)
{
    hfs_error err;
    int rc;
    err.msg[0] = '\0';
    rc = hfs_height_load(path, o, hm, &err);
    if (rc)
        fprintf(stderr, "  load %s -> %d: %s\n", path, rc, err.msg);
    return rc;
}

/* Loads and expects failure; returns the status and checks the message. */
static int load_fail(const char *path, const hfs_height_load_opts *o)
{
    hfs_heightmap hm;
    hfs_error err;
    int rc;
    memset(&hm, 0x5a, sizeof hm);
    err.msg[0] = '\0';
    rc = hfs_height_load(path, o, &hm, &err);
    CHECK(rc < 0);
    CHECK(strstr(err.msg, path) == err.msg);
    CHECK(strchr(err.msg, '\n') == NULL);
    CHECK(hm.z == NULL && hm.width == 0 && hm.height == 0 && hm.holes == 0);
    if (rc == 0)
        hfs_heightmap_free(&hm);
    return rc;
}

/* ---- PGM ----------------------------------------------------------------------- */

static void test_pgm(void)
{
    unsigned char buf[4096];
    hfs_heightmap hm;
    int n;

    /* 8-bit, comments in the header, top row first = j 0. */
    n = sprintf((char *)buf, "P5\n# made by hand\n5 3\n# maxval next\n255\n");
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 5; ++i)
            buf[n++] = (unsigned char)(j * 16 + i);
    write_bytes(tpath("a8.pgm"), buf, (size_t)n);
    CHECK(load(tpath("a8.pgm"), NULL, &hm) == 0);
    CHECK(hm.width == 5 && hm.height == 3 && hm.holes == 0 && hm.format == HFS_HEIGHT_PGM);
    for (int j = 0; j < 3 && hm.z; ++j)
        for (int i = 0; i < 5; ++i)
            CHECK(hm.z[j * 5 + i] == (float)(j * 16 + i));
    CHECK(hm.cellsize == 0.0);
    hfs_heightmap_free(&hm);
    CHECK(hm.z == NULL);

    /* 16-bit big-endian, raw samples (not divided by maxval). */
    n = sprintf((char *)buf, "P5 4 3 65535\n");
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 4; ++i) {
            unsigned v = 1000u * (unsigned)j + 7u * (unsigned)i + 256u + (j == 2 && i == 3 ? 60000u : 0u);
            buf[n++] = (unsigned char)(v >> 8);
            buf[n++] = (unsigned char)v;
        }
    write_bytes(tpath("a16.pgm"), buf, (size_t)n);
    CHECK(load(tpath("a16.pgm"), NULL, &hm) == 0);
    CHECK(hm.width == 4 && hm.height == 3);
    for (int j = 0; j < 3 && hm.z; ++j)
        for (int i = 0; i < 4; ++i)
            CHECK(hm.z[j * 4 + i] ==
                  (float)(1000 * j + 7 * i + 256 + (j == 2 && i == 3 ? 60000 : 0)));
    hfs_heightmap_free(&hm);

    /* maxval 1000 is 16-bit; a sample of 1000 is fine, 1001 is not. */
    n = sprintf((char *)buf, "P5 2 2 1000\n");
    memcpy(buf + n, "\x03\xe8\x00\x00\x00\x01\x03\xe7", 8);
    write_bytes(tpath("m1000.pgm"), buf, (size_t)n + 8);
    CHECK(load(tpath("m1000.pgm"), NULL, &hm) == 0);
    CHECK(hm.z && hm.z[0] == 1000.0f && hm.z[3] == 999.0f);
    hfs_heightmap_free(&hm);
    buf[n + 1] = 0xe9;
    write_bytes(tpath("m1001.pgm"), buf, (size_t)n + 8);
    CHECK(load_fail(tpath("m1001.pgm"), NULL) == HFS_E_FORMAT);

    /* P2 ASCII, with a comment and irregular whitespace. */
    {
        const char *p2 = "P2\n3 2\n# c\n100\n 0 1 2\n\t3  4\n5\n";
        write_bytes(tpath("a.pgm"), p2, strlen(p2));
    }
    CHECK(load(tpath("a.pgm"), NULL, &hm) == 0);
    CHECK(hm.width == 3 && hm.height == 2);
    for (int k = 0; k < 6 && hm.z; ++k)
        CHECK(hm.z[k] == (float)k);
    hfs_heightmap_free(&hm);
}

/* ---- PFM ----------------------------------------------------------------------- */

static void test_pfm(void)
{
    unsigned char buf[4096];
    hfs_heightmap hm;
    int n;

    /* Little-endian (negative scale); SPEC: first row stored = j 0. */
    n = sprintf((char *)buf, "Pf\n4 3\n-1.0\n");
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 4; ++i, n += 4)
            put_le32(buf + n, (float)(j * 10 + i) + 0.25f);
    write_bytes(tpath("le.pfm"), buf, (size_t)n);
    CHECK(load(tpath("le.pfm"), NULL, &hm) == 0);
    CHECK(hm.width == 4 && hm.height == 3 && hm.format == HFS_HEIGHT_PFM);
    for (int j = 0; j < 3 && hm.z; ++j)
        for (int i = 0; i < 4; ++i)
            CHECK(hm.z[j * 4 + i] == (float)(j * 10 + i) + 0.25f);
    hfs_heightmap_free(&hm);

    /* Big-endian (positive scale, magnitude ignored). */
    n = sprintf((char *)buf, "Pf\n2 2\n2.5\n");
    for (int k = 0; k < 4; ++k, n += 4)
        put_be32(buf + n, -3.5f * (float)k);
    write_bytes(tpath("be.pfm"), buf, (size_t)n);
    CHECK(load(tpath("be.pfm"), NULL, &hm) == 0);
    for (int k = 0; k < 4 && hm.z; ++k)
        CHECK(hm.z[k] == -3.5f * (float)k);
    hfs_heightmap_free(&hm);

    /* Our writer, exact round trip of awkward floats. */
    {
        float v[6] = {-1e-30f, 1e30f, 3.14159274f, -0.0f, 65504.0f, 1.17549435e-38f};
        hfs_error err;
        CHECK(hfs_pfm_write_grey(tpath("rt.pfm"), 3, 2, v, &err) == 0);
        CHECK(load(tpath("rt.pfm"), NULL, &hm) == 0);
        CHECK(hm.width == 3 && hm.height == 2);
        for (int k = 0; k < 6 && hm.z; ++k)
            CHECK(memcmp(&hm.z[k], &v[k], 4) == 0);
        hfs_heightmap_free(&hm);
    }
}

/* ---- PNG (written with libpng directly, independent of our writer) -------------- */

static void png_write_raw(const char *path, int w, int h, int depth, int ctype, int interlace,
                          const unsigned char *data, size_t rowbytes)
{
    FILE *f = fopen(path, "wb");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    if (!f || !png || !info || setjmp(png_jmpbuf(png))) {
        fprintf(stderr, "png_write_raw failed\n");
        exit(1);
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, depth, ctype, interlace,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    {
        int passes = png_set_interlace_handling(png);
        for (int p = 0; p < passes; ++p)
            for (int j = 0; j < h; ++j)
                png_write_row(png, (png_bytep)(data + (size_t)j * rowbytes));
    }
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    fclose(f);
}

static void test_png(void)
{
    unsigned char data[4096];
    hfs_heightmap hm;
    const int w = 7, h = 5;

    /* 16-bit grey, both interlace modes. */
    for (int il = 0; il < 2; ++il) {
        const char *p = tpath(il ? "g16i.png" : "g16.png");
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) {
                unsigned v = 9000u * (unsigned)j + 300u * (unsigned)i + 1u;
                data[(j * w + i) * 2] = (unsigned char)(v >> 8);
                data[(j * w + i) * 2 + 1] = (unsigned char)v;
            }
        png_write_raw(p, w, h, 16, PNG_COLOR_TYPE_GRAY,
                      il ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, data, (size_t)w * 2);
        CHECK(load(p, NULL, &hm) == 0);
        CHECK(hm.width == w && hm.height == h && hm.format == HFS_HEIGHT_PNG);
        for (int j = 0; j < h && hm.z; ++j)
            for (int i = 0; i < w; ++i)
                CHECK(hm.z[j * w + i] == (float)(9000 * j + 300 * i + 1));
        hfs_heightmap_free(&hm);
    }

    /* 8-bit grey. */
    for (int k = 0; k < w * h; ++k)
        data[k] = (unsigned char)(k * 7);
    png_write_raw(tpath("g8.png"), w, h, 8, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, data,
                  (size_t)w);
    CHECK(load(tpath("g8.png"), NULL, &hm) == 0);
    for (int k = 0; k < w * h && hm.z; ++k)
        CHECK(hm.z[k] == (float)(unsigned char)(k * 7));
    hfs_heightmap_free(&hm);

    /* 4-bit grey: samples unpacked, not scaled (15 stays 15). */
    {
        /* 3 wide: 2 bytes per row, the last nibble is padding. */
        unsigned char packed[2 * 3] = {0x01, 0x23, 0x45, 0x67, 0x89, 0xaf};
        png_write_raw(tpath("g4.png"), 3, 3, 4, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, packed,
                      2);
        CHECK(load(tpath("g4.png"), NULL, &hm) == 0);
        CHECK(hm.width == 3 && hm.height == 3);
        if (hm.z) {
            CHECK(hm.z[0] == 0 && hm.z[1] == 1 && hm.z[2] == 2);
            CHECK(hm.z[3] == 4 && hm.z[4] == 5 && hm.z[5] == 6);
            CHECK(hm.z[6] == 8 && hm.z[7] == 9 && hm.z[8] == 10);
        }
        hfs_heightmap_free(&hm);
    }

    /* Grey+alpha: alpha 0 is a hole; the hole is filled from its constant
     * neighbourhood. */
    for (int k = 0; k < 9; ++k) {
        data[2 * k] = 50;
        data[2 * k + 1] = k == 4 ? 0 : (unsigned char)(k * 20 + 1);
    }
    data[8] = 200; /* the hidden grey value under alpha 0 must not leak */
    png_write_raw(tpath("ga.png"), 3, 3, 8, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_INTERLACE_NONE, data, 6);
    CHECK(load(tpath("ga.png"), NULL, &hm) == 0);
    CHECK(hm.holes == 1);
    for (int k = 0; k < 9 && hm.z; ++k)
        CHECK(hm.z[k] == 50.0f);
    hfs_heightmap_free(&hm);

    /* RGB is refused with a clear message. */
    memset(data, 9, 3 * 4 * 4);
    png_write_raw(tpath("rgb.png"), 4, 4, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, data, 12);
    CHECK(load_fail(tpath("rgb.png"), NULL) == HFS_E_UNSUPPORTED);

    /* Our 16-bit writer: exact round trip, including rounding to nearest. */
    {
        float v[6] = {0.0f, 65535.0f, 1.4f, 1.6f, 32768.0f, 12345.0f};
        float want[6] = {0, 65535, 1, 2, 32768, 12345};
        hfs_error err;
        CHECK(hfs_png16_write_grey(tpath("w16.png"), 3, 2, v, &err) == 0);
        CHECK(load(tpath("w16.png"), NULL, &hm) == 0);
        for (int k = 0; k < 6 && hm.z; ++k)
            CHECK(hm.z[k] == want[k]);
        hfs_heightmap_free(&hm);
    }
}

/* ---- ESRI ASCII grid ---------------------------------------------------------------- */

static void test_asc(void)
{
    hfs_heightmap hm;
    const char *txt =
        "NCOLS 4\r\nnrows 3\r\nxllcenter 100.5\r\nYLLCORNER -20\r\ncellsize 2.5\r\n"
        "NODATA_value -9999\r\n"
        "1 2 3 4\r\n"
        "5.5 -9999.0 7e0 8\r\n"
        "9 10 11 -1.25E+1\r\n";
    write_bytes(tpath("a.asc"), txt, strlen(txt));
    CHECK(load(tpath("a.asc"), NULL, &hm) == 0);
    CHECK(hm.width == 4 && hm.height == 3 && hm.format == HFS_HEIGHT_ASC);
    CHECK(hm.cellsize == 2.5);
    CHECK(hm.holes == 1);
    if (hm.z) {
        /* First data row (north) is j = 0. */
        CHECK(hm.z[0] == 1 && hm.z[3] == 4);
        CHECK(hm.z[4] == 5.5f && hm.z[6] == 7 && hm.z[7] == 8);
        CHECK(hm.z[8] == 9 && hm.z[11] == -12.5f);
        CHECK(isfinite(hm.z[5]) && hm.z[5] > -12.5f && hm.z[5] < 11.0f);
    }
    hfs_heightmap_free(&hm);

    /* The common float nodata just above FLT_MAX is accepted and matched. */
    txt = "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n"
          "nodata_value -3.4028235e+38\n1 -3.4028235e+38\n1 1\n";
    write_bytes(tpath("b.asc"), txt, strlen(txt));
    CHECK(load(tpath("b.asc"), NULL, &hm) == 0);
    CHECK(hm.holes == 1 && hm.z && hm.z[1] == 1.0f);
    hfs_heightmap_free(&hm);

    /* A decimal comma locale must not change parsing. */
    {
        static const char *const locs[] = {"de_DE.UTF-8", "de_DE.utf8", "fr_FR.UTF-8", "de_DE"};
        const char *got = NULL;
        for (size_t k = 0; k < sizeof locs / sizeof locs[0] && !got; ++k)
            got = setlocale(LC_NUMERIC, locs[k]);
        if (got) {
            txt = "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 0.5\n1.5 2.5\n3.5 4.5\n";
            write_bytes(tpath("c.asc"), txt, strlen(txt));
            CHECK(load(tpath("c.asc"), NULL, &hm) == 0);
            CHECK(hm.z && hm.z[0] == 1.5f && hm.z[3] == 4.5f && hm.cellsize == 0.5);
            hfs_heightmap_free(&hm);
            setlocale(LC_NUMERIC, "C");
        } else {
            printf("note: no comma-decimal locale installed; locale check skipped\n");
        }
    }
}

/* ---- raw float32 --------------------------------------------------------------------- */

static void test_raw(void)
{
    unsigned char buf[4 * 12];
    hfs_height_load_opts o;
    hfs_heightmap hm;

    for (int k = 0; k < 12; ++k)
        put_le32(buf + 4 * k, (float)k * 0.5f - 1.0f);
    write_bytes(tpath("f.raw"), buf, sizeof buf);
    memset(&o, 0, sizeof o);
    o.raw_width = 4;
    o.raw_height = 3;
    CHECK(load(tpath("f.raw"), &o, &hm) == 0);
    CHECK(hm.width == 4 && hm.height == 3 && hm.format == HFS_HEIGHT_RAW_F32);
    for (int k = 0; k < 12 && hm.z; ++k)
        CHECK(hm.z[k] == (float)k * 0.5f - 1.0f);
    hfs_heightmap_free(&hm);

    /* Unknown extension + explicit size = raw. */
    write_bytes(tpath("f.dat"), buf, sizeof buf);
    CHECK(load(tpath("f.dat"), &o, &hm) == 0);
    hfs_heightmap_free(&hm);

    /* Wrong size: exact message with both numbers. */
    o.raw_width = 3;
    o.raw_height = 3;
    CHECK(load_fail(tpath("f.raw"), &o) == HFS_E_FORMAT);
    /* No size at all. */
    CHECK(load_fail(tpath("f.raw"), NULL) == HFS_E_INVALID);
    /* Only one of the two. */
    o.raw_width = 12;
    o.raw_height = 0;
    CHECK(load_fail(tpath("f.raw"), &o) == HFS_E_INVALID);
}

/* ---- nodata and holes through a loader ------------------------------------------------- */

static void test_nodata(void)
{
    unsigned char buf[256];
    float v[9] = {5, 5, 5, 5, -32768.0f, 5, 5, 5, 5};
    hfs_height_load_opts o;
    hfs_heightmap hm;
    int n;

    n = sprintf((char *)buf, "Pf\n3 3\n-1\n");
    for (int k = 0; k < 9; ++k)
        put_le32(buf + n + 4 * k, v[k]);
    write_bytes(tpath("nd.pfm"), buf, (size_t)n + 36);
    /* Without a declared nodata the value is a (deep) height. */
    CHECK(load(tpath("nd.pfm"), NULL, &hm) == 0);
    CHECK(hm.holes == 0 && hm.z && hm.z[4] == -32768.0f);
    hfs_heightmap_free(&hm);
    memset(&o, 0, sizeof o);
    o.has_nodata = 1;
    o.nodata = -32768.0f;
    CHECK(load(tpath("nd.pfm"), &o, &hm) == 0);
    CHECK(hm.holes == 1 && hm.z && hm.z[4] == 5.0f);
    hfs_heightmap_free(&hm);

    /* NaN, +Inf, -Inf are always holes. */
    v[0] = NAN;
    v[4] = INFINITY;
    v[8] = -INFINITY;
    for (int k = 0; k < 9; ++k)
        put_le32(buf + n + 4 * k, v[k]);
    write_bytes(tpath("nf.pfm"), buf, (size_t)n + 36);
    CHECK(load(tpath("nf.pfm"), NULL, &hm) == 0);
    CHECK(hm.holes == 3);
    for (int k = 0; k < 9 && hm.z; ++k)
        CHECK(hm.z[k] == 5.0f);
    hfs_heightmap_free(&hm);

    /* All holes is an error naming the file. */
    for (int k = 0; k < 9; ++k)
        put_le32(buf + n + 4 * k, NAN);
    write_bytes(tpath("allnan.pfm"), buf, (size_t)n + 36);
    CHECK(load_fail(tpath("allnan.pfm"), NULL) == HFS_E_FORMAT);
}

/* ---- detection and guards ------------------------------------------------------------ */

static void test_detection(void)
{
    unsigned char buf[64];
    hfs_height_load_opts o;
    hfs_heightmap hm;
    hfs_error err;
    int n = sprintf((char *)buf, "P5 2 2 255\n");
    memcpy(buf + n, "\1\2\3\4", 4);

    /* PGM content named .png: precise error; no extension: sniffed. */
    write_bytes(tpath("pgm_as.png"), buf, (size_t)n + 4);
    CHECK(load_fail(tpath("pgm_as.png"), NULL) == HFS_E_FORMAT);
    CHECK(hfs_height_load(tpath("pgm_as.png"), NULL, &hm, &err) < 0 && strstr(err.msg, "PGM"));
    write_bytes(tpath("noext"), buf, (size_t)n + 4);
    CHECK(load(tpath("noext"), NULL, &hm) == 0);
    CHECK(hm.format == HFS_HEIGHT_PGM && hm.z && hm.z[3] == 4.0f);
    hfs_heightmap_free(&hm);

    /* A raw size for a non-raw file is an error, not silently ignored. */
    memset(&o, 0, sizeof o);
    o.raw_width = o.raw_height = 2;
    CHECK(load_fail(tpath("noext"), &o) == HFS_E_INVALID);

    /* Guards. */
    memset(&o, 0, sizeof o);
    o.max_width = 1;
    CHECK(load_fail(tpath("noext"), &o) == HFS_E_INVALID);
    memset(&o, 0, sizeof o);
    o.max_texels = 3;
    CHECK(load_fail(tpath("noext"), &o) == HFS_E_INVALID);
    memset(&o, 0, sizeof o);
    o.max_texels = 4;
    CHECK(load(tpath("noext"), &o, &hm) == 0);
    hfs_heightmap_free(&hm);

    /* NULL-safety of the free function and bad arguments. */
    hfs_heightmap_free(NULL);
    CHECK(hfs_height_load(NULL, NULL, &hm, &err) == HFS_E_INVALID);
    CHECK(hfs_height_load(tpath("noext"), NULL, NULL, NULL) == HFS_E_INVALID);
}

int main(void)
{
    if (make_tmpdir("io_height") != 0)
        return 1;
    test_pgm();
    test_pfm();
    test_png();
    test_asc();
    test_raw();
    test_nodata();
    test_detection();
    rm_tmpdir();
    return finish_checks("test_io_height");
}
