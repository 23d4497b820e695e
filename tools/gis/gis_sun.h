/*
 * gis_sun.h — the sun on a DEM, for `hfshade sun` and `hfshade
 * insolation` (issue 39; SPEC.md "Terrain rasters (GIS products)": beam
 * irradiance on the tilted surface E_b = E_0 max(0, N.s) V, irradiation
 * sums in Wh/m^2; docs/GIS.md).  Where the sun stands at an instant
 * (solar_position.h: NOAA's solar calculator), what a clear sky sends
 * (clear_sky.h: ESRA, as GRASS r.sun), the sun as the renderer's key
 * light, and the products of its renders on the DEM's square grid brought
 * back to the input's (gis_resample.h), nodata at the input's holes.
 * No GDAL.
 *
 * The beam factor f.  With albedo 1, no bounces and one key light of
 * radiance Le and angular radius alpha, the renderer's Lo = E / pi, E the
 * disk's irradiance on the texel's tilted surface shadowed by the terrain;
 * unshadowed at normal incidence E = pi sin^2(alpha) Le.  So f = Lo / (Le
 * sin^2 alpha), in [0, 1], is about max(0, N.s) times the disk's visible
 * fraction.  The sun is given Le = 1 / sin^2(alpha) (about 44 500), so
 * that Lo = f itself: every backend's output then holds a number of order
 * 1, not 2e-5 (where fp16 has only subnormals).
 * The visible fraction V = f / f_unshadowed, f_unshadowed from
 * hfs_render_unshadowed (the exact cap irradiance, V = 1), clamped to
 * [0, 1]; 0 where f_unshadowed <= GIS_SUN_SELF_SHADOW (the slope faces away
 * from the sun: self-shadowed).
 * The search radius c->radius (> 0: `--radius`) cuts the sun's horizon
 * search short of its reach: shadows cast from farther are left out.
 * The sky: the isotropic upper hemisphere's share on the tilted surface
 * under the terrain's horizons (gis_sky_add: closed form per azimuth,
 * p->sky_directions azimuths searched within c->radius), 1 on open flat
 * ground: the share of the diffuse horizontal irradiance the texel gets.
 *
 * One sun for the whole DEM: the site is the DEM's centre (its longitude,
 * latitude and height); the sun's direction moves about 0.01 degrees per
 * km across a DEM (docs/GIS.md).  Its azimuth is turned onto the grid by
 * the grid convergence at that centre (gis_compute convergence_deg: a
 * projected grid's north is not true north away from its central
 * meridian).
 */
#ifndef HFS_GIS_SUN_H
#define HFS_GIS_SUN_H

#include "gis_products.h"
#include "gis_sky_map.h"
#include "solar_position.h"

/* The sun's angular radius at 1 AU: 959.63 arcseconds (Auwers; the
 * Astronomical Almanac's), 0.2666 degrees; at R AU it is that / R. */
#define GIS_SUN_RADIUS_ARCSEC 959.63

/* f_unshadowed at or below this: self-shadowed, V = 0 (a disk whose
 * centre is within 0.006 degrees of the tangent plane). */
#define GIS_SUN_SELF_SHADOW 1e-4

/* The sun at one instant over a site. */
typedef struct gis_sun_at {
    double jd;                  /* UTC Julian day                             */
    hfs_solar_angles pos;       /* azimuth (compass), apparent and true elevation */
    double alpha_deg;           /* the disk's angular radius                  */
    double beam_normal;         /* W/m^2, ESRA clear sky; 0 when h0 <= 0      */
    double diffuse_horizontal;  /* W/m^2, ditto                               */
} gis_sun_at;

/* The sun of UTC Julian day jd over site with Linke turbidity linke: its
 * position, its disk, the ESRA clear sky with G0 = I0 / R^2 (the same
 * ephemeris's distance; r.sun's day-of-year formula differs from it by
 * at most 0.11%) and the true elevation h0 (ESRA adds its own refraction).
 * 0, or -1 (a site, instant or turbidity out of range). */
int gis_sun_compute(double jd, const hfs_solar_site *site, double linke, gis_sun_at *out);

/* 1 when the centre of the sun's disk stands above the horizontal plane
 * (apparent elevation > 0): it can light the terrain. */
int gis_sun_up(const gis_sun_at *s);

/* The sun as a key light on a grid whose +x runs east (ex = 1) or west and
 * +y south (ey = 1) or north (gis_grid_phi), its north convergence_deg
 * east of true north (gis_dem_lonlat; 0: true north): SPEC's phi from the
 * compass azimuth less the convergence, the apparent elevation, alpha, Le
 * = 1 / sin^2(alpha). */
void gis_sun_key(const gis_sun_at *s, int ex, int ey, double convergence_deg,
                 hfs_key_light *k);

/* `hfshade sun` at sun s: beam[w*h] = beam_normal * f (W/m^2) and vis[w*h]
 * = V, on the input's grid (the input's holes: c->nodata).  A sun not up
 * (gis_sun_up): zeros, no render. */
int gis_product_sun(const gis_compute *c, const gis_sun_at *s, float *beam, float *vis,
                    hfs_error *err);

/* A period for `hfshade insolation`: [jd_from, jd_to) in steps of step_min
 * minutes, the last one shortened to end at jd_to; each step's sun at its
 * midpoint. */
typedef struct gis_period {
    double jd_from, jd_to, step_min;
    long n_steps;               /* ceil((jd_to - jd_from) / step)             */
    hfs_solar_site site;
    double linke;
    int sky_directions;         /* azimuths of the sky's horizons (>= 1)     */
    const gis_sky_map *sky;     /* the sky's shape (its sky_directions azimuths
                                 * of gis_product_directions); NULL: isotropic */
    double albedo;              /* the ground's, [0, 1]: band 3 adds the
                                 * ground-reflected part; 0: none            */
    int beam_only;              /* the beam alone (--beam-only): no sky's
                                 * horizons searched, diffuse and global
                                 * not written (sky and albedo unused)       */
} gis_period;

/* The period [jd_from, jd_to) in steps of step_min minutes, as the
 * command line and the library both take it: *minutes its length rounded
 * to a microsecond (the Julian days' rounding must not make a step of
 * nothing at the end), *steps = ceil(minutes / step_min) (the last step
 * shortened).  The callers refuse minutes <= 0 and too many steps. */
void gis_period_length(double jd_from, double jd_to, double step_min, double *minutes,
                       double *steps);

/* Step k (0..n_steps - 1) of p: its midpoint (UTC Julian day) and length
 * in hours. */
void gis_period_step(const gis_period *p, long k, double *jd_mid, double *hours);

/* What a period held. */
typedef struct gis_period_stats {
    long steps_sun;             /* steps whose sun has h0 > 0                  */
    double beam_normal_wh;      /* sum of beam_normal * hours, Wh/m^2          */
    double diffuse_wh;          /* sum of diffuse_horizontal * hours          */
    double global_wh;           /* sum of (beam_normal sin h0 + diffuse_horizontal)
                                 * hours: the clear sky's global horizontal
                                 * irradiation, h0 the true elevation (as
                                 * r.sun's beam on the horizontal)           */
} gis_period_stats;

/* Counts the steps with the sun above the horizon and sums the clear
 * sky's irradiation over p, rendering nothing.  0, or -1 (gis_sun_compute
 * refused a step). */
int gis_period_scan(const gis_period *p, gis_period_stats *st);

/* `hfshade insolation` over p (Wh/m^2 on the input's grid): beam[] = the
 * sum over the steps with h0 > 0 of beam_normal * f * hours (one render a
 * step, the same renderer and field: only the key light moves), diffuse[]
 * = the diffuse horizontal irradiation times the sky's share (above),
 * global[] = beam + diffuse.  With p->sky the sky's share is the map's
 * (gis_sky_map.h), else the isotropic sky's.  With p->albedo > 0 global
 * also holds the ground-reflected part, albedo * global_wh * (1 - S_iso):
 * S_iso the isotropic sky's share, so 1 - S_iso is the part of the
 * texel's cosine-weighted view that is ground or terrain, (1 - cos s) / 2
 * on an open plane of slope s (r.sun's refl_rad; the terrain taken as lit
 * as open flat ground: the terrain configuration factor of Dozier & Frew
 * 1990, "Rapid calculation of terrain parameters for radiation modeling
 * from digital elevation data", IEEE TGRS 28(5):963-969).  With
 * p->beam_only only beam[] is written (diffuse and global may be NULL)
 * and the sky's horizons are not searched: the same beam, bit for bit. */
int gis_product_insolation(const gis_compute *c, const gis_period *p, float *beam,
                           float *diffuse, float *global, gis_period_stats *st, hfs_error *err);

#endif /* HFS_GIS_SUN_H */
