/*
 * test_gles_grid.c — the GLES renderer's sub-sampled visibility grid and its
 * exact slice path (label "gl"), one mode per ctest entry:
 *
 *   sub SCENE SUB GRID MEAN MAX [LIGHTS [slice]]
 *       fp16 at subsample SUB against subsample 1 on the same renderer
 *       (mode_sub below says what GRID bounds); LIGHTS = both | env | key
 *       (default both); "slice": the exact slice path instead of Legendre.
 *   slice  the slice path against the CPU reference at subsample 1, and a
 *       turned environment on kept slices against a fresh frame.
 *
 * No GLES context of any kind: exit 77 (gl_test.h).
 */
#include "gles_render_util.h"

#include <stdlib.h>

/* Sub-sampling against the same renderer at subsample 1 (not against the
 * CPU, which has no sub-sampling): texels on the grid read the receiver's
 * own visibility (bilinear weight 0) and add back everything per-texel
 * (hemisphere, floors, E_cap) at their own normal, so they equal subsample
 * 1 (GRID: largest |difference| / max unshadowed allowed there, 0 = bit for
 * bit); between grid points only the interpolated visibility differs,
 * bounded per scene by MEAN / MAX (SPEC metrics over all texels).
 * With a key light GRID is "fF": at most the fraction F of the grid texels
 * may differ by more than 1e-2 (the key light's near search is every
 * texel's own, along the swath's centre and refined apart from the far
 * scales, so a grid texel's shadow can flip where subsample 1's single
 * refinement misses a peak; DESIGN.md "Key lights on the 2x2 grid").
 * LIGHTS: both (default: sky + key light), env, key; then "slice" (the
 * exact slice path) or "tables" (the wedge-table path), and "split". */
static int mode_sub(int argc, char **argv)
{
    if (argc < 7)
        return 2;
    const char *name = argv[2];
    const int sub = atoi(argv[3]);
    const int grid_frac = argv[4][0] == 'f';
    const double max_grid = atof(argv[4] + grid_frac), max_mean = atof(argv[5]),
                 max_max = atof(argv[6]);
    const char *lights = argc > 7 ? argv[7] : "both";
    const int slice = argc > 8 && !strcmp(argv[8], "slice");
    /* "tables": the wedge-table path, which counts every elevation */
    const int tables = argc > 8 && !strcmp(argv[8], "tables");
    /* "split": split horizons with the same far settings at both steps
     * (far-from 16, 2 sub-directions, far grid step 8, refine 2, so that
     * the near part's refining is the same too): the sub-sampling alone. */
    const int split = argc > 9 && !strcmp(argv[9], "split");
    const int n = !strcmp(name, "dem") ? 96 : 64;
    scene s;
    if (scene_make(name, n, HFS_DATA_DIR, &s))
        return 1;
    hfs_renderer *r = gles_or_skip(NULL);
    hfs_lighting l = scene_lighting(strcmp(lights, "key") != 0, strcmp(lights, "env") != 0);
    hfs_quality q1 = quality("fp16", "legendre", 1), qs = quality("fp16", "legendre", sub);
    if (slice)
        q1.visibility = qs.visibility = HFS_VIS_SLICE;
    if (tables)
        q1.visibility = qs.visibility = HFS_VIS_WEDGE_TABLE;
    if (split) {
        q1.split = qs.split = 1;
        q1.far_from = qs.far_from = 16;
        q1.far_dirs = qs.far_dirs = 2;
        q1.far_step = qs.far_step = 8;
        q1.refine = qs.refine = 2;
    }
    hfs_image a = {0}, b = {0};
    if (!render(r, &s, &l, &q1, &a) && !render(r, &s, &l, &qs, &b)) {
        hfs_metrics m = compare(&s, &l, &q1, &b, &a);
        long grid = 0, same = 0, differ = 0, flipped = 0;
        double grid_max = 0.0;
        int gi = -1, gj = -1;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const size_t at = 3 * ((size_t)j * n + i);
                const int eq = !memcmp(&a.rgb[at], &b.rgb[at], 3 * sizeof(float));
                if (on_grid(i, n, sub) && on_grid(j, n, sub)) {
                    ++grid;
                    same += eq;
                    double dmax = 0.0;
                    for (int c = 0; c < 3; ++c)
                        dmax = fmax(dmax, fabs(a.rgb[at + c] - b.rgb[at + c]) / m.norm);
                    flipped += dmax > 1e-2;
                    for (int c = 0; c < 3; ++c)
                        if (fabs(a.rgb[at + c] - b.rgb[at + c]) / m.norm > grid_max) {
                            grid_max = fabs(a.rgb[at + c] - b.rgb[at + c]) / m.norm;
                            gi = i;
                            gj = j;
                        }
                } else {
                    differ += !eq;
                }
            }
        printf("%s %dx%d %s%s subsample %d vs 1: %ld of %ld grid texels bit-equal (largest "
               "difference %.3e at (%d, %d); %ld (%.2e) by more than 1e-2; bound %s%.2e), %ld "
               "others differ; mean %.3e rmse %.3e p99 %.3e max %.3e (bounds %.2e %.2e)\n",
               name, n, n, lights, slice ? " slice" : (tables ? " tables" : ""), sub, same, grid, grid_max, gi, gj,
               flipped, (double)flipped / (double)grid, grid_frac ? "fraction " : "", max_grid,
               differ, m.mean_abs, m.rmse, m.p99_abs, m.max_abs, max_mean, max_max);
        CHECK(m.nonfinite == 0, "%ld non-finite outputs", m.nonfinite);
        if (grid_frac)
            CHECK((double)flipped <= max_grid * (double)grid,
                  "%ld of %ld grid texels differ from subsample 1 by more than 1e-2 (> %.2e)",
                  flipped, grid, max_grid);
        else if (max_grid == 0.0)
            CHECK(same == grid, "%ld of %ld grid texels differ from subsample 1", grid - same,
                  grid);
        else
            CHECK(grid_max <= max_grid, "grid texels differ from subsample 1 by up to %.3e > %.1e",
                  grid_max, max_grid);
        CHECK(differ > 0, "no texel between grid points changed (not sub-sampled?)");
        CHECK(m.mean_abs <= max_mean, "mean %.3e > %.3e", m.mean_abs, max_mean);
        CHECK(m.max_abs <= max_max, "max %.3e > %.3e", m.max_abs, max_max);
    }
    hfs_image_free(&a);
    hfs_image_free(&b);
    hfs_renderer_destroy(r);
    scene_free(&s);
    return failures ? 1 : 0;
}

/* Exact slice lighting (--visibility slice, issue 15) on GLES against the
 * CPU reference's (runtime/core/slice_light.c) at subsample 1: fp32 must match the
 * algorithm, fp16 its storage.  meas: measured {mean, max} (fp16, fp32),
 * llvmpipe, Mesa 22.3.6; the bound is 10x.  Each case with one horizon per
 * direction (split 0) and with split horizons (the defaults: far grid step
 * 2, 3 sub-directions).  Split's larger max: an occluder blended with a
 * receiver that has none (near the field's edge) moves far with a tiny
 * weight, and texture filtering's weights are not the CPU's exactly.
 * The 99th percentile (p99: fp16, fp32; measured at 2156b87 by
 * `build/tests/test_gles_grid slice`; the same in Release, Debug+ASan,
 * under MESA_GLES_VERSION_OVERRIDE=3.0 and HFS_GL_STRICT_LIMITS=1, and
 * with GALLIUM_OVERRIDE_CPU_CAPS=sse4.1 but fractal split 1 fp32, 1.294e-5;
 * re-measured for issue 36's gap search, which the keys' horizons and the
 * far grid now take: split 1 fp32 rose from 5.4e-6 / 6.0e-7 (fractal /
 * dem) to 1.3e-5 / 3.4e-5, the fp16 cases by at most 1.2x; the far
 * occluders are now crossings, which float and double can pick apart
 * where slopes nearly tie, not traced further)
 * is bounded at
 * 1.2x: a drift of a few texels hides in the mean and under the max's
 * 10x (the far sub-directions' turns mirrored on GLES alone: split 1 fp32
 * dem mean 4.5x, p99 140x; issue 35).  Then
 * a turned environment on the kept slices (only the shading reruns)
 * equals a fresh renderer's frame. */
static int mode_slice(void)
{
    hfs_renderer *r = gles_or_skip(NULL);
    struct {
        const char *scene;
        int n, keys, split;
        double meas[2][2];
        double p99[2]; /* fp16, fp32 */
    } cases[] = {
        {"cones", 48, 0, 0, {{3.5e-6, 4.3e-5}, {8.3e-8, 4.1e-7}}, {2.358e-5, 2.015e-7}},
        {"fractal", 48, 1, 0, {{2.8e-5, 1.8e-4}, {1.4e-7, 3.5e-6}}, {1.375e-4, 8.308e-7}},
        {"dem", 40, 0, 0, {{9.0e-6, 8.3e-5}, {1.1e-7, 6.1e-7}}, {4.880e-5, 3.525e-7}},
        {"cones", 48, 0, 1, {{4.9e-6, 3.0e-4}, {5.5e-7, 2.8e-4}}, {2.569e-5, 3.023e-7}},
        {"fractal", 48, 1, 1, {{3.2e-5, 7.2e-4}, {1.5e-6, 6.4e-4}}, {1.547e-4, 1.299e-5}},
        {"dem", 40, 0, 1, {{1.3e-5, 1.8e-3}, {2.8e-6, 1.7e-3}}, {6.532e-5, 3.354e-5}},
    };
    for (size_t ci = 0; ci < sizeof cases / sizeof cases[0]; ++ci)
        for (int prec = 0; prec < 2; ++prec) {
            scene s;
            if (scene_make(cases[ci].scene, cases[ci].n, HFS_DATA_DIR, &s))
                return 1;
            hfs_lighting l = scene_lighting(1, cases[ci].keys > 0);
            l.n_key = cases[ci].keys;
            hfs_quality q = quality(prec ? "fp32" : "fp16", "legendre", 1);
            q.visibility = HFS_VIS_SLICE;
            q.split = cases[ci].split;
            hfs_image g = {0}, c = {0};
            if (!render(r, &s, &l, &q, &g) && !cpu_render(&s, &l, &q, &c)) {
                hfs_metrics m = compare(&s, &l, &q, &g, &c);
                const double bmean = 10.0 * cases[ci].meas[prec][0];
                const double bmax = 10.0 * cases[ci].meas[prec][1];
                const double bp99 = 1.2 * cases[ci].p99[prec];
                printf("slice %-8s %2dx%-2d keys %d split %d %s: mean %.2e max %.2e p99 %.3e\n",
                       cases[ci].scene, cases[ci].n, cases[ci].n, l.n_key, cases[ci].split,
                       prec ? "fp32" : "fp16", m.mean_abs, m.max_abs, m.p99_abs);
                CHECK(m.nonfinite == 0 && m.mean_abs <= bmean && m.max_abs <= bmax &&
                          m.p99_abs <= bp99,
                      "slice %s split %d %s: mean %.3e (bound %.1e) max %.3e (bound %.1e) p99 "
                      "%.3e (bound %.3e)", cases[ci].scene, cases[ci].split,
                      prec ? "fp32" : "fp16", m.mean_abs, bmean, m.max_abs, bmax, m.p99_abs, bp99);
            } else {
                CHECK(0, "slice %s: a render failed", cases[ci].scene);
            }
            if (!failures && prec == 0) { /* the environment turned: planned == fresh */
                l.env_rotate += 0.7;
                hfs_image planned = {0}, fresh = {0};
                const hfs_renderer_desc d = {.backend = HFS_BACKEND_GLES, .context = test_context};
                hfs_renderer *r2 = gl_test_renderer(&d);
                if (!render(r, &s, &l, &q, &planned) && !render(r2, &s, &l, &q, &fresh))
                    CHECK(!memcmp(planned.rgb, fresh.rgb,
                                  (size_t)s.f.width * s.f.height * 3 * sizeof *planned.rgb),
                          "slice %s: the turned environment on kept slices differs from a "
                          "fresh frame", cases[ci].scene);
                hfs_renderer_destroy(r2);
                hfs_image_free(&planned);
                hfs_image_free(&fresh);
            }
            hfs_image_free(&g);
            hfs_image_free(&c);
            scene_free(&s);
        }
    hfs_renderer_destroy(r);
    return failures ? 1 : 0;
}

int main(int argc, char **argv)
{
    setvbuf(stdout, NULL, _IONBF, 0);
    if (argc >= 2 && !strcmp(argv[1], "sub"))
        return mode_sub(argc, argv);
    if (argc >= 2 && !strcmp(argv[1], "slice"))
        return mode_slice();
    fprintf(stderr, "usage: test_gles_grid sub|slice ...\n");
    return 2;
}
