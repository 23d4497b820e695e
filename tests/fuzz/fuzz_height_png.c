/*
 * fuzz_height_png.c — fuzzes the PNG height loader: hfs_height_load() on a
 * ".png" file (libpng through runtime/io/height_png.c, then hole filling),
 * with the default guards hfshade uses.  Chunk CRCs are recomputed before the
 * file is written, so mutations reach the decoder instead of stopping at
 * libpng's CRC check (bad CRCs are covered by tests/data/broken).
 *
 *   tools/fuzz.sh [SECONDS]        every target, bounded (build-fuzz/)
 *   build-fuzz/tests/fuzz_height_png -max_len=8192 \
 *       -dict=tests/fuzz/dict/height_png.dict CORPUS_COPY tests/fuzz/corpus/height_png
 */
#include "fuzz.h"
#include "hfs_io.h"

#include <stdlib.h>
#include <string.h>

static uint32_t crc32_png(const uint8_t *p, size_t n)
{
    uint32_t c = 0xFFFFFFFFu;
    for (size_t k = 0; k < n; ++k) {
        c ^= p[k];
        for (int b = 0; b < 8; ++b)
            c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
    }
    return c ^ 0xFFFFFFFFu;
}

/* Rewrites the CRC of every complete chunk after the 8-byte signature. */
static void fix_crcs(uint8_t *p, size_t n)
{
    size_t at = 8;
    while (n >= 12 && at <= n - 12) {
        uint32_t len = (uint32_t)p[at] << 24 | (uint32_t)p[at + 1] << 16 |
                       (uint32_t)p[at + 2] << 8 | p[at + 3];
        uint32_t crc;
        if (len > n - 12 - at)
            break;
        crc = crc32_png(p + at + 4, 4 + (size_t)len);
        at += 8 + len;
        p[at] = (uint8_t)(crc >> 24);
        p[at + 1] = (uint8_t)(crc >> 16);
        p[at + 2] = (uint8_t)(crc >> 8);
        p[at + 3] = (uint8_t)crc;
        at += 4;
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    uint8_t *copy = malloc(size ? size : 1);
    if (!copy)
        return 0;
    if (size)
        memcpy(copy, data, size);
    fix_crcs(copy, size);
    fuzz_height("h.png", copy, size, NULL, HFS_HEIGHT_PNG);
    free(copy);
    return 0;
}
