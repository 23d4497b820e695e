/*
 * hostile_pfm_check.c — exits 0 when every value of a PFM is finite, 1 when
 * one is not (printing where), 2 when the file cannot be read: the
 * hostile corpus's "no NaN or Inf ever reaches an output" check.
 */
#include "hfs_io.h"

#include <math.h>
#include <stdio.h>

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: hostile_pfm_check FILE.pfm\n");
        return 2;
    }
    hfs_image img = {0};
    hfs_error err = {{0}};
    if (hfs_pfm_read_image(argv[1], &img, &err)) {
        fprintf(stderr, "hostile_pfm_check: %s\n", err.msg);
        return 2;
    }
    const size_t n = (size_t)img.width * (size_t)img.height * 3;
    int rc = 0;
    for (size_t i = 0; i < n && !rc; ++i)
        if (!isfinite(img.rgb[i])) {
            fprintf(stderr, "%s: value %zu is %g\n", argv[1], i, (double)img.rgb[i]);
            rc = 1;
        }
    hfs_image_free(&img);
    return rc;
}
