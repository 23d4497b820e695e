/*
 * fuzz_env_exr.c — fuzzes the OpenEXR environment map loader (OpenEXRCore's decode pipeline; runtime/io/envmap_exr.c): hfs_envmap_load() on a ".exr" file.
 *
 *   tools/fuzz.sh [SECONDS]        every target, bounded (build-fuzz/)
 *   build-fuzz/tests/fuzz_env_exr -max_len=16384 \
 *       -dict=tests/fuzz/dict/env_exr.dict CORPUS_COPY tests/fuzz/corpus/env_exr
 */
#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_envmap("e.exr", data, size);
    return 0;
}
