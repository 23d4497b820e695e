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
 */
#ifndef HFS_VIEW_CAMERA_H
#define HFS_VIEW_CAMERA_H

typedef struct hfs_camera {
    double azimuth, elevation; /* radians: where the camera stands, seen from the target */
    double distance;           /* world units, > 0 */
    double fov;                /* vertical field of view, radians, in (0, pi) */
    double target[3];          /* world point looked at */
    double exaggeration;       /* vertical scale of the terrain in the view, > 0 */
} hfs_camera;

/* The camera's eye and its orthonormal basis: forward (eye -> target),
 * right and up on the image plane, right x up = forward. */
typedef struct hfs_camera_frame {
    double eye[3], forward[3], right[3], up[3];
    double tan_half;           /* tan(fov / 2) */
} hfs_camera_frame;

void hfs_camera_frame_make(const hfs_camera *c, hfs_camera_frame *fr);

/* The unit world direction of the ray through pixel (px, py) of a w x h
 * image (square pixels). */
void hfs_camera_ray(const hfs_camera_frame *fr, int w, int h, int px, int py, double dir[3]);

#endif /* HFS_VIEW_CAMERA_H */
