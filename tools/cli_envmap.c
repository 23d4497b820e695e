/*
 * cli_envmap.c — `hfshade envmap decompose` (cli_envmap.h).
 *
 * Prints, in the scene syntax (docs/SCENE.md, degrees), one `key = PHI,
 * ELEV,ALPHA,R,G,B` line per light (`PHI,ELEV,ALPHA,LE` where R = G = B)
 * and the residual as `env-sh-r`, `env-sh-g`, `env-sh-b` (one line a
 * channel), so the lines are a scene's lighting in colour.  Coefficients
 * are printed with 4 significant digits so each line fits a scene file's
 * 190 characters (at most 186 here).
 *
 * The picture (--picture OUT.png): the map, reduced by an integer factor
 * to at most 2048 texels wide, Reinhard-tonemapped with an exposure that
 * puts the residual's mean luminance at 0.5, each light's disk outlined in
 * red (at least 3 texels across so a small sun stays visible).
 */
#include "cli_envmap.h"
#include "cli_usage.h"
#include "env_decompose.h"
#include "hfs_io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define DEG (180.0 / PI)

typedef struct envmap_args {
    const char *map, *picture;
    hfs_env_decompose_opts o;
} envmap_args;

static void usage(void)
{
    printf("usage: hfshade envmap decompose MAP [--max-lights N] [--min-share F] "
           "[--contrast C] [--max-radius DEG] [--picture OUT.png]\n");
}

/* The error for argument A that is not understood (V: the next one). */
static int bad_argument(const char *a, const char *v)
{
    static const char *const valued[] = {"--max-lights", "--min-share", "--contrast",
                                         "--max-radius", "--picture"};
    for (size_t k = 0; k < sizeof valued / sizeof valued[0] && !v; ++k)
        if (!strcmp(a, valued[k]))
            return hfs_usage_error("hfshade", "envmap: %s: missing value", a);
    return hfs_usage_error("hfshade", "envmap: %s: %s", a,
                           a[0] == '-' ? "unknown option" : "unexpected argument");
}

static int parse(int argc, char **argv, envmap_args *a)
{
    memset(a, 0, sizeof *a);
    hfs_env_decompose_defaults(&a->o);
    if (argc >= 2 && hfs_is_help(argv[1]))
        return -1;
    if (argc < 2 || strcmp(argv[1], "decompose")) {
        if (argc < 2)
            hfs_usage_error("hfshade", "envmap: no subcommand (decompose)");
        else
            hfs_usage_error("hfshade", "envmap: '%s' is not a subcommand (decompose)", argv[1]);
        return -2;
    }
    for (int i = 2; i < argc; ++i) {
        if (hfs_is_help(argv[i]))
            return -1;
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        char *end = NULL;
        if (!strcmp(argv[i], "--max-lights") && v) {
            long n = strtol(v, &end, 10);
            if (*end || n < 0 || n > HFS_ENV_MAX_LIGHTS) {
                fprintf(stderr, "hfshade: --max-lights: '%s' is not an integer in [0, %d]\n",
                        v, HFS_ENV_MAX_LIGHTS);
                return -2;
            }
            a->o.max_lights = (int)n;
        } else if ((!strcmp(argv[i], "--min-share") || !strcmp(argv[i], "--contrast")) && v) {
            const int share = argv[i][2] == 'm';
            double x = strtod(v, &end);
            if (*end || !(share ? x >= 0.0 && x <= 1.0 : x >= 1.0 && x <= 1e6)) {
                fprintf(stderr, "hfshade: %s: '%s' is not a number in %s\n", argv[i], v,
                        share ? "[0, 1]" : "[1, 1e6]");
                return -2;
            }
            *(share ? &a->o.min_share : &a->o.contrast) = x;
        } else if (!strcmp(argv[i], "--max-radius") && v) { /* degrees */
            double x = strtod(v, &end);
            if (*end || !(x >= 0.0 && x <= 180.0)) {
                fprintf(stderr, "hfshade: --max-radius: '%s' is not a number of degrees in "
                        "[0, 180]\n", v);
                return -2;
            }
            a->o.max_radius = x * 3.14159265358979323846 / 180.0;
        } else if (!strcmp(argv[i], "--picture") && v) {
            a->picture = v;
        } else if (argv[i][0] != '-' && !a->map) {
            a->map = argv[i];
            continue;
        } else {
            bad_argument(argv[i], v);
            return -2;
        }
        ++i;
    }
    if (!a->map)
        hfs_usage_error("hfshade", "envmap decompose: no MAP given");
    return a->map ? 0 : -2;
}

static double lum3(const double *v)
{
    return 0.2126 * v[0] + 0.7152 * v[1] + 0.0722 * v[2];
}

static void print_scene(const char *map, int w, int h, const hfs_env_decomp *d)
{
    double share = 0.0;
    for (int k = 0; k < d->n_lights; ++k)
        share += d->light[k].share;
    printf("# %s: %dx%d, %d light%s holding %.1f%% of the energy (luminance)\n", map, w, h,
           d->n_lights, d->n_lights == 1 ? "" : "s", 100.0 * share);
    for (int k = 0; k < d->n_lights; ++k) {
        const hfs_env_light *l = &d->light[k];
        const float *rgb = l->radiance;
        printf("# light %d: %.2f%% of the energy\n", k + 1, 100.0 * l->share);
        printf("key = %.4f,%.4f,%.4f,", l->phi * DEG, l->elev * DEG, l->alpha * DEG);
        if (rgb[0] == rgb[1] && rgb[1] == rgb[2])
            printf("%.9g\n", rgb[0]);
        else
            printf("%.9g,%.9g,%.9g\n", rgb[0], rgb[1], rgb[2]);
    }
    for (int ch = 0; ch < 3; ++ch) {
        printf("env-sh-%c = ", "rgb"[ch]);
        for (int k = 0; k < HFS_SH_COEFFS; ++k)
            printf("%.4g%s", d->residual_sh[ch][k], k + 1 < HFS_SH_COEFFS ? "," : "\n");
    }
}

/* Marks the outline of light l (radius at least 1.5 texels) in img, which
 * shows the map reduced by f. */
static void circle(hfs_image *img, int f, int w, int h, const hfs_env_light *l, float mark)
{
    const double px = PI / h * f;
    const double r = fmax(l->alpha, 1.5 * px);
    const double d[3] = {cos(l->elev) * cos(l->phi), cos(l->elev) * sin(l->phi), sin(l->elev)};
    double u[3] = {-sin(l->phi), cos(l->phi), 0.0}, v[3];
    v[0] = d[1] * u[2] - d[2] * u[1];
    v[1] = d[2] * u[0] - d[0] * u[2];
    v[2] = d[0] * u[1] - d[1] * u[0];
    const int steps = 64 + (int)(8.0 * r / px);
    for (int s = 0; s < steps; ++s) {
        const double t = 2.0 * PI * s / steps;
        double q[3];
        for (int k = 0; k < 3; ++k)
            q[k] = cos(r) * d[k] + sin(r) * (cos(t) * u[k] + sin(t) * v[k]);
        double phi = atan2(q[1], q[0]);
        if (phi < 0.0)
            phi += 2.0 * PI;
        const double e = asin(fmax(-1.0, fmin(1.0, q[2])));
        const int i = (int)(phi / (2.0 * PI) * img->width) % img->width;
        int j = (int)((0.5 * PI - e) / PI * img->height);
        j = j < 0 ? 0 : j >= img->height ? img->height - 1 : j;
        float *p = img->rgb + ((size_t)j * img->width + i) * 3;
        p[0] = mark;
        p[1] = p[2] = 0.0f;
    }
    (void)w;
}

static int picture(const char *path, const float *rgb, int w, int h, const hfs_env_decomp *d,
                   hfs_error *err)
{
    int f = 1;
    while (w / f > 2048 && h / (f + 1) >= 1)
        ++f;
    hfs_image img;
    int rc = hfs_image_alloc(&img, w / f > 0 ? w / f : 1, h / f > 0 ? h / f : 1, err);
    if (rc)
        return rc;
    for (int j = 0; j < img.height; ++j)
        for (int i = 0; i < img.width; ++i)
            for (int c = 0; c < 3; ++c) {
                double s = 0.0;
                for (int b = 0; b < f; ++b)
                    for (int a = 0; a < f; ++a)
                        s += rgb[((size_t)(j * f + b) * w + (size_t)(i * f + a)) * 3 + c];
                img.rgb[((size_t)j * img.width + i) * 3 + c] = (float)(s / (f * f));
            }
    const double mean = lum3(d->residual_energy) / (4.0 * PI);
    hfs_png_opts o = {mean > 0.0 ? 0.5 / mean : 1.0, HFS_TONEMAP_REINHARD};
    for (int k = 0; k < d->n_lights; ++k)
        circle(&img, f, w, h, &d->light[k], (float)(1e6 / o.exposure));
    rc = hfs_png_write(path, &img, &o, err);
    hfs_image_free(&img);
    return rc;
}

int hfs_cli_envmap(int argc, char **argv)
{
    envmap_args a;
    const int p = parse(argc, argv, &a);
    if (p == -1) {
        usage();
        return 0;
    }
    if (p)
        return HFS_EXIT_USAGE;
    hfs_envmap m;
    hfs_error err = {{0}};
    if (hfs_envmap_load(a.map, &m, &err)) {
        fprintf(stderr, "hfshade: %s\n", err.msg);
        return 1;
    }
    /* The picture shows the map as loaded: keep a copy of it. */
    const size_t n = (size_t)m.width * m.height * 3;
    float *orig = a.picture ? malloc(n * sizeof *orig) : NULL;
    int rc = a.picture && !orig ? hfs_fail(&err, HFS_E_NOMEM, "%s: out of memory", a.map) : 0;
    if (orig)
        memcpy(orig, m.rgb, n * sizeof *orig);
    hfs_env_decomp d;
    if (!rc)
        rc = hfs_env_decompose(m.rgb, m.width, m.height, &a.o, a.map, &d, &err);
    if (!rc && a.picture)
        rc = picture(a.picture, orig, m.width, m.height, &d, &err);
    if (!rc)
        print_scene(a.map, m.width, m.height, &d);
    free(orig);
    hfs_envmap_free(&m);
    if (rc) {
        fprintf(stderr, "hfshade: %s\n", err.msg);
        return 1;
    }
    return 0;
}
