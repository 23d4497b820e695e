/*
 * test_view_look.c — the 3-D view's background and haze (issue 41;
 * runtime/core/view_look.h, shaders_es/gles_view.frag.glsl):
 *
 *   scene   a flat 96 x 96 field striped in x (albedo 0.15 / 0.85, period
 *           8 texels) under a small synthetic environment map (a sky
 *           brighter towards the zenith and +x, a warm band at the
 *           horizon, darker ground, odd columns 0.3 brighter), seen in perspective from azimuth
 *           270 degrees, 25 degrees up, the eye near the near edge: an
 *           image row's central half lies at about one distance, farther
 *           up the image;
 *   haze    with haze 1 (optical depth across the diagonal) against haze
 *           0: no value is NaN or Inf (haze 50 neither); every background
 *           pixel (where a view with a colour background shows only the
 *           colour) is the same bit for bit; the terrain's contrast,
 *           (max - min) / (max + min) of its luminance over bands of 8
 *           rows, divided by the haze-free contrast of the same band,
 *           falls monotonically with distance, below 1 at the near band
 *           and at least 0.03 lower at the far one (measured 0.717 and
 *           0.650 on both backends);
 *   off     (cpu) haze 0 is the truth's ray-cast view of the same lit
 *           image with a camera that has no look, bit for bit, on the
 *           terrain;
 *   sky     the background is the map itself: read at a map pixel's centre
 *           (turned by env_rotate) the lookup gives that pixel; a
 *           background pixel equals
 *           hfs_env_map_bilinear in its ray's direction (cpu: within 1e-6
 *           relative; gles: the fp16 map and float atan/asin, bound below);
 *   twin    (gles) the GLES view, hazed, against the truth's ray-cast view
 *           of its own lit image with the same look: the C and GLSL haze
 *           agree away from the stripes' edges (bound below);
 *   studio, colour: the background's value where the view is open.
 *
 *   test_view_look cpu | gles   (gles: 77 without a context)
 */
#include "hfshade.h"
#include "check.h"
#include "gl_test.h"
#include "sh.h"
#include "truth_view.h"
#include "view_look.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define N 96
#define VW 96
#define VH 64
#define MW 64
#define MH 32
#define BAND 8
/* gles against the truth's view, measured on llvmpipe: 9.5e-4 of the
 * sky's max (the fp16 map, rounded to nearest here, then the fp16 target,
 * which GL lets round either way: 2^-11 + 2^-10 relative), bound 2e-3
 * (and the studio's and the colour's values, 9.4e-4 measured, the
 * target's one ulp, the same bound; cpu 1e-6); 3.7e-4 mean relative difference of the
 * hazed terrain away from the stripes' edges and the sky (fp16 target,
 * triangles vs bilinear patches), bound 2.7x.  The haze's z0 or L_in
 * wrong in one path moves the latter by more than 1e-2. */
#define SKY_BOUND_GLES 2e-3
#define TWIN_BOUND 1e-3

static float heights[N * N], albedo[N * N * 3], map[MW * MH * 3];

static void make_scene(hfs_field *f, hfs_lighting *l)
{
    for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i) {
            heights[j * N + i] = 0.0f;
            for (int c = 0; c < 3; ++c)
                albedo[3 * (j * N + i) + c] = (i / 4) % 2 ? 0.85f : 0.15f;
        }
    for (int r = 0; r < MH; ++r)
        for (int q = 0; q < MW; ++q) {
            const double el = PI / 2 - PI * (r + 0.5) / MH, phi = 2 * PI * (q + 0.5) / MW;
            const double up = el > 0.0 ? 1.0 + 2.0 * sin(el) + 0.5 * cos(phi) : 0.3;
            /* and a one-pixel stripe pattern, so a lookup half a pixel
             * off shows */
            const double band = exp(-el * el * 40.0) + 0.3 * (q % 2);
            map[3 * (r * MW + q) + 0] = (float)(0.6 * up + 1.5 * band);
            map[3 * (r * MW + q) + 1] = (float)(0.8 * up + 0.8 * band);
            map[3 * (r * MW + q) + 2] = (float)(1.2 * up + 0.3 * band);
        }
    *f = (hfs_field){N, N, heights, 1.0, 1.0};
    hfs_lighting_defaults(l);
    l->has_env = 1;
    hfs_sh_project_equirect(map, MW, MH, l->env_sh);
    l->env_map = map, l->env_map_width = MW, l->env_map_height = MH;
    l->env_rotate = 0.4;
    l->albedo_map = albedo;
    l->n_key = 1;
    l->key[0] = (hfs_key_light){.phi = 1.0, .elev = 0.9, .alpha = 0.03,
                                .radiance = {900.0f, 850.0f, 800.0f}};
}

static hfs_view make_view(const hfs_field *f, double haze)
{
    hfs_view v;
    hfs_view_defaults(&v, f);
    v.mode = HFS_VIEW_PERSPECTIVE;
    v.width = VW, v.height = VH;
    v.azimuth = 1.5 * PI, v.elevation = 35.0 * PI / 180.0, v.fov = 0.9;
    hfs_view_frame(&v, f);
    v.distance *= 0.6; /* the eye near the field's near edge: the field fills the rows */
    v.haze = haze;
    return v;
}

static double lum(const float *p)
{
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

static int render(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l,
                  const hfs_view *v, hfs_image *lit, hfs_image *out)
{
    hfs_quality q;
    hfs_quality_defaults(&q);
    hfs_error err = {""};
    const int rc = hfs_renderer_render_view(r, f, l, &q, v, lit, out, &err);
    CHECK(!rc, "render: %s", err.msg);
    return rc;
}

static int all_finite(const hfs_image *im)
{
    for (size_t i = 0; i < (size_t)im->width * im->height * 3; ++i)
        if (!isfinite(im->rgb[i]))
            return 0;
    return 1;
}

/* Contrast of the terrain in rows [y0, y0 + BAND), central columns. */
static double band_contrast(const hfs_image *im, int y0)
{
    double lo = INFINITY, hi = 0.0;
    for (int y = y0; y < y0 + BAND; ++y)
        for (int x = VW / 4; x < 3 * VW / 4; ++x) {
            const double v = lum(im->rgb + 3 * (y * VW + x));
            lo = fmin(lo, v), hi = fmax(hi, v);
        }
    return (hi - lo) / (hi + lo);
}

/* Rows whose central columns are all terrain (mask 0), first and last. */
static void terrain_rows(const unsigned char *mask, int *first, int *last)
{
    *first = VH, *last = -1;
    for (int y = 0; y < VH; ++y) {
        int all = 1;
        for (int x = VW / 4; x < 3 * VW / 4; ++x)
            all &= !mask[y * VW + x];
        if (all)
            *first = y < *first ? y : *first, *last = y;
    }
}

static void check_contrast(const hfs_image *clear, const hfs_image *hazy,
                           const unsigned char *mask, const char *be)
{
    int first, last;
    terrain_rows(mask, &first, &last);
    CHECK(last - first > 4 * BAND, "%s: only rows %d..%d show terrain", be, first, last);
    double prev = 2.0, near = 0.0, far = 0.0;
    int bands = 0, mono = 1;
    /* From the bottom (near) up (far); the band at the far edge left out. */
    for (int y0 = last + 1 - BAND; y0 >= first + BAND; y0 -= BAND, ++bands) {
        const double ratio = band_contrast(hazy, y0) / band_contrast(clear, y0);
        mono &= ratio <= prev + 1e-6;
        if (!bands)
            near = ratio;
        far = ratio, prev = ratio;
    }
    printf("%s: contrast with haze / without over %d bands: near %.3f, far %.3f\n", be, bands,
           near, far);
    CHECK(mono, "%s: the contrast ratio does not fall monotonically with distance", be);
    CHECK(bands >= 3 && near < 1.0 && far < near - 0.03, "%s: contrast ratio near %.3f (want "
          "< 1), far %.3f (want 0.03 below it) over %d bands", be, near, far, bands);
}

/* Background pixels: where a view with a colour background shows only it. */
static void background_mask(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l,
                            unsigned char *mask)
{
    hfs_view v = make_view(f, 0.0);
    v.background = HFS_BACKGROUND_COLOR;
    v.background_rgb[0] = 1000.0;
    hfs_image out = {0};
    hfs_error err = {""};
    hfs_image_alloc(&out, VW, VH, &err);
    render(r, f, l, &v, NULL, &out);
    int n = 0;
    for (int i = 0; i < VW * VH; ++i)
        n += mask[i] = out.rgb[3 * i] == 1000.0f && out.rgb[3 * i + 1] == 0.0f;
    CHECK(n > VW * 8 && n < VW * VH * 3 / 4, "background mask: %d pixels", n);
    hfs_image_free(&out);
}

/* The camera of view v (view_params.c's mapping) with v's look. */
static hfs_camera camera_of(const hfs_view *v, const hfs_field *f, const hfs_lighting *l)
{
    hfs_camera c = {.azimuth = v->azimuth, .elevation = v->elevation, .distance = v->distance,
                    .fov = v->fov, .target = {v->target[0], v->target[1], v->target[2]},
                    .exaggeration = v->exaggeration, .ortho = v->mode == HFS_VIEW_ORTHO};
    hfs_view_look_make(v, f, l, &c.look);
    return c;
}

/* The lookup itself, independently: a direction through a map pixel's
 * centre (turned by env_rotate) reads that pixel. */
static void check_map_lookup(const hfs_lighting *l)
{
    double worst = 0.0;
    for (int r = 0; r < MH; r += 3)
        for (int q = 0; q < MW; q += 5) {
            const double phi = 2 * PI * (q + 0.5) / MW + l->env_rotate;
            const double el = PI / 2 - PI * (r + 0.5) / MH;
            const double d[3] = {cos(el) * cos(phi), cos(el) * sin(phi), sin(el)};
            double got[3];
            hfs_env_map_bilinear(map, MW, MH, l->env_rotate, d, got);
            for (int c = 0; c < 3; ++c)
                worst = fmax(worst, fabs(got[c] - map[3 * (r * MW + q) + c]) /
                                        map[3 * (r * MW + q) + c]);
        }
    CHECK(worst <= 1e-9, "the map read at its pixels' centres is %.2e off", worst);
}

/* Background pixels hold the map in their ray's direction. */
static void check_sky(const hfs_image *im, const unsigned char *mask, const hfs_view *v,
                      const hfs_lighting *l, double bound, const char *be)
{
    hfs_camera_frame fr;
    const hfs_camera cam = {.azimuth = v->azimuth, .elevation = v->elevation,
                            .distance = v->distance, .fov = v->fov,
                            .target = {v->target[0], v->target[1], v->target[2]},
                            .exaggeration = 1.0, .ortho = 0};
    hfs_camera_frame_make(&cam, &fr);
    double worst = 0.0, top = 0.0;
    for (int y = 0; y < VH; ++y)
        for (int x = 0; x < VW; ++x) {
            if (!mask[y * VW + x])
                continue;
            double org[3], d[3], want[3];
            hfs_camera_ray_at(&fr, VW, VH, x, y, org, d);
            hfs_env_map_bilinear(l->env_map, MW, MH, l->env_rotate, d, want);
            for (int c = 0; c < 3; ++c) {
                worst = fmax(worst, fabs(im->rgb[3 * (y * VW + x) + c] - want[c]));
                top = fmax(top, fabs(want[c]));
            }
        }
    printf("%s: sky pixels against the map: max %.2e of its max (bound %.0e)\n", be,
           worst / top, bound);
    CHECK(worst <= bound * top, "%s: a sky pixel is %.2e off the map (bound %.0e of %.3g)", be,
          worst, bound, top);
}

/* The truth's ray-cast view of lit through cam (VW x VH RGB, the
 * caller's to free); NULL after a failed check. */
static float *truth_view_of(const hfs_field *f, const hfs_image *lit, const hfs_lighting *l,
                            const hfs_camera *cam)
{
    float *t = malloc(sizeof(float) * VW * VH * 3);
    hfs_error err = {""};
    if (!t || hfs_truth_view(f, lit->rgb, l, cam, NULL, VW, VH, t, 0, &err)) {
        CHECK(0, "truth view: %s", err.msg);
        free(t);
        return NULL;
    }
    return t;
}

/* gles: the hazed view against the truth's of its own lit image, the
 * same look, away from the stripes' edges and the background. */
static void check_twin(const hfs_image *view, const hfs_image *lit, const hfs_view *v,
                       const hfs_field *f, const hfs_lighting *l, const unsigned char *mask)
{
    const hfs_camera cam = camera_of(v, f, l);
    float *t = truth_view_of(f, lit, l, &cam);
    if (!t)
        return;
    double sum = 0.0;
    int n = 0;
    for (int y = 1; y < VH - 1; ++y)
        for (int x = 1; x < VW - 1; ++x) {
            int edge = 0; /* a stripe's edge or the background near: skip */
            const double here = lum(t + 3 * (y * VW + x));
            for (int k = -1; k <= 1; ++k)
                edge |= mask[(y + k) * VW + x] || mask[y * VW + x + k] ||
                        fabs(lum(t + 3 * (y * VW + x + k)) - here) > 0.05 * here;
            if (edge)
                continue;
            sum += fabs(lum(view->rgb + 3 * (y * VW + x)) - here) / here;
            ++n;
        }
    free(t);
    printf("gles: hazed view against the truth's: mean %.2e relative over %d pixels (bound "
           "%.0e)\n", sum / (n ? n : 1), n, TWIN_BOUND);
    CHECK(n > VW * VH / 10 && sum / n <= TWIN_BOUND, "gles: hazed view %.2e off the truth's "
          "(bound %.0e) over %d pixels", sum / (n ? n : 1), TWIN_BOUND, n);
}

/* cpu: haze 0 is the ray-cast view without any look, bit for bit. */
static void check_off(const hfs_image *view, const hfs_image *lit, const hfs_view *v,
                      const hfs_field *f, const hfs_lighting *l, const unsigned char *mask)
{
    hfs_camera cam = camera_of(v, f, l);
    cam.look = (hfs_view_look){.background = HFS_BACKGROUND_SKY};
    float *t = truth_view_of(f, lit, l, &cam);
    if (!t)
        return;
    int diff = 0;
    for (int i = 0; i < VW * VH; ++i)
        diff += !mask[i] && memcmp(t + 3 * i, view->rgb + 3 * i, 3 * sizeof *t) != 0;
    free(t);
    CHECK(diff == 0, "cpu: haze 0 differs from the view without a look at %d pixels", diff);
}

static void check_flat(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l,
                       hfs_background b, const unsigned char *mask, double bound,
                       const char *be)
{
    hfs_view v = make_view(f, 0.0);
    v.background = b;
    v.background_rgb[0] = 0.25, v.background_rgb[1] = 0.5, v.background_rgb[2] = 2.0;
    hfs_camera cam = camera_of(&v, f, l);
    hfs_image out = {0};
    hfs_error err = {""};
    hfs_image_alloc(&out, VW, VH, &err);
    render(r, f, l, &v, NULL, &out);
    hfs_camera_frame fr;
    hfs_camera_frame_make(&cam, &fr);
    double worst = 0.0;
    for (int i = 0; i < VW * VH; ++i) {
        double org[3], d[3], want[3];
        if (!mask[i])
            continue;
        hfs_camera_ray_at(&fr, VW, VH, i % VW, i / VW, org, d);
        hfs_view_background(&cam.look, l, NULL, d, want);
        for (int c = 0; c < 3; ++c)
            worst = fmax(worst, fabs(out.rgb[3 * i + c] - want[c]) / fmax(want[c], 1e-3));
    }
    printf("%s: %s background: max %.2e relative\n", be, b == HFS_BACKGROUND_STUDIO ?
           "studio" : "colour", worst);
    CHECK(worst <= bound, "%s: %s background %.2e off (bound %.0e)", be,
          b == HFS_BACKGROUND_STUDIO ? "studio" : "colour", worst, bound);
    hfs_image_free(&out);
}

static void run(hfs_renderer *r, const char *be, int gles)
{
    hfs_field f;
    hfs_lighting l;
    make_scene(&f, &l);
    unsigned char *mask = calloc(VW * VH, 1);
    hfs_image lit = {0}, clear = {0}, hazy = {0}, thick = {0};
    hfs_error err = {""};
    hfs_image_alloc(&lit, N, N, &err), hfs_image_alloc(&clear, VW, VH, &err);
    hfs_image_alloc(&hazy, VW, VH, &err), hfs_image_alloc(&thick, VW, VH, &err);
    check_map_lookup(&l);
    background_mask(r, &f, &l, mask);
    const hfs_view v0 = make_view(&f, 0.0), v3 = make_view(&f, 1.0), v50 = make_view(&f, 50.0);
    if (!render(r, &f, &l, &v0, &lit, &clear) && !render(r, &f, &l, &v3, NULL, &hazy) &&
        !render(r, &f, &l, &v50, NULL, &thick)) {
        CHECK(all_finite(&clear) && all_finite(&hazy) && all_finite(&thick),
              "%s: a view holds NaN or Inf", be);
        int moved = 0;
        for (int i = 0; i < VW * VH; ++i)
            moved += mask[i] && memcmp(clear.rgb + 3 * i, hazy.rgb + 3 * i, 3 * sizeof(float));
        CHECK(moved == 0, "%s: the haze changed %d background pixels", be, moved);
        check_contrast(&clear, &hazy, mask, be);
        check_sky(&clear, mask, &v0, &l, gles ? SKY_BOUND_GLES : 1e-6, be);
        if (gles)
            check_twin(&hazy, &lit, &v3, &f, &l, mask);
        else
            check_off(&clear, &lit, &v0, &f, &l, mask);
    }
    check_flat(r, &f, &l, HFS_BACKGROUND_STUDIO, mask, gles ? SKY_BOUND_GLES : 1e-6, be);
    check_flat(r, &f, &l, HFS_BACKGROUND_COLOR, mask, gles ? SKY_BOUND_GLES : 1e-6, be);
    hfs_image_free(&lit), hfs_image_free(&clear), hfs_image_free(&hazy), hfs_image_free(&thick);
    free(mask);
}

int main(int argc, char **argv)
{
    int gles;
    hfs_renderer *r = gl_test_from_args(argc, argv, &gles);
    run(r, gles ? "gles" : "cpu", gles);
    hfs_renderer_destroy(r);
    if (failures) {
        fprintf(stderr, "test_view_look %s: %d of %ld checks failed\n", argv[argc > 1],
                failures, checks);
        return 1;
    }
    printf("test_view_look %s: all %ld checks passed\n", gles ? "gles" : "cpu", checks);
    return 0;
}
