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
 * mean, rmse, p99, max.  Each is 1.2x the measured value written under it
 * (mean, rmse, p99, max; RelWithDebInfo, and the same in every build: both
 * backends are deterministic for any thread count), rounded up to two
 * digits, with a floor of 1e-4 where the error is at rounding level (the sun
 * casts no shadow on the cliff from there).  0: not checked, because 1.2x
 * the measurement is 1 or more and no error can exceed 1 (both backends lie
 * in [0, unshadowed]): a sun's hard shadow edge a texel off makes errors of
 * ~1 at a few texels.  The mean and rmse carry the check there.  Re-pinned
 * in issue 36 (session 16) against the exact truth: until then the bounds
 * were 2x measurements of much older builds, 2-30x what the reference now
 * errs. */
typedef struct bound {
    const char *lighting, *scene;
    double mean, rmse, p99, max;
} bound;

static const bound bounds[] = {
    {"env", "cones", 1.8e-03, 2.7e-03, 9.0e-03, 1.8e-02},
     /* measured 1.49e-03, 2.24e-03, 7.47e-03, 1.46e-02 */
    {"env", "fractal", 6.4e-03, 1.2e-02, 4.7e-02, 8.9e-02},
     /* measured 5.27e-03, 9.20e-03, 3.90e-02, 7.38e-02 */
    {"env", "dem", 3.2e-03, 5.4e-03, 2.2e-02, 5.1e-02},
     /* measured 2.61e-03, 4.48e-03, 1.80e-02, 4.17e-02 */
    {"env", "cliff", 4.0e-03, 1.1e-02, 4.9e-02, 8.1e-02},
     /* measured 3.33e-03, 8.47e-03, 4.04e-02, 6.70e-02 */
    {"env_rotated", "cones", 1.8e-03, 2.7e-03, 8.5e-03, 1.3e-02},
     /* measured 1.49e-03, 2.23e-03, 7.08e-03, 1.07e-02 */
    {"env_rotated", "fractal", 6.3e-03, 1.1e-02, 4.3e-02, 9.0e-02},
     /* measured 5.21e-03, 8.77e-03, 3.53e-02, 7.47e-02 */
    {"env_rotated", "dem", 3.1e-03, 5.2e-03, 2.0e-02, 4.7e-02},
     /* measured 2.53e-03, 4.28e-03, 1.62e-02, 3.84e-02 */
    {"env_rotated", "cliff", 3.0e-03, 8.3e-03, 4.2e-02, 6.9e-02},
     /* measured 2.42e-03, 6.88e-03, 3.44e-02, 5.70e-02 */
    {"key_a", "cones", 1.1e-03, 5.6e-03, 2.9e-02, 8.7e-02},
     /* measured 9.04e-04, 4.63e-03, 2.40e-02, 7.21e-02 */
    {"key_a", "fractal", 1.4e-03, 1.1e-02, 4.3e-02, 1.9e-01},
     /* measured 1.12e-03, 8.88e-03, 3.56e-02, 1.56e-01 */
    {"key_a", "dem", 7.5e-04, 7.7e-03, 1.9e-02, 2.8e-01},
     /* measured 6.20e-04, 6.37e-03, 1.56e-02, 2.32e-01 */
    {"key_a", "cliff", 3.4e-03, 4.7e-02, 1.0e-04, 0},
     /* measured 2.82e-03, 3.86e-02, 9.91e-07, 1.00 */
    {"key_b", "cones", 8.8e-04, 4.5e-03, 2.4e-02, 6.4e-02},
     /* measured 7.30e-04, 3.68e-03, 1.95e-02, 5.26e-02 */
    {"key_b", "fractal", 2.9e-03, 1.2e-02, 6.3e-02, 1.7e-01},
     /* measured 2.35e-03, 9.83e-03, 5.21e-02, 1.38e-01 */
    {"key_b", "dem", 1.3e-03, 5.5e-03, 2.8e-02, 6.8e-02},
     /* measured 1.06e-03, 4.58e-03, 2.29e-02, 5.65e-02 */
    {"key_b", "cliff", 1.0e-04, 1.0e-04, 1.0e-04, 1.0e-04},
     /* measured 7.77e-07, 9.81e-07, 2.58e-06, 4.28e-06 */
    {"key_c", "cones", 4.8e-04, 5.0e-03, 1.2e-02, 1.5e-01},
     /* measured 3.94e-04, 4.11e-03, 9.26e-03, 1.19e-01 */
    {"key_c", "fractal", 2.0e-03, 1.8e-02, 5.7e-02, 4.5e-01},
     /* measured 1.59e-03, 1.46e-02, 4.71e-02, 3.69e-01 */
    {"key_c", "dem", 1.7e-03, 2.7e-02, 3.6e-02, 0},
     /* measured 1.40e-03, 2.24e-02, 2.93e-02, 8.51e-01 */
    {"key_c", "cliff", 1.0e-04, 1.0e-04, 1.0e-04, 1.0e-04},
     /* measured 1.16e-08, 2.01e-08, 6.02e-08, 2.41e-07 */
    {"key_d", "cones", 9.3e-03, 1.9e-02, 5.9e-02, 7.2e-02},
     /* measured 7.72e-03, 1.53e-02, 4.84e-02, 5.95e-02 */
    {"key_d", "fractal", 1.1e-02, 2.4e-02, 8.5e-02, 3.0e-01},
     /* measured 8.57e-03, 1.97e-02, 7.07e-02, 2.48e-01 */
    {"key_d", "dem", 1.0e-02, 2.0e-02, 6.7e-02, 2.0e-01},
     /* measured 8.29e-03, 1.64e-02, 5.52e-02, 1.62e-01 */
    {"key_d", "cliff", 1.2e-02, 4.5e-02, 2.1e-01, 3.9e-01},
     /* measured 9.65e-03, 3.72e-02, 1.74e-01, 3.17e-01;
      * the broad disk's partial swath of 3 samples renders it darker than
      * the truth on average (more samples across the disk, --nphi-key,
      * shrink it): left for later */
    {"local", "cones", 6.8e-04, 4.4e-03, 2.2e-02, 7.4e-02},
     /* measured 5.62e-04, 3.61e-03, 1.80e-02, 6.14e-02 */
    {"local", "fractal", 3.2e-03, 1.7e-02, 7.3e-02, 2.8e-01},
     /* measured 2.65e-03, 1.41e-02, 6.03e-02, 2.32e-01 */
    {"local", "dem", 2.7e-04, 1.2e-03, 5.4e-03, 1.8e-02},
     /* measured 2.21e-04, 9.84e-04, 4.47e-03, 1.48e-02 */
    {"local", "cliff", 1.3e-04, 3.8e-03, 1.0e-04, 1.6e-01},
     /* measured 1.03e-04, 3.13e-03, 6.13e-06, 1.28e-01 */
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
