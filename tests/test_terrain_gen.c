/*
 * test_terrain_gen.c — the procedural test scenes (tools/terrain_gen.h,
 * issue 5): every kind by name, deterministic (two calls give the same
 * bits), and each one's defining property: flat is 0, the spike is one
 * raised texel, the cliff and the city have vertical walls (only their two
 * or few levels occur), sine and egg tray stay in [0, 2a] (checked where
 * the field resolves the features, side >= 16), everything is finite and
 * >= 0.  Sizes include non-powers of two and thin fields.
 */
#include "terrain_gen.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

static void check_kind(const char *name, int w, int h)
{
    const size_t n = (size_t)w * h;
    float *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b);
    if (!a || !b) {
        CHECK(0, "out of memory");
        free(a);
        free(b);
        return;
    }
    memset(b, 0xff, n * sizeof *b); /* NaN pattern: every texel must be written */
    CHECK(hfs_terrain_make(name, a, w, h, 7, 0.25) == 0, "%s: make failed", name);
    CHECK(hfs_terrain_make(name, b, w, h, 7, 0.25) == 0, "%s: make failed", name);
    CHECK(!memcmp(a, b, n * sizeof *a), "%s %dx%d: two calls differ", name, w, h);
    const double side = w < h ? w : h;
    double lo = INFINITY, hi = -INFINITY;
    size_t raised = 0, levels_bad = 0;
    for (size_t k = 0; k < n; ++k) {
        CHECK(isfinite(a[k]) && a[k] >= 0.0f, "%s: texel %zu = %g", name, k, a[k]);
        lo = fmin(lo, a[k]);
        hi = fmax(hi, a[k]);
        raised += a[k] > 0.0f;
        if (!strcmp(name, "cliff"))
            levels_bad += a[k] != 0.0f && a[k] != (float)(side / 4.0);
        if (!strcmp(name, "city"))
            levels_bad += a[k] != 0.0f && !(a[k] >= 0.1 * side / 8.0 - 1e-4 &&
                                             a[k] <= 0.6 * side / 8.0 + 1e-4);
    }
    if (!strcmp(name, "flat"))
        CHECK(hi == 0.0, "flat: max %g", hi);
    if (side < 16) { /* features smaller than a texel: finite and deterministic is all */
        free(a);
        free(b);
        return;
    }
    if (!strcmp(name, "spike"))
        CHECK(raised == 1 && hi == (float)(side / 4.0), "spike: %zu raised, max %g", raised, hi);
    if (!strcmp(name, "cliff") || !strcmp(name, "city"))
        CHECK(levels_bad == 0 && raised > 0 && raised < n, "%s: %zu off-level texels, %zu raised",
              name, levels_bad, raised);
    if (!strcmp(name, "sine") || !strcmp(name, "eggtray")) {
        const double a2 = 2.0 * side / 8.0 / 6.283185307179586;
        CHECK(lo >= 0.0 && hi <= a2 * (1 + 1e-6) && hi > 0.7 * a2, "%s: range [%g, %g], 2a %g",
              name, lo, hi, a2);
    }
    if (!strcmp(name, "cones") || !strcmp(name, "fractal") || !strcmp(name, "panel"))
        CHECK(hi > lo, "%s: constant", name);
    free(a);
    free(b);
}

/* The mean |discrete Laplacian| of a field over its height range: the
 * share of the relief at the texel scale. */
static double texel_roughness(const float *z, int w, int h)
{
    double sum = 0.0, lo = INFINITY, hi = -INFINITY;
    for (int j = 1; j < h - 1; ++j)
        for (int i = 1; i < w - 1; ++i) {
            const float *p = z + (size_t)j * w + i;
            sum += fabs(4.0 * p[0] - p[-1] - p[1] - p[-w] - p[w]);
        }
    for (int k = 0; k < w * h; ++k)
        lo = fmin(lo, z[k]), hi = fmax(hi, z[k]);
    return sum / ((w - 2.0) * (h - 2.0)) / (hi - lo);
}

/* hfs_terrain_fbm: Hurst 1 is hfs_terrain_fractal bit for bit; a lower
 * exponent puts more of the relief at the texel scale (issue 36's Hurst
 * 0.25 field), and the heights still span [0, relief * side]. */
static void check_hurst(void)
{
    enum { W = 64, H = 48 };
    static float a[W * H], b[W * H], c[W * H];
    CHECK(!hfs_terrain_fractal(a, W, H, 3, 0.5) && !hfs_terrain_fbm(b, W, H, 3, 0.5, 1.0) &&
              !hfs_terrain_fbm(c, W, H, 3, 0.5, 0.25),
          "fbm failed");
    CHECK(!memcmp(a, b, sizeof a), "Hurst 1 is not hfs_terrain_fractal");
    double lo = INFINITY, hi = -INFINITY;
    for (int k = 0; k < W * H; ++k)
        lo = fmin(lo, c[k]), hi = fmax(hi, c[k]);
    CHECK(lo == 0.0 && fabs(hi - 0.5 * H) < 1e-3 * H, "Hurst 0.25: range [%g, %g]", lo, hi);
    const double r1 = texel_roughness(a, W, H), r025 = texel_roughness(c, W, H);
    CHECK(r025 > 3.0 * r1, "texel-scale roughness: Hurst 0.25 %g, Hurst 1 %g", r025, r1);
    printf("texel-scale roughness (mean |Laplacian| / range): Hurst 1 %.4f, 0.25 %.4f\n", r1,
           r025);
}

int main(void)
{
    check_hurst();
    static const int sizes[][2] = {{64, 64}, {97, 61}, {2, 2}, {1024, 3}};
    char names[256];
    snprintf(names, sizeof names, "%s", hfs_terrain_names());
    int kinds = 0;
    for (char *save = NULL, *t = strtok_r(names, "|", &save); t; t = strtok_r(NULL, "|", &save)) {
        ++kinds;
        for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; ++s)
            check_kind(t, sizes[s][0], sizes[s][1]);
    }
    float z[4];
    CHECK(hfs_terrain_make("mountains", z, 2, 2, 1, 0.25) == -1, "unknown name accepted");
    CHECK(kinds == 11, "%d kinds listed", kinds);
    printf("%d kinds x %zu sizes: %s\n", kinds, sizeof sizes / sizeof sizes[0],
           failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
