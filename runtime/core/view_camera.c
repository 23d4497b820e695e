/*
 * view_camera.c — see view_camera.h.
 */
#include "view_camera.h"

#include <math.h>

static void normalize(double v[3])
{
    const double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; ++k)
        v[k] /= l;
}

static void cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

void hfs_camera_frame_make(const hfs_camera *c, hfs_camera_frame *fr)
{
    const double ca = cos(c->azimuth), sa = sin(c->azimuth);
    const double ce = cos(c->elevation), se = sin(c->elevation);
    const double away[3] = {ce * ca, ce * sa, se}; /* target -> eye */
    for (int k = 0; k < 3; ++k) {
        fr->eye[k] = c->target[k] + c->distance * away[k];
        fr->forward[k] = -away[k];
    }
    /* Up: +z seen on the image plane; straight down, away from the camera's
     * azimuth (the direction +z leans to as the elevation nears 90). */
    double up[3] = {0.0, 0.0, 1.0};
    if (fabs(fabs(c->elevation) - 0.5 * 3.14159265358979323846) < 1e-6)
        up[0] = -ca, up[1] = -sa, up[2] = 0.0; /* (straight up too: +z is degenerate) */
    cross(up, fr->forward, fr->right); /* right x up = forward */
    normalize(fr->right);
    cross(fr->forward, fr->right, fr->up);
    fr->tan_half = tan(0.5 * c->fov);
    fr->ortho = c->ortho != 0;
    fr->half_height = c->distance * fr->tan_half;
}

void hfs_camera_ray(const hfs_camera_frame *fr, int w, int h, int px, int py, double dir[3])
{
    const double sy = fr->tan_half, sx = sy * (double)w / (double)h;
    const double x = (2.0 * (px + 0.5) / w - 1.0) * sx;
    const double y = (1.0 - 2.0 * (py + 0.5) / h) * sy;
    for (int k = 0; k < 3; ++k)
        dir[k] = fr->forward[k] + x * fr->right[k] + y * fr->up[k];
    normalize(dir);
}

void hfs_camera_ray_at(const hfs_camera_frame *fr, int w, int h, int px, int py,
                       double org[3], double dir[3])
{
    if (!fr->ortho) {
        for (int k = 0; k < 3; ++k)
            org[k] = fr->eye[k];
        hfs_camera_ray(fr, w, h, px, py, dir);
        return;
    }
    const double sy = fr->half_height, sx = sy * (double)w / (double)h;
    const double x = (2.0 * (px + 0.5) / w - 1.0) * sx;
    const double y = (1.0 - 2.0 * (py + 0.5) / h) * sy;
    for (int k = 0; k < 3; ++k) {
        org[k] = fr->eye[k] + x * fr->right[k] + y * fr->up[k];
        dir[k] = fr->forward[k];
    }
}

double hfs_camera_framing_distance(const hfs_camera *c, double radius, int w, int h)
{
    const double t = tan(0.5 * c->fov), aspect = (double)w / (double)h;
    const double narrow = aspect < 1.0 ? aspect : 1.0; /* horizontal tan is t * aspect */
    if (c->ortho) /* half height distance * t must hold the sphere; the eye outside it */
        return fmax(radius / (t * narrow), 2.0 * radius);
    const double half = atan(t * narrow); /* the narrower half-angle */
    return radius / sin(half);
}
