/*
 * clear_sky.c — see clear_sky.h.  The coefficients are ESRA's as r.sun's
 * rsunlib.c has them (Rigollier et al. 2000 print the same to the digit);
 * each function is one equation of the header, so a test can pin it.
 */
#include "clear_sky.h"

#include <math.h>

#define PI 3.14159265358979323846
#define RAD (PI / 180.0)
#define SCALE_HEIGHT_M 8434.5 /* p/p0 = exp(-z / 8434.5 m), ESRA and r.sun */

double hfs_esra_extraterrestrial(double day_of_year)
{
    const double day_angle = 2.0 * PI * day_of_year / 365.25;
    return HFS_SOLAR_CONSTANT_WM2 * (1.0 + 0.03344 * cos(day_angle - 0.048869));
}

double hfs_esra_refraction_deg(double h0_deg)
{
    const double h = h0_deg * RAD;
    return 0.061359 * (0.1594 + h * (1.1230 + 0.065656 * h)) /
           (1.0 + h * (28.9344 + 277.3971 * h)) / RAD;
}

double hfs_esra_air_mass(double h0_deg, double site_elevation_m)
{
    const double href_deg = h0_deg + hfs_esra_refraction_deg(h0_deg);
    const double p_p0 = exp(-site_elevation_m / SCALE_HEIGHT_M);
    return p_p0 / (sin(href_deg * RAD) + 0.50572 * pow(href_deg + 6.07995, -1.6364));
}

double hfs_esra_rayleigh(double m)
{
    if (m <= 20.0)
        return 1.0 / (6.6296 + m * (1.7513 + m * (-0.1202 + m * (0.0065 - m * 0.00013))));
    return 1.0 / (10.4 + 0.718 * m);
}

int hfs_clear_sky_g0(double sun_elevation_deg, double site_elevation_m, double linke,
                     double g0_wm2, double *beam_normal_wm2, double *diffuse_horizontal_wm2)
{
    if (!(sun_elevation_deg >= -90.0 && sun_elevation_deg <= 90.0) ||
        !(site_elevation_m >= -1000.0 && site_elevation_m <= 9000.0) ||
        !(linke >= HFS_LINKE_MIN && linke <= HFS_LINKE_MAX) ||
        !(g0_wm2 >= 0.0 && g0_wm2 <= 2.0 * HFS_SOLAR_CONSTANT_WM2))
        return -1;
    if (sun_elevation_deg <= 0.0) { /* r.sun: nothing before sunrise */
        *beam_normal_wm2 = 0.0;
        *diffuse_horizontal_wm2 = 0.0;
        return 0;
    }
    const double m = hfs_esra_air_mass(sun_elevation_deg, site_elevation_m);
    *beam_normal_wm2 = g0_wm2 * exp(-0.8662 * linke * m * hfs_esra_rayleigh(m));

    const double tl = linke;
    const double tn = -0.015843 + tl * (0.030543 + 0.0003797 * tl);
    /* A1 is raised where A1' Tn would fall under 0.0022: ESRA's floor on
     * the diffuse of a sun at the horizon in a very turbid sky. */
    const double a1p = 0.26463 + tl * (-0.061581 + 0.0031408 * tl);
    const double a1 = a1p * tn < 0.0022 ? 0.0022 / tn : a1p;
    const double a2 = 2.04020 + tl * (0.018945 - 0.011161 * tl);
    const double a3 = -1.3025 + tl * (0.039231 + 0.0085079 * tl);
    const double s = sin(sun_elevation_deg * RAD);
    const double fd = a1 + s * (a2 + s * a3);
    *diffuse_horizontal_wm2 = g0_wm2 * tn * fd; /* Tn, Fd > 0 for TLK 1..10 */
    return 0;
}

int hfs_clear_sky(double sun_elevation_deg, double site_elevation_m, double linke,
                  double day_of_year, double *beam_normal_wm2, double *diffuse_horizontal_wm2)
{
    if (!(day_of_year >= 1.0 && day_of_year < 367.0))
        return -1;
    return hfs_clear_sky_g0(sun_elevation_deg, site_elevation_m, linke,
                            hfs_esra_extraterrestrial(day_of_year), beam_normal_wm2,
                            diffuse_horizontal_wm2);
}
