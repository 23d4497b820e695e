/*
 * consumer.c — a program of someone else's, built against the INSTALLED
 * hfshade (tests/install.sh builds it through pkg-config and through
 * find_package(hfshade)).  Usage: consumer EXPECTED_VERSION
 *   - the version macros, hfs_version() and hfs_version_number() agree with
 *     each other and with EXPECTED_VERSION (CMake's project version);
 *   - the CPU backend renders a 32x32 ridge lit by a low sun: every value
 *     finite, the lit side bright, the ridge's shadow darker than the same
 *     texel unshadowed;
 *   - the GLES backend renders the same scene close to the CPU image, or is
 *     skipped when no GL context can be made (a failure when HFS_REQUIRE_GL=1).
 * Exit 0 when all hold, 1 otherwise (one line per failure).
 */
#include <hfshade.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define N 32

static int failures;

static void check(int ok, const char *what)
{
    if (!ok) {
        printf("consumer: FAIL: %s\n", what);
        failures++;
    }
}

static int render(hfs_backend backend, const hfs_field *f, const hfs_lighting *l,
                  const hfs_quality *q, hfs_image *out, hfs_error *err)
{
    hfs_renderer_desc desc;
    hfs_renderer *r = NULL;
    int rc;

    memset(&desc, 0, sizeof desc);
    desc.backend = backend;
    rc = hfs_renderer_create(&desc, &r, err);
    if (rc != HFS_OK)
        return rc;
    rc = hfs_image_alloc(out, f->width, f->height, err);
    if (rc == HFS_OK)
        rc = hfs_renderer_render(r, f, l, q, out, NULL, NULL, err);
    hfs_renderer_destroy(r);
    return rc;
}

int main(int argc, char **argv)
{
    static float z[N * N];
    hfs_field field = {N, N, z, 1.0, 1.0};
    hfs_lighting lighting;
    hfs_quality quality;
    hfs_image cpu = {0, 0, NULL}, gles = {0, 0, NULL}, flat = {0, 0, NULL};
    hfs_error err;
    char number[32];
    int i, j, rc;

    if (argc != 2) {
        fprintf(stderr, "usage: consumer EXPECTED_VERSION\n");
        return 2;
    }
    printf("consumer: headers %s, library %s\n", HFS_VERSION_STRING, hfs_version());
    check(strcmp(hfs_version(), HFS_VERSION_STRING) == 0, "hfs_version() == HFS_VERSION_STRING");
    check(strcmp(hfs_version(), argv[1]) == 0, "hfs_version() == the CMake project version");
    check(hfs_version_number() == HFS_VERSION_NUMBER, "hfs_version_number() == HFS_VERSION_NUMBER");
    snprintf(number, sizeof number, "%d.%d.%d", HFS_VERSION_MAJOR, HFS_VERSION_MINOR,
             HFS_VERSION_PATCH);
    check(strcmp(number, HFS_VERSION_STRING) == 0, "MAJOR.MINOR.PATCH == HFS_VERSION_STRING");

    /* A ridge along y at x = 12, 8 units high; the sun low in the -x sky
     * (azimuth pi), so the ridge shades the texels at x > 12. */
    for (j = 0; j < N; j++)
        for (i = 0; i < N; i++)
            z[j * N + i] = (float)(8.0 * exp(-0.5 * (i - 12) * (i - 12)));
    hfs_lighting_defaults(&lighting);
    lighting.n_key = 1;
    lighting.key[0].phi = 3.14159265358979;
    lighting.key[0].elev = 0.25;
    lighting.key[0].alpha = 0.02;
    lighting.key[0].radiance[0] = lighting.key[0].radiance[1] = lighting.key[0].radiance[2] = 100.0f;
    hfs_quality_defaults(&quality);

    rc = render(HFS_BACKEND_CPU, &field, &lighting, &quality, &cpu, &err);
    check(rc == HFS_OK, "CPU render");
    if (rc != HFS_OK) {
        printf("consumer: %s\n", err.msg);
        return 1;
    }
    rc = hfs_image_alloc(&flat, N, N, &err);
    if (rc == HFS_OK)
        rc = hfs_render_unshadowed(&field, &lighting, &quality, &flat, &err);
    check(rc == HFS_OK, "unshadowed render");
    if (rc == HFS_OK) {
        long nonfinite = 0;
        int k = (N / 2) * N + 16; /* behind the ridge, on the flat */
        for (i = 0; i < N * N * 3; i++)
            nonfinite += !isfinite(cpu.rgb[i]);
        check(nonfinite == 0, "CPU image finite");
        check(cpu.rgb[(N / 2) * N * 3 + 4 * 3] > 0.0f, "the sun-side flat is lit");
        check(flat.rgb[k * 3] > 0.0f && cpu.rgb[k * 3] < 0.5f * flat.rgb[k * 3],
              "the ridge's shadow is darker than the unshadowed texel");
        printf("consumer: cpu ok (shadowed %.3g of unshadowed %.3g)\n", cpu.rgb[k * 3],
               flat.rgb[k * 3]);
    }

    rc = render(HFS_BACKEND_GLES, &field, &lighting, &quality, &gles, &err);
    if (rc == HFS_E_CONTEXT || rc == HFS_E_UNSUPPORTED) {
        const char *req = getenv("HFS_REQUIRE_GL");
        printf("consumer: gles skipped: %s\n", err.msg);
        check(!(req && strcmp(req, "1") == 0), "a GLES context (HFS_REQUIRE_GL=1)");
    } else {
        hfs_metrics m;
        check(rc == HFS_OK, "GLES render");
        if (rc == HFS_OK &&
            hfs_compare_images(&gles, &cpu, hfs_image_max(&flat), &m, &err) == HFS_OK) {
            printf("consumer: gles vs cpu: mean %.4f max %.4f (of the unshadowed max)\n",
                   m.mean_abs, m.max_abs);
            check(m.nonfinite == 0 && m.mean_abs < 0.02 && m.max_abs < 0.25,
                  "GLES close to CPU (mean < 0.02, max < 0.25)");
        } else {
            printf("consumer: %s\n", err.msg);
        }
    }
    hfs_image_free(&cpu);
    hfs_image_free(&gles);
    hfs_image_free(&flat);
    if (failures == 0)
        printf("consumer: ok\n");
    return failures ? 1 : 0;
}
