/*
 * test_io_fuzz.c — libFuzzer entry point for the loaders (built only with
 * -DHFS_FUZZ=ON and clang; not a ctest test).  The first input byte picks the
 * file name's extension, and so the format the loaders expect; the rest is
 * the file's content, written to a private temporary file because the public
 * API takes paths.  Any crash, sanitizer report or leak is a bug; a load that
 * succeeds must give a sane, finite result.
 *
 *   ./fuzz_io_load -max_len=4096 CORPUS_DIR tests/data/broken/height tests/data/io
 */
#include "hfs_io.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const ext[] = {".png", ".pgm", ".pfm", ".asc", ".raw",
                                      ".hdr", ".exr", "",     ".dat", ".pnm"};
    char path[128];
    hfs_height_load_opts o;
    hfs_heightmap hm;
    hfs_envmap em;
    hfs_image img;
    hfs_error err;
    FILE *f;
    unsigned pick;

    if (size < 1)
        return 0;
    pick = data[0] % (sizeof ext / sizeof ext[0]);
    snprintf(path, sizeof path, "/dev/shm/hfs_fuzz_%d%s", (int)getpid(), ext[pick]);
    f = fopen(path, "wb");
    if (!f)
        return 0;
    if (size > 1)
        fwrite(data + 1, 1, size - 1, f);
    fclose(f);

    memset(&o, 0, sizeof o);
    if (pick == 4 || pick == 8) { /* raw: a size from the second byte */
        o.raw_width = 2 + (size > 1 ? data[1] % 8 : 0);
        o.raw_height = 2;
    }
    o.max_width = o.max_height = 4096;
    o.max_texels = 1 << 20;
    if (hfs_height_load(path, &o, &hm, &err) == 0) {
        for (long k = 0; k < (long)hm.width * hm.height; ++k)
            if (!isfinite(hm.z[k]))
                abort();
        hfs_heightmap_free(&hm);
    } else if (strncmp(err.msg, path, strlen(path)) != 0 || strchr(err.msg, '\n')) {
        abort();
    }
    if (hfs_envmap_load(path, &em, &err) == 0) {
        for (size_t k = 0; k < (size_t)em.width * em.height * 3; ++k)
            if (!isfinite(em.rgb[k]))
                abort();
        hfs_envmap_free(&em);
    } else if (strncmp(err.msg, path, strlen(path)) != 0) {
        abort();
    }
    if (hfs_pfm_read_image(path, &img, &err) == 0)
        hfs_image_free(&img);
    unlink(path);
    return 0;
}
