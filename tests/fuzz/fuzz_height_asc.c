/*
 * fuzz_height_asc.c — fuzzes the ESRI ASCII grid height loader (runtime/io/height_asc.c):
 * hfs_height_load() on a ".asc" file, then hole filling, with the default
 * guards hfshade uses.
 *
 *   tools/fuzz.sh [SECONDS]        every target, bounded (build-fuzz/)
 *   build-fuzz/tests/fuzz_height_asc -max_len=4096 \
 *       -dict=tests/fuzz/dict/height_asc.dict CORPUS_COPY tests/fuzz/corpus/height_asc
 */
#include "fuzz.h"
#include "hfs_io.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_height("h.asc", data, size, NULL, HFS_HEIGHT_ASC);
    return 0;
}
