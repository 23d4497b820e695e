/*
 * solar_position.c — see solar_position.h.  NOAA's sheet computes in
 * degrees with RADIANS()/DEGREES() around every sine; here the angles stay
 * degrees in the names (_deg) and turn into radians only inside the
 * trigonometry, so each line reads against the sheet's column.
 */
#include "solar_position.h"

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#define PI 3.14159265358979323846
#define RAD (PI / 180.0)

/* The standard atmosphere of the defaults: the scale height is r.sun's
 * (clear_sky.h's p/p0), so the two modules share one air; 1010 hPa and
 * 283.15 K are the conditions of NOAA's (Meeus's) refraction formula. */
#define SCALE_HEIGHT_M 8434.5
#define REFRACTION_P_HPA 1010.0
#define REFRACTION_T_K 283.15
#define SUN_PARALLAX_DEG (8.794 / 3600.0) /* at 1 AU (SPA eq. 39) */
#define MAX_OFFSET_MIN (14 * 60)          /* UTC+14:00, Line Islands */

static int say(char *msg, size_t msg_size, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Formats the one-line message (when msg is given) and returns -1. */
static int say(char *msg, size_t msg_size, const char *fmt, ...)
{
    if (msg && msg_size) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(msg, msg_size, fmt, ap);
        va_end(ap);
    }
    return -1;
}

static double wrap360(double deg)
{
    double w = fmod(deg, 360.0);
    return w < 0.0 ? w + 360.0 : w;
}

int hfs_solar_days_in_month(int year, int month)
{
    static const int days[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    if (month < 1 || month > 12)
        return 0;
    const int leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    return days[month - 1] + (month == 2 && leap);
}

int hfs_solar_time_check(const hfs_solar_time *t, char *msg, size_t msg_size)
{
    static const char *const names[12] = {"January", "February", "March",     "April",
                                          "May",     "June",     "July",      "August",
                                          "September", "October", "November", "December"};
    if (t->year < HFS_SOLAR_YEAR_MIN || t->year > HFS_SOLAR_YEAR_MAX)
        return say(msg, msg_size, "year %d out of range %d-%d", t->year, HFS_SOLAR_YEAR_MIN,
                   HFS_SOLAR_YEAR_MAX);
    if (t->month < 1 || t->month > 12)
        return say(msg, msg_size, "month %d out of range 1-12", t->month);
    const int dim = hfs_solar_days_in_month(t->year, t->month);
    if (t->day < 1 || t->day > dim)
        return say(msg, msg_size, "day %d out of range: %s %d has %d days", t->day,
                   names[t->month - 1], t->year, dim);
    if (t->hour < 0 || t->hour > 23)
        return say(msg, msg_size, "hour %d out of range 0-23", t->hour);
    if (t->minute < 0 || t->minute > 59)
        return say(msg, msg_size, "minute %d out of range 0-59", t->minute);
    if (!(t->second >= 0.0 && t->second < 61.0))
        return say(msg, msg_size, "second %g out of range 0-60", t->second);
    return 0;
}

double hfs_solar_julian_day(const hfs_solar_time *t)
{
    /* Meeus eq. 7.1: January and February count as months 13 and 14 of
     * the year before, so the leap day falls at the end of the count. */
    int y = t->year, m = t->month;
    if (m <= 2) {
        y -= 1;
        m += 12;
    }
    const int a = y / 100;
    const int b = 2 - a + a / 4; /* the Gregorian correction (y > 0 here) */
    const double day =
        t->day + (t->hour + (t->minute + t->second / 60.0) / 60.0) / 24.0;
    return floor(365.25 * (y + 4716)) + floor(30.6001 * (m + 1)) + day + b - 1524.5;
}

double hfs_solar_day_of_year(const hfs_solar_time *t)
{
    hfs_solar_time jan1 = {t->year, 1, 1, 0, 0, 0.0};
    return 1.0 + hfs_solar_julian_day(t) - hfs_solar_julian_day(&jan1);
}

void hfs_solar_ephemeris_at(double jd, hfs_solar_ephemeris *out)
{
    /* NOAA's columns G..V; t in Julian centuries from J2000.0. */
    const double t = (jd - 2451545.0) / 36525.0;
    const double l0 = wrap360(280.46646 + t * (36000.76983 + t * 0.0003032));
    const double m = wrap360(357.52911 + t * (35999.05029 - 0.0001537 * t));
    const double e = 0.016708634 - t * (0.000042037 + 0.0000001267 * t);
    const double c = sin(m * RAD) * (1.914602 - t * (0.004817 + 0.000014 * t)) +
                     sin(2.0 * m * RAD) * (0.019993 - 0.000101 * t) +
                     sin(3.0 * m * RAD) * 0.000289;
    const double true_long = l0 + c, true_anom = m + c;
    const double r = 1.000001018 * (1.0 - e * e) / (1.0 + e * cos(true_anom * RAD));
    /* Omega, the moon's ascending node, drives the main nutation term. */
    const double omega = 125.04 - 1934.136 * t;
    const double app_long = true_long - 0.00569 - 0.00478 * sin(omega * RAD);
    const double eps0 =
        23.0 + (26.0 + (21.448 - t * (46.815 + t * (0.00059 - t * 0.001813))) / 60.0) / 60.0;
    const double eps = eps0 + 0.00256 * cos(omega * RAD);
    const double ra = atan2(cos(eps * RAD) * sin(app_long * RAD), cos(app_long * RAD)) / RAD;
    const double dec = asin(sin(eps * RAD) * sin(app_long * RAD)) / RAD;
    /* Meeus eq. 28.3 (Smart), with y = tan^2(eps / 2). */
    const double y = tan(eps * RAD / 2.0) * tan(eps * RAD / 2.0);
    const double eot_rad = y * sin(2.0 * l0 * RAD) - 2.0 * e * sin(m * RAD) +
                           4.0 * e * y * sin(m * RAD) * cos(2.0 * l0 * RAD) -
                           0.5 * y * y * sin(4.0 * l0 * RAD) - 1.25 * e * e * sin(2.0 * m * RAD);
    out->mean_longitude_deg = l0;
    out->mean_anomaly_deg = m;
    out->eccentricity = e;
    out->center_deg = c;
    out->true_longitude_deg = true_long;
    out->apparent_longitude_deg = app_long;
    out->obliquity_deg = eps;
    out->right_ascension_deg = wrap360(ra);
    out->declination_deg = dec;
    out->distance_au = r;
    out->equation_of_time_min = 4.0 * eot_rad / RAD; /* 4 minutes of time a degree */
}

double hfs_solar_refraction_deg(double elevation_true_deg, double pressure_hpa,
                                double temperature_k)
{
    /* NOAA's column AF, in arc seconds: Meeus's tan series above 5 deg,
     * a polynomial fit down to -0.575 deg, and its continuation below. */
    const double e = elevation_true_deg;
    if (e > 85.0)
        return 0.0;
    const double te = tan(e * RAD);
    double arcsec;
    if (e > 5.0)
        arcsec = 58.1 / te - 0.07 / (te * te * te) + 0.000086 / (te * te * te * te * te);
    else if (e > -0.575)
        arcsec = 1735.0 + e * (-518.2 + e * (103.4 + e * (-12.79 + e * 0.711)));
    else
        arcsec = -20.772 / te;
    return arcsec / 3600.0 * (pressure_hpa / REFRACTION_P_HPA) * (REFRACTION_T_K / temperature_k);
}

static int site_ok(const hfs_solar_site *s)
{
    return s->lat_deg >= -90.0 && s->lat_deg <= 90.0 && s->lon_deg >= -360.0 &&
           s->lon_deg <= 360.0 && s->elevation_m >= -1000.0 && s->elevation_m <= 9000.0 &&
           s->pressure_hpa >= 0.0 && s->pressure_hpa <= 1200.0 && s->temperature_k >= 0.0 &&
           s->temperature_k <= 400.0 && (s->temperature_k == 0.0 || s->temperature_k >= 150.0);
}

int hfs_solar_position_jd(double jd_utc, const hfs_solar_site *site, hfs_solar_angles *out)
{
    const hfs_solar_time lo = {HFS_SOLAR_YEAR_MIN, 1, 1, 0, 0, 0.0};
    const hfs_solar_time hi = {HFS_SOLAR_YEAR_MAX + 1, 1, 1, 0, 0, 0.0};
    if (!site_ok(site) || !(jd_utc >= hfs_solar_julian_day(&lo)) ||
        !(jd_utc < hfs_solar_julian_day(&hi)))
        return -1;
    hfs_solar_ephemeris eph;
    hfs_solar_ephemeris_at(jd_utc, &eph);
    /* The hour angle from the true solar time (NOAA's AB, AC): UT
     * minutes of the day, plus the equation of time, plus 4 minutes per
     * degree east. */
    const double ut_min = (jd_utc + 0.5 - floor(jd_utc + 0.5)) * 1440.0;
    const double tst_min = ut_min + eph.equation_of_time_min + 4.0 * site->lon_deg;
    const double h_deg = wrap360(tst_min / 4.0) - 180.0;
    const double lat = site->lat_deg * RAD, dec = eph.declination_deg * RAD, h = h_deg * RAD;
    const double cos_z = sin(lat) * sin(dec) + cos(lat) * cos(dec) * cos(h);
    const double e_geo = 90.0 - acos(fmax(-1.0, fmin(1.0, cos_z))) / RAD;
    /* Meeus eq. 13.5 (from south, westward) turned to compass; atan2
     * rather than the sheet's acos, which loses digits near the zenith
     * and is undefined at the poles. */
    const double az_south =
        atan2(cos(dec) * sin(h), cos(dec) * cos(h) * sin(lat) - sin(dec) * cos(lat));
    const double e_true = e_geo - SUN_PARALLAX_DEG / eph.distance_au * cos(e_geo * RAD);
    const double p_hpa = site->pressure_hpa > 0.0
                             ? site->pressure_hpa
                             : REFRACTION_P_HPA * exp(-site->elevation_m / SCALE_HEIGHT_M);
    const double t_k = site->temperature_k > 0.0 ? site->temperature_k : REFRACTION_T_K;
    const double refr = hfs_solar_refraction_deg(e_true, p_hpa, t_k);
    out->elevation_true_deg = e_true;
    out->refraction_deg = refr;
    out->elevation_deg = e_true + refr;
    out->zenith_deg = 90.0 - out->elevation_deg;
    out->azimuth_deg = wrap360(az_south / RAD + 180.0);
    out->hour_angle_deg = h_deg;
    out->declination_deg = eph.declination_deg;
    out->equation_of_time_min = eph.equation_of_time_min;
    out->distance_au = eph.distance_au;
    out->distance_factor = 1.0 / (eph.distance_au * eph.distance_au);
    return 0;
}

int hfs_solar_position(const hfs_solar_time *utc, const hfs_solar_site *site,
                       hfs_solar_angles *out)
{
    if (hfs_solar_time_check(utc, NULL, 0))
        return -1;
    return hfs_solar_position_jd(hfs_solar_julian_day(utc), site, out);
}

/* ---- parsing ---------------------------------------------------------- */

/* Reads n_min..n_max decimal digits at *p into *v, advancing *p; 0 when
 * fewer than n_min digits are there. */
static int digits(const char **p, int n_min, int n_max, int *v)
{
    int n = 0, x = 0;
    while (n < n_max && isdigit((unsigned char)(*p)[n]))
        x = 10 * x + ((*p)[n++] - '0');
    if (n < n_min)
        return 0;
    *p += n;
    *v = x;
    return 1;
}

/* The offset at *p (see hfs_solar_parse_offset), advancing *p past it;
 * leaves *p at the first character it could not use.  what names the
 * input in the message: "time zone" or "date-time". */
static int offset_at(const char **p, int *minutes_east, const char *what, const char *whole,
                     char *msg, size_t msg_size)
{
    const char *s = *p;
    if (*s == 'Z' || *s == 'z') {
        *minutes_east = 0;
        *p = s + 1;
        return 0;
    }
    if (*s != '+' && *s != '-')
        return say(msg, msg_size,
                   "%s '%.40s': expected Z or a signed offset (+02:00, -05:00, -5; east of "
                   "Greenwich is +)", what, whole);
    const int sign = *s++ == '-' ? -1 : 1;
    int hh = 0, mm = 0;
    const char *start = s;
    if (!digits(&s, 1, 2, &hh))
        return say(msg, msg_size, "%s '%.40s': no hours after the sign", what, whole);
    if (*s == ':') {
        ++s;
        if (!digits(&s, 2, 2, &mm))
            return say(msg, msg_size, "%s '%.40s': expected two digits of minutes", what,
                           whole);
    } else if (s - start == 2 && isdigit((unsigned char)*s)) {
        if (!digits(&s, 2, 2, &mm)) /* +HHMM */
            return say(msg, msg_size, "%s '%.40s': expected +HHMM", what, whole);
    }
    if (mm > 59)
        return say(msg, msg_size, "%s '%.40s': minutes %d out of range 0-59", what, whole,
                   mm);
    if (hh * 60 + mm > MAX_OFFSET_MIN)
        return say(msg, msg_size, "%s '%.40s': offset beyond +-14:00", what, whole);
    *minutes_east = sign * (hh * 60 + mm);
    *p = s;
    return 0;
}

int hfs_solar_parse_offset(const char *tz, int *minutes_east, char *msg, size_t msg_size)
{
    if (!tz || !*tz)
        return say(msg, msg_size, "no time zone given");
    const char *p = tz;
    int off = 0;
    if (!strcmp(tz, "0")) { /* no sign needed: +0 and -0 are the same */
        *minutes_east = 0;
        return 0;
    }
    if (offset_at(&p, &off, "time zone", tz, msg, msg_size))
        return -1;
    if (*p)
        return say(msg, msg_size, "time zone '%.40s': unexpected '%.10s'", tz, p);
    *minutes_east = off;
    return 0;
}

/* The date and time of day at the start of s into *t; *p past them. */
static int date_time_at(const char **p, hfs_solar_time *t, const char *whole, char *msg,
                        size_t msg_size)
{
    const char *s = *p;
    if (!digits(&s, 4, 4, &t->year) || *s++ != '-' || !digits(&s, 2, 2, &t->month) ||
        *s++ != '-' || !digits(&s, 2, 2, &t->day))
        return say(msg, msg_size, "date-time '%.40s': expected YYYY-MM-DDTHH:MM[:SS]", whole);
    if (*s != 'T' && *s != 't' && *s != ' ')
        return say(msg, msg_size, "date-time '%.40s': expected 'T' and a time after the date",
                   whole);
    ++s;
    if (!digits(&s, 2, 2, &t->hour) || *s++ != ':' || !digits(&s, 2, 2, &t->minute))
        return say(msg, msg_size, "date-time '%.40s': expected HH:MM after the date", whole);
    t->second = 0.0;
    if (*s == ':') {
        int whole_s = 0;
        ++s;
        if (!digits(&s, 2, 2, &whole_s))
            return say(msg, msg_size, "date-time '%.40s': expected two digits of seconds", whole);
        t->second = whole_s;
        if (*s == '.' || *s == ',') { /* ISO 8601 allows either mark */
            double scale = 0.1;
            if (!isdigit((unsigned char)*++s))
                return say(msg, msg_size, "date-time '%.40s': no digits after the decimal mark",
                           whole);
            for (; isdigit((unsigned char)*s); ++s, scale *= 0.1)
                t->second += (*s - '0') * scale;
        }
    }
    *p = s;
    return 0;
}

/* *t moved by -minutes_east: local time to UTC, across days, months and
 * years (days counted from 1970-01-01, Hinnant's days_from_civil). */
static void to_utc(hfs_solar_time *t, int minutes_east)
{
    const int y = t->year - (t->month <= 2);
    const int era = y / 400; /* y >= 1899 here: no negative years */
    const int yoe = y - era * 400;
    const int doy = (153 * (t->month + (t->month > 2 ? -3 : 9)) + 2) / 5 + t->day - 1;
    const int doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    const long days = (long)era * 146097 + doe - 719468;
    const long minutes = days * 1440 + t->hour * 60 + t->minute - minutes_east;
    const long d = (minutes >= 0 ? minutes : minutes - 1439) / 1440; /* floor */
    const long mod = minutes - d * 1440;
    /* ... and back (Hinnant's civil_from_days). */
    const long z = d + 719468;
    const long era2 = z / 146097;
    const long doe2 = z - era2 * 146097;
    const long yoe2 = (doe2 - doe2 / 1460 + doe2 / 36524 - doe2 / 146096) / 365;
    const long doy2 = doe2 - (365 * yoe2 + yoe2 / 4 - yoe2 / 100);
    const long mp = (5 * doy2 + 2) / 153;
    t->day = (int)(doy2 - (153 * mp + 2) / 5 + 1);
    t->month = (int)(mp < 10 ? mp + 3 : mp - 9);
    t->year = (int)(yoe2 + era2 * 400 + (t->month <= 2));
    t->hour = (int)(mod / 60);
    t->minute = (int)(mod % 60);
}

int hfs_solar_parse_local(const char *datetime, const char *tz, hfs_solar_time *utc, char *msg,
                          size_t msg_size)
{
    if (!datetime || !*datetime)
        return say(msg, msg_size, "no date-time given");
    const char *p = datetime;
    hfs_solar_time t;
    if (date_time_at(&p, &t, datetime, msg, msg_size))
        return -1;
    int own = 0, has_own = 0;
    if (*p) {
        if (offset_at(&p, &own, "date-time", datetime, msg, msg_size))
            return -1;
        if (*p)
            return say(msg, msg_size, "date-time '%.40s': unexpected '%.10s'", datetime, p);
        has_own = 1;
    }
    int off = own;
    if (tz && *tz) {
        if (hfs_solar_parse_offset(tz, &off, msg, msg_size))
            return -1;
        if (has_own && off != own)
            return say(msg, msg_size,
                       "date-time '%.40s' carries its own offset, and the time zone '%.20s' "
                       "differs from it", datetime, tz);
    } else if (!has_own) {
        return say(msg, msg_size,
                   "date-time '%.40s' has no time zone: give one (Z, +02:00, -5)", datetime);
    }
    /* The local fields are checked as written, before the shift, so the
     * message names what the user typed. */
    char why[96];
    if (hfs_solar_time_check(&t, why, sizeof why))
        return say(msg, msg_size, "date-time '%.40s': %s", datetime, why);
    to_utc(&t, off);
    if (hfs_solar_time_check(&t, why, sizeof why))
        return say(msg, msg_size, "date-time '%.40s' in UTC: %s", datetime, why);
    *utc = t;
    return 0;
}
