/*
 * metamorphic.h — what the metamorphic tests share (issue 35, deliverable
 * 1: test_metamorphic.c, test_metamorphic_turn.c, test_metamorphic_pad.c,
 * test_metamorphic_view.c): a scene of up to MM_MAX x MM_MAX heights at a
 * world scale, with its lighting and queried points; its render and point
 * queries; a setting of the renderer with its bounds, and the report of a
 * relation against them; the programs' main.  Header-only (static), one
 * test a translation unit.
 */
#ifndef HFS_TEST_METAMORPHIC_H
#define HFS_TEST_METAMORPHIC_H

#include "gl_test.h"
#include "hfshade.h"
#include "terrain_gen.h"
#include "test_util.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define MM_MAX 64   /* the largest side of a test field */
#define MM_NPTS 24  /* queried points */

typedef struct mm_scene {
    float z[MM_MAX * MM_MAX];
    hfs_field f;
    hfs_lighting l;
    double xyz[3 * MM_NPTS];
} mm_scene;

/* The base scene at world scale s: fractal heights (relief 6, seed 7) on w
 * x h texels, dx 0.7 s, zscale 0.9 s (neither 1: a world position read as
 * a grid position shows); a sky whose SH has terms of every band, odd and
 * even in x and y (a turn or a mirror of it shows); two key lights; a
 * local light and MM_NPTS points over the footprint (some above the
 * surface, some near it) in world units, times s.  No bounces. */
static inline void mm_scene_make(mm_scene *sc, int w, int h, double s)
{
    hfs_terrain_fractal(sc->z, w, h, 7u, 0.5);
    for (int i = 0; i < w * h; ++i)
        sc->z[i] *= 6.0f;
    sc->f = (hfs_field){.width = w, .height = h, .z = sc->z, .dx = 0.7 * s, .zscale = 0.9 * s};
    hfs_lighting_defaults(&sc->l);
    sc->l.has_env = 1;
    const double sky[HFS_SH_COEFFS] = {3.5449077, 0.3, 0.8, -0.2, 0.15, -0.1, 0.05, 0.12,
                                       -0.09, 0.07, 0.05, -0.04, 0.03, 0.06, -0.05, 0.04};
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < HFS_SH_COEFFS; ++k)
            sc->l.env_sh[c][k] = sky[k] * (1.0 - 0.1 * c * (k % 3));
    sc->l.n_key = 2;
    sc->l.key[0] = (hfs_key_light){.phi = 0.7, .elev = 0.35, .alpha = 0.03,
                                   .radiance = {40, 38, 35}};
    sc->l.key[1] = (hfs_key_light){.phi = 2.6, .elev = 0.2, .alpha = 0.05,
                                   .radiance = {10, 12, 16}};
    sc->l.albedo = 0.6;
    sc->l.n_local = 1;
    sc->l.local[0] = (hfs_local_light){.pos = {11.0 * s, 9.0 * s, 7.0 * s}, .radius = 0.8 * s,
                                       .radiance = {200, 180, 160}};
    for (int p = 0; p < MM_NPTS; ++p) {
        const int i = 1 + (p * 7) % (w - 2), j = 1 + (p * 5) % (h - 2);
        sc->xyz[3 * p] = i * sc->f.dx;
        sc->xyz[3 * p + 1] = j * sc->f.dx;
        sc->xyz[3 * p + 2] = (sc->z[j * w + i] + 0.3 + 0.2 * (p % 4)) * sc->f.zscale;
    }
}

typedef struct mm_result {
    hfs_image img;
    float vis[MM_NPTS * HFS_MAX_KEY_LIGHTS];
} mm_result;

/* The scene's image (allocated here: hfs_image_free it) and its points'
 * key-light visibility; 0, or -1 after printing why. */
static inline int mm_render(hfs_renderer *r, const mm_scene *sc, const hfs_quality *q,
                            mm_result *out)
{
    hfs_error err = {""};
    memset(out, 0, sizeof *out);
    if (hfs_image_alloc(&out->img, sc->f.width, sc->f.height, &err) ||
        hfs_renderer_render(r, &sc->f, &sc->l, q, &out->img, NULL, NULL, &err) ||
        hfs_renderer_query_points(r, &sc->f, &sc->l, q, sc->xyz, MM_NPTS, out->vis, &err)) {
        fprintf(stderr, "render: %s\n", err.msg);
        hfs_image_free(&out->img);
        return -1;
    }
    return 0;
}

/* The largest value of an image's channels (the scale differences are
 * told against). */
static inline double mm_peak(const hfs_image *a)
{
    double peak = 0.0;
    for (size_t k = 0; k < (size_t)a->width * (size_t)a->height * 3; ++k)
        peak = fmax(peak, fabs(a->rgb[k]));
    return peak;
}

/* The largest difference of two images of one size, over a's maximum. */
static inline double mm_image_diff(const hfs_image *a, const hfs_image *b)
{
    double d = 0.0;
    for (size_t k = 0; k < (size_t)a->width * (size_t)a->height * 3; ++k)
        d = fmax(d, fabs((double)a->rgb[k] - b->rgb[k]));
    const double peak = mm_peak(a);
    return peak > 0.0 ? d / peak : d;
}

/* The largest difference of the first n points' visibilities. */
static inline double mm_vis_diff(const mm_result *a, const mm_result *b, int n)
{
    double v = 0.0;
    for (int p = 0; p < n; ++p)
        v = fmax(v, fabs((double)a->vis[p] - b->vis[p]));
    return v;
}

/* A backend's setting for a relation and its bounds (measured, x 1.2):
 * precision, split horizons, bounces, key lights on. */
typedef struct mm_setting {
    hfs_precision precision;
    int split, bounces, keys;
    double bound_img, bound_vis;
} mm_setting;

/* The quality of setting st at subsample sub (the defaults otherwise). */
static inline hfs_quality mm_quality(int sub, const mm_setting *st)
{
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.subsample = sub;
    q.precision = st->precision;
    q.split = st->split;
    return q;
}

/* Prints one relation's differences and counts a failure (test_util.h)
 * where they pass the bounds. */
static inline void mm_report(const char *name, int sub, const mm_setting *st, const char *what,
                      double d_img, double d_vis)
{
    const char *prec = !strcmp(name, "cpu") ? "double"
                       : st->precision == HFS_PRECISION_FP32 ? "fp32" : "fp16";
    printf("%s subsample %d %s split %d, %d bounce(s)%s, %s: image %.3e of its maximum, "
           "points %.3e\n", name, sub, prec, st->split, st->bounces, st->keys ? "" : ", no keys",
           what, d_img, d_vis);
    if (d_img > st->bound_img || d_vis > st->bound_vis) {
        ++failures;
        fprintf(stderr, "FAIL: %s subsample %d %s split %d, %d bounce(s): %s moved the image by "
                "%.3e (bound %.1e) or the points by %.3e (bound %.1e)\n", name, sub, prec,
                st->split, st->bounces, what, d_img, st->bound_img, d_vis, st->bound_vis);
    }
}

/* One frame of r (field f's size, allocated here: hfs_image_free it); 0,
 * or -1 after a failed check (the error on stderr). */
static inline int mm_frame(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l,
                           const hfs_quality *q, hfs_image *img)
{
    hfs_error err = {""};
    if (hfs_image_alloc(img, f->width, f->height, &err) ||
        hfs_renderer_render(r, f, l, q, img, NULL, NULL, &err)) {
        fprintf(stderr, "frame: %s\n", err.msg);
        ++failures;
        return -1;
    }
    return 0;
}

/* img against the CPU reference's frame at quality q: the largest and the
 * mean difference over every value; 0, or -1 after a failed check. */
static inline int mm_against_cpu(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                                 const hfs_image *img, double *max, double *mean)
{
    hfs_renderer *c = NULL;
    hfs_error err = {""};
    const hfs_renderer_desc cd = {.backend = HFS_BACKEND_CPU};
    hfs_image ref = {0};
    if (hfs_renderer_create(&cd, &c, &err) || mm_frame(c, f, l, q, &ref)) {
        fprintf(stderr, "cpu: %s\n", err.msg);
        ++failures;
        hfs_renderer_destroy(c);
        hfs_image_free(&ref);
        return -1;
    }
    const size_t n = 3 * (size_t)f->width * (size_t)f->height;
    *max = *mean = 0.0;
    for (size_t k = 0; k < n; ++k) {
        const double e = fabs((double)img->rgb[k] - ref.rgb[k]);
        *max = fmax(*max, e);
        *mean += e / (double)n;
    }
    hfs_renderer_destroy(c);
    hfs_image_free(&ref);
    return 0;
}

/* A uniform sky of radiance 1 (the SH's constant term sqrt(4 pi)) into l,
 * and the truth backend's frame of field f under it at the default
 * quality into truth (allocated here: hfs_image_free it); 0, or -1 after
 * a failed check (test_wall_foot, test_far_heights). */
static inline int mm_uniform_sky_truth(const hfs_field *f, hfs_lighting *l, hfs_image *truth)
{
    hfs_lighting_defaults(l);
    l->has_env = 1;
    for (int c = 0; c < 3; ++c)
        l->env_sh[c][0] = 3.5449077018110318;
    hfs_renderer *t = NULL;
    hfs_error err = {""};
    const hfs_renderer_desc td = {.backend = HFS_BACKEND_TRUTH};
    hfs_quality q;
    hfs_quality_defaults(&q);
    int rc = hfs_renderer_create(&td, &t, &err) ||
             hfs_image_alloc(truth, f->width, f->height, &err) ||
             hfs_renderer_render(t, f, l, &q, truth, NULL, NULL, &err);
    hfs_renderer_destroy(t);
    if (rc) {
        fprintf(stderr, "truth: %s\n", err.msg);
        ++failures;
        return -1;
    }
    return 0;
}

/* One subsample's checks of field f under lighting l against its truth. */
typedef void (*mm_sub_fn)(hfs_renderer *r, const char *backend, int sub, const hfs_field *f,
                          const hfs_lighting *l, const hfs_image *truth);

/* Field f under a uniform sky (mm_uniform_sky_truth): fn at subsample sub
 * where it is 1, 2 or 4, else at 1 and 2 (the CPU's run). */
static inline void mm_sky_subsamples(hfs_renderer *r, const char *backend, int sub,
                                     const hfs_field *f, mm_sub_fn fn)
{
    hfs_lighting l;
    hfs_image truth = {0};
    if (!mm_uniform_sky_truth(f, &l, &truth)) {
        if (sub == 1 || sub == 2 || sub == 4) {
            fn(r, backend, sub, f, &l, &truth);
        } else {
            fn(r, backend, 1, f, &l, &truth);
            fn(r, backend, 2, f, &l, &truth);
        }
    }
    hfs_image_free(&truth);
}

/* A test program's main: `TEST cpu` runs run(cpu renderer, "cpu", 0),
 * `TEST gles SUBSAMPLE` run(gles renderer, "gles", SUBSAMPLE) (77 without
 * a context, gl_test.h); the exit status of the checks. */
static inline int mm_main(int argc, char **argv, const char *test,
                   void (*run)(hfs_renderer *r, const char *backend, int sub))
{
    int gles;
    hfs_renderer *r = gl_test_from_args(argc, argv, &gles);
    /* the subsample: argv[2], else 2 on GLES and the CPU's 0 (its default) */
    run(r, gles ? "gles" : "cpu", argc > 2 ? atoi(argv[2]) : (gles ? 2 : 0));
    hfs_renderer_destroy(r);
    char name[128];
    snprintf(name, sizeof name, "%s %s", test, gles ? "gles" : "cpu");
    return finish_checks(name);
}

#endif /* HFS_TEST_METAMORPHIC_H */
