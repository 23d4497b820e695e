/*
 * cpu_local_util.h — what test_cpu_local.c and test_cpu_local_truth.c
 * share: their CHECK, renders of the CPU reference in one local-light
 * swath mode and unshadowed, a light, and the bumpy scene (a 3-light
 * field both the determinism and the truth checks use).  Static
 * functions: include once per test program.
 */
#ifndef HFS_TEST_CPU_LOCAL_UTIL_H
#define HFS_TEST_CPU_LOCAL_UTIL_H

#include "backends.h"
#include "cpu_local.h"
#include "hfshade.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define PI 3.14159265358979323846

static int failures;

#define CHECK(cond, ...) do { if (!(cond)) { failures++; printf("FAIL %s:%d: ", __FILE__, __LINE__); \
    printf(__VA_ARGS__); printf("\n"); } } while (0)

static const char *mode_name(int m) { return m == HFS_LOCAL_SWATH_FULL ? "full" : "partial"; }
static const char *path_name(int p) { return p == HFS_VIS_WEDGE_TABLE ? "tables" : "legendre"; }

static int render_mode(const float *z, int w, int h, double dx, double zscale,
                       const hfs_lighting *l, const hfs_quality *q, int mode, hfs_image *img)
{
    hfs_field f = {.width = w, .height = h, .z = z, .dx = dx, .zscale = zscale};
    hfs_error err = {{0}};
    hfs_cpu_local_options o;
    hfs_cpu_local_options_default(&o);
    o.swath = (hfs_local_swath_mode)mode;
    int rc = hfs_image_alloc(img, w, h, &err);
    if (rc == HFS_OK)
        rc = hfs_validate_inputs(&f, l, q, &err);
    if (rc == HFS_OK)
        rc = hfs_cpu_render_with(&f, l, q, &o, img, NULL, NULL, &err);
    CHECK(rc == HFS_OK, "render %dx%d failed: %s", w, h, err.msg);
    return rc;
}

static void unshadowed(const float *z, int w, int h, double dx, double zscale,
                       const hfs_lighting *l, const hfs_quality *q, hfs_image *img)
{
    hfs_field f = {.width = w, .height = h, .z = z, .dx = dx, .zscale = zscale};
    hfs_error err = {{0}};
    hfs_image_alloc(img, w, h, &err);
    CHECK(hfs_unshadowed_render(&f, l, q, img, &err) == HFS_OK, "unshadowed: %s", err.msg);
}

static hfs_local_light light(double x, double y, double z, double r, float le)
{
    return (hfs_local_light){.pos = {x, y, z}, .radius = r, .radiance = {le, le, le}};
}

static float *bumpy(int w, int h, double amp)
{
    float *z = malloc((size_t)w * h * sizeof *z);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            z[j * w + i] = (float)(amp * (sin(i * 0.21) * cos(j * 0.17) + 0.5 * sin(i * 0.53 + j * 0.71)) +
                                   amp);
    return z;
}

static void bumpy_lights(hfs_lighting *l, double amp)
{
    hfs_lighting_defaults(l);
    l->n_local = 3;
    l->local[0] = light(20, 14, 2.6 * amp, 1.5, 10);
    l->local[1] = light(6, 30, 1.2 * amp, 0.8, 6);
    l->local[2] = light(36, 34, 4 * amp, 3.0, 4);
    l->local[1].radiance[0] = 3.0f; /* colour */
}

#endif /* HFS_TEST_CPU_LOCAL_UTIL_H */
