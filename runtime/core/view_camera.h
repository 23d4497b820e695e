/*
 * view_camera.h — the 3-D view's orbit camera (issue 16, deliverable 4):
 * where it stands, where it looks, and the ray through each pixel.  Neutral
 * (no backend): the truth's ray-cast view uses the rays, the GLES view pass
 * will build its matrices from the same basis.
 *
 * World coordinates are SPEC's: x = i dx, y = j dx, z = zscale h (times the
 * view's vertical exaggeration).  The camera stands `distance` world units
 * from `target` in the direction (azimuth, elevation) (SPEC's azimuth: from
 * +x toward +y) and looks at the target; fov is the vertical field of view.
 * Screen up is world +z projected onto the image plane; looking straight
 * down (elevation within 1e-6 rad of 90 degrees) it is the direction away
 * from the camera's azimuth, so the default camera (azimuth 90, elevation
 * 90) shows the field as its dumps do: +x to the right, row j = 0 at the
 * top.  Pixel (px, py) of a W x H image, py = 0 at the top, is sampled at
 * its centre.
 *
 * Orthographic (ortho = 1): parallel rays along `forward`, from the plane
 * through the eye perpendicular to it (nothing behind that plane is seen,
 * as nothing behind a perspective eye is), covering a view of height
 * 2 distance tan(fov / 2) at every depth: what the perspective camera
 * shows at the target's depth.  Straight down it shows the field as its
 * dumps do, without perspective.
 */
#ifndef HFS_VIEW_CAMERA_H
#define HFS_VIEW_CAMERA_H

#include "view_look.h"

typedef struct hfs_camera {
    double azimuth, elevation; /* radians: where the camera stands, seen from the target */
    double distance;           /* world units, > 0 */
    double fov;                /* vertical field of view, radians, in (0, pi) */
    double target[3];          /* world point looked at */
    double exaggeration;       /* vertical scale of the terrain in the view, > 0 */
    int ortho;                 /* 1: parallel projection (see above)              */
    hfs_view_look look;        /* background and haze (zero: the sky, no haze);
                                  travels with the camera so that every backend's
                                  view, and the GLES planner, sees it          */
} hfs_camera;

/* The camera's eye and its orthonormal basis: forward (eye -> target),
 * right and up on the image plane, right x up = forward. */
typedef struct hfs_camera_frame {
    double eye[3], forward[3], right[3], up[3];
    double tan_half;           /* tan(fov / 2) */
    int ortho;
    double half_height;        /* ortho: half the view's height, world units */
} hfs_camera_frame;

void hfs_camera_frame_make(const hfs_camera *c, hfs_camera_frame *fr);

/* The unit world direction of the ray through pixel (px, py) of a w x h
 * image (square pixels). */
void hfs_camera_ray(const hfs_camera_frame *fr, int w, int h, int px, int py, double dir[3]);

/* The ray through pixel (px, py) for either projection: its origin (the
 * eye, or ortho the pixel's point on the eye's plane) and unit direction. */
void hfs_camera_ray_at(const hfs_camera_frame *fr, int w, int h, int px, int py,
                       double org[3], double dir[3]);

/* A distance from the target at which the camera frames a box of
 * half-diagonal `radius` (world units) centred on it in a w x h view:
 * the box's bounding sphere fits the narrower of the two fields of view
 * (perspective), or the view's height and width (ortho, with the eye's
 * plane outside the sphere). */
double hfs_camera_framing_distance(const hfs_camera *c, double radius, int w, int h);

#endif /* HFS_VIEW_CAMERA_H */
