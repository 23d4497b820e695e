/*
 * fuzz_env_hdr.c — fuzzes the Radiance .hdr environment map loader (our header check, then stb_image through callbacks; runtime/io/envmap.c): hfs_envmap_load() on a ".hdr" file.
 *
 *   tools/fuzz.sh [SECONDS]        every target, bounded (build-fuzz/)
 *   build-fuzz/tests/fuzz_env_hdr -max_len=8192 \
 *       -dict=tests/fuzz/dict/env_hdr.dict CORPUS_COPY tests/fuzz/corpus/env_hdr
 */
#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_envmap("e.hdr", data, size);
    return 0;
}
