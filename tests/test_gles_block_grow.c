/*
 * test_gles_block_grow.c — uniform data carried by a texture (block_texture.h:
 * a block larger than ES 3.0's 16 KiB uniform blocks) on a KEPT renderer
 * whose next frame needs more of it (issue 35, "edges of ranges"): under
 * strict limits (the ES 3.0 minimums, whatever the driver offers) frame A
 * puts every such block in a texture, frames B1, B2, B3 each need more
 * rows of one of them (the environment's, the keys', the local lights';
 * the others as in A), so that a block not regrown is named:
 *
 *   block                      A                      B
 *   environment swath          nphi-env 64            nphi-env 96
 *   split horizons' far dirs   64 x 4 sub-directions  96 x 4
 *   key-light swaths, records  1 key, nphi-key 60     4 keys (244 horizon
 *                                                     layers of 256)
 *   local lights               1 light, nphi-local 340  8, nphi-local 700
 *
 * (vec4: an environment or key swath of n samples 19 n + 4, a key record 7
 * more and the records in powers of two, the far directions 18 + 5 n, the
 * local block 50 + 3 nphi; the texture holds 512 vec4 a row.)  With
 * objects in the view, 2 then 12 (each lit on the CPU: the costly part).
 * Subsample 4: the visibility passes loop over these many samples per
 * texel, and the blocks are the point.  The kept renderer must grow each
 * texture, not write past it (GL_INVALID_VALUE: the frame fails), and
 * render each frame as a fresh renderer does, bit for bit: the image and
 * the view.  No GLES context of any kind: exit 77 (gl_test.h).
 */
#include "gl_test.h"
#include "hfshade.h"
#include "terrain_gen.h"
#include "uniform_blocks.h"
#include "visibility.h"

#include <stdlib.h>
#include <string.h>

#include "check.h"

#define N 24

typedef struct frame {
    hfs_lighting l;
    hfs_quality q;
    hfs_object obj[12];
    int n_obj;
} frame;

/* Frame A (stage 0) and B1..B3: A with the environment's blocks grown,
 * the keys', the local lights' (and more objects). */
static void make_frame(frame *fr, int stage)
{
    hfs_lighting_defaults(&fr->l);
    fr->l.has_env = 1;
    for (int c = 0; c < 3; ++c)
        fr->l.env_sh[c][0] = 2.0, fr->l.env_sh[c][2] = 0.8, fr->l.env_sh[c][3] = 0.3;
    fr->l.n_key = stage == 2 ? 4 : 1;
    for (int i = 0; i < fr->l.n_key; ++i)
        fr->l.key[i] = (hfs_key_light){.phi = 0.5 + 1.5 * i, .elev = 0.3 + 0.1 * i,
                                       .alpha = 0.05, .radiance = {10, 9, 8}};
    fr->l.n_local = stage == 3 ? 8 : 1;
    for (int i = 0; i < fr->l.n_local; ++i)
        fr->l.local[i] = (hfs_local_light){.pos = {3.0 + 2.5 * i, 20.0 - 2.0 * i, 4.0},
                                           .radius = 0.8, .radiance = {6, 6, 6}};
    hfs_quality_defaults(&fr->q);
    fr->q.nphi_env = stage == 1 ? 96 : 64;
    fr->q.far_dirs = 4, fr->q.far_from = 4; /* split horizons: the far part in 24 texels */
    fr->q.nphi_key = 60;
    fr->q.nphi_local = stage == 3 ? 700 : 340;
    fr->q.subsample = 4;
    fr->n_obj = stage == 3 ? 12 : 2;
    for (int i = 0; i < fr->n_obj; ++i)
        fr->obj[i] = (hfs_object){.kind = (hfs_object_kind)(i % 3), .x = 2.0 + (i % 8) * 2.6,
                                  .y = 2.0 + (i / 8) * 4.5, .z = 0.5, .size = {0.8, 0.8, 2.0},
                                  .albedo = {0.8f, 0.6f, 0.4f}};
}

/* The premise, from the blocks' sizes (the key swaths as the renderer
 * makes them): A's blocks exceed 16 KiB (so they are textures), B's need
 * more rows. */
static void check_premise(const frame *a, const frame *b1, const frame *b2)
{
    const size_t max4 = 16384 / 16;
    const size_t env_a = hfs_gles_swath_vec4(a->q.nphi_env);
    const size_t env_b = hfs_gles_swath_vec4(b1->q.nphi_env);
    size_t key[2] = {0, 0}, swath_a = 0;
    for (int k = 0; k < 2; ++k) {
        const frame *fr = k ? b2 : a;
        for (int i = 0; i < fr->l.n_key; ++i) {
            const hfs_key_light *kl = &fr->l.key[i];
            hfs_swath s;
            hfs_swath_key(kl->phi, kl->elev, kl->alpha, fr->q.nphi_key, fr->q.nphi_env, &s);
            key[k] += hfs_gles_key_vec4(s.n);
            swath_a = k ? swath_a : hfs_gles_swath_vec4(s.n);
        }
    }
    const size_t key_a = key[0], key_b = key[1];
    CHECK(swath_a > max4, "key swath: %zu vec4, fits a block", swath_a);
    CHECK(env_a > max4 && (2 * env_b + 1023) / 1024 > (2 * env_a + 1023) / 1024,
          "environment swath: %zu then %zu vec4", env_a, env_b);
    CHECK(key_a > max4 && (2 * key_b + 1023) / 1024 > (2 * key_a + 1023) / 1024,
          "key records: %zu then %zu vec4", key_a, key_b);
}

/* The image and the view of fr on r. */
static int render(hfs_renderer *r, const hfs_field *f, const frame *fr, hfs_image *img,
                  hfs_image *view, const char *what)
{
    hfs_error err = {""};
    hfs_view v;
    hfs_view_defaults(&v, f);
    v.mode = HFS_VIEW_PERSPECTIVE;
    v.azimuth = 0.6, v.elevation = 0.5, v.fov = 0.9;
    v.width = 32, v.height = 24;
    v.objects = fr->obj, v.n_objects = fr->n_obj;
    hfs_view_frame(&v, f);
    int rc = hfs_renderer_render(r, f, &fr->l, &fr->q, img, NULL, NULL, &err);
    if (!rc)
        rc = hfs_renderer_render_view(r, f, &fr->l, &fr->q, &v, NULL, view, &err);
    CHECK(!rc, "%s: %s", what, err.msg);
    printf("%-40s %s\n", what, rc ? err.msg : "ok");
    return rc;
}

static hfs_renderer *strict(void)
{
    const hfs_renderer_desc d = {.backend = HFS_BACKEND_GLES, .gl_strict_limits = 1};
    return gl_test_renderer(&d);
}

#define STAGES 4

int main(void)
{
    float z[N * N];
    hfs_terrain_cones(z, N, N);
    for (int i = 0; i < N * N; ++i)
        z[i] *= 3.0f;
    const hfs_field f = {.width = N, .height = N, .z = z, .dx = 1.0, .zscale = 1.0};
    frame fr[STAGES];
    for (int b = 0; b < STAGES; ++b)
        make_frame(&fr[b], b);
    check_premise(&fr[0], &fr[1], &fr[2]);
    hfs_error err = {""};
    hfs_image img[2], view[2]; /* kept, fresh */
    for (int k = 0; k < 2; ++k)
        if (hfs_image_alloc(&img[k], N, N, &err) || hfs_image_alloc(&view[k], 32, 24, &err))
            return 1;
    hfs_renderer *kept = strict();
    const char *name[STAGES] = {"A (textures)", "B1 (environment grown)", "B2 (keys grown)",
                                "B3 (local lights grown)"};
    float first[N * N * 3];
    for (int b = 0; b < STAGES; ++b) {
        char what[64];
        snprintf(what, sizeof what, "kept renderer, %s", name[b]);
        render(kept, &f, &fr[b], &img[0], &view[0], what);
        hfs_renderer *fresh = strict();
        snprintf(what, sizeof what, "fresh renderer, %s", name[b]);
        render(fresh, &f, &fr[b], &img[1], &view[1], what);
        hfs_renderer_destroy(fresh);
        CHECK(!memcmp(img[0].rgb, img[1].rgb, sizeof(float) * N * N * 3),
              "%s: the kept renderer's image differs from a fresh one's", name[b]);
        CHECK(!memcmp(view[0].rgb, view[1].rgb, sizeof(float) * 32 * 24 * 3),
              "%s: the kept renderer's view differs from a fresh one's", name[b]);
        if (b == 0)
            memcpy(first, img[1].rgb, sizeof first);
    }
    CHECK(memcmp(first, img[1].rgb, sizeof first), "A and B3 render the same image");
    hfs_renderer_destroy(kept);
    for (int k = 0; k < 2; ++k)
        hfs_image_free(&img[k]), hfs_image_free(&view[k]);
    printf("block grow: %s\n", failures ? "FAILED" : "ok");
    return failures ? 1 : 0;
}
