/*
 * cli_gis.c — the GIS commands' command line (cli_gis.h).  One table of
 * options serves the parser (which command takes which option, and
 * whether it takes a value) and the usage, printed GDAL-style (a "Usage:"
 * synopsis, then one option a line).  Values are checked here, before any
 * file is opened; an option given twice is an error, as in `render`.
 */
#include "cli_gis.h"

#include "clear_sky.h"
#include "cli_usage.h"
#include "gis_command.h"
#include "gis_sun.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum {
    SVF = 1 << GIS_SVF,
    HOR = 1 << GIS_HORIZON,
    OPEN = 1 << GIS_OPENNESS,
    SUN = 1 << GIS_SUN,
    INS = 1 << GIS_INSOLATION,
    ALL = SVF | HOR | OPEN | SUN | INS
};

typedef struct gis_opt {
    const char *name, *arg; /* arg NULL: a switch                            */
    unsigned cmds;          /* the commands that take it                     */
    const char *help;
} gis_opt;

static const gis_opt opts[] = {
    {"-o", "OUT.tif", SVF | OPEN | SUN | INS, "the GeoTIFF written (Float32, the DEM's grid)"},
    {"--datetime", "DATETIME", SUN,
     "the local date-time, ISO 8601: 2026-06-21T09:30[:SS], with its offset (Z, +02:00) or "
     "--timezone's"},
    {"--from", "DATETIME", INS, "the period's start, local ISO 8601 date-time (as --datetime)"},
    {"--to", "DATETIME", INS, "the period's end, after --from"},
    {"--step", "MINUTES", INS, "the step, minutes > 0 (default 15); each step's sun at its "
     "middle"},
    {"--timezone", "TZ", SUN | INS,
     "the date-times' offset east of UTC: Z, +02:00, +0530, -5 (unless they carry one)"},
    {"--linke", "TLK", SUN | INS, "Linke turbidity, 1..10 (default 3.0, r.sun's)"},
    {"--relief", "H", SUN | INS, "the DEM's highest minus lowest height, in its own units, as "
     "`hfshade tiles plan` measured it (its jobs are given it): not read from the DEM again"},
    {"-o", "PREFIX", HOR, "the GeoTIFFs written: PREFIX_AAA.tif an azimuth (r.horizon's names)"},
    {"--directions", "N", SVF, "azimuths, equally spaced from east (1..1024; default 16)"},
    {"--directions", "N", OPEN, "azimuths, equally spaced from east (1..1024; default 8)"},
    {"--directions", "N", INS, "the sky's horizons: azimuths, equally spaced from east "
     "(1..1024; default 16)"},
    {"--sky-map", "FILE", INS, "the sky's shape from an equirectangular map (.exr, .hdr, .pfm; "
     "its upper half, luminance), scaled to the clear sky's diffuse; default: isotropic"},
    {"--sky-north", "DEG", INS, "the compass azimuth the map's left edge looks at (default 0: "
     "north; 90: east)"},
    {"--albedo", "A", INS, "the ground's albedo, 0..1: band 3 adds the light the terrain and "
     "the ground reflect onto the texel (r.sun's refl_rad; default 0: none)"},
    {"--beam-only", NULL, INS, "band 1 alone, the beam: the sky's horizons are not searched "
     "(r.sun with beam_rad alone); not with --sky-map, --albedo, --directions"},
    {"--lambertian", NULL, SVF, "the Lambertian-weighted variant, mean cos^2 (SAGA's)"},
    {"--azimuths", "A,B,...", HOR, "these azimuths, degrees (or --step)"},
    {"--step", "DEG", HOR, "every DEG degrees around the circle, in (0, 360]"},
    {"--start", "DEG", HOR, "with --step: the first azimuth (default 0)"},
    {"--convention", "ccw-east|compass", HOR,
     "ccw-east: degrees counter-clockwise from east (GRASS r.horizon's; default); "
     "compass: clockwise from north"},
    {"--radius", "R", SVF | HOR, "search radius, metres (default 0: the whole DEM)"},
    {"--radius", "R", OPEN, "search radius, metres (default 10 cells of the DEM)"},
    {"--radius", "R", SUN | INS, "shadows cast from farther than R metres are left out, "
     "and the sky's horizons searched within R (default 0: as far as terrain can reach)"},
    {"--tile", "N", SVF | HOR | OPEN | SUN | INS,
     "with a radius, a DEM wider or taller than N texels is read, computed and written "
     "window by window, memory bounded (square cells only); 0: always whole (default 4096)"},
    {"--job", "K", SVF | HOR | OPEN | SUN | INS,
     "with --tile: only window K (from 1, row by row) of a DEM that streams, written as a "
     "GeoTIFF of its own extent (what `hfshade tiles run` does for one job)"},
    {"--backend", "gles|cpu|truth", ALL, "GLES renderer (default), CPU reference, ground truth"},
    {"--method", "exact|sweep", ALL, "the horizons: exact, the bilinear surface's supremum on "
     "--backend (default); sweep, on the host, the whole DEM, convex hulls along lines "
     "a texel apart (faster, a few hundredths of a degree off; docs/GIS.md)"},
    {"--zscale", "F", ALL, "heights times F are metres (default 1)"},
    {"--nodata", "V", ALL, "V marks holes (instead of the band's nodata value)"},
    {"--cog", NULL, ALL, "a Cloud Optimized GeoTIFF (GDAL's COG driver)"},
    {"--quiet", NULL, ALL, "no summary line on stderr"},
    {"--help", NULL, ALL, "this text"},
};
#define N_OPTS (sizeof opts / sizeof opts[0])

static const char *const what[] = {
    "Sky-view factor (Zaksek et al. 2011): 1 - mean sin(max(gamma, 0)) over the\n"
    "directions (gamma: the horizon's elevation angle), 1 on a plane; one band.",
    "Horizon elevation angle (GRASS r.horizon -d): degrees above the horizontal,\n"
    "0 where nothing rises above it; one GeoTIFF per azimuth.",
    "Topographic openness (Yokoyama et al. 2002): the mean of 90 - gamma over the\n"
    "directions, degrees, gamma signed (from the texel); band 1 positive, band 2\n"
    "negative openness (the positive openness of the negated DEM).",
    "The sun at one instant (NOAA solar calculator; ESRA clear sky, as GRASS r.sun)\n"
    "on the terrain: band 1 the direct-beam irradiance on the tilted, shadowed\n"
    "surface (W/m^2), band 2 the visible fraction of the sun's disk (0..1).",
    "Clear-sky irradiation over a period (GRASS r.sun's mode 2), Wh/m^2: band 1\n"
    "beam (the sun's renders, one a step), band 2 sky-diffuse (isotropic sky over\n"
    "the terrain's horizons), band 3 global (beam + diffuse); band 1 alone with\n"
    "--beam-only."};

/* The options a command cannot go without: no brackets in its synopsis. */
static int required(const gis_opt *o, gis_product p)
{
    return (p == GIS_SUN && !strcmp(o->name, "--datetime")) ||
           (p == GIS_INSOLATION && (!strcmp(o->name, "--from") || !strcmp(o->name, "--to")));
}

static const gis_opt *find(const char *name, gis_product p)
{
    for (size_t k = 0; k < N_OPTS; ++k)
        if (!strcmp(opts[k].name, name) && (opts[k].cmds & (1u << p)))
            return &opts[k];
    return NULL;
}

/* "  NAME ARG   help", the help wrapped at 79 columns under itself (a NAME
 * ARG too long for its column gets a line of its own). */
static void print_option(const gis_opt *o)
{
    enum { COL = 29, WIDTH = 79 };
    char head[64];
    snprintf(head, sizeof head, "%s%s%s", o->name, o->arg ? " " : "", o->arg ? o->arg : "");
    int col = printf("  %-*s", COL - 3, head);
    if (col > COL - 1) {
        printf("\n");
        col = printf("%*s", COL - 1, "");
    }
    for (const char *w = o->help; *w;) {
        const char *end = strchr(w, ' ');
        const int len = end ? (int)(end - w) : (int)strlen(w);
        if (col + 1 + len > WIDTH)
            col = printf("\n%*s", COL - 1, "") - 1;
        col += printf(" %.*s", len, w);
        w += len + (end ? 1 : 0);
    }
    printf("\n");
}

static void usage(const char *cmd, gis_product p)
{
    char line[512];
    int n = snprintf(line, sizeof line, "Usage: hfshade %s DEM -o %s", cmd,
                     p == GIS_HORIZON ? "PREFIX" : "OUT.tif");
    const int indent = (int)strlen("Usage: hfshade ") + (int)strlen(cmd) + 1;
    for (size_t k = 0; k < N_OPTS; ++k) {
        if (!(opts[k].cmds & (1u << p)) || !strcmp(opts[k].name, "-o") ||
            !strcmp(opts[k].name, "--help"))
            continue;
        char item[96];
        const int req = required(&opts[k], p);
        const int m = snprintf(item, sizeof item, " %s%s%s%s%s", req ? "" : "[", opts[k].name,
                               opts[k].arg ? " " : "", opts[k].arg ? opts[k].arg : "",
                               req ? "" : "]");
        if (n + m > 78) {
            printf("%s\n", line);
            n = snprintf(line, sizeof line, "%*s", indent - 1, "");
        }
        n += snprintf(line + n, sizeof line - (size_t)n, "%s", item);
    }
    printf("%s\n\n%s\nFloat32, on DEM's own grid: its size, geotransform, CRS and nodata\n"
           "(docs/GIS.md).\n\nOptions:\n", line, what[p]);
    for (size_t k = 0; k < N_OPTS; ++k)
        if (opts[k].cmds & (1u << p))
            print_option(&opts[k]);
}

/* --azimuths A,B,...: each in [-1e6, 1e6] degrees, at most 1024. */
static int parse_azimuths(gis_args *a, const char *v)
{
    a->n_azimuths = 0;
    for (const char *s = v; a->n_azimuths <= HFS_MAX_HORIZON_AZIMUTHS;) {
        const char *comma = strchr(s, ',');
        char item[64];
        const size_t len = comma ? (size_t)(comma - s) : strlen(s);
        double x;
        if (len >= sizeof item)
            return -1;
        memcpy(item, s, len);
        item[len] = '\0';
        if (hfs_cli_real(item, -1e6, 1e6, &x))
            return -1;
        if (a->n_azimuths == HFS_MAX_HORIZON_AZIMUTHS)
            return -1;
        a->azimuth[a->n_azimuths++] = x;
        const int d = gis_decimals_of(item);
        a->decimals = d > a->decimals ? d : a->decimals;
        if (!comma)
            return 0;
        s = comma + 1;
    }
    return -1;
}

/* What the options leave to check together. */
typedef struct pending {
    double step, start;               /* horizon                            */
    const char *step_s, *start_s;     /* as given; NULL: not given          */
    const char *datetime, *from, *to; /* sun, insolation: parsed at the end */
    const char *tz;
    const char *sky_north;            /* insolation: --sky-north as given   */
    const char *sky_opt;              /* insolation: the last of the sky's
                                       * options given (--sky-map, --albedo,
                                       * --directions); NULL: none          */
} pending;

/* The sun's options' values; 0, or the usage error's exit status. */
static int set_sun_value(gis_args *a, const char *prog, const char *name, const char *v,
                         pending *st)
{
    if (!strcmp(name, "--datetime")) {
        st->datetime = v;
    } else if (!strcmp(name, "--from")) {
        st->from = v;
    } else if (!strcmp(name, "--to")) {
        st->to = v;
    } else if (!strcmp(name, "--timezone")) {
        st->tz = v;
    } else if (!strcmp(name, "--relief")) {
        if (hfs_cli_real(v, 0.0, FLT_MAX, &a->relief))
            return hfs_usage_error(prog, "--relief: '%s' is not a height difference >= 0", v);
        a->relief_given = 1;
    } else if (!strcmp(name, "--albedo")) {
        if (hfs_cli_real(v, 0.0, 1.0, &a->albedo))
            return hfs_usage_error(prog, "--albedo: '%s' is not an albedo in [0, 1]", v);
    } else if (!strcmp(name, "--sky-map")) {
        a->sky_map = v;
    } else if (!strcmp(name, "--sky-north")) {
        if (hfs_cli_real(v, -360.0, 360.0, &a->sky_north))
            return hfs_usage_error(prog, "--sky-north: '%s' is not an angle in [-360, 360] "
                                   "degrees", v);
        st->sky_north = v;
    } else if (!strcmp(name, "--linke")) {
        if (hfs_cli_real(v, HFS_LINKE_MIN, HFS_LINKE_MAX, &a->linke))
            return hfs_usage_error(prog, "--linke: '%s' is not a Linke turbidity in [%g, %g]", v,
                                   HFS_LINKE_MIN, HFS_LINKE_MAX);
    } else { /* insolation's --step */
        double x = 0.0;
        if (hfs_cli_real(v, 0.0, 1e9, &x) || !(x > 0.0))
            return hfs_usage_error(prog, "--step: '%s' is not a number of minutes above 0", v);
        a->step_min = x;
    }
    return 0;
}

/* One option's value into a; 0, or the usage error's exit status. */
static int set_value(gis_args *a, const char *prog, const char *name, const char *v,
                     pending *st)
{
    long n;
    static const char *const sun_only[] = {"--datetime", "--from", "--to", "--timezone",
                                           "--linke", "--step", "--relief", "--sky-map",
                                           "--sky-north", "--albedo"};
    for (size_t k = 0; k < sizeof sun_only / sizeof sun_only[0]; ++k)
        if ((a->product == GIS_SUN || a->product == GIS_INSOLATION) && !strcmp(name, sun_only[k]))
            return set_sun_value(a, prog, name, v, st);
    if (!strcmp(name, "-o")) {
        a->out = v;
    } else if (!strcmp(name, "--directions")) {
        if (hfs_cli_long(v, 1, HFS_MAX_HORIZON_AZIMUTHS, &n))
            return hfs_usage_error(prog, "--directions: '%s' is not a whole number in [1, %d]",
                                   v, HFS_MAX_HORIZON_AZIMUTHS);
        a->directions = (int)n;
    } else if (!strcmp(name, "--azimuths")) {
        if (parse_azimuths(a, v))
            return hfs_usage_error(prog, "--azimuths: '%s' is not a list of 1 to %d angles in "
                                   "degrees (A,B,...)", v, HFS_MAX_HORIZON_AZIMUTHS);
    } else if (!strcmp(name, "--step") || !strcmp(name, "--start")) {
        const int is_step = !strcmp(name, "--step");
        double x;
        if (hfs_cli_real(v, is_step ? 1e-6 : -1e6, is_step ? 360.0 : 1e6, &x))
            return hfs_usage_error(prog, "%s: '%s' is not %s", name, v,
                                   is_step ? "an angle in (0, 360] degrees"
                                           : "an angle in degrees");
        *(is_step ? &st->step : &st->start) = x;
        *(is_step ? &st->step_s : &st->start_s) = v;
    } else if (!strcmp(name, "--convention")) {
        if (strcmp(v, "ccw-east") && strcmp(v, "compass"))
            return hfs_usage_error(prog, "--convention: '%s' is not ccw-east or compass", v);
        a->convention = !strcmp(v, "compass") ? GIS_COMPASS : GIS_CCW_EAST;
    } else if (!strcmp(name, "--radius")) {
        if (hfs_cli_real(v, 0.0, 1e9, &a->radius))
            return hfs_usage_error(prog, "--radius: '%s' is not a distance in [0, 1e9] metres",
                                   v);
        a->radius_given = 1;
    } else if (!strcmp(name, "--tile")) {
        if (hfs_cli_long(v, 0, GIS_TILE_MAX, &n) || (n > 0 && n < GIS_TILE_MIN))
            return hfs_usage_error(prog, "--tile: '%s' is not 0 or a whole number of texels "
                                   "in [%d, %d]", v, GIS_TILE_MIN, GIS_TILE_MAX);
        a->tile = (int)n;
    } else if (!strcmp(name, "--job")) {
        if (hfs_cli_long(v, 1, 1L << 30, &n))
            return hfs_usage_error(prog, "--job: '%s' is not a window number (1, 2, ...)", v);
        a->job = (int)n;
    } else if (!strcmp(name, "--method")) {
        if (strcmp(v, "exact") && strcmp(v, "sweep"))
            return hfs_usage_error(prog, "--method: '%s' is not exact or sweep", v);
        a->sweep = !strcmp(v, "sweep");
    } else if (!strcmp(name, "--backend")) {
        static const char *const names[] = {"gles", "cpu", "truth"};
        static const hfs_backend b[] = {HFS_BACKEND_GLES, HFS_BACKEND_CPU, HFS_BACKEND_TRUTH};
        int k = 0;
        while (k < 3 && strcmp(v, names[k]))
            ++k;
        if (k == 3)
            return hfs_usage_error(prog, "--backend: '%s' is not gles, cpu or truth", v);
        a->backend = b[k];
    } else if (!strcmp(name, "--zscale")) {
        if (hfs_cli_real(v, 1e-9, 1e6, &a->zscale))
            return hfs_usage_error(prog, "--zscale: '%s' is not a number in [1e-9, 1e6]", v);
    } else { /* --nodata */
        double x;
        if (hfs_cli_real(v, -FLT_MAX, FLT_MAX, &x))
            return hfs_usage_error(prog, "--nodata: '%s' is not a finite number", v);
        a->load.has_nodata = 1, a->load.nodata = (float)x;
    }
    return 0;
}

/* --step's azimuths: START, START + STEP, ... once around the circle. */
static int step_azimuths(gis_args *a, const char *prog, double step, double start,
                         const char *step_s, const char *start_s)
{
    const double count = ceil(360.0 / step - 1e-9);
    if (count > HFS_MAX_HORIZON_AZIMUTHS)
        return hfs_usage_error(prog, "--step: %s degrees makes %.0f azimuths (at most %d)",
                               step_s, count, HFS_MAX_HORIZON_AZIMUTHS);
    a->n_azimuths = (int)count;
    for (int k = 0; k < a->n_azimuths; ++k)
        a->azimuth[k] = start + k * step;
    const int ds = gis_decimals_of(step_s), d0 = start_s ? gis_decimals_of(start_s) : 0;
    a->decimals = ds > d0 ? ds : d0;
    a->decimals = a->decimals > 6 ? 6 : a->decimals;
    return 0;
}

/* A local date-time of flag into the UTC instant *t and its Julian day. */
static int instant(const char *prog, const char *flag, const char *v, const char *tz,
                   hfs_solar_time *t, double *jd)
{
    char msg[200];
    if (!v)
        return hfs_usage_error(prog, "no %s given (a date-time: %s 2026-06-21T09:30 --timezone "
                               "+02:00)", flag, flag);
    if (hfs_solar_parse_local(v, tz, t, msg, sizeof msg))
        return hfs_usage_error(prog, "%s: %s", flag, msg);
    *jd = hfs_solar_julian_day(t);
    return 0;
}

/* sun: the instant; insolation: the period and its steps. */
static int check_sun(gis_args *a, const char *prog, const pending *st)
{
    if (a->product == GIS_SUN)
        return instant(prog, "--datetime", st->datetime, st->tz, &a->at, &a->jd);
    int rc = instant(prog, "--from", st->from, st->tz, &a->from, &a->jd_from);
    if (!rc)
        rc = instant(prog, "--to", st->to, st->tz, &a->to, &a->jd_to);
    if (rc)
        return rc;
    double minutes, steps;
    gis_period_length(a->jd_from, a->jd_to, a->step_min, &minutes, &steps);
    if (!(minutes > 0.0))
        return hfs_usage_error(prog, "--to: %s is not after --from %s", st->to, st->from);
    if (steps > GIS_MAX_STEPS)
        return hfs_usage_error(prog, "--step: %g minutes over %g minutes makes %.0f steps (at "
                               "most %ld)", a->step_min, minutes, steps, GIS_MAX_STEPS);
    a->n_steps = (long)steps;
    return 0;
}

/* What the options left to check together. */
static int check_args(gis_args *a, const char *prog, const pending *st)
{
    if (!a->dem)
        return hfs_usage_error(prog, "no DEM given");
    if (!a->out)
        return hfs_usage_error(prog, "no output given (-o %s)",
                               a->product == GIS_HORIZON ? "PREFIX" : "OUT.tif");
    if ((a->product == GIS_SUN || a->product == GIS_INSOLATION) && a->radius_given &&
        a->backend == HFS_BACKEND_TRUTH)
        return hfs_usage_error(prog, "--radius: not with --backend truth (the truth renders the "
                               "sun's exact shadows from the whole DEM)");
    if (a->sweep && a->backend == HFS_BACKEND_TRUTH)
        return hfs_usage_error(prog, "--method sweep: not with --backend truth (the truth is "
                               "exact)");
    if (a->sweep && (a->radius_given ? a->radius > 0.0 : a->product == GIS_OPENNESS))
        return hfs_usage_error(prog, "--method sweep: the sweep searches the whole DEM; give "
                               "--radius 0%s", a->product == GIS_OPENNESS && !a->radius_given
                               ? " (openness searches 10 cells unless told)" : "");
    if (st->sky_north && !a->sky_map)
        return hfs_usage_error(prog, "--sky-north: only with --sky-map");
    if (a->beam_only && st->sky_opt)
        return hfs_usage_error(prog, "%s: not with --beam-only (the beam alone has no sky)",
                               st->sky_opt);
    if (a->product == GIS_SUN || a->product == GIS_INSOLATION)
        return check_sun(a, prog, st);
    if (a->product != GIS_HORIZON)
        return 0;
    if (a->n_azimuths && st->step_s)
        return hfs_usage_error(prog, "--azimuths and --step: give one of them");
    if (st->start_s && !st->step_s)
        return hfs_usage_error(prog, "--start: only with --step");
    if (!a->n_azimuths && !st->step_s)
        return hfs_usage_error(prog, "no azimuths (--azimuths A,B,... or --step DEG)");
    if (st->step_s)
        return step_azimuths(a, prog, st->step, st->start, st->step_s, st->start_s);
    a->decimals = a->decimals > 6 ? 6 : a->decimals;
    return 0;
}

/* argv into a; 0, -1 (--help printed) or a usage error's exit status. */
static int parse(int argc, char **argv, gis_args *a)
{
    char prog[32]; /* "hfshade svf": the usage errors point at its --help */
    snprintf(prog, sizeof prog, "hfshade %s", argv[0]);
    pending st = {0};
    for (int i = 1; i < argc; ++i) {
        const char *s = argv[i];
        if (hfs_is_help(s)) {
            usage(argv[0], a->product);
            return -1;
        }
        if (s[0] != '-' || !s[1]) {
            if (a->dem)
                return hfs_usage_error(prog, "%s: unexpected argument", s);
            a->dem = s;
            continue;
        }
        const gis_opt *o = find(s, a->product);
        if (!o)
            return hfs_usage_error(prog, "%s: unknown option", s);
        for (int j = 1; j < i; ++j)
            if (!strcmp(argv[j], s))
                return hfs_usage_error(prog, "%s: given twice (once is allowed)", s);
        if (!o->arg) {
            a->svf = !strcmp(s, "--lambertian") ? GIS_SVF_LAMBERTIAN : a->svf;
            a->cog |= !strcmp(s, "--cog");
            a->quiet |= !strcmp(s, "--quiet");
            a->beam_only |= !strcmp(s, "--beam-only");
            continue;
        }
        if (a->product == GIS_INSOLATION && (!strcmp(s, "--sky-map") || !strcmp(s, "--albedo") ||
                                             !strcmp(s, "--directions")))
            st.sky_opt = s;
        if (i + 1 >= argc)
            return hfs_usage_error(prog, "%s: missing value", s);
        const int rc = set_value(a, prog, s, argv[++i], &st);
        if (rc)
            return rc;
    }
    return check_args(a, prog, &st);
}

int hfs_cli_is_gis(const char *name)
{
    return !strcmp(name, "svf") || !strcmp(name, "horizon") || !strcmp(name, "openness") ||
           !strcmp(name, "sun") || !strcmp(name, "insolation");
}

/* The product of command name (svf when none matches: the callers check). */
static gis_product product_of(const char *name)
{
    static const char *const names[GIS_N_PRODUCTS] = {"svf", "horizon", "openness", "sun",
                                                      "insolation"};
    gis_product p = GIS_SVF;
    while (p + 1 < GIS_N_PRODUCTS && strcmp(name, names[p]))
        p = (gis_product)(p + 1);
    return p;
}

int hfs_cli_gis_file_option(const char *command, const char *flag)
{
    const gis_opt *o = find(flag, product_of(command));
    return o && o->arg && !strcmp(o->arg, "FILE");
}

int hfs_cli_gis_args(int argc, char **argv, gis_args *a, double *azimuth)
{
    const gis_product p = product_of(argv[0]);
    *a = (gis_args){.product = p, .backend = HFS_BACKEND_GLES, .zscale = 1.0,
                    .linke = HFS_LINKE_DEFAULT, .step_min = 15.0, .tile = GIS_TILE_DEFAULT,
                    .azimuth = azimuth};
    a->directions = a->product == GIS_OPENNESS ? 8 : 16;
    return parse(argc, argv, a);
}

int hfs_cli_gis(int argc, char **argv)
{
    gis_args a;
    double azimuth[HFS_MAX_HORIZON_AZIMUTHS];
    int rc = hfs_cli_gis_args(argc, argv, &a, azimuth); /* --help, a bad command line */
    if (rc)
        return rc < 0 ? 0 : rc;
#ifdef HFS_HAVE_GDAL
    hfs_error err = {{0}};
    if ((rc = gis_command_run(&a, &err)))
        fprintf(stderr, "hfshade: %s\n", err.msg);
    return rc ? 1 : 0;
#else
    fprintf(stderr, "hfshade: %s: this hfshade was built without GDAL (the GIS commands read "
            "and write rasters through it)\n", argv[0]);
    return 1;
#endif
}
