/*
 * objects.h — what stands above the field (issue 19; DESIGN.md "Objects
 * above the field"): points, pins and boxes (hfshade.h hfs_object) as
 * axis-aligned boxes, their faces sampled on a grid of vertices, each
 * vertex lit by the scene's lights:
 *   key lights   Le E_cap(N.d, alpha) times the key light's visible fraction
 *                at the vertex, from the renderer's point query (Lee &
 *                Kim's shadow height maps on the CPU reference and GLES,
 *                exact rays on the truth);
 *   environment  the horizon method at the vertex's own height: along each
 *                of nphi_env azimuths the terrain's highest elevation seen
 *                from the vertex (a march over the bilinear surface at one
 *                texel steps, to the field's edge), then the exact slice
 *                integral of the clamped cosine about the face's normal
 *                above those horizons (at least HFS_OBJ_SLICES azimuths:
 *                a side face's ground fills half its hemisphere) against
 *                the environment (slice_light.h;
 *                with env-shade = map the map's own open sky and slices:
 *                env_open.h, env_map_slices.h).  The approximation is the
 *                seeds': one horizon stands for its slice's wedge;
 *   local lights Le E_cap at the vertex, unshadowed (not yet shadowed for
 *                objects).
 * Objects cast no shadow, neither on the terrain nor on each other (nor a
 * box's face on its other faces: a face turned away gets no key light
 * anyway); their bottom faces are not lit or drawn (black).  Lo = albedo /
 * pi times the irradiance.  Views draw the lit vertices (bilinear over
 * each face's grid).  Neutral: the CPU reference's and the truth's ray
 * cast view and the GLES view draw the same lit grid.
 */
#ifndef HFS_OBJECTS_H
#define HFS_OBJECTS_H

#include "hfshade.h"

#define HFS_OBJ_GRID 4                                  /* quads per face side */
#define HFS_OBJ_SLICES 48   /* environment slices at least (nphi_env if more) */
#define HFS_OBJ_VERTS ((HFS_OBJ_GRID + 1) * (HFS_OBJ_GRID + 1)) /* per face */
#define HFS_OBJ_FACE_VALUES (6 * HFS_OBJ_VERTS * 3)     /* RGB per box */

/* The lit objects, in the lighting's world (z unexaggerated).  Faces:
 * 0 -x, 1 +x, 2 -y, 3 +y, 4 -z (bottom), 5 +z; a face's vertex (a, b) at
 * fractions (a / G, b / G) along its two other axes in increasing order
 * (x, y, z minus the face's own). */
typedef struct hfs_object_set {
    int n;
    double (*box)[6];  /* n x (x0, y0, z0, x1, y1, z1), world units          */
    float *rgb;        /* n x HFS_OBJ_FACE_VALUES exit radiance               */
    float (*albedo)[3];
} hfs_object_set;

/* Checks n objects over field f (one line naming the object: a position
 * off the footprint, a non-positive or non-finite size, an albedo outside
 * [0, 1]). */
int hfs_objects_check(const hfs_field *f, const hfs_object *o, int n, hfs_error *err);

/* The objects' boxes (a pin or point's z and a box's bottom are above the
 * surface at (x, y), read bilinearly); rgb allocated, zero. */
int hfs_objects_make(const hfs_field *f, const hfs_object *o, int n, hfs_object_set *s,
                     hfs_error *err);
void hfs_objects_free(hfs_object_set *s);

/* Vertex v of face `face` of box b: its world position. */
void hfs_objects_vertex(const hfs_object_set *s, int b, int face, int v, double p[3]);

/* Lights every vertex: key_vis[(b * 6 + face) * HFS_OBJ_VERTS + v) * n_key
 * + k] is key light k's visible fraction there (the caller's point query
 * at the vertices lifted off the face, hfs_objects_query_points). */
int hfs_objects_light(hfs_object_set *s, const hfs_field *f, const hfs_lighting *l,
                      const hfs_quality *q, const float *key_vis, hfs_error *err);

/* The points to query for key visibility: every vertex of faces 0-3 and 5
 * lifted 1e-3 dx off its face, clamped to the footprint; xyz gets
 * n * 6 * HFS_OBJ_VERTS points (bottom faces too, unused). */
void hfs_objects_query_points(const hfs_object_set *s, const hfs_field *f, double *xyz);

/* The exit radiance at point (u, v) in [0, 1]^2 of a face: bilinear over
 * its vertex grid. */
void hfs_objects_face_rgb(const hfs_object_set *s, int b, int face, double u, double v,
                          double rgb[3]);

#endif /* HFS_OBJECTS_H */
