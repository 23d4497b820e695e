/*
 * parallel.c — a minimal pthread pool for row loops.  Rows are handed out by
 * an atomic counter; the calling thread is worker 0 and reports progress.
 */
#include "parallel.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <unistd.h>

#define HFS_MAX_THREADS 64

typedef struct row_job {
    hfs_row_fn fn;
    void *ctx;
    int n_rows;
    atomic_int next_row;
    atomic_int rows_done;
} row_job;

typedef struct worker_arg {
    row_job *job;
    int worker;
} worker_arg;

int hfs_parallel_default_threads(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    if (n < 1)
        n = 1;
    if (n > HFS_MAX_THREADS)
        n = HFS_MAX_THREADS;
    return (int)n;
}

static void run_rows(row_job *job, int worker)
{
    for (;;) {
        int row = atomic_fetch_add(&job->next_row, 1);
        if (row >= job->n_rows)
            return;
        job->fn(job->ctx, row, worker);
        atomic_fetch_add(&job->rows_done, 1);
    }
}

static void *worker_main(void *p)
{
    worker_arg *a = p;
    run_rows(a->job, a->worker);
    return NULL;
}

int hfs_parallel_rows(int n_rows, int threads, hfs_row_fn fn, void *ctx,
                      hfs_row_progress_fn progress, void *progress_user)
{
    if (threads <= 0)
        threads = hfs_parallel_default_threads();
    if (threads > HFS_MAX_THREADS)
        threads = HFS_MAX_THREADS;
    if (threads > n_rows)
        threads = n_rows > 0 ? n_rows : 1;

    row_job job = {.fn = fn, .ctx = ctx, .n_rows = n_rows};
    atomic_init(&job.next_row, 0);
    atomic_init(&job.rows_done, 0);

    pthread_t tid[HFS_MAX_THREADS];
    worker_arg args[HFS_MAX_THREADS];
    int started = 1; /* worker 0 is this thread */
    for (int w = 1; w < threads; ++w) {
        args[w] = (worker_arg){.job = &job, .worker = w};
        if (pthread_create(&tid[w], NULL, worker_main, &args[w]) != 0)
            break;
        started++;
    }

    if (!progress) {
        run_rows(&job, 0);
    } else {
        /* Interleave own rows with progress reports (calling thread only). */
        for (;;) {
            int row = atomic_fetch_add(&job.next_row, 1);
            if (row >= n_rows)
                break;
            fn(ctx, row, 0);
            atomic_fetch_add(&job.rows_done, 1);
            progress(progress_user, (double)atomic_load(&job.rows_done) / n_rows);
        }
    }
    for (int w = 1; w < started; ++w)
        pthread_join(tid[w], NULL);
    if (progress)
        progress(progress_user, 1.0);
    return started;
}

typedef struct range_job {
    size_t n;
    hfs_range_fn fn;
    void *ctx;
} range_job;

static void range_chunk(void *ctx, int row, int worker)
{
    (void)worker;
    const range_job *j = ctx;
    const size_t c = (size_t)row;
    j->fn(j->ctx, j->n * c / HFS_PARALLEL_CHUNKS, j->n * (c + 1) / HFS_PARALLEL_CHUNKS, row);
}

void hfs_parallel_ranges(size_t n, size_t min_parallel, hfs_range_fn fn, void *ctx)
{
    if (n < min_parallel) {
        fn(ctx, 0, n, 0);
        return;
    }
    range_job j = {n, fn, ctx};
    hfs_parallel_rows(HFS_PARALLEL_CHUNKS, 0, range_chunk, &j, NULL, NULL);
}
