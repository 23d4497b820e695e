/*
 * fuzz_height_pfm.c — fuzzes the PFM height loader ("Pf", runtime/io/height_netpbm.c):
 * hfs_height_load() on a ".pfm" file, then hole filling, with the default
 * guards hfshade uses.
 *
 *   tools/fuzz.sh [SECONDS]        every target, bounded (build-fuzz/)
 *   build-fuzz/tests/fuzz_height_pfm -max_len=4096 \
 *       -dict=tests/fuzz/dict/height_pfm.dict CORPUS_COPY tests/fuzz/corpus/height_pfm
 */
#include "fuzz.h"
#include "hfs_io.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_height("h.pfm", data, size, NULL, HFS_HEIGHT_PFM);
    return 0;
}
