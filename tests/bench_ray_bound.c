/*
 * bench_ray_bound.c — what the gap search (runtime/core/ray_bound.h) reads
 * on a height field (not a test; BENCHMARKS.md "Long shadows of narrow
 * features"):
 *
 *   build/tests/bench_ray_bound FIELD.pfm [ZS] [PHI_DEG] [ELEV_DEG]
 *
 * For every third receiver and the direction PHI (default 336 degrees),
 * the reads (bound reads and crossings evaluated) of one search started
 *   1. from -infinity (the ray's whole max, nothing known),
 *   2. from the ray's max itself (the least any search started from the
 *      scales' best can read: every remaining read is the walk's),
 *   3. from max(the ray's max, tan(ELEV - 2 degrees)) (a key light that
 *      needs no horizon below its window; ELEV default 15).
 * ZS: zscale / dx (default 1).
 */
#include "hfs_io.h"
#include "ray_bound.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define PI 3.14159265358979323846

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: bench_ray_bound FIELD.pfm [ZS] [PHI_DEG] [ELEV_DEG]\n");
        return 2;
    }
    hfs_error err = {""};
    hfs_heightmap hm;
    if (hfs_height_load(argv[1], NULL, &hm, &err)) {
        fprintf(stderr, "bench_ray_bound: %s\n", err.msg);
        return 1;
    }
    const double zs = argc > 2 ? atof(argv[2]) : 1.0;
    const double phi = (argc > 3 ? atof(argv[3]) : 336.0) * PI / 180.0;
    const double elev = (argc > 4 ? atof(argv[4]) : 15.0) * PI / 180.0;
    const int w = hm.width, h = hm.height;
    double *z = malloc((size_t)w * h * sizeof *z);
    hfs_ray_bound_layout L;
    hfs_ray_bound_layout_make(w, h, &L);
    double *atlas = malloc((size_t)L.aw * L.ah * sizeof *atlas);
    double *scratch = malloc(2 * (size_t)L.lw[1] * L.lh[1] * sizeof *scratch);
    if (!z || !atlas || !scratch) {
        fprintf(stderr, "bench_ray_bound: out of memory\n");
        return 1;
    }
    for (size_t t = 0; t < (size_t)w * h; ++t)
        z[t] = hm.z[t];
    hfs_ray_bound_build(&L, hm.z, 0.0, 1.0, -HUGE_VAL, atlas, scratch);
    double c = cos(phi), s = sin(phi);
    c = fabs(c) < 1e-12 ? 0.0 : c;
    s = fabs(s) < 1e-12 ? 0.0 : s;
    long reads[3] = {0, 0, 0}, n = 0;
    for (int j = 0; j < h; j += 3)
        for (int i = 0; i < w; i += 3) {
            double d = 0.0;
            const double top = hfs_ray_bound_search(&L, atlas, z, (size_t)w, i, j, c, s, 0.0,
                                                    HUGE_VAL, zs, 0.0, -1e30, &d, &reads[0]);
            const double at = top - 1e-9 * (1.0 + fabs(top));
            hfs_ray_bound_search(&L, atlas, z, (size_t)w, i, j, c, s, 0.0, HUGE_VAL, zs, 0.0, at,
                                 &d, &reads[1]);
            hfs_ray_bound_search(&L, atlas, z, (size_t)w, i, j, c, s, 0.0, HUGE_VAL, zs, 0.0,
                                 fmax(at, tan(elev - 2.0 * PI / 180.0)), &d, &reads[2]);
            ++n;
        }
    printf("%s %dx%d zs %g phi %.1f: reads per search from -inf %.1f, from the ray's max %.1f, "
           "from max(max, tan(%.0f - 2 deg)) %.1f (%ld searches)\n",
           argv[1], w, h, zs, phi * 180.0 / PI, (double)reads[0] / n, (double)reads[1] / n,
           elev * 180.0 / PI, (double)reads[2] / n, n);
    free(z), free(atlas), free(scratch);
    hfs_heightmap_free(&hm);
    return 0;
}
