/*
 * test_gles_view.c — the GLES 3-D view (runtime/gles/pass_view.c) against
 * the truth's ray-cast view (runtime/truth/truth_view.c) of the SAME lit image
 * (the GLES frame's own), so that only the view differs:
 *
 *   compare fp16|fp32  a 33 x 33 field (an off-centre hill on a slope, a
 *                      sky with a tilt and a key light: nothing symmetric,
 *                      so a mirrored basis, a flipped image, a wrong
 *                      exaggeration or a shifted radiance lookup all show),
 *                      a 96 x 64 perspective view and a straight-down
 *                      ortho view:
 *                        - ortho, pixel centres on known grid points: the
 *                          view equals the lit image resampled bilinearly
 *                          (fp16 target: 2e-3 of the max);
 *                        - perspective vs the truth: the fraction of
 *                          pixels over 5% of the max, and the mean
 *                          difference away from silhouettes (bounds below);
 *   plan               a camera move reruns the view alone (frame report),
 *                      and equals a fresh renderer's frame bit for bit;
 *                      a light change reruns the shading, read-back, view.
 * Skipped (77) without a GL context.
 */
#include "hfshade.h"
#include "check.h"
#include "truth_view.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define N 33
#define VW 96
#define VH 64

/* Perspective vs truth bounds.  Measured on Mesa llvmpipe, fp16, fp32 and
 * an ES 3.0 context alike: 1.79% of the pixels over 5% of the max, all on
 * silhouettes (the field's outline against the sky, a one-pixel band: a
 * triangle edge vs the bilinear patch's curve moves an outline by a
 * fraction of a pixel, and multisampling blends the two sides), mean
 * 4.2e-4 of the max away from the sky's outline (the fp16 target's
 * rounding, 2^-11 relative, and triangles vs bilinear patches inside
 * cells: the hit moves by up to a quarter of a cell's twist, the radiance
 * read there with it).  Bounds 1.5x (fraction) and 2.4x (mean) that, below
 * what each broken piece measured on purpose: right vector negated 21% /
 * 3.5e-2, rows not flipped 74% / 0.17, exaggeration ignored 7.1% /
 * 1.2e-2, radiance read one texel off in x 1.8% / 2.5e-3 (the ortho check
 * catches it too: 3.0e-2), i and j swapped 7.3% / 1.4e-2.  Ortho straight
 * down: 5.3e-4 measured (fp16's half ulp at the top of the range), bound
 * 2e-3; broken as above 3e-2 .. 7.7e-2. */
#define FRAC_THRESHOLD 0.05
#define FRAC_BOUND 0.027
#define MEAN_BOUND 1e-3
#define ORTHO_BOUND 2e-3

static float heights[N * N];

static void make_field(hfs_field *f)
{
    for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i) {
            const double dx = i - 20.0, dy = j - 12.0;
            heights[j * N + i] = (float)(6.0 * exp(-(dx * dx + 0.5 * dy * dy) / 40.0) + 0.08 * i +
                                         0.5 * sin(0.4 * j));
        }
    *f = (hfs_field){N, N, heights, 1.0, 1.0};
}

static hfs_lighting lighting(void)
{
    hfs_lighting l;
    hfs_lighting_defaults(&l);
    l.has_env = 1;
    for (int c = 0; c < 3; ++c) {
        l.env_sh[c][0] = sqrt(4.0 * PI) * (0.5 + 0.1 * c);
        l.env_sh[c][2] = 0.6;       /* brighter up */
        l.env_sh[c][3] = 0.3 - 0.1 * c; /* and toward +x */
    }
    l.n_key = 1;
    l.key[0] = (hfs_key_light){.phi = 2.3, .elev = 0.35, .alpha = 0.05,
                               .radiance = {40.0f, 36.0f, 30.0f}};
    return l;
}

static hfs_renderer *gles(void)
{
    hfs_renderer_desc d = {.backend = HFS_BACKEND_GLES};
    hfs_renderer *r = NULL;
    hfs_error err;
    if (hfs_renderer_create(&d, &r, &err)) {
        printf("test_gles_view: skipped: %s\n", err.msg);
        exit(77);
    }
    return r;
}

static double image_max(const float *p, size_t n)
{
    double m = 0.0;
    for (size_t i = 0; i < n; ++i)
        m = fmax(m, p[i]);
    return m;
}

/* Straight down, ortho, pixel (px, py) centred on grid point
 * ((px + 0.5) / 2, (py + 0.5) / 2) of a 64 x 64 view. */
static void check_ortho(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l,
                        const hfs_quality *q)
{
    hfs_view v;
    hfs_view_defaults(&v, f);
    v.width = v.height = 64;
    v.target[0] = v.target[1] = 16.0;
    v.fov = 0.5;
    v.distance = 16.0 / tan(0.25);
    hfs_image lit, view;
    hfs_error err = {""};
    hfs_image_alloc(&lit, N, N, &err), hfs_image_alloc(&view, 64, 64, &err);
    int rc = hfs_renderer_render_view(r, f, l, q, &v, &lit, &view, &err);
    CHECK(!rc, "ortho view: %s", err.msg);
    const double m = image_max(lit.rgb, (size_t)N * N * 3);
    double worst = 0.0;
    for (int py = 0; py < 64; ++py)
        for (int px = 0; px < 64; ++px) {
            const double gx = (px + 0.5) / 2.0, gy = (py + 0.5) / 2.0;
            const int i = (int)gx, j = (int)gy;
            const double fx = gx - i, fy = gy - j;
            for (int c = 0; c < 3; ++c) {
                const float *p = lit.rgb + 3 * (j * N + i) + c;
                const double want = (p[0] * (1 - fx) + p[3] * fx) * (1 - fy) +
                                    (p[3 * N] * (1 - fx) + p[3 * N + 3] * fx) * fy;
                worst = fmax(worst, fabs(view.rgb[3 * (py * 64 + px) + c] - want) / m);
            }
        }
    CHECK(!rc && worst <= ORTHO_BOUND, "ortho straight down: max %.2e of the max from the lit "
          "image resampled (bound %.0e)", worst, ORTHO_BOUND);
    printf("ortho straight down vs the lit image resampled: max %.2e of the max (bound %.0e)\n",
           worst, ORTHO_BOUND);
    hfs_image_free(&lit), hfs_image_free(&view);
}

/* A pixel next to (3 x 3) both a sky pixel and a terrain pixel of the
 * truth (hit: a non-zero value without the sky). */
static int near_sky_edge(const float *nosky, int px, int py)
{
    int sky = 0, hit = 0;
    for (int y = py - 1; y <= py + 1; ++y)
        for (int x = px - 1; x <= px + 1; ++x) {
            if (x < 0 || y < 0 || x >= VW || y >= VH)
                continue;
            const float *p = nosky + 3 * (y * VW + x);
            if (p[0] == 0.0f && p[1] == 0.0f && p[2] == 0.0f)
                sky = 1;
            else
                hit = 1;
        }
    return sky && hit;
}

static void check_perspective(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l,
                              const hfs_quality *q, const char *what)
{
    hfs_view v;
    hfs_view_defaults(&v, f);
    v.mode = HFS_VIEW_PERSPECTIVE;
    v.width = VW, v.height = VH;
    v.azimuth = 3.9, v.elevation = 0.45, v.fov = 0.75, v.exaggeration = 1.7;
    v.target[2] = 3.0;
    v.distance = 44.0;
    hfs_image lit, view;
    hfs_error err = {""};
    hfs_image_alloc(&lit, N, N, &err), hfs_image_alloc(&view, VW, VH, &err);
    int rc = hfs_renderer_render_view(r, f, l, q, &v, &lit, &view, &err);
    CHECK(!rc, "%s: %s", what, err.msg);
    const hfs_camera cam = {v.azimuth, v.elevation, v.distance, v.fov,
                            {v.target[0], v.target[1], v.target[2]}, v.exaggeration, 0,
                            {.background = HFS_BACKGROUND_SKY}};
    float *truth = malloc(sizeof(float) * VW * VH * 3), *nosky = malloc(sizeof(float) * VW * VH * 3);
    hfs_lighting dark = *l;
    dark.has_env = 0;
    rc |= hfs_truth_view(f, lit.rgb, l, &cam, NULL, VW, VH, truth, 0, &err);
    rc |= hfs_truth_view(f, lit.rgb, &dark, &cam, NULL, VW, VH, nosky, 0, &err);
    const double m = image_max(truth, (size_t)VW * VH * 3);
    int over = 0, n_in = 0, n_hit = 0;
    double sum = 0.0;
    for (int py = 0; py < VH; ++py)
        for (int px = 0; px < VW; ++px) {
            double d = 0.0;
            for (int c = 0; c < 3; ++c)
                d = fmax(d, fabs(view.rgb[3 * (py * VW + px) + c] - truth[3 * (py * VW + px) + c]));
            d /= m;
            over += d > FRAC_THRESHOLD;
            n_hit += nosky[3 * (py * VW + px)] != 0.0f;
            if (!near_sky_edge(nosky, px, py))
                sum += d, ++n_in;
        }
    const double frac = (double)over / (VW * VH), mean = sum / (n_in ? n_in : 1);
    CHECK(!rc && frac <= FRAC_BOUND && mean <= MEAN_BOUND,
          "%s: %.2f%% of the pixels over %.0f%% of the max (bound %.1f%%), mean %.2e off the "
          "sky's silhouette (bound %.0e)", what, 100 * frac, 100 * FRAC_THRESHOLD,
          100 * FRAC_BOUND, mean, MEAN_BOUND);
    CHECK(n_hit > VW * VH / 3 && n_hit < VW * VH - 100, "%s: the view shows %d terrain pixels "
          "(want terrain and sky)", what, n_hit);
    printf("%s vs the truth's view: %.2f%% of the pixels over %.0f%% of the max (bound %.1f%%), "
           "mean %.2e off the sky's silhouette over %d pixels (bound %.0e); %d terrain pixels\n",
           what, 100 * frac, 100 * FRAC_THRESHOLD, 100 * FRAC_BOUND, mean, n_in, MEAN_BOUND,
           n_hit);
    free(truth), free(nosky);
    hfs_image_free(&lit), hfs_image_free(&view);
}

/* The passes the last frame ran, space-separated. */
static void ran(hfs_renderer *r, char *out, size_t n)
{
    hfs_frame_report rep;
    hfs_renderer_frame_report(r, &rep);
    out[0] = '\0';
    for (int i = 0; i < rep.n_steps; ++i)
        if (rep.step[i].ran && strlen(out) + strlen(rep.step[i].pass) + 2 < n)
            strcat(strcat(out, rep.step[i].pass), " ");
}

static void check_plan(const hfs_field *f, hfs_lighting l, const hfs_quality *q)
{
    hfs_renderer *r = gles(), *fresh = gles();
    hfs_view v;
    hfs_view_defaults(&v, f);
    v.mode = HFS_VIEW_PERSPECTIVE, v.width = VW, v.height = VH, v.elevation = 0.6;
    hfs_view_frame(&v, f);
    hfs_image lit, a, b;
    hfs_error err = {""};
    hfs_image_alloc(&lit, N, N, &err), hfs_image_alloc(&a, VW, VH, &err);
    hfs_image_alloc(&b, VW, VH, &err);
    char steps[256];
    int rc = hfs_renderer_render_view(r, f, &l, q, &v, &lit, &a, &err);
    v.azimuth += 0.4, v.distance *= 0.8; /* a camera move */
    rc |= hfs_renderer_render_view(r, f, &l, q, &v, &lit, &a, &err);
    ran(r, steps, sizeof steps);
    CHECK(!rc && !strcmp(steps, "view "), "camera moved: ran '%s', want the view alone", steps);
    printf("camera moved: ran '%s'\n", steps);
    rc |= hfs_renderer_render_view(fresh, f, &l, q, &v, NULL, &b, &err);
    CHECK(!rc && !memcmp(a.rgb, b.rgb, sizeof(float) * VW * VH * 3),
          "camera moved: the view differs from a fresh renderer's");
    rc |= hfs_renderer_render_view(r, f, &l, q, &v, &lit, &a, &err);
    ran(r, steps, sizeof steps);
    CHECK(!rc && !strcmp(steps, ""), "nothing changed: ran '%s', want nothing", steps);
    CHECK(!memcmp(a.rgb, b.rgb, sizeof(float) * VW * VH * 3), "nothing changed: another view");
    l.key[0].radiance[0] *= 0.5f; /* a light's radiance: shading, read-back, view */
    rc |= hfs_renderer_render_view(r, f, &l, q, &v, &lit, &a, &err);
    ran(r, steps, sizeof steps);
    CHECK(!rc && !strcmp(steps, "shade readback view "), "light dimmed: ran '%s'", steps);
    printf("light dimmed: ran '%s'\n", steps);
    rc |= hfs_renderer_render(r, f, &l, q, &lit, NULL, NULL, &err); /* no view: none drawn */
    ran(r, steps, sizeof steps);
    CHECK(!rc && !strcmp(steps, ""), "the same frame without a view: ran '%s'", steps);
    CHECK(!rc, "plan: %s", err.msg);
    hfs_image_free(&lit), hfs_image_free(&a), hfs_image_free(&b);
    hfs_renderer_destroy(r), hfs_renderer_destroy(fresh);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: test_gles_view compare fp16|fp32 | plan\n");
        return 2;
    }
    hfs_field f;
    make_field(&f);
    const hfs_lighting l = lighting();
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.subsample = 1;
    if (!strcmp(argv[1], "plan")) {
        check_plan(&f, l, &q);
    } else {
        q.precision = argc > 2 && !strcmp(argv[2], "fp32") ? HFS_PRECISION_FP32 : HFS_PRECISION_FP16;
        hfs_renderer *r = gles();
        check_ortho(r, &f, &l, &q);
        check_perspective(r, &f, &l, &q, "perspective");
        hfs_renderer_destroy(r);
    }
    printf("test_gles_view %s: %s (%ld checks)\n", argv[1], failures ? "FAILED" : "ok", checks);
    return failures ? 1 : 0;
}
