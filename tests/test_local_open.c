/*
 * test_local_open.c — the shadow-range test of local lights
 * (lights.h hfs_local_light_open): a light it calls open must really be
 * unshadowed from every receiver, and the CPU reference must then give the
 * unshadowed value exactly.
 *   1. Random small fields (cones, ridges, noise at several zscales) and
 *      random lights: for each light called open, rays from every receiver
 *      (lifted 1e-4 dx, as the backends) to 64 points of the sphere are
 *      marched at 1/8 texel over the bilinear surface and must stay above it.
 *      Lights far above are open, lights near the terrain are not: both
 *      kinds occur (the test is not vacuous).
 *   2. A CPU render with one open light equals rho/pi Le E_cap (no shadow).
 */
#include "hfshade.h"
#include "field_geom.h"
#include "lights.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

#define PI 3.14159265358979323846

static double frand(unsigned *s)
{
    *s = *s * 1664525u + 1013904223u;
    return (*s >> 8) * (1.0 / 16777216.0);
}

static void make_field(float *z, int n, int kind, unsigned *seed)
{
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            double v;
            if (kind == 0) /* a cone */
                v = fmax(0.0, 6.0 - 0.8 * hypot(i - n / 2.0, j - n / 2.0));
            else if (kind == 1) /* ridges */
                v = 3.0 * sin(0.7 * i) * cos(0.4 * j);
            else /* noise */
                v = 4.0 * frand(seed);
            z[j * n + i] = (float)v;
        }
}

/* 1 if the segment from p to q stays above the bilinear surface. */
static int segment_clear(const hfs_field *f, const double p[3], const double q[3])
{
    const double len = hypot(q[0] - p[0], q[1] - p[1]) / f->dx;
    const int steps = (int)ceil(8.0 * len) + 1;
    for (int k = 1; k <= steps; ++k) {
        const double t = (double)k / steps;
        const double x = p[0] + t * (q[0] - p[0]), y = p[1] + t * (q[1] - p[1]);
        double zt;
        if (!hfs_field_bilinear(f, x / f->dx, y / f->dx, &zt))
            return 1; /* beyond the field: nothing there */
        if (zt >= p[2] + t * (q[2] - p[2]))
            return 0;
    }
    return 1;
}

int main(void)
{
    enum { N = 16 };
    float z[N * N];
    unsigned seed = 12345;
    int open = 0, closed = 0;
    for (int trial = 0; trial < 240; ++trial) {
        make_field(z, N, trial % 3, &seed);
        hfs_field f = {.width = N, .height = N, .z = z, .dx = 0.5 + frand(&seed),
                       .zscale = 0.2 + 2.0 * frand(&seed)};
        hfs_field_extent e;
        hfs_field_extent_make(&f, &e);
        const double span = (N - 1) * f.dx;
        hfs_local_light l = {.pos = {span * (2.0 * frand(&seed) - 0.5),
                                     span * (2.0 * frand(&seed) - 0.5),
                                     e.z_top + (trial % 2 ? 40.0 : 4.0) * frand(&seed) * span},
                             .radius = 0.05 + 0.3 * frand(&seed) * f.dx,
                             .radiance = {1, 1, 1}};
        if (!hfs_local_light_open(&e, &l)) {
            ++closed;
            continue;
        }
        ++open;
        for (int j = 0; j < N; ++j)
            for (int i = 0; i < N; ++i) {
                const double p[3] = {i * f.dx, j * f.dx, hfs_field_z(&f, i, j) + 1e-4 * f.dx};
                for (int s = 0; s < 64; ++s) {
                    /* A point of the sphere (uniform in z and azimuth). */
                    const double cz = 2.0 * frand(&seed) - 1.0, az = 2.0 * PI * frand(&seed);
                    const double rr = sqrt(fmax(0.0, 1.0 - cz * cz));
                    const double q[3] = {l.pos[0] + l.radius * rr * cos(az),
                                         l.pos[1] + l.radius * rr * sin(az),
                                         l.pos[2] + l.radius * cz};
                    if (!segment_clear(&f, p, q)) {
                        CHECK(0, "trial %d: open light blocked from receiver (%d, %d)", trial, i,
                              j);
                        i = j = N; /* one report per light */
                        break;
                    }
                }
            }
    }
    printf("open lights %d, not open %d\n", open, closed);
    CHECK(open >= 40 && closed >= 40, "both kinds must occur (open %d, not %d)", open, closed);

    /* 2. The CPU reference gives an open light its unshadowed value. */
    make_field(z, N, 0, &seed);
    hfs_field f = {.width = N, .height = N, .z = z, .dx = 1.0, .zscale = 1.0};
    hfs_lighting l;
    hfs_lighting_defaults(&l);
    l.albedo = 0.7;
    l.n_local = 1;
    l.local[0] = (hfs_local_light){.pos = {7, 9, 300}, .radius = 2.0, .radiance = {3, 4, 5}};
    hfs_field_extent e;
    hfs_field_extent_make(&f, &e);
    CHECK(hfs_local_light_open(&e, &l.local[0]), "a light 300 above a cone of 6 is open");
    hfs_quality q;
    hfs_quality_defaults(&q);
    hfs_renderer_desc d = {.backend = HFS_BACKEND_CPU};
    hfs_renderer *r = NULL;
    hfs_error err;
    hfs_image img = {0};
    if (hfs_renderer_create(&d, &r, &err) || hfs_image_alloc(&img, N, N, &err)) {
        CHECK(0, "cpu renderer: %s", err.msg);
    } else if (hfs_renderer_render(r, &f, &l, &q, &img, NULL, NULL, &err)) {
        CHECK(0, "render: %s", err.msg);
    } else {
        double worst = 0.0;
        for (int j = 0; j < N; ++j)
            for (int i = 0; i < N; ++i) {
                double n[3], p[3] = {i, j, hfs_field_z(&f, i, j) + 1e-4}, dir[3], dist, alpha;
                hfs_field_normal(&f, i, j, n);
                hfs_local_light_cap(&l.local[0], p, dir, &dist, &alpha);
                const double e_cap =
                    hfs_cap_irradiance(n[0] * dir[0] + n[1] * dir[1] + n[2] * dir[2], alpha);
                for (int c = 0; c < 3; ++c) {
                    const double want = l.albedo / PI * e_cap * l.local[0].radiance[c];
                    const double got = img.rgb[3 * (j * N + i) + c];
                    worst = fmax(worst, fabs(got - want) / fmax(want, 1e-30));
                }
            }
        printf("cpu, open light: worst relative difference to unshadowed %.3g\n", worst);
        CHECK(worst < 1e-6, "open light shadowed on the CPU: %g", worst);
    }
    hfs_image_free(&img);
    hfs_renderer_destroy(r);
    printf("local open: %s\n", failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
