/*
 * julian_day.c — `python_julian_day DATETIME...`: the UTC Julian day the
 * commands take for each date-time (tools/cli_gis.c: hfs_solar_parse_local,
 * then hfs_solar_julian_day), one "DATETIME %a" line each, for
 * tests/python/test_sun.py to compare with libhfshade_gis's
 * hfs_gis_julian_day of the same instant as POSIX seconds (the path of
 * hfshade.sun and hfshade.insolation): the same double, bit for bit, is
 * what makes their rasters the command's.  Exit 1 on a date-time the
 * parser refuses.
 */
#include "solar_position.h"

#include <stdio.h>

int main(int argc, char **argv)
{
    for (int i = 1; i < argc; ++i) {
        hfs_solar_time t;
        char msg[200];
        if (hfs_solar_parse_local(argv[i], NULL, &t, msg, sizeof msg)) {
            fprintf(stderr, "python_julian_day: %s\n", msg);
            return 1;
        }
        printf("%s %a\n", argv[i], hfs_solar_julian_day(&t));
    }
    return 0;
}
