/*
 * parallel.h — deterministic row-parallel loops on pthreads.
 *
 * Work is split into rows; each row is computed by exactly one worker and
 * writes only its own outputs, so results do not depend on the thread count
 * or scheduling (same input, same output, bit for bit).
 */
#ifndef HFS_PARALLEL_H
#define HFS_PARALLEL_H

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

#endif /* HFS_PARALLEL_H */
