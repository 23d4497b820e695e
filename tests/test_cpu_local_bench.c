/*
 * test_cpu_local_bench.c — the CPU reference with a chosen local-light swath
 * mode (not a test; built as bench_cpu_local).  hfs_quality has no field for
 * the mode yet (see the report to the lead), so this driver calls
 * hfs_cpu_render_with directly.
 *
 *   bench_cpu_local [--swath partial|full] [--repeat N] [scene flags as for
 *                   hfshade render ...] --pfm OUT.pfm
 *
 * Scene flags are hfshade's (--height, --dx, --zscale, --local, --k, ...;
 * --backend is ignored: this is always the CPU reference).  Prints
 * "OUT: WxH, swath MODE, median S s (N runs)" on stderr; compare the PFM with
 * `hfshade compare`.
 */
#include "backends.h"
#include "cpu_local.h"
#include "hfs_io.h"
#include "scene.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    hfs_scene sc;
    hfs_scene_init(&sc);
    hfs_error err = {{0}};
    hfs_cpu_local_options opt;
    hfs_cpu_local_options_default(&opt);
    const char *out = NULL;
    int repeat = 1;
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        if (strncmp(a, "--", 2) || i + 1 >= argc) {
            fprintf(stderr, "bench_cpu_local: %s: expected --flag VALUE\n", a);
            return 2;
        }
        const char *name = a + 2, *v = argv[++i];
        if (!strcmp(name, "swath")) {
            if (!strcmp(v, "full"))
                opt.swath = HFS_LOCAL_SWATH_FULL;
            else if (!strcmp(v, "partial"))
                opt.swath = HFS_LOCAL_SWATH_PARTIAL;
            else {
                fprintf(stderr, "bench_cpu_local: --swath %s: not partial or full\n", v);
                return 2;
            }
        } else if (!strcmp(name, "repeat")) {
            repeat = atoi(v);
            if (repeat < 1 || repeat > 1000) {
                fprintf(stderr, "bench_cpu_local: --repeat %s: not in 1..1000\n", v);
                return 2;
            }
        } else if (!strcmp(name, "pfm")) {
            out = v;
        } else if (hfs_scene_set(&sc, HFS_SOURCE_FLAG, name, v, a, NULL, &err)) {
            fprintf(stderr, "bench_cpu_local: %s\n", err.msg);
            return 2;
        }
    }
    if (!out || hfs_scene_validate(&sc, &err)) {
        fprintf(stderr, "bench_cpu_local: %s\n", out ? err.msg : "give --pfm OUT.pfm");
        return 2;
    }
    if (sc.env_map[0]) {
        fprintf(stderr, "bench_cpu_local: --env-map is not supported here (use --env-sh)\n");
        return 2;
    }
    hfs_height_load_opts lo = {0};
    lo.has_nodata = sc.has_nodata;
    lo.nodata = (float)sc.nodata;
    lo.raw_width = sc.raw_width;
    lo.raw_height = sc.raw_height;
    hfs_heightmap hm;
    if (hfs_height_load(sc.height, &lo, &hm, &err)) {
        fprintf(stderr, "bench_cpu_local: %s\n", err.msg);
        return 1;
    }
    hfs_field f = {.width = hm.width, .height = hm.height, .z = hm.z,
                   .dx = sc.dx_given ? sc.dx : (hm.cellsize > 0.0 ? hm.cellsize : 1.0),
                   .zscale = sc.zscale_given ? sc.zscale : 1.0};
    hfs_lighting l;
    hfs_quality q;
    hfs_scene_lighting(&sc, NULL, &l);
    hfs_scene_quality(&sc, &q);
    hfs_image img = {0};
    int rc = hfs_validate_inputs(&f, &l, &q, &err);
    if (!rc)
        rc = hfs_image_alloc(&img, f.width, f.height, &err);
    double *t = calloc((size_t)repeat, sizeof *t);
    for (int r = 0; !rc && r < repeat; ++r) {
        const double t0 = now_seconds();
        rc = hfs_cpu_render_with(&f, &l, &q, &opt, &img, NULL, NULL, &err);
        t[r] = now_seconds() - t0;
    }
    if (!rc)
        rc = hfs_pfm_write(out, &img, 0, &err);
    if (rc) {
        fprintf(stderr, "bench_cpu_local: %s\n", err.msg);
    } else {
        qsort(t, (size_t)repeat, sizeof *t, cmp_double);
        const double med = repeat % 2 ? t[repeat / 2] : 0.5 * (t[repeat / 2 - 1] + t[repeat / 2]);
        fprintf(stderr, "%s: %dx%d, swath %s, median %.4f s (%d runs)\n", out, f.width, f.height,
                opt.swath == HFS_LOCAL_SWATH_FULL ? "full" : "partial", med, repeat);
    }
    free(t);
    hfs_image_free(&img);
    hfs_heightmap_free(&hm);
    return rc ? 1 : 0;
}
