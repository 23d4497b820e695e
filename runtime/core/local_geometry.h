/*
 * local_geometry.h — a local spherical light seen from one receiver: its
 * view (distance, cap, azimuth range), the per-receiver swath and the
 * Legendre visibility of that swath (DESIGN.md "Local lights").  Shared by
 * the CPU reference (cpu_local.c) and the GLES path (its local pass uses the
 * elevation moments), so neither owns it.
 */
#ifndef HFS_LOCAL_GEOMETRY_H
#define HFS_LOCAL_GEOMETRY_H

#include "hfshade.h"
#include "sh.h"
#include "visibility.h"

typedef enum hfs_local_swath_mode {
    HFS_LOCAL_SWATH_PARTIAL = 0, /* per-receiver partial swath where possible (default) */
    HFS_LOCAL_SWATH_FULL = 1     /* always the full swath of nphi_local (thesis) */
} hfs_local_swath_mode;

/* Fewest samples of a partial swath. */
#define HFS_LOCAL_PARTIAL_MIN 3

/* A sample's own ray is searched (cpu_local.c ray_horizon, GLES
 * local_visibility.frag) where the light's section begins at least this
 * many texels out: past the receiver's own cell, whose far edge lies at
 * most sqrt(2) away, so that nothing behind the light is taken. */
#define HFS_LOCAL_RAY_FROM 1.5

/* ---- geometry of one light seen from one receiver ---------------------------- */

typedef struct hfs_local_view {
    int inside;          /* receiver in or on the sphere (d <= r, r > 0)       */
    double v[3];         /* centre - receiver, world units                     */
    double d, r;         /* distance to the centre, radius                     */
    double dir[3];       /* v / d (+z when d = 0)                              */
    double alpha;        /* asin(r/d); pi inside                               */
    double sin_a, cos_a; /* r/d and sqrt((d-r)(d+r))/d (outside only)          */
    double c_tan;        /* (d-r)(d+r): squared tangent length (outside only)  */
    double rho_h;        /* horizontal distance to the centre                  */
    double phi_l, elev_l;/* azimuth and elevation of the centre                */
    int surround;        /* r >= rho_h: the light covers every azimuth         */
} hfs_local_view;

/* Fills the view of light l (radius > 0) from receiver point p (world). */
void hfs_local_view_make(const hfs_local_light *l, const double p[3], hfs_local_view *lv);

/* Elevation extent [lo, hi] (clipped to [-pi/2, pi/2]) of the cap in the
 * vertical half-plane of unit azimuth (c, s).  Returns 0 (lo = hi = 0) when
 * that half-plane misses the cap.  Outside the sphere only. */
int hfs_local_cap_window(const hfs_local_view *lv, double c, double s, double *lo, double *hi);

/* Horizontal distance (world) at which the ray of azimuth (c, s) and
 * elevation (cos e, sin e) = (ce, se) enters the sphere; where the ray misses,
 * the horizontal distance of its closest approach to the centre; never < 0. */
double hfs_local_entry_distance(const hfs_local_view *lv, double c, double s, double ce,
                                double se);

/* ---- swath and Legendre visibility ------------------------------------------------- */

/* Same layout as hfs_swath (visibility.h): full = n samples at
 * phi0 + k dphi, dphi = 2 pi/n, hat functions of half-width dphi; partial = n
 * samples at phi0 + k dphi with boundary wedges of dphi/2 that fade to 0. */
typedef struct hfs_local_swath {
    int n, full;
    double phi0, dphi;
} hfs_local_swath;

/* The swath the renderer uses for view lv (see the header comment). */
void hfs_local_swath_make(const hfs_local_view *lv, int nphi_local,
                          hfs_local_swath_mode mode, hfs_visibility_path path,
                          hfs_local_swath *sw);


/* Azimuthal weights A[r] = integral hat_k(phi) azim_r(phi) dphi of sample k
 * (hat of half-widths: the neighbouring spacing, dphi/2 at a partial swath's
 * ends). */
void hfs_local_sample_weights(const hfs_local_swath *sw, int k, double A[HFS_SH_N]);

/* V = sum_k A_k (.) (E nlp_k): the SH of the linearly blended visible bands,
 * nlp = n x 4 NLP vectors.  Identical (to rounding) to hfs_visibility_eval on
 * the same swath when every sample has the same window: M_lin folded per
 * sample in closed form, for any dphi. */
void hfs_local_legendre_eval(const hfs_local_swath *sw, const double *E, const double *nlp,
                             double V[HFS_SH_N]);

/* Moments of a hat of half-widths wl (left), wr (right) centred at 0:
 * gc[m] = integral hat cos(m u) du, gs[m] = integral hat sin(m u) du. */
typedef struct hfs_local_hat {
    double gc[4], gs[4];
} hfs_local_hat;

/* The three hats of a swath: first sample, interior, last sample. */
void hfs_local_swath_hats(const hfs_local_swath *sw, hfs_local_hat hats[3]);
/* The hat of sample k among those three. */
const hfs_local_hat *hfs_local_sample_hat(const hfs_local_swath *sw, const hfs_local_hat hats[3],
                                          int k);
/* A[r] of the hat hm centred at the azimuth (cos, sin) = (c, s). */
void hfs_local_weights_at(double c, double s, const hfs_local_hat *hm, double A[HFS_SH_N]);

#endif /* HFS_LOCAL_GEOMETRY_H */
