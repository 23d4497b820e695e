/*
 * hfgen — deterministic procedural height fields for tests and benchmarks
 * (tools/terrain_gen.h describes each kind).
 *
 *   hfgen KIND    --size WxH -o OUT.pfm [--seed N] [--relief R]
 *       KIND = flat | cones (SN08 figs. 3-10 style) | sine (grating) |
 *              eggtray | city (blocks, vertical walls) | spike (one texel) |
 *              cliff | fractal (--seed, --relief) | panel (grooved, embossed)
 *   hfgen crop    IN --rect X,Y,W,H -o OUT.pfm   (any loadable height file)
 *   hfgen albedo  IN -o OUT.pfm                  (an albedo map for IN's heights)
 *   hfgen sky     [--size WxH] -o OUT.pfm [--sun PHI,ELEV] [--sun-diameter D]
 *                 [--share S] [--noise A --seed N]
 *       a synthetic equirect sky (tools/sky_gen.h; RGB PFM, first row =
 *       zenith): blue gradient sky, brown ground, a white-ish sun disk of
 *       angular diameter D degrees (default 0.5) at PHI,ELEV degrees
 *       (default 135,35) holding the share S of the map's luminance energy
 *       (default 0.8), anti-aliased; size default 2048x1024; --noise A
 *       multiplies every texel by 1 + A u, u uniform in [-1, 1) (default 0).
 *
 * The albedo map (RGB PFM, the heights' size; what tools/bench_bounce.sh
 * lights its scenes with) is vegetation below and bare rock above:
 * (0.10, 0.16, 0.07) to (0.42, 0.40, 0.36) over the middle half of the
 * height range (a smoothstep of the normalized height), so an indirect
 * bounce carries colour and the albedo varies from texel to texel.
 *
 * Heights are in texel units (use dx = 1, zscale = 1 to keep proportions);
 * the same arguments give the same file, bit for bit, on any machine
 * (integer hashing, no libc random).  Output is PFM "Pf", row j = 0 first.
 */
#include "hfs_io.h"
#ifdef HFS_HAVE_GDAL
#include "height_gdal.h"
#endif
#include "sky_gen.h"
#include "terrain_gen.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void usage(void)
{
    fprintf(stderr, "usage: hfgen %s --size WxH -o OUT.pfm [--seed N] [--relief R]\n"
                    "       hfgen crop IN --rect X,Y,W,H -o OUT.pfm\n"
                    "       hfgen albedo IN -o OUT.pfm\n"
                    "       hfgen sky [--size WxH] -o OUT.pfm [--sun PHI,ELEV] [--sun-diameter D]\n"
                    "                 [--share S] [--noise A] [--seed N]\n", hfs_terrain_names());
}

/* hfgen albedo: the map described above, written as RGB PFM. */
static int albedo_map(const char *in, const char *out)
{
    hfs_error err = {{0}};
    hfs_heightmap hm;
    if (hfs_height_load(in, NULL, &hm, &err)) {
        fprintf(stderr, "hfgen: %s\n", err.msg);
        return 1;
    }
    const size_t n = (size_t)hm.width * hm.height;
    float lo = hm.z[0], hi = hm.z[0];
    for (size_t i = 1; i < n; ++i)
        lo = hm.z[i] < lo ? hm.z[i] : lo, hi = hm.z[i] > hi ? hm.z[i] : hi;
    hfs_image img;
    int rc = hfs_image_alloc(&img, hm.width, hm.height, &err);
    static const float veg[3] = {0.10f, 0.16f, 0.07f}, rock[3] = {0.42f, 0.40f, 0.36f};
    for (size_t i = 0; i < n && !rc; ++i) {
        const double t = hi > lo ? (hm.z[i] - lo) / (hi - lo) : 0.0;
        const double u = fmin(fmax((t - 0.25) / 0.5, 0.0), 1.0), s = u * u * (3.0 - 2.0 * u);
        for (int c = 0; c < 3; ++c)
            img.rgb[3 * i + (size_t)c] = (float)(veg[c] + s * (rock[c] - veg[c]));
    }
    if (!rc)
        rc = hfs_pfm_write(out, &img, 0, &err);
    if (rc)
        fprintf(stderr, "hfgen: %s\n", err.msg);
    hfs_image_free(&img);
    hfs_heightmap_free(&hm);
    return rc ? 1 : 0;
}

/* hfgen sky: the sky described above. */
static int sky_map(int argc, char **argv)
{
    int w = 2048, h = 1024;
    double phi = 135.0, elev = 35.0, diam = 0.5, share = 0.8, noise = 0.0;
    unsigned seed = 1;
    const char *out = NULL;
    for (int i = 2; i < argc; ++i) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        int ok = v != NULL;
        if (ok && !strcmp(a, "--size"))
            ok = sscanf(v, "%dx%d", &w, &h) == 2 && w >= 1 && h >= 1 && w <= 16384 && h <= 16384;
        else if (ok && !strcmp(a, "--sun"))
            ok = sscanf(v, "%lf,%lf", &phi, &elev) == 2 && elev >= -90.0 && elev <= 90.0;
        else if (ok && !strcmp(a, "--sun-diameter"))
            ok = sscanf(v, "%lf", &diam) == 1 && diam > 0.0 && diam <= 90.0;
        else if (ok && !strcmp(a, "--share"))
            ok = sscanf(v, "%lf", &share) == 1 && share > 0.0 && share < 1.0;
        else if (ok && !strcmp(a, "--noise"))
            ok = sscanf(v, "%lf", &noise) == 1 && noise >= 0.0 && noise < 1.0;
        else if (ok && !strcmp(a, "--seed"))
            seed = (unsigned)strtoul(v, NULL, 10);
        else if (ok && !strcmp(a, "-o"))
            out = v;
        else {
            fprintf(stderr, "hfgen: sky: %s%s%s: unexpected or out of range\n", a, v ? " " : "",
                    v ? v : "");
            return 2;
        }
        if (!ok) {
            fprintf(stderr, "hfgen: sky: %s %s: malformed or out of range\n", a, v ? v : "");
            return 2;
        }
        ++i;
    }
    if (!out) {
        usage();
        return 2;
    }
    hfs_sky_desc d;
    hfs_sky_defaults(&d, w, h);
    d.noise = noise;
    d.seed = seed;
    d.n_disks = 1;
    d.disk[0] = (hfs_sky_disk){phi, elev, 0.5 * diam, {1.0f, 0.96f, 0.9f}};
    hfs_error err = {{0}};
    hfs_image img;
    double e[1][3];
    if (hfs_image_alloc(&img, w, h, &err) || hfs_sky_render(&d, img.rgb, e)) {
        fprintf(stderr, "hfgen: sky: out of memory for %dx%d\n", w, h);
        return 1;
    }
    hfs_sky_set_share(&d, 0, share, img.rgb, e);
    const int rc = hfs_pfm_write(out, &img, 0, &err);
    if (rc)
        fprintf(stderr, "hfgen: %s\n", err.msg);
    hfs_image_free(&img);
    return rc ? 1 : 0;
}

int main(int argc, char **argv)
{
#ifdef HFS_HAVE_GDAL
    hfs_gdal_register(); /* hfgen crop reads GeoTIFF, SRTM .hgt, VRT ... */
#endif
    if (argc < 2) {
        usage();
        return 2;
    }
    if (!strcmp(argv[1], "sky"))
        return sky_map(argc, argv);
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
    if (!strcmp(kind, "albedo")) {
        if (!in) {
            usage();
            return 2;
        }
        return albedo_map(in, out);
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
