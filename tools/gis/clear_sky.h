/*
 * clear_sky.h — the irradiance of a cloudless sky, for `hfshade
 * insolation` (issue 39): the ESRA clear-sky model as GRASS r.sun computes
 * it (Rigollier, Bauer & Wald 2000, "On the clear sky model of the ESRA —
 * European Solar Radiation Atlas — with respect to the heliosat method",
 * Solar Energy 68(1):33-48; Suri & Hofierka 2004, "A new GIS-based solar
 * radiation model and its application to photovoltaic assessments",
 * Transactions in GIS 8(2):175-190; r.sun's rsunlib.c brad() and drad()
 * for a horizontal plane).  Pure math: no GDAL, no globals.
 *
 *   G0       = I0 eps(j), I0 = 1367 W/m^2, eps = 1 + 0.03344 cos(2 pi j /
 *              365.25 - 0.048869) (j the day of the year; r.sun's
 *              com_sol_const: perihelion on 2 January 20:18)
 *   h0ref    = h0 + dh, dh = 0.061359 (0.1594 + 1.1230 h0 + 0.065656 h0^2)
 *              / (1 + 28.9344 h0 + 277.3971 h0^2), radians (ESRA's
 *              refraction of the true elevation h0, for the air mass only)
 *   m        = (p/p0) / (sin h0ref + 0.50572 (h0ref + 6.07995 deg)^-1.6364),
 *              Kasten & Young 1989, p/p0 = exp(-z / 8434.5 m) at the site's
 *              elevation z
 *   dR(m)    = 1 / (6.6296 + 1.7513 m - 0.1202 m^2 + 0.0065 m^3 -
 *              0.00013 m^4) for m <= 20, 1 / (10.4 + 0.718 m) above: the
 *              Rayleigh optical thickness (Kasten 1996, as ESRA fits it)
 *   B0c      = G0 exp(-0.8662 TLK m dR(m)), the beam normal irradiance
 *   Tn       = -0.015843 + 0.030543 TLK + 0.0003797 TLK^2, the diffuse
 *              transmission at the zenith
 *   Fd(h0)   = A1 + A2 sin h0 + A3 sin^2 h0, the diffuse angular function:
 *              A1' = 0.26463 - 0.061581 TLK + 0.0031408 TLK^2, A1 = 0.0022 /
 *              Tn where A1' Tn < 0.0022 (else A1'), A2 = 2.04020 + 0.018945
 *              TLK - 0.011161 TLK^2, A3 = -1.3025 + 0.039231 TLK + 0.0085079
 *              TLK^2
 *   Dhc      = G0 Tn Fd(h0), the diffuse horizontal irradiance
 *
 * h0 is the true (airless) solar elevation, solar_position.h's
 * elevation_true_deg: the model adds its own refraction for the air mass,
 * and Fd and the beam on the horizontal (B0c sin h0) take h0 itself, as
 * r.sun does.  Below the horizon (h0 <= 0) both are 0: r.sun sums only
 * from sunrise to sunset, so the beam does not fade to 0 at h0 = 0 (about
 * 118 W/m^2 normal, 0 on the horizontal) and the diffuse steps from about
 * 12 W/m^2 to 0 (TLK 3, March).  TLK, the Linke turbidity for an air mass of 2,
 * is 1 for a clean dry atmosphere, 2-3 for clean mountain air, 3-5 in
 * rural Europe, above 6 in cities (r.sun's default 3.0); the fits hold for
 * about 2-7.  Irradiances in W/m^2.
 */
#ifndef HFS_CLEAR_SKY_H
#define HFS_CLEAR_SKY_H

#define HFS_SOLAR_CONSTANT_WM2 1367.0 /* I0, r.sun's default */
#define HFS_LINKE_DEFAULT 3.0         /* r.sun's default TLK */
#define HFS_LINKE_MIN 1.0             /* a clean dry atmosphere */
#define HFS_LINKE_MAX 10.0            /* Tn and Fd stay positive to here */

/* G0 of day of the year j (1..366, fractional allowed): I0 eps(j). */
double hfs_esra_extraterrestrial(double day_of_year);

/* ESRA's refraction dh (degrees) of a true elevation h0_deg (>= 0). */
double hfs_esra_refraction_deg(double h0_deg);

/* m of the true elevation h0_deg (> 0) at a site site_elevation_m above
 * sea level (with ESRA's refraction). */
double hfs_esra_air_mass(double h0_deg, double site_elevation_m);

/* dR(m), the Rayleigh optical thickness of relative air mass m (> 0). */
double hfs_esra_rayleigh(double m);

/* The model with the extraterrestrial irradiance given, g0_wm2 (I0 / R^2
 * from solar_position.h, or hfs_esra_extraterrestrial): the beam normal
 * and the diffuse horizontal irradiances of a sun at true elevation
 * sun_elevation_deg (-90..90) over a site site_elevation_m (-1000..9000 m)
 * above sea level with Linke turbidity linke (HFS_LINKE_MIN..MAX).  0, or
 * -1 for an argument out of its range or not finite (outputs left). */
int hfs_clear_sky_g0(double sun_elevation_deg, double site_elevation_m, double linke,
                     double g0_wm2, double *beam_normal_wm2, double *diffuse_horizontal_wm2);

/* The same with G0 of day of the year day_of_year (1 <= j < 367), as
 * r.sun: its beam and diffuse on a horizontal plane (the beam on the
 * horizontal is *beam_normal_wm2 times sin of the elevation). */
int hfs_clear_sky(double sun_elevation_deg, double site_elevation_m, double linke,
                  double day_of_year, double *beam_normal_wm2, double *diffuse_horizontal_wm2);

#endif /* HFS_CLEAR_SKY_H */
