/*
 * test_cpu_truth.c — the CPU reference (HFS_BACKEND_CPU at hfs_quality_defaults,
 * subsample 1)
 * against the brute-force ground truth (HFS_BACKEND_TRUTH) through the public
 * API, for every kind of light on non-flat terrain, with SPEC's metrics.
 *
 * What it guards: code the CPU reference shares with the GLES path (the SH
 * basis and zonal vectors, the environment's z-rotation, the key lights'
 * azimuth lattice and elevation window in hfs_swath_key, the ratio form of
 * key and local lights), which no GLES-vs-CPU test can see, since both sides
 * would be wrong together; only an independent oracle catches it.  Measured
 * (mean error, correct -> mutated; each fails its tests' bounds): the
 * environment rotated by -a instead of +a, env_rotated 4.2e-3 -> 3.7e-2
 * (cones), 1.2e-2 -> 1.1e-1 (fractal), 6.3e-3 -> 9.6e-2 (dem); the key-light
 * lattice's phi0 shifted by half a spacing, key_d cliff 4.9e-3 -> 2.0e-2 (the
 * one test it fails: it moves the suns a-c by < 10%, and key_d elsewhere by
 * up to 1.8x, cones 4.5e-3 -> 7.9e-3, within the bounds: a shift of the
 * swath's samples matters only where the disk is wide and the terrain hides
 * one side of it); the key-light elevation window dropped, 12 of the 16 key
 * tests, e.g. key_b cones 4.3e-3 -> 2.5e-2, key_a dem 7.7e-3 -> 3.1e-2; bands 1 and 2 of the clamped-cosine zonal vector swapped, every
 * environment test, e.g. env cones 4.3e-3 -> 2.0e-1; sin and cos swapped in
 * the azimuthal basis of the wedge integrals (hfs_sh_eval_azim), every
 * environment test, e.g. env dem 6.7e-3 -> 5.4e-2.
 *
 * Usage: test_cpu_truth LIGHTING SCENE (tests/cpu_truth.cmake runs every pair)
 *   LIGHTING  env          order-4 SH sky, no rotation
 *             env_rotated  the same sky rotated by 137 degrees about +z
 *             key_a|b|c    one low sun (different azimuth, elevation, radius)
 *             key_d        one broad disk low along the cliff (see suns[])
 *             local        one local spherical light
 *   SCENE     cones | fractal | dem (a window of data/jacksboro.png) | cliff
 * Prints the four SPEC metrics (mean, rmse, p99, max of |cpu - truth| over
 * every texel and channel / the largest unshadowed value), checks them
 * against the bounds table below, and checks that no output of either
 * backend is non-finite.
 *
 * The sky (test_sky.h) is a constant plus two clamped-cosine lobes (azimuth
 * 50, elevation 25 degrees and azimuth 205, elevation 8) plus a few band-3
 * terms: min 0.48, max 2.05 over the sphere, not rotationally symmetric, and
 * not symmetric under x -> -x or y -> -y (|L(phi) - L(pi - phi)| and
 * |L(phi) - L(-phi)| reach 0.94 and 1.33 at elevation 15 degrees), so a sign
 * error in a rotation or an azimuth moves its bright side.
 *
 * The truth runs at 720 azimuths, 16 elevation points (its defaults) and
 * 1024 samples per light (default 256): its own error, measured against
 * 2880 azimuths and 16384 samples, is at most 3.5% of the CPU's mean error
 * in every case here (0.2% for the environment), and its largest error
 * (1.1e-2, key_d) is far below the CPU's.
 */
#include "hfs_io.h"
#include "hfshade.h"
#include "terrain_gen.h"
#include "test_sky.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef HFS_DATA_DIR
#define HFS_DATA_DIR "data"
#endif

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)

#include "check.h"

/* ---- scenes --------------------------------------------------------------------- */

#define N 40 /* every scene is N x N */

/* cones: five cones of slope 0.8; fractal: relief 0.5 (heights 0..20 texels,
 * slopes up to ~2); dem: the window of the DEM at (150, 120) that the GLES
 * tests use, dx 83 m, zscale 2 (the demo's exaggeration). */
static int make_scene(const char *name, float *z, hfs_field *f)
{
    *f = (hfs_field){.width = N, .height = N, .z = z, .dx = 1.0, .zscale = 1.0};
    if (!strcmp(name, "cones")) {
        hfs_terrain_cones(z, N, N);
        return 0;
    }
    if (!strcmp(name, "fractal"))
        return hfs_terrain_fractal(z, N, N, 1, 0.5);
    if (!strcmp(name, "cliff")) {
        hfs_terrain_cliff(z, N, N);
        return 0;
    }
    if (!strcmp(name, "dem")) {
        hfs_heightmap hm;
        hfs_error err;
        const char *path = HFS_DATA_DIR "/jacksboro.png";
        if (hfs_height_load(path, NULL, &hm, &err)) {
            fprintf(stderr, "%s\n", err.msg);
            return -1;
        }
        const int x0 = 150, y0 = 120;
        if (hm.width < x0 + N || hm.height < y0 + N) {
            fprintf(stderr, "%s: %dx%d, too small for the window\n", path, hm.width, hm.height);
            hfs_heightmap_free(&hm);
            return -1;
        }
        for (int j = 0; j < N; ++j)
            for (int i = 0; i < N; ++i)
                z[j * N + i] = hm.z[(size_t)(y0 + j) * hm.width + (size_t)(x0 + i)];
        hfs_heightmap_free(&hm);
        f->dx = 83.0;
        f->zscale = 2.0;
        return 0;
    }
    fprintf(stderr, "unknown scene '%s' (cones|fractal|dem|cliff)\n", name);
    return -1;
}

/* ---- lightings --------------------------------------------------------------------- */


/* Key lights: azimuth, elevation, angular radius (degrees).  a-c: low suns
 * at angles on no lattice.  d: a broad disk low over the cliff, along its
 * edge (azimuth 258.7): receivers at the foot of the wall see part of the
 * disk hidden by it, a fraction set by where the swath's samples fall; the
 * azimuth puts the disk's low edge just past a lattice wedge boundary
 * (lattice spacing 11.25 degrees here), so a lattice shifted by half a
 * spacing leaves a sliver of ~5 degrees of the disk unsampled. */
static const double suns[4][3] = {
    {337.3, 11.7, 1.3}, {103.9, 23.4, 3.1}, {218.6, 6.8, 0.6}, {256.72, 15.0, 14.0}};

static int make_lighting(const char *name, const hfs_field *f, hfs_lighting *l)
{
    hfs_lighting_defaults(l);
    l->albedo = 0.8;
    if (!strcmp(name, "env") || !strcmp(name, "env_rotated")) {
        l->has_env = 1;
        for (int c = 0; c < 3; ++c)
            memcpy(l->env_sh[c], test_sky_sh, sizeof test_sky_sh);
        l->env_rotate = !strcmp(name, "env_rotated") ? 137.0 * DEG : 0.0;
        return 0;
    }
    if (!strncmp(name, "key_", 4) && name[4] >= 'a' && name[4] <= 'd' && !name[5]) {
        const double *s = suns[name[4] - 'a'];
        l->n_key = 1;
        l->key[0] = (hfs_key_light){.phi = s[0] * DEG, .elev = s[1] * DEG, .alpha = s[2] * DEG,
                                    .radiance = {900.0f, 800.0f, 650.0f}};
        return 0;
    }
    if (!strcmp(name, "local")) {
        /* Above the field at (0.3, 0.62) of its extent, 0.15 of the side above
         * the highest point, radius 1.5 texels. */
        float zmax = f->z[0];
        for (int k = 1; k < f->width * f->height; ++k)
            zmax = f->z[k] > zmax ? f->z[k] : zmax;
        const double side = (f->width - 1) * f->dx;
        l->n_local = 1;
        l->local[0] = (hfs_local_light){
            .pos = {0.3 * side, 0.62 * side, zmax * f->zscale + 0.15 * side},
            .radius = 1.5 * f->dx,
            .radiance = {60.0f, 55.0f, 45.0f}};
        return 0;
    }
    fprintf(stderr, "unknown lighting '%s' (env|env_rotated|key_a|key_b|key_c|key_d|local)\n", name);
    return -1;
}

/* ---- bounds --------------------------------------------------------------------- */

/* Bounds on SPEC's metrics of |cpu - truth| / the largest unshadowed value:
 * mean, rmse, p99, max.  Each is ~2x the measured value written under it
 * (mean, rmse, p99, max; RelWithDebInfo, and the same in every build: both
 * backends are deterministic for any thread count), rounded up, with a floor
 * of 1e-4 where the error is at rounding level (the sun casts no shadow on
 * the cliff from there).  0: not checked, because 2x the measurement is 1 or
 * more and no error can exceed 1 (both backends lie in [0, unshadowed]): a
 * sun's hard shadow edge, misplaced by a texel by the pyramid's prefiltering
 * at the default quality, makes errors of ~1 at a few texels.  The mean and
 * rmse carry the check there. */
typedef struct bound {
    const char *lighting, *scene;
    double mean, rmse, p99, max;
} bound;

static const bound bounds[] = {
    {"env", "cones", 8.6e-3, 1.1e-2, 2.9e-2, 3.7e-2},
     /* measured 4.30e-3, 5.37e-3, 1.41e-2, 1.83e-2 */
    {"env", "fractal", 2.5e-2, 3.7e-2, 1.4e-1, 2.6e-1},
     /* measured 1.24e-2, 1.83e-2, 6.90e-2, 1.29e-1 */
    {"env", "dem", 1.4e-2, 1.8e-2, 5.3e-2, 6.9e-2},
     /* measured 6.67e-3, 8.68e-3, 2.65e-2, 3.43e-2 */
    {"env", "cliff", 2.6e-2, 4.0e-2, 1.2e-1, 2.0e-1},
     /* measured 1.30e-2, 1.96e-2, 5.85e-2, 9.77e-2 */
    {"env_rotated", "cones", 8.5e-3, 1.1e-2, 2.8e-2, 3.3e-2},
     /* measured 4.21e-3, 5.28e-3, 1.38e-2, 1.65e-2 */
    {"env_rotated", "fractal", 2.4e-2, 3.4e-2, 1.2e-1, 2.5e-1},
     /* measured 1.18e-2, 1.70e-2, 5.69e-2, 1.24e-1 */
    {"env_rotated", "dem", 1.3e-2, 1.6e-2, 4.3e-2, 6.8e-2},
     /* measured 6.30e-3, 7.92e-3, 2.13e-2, 3.40e-2 */
    {"env_rotated", "cliff", 2.0e-2, 3.1e-2, 1.1e-1, 1.5e-1},
     /* measured 1.00e-2, 1.53e-2, 5.06e-2, 7.26e-2 */
    {"key_a", "cones", 2.1e-2, 9.4e-2, 4.7e-1, 0},
     /* measured 1.04e-2, 4.66e-2, 2.34e-1, 6.40e-1 */
    {"key_a", "fractal", 7.2e-2, 2.6e-1, 0, 0},
     /* measured 3.56e-2, 1.30e-1, 6.52e-1, 9.37e-1 */
    {"key_a", "dem", 1.6e-2, 1.1e-1, 5.8e-1, 0},
     /* measured 7.74e-3, 5.13e-2, 2.88e-1, 8.06e-1 */
    {"key_a", "cliff", 1.6e-2, 1.5e-1, 6.0e-1, 0},
     /* measured 7.85e-3, 7.47e-2, 3.00e-1, 1.00 */
    {"key_b", "cones", 8.6e-3, 5.6e-2, 3.1e-1, 0},
     /* measured 4.29e-3, 2.79e-2, 1.52e-1, 6.00e-1 */
    {"key_b", "fractal", 5.8e-2, 2.3e-1, 0, 0},
     /* measured 2.89e-2, 1.11e-1, 6.25e-1, 9.93e-1 */
    {"key_b", "dem", 2.1e-2, 1.2e-1, 5.5e-1, 0},
     /* measured 1.05e-2, 5.76e-2, 2.71e-1, 8.73e-1 */
    {"key_b", "cliff", 1.0e-4, 1.0e-4, 1.0e-4, 1.0e-4},
     /* measured 7.77e-7, 9.81e-7, 2.58e-6, 4.28e-6 */
    {"key_c", "cones", 2.2e-2, 1.2e-1, 4.9e-1, 0},
     /* measured 1.07e-2, 5.69e-2, 2.44e-1, 9.07e-1 */
    {"key_c", "fractal", 5.0e-2, 2.2e-1, 0, 0},
     /* measured 2.49e-2, 1.08e-1, 5.85e-1, 9.52e-1 */
    {"key_c", "dem", 6.2e-2, 2.7e-1, 0, 0},
     /* measured 3.10e-2, 1.34e-1, 7.48e-1, 9.71e-1 */
    {"key_c", "cliff", 1.0e-4, 1.0e-4, 1.0e-4, 1.0e-4},
     /* measured 1.16e-8, 2.01e-8, 6.02e-8, 2.41e-7 */
    {"key_d", "cones", 9.1e-3, 2.5e-2, 1.1e-1, 2.9e-1},
     /* measured 4.52e-3, 1.23e-2, 5.26e-2, 1.44e-1 */
    {"key_d", "fractal", 2.9e-2, 7.5e-2, 3.3e-1, 6.8e-1},
     /* measured 1.44e-2, 3.72e-2, 1.64e-1, 3.38e-1 */
    {"key_d", "dem", 3.1e-2, 7.0e-2, 2.9e-1, 6.6e-1},
     /* measured 1.51e-2, 3.48e-2, 1.44e-1, 3.28e-1 */
    {"key_d", "cliff", 9.8e-3, 4.5e-2, 2.0e-1, 3.8e-1},
     /* measured 4.89e-3, 1.83e-2, 9.73e-2, 1.86e-1; 7.69e-3, 3.18e-2,
      * 1.49e-1 at d8d97c1; 9.65e-3, 3.72e-2, 1.74e-1, 3.17e-1 with the gap
      * search (issue 36), rmse bound 1.2x that.  The gap search's horizons
      * are exact at every crossing: the small suns a-c fell 1.1-4x (key_a
      * fractal 6.67e-3 -> 1.69e-3, key_c dem 5.66e-3 -> 1.40e-3), the broad
      * disk d rose 7-25% on every scene (`build/tests/test_cpu_truth key_d
      * SCENE` in both builds): its partial swath of 3 samples renders it
      * darker than the truth on average, and higher horizons add to that
      * (more samples across the disk, --nphi-key, shrink it).  The broad
      * disk's bias is left for later. */
    {"local", "cones", 1.2e-3, 7.6e-3, 3.8e-2, 1.4e-1},
     /* measured 5.75e-4, 3.76e-3, 1.87e-2, 6.90e-2 */
    {"local", "fractal", 5.3e-3, 2.9e-2, 1.3e-1, 4.7e-1},
     /* measured 2.65e-3, 1.41e-2, 6.03e-2, 2.32e-1 */
    {"local", "dem", 4.6e-4, 2.1e-3, 8.8e-3, 3.4e-2},
     /* measured 2.28e-4, 1.01e-3, 4.38e-3, 1.66e-2 */
    {"local", "cliff", 2.1e-4, 6.3e-3, 1.0e-4, 2.6e-1},
     /* measured 1.03e-4, 3.13e-3, 6.13e-6, 1.28e-1 */
};

/* ---- rendering --------------------------------------------------------------------- */

static long nonfinite(const hfs_image *img)
{
    long n = 0;
    for (size_t k = 0; k < (size_t)img->width * img->height * 3; ++k)
        n += !isfinite(img->rgb[k]);
    return n;
}

static int render(hfs_backend backend, const hfs_field *f, const hfs_lighting *l,
                  const hfs_quality *q, hfs_image *out)
{
    hfs_renderer_desc desc = {.backend = backend};
    hfs_renderer *r = NULL;
    hfs_error err = {{0}};
    int rc = hfs_image_alloc(out, f->width, f->height, &err);
    if (rc == HFS_OK)
        rc = hfs_renderer_create(&desc, &r, &err);
    if (rc == HFS_OK)
        rc = hfs_renderer_render(r, f, l, q, out, NULL, NULL, &err);
    CHECK(rc == HFS_OK, "%s render: %s", backend == HFS_BACKEND_CPU ? "cpu" : "truth", err.msg);
    hfs_renderer_destroy(r);
    return rc;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: %s LIGHTING SCENE\n", argv[0]);
        return 2;
    }
    const char *lname = argv[1], *sname = argv[2];
    const bound *b = NULL;
    for (size_t i = 0; i < sizeof bounds / sizeof bounds[0]; ++i)
        if (!strcmp(bounds[i].lighting, lname) && !strcmp(bounds[i].scene, sname))
            b = &bounds[i];
    float *z = malloc(N * N * sizeof *z);
    hfs_field f;
    hfs_lighting l;
    if (!z || !b || make_scene(sname, z, &f) || make_lighting(lname, &f, &l)) {
        fprintf(stderr, "%s %s: no such case\n", lname, sname);
        free(z);
        return 2;
    }

    hfs_quality q_cpu, q_truth;
    hfs_quality_defaults(&q_cpu);
    q_cpu.subsample = 1; /* the full-resolution reference (cpu_grid.h: 2, 4) */
    hfs_quality_defaults(&q_truth);
    q_truth.truth_azimuths = 720;
    q_truth.truth_elev_order = 16;
    q_truth.truth_light_samples = 1024;

    hfs_image cpu = {0}, tru = {0}, unsh = {0};
    hfs_error err = {{0}};
    if (render(HFS_BACKEND_CPU, &f, &l, &q_cpu, &cpu) == HFS_OK &&
        render(HFS_BACKEND_TRUTH, &f, &l, &q_truth, &tru) == HFS_OK) {
        int rc = hfs_image_alloc(&unsh, N, N, &err);
        if (rc == HFS_OK)
            rc = hfs_render_unshadowed(&f, &l, &q_cpu, &unsh, &err);
        CHECK(rc == HFS_OK, "unshadowed: %s", err.msg);
        const double norm = hfs_image_max(&unsh);
        CHECK(norm > 0.0 && isfinite(norm), "largest unshadowed value %g", norm);
        hfs_metrics m = {0};
        rc = hfs_compare_images(&cpu, &tru, norm, &m, &err);
        CHECK(rc == HFS_OK, "compare: %s", err.msg);
        const long bad_truth = nonfinite(&tru);
        printf("%s %s: |cpu - truth| / %.4g: mean %.2e rmse %.2e p99 %.2e max %.2e "
               "(bounds %.1e %.1e %.1e %.1e), non-finite cpu %ld truth %ld\n",
               lname, sname, norm, m.mean_abs, m.rmse, m.p99_abs, m.max_abs, b->mean, b->rmse,
               b->p99, b->max, m.nonfinite, bad_truth);
        CHECK(m.nonfinite == 0 && bad_truth == 0, "%s %s: non-finite outputs: cpu %ld, truth %ld",
              lname, sname, m.nonfinite, bad_truth);
        CHECK(!b->mean || m.mean_abs <= b->mean, "%s %s: mean error %.3e > bound %.1e", lname, sname,
              m.mean_abs, b->mean);
        CHECK(!b->rmse || m.rmse <= b->rmse, "%s %s: rmse %.3e > bound %.1e", lname, sname, m.rmse,
              b->rmse);
        CHECK(!b->p99 || m.p99_abs <= b->p99, "%s %s: p99 error %.3e > bound %.1e", lname, sname, m.p99_abs,
              b->p99);
        CHECK(!b->max || m.max_abs <= b->max, "%s %s: max error %.3e > bound %.1e", lname, sname, m.max_abs,
              b->max);
    }
    hfs_image_free(&cpu);
    hfs_image_free(&tru);
    hfs_image_free(&unsh);
    free(z);
    if (failures) {
        fprintf(stderr, "test_cpu_truth %s %s: %d check(s) failed\n", lname, sname, failures);
        return 1;
    }
    printf("test_cpu_truth %s %s: all checks passed\n", lname, sname);
    return 0;
}
