/*
 * test_truth_view.c — the 3-D view's camera (view_camera.h) and the truth's
 * ray-cast view (truth_view.h) against answers computed here:
 *   frame        orthonormal, right x up = forward; the default camera
 *                (azimuth 90, elevation 90) has +x right and -y (row 0) up;
 *                an oblique one keeps row 0 toward the top
 *   nadir        a flat field seen straight down: every pixel is the lit
 *                image's bilinear value where its ray meets z = 0
 *   background   rays that miss show the sky: radiance 1 under a uniform sky
 *   sky rotation the sky turned by env-rotate: the SH at each ray turned
 *                back, and the view of the coefficients rotated beforehand
 *   exaggeration a ramp with exaggeration 2 is the ramp at zscale 2,
 *                bit for bit
 */
#include "field_geom.h"
#include "sh.h"
#include "test_util.h"
#include "truth_view.h"

#include <math.h>

#define PI 3.14159265358979323846

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void test_frame(void)
{
    hfs_camera c = {PI / 2, PI / 2, 10.0, 0.8, {5, 5, 0}, 1.0, 0,
                    {.background = HFS_BACKGROUND_SKY}};
    hfs_camera_frame fr;
    hfs_camera_frame_make(&c, &fr);
    REQUIRE(fabs(fr.right[0] - 1.0) < 1e-12 && fabs(fr.up[1] + 1.0) < 1e-12 &&
                fabs(fr.forward[2] + 1.0) < 1e-12,
            "nadir: right %g %g %g up %g %g %g", fr.right[0], fr.right[1], fr.right[2], fr.up[0],
            fr.up[1], fr.up[2]);
    const double az[3] = {0.3, PI / 2, 4.0}, el[3] = {0.2, PI / 4, 1.2};
    for (int k = 0; k < 3; ++k) {
        c.azimuth = az[k], c.elevation = el[k];
        hfs_camera_frame_make(&c, &fr);
        const double x[3] = {fr.right[1] * fr.up[2] - fr.right[2] * fr.up[1],
                             fr.right[2] * fr.up[0] - fr.right[0] * fr.up[2],
                             fr.right[0] * fr.up[1] - fr.right[1] * fr.up[0]};
        CHECK(fabs(dot3(fr.right, fr.up)) < 1e-12 && fabs(dot3(fr.right, fr.forward)) < 1e-12 &&
              fabs(dot3(fr.right, fr.right) - 1.0) < 1e-12 &&
              fabs(dot3(fr.up, fr.up) - 1.0) < 1e-12 && fabs(dot3(x, fr.forward) - 1.0) < 1e-12);
        CHECK(fr.up[2] > 0.0); /* +z leans up on the image */
    }
    printf("frame: orthonormal, right x up = forward; nadir shows +x right, row 0 up\n");
}

static float *lit_pattern(int w, int h)
{
    float *lit = malloc(sizeof(float) * w * h * 3);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            for (int c = 0; c < 3; ++c)
                lit[3 * (j * w + i) + c] = (float)(0.1 * i + 0.37 * j + c + 0.01 * ((i * j) % 7));
    return lit;
}

static void test_nadir(void)
{
    const int w = 40, h = 30, vw = 64, vh = 48;
    float *z = calloc((size_t)w * h, sizeof *z), *lit = lit_pattern(w, h);
    float *view = malloc(sizeof(float) * vw * vh * 3);
    const hfs_field f = {w, h, z, 0.5, 1.0};
    hfs_lighting l;
    hfs_lighting_defaults(&l);
    const hfs_camera c = {PI / 2, PI / 2, 30.0, 0.6, {9.75, 7.25, 0.0}, 1.0, 0,
                    {.background = HFS_BACKGROUND_SKY}};
    hfs_error err = {""};
    REQUIRE(hfs_truth_view(&f, lit, &l, &c, NULL, vw, vh, view, 1, &err) == HFS_OK, "%s", err.msg);
    hfs_camera_frame fr;
    hfs_camera_frame_make(&c, &fr);
    double worst = 0.0;
    int inside = 0;
    for (int py = 0; py < vh; ++py)
        for (int px = 0; px < vw; ++px) {
            double d[3], want[3];
            hfs_camera_ray(&fr, vw, vh, px, py, d);
            const double t = -fr.eye[2] / d[2];
            const double gx = (fr.eye[0] + t * d[0]) / f.dx, gy = (fr.eye[1] + t * d[1]) / f.dx;
            const int on = gx >= 0.0 && gy >= 0.0 && gx <= w - 1.0 && gy <= h - 1.0;
            hfs_rgb_bilinear(lit, w, h, gx, gy, want);
            for (int ch = 0; ch < 3 && !on; ++ch)
                want[ch] = 0.0; /* off the field: the (absent) sky */
            inside += on;
            for (int ch = 0; ch < 3; ++ch)
                worst = fmax(worst, fabs(view[3 * (py * vw + px) + ch] - want[ch]));
        }
    CHECK(worst < 1e-5 && inside > vw * vh / 2);
    printf("nadir: %dx%d view of a flat field = the lit image where the rays land (%d on the "
           "field, %.1e)\n", vw, vh, inside, worst);
    free(z), free(lit), free(view);
}

static void test_background(void)
{
    const int w = 8, h = 8, vw = 16, vh = 8;
    float *z = calloc((size_t)w * h, sizeof *z), *lit = lit_pattern(w, h);
    float *view = malloc(sizeof(float) * vw * vh * 3);
    const hfs_field f = {w, h, z, 1.0, 1.0};
    hfs_lighting l;
    hfs_lighting_defaults(&l);
    l.has_env = 1;
    for (int c = 0; c < 3; ++c)
        l.env_sh[c][0] = sqrt(4.0 * PI);
    /* Off the field, above it, looking up and away (the lowest ray rises
     * 0.05 rad): only sky. */
    const hfs_camera c = {0.0, -0.3, 100.0, 0.5, {3.5, 3.5, 50.0}, 1.0, 0,
                    {.background = HFS_BACKGROUND_SKY}};
    hfs_error err = {""};
    REQUIRE(hfs_truth_view(&f, lit, &l, &c, NULL, vw, vh, view, 1, &err) == HFS_OK, "%s", err.msg);
    double worst = 0.0;
    for (int i = 0; i < vw * vh * 3; ++i)
        worst = fmax(worst, fabs(view[i] - 1.0));
    CHECK(worst < 1e-6);
    printf("background: the uniform sky, %.1e from 1\n", worst);
    free(z), free(lit), free(view);
}

/* The sky turned by env-rotate (a feature at azimuth phi seen at phi +
 * angle, sh.h hfs_sh_rotate_z): every pixel of an all-sky view is the
 * unrotated SH evaluated at its ray turned back, R_z(-angle) d, and the
 * same view as with the coefficients rotated beforehand; a sky with a
 * sideways gradient, so that the turn shows. */
static void test_sky_rotation(void)
{
    const int w = 8, h = 8, vw = 16, vh = 8;
    float *z = calloc((size_t)w * h, sizeof *z), *lit = lit_pattern(w, h);
    float *a = malloc(sizeof(float) * vw * vh * 3), *b = malloc(sizeof(float) * vw * vh * 3);
    const hfs_field f = {w, h, z, 1.0, 1.0};
    hfs_lighting l, pre;
    hfs_lighting_defaults(&l);
    l.has_env = 1;
    for (int c = 0; c < 3; ++c) /* constant, +z, +x and +y gradients, a little m = 2 */
        l.env_sh[c][0] = 3.0, l.env_sh[c][2] = 0.5, l.env_sh[c][3] = 1.0 + 0.2 * c,
        l.env_sh[c][1] = 0.4, l.env_sh[c][8] = 0.3;
    pre = l;
    const double angle = 1.1;
    l.env_rotate = angle;
    for (int c = 0; c < 3; ++c)
        hfs_sh_rotate_z(l.env_sh[c], angle, pre.env_sh[c]);
    const hfs_camera cam = {0.0, -0.3, 100.0, 0.5, {3.5, 3.5, 50.0}, 1.0, 0,
                    {.background = HFS_BACKGROUND_SKY}};
    hfs_error err = {""};
    REQUIRE(hfs_truth_view(&f, lit, &l, &cam, NULL, vw, vh, a, 1, &err) == HFS_OK, "%s", err.msg);
    REQUIRE(hfs_truth_view(&f, lit, &pre, &cam, NULL, vw, vh, b, 1, &err) == HFS_OK, "%s",
            err.msg);
    hfs_camera_frame fr;
    hfs_camera_frame_make(&cam, &fr);
    double worst = 0.0, worst_pre = 0.0, turned = 0.0;
    for (int p = 0; p < vw * vh; ++p) {
        double d[3], y[HFS_SH_N], y0[HFS_SH_N];
        hfs_camera_ray(&fr, vw, vh, p % vw, p / vw, d);
        const double cs = cos(angle), sn = sin(angle);
        hfs_sh_eval(cs * d[0] + sn * d[1], -sn * d[0] + cs * d[1], d[2], y);
        hfs_sh_eval(d[0], d[1], d[2], y0);
        for (int c = 0; c < 3; ++c) {
            const double want = hfs_sh_dot(y, l.env_sh[c]);
            worst = fmax(worst, fabs(a[3 * p + c] - want) / fabs(want));
            worst_pre = fmax(worst_pre, fabs(a[3 * p + c] - b[3 * p + c]) / fabs(want));
            turned = fmax(turned, fabs(a[3 * p + c] - hfs_sh_dot(y0, l.env_sh[c])));
        }
    }
    CHECK(worst < 1e-6);
    CHECK(worst_pre < 1e-6);
    CHECK(turned > 0.1);
    printf("sky rotation: the turned sky within %.1e of the SH at the turned-back rays, %.1e of "
           "the rotated coefficients (the turn moves it by %.2f)\n", worst, worst_pre, turned);
    free(z), free(lit), free(a), free(b);
}

static void test_exaggeration(void)
{
    const int w = 24, h = 20, vw = 40, vh = 30;
    float *z = malloc(sizeof(float) * w * h), *lit = lit_pattern(w, h);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            z[j * w + i] = (float)(0.3 * i + 0.1 * (j % 5));
    float *a = malloc(sizeof(float) * vw * vh * 3), *b = malloc(sizeof(float) * vw * vh * 3);
    hfs_lighting l;
    hfs_lighting_defaults(&l);
    hfs_camera c = {0.7, 0.5, 40.0, 0.7, {12, 10, 3}, 2.0, 0,
                    {.background = HFS_BACKGROUND_SKY}};
    const hfs_field f1 = {w, h, z, 1.0, 1.0}, f2 = {w, h, z, 1.0, 2.0};
    hfs_error err = {""};
    REQUIRE(hfs_truth_view(&f1, lit, &l, &c, NULL, vw, vh, a, 1, &err) == HFS_OK, "%s", err.msg);
    c.exaggeration = 1.0;
    REQUIRE(hfs_truth_view(&f2, lit, &l, &c, NULL, vw, vh, b, 2, &err) == HFS_OK, "%s", err.msg);
    CHECK(!memcmp(a, b, sizeof(float) * vw * vh * 3));
    long hits = 0;
    for (int i = 0; i < vw * vh; ++i)
        hits += a[3 * i + 1] != 0.0f;
    CHECK(hits > vw * vh / 4); /* the ramp fills much of the view */
    /* Against a dense march of each ray over the exaggerated ramp (0.005
     * world steps): the colour where it first enters the solid block under
     * the surface (down to the lowest height, 0 here), black where it
     * never does; a few pixels may differ at silhouettes, where the march
     * steps past a grazing hit. */
    hfs_camera_frame fr;
    c.exaggeration = 2.0;
    hfs_camera_frame_make(&c, &fr);
    int differ = 0;
    for (int p = 0; p < vw * vh; ++p) {
        double d[3], want[3] = {0, 0, 0}, zs;
        hfs_camera_ray(&fr, vw, vh, p % vw, p / vw, d);
        for (double t = 0.0; t < 200.0; t += 0.005) {
            const double x = fr.eye[0] + t * d[0], y = fr.eye[1] + t * d[1];
            const double zr = fr.eye[2] + t * d[2];
            if (hfs_field_bilinear(&f2, x, y, &zs) && zr <= zs && zr >= 0.0) {
                hfs_rgb_bilinear(lit, w, h, x, y, want);
                break;
            }
        }
        differ += fabs(a[3 * p] - want[0]) > 0.01;
    }
    CHECK(differ <= vw * vh / 100);
    printf("exaggeration: against a dense march, %d of %d pixels differ (silhouettes)\n", differ,
           vw * vh);
    printf("exaggeration: 2x the heights = zscale 2, bit for bit (%ld of %d pixels on the field)\n",
           hits, vw * vh);
    free(z), free(lit), free(a), free(b);
}

int main(void)
{
    test_frame();
    test_nadir();
    test_background();
    test_sky_rotation();
    test_exaggeration();
    return finish_checks("test_truth_view");
}
