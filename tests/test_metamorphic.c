/*
 * test_metamorphic.c — relations every backend must keep without an oracle
 * (issue 35, deliverable 1; first part): scaling the world leaves the
 * picture unchanged.  Multiplying dx, zscale (so every height), every local
 * light's position and radius, and every queried point by the same s > 0
 * (GLES also with one bounce of indirect light)
 * changes no angle and no solid angle: the image and the key-light
 * visibility of the points must not move.  Key lights and the sky are
 * directions, untouched.  Bugs that read a world position as a grid
 * position (or the reverse) break it, and dx = 1 hides them.
 *
 * The field is non-square (40 x 28), the scales are s = 2.5 and 0.125 from
 * dx = 0.7, so neither side is 1.  Bounds are per backend, relative to the
 * frame's maximum: measured 0 (the product keeps this exactly), bound 1e-6.
 *
 *   test_metamorphic cpu | gles SUBSAMPLE   (gles: 77 without a context)
 */
#include "gl_test.h"
#include "terrain_gen.h"
#include "test_util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 40
#define H 28
#define NPTS 24

typedef struct scene {
    float z[W * H];
    hfs_field f;
    hfs_lighting l;
    double xyz[3 * NPTS];
} scene;

/* The base scene at world scale s (dx 0.7 s, zscale 0.9 s), with
 * `bounces` bounces of indirect light. */
static void make_scene(scene *sc, double s, int bounces)
{
    hfs_terrain_fractal(sc->z, W, H, 7u, 0.5);
    for (int i = 0; i < W * H; ++i)
        sc->z[i] *= 6.0f;
    sc->f = (hfs_field){.width = W, .height = H, .z = sc->z, .dx = 0.7 * s, .zscale = 0.9 * s};
    hfs_lighting_defaults(&sc->l);
    sc->l.has_env = 1;
    const double sky[HFS_SH_COEFFS] = {3.5449077, 0.3, 0.8, -0.2, 0, 0.1};
    for (int c = 0; c < 3; ++c)
        memcpy(sc->l.env_sh[c], sky, sizeof sky);
    sc->l.n_key = 1;
    sc->l.key[0] = (hfs_key_light){.phi = 0.7, .elev = 0.35, .alpha = 0.03,
                                   .radiance = {40, 38, 35}};
    sc->l.bounces = bounces; /* the bounce walk steps in world units too */
    sc->l.albedo = 0.6;
    sc->l.n_local = 1;
    sc->l.local[0] = (hfs_local_light){.pos = {11.0 * s, 9.0 * s, 7.0 * s}, .radius = 0.8 * s,
                                       .radiance = {200, 180, 160}};
    /* Points over the footprint, some above the surface and some near it. */
    for (int p = 0; p < NPTS; ++p) {
        const int i = 1 + (p * 7) % (W - 2), j = 1 + (p * 5) % (H - 2);
        sc->xyz[3 * p] = i * 0.7 * s;
        sc->xyz[3 * p + 1] = j * 0.7 * s;
        sc->xyz[3 * p + 2] = (sc->z[j * W + i] + 0.3 + 0.2 * (p % 4)) * 0.9 * s;
    }
}

typedef struct result {
    hfs_image img;
    float vis[NPTS];
} result;

static int render(hfs_renderer *r, const scene *sc, const hfs_quality *q, result *out)
{
    hfs_error err = {""};
    if (hfs_image_alloc(&out->img, W, H, &err) ||
        hfs_renderer_render(r, &sc->f, &sc->l, q, &out->img, NULL, NULL, &err) ||
        hfs_renderer_query_points(r, &sc->f, &sc->l, q, sc->xyz, NPTS, out->vis, &err)) {
        fprintf(stderr, "render: %s\n", err.msg);
        return -1;
    }
    return 0;
}

/* The largest difference of two frames over the first one's maximum, and
 * of the points' visibilities. */
static void compare(const result *a, const result *b, double *d_img, double *d_vis)
{
    double peak = 0.0, d = 0.0, v = 0.0;
    for (int k = 0; k < W * H * 3; ++k) {
        peak = fmax(peak, fabs(a->img.rgb[k]));
        d = fmax(d, fabs((double)a->img.rgb[k] - b->img.rgb[k]));
    }
    for (int p = 0; p < NPTS; ++p)
        v = fmax(v, fabs((double)a->vis[p] - b->vis[p]));
    *d_img = peak > 0.0 ? d / peak : d;
    *d_vis = v;
}

static void scale_invariance(hfs_renderer *r, const char *name, int subsample, int bounces,
                             double bound_img, double bound_vis)
{
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.subsample = subsample;
    static scene base, scaled;
    result rb, rs;
    memset(&rb, 0, sizeof rb), memset(&rs, 0, sizeof rs);
    make_scene(&base, 1.0, bounces);
    REQUIRE(render(r, &base, &q, &rb) == 0, "%s: the base scene", name);
    const double scales[] = {2.5, 0.125};
    for (int i = 0; i < 2; ++i) {
        make_scene(&scaled, scales[i], bounces);
        REQUIRE(render(r, &scaled, &q, &rs) == 0, "%s: the scene at scale %g", name, scales[i]);
        double d_img, d_vis;
        compare(&rb, &rs, &d_img, &d_vis);
        printf("%s subsample %d, %d bounce(s), world x %g: image %.3e of its maximum, "
               "points %.3e\n", name, subsample, bounces, scales[i], d_img, d_vis);
        REQUIRE(d_img <= bound_img && d_vis <= bound_vis,
                "%s: scaling the world by %g moved the image by %.3e (bound %.1e) or the "
                "points by %.3e (bound %.1e)", name, scales[i], d_img, bound_img, d_vis,
                bound_vis);
        hfs_image_free(&rs.img);
    }
    hfs_image_free(&rb.img);
}

int main(int argc, char **argv)
{
    if (argc > 1 && !strcmp(argv[1], "gles")) {
        const int sub = argc > 2 ? atoi(argv[2]) : 2;
        hfs_renderer *g = gl_test_gles();
        for (int bounces = 0; bounces < 2; ++bounces)
            scale_invariance(g, "gles", sub, bounces, 1e-6, 1e-6);
        hfs_renderer_destroy(g);
        return finish_checks("test_metamorphic gles");
    }
    hfs_renderer *c = NULL;
    hfs_error err = {""};
    const hfs_renderer_desc d = {.backend = HFS_BACKEND_CPU};
    if (hfs_renderer_create(&d, &c, &err)) {
        fprintf(stderr, "cpu: %s\n", err.msg);
        return 1;
    }
    /* With a bounce too: the walk once lit a band at a sample that rose
     * above the top by a rounding error only, which a scaled world rounds
     * the other way (1.0e-2 of the maximum at x 2.5). */
    for (int bounces = 0; bounces < 2; ++bounces)
        scale_invariance(c, "cpu", 1, bounces, 1e-6, 1e-6);
    hfs_renderer_destroy(c);
    return finish_checks("test_metamorphic cpu");
}
