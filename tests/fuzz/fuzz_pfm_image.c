/*
 * fuzz_pfm_image.c — fuzzes hfs_pfm_read_image(), the PFM reader of
 * `hfshade compare` (runtime/io/height_netpbm.c): "Pf" and "PF", 1x1 and up,
 * values kept as stored (NaN/Inf included), grey expanded to RGB in place.
 *
 *   tools/fuzz.sh [SECONDS]        every target, bounded (build-fuzz/)
 *   build-fuzz/tests/fuzz_pfm_image -max_len=4096 \
 *       -dict=tests/fuzz/dict/pfm_image.dict CORPUS_COPY tests/fuzz/corpus/pfm_image
 */
#include "fuzz.h"
#include "hfs_io.h"

#include <string.h>

static volatile float sink;

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_write("i.pfm", data, size);
    hfs_image img;
    hfs_error err;
    int rc;

    if (!path)
        return 0;
    err.msg[0] = '\0';
    rc = hfs_pfm_read_image(path, &img, &err);
    if (rc == 0) {
        size_t n = (size_t)img.width * (size_t)img.height;
        int grey = size >= 2 && data[1] == 'f';
        fuzz_check_size(path, img.width, img.height, 1, HFS_HEIGHT_MAX_DIM, img.rgb);
        /* Reads every value (ASan checks the bounds); a "Pf" grey image
         * must come back with R = G = B, bit for bit (NaNs included). */
        for (size_t k = 0; k < n; ++k) {
            const float *p = img.rgb + 3 * k;
            sink = p[0] + p[1] + p[2];
            if (grey && (memcmp(p, p + 1, sizeof *p) || memcmp(p, p + 2, sizeof *p)))
                fuzz_fail("grey PFM pixel not expanded to R = G = B", path);
        }
        hfs_image_free(&img);
    } else {
        fuzz_check_failure(path, rc, &err, !img.rgb && !img.width && !img.height);
    }
    fuzz_remove(path);
    return 0;
}
