/*
 * test_env_dirs.c — the environment's directions matched to the grid step
 * (hfshade.h HFS_NPHI_ENV_MATCHED, hfs_quality_env_dirs):
 *   - the rule: the defaults give 12 at subsample 2 and 4, 24 at 1; a set
 *     count is kept; the scene key takes "auto" and refuses 0;
 *   - a frame follows it: with the defaults at subsample 1 the CPU
 *     reference and the GLES path render exactly what an explicit 24 does,
 *     and not what 12 does;
 *   - the GLES planner notices a change of subsample alone: a renderer
 *     that drew the default 2x2 frame first then draws subsample 1 bit for
 *     bit as a fresh renderer does.
 * usage: test_env_dirs [gles]   (without gles: the rule and the CPU only)
 */
#include "check.h"
#include "gl_test.h"
#include "scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define N 40

/* Rough relief, so that the directions' count shows in the light. */
static void make_field(float *z, hfs_field *f)
{
    for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i)
            z[j * N + i] = (float)(3.0 * sin(0.9 * i) * cos(0.7 * j) +
                                   2.0 * exp(-((i - 20) * (i - 20) + (j - 14) * (j - 14)) / 20.0));
    *f = (hfs_field){N, N, z, 1.0, 1.0};
}

static hfs_lighting sky(void)
{
    hfs_lighting l;
    hfs_lighting_defaults(&l);
    l.has_env = 1;
    for (int c = 0; c < 3; ++c) {
        l.env_sh[c][0] = 1.0;
        l.env_sh[c][2] = 0.6; /* brighter towards the zenith */
        l.env_sh[c][3] = 0.2 * (c + 1);
    }
    return l;
}

static void check_rule(void)
{
    hfs_quality q;
    hfs_quality_defaults(&q);
    CHECK(q.nphi_env == HFS_NPHI_ENV_MATCHED, "defaults: nphi_env %d, not matched", q.nphi_env);
    const int want[5] = {0, 24, 12, 0, 12};
    for (int s = 1; s <= 4; s *= 2) {
        q.subsample = s;
        CHECK(hfs_quality_env_dirs(&q) == want[s], "subsample %d: %d directions, want %d", s,
              hfs_quality_env_dirs(&q), want[s]);
    }
    q.nphi_env = 16;
    q.subsample = 1;
    CHECK(hfs_quality_env_dirs(&q) == 16, "a set count is kept at subsample 1");
    for (const char *p = "kiosk"; p; p = !strcmp(p, "kiosk") ? "headless" : NULL) {
        hfs_quality_preset(&q, p);
        q.subsample = 1;
        CHECK(hfs_quality_env_dirs(&q) == 24, "preset %s at subsample 1: %d directions", p,
              hfs_quality_env_dirs(&q));
    }
    hfs_scene s;
    hfs_error err = {""};
    hfs_scene_init(&s);
    s.quality.nphi_env = 9;
    CHECK(hfs_scene_set(&s, HFS_SOURCE_FLAG, "nphi-env", "auto", "test", NULL, &err) == 0 &&
              s.quality.nphi_env == HFS_NPHI_ENV_MATCHED, "nphi-env auto: %s", err.msg);
    CHECK(hfs_scene_set(&s, HFS_SOURCE_FLAG, "nphi-env", "0", "test", NULL, &err) != 0 &&
              strstr(err.msg, "nphi-env"), "nphi-env 0 is no count: '%s'", err.msg);
    hfs_quality_defaults(&q);
    CHECK(hfs_validate_quality(&q, &err) == 0, "matched directions refused: %s", err.msg);
}

static int render(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l, int sub,
                  int nphi, hfs_image *out)
{
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.subsample = sub;
    q.nphi_env = nphi;
    q.threads = 1;
    hfs_error err = {""};
    const int rc = hfs_image_alloc(out, f->width, f->height, &err) ||
                   hfs_renderer_render(r, f, l, &q, out, NULL, NULL, &err);
    CHECK(rc == 0, "render subsample %d nphi-env %d: %s", sub, nphi, err.msg);
    return rc;
}

static int same(const hfs_image *a, const hfs_image *b)
{
    return !memcmp(a->rgb, b->rgb, (size_t)a->width * (size_t)a->height * 3 * sizeof(float));
}

/* Defaults at subsample 1 (on rp, after the default 2x2 frame where
 * `planned`) == explicit 24 != explicit 12 (on rf, a fresh renderer for
 * GLES: planned == from scratch). */
static void check_frames(hfs_renderer *rp, hfs_renderer *rf, const char *name, int planned)
{
    float z[N * N];
    hfs_field f;
    make_field(z, &f);
    const hfs_lighting l = sky();
    hfs_image first = {0}, dflt = {0}, d24 = {0}, d12 = {0};
    if (!(planned && render(rp, &f, &l, 2, HFS_NPHI_ENV_MATCHED, &first)) &&
        !render(rp, &f, &l, 1, HFS_NPHI_ENV_MATCHED, &dflt) && !render(rf, &f, &l, 1, 24, &d24) &&
        !render(rf, &f, &l, 1, 12, &d12)) {
        CHECK(same(&dflt, &d24), "%s: default at subsample 1 is not 24 directions", name);
        CHECK(!same(&dflt, &d12), "%s: default at subsample 1 is 12 directions", name);
    }
    hfs_image_free(&first);
    hfs_image_free(&dflt);
    hfs_image_free(&d24);
    hfs_image_free(&d12);
}

int main(int argc, char **argv)
{
    const int gles = argc > 1 && !strcmp(argv[1], "gles");
    if (!gles) {
        check_rule();
        hfs_renderer_desc d = {.backend = HFS_BACKEND_CPU};
        hfs_renderer *r = NULL;
        hfs_error err = {""};
        CHECK(hfs_renderer_create(&d, &r, &err) == 0, "cpu renderer: %s", err.msg);
        if (r)
            check_frames(r, r, "cpu", 0);
        hfs_renderer_destroy(r);
    } else {
        hfs_renderer_desc d = {.backend = HFS_BACKEND_GLES};
        hfs_renderer *rp = gl_test_renderer(&d), *rf = gl_test_renderer(&d);
        check_frames(rp, rf, "gles after a 2x2 frame", 1);
        hfs_renderer_destroy(rp);
        hfs_renderer_destroy(rf);
    }
    printf("env directions matched to the grid step (%s): %ld checks, %d failures\n",
           gles ? "gles" : "rule, cpu", checks, failures);
    return failures ? 1 : 0;
}
