/*
 * test_camera_env_gl.c — a sky camera's lighting on the kept GLES renderer
 * (docs/CAPTURE.md "In the kiosk"): each new frame changes the lighting
 * only, so the frame planner reruns the lighting's passes and nothing of
 * the terrain (hfs_renderer_frame_report):
 *   - the sun moved (the tracked key light's direction) and the residual
 *     SH changed: the key light's passes ("key 0", "factor"), "shade",
 *     "readback"; never "terrain", "env" or "transfer";
 *   - the SH alone changed (same light): "shade" and "readback" only;
 *   - every pixel finite.
 * 77 without a GLES context.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "camera_sky.h"
#include "capture_synth_sky.h"
#include "check.h"
#include "gl_test.h"

#define W 64
#define H 48

static void lighting_of(const hfs_camsky_out *o, hfs_lighting *l)
{
    hfs_lighting_defaults(l);
    l->has_env = 1;
    memcpy(l->env_sh, o->sh, sizeof l->env_sh);
    l->n_key = o->n_keys;
    memcpy(l->key, o->keys, sizeof o->keys[0] * (size_t)o->n_keys);
}

/* The passes the last frame ran, space-separated, into ran. */
static void ran_passes(const hfs_renderer *r, char *ran, size_t size)
{
    hfs_frame_report rep;
    hfs_renderer_frame_report(r, &rep);
    ran[0] = 0;
    for (int i = 0; i < rep.n_steps; ++i)
        if (rep.step[i].ran)
            snprintf(ran + strlen(ran), size - strlen(ran), "%s ", rep.step[i].pass);
}

static int render(hfs_renderer *r, const hfs_field *f, const hfs_lighting *l, hfs_image *img)
{
    hfs_quality q;
    hfs_quality_defaults(&q);
    hfs_error err = {""};
    const int rc = hfs_renderer_render(r, f, l, &q, img, NULL, NULL, &err);
    CHECK(rc == HFS_OK, "render: %s", err.msg);
    int bad = 0;
    for (int i = 0; i < img->width * img->height * 3; ++i)
        bad += !isfinite(img->rgb[i]);
    CHECK(!bad, "%d values not finite", bad);
    return rc;
}

int main(void)
{
    hfs_renderer *r = gl_test_gles();
    static float z[W * H];
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i)
            z[j * W + i] = (float)(6.0 * sin(i * 0.2) * cos(j * 0.15));
    const hfs_field f = {.width = W, .height = H, .z = z, .dx = 1.0, .zscale = 1.0};
    hfs_synth_sky_desc d;
    hfs_synth_sky_defaults(&d);
    hfs_camsky *s = NULL;
    hfs_error err = {""};
    CHECK(!hfs_camsky_create(&d.cam, 4, &s, &err), "%s", err.msg);
    uint8_t *yuyv = malloc((size_t)d.width * d.height * 2);
    hfs_image img;
    hfs_image_alloc(&img, W, H, &err);
    hfs_lighting l;
    char ran[400];
    for (int k = 0; k < 8 && s; ++k) {
        hfs_synth_sky_frame(&d, k, yuyv);
        const hfs_capture_frame fr = {.data = yuyv, .bytes = (size_t)d.width * d.height * 2,
                                      .width = d.width, .height = d.height,
                                      .stride = 2 * d.width, .format = HFS_PIX_YUYV,
                                      .t_ns = (int64_t)k * 33333333};
        CHECK(!hfs_camsky_push(s, &fr, &err), "frame %d: %s", k, err.msg);
        const hfs_camsky_out *o = hfs_camsky_get(s);
        lighting_of(o, &l);
        render(r, &f, &l, &img);
        ran_passes(r, ran, sizeof ran);
        printf("frame %d: %d light(s), ran: %s\n", k, o->n_keys, ran);
        if (k < 4)
            continue;
        /* The sun moves every frame: its passes and the shading, never
         * the terrain's, the environment's visibility or its transfer. */
        CHECK(o->n_keys == 1 && strstr(ran, "key 0 ") && strstr(ran, "shade ") &&
                  !strstr(ran, "terrain") && !strstr(ran, "env ") && !strstr(ran, "transfer"),
              "frame %d: ran '%s' (want the key light's passes and the shading only)", k, ran);
    }
    /* The SH alone (the same light where it was): the shading only. */
    l.env_sh[0][0] *= 1.1;
    render(r, &f, &l, &img);
    ran_passes(r, ran, sizeof ran);
    CHECK(!strcmp(ran, "shade readback "), "SH only: ran '%s', want 'shade readback '", ran);
    printf("SH only: ran %s\n", ran);
    hfs_image_free(&img);
    free(yuyv);
    hfs_camsky_destroy(s);
    hfs_renderer_destroy(r);
    printf("test_camera_env_gl: %ld checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
