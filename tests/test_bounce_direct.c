/*
 * test_bounce_direct.c — turning bounces on never lowers a texel (issue
 * 36): a frame with bounces keeps the split horizons of the frame without
 * them (split_horizon.h hfs_split_make), its bounce bands clipped to each
 * sub-horizon (hfs_split_band), so its direct part is that frame's and the
 * bounces (>= 0) only add.  64^2 fields under a uniform sky, albedo 0.8,
 * one bounce: the fractal at relief 0.25 (hfgen fractal) at subsample 2
 * and 4,
 * city blocks (hfgen city) at subsample 2.
 *   cpu   (argv[1] "cpu") the bounce frame >= the direct frame at every
 *         texel, and = the direct frame + hfs_cpu_bounces of it bit for
 *         bit (its direct part unchanged)
 *   gles  (argv[1] "gles"; skipped with 77 without a context) the bounce
 *         frame >= the direct frame at every texel, fp16 frame
 * Before (one horizon per direction in bounce frames), measured with this
 * test: the bounce frame lower than the direct one at 12 of the CPU's RGB
 * values (by up to 3.5e-4; 0.8 is the unshadowed value) and 15 of GLES's
 * (3.1e-4) on the fractal at subsample 4, GLES 6 (1.7e-4) at subsample 2,
 * and on the city 90 (1.3e-5) and 153 (4.5e-5); the CPU's direct part
 * changed in all three.
 */
#include "cpu_bounce.h"
#include "gl_test.h"
#include "terrain_gen.h"

#include <math.h>
#include <string.h>

#include "check.h"

#define N 64

typedef struct bcase {
    const char *scene;
    int subsample;
} bcase;

static const bcase cases[] = {{"fractal", 4}, {"fractal", 2}, {"city", 2}};

static hfs_lighting sky(void)
{
    hfs_lighting l;
    hfs_lighting_defaults(&l);
    l.has_env = 1;
    for (int c = 0; c < 3; ++c)
        l.env_sh[c][0] = sqrt(4.0 * 3.14159265358979323846); /* radiance 1 */
    l.albedo = 0.8;
    return l;
}

/* The case's frames without and with one bounce on r; on the CPU also the
 * direct frame plus its bounce by hfs_cpu_bounces, which the bounce frame
 * must equal bit for bit. */
static void check_case(hfs_renderer *r, const bcase *c, int cpu)
{
    float *z = malloc((size_t)N * N * sizeof *z);
    if (!z || hfs_terrain_make(c->scene, z, N, N, 1, 0.25)) {
        CHECK(0, "scene %s", c->scene);
        free(z);
        return;
    }
    const hfs_field f = {N, N, z, 1.0, 1.0};
    hfs_lighting l = sky();
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.subsample = c->subsample;
    hfs_image img[2] = {{0}}; /* without and with the bounce */
    hfs_error err = {""};
    int rc = 0;
    for (int k = 0; k < 2 && !rc; ++k) {
        l.bounces = k;
        rc = hfs_image_alloc(&img[k], N, N, &err) ||
             hfs_renderer_render(r, &f, &l, &q, &img[k], NULL, NULL, &err);
        CHECK(!rc, "render (%d bounces): %s", k, err.msg);
    }
    const hfs_image a = img[0], b = img[1];
    const size_t n = (size_t)N * N * 3;
    double worst = 0.0, gain = 0.0;
    int darker = 0;
    for (size_t p = 0; p < n && !rc; ++p) {
        const double d = (double)b.rgb[p] - a.rgb[p];
        worst = fmin(worst, d), gain = fmax(gain, d);
        darker += d < 0.0;
    }
    CHECK(!rc && darker == 0 && gain > 0.0,
          "%s, subsample %d: the bounce frame darker than the direct one at %d values "
          "(by up to %.3e), largest gain %.3e", c->scene, c->subsample, darker, -worst, gain);
    int same = 1;
    if (cpu && !rc) {
        rc = hfs_cpu_bounces(&f, &l, &q, 1, a.rgb, NULL, NULL, &err);
        CHECK(rc == HFS_OK, "hfs_cpu_bounces: %s", err.msg);
        same = !rc && !memcmp(a.rgb, b.rgb, n * sizeof *a.rgb);
        CHECK(same, "%s, subsample %d: the bounce frame is not the direct frame + its bounce",
              c->scene, c->subsample);
    }
    printf("%s, subsample %d: %d values lower, by up to %.2e, largest gain "
           "%.3f%s\n", c->scene, c->subsample, darker, worst < 0.0 ? -worst : 0.0, gain,
           cpu ? (same ? "; direct part bit for bit" : "; direct part CHANGED") : "");
    hfs_image_free(&img[0]), hfs_image_free(&img[1]);
    free(z);
}

int main(int argc, char **argv)
{
    const int cpu = argc < 2 || strcmp(argv[1], "gles") != 0;
    hfs_renderer *r = NULL;
    if (cpu) {
        const hfs_renderer_desc d = {.backend = HFS_BACKEND_CPU};
        hfs_error err = {""};
        if (hfs_renderer_create(&d, &r, &err) != HFS_OK) {
            printf("FAIL: cpu renderer: %s\n", err.msg);
            return 1;
        }
    } else {
        r = gl_test_gles();
    }
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k)
        check_case(r, &cases[k], cpu);
    hfs_renderer_destroy(r);
    printf("test_bounce_direct (%s): %s\n", cpu ? "cpu" : "gles", failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
