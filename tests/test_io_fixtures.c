/*
 * test_io_fixtures.c — loads the small valid files in tests/data/io, written
 * from the format specifications by tests/data/broken/make_corpus.py (Python
 * standard library only), and compares every value exactly.  This checks our
 * loaders against an encoder that shares no code with them or with our
 * writers: a PNG (16-bit grey), OpenEXR (uncompressed half RGB; float Y with
 * an offset data window) and Radiance (flat and RLE scanlines).
 */
#include "hfs_io.h"
#include "test_util.h"

#include <stdio.h>
#include <string.h>

static const char *dir;

static const char *fix(const char *name)
{
    static char buf[4096];
    snprintf(buf, sizeof buf, "%s/%s", dir, name);
    return buf;
}

static int env(const char *name, hfs_envmap *m)
{
    hfs_error err;
    int rc = hfs_envmap_load(fix(name), m, &err);
    if (rc)
        fprintf(stderr, "  %s\n", err.msg);
    return rc;
}

int main(int argc, char **argv)
{
    hfs_heightmap hm;
    hfs_envmap m;
    hfs_error err;

    if (argc != 2) {
        fprintf(stderr, "usage: %s FIXTURE_DIR\n", argv[0]);
        return 2;
    }
    dir = argv[1];

    CHECK(hfs_height_load(fix("grey16.png"), NULL, &hm, &err) == 0);
    CHECK(hm.width == 3 && hm.height == 2);
    for (int j = 0; hm.z && j < 2; ++j)
        for (int i = 0; i < 3; ++i)
            CHECK(hm.z[j * 3 + i] == (float)(1000 * j + 300 * i + 1));
    hfs_heightmap_free(&hm);

    CHECK(env("rgb_half.exr", &m) == 0);
    CHECK(m.width == 4 && m.height == 3);
    for (int j = 0; m.rgb && j < 3; ++j)
        for (int i = 0; i < 4; ++i) {
            const float *p = m.rgb + (j * 4 + i) * 3;
            CHECK(p[0] == 1.0f * (float)(i + 1) + 0.25f * (float)j);
            CHECK(p[1] == 2.0f * (float)(i + 1) + 0.25f * (float)j);
            CHECK(p[2] == 4.0f * (float)(i + 1) + 0.25f * (float)j);
        }
    hfs_envmap_free(&m);

    CHECK(env("y_float.exr", &m) == 0);
    CHECK(m.width == 3 && m.height == 2);
    for (int j = 0; m.rgb && j < 2; ++j)
        for (int i = 0; i < 3; ++i)
            for (int c = 0; c < 3; ++c)
                CHECK(m.rgb[(j * 3 + i) * 3 + c] == (float)(i + 1) + 0.25f * (float)j);
    hfs_envmap_free(&m);

    {
        static const char *const hdrs[2] = {"flat.hdr", "rle.hdr"};
        static const int widths[2] = {3, 9};
        for (int t = 0; t < 2; ++t) {
            int w = widths[t];
            CHECK(env(hdrs[t], &m) == 0);
            CHECK(m.width == w && m.height == 2);
            for (int j = 0; m.rgb && j < 2; ++j)
                for (int i = 0; i < w; ++i) {
                    const float *p = m.rgb + (j * w + i) * 3;
                    CHECK(p[0] == (float)(4 + i));
                    CHECK(p[1] == (float)(2 + j) * 0.5f);
                    CHECK(p[2] == 1.0f);
                }
            hfs_envmap_free(&m);
        }
    }

    return finish_checks("test_io_fixtures");
}
