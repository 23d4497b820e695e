/*
 * test_io_mutate.c — robustness of the height loaders on damaged versions of
 * valid files: every proper prefix (must fail cleanly, except for the text
 * formats, where a prefix can be a valid smaller file) and every byte XOR-ed
 * with a few masks (may load or fail, but a load must give a sane field and
 * a failure a clean one-line message).  Meant to run under ASan/UBSan too.
 */
#include "hfs_io.h"
#include "test_util.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* 1 = loaded a sane field, 0 = failed cleanly, -1 = anything else. */
static int try_load(const char *path, const hfs_height_load_opts *o)
{
    hfs_heightmap hm;
    hfs_error err;
    int rc;
    memset(&hm, 0x5a, sizeof hm);
    err.msg[0] = '\0';
    rc = hfs_height_load(path, o, &hm, &err);
    if (rc == 0) {
        int sane = hm.width >= 2 && hm.height >= 2 && hm.z && hm.holes >= 0 &&
                   hm.holes < (long)hm.width * hm.height;
        for (long k = 0; sane && k < (long)hm.width * hm.height; ++k)
            sane = isfinite(hm.z[k]);
        hfs_heightmap_free(&hm);
        return sane ? 1 : -1;
    }
    if (rc < 0 && strstr(err.msg, path) == err.msg && !strchr(err.msg, '\n') && !hm.z &&
        !hm.width && !hm.height)
        return 0;
    fprintf(stderr, "  bad failure (%d) for %s: %s\n", rc, path, err.msg);
    return -1;
}

static void mutate(const char *name, const hfs_height_load_opts *o, int prefixes_may_load)
{
    size_t n;
    unsigned char *b = read_all(tpath(name), &n);
    char victim[64];
    static const unsigned char masks[] = {0x01, 0x20, 0x80, 0xff};
    int loads = 0, fails = 0, bad = 0;

    snprintf(victim, sizeof victim, "m_%s", name);
    CHECK(b != NULL);
    if (!b)
        return;
    CHECK(try_load(tpath(name), o) == 1); /* the original is valid */
    for (size_t len = 0; len < n; ++len) {
        int r;
        write_bytes(tpath(victim), b, len);
        r = try_load(tpath(victim), o);
        if (r < 0 || (r == 1 && !prefixes_may_load)) {
            if (!bad++)
                fprintf(stderr, "  %s: prefix of %zu bytes -> %d\n", name, len, r);
        }
    }
    for (size_t k = 0; k < n; ++k) {
        for (size_t m = 0; m < sizeof masks; ++m) {
            int r;
            b[k] ^= masks[m];
            write_bytes(tpath(victim), b, n);
            b[k] ^= masks[m];
            r = try_load(tpath(victim), o);
            if (r < 0)
                ++bad;
            else if (r)
                ++loads;
            else
                ++fails;
        }
    }
    printf("%-12s %4zu bytes: %d flips loaded, %d rejected, %d bad\n", name, n, loads, fails, bad);
    CHECK(bad == 0);
    free(b);
}

int main(void)
{
    float v[30];
    hfs_error err;
    hfs_height_load_opts raw;
    unsigned char buf[512];
    int n;

    if (make_tmpdir("io_mutate") != 0)
        return 1;
    for (int k = 0; k < 30; ++k)
        v[k] = (float)(k * 1000 + 7);

    CHECK(hfs_png16_write_grey(tpath("a.png"), 6, 5, v, &err) == 0);
    CHECK(hfs_pfm_write_grey(tpath("a.pfm"), 6, 5, v, &err) == 0);
    n = sprintf((char *)buf, "P5\n6 5\n65535\n");
    for (int k = 0; k < 30; ++k) {
        buf[n++] = (unsigned char)((unsigned)v[k] >> 8);
        buf[n++] = (unsigned char)(unsigned)v[k];
    }
    write_bytes(tpath("a16.pgm"), buf, (size_t)n);
    n = sprintf((char *)buf, "P5 3 2 255 ");
    memcpy(buf + n, "\x01\x02\x03\x04\x05\x06", 6);
    write_bytes(tpath("a8.pgm"), buf, (size_t)n + 6);
    n = sprintf((char *)buf, "P2\n3 2\n255\n1 2 3\n4 5 6\n");
    write_bytes(tpath("a2.pgm"), buf, (size_t)n);
    n = sprintf((char *)buf, "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n"
                             "NODATA_value -1\n1.5 2 -1\n4 5e1 6\n");
    write_bytes(tpath("a.asc"), buf, (size_t)n);
    for (int k = 0; k < 6; ++k)
        memcpy(buf + 4 * k, &v[k], 4); /* host order is little-endian here */
    write_bytes(tpath("a.raw"), buf, 24);

    mutate("a.png", NULL, 0);
    mutate("a.pfm", NULL, 0);
    mutate("a16.pgm", NULL, 0);
    mutate("a8.pgm", NULL, 0);
    mutate("a2.pgm", NULL, 1);
    mutate("a.asc", NULL, 1);
    memset(&raw, 0, sizeof raw);
    raw.raw_width = 3;
    raw.raw_height = 2;
    mutate("a.raw", &raw, 0);

    rm_tmpdir();
    return finish_checks("test_io_mutate");
}
