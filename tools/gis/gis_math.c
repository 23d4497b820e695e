/*
 * gis_math.c — see gis_math.h.  Sums are kept in double: a 1024-direction
 * mean of float terms would otherwise lose the last digits of a sky-view
 * factor near 1.
 */
#include "gis_math.h"

#include "hfshade.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define PI 3.14159265358979323846
#define RAD (PI / 180.0)

const char *gis_convention_name(gis_convention c)
{
    return c == GIS_CCW_EAST ? "ccw-east" : c == GIS_COMPASS ? "compass" : NULL;
}

double gis_phi_of(double deg, gis_convention c)
{
    return (c == GIS_COMPASS ? deg - 90.0 : -deg) * RAD;
}

double gis_grid_phi(double map_phi, int ex, int ey)
{
    if (ex > 0 && ey > 0)
        return map_phi; /* north-up: the map's axes are the grid's */
    return atan2(ey * sin(map_phi), ex * cos(map_phi));
}

int gis_horizon_none(float gamma)
{
    return gamma <= HFS_HORIZON_NONE + 1e-5f;
}

void gis_svf_add(double *acc, const float *gamma, size_t n, gis_svf_kind kind)
{
    for (size_t p = 0; p < n; ++p) {
        const double g = gamma[p] > 0.0f ? (double)gamma[p] : 0.0;
        const double c = cos(g);
        acc[p] += kind == GIS_SVF_LAMBERTIAN ? c * c : sin(g);
    }
}

void gis_svf_finish(float *out, const double *acc, size_t n, int n_dirs, gis_svf_kind kind)
{
    for (size_t p = 0; p < n; ++p) {
        const double mean = acc[p] / n_dirs;
        out[p] = (float)(kind == GIS_SVF_LAMBERTIAN ? mean : 1.0 - mean);
    }
}

void gis_openness_add(double *sum, int *count, const float *gamma, size_t n)
{
    for (size_t p = 0; p < n; ++p)
        if (!gis_horizon_none(gamma[p])) {
            sum[p] += 90.0 - gamma[p] / RAD;
            ++count[p];
        }
}

void gis_openness_finish(float *out, const double *sum, const int *count, size_t n)
{
    for (size_t p = 0; p < n; ++p)
        out[p] = count[p] > 0 ? (float)(sum[p] / count[p]) : NAN;
}

void gis_horizon_degrees(float *out, const float *gamma, size_t n)
{
    for (size_t p = 0; p < n; ++p)
        out[p] = gamma[p] > 0.0f ? (float)(gamma[p] / RAD) : 0.0f;
}

float gis_nodata_for(int has_nodata, double nodata, double lo, double hi)
{
    if (!has_nodata || !(isnan(nodata) || fabs(nodata) <= FLT_MAX))
        return GIS_NODATA; /* none, or beyond a Float32 */
    const float v = (float)nodata;
    return isnan(v) || v < lo || v > hi ? v : GIS_NODATA;
}

double gis_wrap_degrees(double deg)
{
    double a = fmod(deg, 360.0);
    if (a < 0.0)
        a += 360.0;
    return a >= 360.0 ? 0.0 : a; /* fmod(-1e-17, 360) + 360 rounds to 360 */
}

int gis_horizon_name(char *buf, size_t n, const char *prefix, double deg, int decimals)
{
    const int width = 3 + (decimals > 0 ? decimals + 1 : 0);
    const size_t lead = strlen(prefix) + 1; /* the suffix starts after "PREFIX_" */
    const int m = snprintf(buf, n, "%s_%0*.*f.tif", prefix, width, decimals,
                           gis_wrap_degrees(deg));
    if (m < 0 || (size_t)m >= n)
        return -1;
    char *dot = strchr(buf + lead, '.');
    if (decimals > 0 && dot)
        *dot = '_'; /* the number's dot; the extension's stays */
    return 0;
}

int gis_decimals_of(const char *number)
{
    const char *dot = strchr(number, '.');
    if (!dot)
        return 0;
    int d = 0;
    for (const char *c = dot + 1; *c >= '0' && *c <= '9'; ++c)
        ++d;
    return d;
}

int gis_disk_cut(double elev, double alpha, float gamma)
{
    return !gis_horizon_none(gamma) && gamma > (float)(elev - alpha) &&
           gamma < (float)(elev + alpha);
}

double gis_disk_visible(const double n[3], double phi, double elev, double alpha, float gamma)
{
    if (!gis_disk_cut(elev, alpha, gamma))
        return gis_horizon_none(gamma) || gamma <= (float)(elev - alpha) ? 1.0 : 0.0;
    /* n . w over the disk, linear in its offsets (u along the azimuth, v
     * up): n.s + alpha (a n.t_u + b n.t_v), (a, b) in the unit disk. */
    const double cp = cos(phi), sp = sin(phi), ce = cos(elev), se = sin(elev);
    const double ns = n[0] * cp * ce + n[1] * sp * ce + n[2] * se;
    const double nu = -n[0] * sp + n[1] * cp;
    const double nv = -n[0] * se * cp - n[1] * se * sp + n[2] * ce;
    if (ns - alpha * sqrt(nu * nu + nv * nv) > 0.0) {
        /* the whole disk in front of the plane: both integrals in closed
         * form.  Over the unit disk the weight's a and b terms vanish (all
         * = pi ns); above the chord b > b0 the a term still does, and the
         * segment's area is acos b0 - b0 sqrt(1 - b0^2), its moment in b
         * the integral of 2 b sqrt(1 - b^2) from b0 to 1. */
        double b0 = ((double)gamma - elev) / alpha;
        b0 = b0 < -1.0 ? -1.0 : b0 > 1.0 ? 1.0 : b0;
        const double c2 = 1.0 - b0 * b0, c = sqrt(c2);
        const double lit = ns * (acos(b0) - b0 * c) + alpha * nv * (2.0 / 3.0) * c2 * c;
        const double v = lit / (PI * ns);
        return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0;
    }
    /* a disk across the plane (a sun grazing the surface): the midpoint
     * grid, its part behind the plane left out */
    double lit = 0.0, all = 0.0;
    for (int y = 0; y < GIS_DISK_GRID; ++y) {
        const double b = (2.0 * y + 1.0) / GIS_DISK_GRID - 1.0;
        const int above = elev + alpha * b > (double)gamma;
        for (int x = 0; x < GIS_DISK_GRID; ++x) {
            const double a = (2.0 * x + 1.0) / GIS_DISK_GRID - 1.0;
            const double w = ns + alpha * (a * nu + b * nv);
            if (a * a + b * b > 1.0 || !(w > 0.0))
                continue;
            all += w;
            lit += above ? w : 0.0;
        }
    }
    return all > 0.0 ? lit / all : 0.0;
}

void gis_sky_add(double *acc, const float *gamma, const float *n, size_t count, double phi)
{
    const double cp = cos(phi), sp = sin(phi);
    for (size_t p = 0; p < count; ++p) {
        const double nx = n[3 * p], ny = n[3 * p + 1], nz = n[3 * p + 2];
        const double nh = nx * cp + ny * sp, t = atan2(-nh, nz);
        const double g = fmax(fmax((double)gamma[p], t), 0.0); /* NONE is -pi/2 */
        const double c = cos(g);
        acc[p] += 0.5 * nz * c * c + nh * (0.5 * (0.5 * PI - g) - 0.25 * sin(2.0 * g));
    }
}

void gis_sky_finish(float *out, const double *acc, size_t count, int n_dirs)
{
    for (size_t p = 0; p < count; ++p)
        out[p] = (float)fmin(fmax(2.0 * acc[p] / n_dirs, 0.0), 1.0);
}

double gis_shadow_reach(double relief, double low)
{
    if (!(low > 0.0))
        return HUGE_VAL;
    const double r = relief / tan(low);
    return isfinite(r) && r >= 0.0 ? r : HUGE_VAL;
}
