/*
 * test_cpu_local_truth.c — local spherical lights in the CPU reference
 * (runtime/cpu/cpu_local.c) against the ground truth on a small bumpy
 * scene, both swath modes and both visibility paths (test_cpu_local.c
 * checks the closed forms and the invariants; the truth render is most
 * of the time, so it runs on its own).
 */
#include "cpu_local_util.h"
#include "visibility.h"

/* ---- (8) against the ground truth --------------------------------------------------------------- */

/* SPEC metrics (mean abs, max abs over texels and channels / largest
 * unshadowed value) and the relative mean error sum|cpu - truth| / sum truth
 * of the reference against truth on a 48x40 bumpy field (relief 0..6
 * texels, slopes up to ~1) with three lights at 3.6-12 texels above the base
 * (radius 0.8-3, one coloured), truth with 1024 samples per light.  Measured
 * at default quality (this machine): partial Legendre mean 4.2e-4, max
 * 4.9e-3, relative 4.2e-2; full swath 5.2e-4, 4.8e-3, 5.2e-2; wedge tables
 * 1.0e-3, 1.4e-2, 1.0e-1.  Limits are about 2x (SPEC metrics) and 1.6-2x
 * (relative).  The partial swath must beat the full one.  (The relative
 * error falls to 1.4e-2 at k 8, o 4 and 0.9e-2 at k 16, o 8 for the partial
 * swath: the defaults' error is the pyramid's prefiltering.) */
typedef struct truth_case {
    int path, mode;
    double mean_lim, max_lim, rel_lim;
} truth_case;

static void test_truth(void)
{
    const int w = 48, h = 40;
    const double amp = 3.0;
    float *z = bumpy(w, h, amp);
    hfs_lighting l;
    bumpy_lights(&l, amp);
    hfs_quality q;
    hfs_quality_defaults(&q);
    q.truth_light_samples = 1024;
    hfs_field f = {.width = w, .height = h, .z = z, .dx = 1, .zscale = 1};
    hfs_error err;
    hfs_image tru, ref;
    hfs_image_alloc(&tru, w, h, &err);
    CHECK(hfs_truth_render(&f, &l, &q, &tru, NULL, NULL, &err) == HFS_OK, "truth: %s", err.msg);
    unshadowed(z, w, h, 1, 1, &l, &q, &ref);
    const double norm = hfs_image_max(&ref);
    const truth_case cases[3] = {
        {HFS_VIS_LEGENDRE, HFS_LOCAL_SWATH_PARTIAL, 9e-4, 1e-2, 0.07},
        {HFS_VIS_LEGENDRE, HFS_LOCAL_SWATH_FULL, 1.1e-3, 1e-2, 0.1},
        {HFS_VIS_WEDGE_TABLE, HFS_LOCAL_SWATH_FULL, 2.1e-3, 2.7e-2, 0.2}};
    double rels[3];
    for (int c = 0; c < 3; ++c) {
        q.visibility = (hfs_visibility_path)cases[c].path;
        hfs_image img;
        rels[c] = 1.0;
        if (render_mode(z, w, h, 1, 1, &l, &q, cases[c].mode, &img) == HFS_OK) {
            hfs_metrics m;
            CHECK(hfs_compare_images(&img, &tru, norm, &m, &err) == HFS_OK, "compare: %s", err.msg);
            double sa = 0.0, st = 0.0;
            for (int k = 0; k < w * h * 3; ++k) {
                sa += fabs(img.rgb[k] - tru.rgb[k]);
                st += tru.rgb[k];
            }
            rels[c] = sa / st;
            printf("truth: %s/%s mean %.2e rmse %.2e p99 %.2e max %.2e relative %.2e\n",
                   path_name(cases[c].path), mode_name(cases[c].mode), m.mean_abs, m.rmse,
                   m.p99_abs, m.max_abs, rels[c]);
            CHECK(m.nonfinite == 0 && m.mean_abs <= cases[c].mean_lim &&
                  m.max_abs <= cases[c].max_lim && rels[c] <= cases[c].rel_lim,
                  "truth %s/%s: mean %g (limit %g), max %g (limit %g), relative %g (limit %g)",
                  path_name(cases[c].path), mode_name(cases[c].mode), m.mean_abs,
                  cases[c].mean_lim, m.max_abs, cases[c].max_lim, rels[c], cases[c].rel_lim);
        }
        hfs_image_free(&img);
    }
    CHECK(rels[0] < rels[1], "partial swath (%g) not better than full (%g)", rels[0], rels[1]);
    hfs_image_free(&tru);
    hfs_image_free(&ref);
    free(z);
}

int main(void)
{
    test_truth();
    if (failures) {
        printf("%d failure(s)\n", failures);
        return 1;
    }
    printf("test_cpu_local_truth: all passed\n");
    return 0;
}
