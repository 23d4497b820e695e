/*
 * hfgen — deterministic procedural height fields for tests and benchmarks
 * (tools/terrain_gen.h describes each kind).
 *
 *   hfgen KIND    --size WxH -o OUT.pfm [--seed N] [--relief R]
 *       KIND = flat | cones (SN08 figs. 3-10 style) | sine (grating) |
 *              eggtray | city (blocks, vertical walls) | spike (one texel) |
 *              cliff | fractal (--seed, --relief) | panel (grooved, embossed)
 *   hfgen crop    IN --rect X,Y,W,H -o OUT.pfm   (any loadable height file)
 *
 * Heights are in texel units (use dx = 1, zscale = 1 to keep proportions);
 * the same arguments give the same file, bit for bit, on any machine
 * (integer hashing, no libc random).  Output is PFM "Pf", row j = 0 first.
 */
#include "hfs_io.h"
#include "terrain_gen.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void usage(void)
{
    fprintf(stderr, "usage: hfgen %s --size WxH -o OUT.pfm [--seed N] [--relief R]\n"
                    "       hfgen crop IN --rect X,Y,W,H -o OUT.pfm\n", hfs_terrain_names());
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        usage();
        return 2;
    }
    const char *kind = argv[1], *out = NULL, *in = NULL, *rect = NULL;
    int w = 0, h = 0;
    unsigned seed = 1;
    double relief = 0.25;
    for (int i = 2; i < argc; ++i) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--size") && v) {
            if (sscanf(v, "%dx%d", &w, &h) != 2 || w < 2 || h < 2 || w > 16384 || h > 16384) {
                fprintf(stderr, "hfgen: --size: '%s' is not WxH within [2, 16384]\n", v);
                return 2;
            }
            ++i;
        } else if (!strcmp(a, "-o") && v) {
            out = v;
            ++i;
        } else if (!strcmp(a, "--seed") && v) {
            seed = (unsigned)strtoul(v, NULL, 10);
            ++i;
        } else if (!strcmp(a, "--relief") && v) {
            relief = strtod(v, NULL);
            if (!(relief >= 0.0 && relief <= 100.0)) {
                fprintf(stderr, "hfgen: --relief: '%s' is out of range [0, 100]\n", v);
                return 2;
            }
            ++i;
        } else if (!strcmp(a, "--rect") && v) {
            rect = v;
            ++i;
        } else if (a[0] != '-' && !in) {
            in = a;
        } else {
            fprintf(stderr, "hfgen: %s: unexpected argument\n", a);
            usage();
            return 2;
        }
    }
    if (!out) {
        usage();
        return 2;
    }
    hfs_error err = {{0}};
    float *z = NULL;
    if (!strcmp(kind, "crop")) {
        int x0, y0;
        hfs_heightmap hm;
        if (!in || !rect || sscanf(rect, "%d,%d,%d,%d", &x0, &y0, &w, &h) != 4) {
            usage();
            return 2;
        }
        if (hfs_height_load(in, NULL, &hm, &err)) {
            fprintf(stderr, "hfgen: %s\n", err.msg);
            return 1;
        }
        if (x0 < 0 || y0 < 0 || w < 2 || h < 2 || x0 + w > hm.width || y0 + h > hm.height) {
            fprintf(stderr, "hfgen: --rect %s lies outside %s (%dx%d)\n", rect, in, hm.width, hm.height);
            hfs_heightmap_free(&hm);
            return 2;
        }
        z = malloc((size_t)w * h * sizeof *z);
        if (z)
            for (int j = 0; j < h; ++j)
                memcpy(z + (size_t)j * w, hm.z + (size_t)(y0 + j) * hm.width + x0, (size_t)w * sizeof *z);
        hfs_heightmap_free(&hm);
    } else {
        if (w < 2) {
            fprintf(stderr, "hfgen: %s needs --size WxH\n", kind);
            return 2;
        }
        z = calloc((size_t)w * h, sizeof *z);
        if (z) {
            const int rc = hfs_terrain_make(kind, z, w, h, seed, relief);
            if (rc == -1) {
                fprintf(stderr, "hfgen: unknown kind '%s'\n", kind);
                free(z);
                usage();
                return 2;
            }
            if (rc) {
                free(z);
                z = NULL;
            }
        }
    }
    if (!z) {
        fprintf(stderr, "hfgen: out of memory\n");
        return 1;
    }
    int rc = hfs_pfm_write_grey(out, w, h, z, &err);
    free(z);
    if (rc) {
        fprintf(stderr, "hfgen: %s\n", err.msg);
        return 1;
    }
    return 0;
}
