/*
 * test_local_shadow.c — a local light's shadow of a narrow post stays whole
 * (issue 36, deliverable 1, for local spherical lights): a post a few
 * texels wide on a flat field, a small light low beside it, the umbra and
 * the lit ground told by geometry alone (no truth render): a ground point
 * is in umbra where its rays to the light's centre and to the sphere's
 * left, right and top enter the post's top square (shrunk by half a
 * texel) while still below its height less half a texel; it is lit where
 * those rays and the one to the sphere's bottom miss the post's footprint
 * grown by its one-texel ramp (and half a texel more), or pass above its
 * height plus half a texel.  Each umbra texel must render below 5% of its
 * unshadowed value, each lit one above 95%.  On a sub-sampled grid only
 * the grid's own texels are checked: the others read the receivers' ratios
 * bilinearly (DESIGN.md "Local lights"), and at a receiver the ratio is
 * the one subsample 1 computes.
 *
 * Before session 41 a local light's samples were the pyramid's scales
 * alone, which step over a post beyond a few times its width: the shadow
 * came out in stripes (290 of 396, 398 of 504 and 221 of 356 umbra texels
 * lit in the three cases, CPU and GLES alike at subsample 1; 72 of 100,
 * 106 of 131 and 60 of 91 of the grid's at 2).  Now each sample also
 * searches its own ray through every crossing and cell (cpu_local.c
 * ray_horizon, local_visibility.frag).
 *
 *   test_local_shadow cpu [SUBSAMPLE] | gles SUBSAMPLE
 */
#include "metamorphic.h" /* mm_main: the backend from the command line */
#include "post_geometry.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct post_case {
    int w, h;               /* field */
    int x0, y0, side;       /* the post's grid points [x0, x0 + side - 1]^2 */
    double height;
    double lx, ly, lz, lr;  /* the light: centre and radius (dx 1, zscale 1) */
} post_case;

/* The height at horizontal distance t of the ray from ground point (i, j)
 * to q, and whether t lies before q. */
static double ray_height(double i, double j, const double q[3], double t, int *before)
{
    const double run = hypot(q[0] - i, q[1] - j);
    *before = t < run;
    return q[2] * t / run;
}

/* 1: umbra, 0: lit, -1: neither (penumbra, the post, its ramp), for the
 * ground point (i, j). */
static int classify(const post_case *pc, double i, double j)
{
    const double a0 = pc->x0, a1 = pc->x0 + pc->side - 1, b0 = pc->y0, b1 = pc->y0 + pc->side - 1;
    if (i >= a0 - 1 && i <= a1 + 1 && j >= b0 - 1 && j <= b1 + 1)
        return -1;
    const double dx = pc->lx - i, dy = pc->ly - j, run = hypot(dx, dy);
    const double ux = -dy / run * pc->lr, uy = dx / run * pc->lr; /* the sphere's side */
    const double pts[5][3] = {{pc->lx, pc->ly, pc->lz},
                              {pc->lx + ux, pc->ly + uy, pc->lz},
                              {pc->lx - ux, pc->ly - uy, pc->lz},
                              {pc->lx, pc->ly, pc->lz + pc->lr},
                              {pc->lx, pc->ly, pc->lz - pc->lr}};
    int umbra = 1, lit = 1;
    for (int k = 0; k < 5; ++k) {
        const double *q = pts[k];
        const double r = hypot(q[0] - i, q[1] - j), c = (q[0] - i) / r, s = (q[1] - j) / r;
        int before = 0;
        if (k < 4) { /* the sphere's centre, sides and top: all blocked */
            const double t_in = ray_enter(i, j, c, s, a0 + 0.5, a1 - 0.5, b0 + 0.5, b1 - 0.5);
            if (t_in < 0.0 || ray_height(i, j, q, t_in, &before) > pc->height - 0.5 || !before)
                umbra = 0;
        }
        /* every one of the five clear of the post and its ramp */
        const double t_ramp = ray_enter(i, j, c, s, a0 - 1.5, a1 + 1.5, b0 - 1.5, b1 + 1.5);
        if (t_ramp >= 0.0 && ray_height(i, j, q, t_ramp, &before) < pc->height + 0.5 && before)
            lit = 0;
    }
    return umbra ? 1 : (lit ? 0 : -1);
}

static void run_case(hfs_renderer *r, const char *name, const post_case *pc,
                     const hfs_quality *q)
{
    const int w = pc->w, h = pc->h, sub = q->subsample > 1 ? q->subsample : 1;
    float *z;
    const hfs_field f = post_field(w, h, pc->x0, pc->y0, pc->side, pc->height, &z);
    hfs_lighting l;
    hfs_lighting_defaults(&l);
    l.n_local = 1;
    l.local[0] = (hfs_local_light){.pos = {pc->lx, pc->ly, pc->lz}, .radius = pc->lr,
                                   .radiance = {1000, 1000, 1000}};
    hfs_image img = {0}, un = {0};
    hfs_error err = {""};
    if (hfs_image_alloc(&img, w, h, &err) || hfs_image_alloc(&un, w, h, &err) ||
        hfs_renderer_render(r, &f, &l, q, &img, NULL, NULL, &err) ||
        hfs_render_unshadowed(&f, &l, q, &un, &err)) {
        LS_CHECK(0, "%s: %s", name, err.msg);
    } else {
        long n_umbra = 0, n_lit = 0, bad_umbra = 0, bad_lit = 0;
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) {
                const int k = classify(pc, i, j);
                const size_t t = 3 * ((size_t)j * w + i);
                const double v = img.rgb[t], u = un.rgb[t];
                if ((i % sub || j % sub) && i != w - 1 && j != h - 1)
                    continue; /* between the grid's receivers */
                if (k == 1) {
                    ++n_umbra;
                    bad_umbra += v > 0.05 * u;
                    if (v > 0.05 * u && bad_umbra <= 3)
                        printf("  umbra texel (%d, %d) at %.3f of its unshadowed value\n", i, j,
                               v / u);
                } else if (k == 0 && u > 0.0) {
                    ++n_lit;
                    bad_lit += v < 0.95 * u;
                }
            }
        printf("%s: post %d wide, %.0f tall, light at (%.0f, %.0f, %.0f): umbra %ld texels, "
               "%ld lit; lit ground %ld texels, %ld shadowed\n", name, pc->side, pc->height,
               pc->lx, pc->ly, pc->lz, n_umbra, bad_umbra, n_lit, bad_lit);
        post_checks(name, 20, n_umbra, bad_umbra, n_lit, bad_lit);
    }
    hfs_image_free(&img);
    hfs_image_free(&un);
    free(z);
}

static void run(hfs_renderer *r, const char *backend, int sub)
{
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.subsample = sub > 0 ? sub : 1;
    static const post_case cases[] = {
        {160, 24, 100, 10, 4, 10.0, 140.0, 11.5, 6.0, 0.3}, /* along -x, the light 40 out */
        {32, 160, 14, 40, 4, 12.0, 15.5, 10.0, 9.0, 0.4},   /* along +y */
        {128, 128, 60, 60, 4, 8.0, 100.0, 90.0, 5.0, 0.2},  /* oblique */
        /* a tall post behind a low light: the texels before the light see
         * it above them, which a search past the light would take */
        {160, 24, 100, 10, 4, 30.0, 80.0, 11.5, 2.0, 0.3},
    };
    char name[64];
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        snprintf(name, sizeof name, "%s sub %d case %zu", backend, q.subsample, c);
        run_case(r, name, &cases[c], &q);
    }
}

int main(int argc, char **argv)
{
    return mm_main(argc, argv, "test_local_shadow", run);
}
