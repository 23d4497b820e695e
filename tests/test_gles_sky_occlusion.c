/*
 * test_gles_sky_occlusion.c — the SH sky's occluded light kept as one
 * target per texel (pass_env_sky_occlusion.c) until the sky turns, then
 * the transfer (gles_frame.c env_fold), on GLES:
 *   - a renderer's first frames under a still sky run "sky occlusion", not
 *     "transfer", and hold an RGBA and an RG target a texel instead of 4
 *     RGBA ones;
 *   - the first turn (or re-tint) runs the transfer, later turns only the
 *     shading and the read-back;
 *   - the turned renderer's image equals, bit for bit, a new renderer's
 *     image of the same scene (which folds): the two modes shade the same
 *     values (hfs_env_occ);
 *   - what reads all of T keeps it: a glossy lobe, bounces capped at the
 *     grid's horizons;
 * at subsample 2 (fp16) and 1 (fp32), on a non-square field with dx != 1.
 * No GLES context of any kind: exit 77 (gl_test.h).
 */
#include "hfshade.h"
#include "terrain_gen.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "gl_test.h"

#define W 40
#define H 28

static float z[W * H];
static const hfs_field field = {.width = W, .height = H, .z = z, .dx = 0.7, .zscale = 1.3};

static void sky(hfs_lighting *l, double rotate)
{
    hfs_lighting_defaults(l);
    l->has_env = 1;
    l->albedo = 0.8;
    for (int c = 0; c < 3; ++c) { /* tinted, brighter towards +x and up */
        l->env_sh[c][0] = 2.0 + 0.2 * c;
        l->env_sh[c][1] = 0.2;
        l->env_sh[c][2] = 0.9;
        l->env_sh[c][3] = 0.5 - 0.1 * c;
        l->env_sh[c][6] = -0.2;
    }
    l->env_rotate = rotate;
    l->n_key = 1;
    l->key[0] = (hfs_key_light){.phi = 0.7, .elev = 0.35, .alpha = 0.03, .radiance = {9, 9, 8}};
}

/* Renders into img; the passes that ran into ran, the texture bytes. */
static size_t render(hfs_renderer *r, const hfs_lighting *l, const hfs_quality *q,
                     hfs_image *img, char *ran, size_t n)
{
    hfs_error err;
    if (hfs_renderer_render(r, &field, l, q, img, NULL, NULL, &err))
        gl_test_unavailable("render", &err);
    gl_test_ran(r, ran, n);
    hfs_timings t;
    hfs_renderer_timings(r, &t);
    return t.texture_bytes;
}

static int has(const char *ran, const char *pass)
{
    char want[64];
    snprintf(want, sizeof want, "%s ", pass);
    for (const char *p = ran; (p = strstr(p, want)); ++p)
        if (p == ran || p[-1] == ' ')
            return 1;
    return 0;
}

static void one_setting(int sub, hfs_precision prec)
{
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.subsample = sub;
    q.precision = prec;
    const char *name = prec == HFS_PRECISION_FP32 ? "fp32" : "fp16";
    const size_t rgba = prec == HFS_PRECISION_FP32 ? 16 : 8;
    hfs_lighting l;
    hfs_image a, b;
    hfs_error err;
    if (hfs_image_alloc(&a, W, H, &err) || hfs_image_alloc(&b, W, H, &err))
        exit(1);
    char ran[512];
    hfs_renderer *kept = gl_test_gles(), *fresh = gl_test_gles();
    hfs_renderer_set_timing(kept, 1);
    hfs_renderer_set_timing(fresh, 1);

    sky(&l, 0.0);
    const size_t folded = render(kept, &l, &q, &a, ran, sizeof ran);
    CHECK(has(ran, "sky occlusion") && !has(ran, "transfer"),
          "sub %d %s: a still sky's first frame ran '%s'", sub, name, ran);
    sky(&l, 0.0); /* the same sky again: still folded, nothing runs */
    render(kept, &l, &q, &a, ran, sizeof ran);
    CHECK(!*ran, "sub %d %s: an unchanged frame ran '%s'", sub, name, ran);

    sky(&l, 1.1); /* the first turn: the transfer from now on */
    const size_t kept_t = render(kept, &l, &q, &a, ran, sizeof ran);
    CHECK(has(ran, "transfer") && !has(ran, "sky occlusion"),
          "sub %d %s: the first turn ran '%s'", sub, name, ran);
    /* 4 RGBA targets instead of an RGBA and an RG one, and the grid's
     * horizons, which the sky occlusion's renderer frees after its frames
     * and a turned one keeps (gles_frame.c grid_release; their bytes are
     * pinned in test_gles_render.c mode_memory) */
    const size_t more = (size_t)W * H * (4 * rgba - rgba - rgba / 2);
    CHECK(kept_t > folded + more,
          "sub %d %s: the transfer holds %zu bytes more than the sky occlusion, want %zu and "
          "the grid's horizons", sub, name, kept_t - folded, more);
    const size_t fresh_b = render(fresh, &l, &q, &b, ran, sizeof ran);
    CHECK(has(ran, "sky occlusion"), "sub %d %s: a new renderer ran '%s'", sub, name, ran);
    CHECK(fresh_b == folded, "sub %d %s: %zu texture bytes, the first frame %zu", sub, name,
          fresh_b, folded);
    CHECK(!memcmp(a.rgb, b.rgb, sizeof(float) * 3 * W * H),
          "sub %d %s: the turned renderer's image differs from a new one's", sub, name);

    sky(&l, 2.3); /* a later turn: the shading only */
    render(kept, &l, &q, &a, ran, sizeof ran);
    CHECK(!strcmp(ran, "shade readback "), "sub %d %s: a second turn ran '%s'", sub, name, ran);
    for (int c = 0; c < 3; ++c) /* a re-tint too */
        l.env_sh[c][0] *= 1.25;
    render(kept, &l, &q, &a, ran, sizeof ran);
    CHECK(!strcmp(ran, "shade readback "), "sub %d %s: a re-tint ran '%s'", sub, name, ran);
    render(fresh, &l, &q, &b, ran, sizeof ran); /* the fresh one's first change */
    CHECK(!memcmp(a.rgb, b.rgb, sizeof(float) * 3 * W * H),
          "sub %d %s: re-tinted, the two renderers differ", sub, name);

    hfs_renderer_destroy(kept);
    hfs_renderer_destroy(fresh);
    hfs_image_free(&a);
    hfs_image_free(&b);
}

/* What reads all of T keeps the transfer from the first frame. */
static void readers_of_t(void)
{
    hfs_quality q;
    hfs_quality_defaults(&q);
    hfs_lighting l;
    hfs_image a;
    hfs_error err;
    if (hfs_image_alloc(&a, W, H, &err))
        exit(1);
    char ran[512];
    hfs_renderer *r = gl_test_gles();
    sky(&l, 0.4);
    l.specular = 0.15; /* a glossy lobe: its visible part is T's */
    l.gloss = 20.0;
    render(r, &l, &q, &a, ran, sizeof ran);
    CHECK(has(ran, "transfer") && !has(ran, "sky occlusion"), "glossy: ran '%s'", ran);
    hfs_renderer_destroy(r);
    r = gl_test_gles();
    sky(&l, 0.4);
    l.bounces = 1;
    render(r, &l, &q, &a, ran, sizeof ran);
    /* on the slice path with a sky the bounces' bands stop at the grid's
     * horizons, each texel's occluded part (lights.c hfs_bounce_capped) */
    CHECK(has(ran, "transfer") && !has(ran, "sky occlusion"), "bounces: ran '%s'", ran);
    hfs_renderer_destroy(r);
    hfs_image_free(&a);
}

int main(void)
{
    if (hfs_terrain_fractal(z, W, H, 7, 1.0))
        return 1;
    for (int i = 0; i < W * H; ++i)
        z[i] *= 9.0f;
    /* The default grid (the occluders in pairs, split horizons) at the
     * product's precision, and the full grid at fp32's (no rounding to
     * fp16 anywhere): each pair of renderers compiles its own programs. */
    one_setting(2, HFS_PRECISION_FP16);
    one_setting(1, HFS_PRECISION_FP32);
    readers_of_t();
    printf("sky occlusion: %ld checks, %s\n", checks, failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
