/*
 * test_metamorphic.c — relations every backend must keep without an oracle
 * (issue 35, deliverable 1; first part): scaling the world leaves the
 * picture unchanged.  Multiplying dx, zscale (so every height), every local
 * light's position and radius, and every queried point by the same s > 0
 * (GLES also with one bounce of indirect light)
 * changes no angle and no solid angle: the image and the key-light
 * visibility of the points must not move.  Key lights and the sky are
 * directions, untouched.  Bugs that read a world position as a grid
 * position (or the reverse) break it, and dx = 1 hides them.
 *
 * The field is non-square (40 x 28), the scales are s = 2.5 and 0.125 from
 * dx = 0.7, so neither side is 1; the scene is metamorphic.h's (a sky, two
 * key lights, a local light, 24 points).  Bounds are per backend, relative
 * to the frame's maximum: measured 0 (the product keeps this exactly),
 * bound 1e-6.
 *
 *   test_metamorphic cpu | gles SUBSAMPLE   (gles: 77 without a context)
 */
#include "metamorphic.h"

#include <stdlib.h>

#define W 40
#define H 28

static void scale_invariance(hfs_renderer *r, const char *name, int subsample, int bounces)
{
    /* Measured 0 on every backend and setting: bound 1e-6 (the image over
     * its maximum, the points' visible fractions). */
    const mm_setting st = {HFS_PRECISION_FP16, 1, bounces, 1, 1e-6, 1e-6};
    const hfs_quality q = mm_quality(subsample, &st);
    static mm_scene base, scaled;
    mm_result rb, rs;
    mm_scene_make(&base, W, H, 1.0);
    base.l.bounces = bounces; /* the bounce walk steps in world units too */
    REQUIRE(mm_render(r, &base, &q, &rb) == 0, "%s: the base scene", name);
    const double scales[] = {2.5, 0.125};
    for (int i = 0; i < 2; ++i) {
        mm_scene_make(&scaled, W, H, scales[i]);
        scaled.l.bounces = bounces;
        REQUIRE(mm_render(r, &scaled, &q, &rs) == 0, "%s: the scene at scale %g", name,
                scales[i]);
        char what[48];
        snprintf(what, sizeof what, "scaling the world by %g", scales[i]);
        mm_report(name, subsample, &st, what, mm_image_diff(&rb.img, &rs.img),
                  mm_vis_diff(&rb, &rs, MM_NPTS * base.l.n_key));
        hfs_image_free(&rs.img);
    }
    hfs_image_free(&rb.img);
}

static void run(hfs_renderer *r, const char *backend, int sub)
{
    if (!strcmp(backend, "gles")) {
        for (int bounces = 0; bounces < 2; ++bounces)
            scale_invariance(r, "gles", sub, bounces);
        return;
    }
    /* With a bounce too: the walk once lit a band at a sample that rose
     * above the top by a rounding error only, which a scaled world rounds
     * the other way (1.0e-2 of the maximum at x 2.5). */
    for (int bounces = 0; bounces < 2; ++bounces)
        scale_invariance(r, "cpu", 1, bounces);
}

int main(int argc, char **argv)
{
    return mm_main(argc, argv, "test_metamorphic", run);
}
