/*
 * view_params.c — see view_params.h and hfshade.h (hfs_view_defaults,
 * hfs_view_frame).
 */
#include "view_params.h"

#include <math.h>

#define PI 3.14159265358979323846

void hfs_view_camera(const hfs_view *v, hfs_camera *cam)
{
    *cam = (hfs_camera){.azimuth = v->azimuth, .elevation = v->elevation,
                        .distance = v->distance, .fov = v->fov,
                        .target = {v->target[0], v->target[1], v->target[2]},
                        .exaggeration = v->exaggeration, .ortho = v->mode == HFS_VIEW_ORTHO};
}

static int range(double x, double lo, double hi, int open_lo, const char *what, hfs_error *err)
{
    if (!isfinite(x) || x > hi || (open_lo ? x <= lo : x < lo))
        return hfs_fail(err, HFS_E_INVALID, "view: %s %g is out of range %s%g, %g]", what, x,
                        open_lo ? "(" : "[", lo, hi);
    return HFS_OK;
}

int hfs_view_check(const hfs_view *v, hfs_error *err)
{
    if (!v)
        return hfs_fail(err, HFS_E_INVALID, "view: missing");
    if (v->mode != HFS_VIEW_PERSPECTIVE && v->mode != HFS_VIEW_ORTHO)
        return hfs_fail(err, HFS_E_INVALID, "view: unknown mode %d", (int)v->mode);
    if (v->width < 1 || v->height < 1 || v->width > HFS_VIEW_MAX_SIZE ||
        v->height > HFS_VIEW_MAX_SIZE)
        return hfs_fail(err, HFS_E_INVALID, "view: size %dx%d is out of range [1, %d]",
                        v->width, v->height, HFS_VIEW_MAX_SIZE);
    int rc = range(v->azimuth, -1e6, 1e6, 0, "azimuth (radians)", err);
    if (!rc)
        rc = range(v->elevation, -0.5 * PI, 0.5 * PI, 0, "elevation (radians)", err);
    if (!rc)
        rc = range(v->distance, 0.0, 1e12, 1, "distance", err);
    if (!rc)
        rc = range(v->fov, 0.0, PI - 1e-6, 1, "fov (radians)", err);
    if (!rc)
        rc = range(v->exaggeration, 0.0, 1e6, 1, "exaggeration", err);
    for (int k = 0; k < 3 && !rc; ++k)
        rc = range(v->target[k], -1e12, 1e12, 0, "target", err);
    return rc ? rc : hfs_view_look_check(v, err);
}

/* The field's height range (finite heights). */
static void height_range(const hfs_field *f, double *lo, double *hi)
{
    double a = INFINITY, b = -INFINITY;
    for (size_t i = 0; i < (size_t)f->width * (size_t)f->height; ++i)
        if (isfinite(f->z[i]))
            a = fmin(a, f->z[i]), b = fmax(b, f->z[i]);
    *lo = isfinite(a) ? a : 0.0;
    *hi = isfinite(b) ? b : 0.0;
}

void hfs_view_frame(hfs_view *v, const hfs_field *f)
{
    double lo, hi;
    height_range(f, &lo, &hi);
    const double zs = f->zscale * v->exaggeration;
    const double box[2][3] = {{0.0, 0.0, zs * lo},
                              {(f->width - 1) * f->dx, (f->height - 1) * f->dx, zs * hi}};
    double r2 = 0.0; /* the farthest corner of the box from the target */
    for (int c = 0; c < 8; ++c) {
        double d2 = 0.0;
        for (int k = 0; k < 3; ++k) {
            const double d = box[(c >> k) & 1][k] - v->target[k];
            d2 += d * d;
        }
        r2 = fmax(r2, d2);
    }
    hfs_camera cam;
    hfs_view_camera(v, &cam);
    const double r = sqrt(r2) > 0.0 ? sqrt(r2) : f->dx;
    v->distance = hfs_camera_framing_distance(&cam, r, v->width, v->height);
}

void hfs_view_defaults(hfs_view *v, const hfs_field *f)
{
    double lo, hi;
    height_range(f, &lo, &hi);
    *v = (hfs_view){.mode = HFS_VIEW_ORTHO, .azimuth = 0.5 * PI, .elevation = 0.5 * PI,
                    .fov = 30.0 * PI / 180.0, .exaggeration = 1.0, .width = 512, .height = 512};
    v->target[0] = 0.5 * (f->width - 1) * f->dx;
    v->target[1] = 0.5 * (f->height - 1) * f->dx;
    v->target[2] = 0.5 * f->zscale * (lo + hi);
    hfs_view_frame(v, f);
}
