/*
 * cli_compare.c — see cli_compare.h.
 */
#include "cli_compare.h"

#include "hfs_io.h"

#include <stdio.h>

/* Of the texels ref holds in umbra, how many res renders lit. */
static void umbra_lit(const hfs_image *res, const hfs_image *ref, const hfs_image *unsh,
                      double norm, long *lit, long *umbra)
{
    *lit = *umbra = 0;
    const size_t n = (size_t)ref->width * (size_t)ref->height;
    for (size_t t = 0; t < n; ++t) {
        const double u = unsh->rgb[3 * t], r = ref->rgb[3 * t], v = res->rgb[3 * t];
        if (!(u > 0.01 * norm) || !(r < 0.01 * u))
            continue;
        ++*umbra;
        *lit += v >= 0.5 * u;
    }
}

int cli_compare_run(const hfs_field *f, const hfs_lighting *l, const hfs_quality *q,
                    const char *result, const char *reference, hfs_error *err)
{
    hfs_image res = {0}, ref = {0}, unsh = {0};
    int rc;
    if ((rc = hfs_pfm_read_image(result, &res, err)) ||
        (rc = hfs_pfm_read_image(reference, &ref, err)))
        goto out;
    if (res.width != f->width || res.height != f->height) {
        rc = hfs_fail(err, HFS_E_INVALID, "%s: %dx%d does not match the scene's %dx%d", result,
                      res.width, res.height, f->width, f->height);
        goto out;
    }
    if ((rc = hfs_image_alloc(&unsh, f->width, f->height, err)) ||
        (rc = hfs_render_unshadowed(f, l, q, &unsh, err)))
        goto out;
    const double norm = hfs_image_max(&unsh);
    hfs_metrics m;
    if ((rc = hfs_compare_images(&res, &ref, norm, &m, err)))
        goto out;
    long lit, umbra;
    umbra_lit(&res, &ref, &unsh, norm, &lit, &umbra);
    printf("mean_abs %.3e rmse %.3e p99_abs %.3e max_abs %.3e nonfinite %ld norm %.6g "
           "umbra_lit %ld/%ld\n",
           m.mean_abs, m.rmse, m.p99_abs, m.max_abs, m.nonfinite, m.norm, lit, umbra);
out:
    hfs_image_free(&res);
    hfs_image_free(&ref);
    hfs_image_free(&unsh);
    return rc;
}
