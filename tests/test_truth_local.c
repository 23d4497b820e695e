/*
 * test_truth_local.c — hfs_truth_render and hfs_unshadowed_render with local
 * (sphere) lights, on scenes with known answers (split from
 * test_truth_render.c):
 *   local_flat         local light over a plane = unshadowed; inside sphere
 *   local_wall         occluders count only between receiver and light
 * Tolerances are stated where they are checked.
 */
#include "backends.h"
#include "lights.h"
#include "test_util.h"
#include "truth_render_util.h"

#include <math.h>
#include <stdlib.h>

/* ---- (5) local lights --------------------------------------------------------------- */

static void test_local_flat(void)
{
    /* Sphere lights over a flat plane: nothing occludes them, so truth is the
     * stratified estimate of the exact cap irradiance.
     * (a) a light well above the plane (no cap crosses the horizon) at the
     *     default 256 samples, with a radius-0 light and a black light that
     *     must add nothing: tolerance 1e-3 of the largest value (observed
     *     ~4e-4: the 1D cos theta stratification, see key_flat);
     * (b) a light centred ON the plane (radius 1.5): receivers inside it get
     *     rho*Le exactly (E = pi, no occlusion); outside, its cap straddles
     *     the horizon, whose kink costs accuracy: 4096 samples, tolerance 2e-3
     *     of the largest value (observed ~7e-4). */
    const int w = 21, h = 17;
    float *z = calloc((size_t)w * h, sizeof *z);
    const hfs_field f = {w, h, z, 0.5, 1.0};
    const hfs_local_light lights[2][3] = {
        {{.pos = {4.0, 3.0, 2.0}, .radius = 0.7, .radiance = {5.0f, 4.0f, 3.0f}},
         {.pos = {2.0, 2.0, 1.0}, .radius = 0.0, .radiance = {100.0f, 100.0f, 100.0f}},
         {.pos = {2.0, 2.0, 1.0}, .radius = 0.5}},
        {{.pos = {7.5, 5.0, 0.0}, .radius = 1.5, .radiance = {1.0f, 2.0f, 0.25f}}}};
    const int counts[2] = {3, 1}, samples[2] = {256, 4096};
    const double tols[2] = {1e-3, 2e-3};
    double worst[2] = {0.0, 0.0};
    int inside = 0;
    for (int c = 0; c < 2; ++c) {
        hfs_lighting l = no_lights();
        l.albedo = 0.9;
        l.n_local = counts[c];
        for (int n = 0; n < counts[c]; ++n)
            l.local[n] = lights[c][n];
        hfs_quality q = default_quality(0);
        q.truth_light_samples = samples[c];
        hfs_image t = {0}, u = {0};
        REQUIRE(render_both(&f, &l, &q, &t, &u) == 0, "render");
        double umax = 0.0;
        for (int k = 0; k < w * h * 3; ++k)
            umax = u.rgb[k] > umax ? u.rgb[k] : umax;
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) {
                const double p[3] = {i * 0.5, j * 0.5, 1e-4 * 0.5};
                double d[3], dist, alpha;
                const int in = hfs_local_light_cap(&l.local[0], p, d, &dist, &alpha);
                inside += in;
                for (int ch = 0; ch < 3; ++ch) {
                    const int k = 3 * (j * w + i) + ch;
                    /* unshadowed, independently (only light 0 is lit) */
                    const double want = 0.9 / PI * l.local[0].radiance[ch] *
                                        hfs_cap_irradiance(d[2], alpha);
                    REQUIRE(fabs(u.rgb[k] - want) <= 1e-6 * umax, "unshadowed (%d,%d): %g want %g",
                            i, j, u.rgb[k], want);
                    if (in)
                        REQUIRE(fabs(t.rgb[k] - 0.9 * l.local[0].radiance[ch]) <= 1e-6 * umax,
                                "inside the sphere (%d,%d): truth %g want %g", i, j, t.rgb[k],
                                0.9 * l.local[0].radiance[ch]);
                    const double e = fabs(t.rgb[k] - u.rgb[k]) / umax;
                    worst[c] = e > worst[c] ? e : worst[c];
                    REQUIRE(e <= tols[c], "light set %d (%d,%d) ch %d: truth %.8g unshadowed %.8g",
                            c, i, j, ch, t.rgb[k], u.rgb[k]);
                }
            }
        hfs_image_free(&t);
        hfs_image_free(&u);
    }
    REQUIRE(inside >= 20, "only %d receivers inside the sphere", inside);
    free(z);
    printf("local_flat: worst |truth-unshadowed|/max %.2e (above the plane), %.2e (on the "
           "plane, 4096 samples; %d receivers inside: exact)\n", worst[0], worst[1], inside);
}

static void test_local_wall(void)
{
    /* Terrain occludes a local light only between receiver and light:
     * flat ground, a wall (height 10, column x = 20, rows 2..h-3 so that the
     * ends stay in the grid) and a sphere light at (12, 8, 3), r = 0.5.
     *  - receivers at x <= 8 have the wall BEHIND the light: rays continued
     *    past the sphere would hit it, but must not count: truth = unshadowed
     *    (measured 3.2e-5 of the value: tolerance 3.2e-4);
     *  - receivers at x >= 23 (rows 5..10) see the light through the wall
     *    (the rays cross x = 20 below z = 3 * 3/11 + 0.5 < 10): exactly 0. */
    const int w = 30, h = 16;
    float *z = calloc((size_t)w * h, sizeof *z);
    for (int j = 2; j < h - 2; ++j)
        z[j * w + 20] = 10.0f;
    const hfs_field f = {w, h, z, 1.0, 1.0};
    hfs_lighting l = no_lights();
    l.n_local = 1;
    l.local[0] = (hfs_local_light){.pos = {12.0, 8.0, 3.0}, .radius = 0.5,
                                   .radiance = {1.0f, 1.0f, 1.0f}};
    const hfs_quality q = default_quality(0);
    hfs_image t = {0}, u = {0};
    REQUIRE(render_both(&f, &l, &q, &t, &u) == 0, "render");
    double worst = 0.0;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const double v = t.rgb[3 * (j * w + i)], un = u.rgb[3 * (j * w + i)];
            if (i <= 8) {
                const double e = fabs(v - un) / un;
                worst = e > worst ? e : worst;
                REQUIRE(e <= 3.2e-4, "in front of the light (%d,%d): truth %g unshadowed %g", i, j,
                        v, un);
            }
            if (i >= 23 && j >= 5 && j <= 10)
                REQUIRE(v == 0.0 && un > 0.0, "behind the wall (%d,%d): truth %g (unshadowed %g)",
                        i, j, v, un);
        }
    hfs_image_free(&t);
    hfs_image_free(&u);
    free(z);
    printf("local_wall: terrain beyond the light ignored (worst %.2e), wall in between: 0\n",
           worst);
}

int main(void)
{
    test_local_flat();
    test_local_wall();
    return finish_checks("test_truth_local");
}
