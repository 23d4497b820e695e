/*
 * fuzz_height_pgm.c — fuzzes the PGM height loader (P5 binary and P2 ASCII, runtime/io/height_netpbm.c):
 * hfs_height_load() on a ".pgm" file, then hole filling, with the default
 * guards hfshade uses.
 *
 *   tools/fuzz.sh [SECONDS]        every target, bounded (build-fuzz/)
 *   build-fuzz/tests/fuzz_height_pgm -max_len=4096 \
 *       -dict=tests/fuzz/dict/height_pgm.dict CORPUS_COPY tests/fuzz/corpus/height_pgm
 */
#include "fuzz.h"
#include "hfs_io.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_height("h.pgm", data, size, NULL, HFS_HEIGHT_PGM);
    return 0;
}
