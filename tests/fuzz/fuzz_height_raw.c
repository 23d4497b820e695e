/*
 * fuzz_height_raw.c — fuzzes raw float32 height loading and the hole filler
 * (runtime/io/height_load.c, hole_fill.c).  Input: byte 0 and 1 give the
 * size (2 + b % 31 each), byte 2 the options (bit 0: nodata = 0.0 marks
 * holes; bit 1: no file extension, so the content sniffer decides and a raw
 * size given for a recognised format must be refused); the rest is the file.
 *
 *   tools/fuzz.sh [SECONDS]        every target, bounded (build-fuzz/)
 *   build-fuzz/tests/fuzz_height_raw -max_len=4096 CORPUS_COPY tests/fuzz/corpus/height_raw
 */
#include "fuzz.h"
#include "hfs_io.h"

#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    hfs_height_load_opts o;

    if (size < 3)
        return 0;
    memset(&o, 0, sizeof o);
    o.raw_width = 2 + data[0] % 31;
    o.raw_height = 2 + data[1] % 31;
    o.has_nodata = data[2] & 1;
    o.nodata = 0.0f;
    fuzz_height(data[2] & 2 ? "h" : "h.raw", data + 3, size - 3, &o, HFS_HEIGHT_RAW_F32);
    return 0;
}
