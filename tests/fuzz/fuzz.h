/*
 * fuzz.h — what the fuzz targets of tests/fuzz/ share.
 *
 * Each fuzz_<target>.c defines LLVMFuzzerTestOneInput() for one input kind and
 * is linked two ways (tests/fuzz.cmake):
 *   - with libFuzzer: build-fuzz/tests/fuzz_<target> (clang, -DHFS_FUZZ=ON;
 *     tools/fuzz.sh builds and runs them);
 *   - with fuzz_replay.c, a plain main() that feeds it every seed and every
 *     former crash (ctest fuzz_replay_<target>, label "io", any compiler).
 *
 * The loaders take paths, so the input is written to a per-process temporary
 * file first (fuzz_util.c).  Contract checked for every input: no crash, no
 * sanitizer report, no leak; a failure is a negative status with a one-line
 * message that starts with the path and a zeroed output; a success is a sane,
 * finite result.  A broken contract calls fuzz_fail(), which aborts (a finding).
 */
#ifndef HFS_FUZZ_H
#define HFS_FUZZ_H

#include "hfshade.h"

#include <stddef.h>
#include <stdint.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Prints "fuzz contract broken: WHAT (DETAIL)" and aborts. */
_Noreturn void fuzz_fail(const char *what, const char *detail);

/* Writes data to "DIR/hfs_fuzz_PID_NAME" (DIR: $TMPDIR, else /dev/shm, else
 * /tmp) and returns that path (a static buffer), or NULL if it cannot be
 * written (then the input is skipped).  fuzz_remove() deletes it. */
const char *fuzz_write(const char *name, const void *data, size_t size);
void fuzz_remove(const char *path);

/* rc must be negative and err->msg one line that starts with "PATH:"
 * followed by some text; otherwise fuzz_fail(). */
void fuzz_check_error(const char *path, int rc, const hfs_error *err);
/* fuzz_check_error(), and zeroed (the output after the failure) must hold. */
void fuzz_check_failure(const char *path, int rc, const hfs_error *err, int zeroed);
/* A loaded image's size must lie in [min_side, max_side] and data be set. */
void fuzz_check_size(const char *path, int width, int height, int min_side, int max_side,
                     const void *data);

/* fuzz_io.c (targets that link hfshade_io). */
struct hfs_height_load_opts;
/* Loads data as a height field from a file called `name` (its extension
 * picks the format) with opts (NULL: the defaults hfshade uses) and checks
 * the contract; expect is the hfs_height_format a success must report. */
void fuzz_height(const char *name, const uint8_t *data, size_t size,
                 const struct hfs_height_load_opts *opts, int expect);
/* Loads data as an environment map from a file called `name`. */
void fuzz_envmap(const char *name, const uint8_t *data, size_t size);

#endif /* HFS_FUZZ_H */
