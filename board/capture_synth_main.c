/*
 * hfs-capture-synth DIR [--frames N] [--size WxH] [--noise-mm F]
 *                       [--holes F] [--hand FROM,STOP,TO | --no-hand] [--seed N]
 * Writes a synthetic depth recording (capture_synth.h: a hand moving over a
 * sandbox, sensor noise, holes) that hfshade-kiosk plays with a
 * [capture NAME] section's `replay = DIR`.  Exit 0, 1 on an error, 2 on
 * usage.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "capture_synth.h"

static int usage(const char *why)
{
    fprintf(stderr, "hfs-capture-synth: %s\nusage: hfs-capture-synth DIR [--frames N] "
            "[--size WxH] [--noise-mm F] [--holes F] [--hand FROM,STOP,TO | --no-hand] "
            "[--seed N]\n", why);
    return 2;
}

int main(int argc, char **argv)
{
    hfs_synth_desc d;
    hfs_synth_defaults(&d);
    const char *dir = NULL;
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        char tail;
        double x;
        if (a[0] != '-') {
            if (dir)
                return usage("one directory only");
            dir = a;
        } else if (!strcmp(a, "--no-hand")) {
            d.hand_from = -1;
        } else if (!v) {
            return usage("an option lacks its value");
        } else if (!strcmp(a, "--frames") && sscanf(v, "%d%c", &d.frames, &tail) == 1 &&
                   d.frames >= 1 && d.frames <= 100000) {
            ++i;
        } else if (!strcmp(a, "--size") && sscanf(v, "%dx%d%c", &d.width, &d.height, &tail) == 2 &&
                   d.width >= 2 && d.height >= 2 && d.width <= 4096 && d.height <= 4096) {
            ++i;
        } else if (!strcmp(a, "--noise-mm") && sscanf(v, "%lf%c", &x, &tail) == 1 && x >= 0 &&
                   x <= 100) {
            d.noise_m = x * 1e-3, ++i;
        } else if (!strcmp(a, "--holes") && sscanf(v, "%lf%c", &x, &tail) == 1 && x >= 0 &&
                   x <= 1) {
            d.hole_frac = x, ++i;
        } else if (!strcmp(a, "--hand") &&
                   sscanf(v, "%d,%d,%d%c", &d.hand_from, &d.hand_stop, &d.hand_to, &tail) == 3 &&
                   d.hand_from >= 0 && d.hand_stop >= d.hand_from && d.hand_to >= d.hand_stop) {
            ++i;
        } else if (!strcmp(a, "--seed") && sscanf(v, "%u%c", &d.seed, &tail) == 1) {
            ++i;
        } else {
            return usage(a);
        }
    }
    if (!dir)
        return usage("no directory");
    hfs_error err = {{0}};
    if (hfs_synth_record(&d, dir, &err)) {
        fprintf(stderr, "hfs-capture-synth: %s\n", err.msg);
        return 1;
    }
    return 0;
}
