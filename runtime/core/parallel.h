/*
 * parallel.h — deterministic row-parallel loops on pthreads.
 *
 * Work is split into rows; each row is computed by exactly one worker and
 * writes only its own outputs, so results do not depend on the thread count
 * or scheduling (same input, same output, bit for bit).
 */
#ifndef HFS_PARALLEL_H
#define HFS_PARALLEL_H

#include <stddef.h>

/* Computes row `row` (0 <= row < n_rows).  worker is 0..threads-1, so a
 * callback can index per-worker scratch memory. */
typedef void (*hfs_row_fn)(void *ctx, int row, int worker);

/* Progress is reported from the calling thread only, as rows complete. */
typedef void (*hfs_row_progress_fn)(void *user, double fraction);

/* Number of worker threads to use when the caller asks for 0 (all cores). */
int hfs_parallel_default_threads(void);

/* Runs fn for every row using `threads` workers (0 = default).  Falls back to
 * running on the calling thread if threads cannot be created.  Returns the
 * number of workers actually used (>= 1). */
int hfs_parallel_rows(int n_rows, int threads, hfs_row_fn fn, void *ctx,
                      hfs_row_progress_fn progress, void *progress_user);

/* A loop over [0, n) in HFS_PARALLEL_CHUNKS contiguous chunks on the
 * default workers, or, when n < min_parallel (threads would cost more than
 * they save), in one call fn(ctx, 0, n, 0) on the calling thread.  Chunk c
 * is [n c / CHUNKS, n (c + 1) / CHUNKS); each writes only its own outputs
 * (and its own slot c of a per-chunk result), so results do not depend on
 * the thread count. */
#define HFS_PARALLEL_CHUNKS 64
typedef void (*hfs_range_fn)(void *ctx, size_t begin, size_t end, int chunk);
void hfs_parallel_ranges(size_t n, size_t min_parallel, hfs_range_fn fn, void *ctx);

#endif /* HFS_PARALLEL_H */
