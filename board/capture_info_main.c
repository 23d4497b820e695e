/*
 * hfs-capture-info DEVICE... — a V4L2 device's formats, frame sizes and
 * intervals, as `v4l2-ctl --list-formats-ext` prints them, with what
 * hfshade can read marked (hfs_v4l2_list, capture_info.c).
 * Exit 0, 1 on a device error (one line naming it), 2 on usage.
 */
#include <stdio.h>
#include <string.h>

#include "capture_v4l2.h"
#include "cli_usage.h"

int main(int argc, char **argv)
{
    if (argc < 2)
        return hfs_usage_error("hfs-capture-info", "no device given (e.g. /dev/video0)");
    for (int i = 1; i < argc; ++i) {
        if (hfs_is_help(argv[i])) {
            printf("usage: hfs-capture-info DEVICE...   (e.g. /dev/video0, /dev/v4l/by-id/...)\n");
            return 0;
        }
        if (argv[i][0] == '-')
            return hfs_usage_error("hfs-capture-info", "%s: unknown option", argv[i]);
    }
    int rc = 0;
    for (int i = 1; i < argc; ++i) {
        hfs_error err = {{0}};
        if (hfs_v4l2_list(argv[i], NULL, stdout, &err)) {
            fprintf(stderr, "hfs-capture-info: %s\n", err.msg);
            rc = 1;
        }
    }
    return rc;
}
