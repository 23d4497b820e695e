/*
 * solar_position.h — where the sun is, for `hfshade sun` and `hfshade
 * insolation` (issue 39; SPEC.md "Terrain rasters (GIS products)": "Sun
 * position ... by a published algorithm ... checked against its published
 * reference values").  Pure math: no GDAL, no renderer, no globals.
 *
 * Algorithm: NOAA's solar calculator (Global Monitoring Laboratory, the
 * spreadsheet NOAA_Solar_Calculations_day.xls and its web calculator),
 * which is the low-accuracy sun of Meeus, "Astronomical Algorithms" (2nd
 * ed., 1998): ch. 25 (the geometric mean longitude and anomaly, the
 * equation of the centre, the apparent longitude), ch. 22 (the obliquity),
 * ch. 28 eq. 28.3 (Smart's equation of time), the hour angle from the
 * true solar time, and NOAA's piecewise refraction.  Chosen over NREL's
 * SPA (Reda & Andreas 2004, Solar Energy 76(5):577-589) because it is
 * about 60 lines against SPA's VSOP87 and nutation tables (some 260 rows
 * to transcribe and check), and its error is below what a shadow on a
 * DEM can show: Meeus gives this sun as good to 0.01 deg, and on SPA's own
 * example it is 0.0026 deg off in zenith and 0.0023 deg in azimuth
 * (tests/test_solar.c); at a 10 deg sun 0.01 deg moves the shadow of a
 * 100 m ridge by 0.6 m, and near the horizon refraction varies with the
 * weather by tenths of a degree, ten times more.
 * Two additions to NOAA's sheet, both from SPA's steps: the topocentric
 * parallax (SPA eq. 39-41 to first order: the elevation drops by
 * 8.794 arcsec / R cos(e), at most 0.0025 deg), and the refraction scaled
 * by the site's air, (p / 1010 hPa) (283.15 K / T) (Meeus ch. 16; SPA
 * eq. 42), p by default the standard atmosphere's at the site's elevation.
 * Not modelled: delta T (NOAA, too, takes UT for the ephemeris time: 70 s
 * moves the sun by 0.0008 deg) and the polar motion / UT1 (< 1 s).
 *
 * Conventions: latitude north positive, longitude east positive, degrees;
 * azimuth in compass degrees, clockwise from north, in [0, 360) (SPEC
 * "Azimuths for map users": SPEC's phi = azimuth - 90 deg on a north-up
 * grid, gis_phi_of(az, GIS_COMPASS)).  Times are UTC (UT1 = UTC, < 0.9 s).
 *
 * What to use for what:
 *   elevation_deg       the apparent (refracted) topocentric elevation: the
 *                       direction light arrives from, so the one that casts
 *                       shadows on terrain (and the one `hfshade sun` uses);
 *   elevation_true_deg  the airless topocentric elevation: the h0 of the
 *                       ESRA clear-sky model (clear_sky.h), which adds its
 *                       own refraction for the air mass, as GRASS r.sun;
 *   distance_factor     (1 AU / R)^2: the extraterrestrial irradiance is
 *                       the solar constant times it.
 * Valid for the years HFS_SOLAR_YEAR_MIN..HFS_SOLAR_YEAR_MAX.
 */
#ifndef HFS_SOLAR_POSITION_H
#define HFS_SOLAR_POSITION_H

#include <stddef.h>

/* The years accepted: Meeus's series hold for centuries, but delta T,
 * which NOAA leaves out, is known (or predicted within a minute) only
 * around now. */
#define HFS_SOLAR_YEAR_MIN 1900
#define HFS_SOLAR_YEAR_MAX 2100

/* A UTC instant on the Gregorian calendar. */
typedef struct hfs_solar_time {
    int year;      /* HFS_SOLAR_YEAR_MIN..HFS_SOLAR_YEAR_MAX */
    int month;     /* 1..12 */
    int day;       /* 1..days in the month */
    int hour;      /* 0..23 */
    int minute;    /* 0..59 */
    double second; /* [0, 61): 60.x is a leap second */
} hfs_solar_time;

/* Where the observer stands.  Zero means default for the atmosphere. */
typedef struct hfs_solar_site {
    double lat_deg;       /* -90..90, north positive */
    double lon_deg;       /* -360..360, east positive (enters as lon/15 h) */
    double elevation_m;   /* above sea level, -1000..9000 m */
    double pressure_hpa;  /* 0: 1010 hPa exp(-elevation_m / 8434.5 m) */
    double temperature_k; /* 0: 283.15 K (10 C) */
} hfs_solar_site;

/* Meeus ch. 25's sun at one instant (NOAA's columns I..V), for the
 * position and for the test against Meeus's worked examples. */
typedef struct hfs_solar_ephemeris {
    double mean_longitude_deg;     /* L0, in [0, 360) */
    double mean_anomaly_deg;       /* M, in [0, 360) */
    double eccentricity;           /* e of the earth's orbit */
    double center_deg;             /* C, the equation of the centre */
    double true_longitude_deg;     /* L0 + C, geometric */
    double apparent_longitude_deg; /* with nutation and aberration */
    double obliquity_deg;          /* the mean obliquity + 0.00256 cos(Omega) */
    double right_ascension_deg;    /* apparent, in [0, 360) */
    double declination_deg;        /* apparent */
    double distance_au;            /* R, sun-earth */
    double equation_of_time_min;   /* apparent - mean solar time, minutes */
} hfs_solar_ephemeris;

typedef struct hfs_solar_angles {
    double zenith_deg;           /* 90 - elevation_deg */
    double elevation_deg;        /* apparent: true + refraction_deg */
    double elevation_true_deg;   /* topocentric, airless */
    double refraction_deg;       /* NOAA's, scaled by the site's air */
    double azimuth_deg;          /* compass, [0, 360) */
    double hour_angle_deg;       /* [-180, 180), 0 at local solar noon, + west */
    double declination_deg;      /* geocentric, apparent */
    double equation_of_time_min; /* minutes */
    double distance_au;          /* R */
    double distance_factor;      /* 1 / R^2 (R in AU) */
} hfs_solar_angles;

/* Days in month (1..12) of year (Gregorian leap years); 0 for a bad month. */
int hfs_solar_days_in_month(int year, int month);

/* 0 when every field of t is in its range (above), else -1 with a
 * one-line message in msg (msg_size bytes, NULL allowed). */
int hfs_solar_time_check(const hfs_solar_time *t, char *msg, size_t msg_size);

/* The Julian day of t (Meeus ch. 7, Gregorian), e.g. 2451545.0 for
 * 2000-01-01T12:00Z.  t must pass hfs_solar_time_check. */
double hfs_solar_julian_day(const hfs_solar_time *t);

/* The day of the year of t, 1.0 at 00:00 on 1 January, with the day's
 * fraction (the `j` of the ESRA model, clear_sky.h). */
double hfs_solar_day_of_year(const hfs_solar_time *t);

/* The sun of Meeus ch. 25 at Julian day jd (taken as ephemeris time). */
void hfs_solar_ephemeris_at(double jd, hfs_solar_ephemeris *out);

/* NOAA's refraction (degrees, >= 0 down to the horizon) of a sun at the
 * airless elevation elevation_true_deg, in air at pressure_hpa (> 0) and
 * temperature_k (> 0): Meeus's tan series above 5 deg, NOAA's polynomial
 * fit from 5 down to -0.575 deg and its continuation, -20.772" / tan(e),
 * below (which matters only for a sun seen from above the horizontal
 * plane, e.g. from a summit); 0 above 85 deg.  The sheet's value at 1010
 * hPa and 283.15 K, scaled by (p / 1010) (283.15 / T). */
double hfs_solar_refraction_deg(double elevation_true_deg, double pressure_hpa,
                                double temperature_k);

/* The sun seen from site at the UTC Julian day jd_utc (a loop over a day
 * steps jd_utc by step_s / 86400).  0, or -1 when a site value is out of
 * its range or jd_utc outside the years accepted (*out left as is). */
int hfs_solar_position_jd(double jd_utc, const hfs_solar_site *site, hfs_solar_angles *out);

/* The same at the UTC instant utc; -1 also when utc fails
 * hfs_solar_time_check. */
int hfs_solar_position(const hfs_solar_time *utc, const hfs_solar_site *site,
                       hfs_solar_angles *out);

/* A time-zone offset, as `--timezone` takes it, into minutes east of UTC:
 * "Z", "0", "+02:00", "+0200", "+02", "-5", "+5:30", "-03:30".  The sign
 * is required (POSIX TZ strings count west positive; ISO 8601, and this,
 * east), |offset| <= 14:00, minutes 0..59.  0, or -1 with a one-line
 * message. */
int hfs_solar_parse_offset(const char *tz, int *minutes_east, char *msg, size_t msg_size);

/* An ISO 8601 local date-time, "2026-06-21T09:30", "2026-06-21 09:30:15",
 * "2026-06-21T09:30:15.5", optionally ending in its own offset ("Z",
 * "+02:00", "-0500"), with the time zone tz (hfs_solar_parse_offset's
 * forms; NULL or "" when the date-time carries its offset), into the UTC
 * instant *utc (the day, month and year carried across midnight).  The
 * offset must come from one of the two, or from both when they agree.
 * Ranges: month 1..12, day 1..the month's days (leap years), hour 0..23,
 * minute 0..59, second 0..60 (60: a leap second), year
 * HFS_SOLAR_YEAR_MIN..HFS_SOLAR_YEAR_MAX.  0, or -1 with a one-line
 * message naming the bad part (*utc left as is). */
int hfs_solar_parse_local(const char *datetime, const char *tz, hfs_solar_time *utc, char *msg,
                          size_t msg_size);

#endif /* HFS_SOLAR_POSITION_H */
