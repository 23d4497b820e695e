/*
 * view_look.h — what the 3-D view shows besides the lit terrain (issue 41):
 * the background where a ray meets nothing, and the aerial perspective
 * (haze) over what it meets.  Neutral: the truth's ray-cast view (which
 * the cpu backend draws too) calls these functions per pixel, and the
 * GLES view pass evaluates the same expressions in float
 * (shaders_es/gles_view.frag.glsl), from a block filled from the same
 * hfs_view_look (DESIGN.md "Sky and haze in the view").
 *
 * Background (hfs_background):
 *   sky     an env_map: the map itself, bilinear between its pixel centres
 *           (wrapping in azimuth, clamped at the poles), turned by
 *           env_rotate as the lighting turns it (a pixel at azimuth phi
 *           shows at phi + env_rotate); else the SH sky in the ray's
 *           direction; black without an environment;
 *   studio  level * (0.12 + 0.14 (1 + dz)) grey, dz the ray direction's z:
 *           0.12 x level straight down, 0.26 at the horizon, 0.40 straight
 *           up: a backdrop darker than the lit subject (level is what a
 *           white level surface at the field's centre would show), so a
 *           panel stands out from it, lighter above as under a softbox;
 *   color   the given linear radiance.
 *
 * Haze: an exponential atmosphere over the field's lowest height z0
 * (view world, z times the exaggeration), extinction
 * sigma exp(-max(z - z0, 0) / H).  The optical depth of the segment from
 * (distance 0, height za) to (distance D, height zb) in closed form:
 *   tau = sigma D (e^-a - e^-b) / (b - a),  a, b = max(z - z0, 0) / H,
 * its limit sigma D e^-a (1 - x/2 + x^2/6), x = b - a, for |x| < 1e-2
 * (where the difference cancels); T = exp(-tau), and
 *   L = L_surface T + L_in (1 - T).
 * sigma 0 is "off": callers skip the blend, so the view is bit for bit the
 * one without haze.
 */
#ifndef HFS_VIEW_LOOK_H
#define HFS_VIEW_LOOK_H

#include "hfshade.h"

/* The series takes over below this |b - a| (C and GLSL alike). */
#define HFS_HAZE_SERIES 1e-2
/* The studio gradient: level * (BASE + SLOPE (1 + dz)). */
#define HFS_STUDIO_BASE 0.12
#define HFS_STUDIO_SLOPE 0.14

typedef struct hfs_view_look {
    hfs_background background;
    double rgb[3];          /* color: the colour; studio: its level (grey)    */
    double sigma;           /* haze extinction at z0, 1 / world unit; 0: off */
    double z0, scale_h;     /* the atmosphere's base and scale height (world) */
    double in[3];           /* in-scattered radiance L_in                     */
} hfs_view_look;

/* The look of view v of field f under lighting l (v, f, l valid: the
 * renderer checked them; hfs_view_look_check first). */
void hfs_view_look_make(const hfs_view *v, const hfs_field *f, const hfs_lighting *l,
                        hfs_view_look *out);

/* Whether a and b draw the same view (field by field). */
int hfs_view_look_equal(const hfs_view_look *a, const hfs_view_look *b);

/* One-line HFS_E_INVALID naming the hfs_view field, or HFS_OK. */
int hfs_view_look_check(const hfs_view *v, hfs_error *err);

/* The background's radiance in unit world direction d (k NULL: the sky;
 * sky: from l as described above, sh = l's env_sh turned by env_rotate,
 * made once per view by the caller). */
void hfs_view_background(const hfs_view_look *k, const hfs_lighting *l,
                         const double sh[3][HFS_SH_COEFFS], const double d[3], double rgb[3]);

/* An equirect map's bilinear radiance in unit direction d, the map turned
 * by rot about +z (the sky background's lookup). */
void hfs_env_map_bilinear(const float *map, int w, int h, double rot, const double d[3],
                          double rgb[3]);

/* The transmittance of the segment of length dist from height za to zb. */
double hfs_haze_transmittance(const hfs_view_look *k, double dist, double za, double zb);

/* rgb = rgb T + L_in (1 - T) for the segment (k->sigma > 0). */
void hfs_haze_apply(const hfs_view_look *k, double dist, double za, double zb, double rgb[3]);

#endif /* HFS_VIEW_LOOK_H */
