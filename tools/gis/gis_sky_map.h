/*
 * gis_sky_map.h — a sky of the user's own for `hfshade insolation
 * --sky-map` (issue 39: "the sky from ... a clear-sky model or a user's
 * env map"): the share of the diffuse horizontal irradiance a texel gets
 * under a sky whose radiance follows an equirectangular map, tilted and
 * shadowed by the terrain's horizons (docs/GIS.md "The sun").
 *
 * The map gives the sky's SHAPE; the clear-sky model (ESRA) still gives
 * its size at each step.  The share is
 *     S = E(texel) / E(open flat ground),
 *     E = integral over the upper hemisphere above the texel's horizons of
 *         L(w) max(0, N.w) dw,
 * L the map's luminance (Rec. 709: 0.2126 R + 0.7152 G + 0.0722 B).  A
 * uniform map gives the isotropic sky's share (gis_sky_add) to rounding; a
 * sky brighter to the north gives a north slope more than 1 where the
 * isotropic one gives less.  Below the horizontal lies ground (not
 * counted, as for the isotropic sky and the clear sky's own diffuse
 * horizontal irradiance): the map's lower half is not read.
 *
 * Where the map is: its column u (SPEC: phi = 2 pi u, top row the zenith)
 * looks at compass azimuth north_deg + 360 u, clockwise from north, on the
 * ground (not on the grid: a south-up or west-running DEM sees the same
 * sky).  north_deg 0: the map's left edge looks north.
 *
 * How it integrates: the terrain's horizons come in n_dirs azimuths (as
 * the isotropic sky's); each azimuth stands for its sector of 360 / n_dirs
 * degrees, whose radiance at each elevation is the map's mean over the
 * sector (each map column weighted by the part of it inside).  Over
 * elevation the map is a stack of rows, each of constant radiance, so per
 * azimuth the integral of L (n_z sin e + n_h cos e) cos e de above the
 * texel's lowest open elevation g has the closed form of gis_sky_add row
 * by row; the rows wholly above g are suffix sums made once, so a texel
 * costs one row search and a few products an azimuth.
 */
#ifndef HFS_GIS_SKY_MAP_H
#define HFS_GIS_SKY_MAP_H

#include <stddef.h>

#include "hfshade.h"

typedef struct gis_sky_map {
    int n_dirs;          /* azimuths                                           */
    int n_bands;         /* the map's rows above the horizon                   */
    double *edge;        /* n_bands + 1 elevations, radians, 0 up to pi/2      */
    double *lum;         /* [k * n_bands + j]: azimuth k's sector, band j      */
    double *sa, *sb;     /* [k * (n_bands + 1) + j]: sum over bands >= j of lum
                          * times the band's part of the n_z and n_h integrals */
    double open;         /* sum over k of sa[k][0]: open flat ground's E       */
} gis_sky_map;

/* The map (w x h RGB, top row first; finite, >= 0) for the n_dirs
 * azimuths the sky's horizons are searched in, gis_product_directions's
 * (1..HFS_MAX_HORIZON_AZIMUTHS; SPEC phi on a north-up map: compass = phi
 * + 90 degrees), the map's left edge at compass north_deg.  0, or an error
 * naming `name` (negative radiance, a black upper half, out of memory). */
int gis_sky_map_make(const float *rgb, int w, int h, double north_deg, int n_dirs,
                     const char *name, gis_sky_map *out, hfs_error *err);
void gis_sky_map_free(gis_sky_map *m);

/* acc[p] += azimuth k's part of E at texel p: its horizon gamma[p] (the
 * grid's, radians; gis_horizon_none: no terrain), unit normal
 * n[3p..3p+2] on the grid, phi the azimuth in the grid's axes
 * (gis_grid_phi of gis_product_directions's k-th). */
void gis_sky_map_add(const gis_sky_map *m, int k, double phi, double *acc, const float *gamma,
                     const float *n, size_t count);

/* out[p] = acc[p] / open, the share (>= 0; 1 on open flat ground). */
void gis_sky_map_finish(const gis_sky_map *m, float *out, const double *acc, size_t count);

#endif /* HFS_GIS_SKY_MAP_H */
