/*
 * hfgen — deterministic procedural height fields for tests and benchmarks
 * (tools/terrain_gen.h describes each kind).
 *
 *   hfgen KIND    --size WxH -o OUT.pfm [--seed N] [--relief R]
 *       KIND = flat | cones (SN08 figs. 3-10 style) | sine (grating) |
 *              eggtray | city (blocks, vertical walls) | spike (one texel) |
 *              cliff | fractal (--seed, --relief, --hurst H: the octaves'
 *              amplitude ratio 2^-H, default 1) | panel (grooved, embossed) |
 *              tower (--block W,H: one block, default 40,30) | boxes (--seed)
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
#include "cli_usage.h"
#include "sky_gen.h"
#include "terrain_gen.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void usage(FILE *to)
{
    fprintf(to, "usage: hfgen %s --size WxH -o OUT.pfm [--seed N] [--relief R]\n"
                "             [--block W,H (tower)] [--hurst H (fractal, default 1)]\n"
                "       hfgen crop IN --rect X,Y,W,H -o OUT.pfm\n"
                "       hfgen albedo IN -o OUT.pfm\n"
                "       hfgen sky [--size WxH] -o OUT.pfm [--sun PHI,ELEV] [--sun-diameter D]\n"
                "                 [--share S] [--noise A] [--seed N]\n", hfs_terrain_names());
}

/* A seed: a whole number in [0, 2^32). */
static int parse_seed(const char *v, unsigned *seed)
{
    char *end;
    const unsigned long long x = strtoull(v, &end, 10);
    if (end == v || *end || v[0] == '-' || x > 0xffffffffull)
        return -1;
    *seed = (unsigned)x;
    return 0;
}

/* WxH, each side in [lo, 16384]. */
static int parse_size(const char *v, int lo, int *w, int *h)
{
    char tail;
    return sscanf(v, "%dx%d%c", w, h, &tail) == 2 && *w >= lo && *h >= lo && *w <= 16384 &&
                   *h <= 16384
               ? 0
               : -1;
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

/* hfgen sky's flags: 0, or the usage error printed (HFS_EXIT_USAGE). */
typedef struct sky_args {
    int w, h;
    double phi, elev, diam, share, noise;
    unsigned seed;
    const char *out;
} sky_args;

static int sky_flag(sky_args *s, const char *a, const char *v)
{
    int bad = 0;
    if (!strcmp(a, "--size"))
        bad = parse_size(v, 1, &s->w, &s->h);
    else if (!strcmp(a, "--sun")) {
        char tail;
        bad = !(sscanf(v, "%lf,%lf%c", &s->phi, &s->elev, &tail) == 2 && isfinite(s->phi) &&
                s->elev >= -90.0 && s->elev <= 90.0);
    } else if (!strcmp(a, "--sun-diameter"))
        bad = hfs_cli_real(v, 0.0, 90.0, &s->diam) || !(s->diam > 0.0);
    else if (!strcmp(a, "--share"))
        bad = hfs_cli_real(v, 0.0, 1.0, &s->share) || !(s->share > 0.0 && s->share < 1.0);
    else if (!strcmp(a, "--noise"))
        bad = hfs_cli_real(v, 0.0, 1.0, &s->noise) || !(s->noise < 1.0);
    else if (!strcmp(a, "--seed"))
        bad = parse_seed(v, &s->seed);
    else if (!strcmp(a, "-o"))
        s->out = v;
    else
        return hfs_usage_error("hfgen", "sky: %s: unknown option", a);
    return bad ? hfs_usage_error("hfgen", "sky: %s: '%s' is malformed or out of range", a, v) : 0;
}

/* hfgen sky: the sky described above. */
static int sky_map(int argc, char **argv)
{
    sky_args s = {2048, 1024, 135.0, 35.0, 0.5, 0.8, 0.0, 1, NULL};
    for (int i = 2; i < argc; i += 2) {
        if (argv[i][0] != '-')
            return hfs_usage_error("hfgen", "sky: %s: unexpected argument", argv[i]);
        if (i + 1 >= argc)
            return hfs_usage_error("hfgen", "sky: %s: missing value", argv[i]);
        if (sky_flag(&s, argv[i], argv[i + 1]))
            return HFS_EXIT_USAGE;
    }
    if (!s.out)
        return hfs_usage_error("hfgen", "sky: no output file (-o OUT.pfm)");
    hfs_sky_desc d;
    hfs_sky_defaults(&d, s.w, s.h);
    d.noise = s.noise;
    d.seed = s.seed;
    d.n_disks = 1;
    d.disk[0] = (hfs_sky_disk){s.phi, s.elev, 0.5 * s.diam, {1.0f, 0.96f, 0.9f}};
    hfs_error err = {{0}};
    hfs_image img;
    double e[1][3];
    if (hfs_image_alloc(&img, s.w, s.h, &err) || hfs_sky_render(&d, img.rgb, e)) {
        fprintf(stderr, "hfgen: sky: out of memory for %dx%d\n", s.w, s.h);
        return 1;
    }
    hfs_sky_set_share(&d, 0, s.share, img.rgb, e);
    const int rc = hfs_pfm_write(s.out, &img, 0, &err);
    if (rc)
        fprintf(stderr, "hfgen: %s\n", err.msg);
    hfs_image_free(&img);
    return rc ? 1 : 0;
}

/* The arguments of the other kinds (crop, albedo, the terrains). */
typedef struct gen_args {
    const char *kind, *out, *in, *rect;
    int w, h;
    unsigned seed;
    double relief;
    int block_w, block_h; /* tower: --block W,H (0: the default 40,30) */
    double hurst;         /* fractal: --hurst H (default 1) */
} gen_args;

/* 1 if KIND is one of hfs_terrain_names()' "a|b|c". */
static int is_terrain(const char *kind)
{
    const size_t n = strlen(kind);
    for (const char *p = hfs_terrain_names(); *p;) {
        const char *bar = strchr(p, '|');
        const size_t len = bar ? (size_t)(bar - p) : strlen(p);
        if (len == n && n && !strncmp(p, kind, n))
            return 1;
        p += len + (bar != NULL);
    }
    return 0;
}

static int gen_flag(gen_args *g, const char *a, const char *v)
{
    if (!strcmp(a, "--size")) {
        if (parse_size(v, 2, &g->w, &g->h))
            return hfs_usage_error("hfgen", "--size: '%s' is not WxH within [2, 16384]", v);
    } else if (!strcmp(a, "--seed")) {
        if (parse_seed(v, &g->seed))
            return hfs_usage_error("hfgen", "--seed: '%s' is not a whole number", v);
    } else if (!strcmp(a, "--relief")) {
        if (hfs_cli_real(v, 0.0, 100.0, &g->relief))
            return hfs_usage_error("hfgen", "--relief: '%s' is out of range [0, 100]", v);
    } else if (!strcmp(a, "--hurst")) {
        if (hfs_cli_real(v, 0.0, 2.0, &g->hurst))
            return hfs_usage_error("hfgen", "--hurst: '%s' is out of range [0, 2]", v);
    } else if (!strcmp(a, "--block")) {
        char tail;
        if (sscanf(v, "%d,%d%c", &g->block_w, &g->block_h, &tail) != 2 || g->block_w < 1 ||
            g->block_h < 1 || g->block_w > 16384 || g->block_h > 16384)
            return hfs_usage_error("hfgen", "--block: '%s' is not W,H within [1, 16384]", v);
    } else if (!strcmp(a, "-o")) {
        g->out = v;
    } else if (!strcmp(a, "--rect")) {
        g->rect = v;
    } else {
        return hfs_usage_error("hfgen", "%s: unknown option", a);
    }
    return 0;
}

/* 0, or HFS_EXIT_USAGE with the one line printed. */
static int gen_parse(int argc, char **argv, gen_args *g)
{
    *g = (gen_args){argv[1], NULL, NULL, NULL, 0, 0, 1, 0.25, 0, 0, 1.0};
    const int terrain = is_terrain(g->kind), takes_in = !terrain;
    if (!terrain && strcmp(g->kind, "crop") && strcmp(g->kind, "albedo"))
        return hfs_usage_error("hfgen", "'%s' is not a kind (%s|crop|albedo|sky)", g->kind,
                               hfs_terrain_names());
    for (int i = 2; i < argc; ++i) {
        const char *a = argv[i];
        if (a[0] != '-') {
            if (!takes_in || g->in)
                return hfs_usage_error("hfgen", "%s: unexpected argument", a);
            g->in = a;
        } else if (i + 1 >= argc) {
            return hfs_usage_error("hfgen", "%s: missing value", a);
        } else if (gen_flag(g, a, argv[++i])) {
            return HFS_EXIT_USAGE;
        }
    }
    if (takes_in && !g->in)
        return hfs_usage_error("hfgen", "%s: no input height file", g->kind);
    if (!strcmp(g->kind, "crop") && !g->rect)
        return hfs_usage_error("hfgen", "crop: no --rect X,Y,W,H");
    if (terrain && g->w < 2)
        return hfs_usage_error("hfgen", "%s needs --size WxH", g->kind);
    if (!g->out)
        return hfs_usage_error("hfgen", "%s: no output file (-o OUT.pfm)", g->kind);
    return 0;
}

/* hfgen crop: the rectangle of the input's heights; NULL after a message. */
static float *crop(gen_args *g, int *rc)
{
    int x0, y0;
    char tail;
    if (sscanf(g->rect, "%d,%d,%d,%d%c", &x0, &y0, &g->w, &g->h, &tail) != 4) {
        *rc = hfs_usage_error("hfgen", "--rect: '%s' is not X,Y,W,H", g->rect);
        return NULL;
    }
    hfs_error err = {{0}};
    hfs_heightmap hm;
    if (hfs_height_load(g->in, NULL, &hm, &err)) {
        fprintf(stderr, "hfgen: %s\n", err.msg);
        *rc = 1;
        return NULL;
    }
    float *z = NULL;
    if (x0 < 0 || y0 < 0 || g->w < 2 || g->h < 2 || x0 > hm.width - g->w ||
        y0 > hm.height - g->h) {
        fprintf(stderr, "hfgen: --rect %s lies outside %s (%dx%d)\n", g->rect, g->in, hm.width,
                hm.height);
        *rc = 2;
    } else if (!(z = malloc((size_t)g->w * g->h * sizeof *z))) {
        fprintf(stderr, "hfgen: out of memory\n");
        *rc = 1;
    } else {
        for (int j = 0; j < g->h; ++j)
            memcpy(z + (size_t)j * g->w, hm.z + (size_t)(y0 + j) * hm.width + x0,
                   (size_t)g->w * sizeof *z);
    }
    hfs_heightmap_free(&hm);
    return z;
}

int main(int argc, char **argv)
{
#ifdef HFS_HAVE_GDAL
    hfs_gdal_register(); /* hfgen crop reads GeoTIFF, SRTM .hgt, VRT ... */
#endif
    if (argc < 2)
        return hfs_usage_error("hfgen", "no kind given (%s|crop|albedo|sky)", hfs_terrain_names());
    if (hfs_is_help(argv[1])) {
        usage(stdout);
        return 0;
    }
    if (!strcmp(argv[1], "sky"))
        return sky_map(argc, argv);
    gen_args g;
    if (gen_parse(argc, argv, &g))
        return HFS_EXIT_USAGE;
    if (!strcmp(g.kind, "albedo"))
        return albedo_map(g.in, g.out);
    int rc = 0;
    float *z = NULL;
    if (!strcmp(g.kind, "crop")) {
        if (!(z = crop(&g, &rc)))
            return rc;
    } else if (!(z = calloc((size_t)g.w * g.h, sizeof *z)) ||
               hfs_terrain_make(g.kind, z, g.w, g.h, g.seed, g.relief)) {
        fprintf(stderr, "hfgen: out of memory\n");
        free(z);
        return 1;
    }
    if (g.block_w && !strcmp(g.kind, "tower"))
        hfs_terrain_tower(z, g.w, g.h, g.block_w, g.block_h);
    if (g.hurst != 1.0 && !strcmp(g.kind, "fractal") &&
        hfs_terrain_fbm(z, g.w, g.h, g.seed, g.relief, g.hurst)) {
        fprintf(stderr, "hfgen: out of memory\n");
        free(z);
        return 1;
    }
    hfs_error err = {{0}};
    rc = hfs_pfm_write_grey(g.out, g.w, g.h, z, &err);
    free(z);
    if (rc) {
        fprintf(stderr, "hfgen: %s\n", err.msg);
        return 1;
    }
    return 0;
}
