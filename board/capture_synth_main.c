/*
 * hfs-capture-synth DIR [--frames N] [--size WxH] [--noise-mm F]
 *                       [--holes F] [--hand FROM,STOP,TO | --no-hand] [--seed N]
 * hfs-capture-synth DIR --sky mirrorball|fisheye|equirect [--frames N]
 *                       [--size WxH] [--sun FROM,TO,ELEV] [--noise-codes F]
 *                       [--seed N]
 * Writes a synthetic depth recording (capture_synth.h: a hand moving over a
 * sandbox, sensor noise, holes), or with --sky an environment camera's
 * YUYV recording (capture_synth_sky.h: a sun moving across a dim sky,
 * azimuths FROM to TO at elevation ELEV, degrees), that hfshade-kiosk plays
 * with a [capture NAME] section's `replay = DIR`.  Exit 0, 1 on an error,
 * 2 on usage.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "capture_synth.h"
#include "capture_synth_sky.h"
#include "cli_usage.h"

#define PROG "hfs-capture-synth"

static void usage(FILE *to)
{
    fprintf(to, "usage: " PROG " DIR [--frames N] [--size WxH] [--noise-mm F] [--holes F] "
                "[--hand FROM,STOP,TO | --no-hand] [--seed N]\n"
                "       " PROG " DIR --sky mirrorball|fisheye|equirect [--frames N] "
                "[--size WxH] [--sun FROM,TO,ELEV] [--noise-codes F] [--seed N]\n");
}

/* The error for option A that did not parse (with value V, or none). */
static int bad_option(const char *a, const char *v)
{
    static const char *const valued[] = {"--sky",      "--sun",   "--noise-codes", "--frames",
                                         "--size",     "--holes", "--noise-mm",    "--hand",
                                         "--seed"};
    for (size_t k = 0; k < sizeof valued / sizeof valued[0]; ++k)
        if (!strcmp(a, valued[k]))
            return v ? hfs_usage_error(PROG, "%s: '%s' is malformed or out of range", a, v)
                     : hfs_usage_error(PROG, "%s: missing value", a);
    return hfs_usage_error(PROG, "%s: unknown option", a);
}

int main(int argc, char **argv)
{
    hfs_synth_desc d;
    hfs_synth_defaults(&d);
    hfs_synth_sky_desc sky;
    hfs_synth_sky_defaults(&sky);
    int is_sky = 0, depth_opt = 0, sky_opt = 0, size_given = 0, frames_given = 0;
    const char *dir = NULL;
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        char tail;
        double x;
        if (a[0] != '-') {
            if (dir)
                return hfs_usage_error(PROG, "%s: a second directory (one only)", a);
            dir = a;
        } else if (hfs_is_help(a)) {
            usage(stdout);
            return 0;
        } else if (!strcmp(a, "--no-hand")) {
            d.hand_from = -1, depth_opt = 1;
        } else if (v && !strcmp(a, "--sky")) {
            is_sky = 1, ++i;
            sky.cam.mapping = !strcmp(v, "fisheye") ? HFS_MAP_FISHEYE
                              : !strcmp(v, "equirect") ? HFS_MAP_EQUIRECT : HFS_MAP_MIRRORBALL;
            if (strcmp(v, "fisheye") && strcmp(v, "equirect") && strcmp(v, "mirrorball"))
                return hfs_usage_error(PROG, "--sky: '%s' is not mirrorball, fisheye or equirect",
                                       v);
        } else if (v && !strcmp(a, "--sun") &&
                   sscanf(v, "%lf,%lf,%lf%c", &sky.az_from, &sky.az_to, &sky.elev, &tail) == 3 &&
                   fabs(sky.elev) <= 89.0) {
            sky_opt = 1, ++i;
        } else if (v && !strcmp(a, "--noise-codes") && sscanf(v, "%lf%c", &x, &tail) == 1 &&
                   x >= 0 && x <= 64) {
            sky.noise = x, sky_opt = 1, ++i;
        } else if (!v) {
            return bad_option(a, v);
        } else if (!strcmp(a, "--frames") && sscanf(v, "%d%c", &d.frames, &tail) == 1 &&
                   d.frames >= 1 && d.frames <= 100000) {
            frames_given = 1, ++i;
        } else if (!strcmp(a, "--size") && sscanf(v, "%dx%d%c", &d.width, &d.height, &tail) == 2 &&
                   d.width >= 2 && d.height >= 2 && d.width <= 4096 && d.height <= 4096) {
            size_given = 1, ++i;
        } else if (!strcmp(a, "--noise-mm") && sscanf(v, "%lf%c", &x, &tail) == 1 && x >= 0 &&
                   x <= 100) {
            d.noise_m = x * 1e-3, depth_opt = 1, ++i;
        } else if (!strcmp(a, "--holes") && sscanf(v, "%lf%c", &x, &tail) == 1 && x >= 0 &&
                   x <= 1) {
            d.hole_frac = x, depth_opt = 1, ++i;
        } else if (!strcmp(a, "--hand") &&
                   sscanf(v, "%d,%d,%d%c", &d.hand_from, &d.hand_stop, &d.hand_to, &tail) == 3 &&
                   d.hand_from >= 0 && d.hand_stop >= d.hand_from && d.hand_to >= d.hand_stop) {
            depth_opt = 1, ++i;
        } else if (!strcmp(a, "--seed") && sscanf(v, "%u%c", &d.seed, &tail) == 1) {
            ++i;
        } else {
            return bad_option(a, v);
        }
    }
    if (!dir)
        return hfs_usage_error(PROG, "no directory given");
    if (is_sky ? depth_opt : sky_opt)
        return hfs_usage_error(PROG, "%s", is_sky ? "a depth option with --sky"
                                                 : "--sun or --noise-codes without --sky");
    hfs_error err = {{0}};
    if (is_sky) {
        sky.frames = frames_given ? d.frames : sky.frames;
        sky.seed = d.seed;
        if (size_given)
            sky.width = d.width, sky.height = d.height;
    }
    if (is_sky ? hfs_synth_sky_record(&sky, dir, &err) : hfs_synth_record(&d, dir, &err)) {
        fprintf(stderr, "hfs-capture-synth: %s\n", err.msg);
        return 1;
    }
    return 0;
}
