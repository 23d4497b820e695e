/*
 * test_capture_real.c — a real V4L2 device, where the machine has one:
 * the first /dev/videoN that lists (hfs_v4l2_list) and, if it offers Z16,
 * 10 frames streamed through the capture source.  Exit 77 (skip) when no
 * /dev/video* exists (the CI machines have none and cannot load vivid) or
 * the user may not open it.
 */
#include <glob.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "capture_v4l2.h"

int main(void)
{
    glob_t g;
    if (glob("/dev/video*", 0, NULL, &g) != 0 || g.gl_pathc == 0) {
        printf("SKIP: test_capture_real: no /dev/video* device here\n");
        return 77;
    }
    int rc = 0;
    const char *dev = g.gl_pathv[0];
    if (access(dev, R_OK | W_OK) != 0) { /* not ours to test (group video) */
        printf("SKIP: test_capture_real: %s is not accessible\n", dev);
        globfree(&g);
        return 77;
    }
    hfs_error err = {{0}};
    if (hfs_v4l2_list(dev, NULL, stdout, &err)) {
        fprintf(stderr, "FAIL: %s\n", err.msg);
        rc = 1;
    }
    hfs_v4l2_desc d = {.path = dev, .format = HFS_PIX_Z16};
    hfs_capture *c = NULL;
    if (!rc && hfs_v4l2_open(&d, &c, &err) == HFS_OK) {
        int got = 0;
        for (int i = 0; i < 100 && got < 10; ++i) {
            hfs_capture_frame f;
            if (hfs_v4l2_wait(c, 100, &err) < 0 || hfs_capture_next(c, 0, &f, &err) < 0) {
                fprintf(stderr, "FAIL: %s\n", err.msg);
                rc = 1;
                break;
            }
            got += hfs_capture_frame_check(&f, dev, &err) == 0 && f.data;
        }
        printf("%s: %d Z16 frames, %ld dropped\n", dev, got, c->dropped);
        hfs_capture_destroy(c);
    } else if (!rc) {
        printf("%s: no Z16 stream (%s): listing only\n", dev, err.msg);
    }
    globfree(&g);
    return rc;
}
