/*
 * fuzz_replay.c — a plain main() for the fuzz targets (no libFuzzer needed):
 * feeds every file in the given directories (sorted; names starting with '.'
 * and README files skipped) to LLVMFuzzerTestOneInput() once, so seeds and
 * former crashes replay under any compiler and the sanitizer builds.
 *
 *   fuzz_replay_<target> tests/fuzz/corpus/<target> [tests/fuzz/regressions/<target>]
 *
 * Exit 0 when every input went through (a finding aborts), 1 on a missing
 * directory, an unreadable file, an input that took longer than libFuzzer's
 * -timeout (10 s), or no input at all.
 *
 * Huge allocations are findings too, as under tools/fuzz.sh
 * (-malloc_limit_mb=512): sanitizer builds get ASAN_OPTIONS
 * max_allocation_size_mb=512 from tests/fuzz.cmake; other glibc builds
 * (HFS_REPLAY_MALLOC_LIMIT) replace malloc, calloc and realloc, as glibc
 * allows, by versions that abort above the limit and otherwise call glibc's
 * own (so allocations inside libpng or OpenEXRCore are checked as well).
 * HFS_FUZZ_MALLOC_LIMIT_MB overrides the limit.
 */
#include "fuzz.h"

#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#define REPLAY_TIMEOUT_S 10.0
#define REPLAY_MALLOC_LIMIT_MB 512

#if defined(HFS_REPLAY_MALLOC_LIMIT) && defined(__GLIBC__)
extern void *__libc_malloc(size_t n);
extern void *__libc_calloc(size_t k, size_t n);
extern void *__libc_realloc(void *p, size_t n);
extern void __libc_free(void *p);

static size_t malloc_limit = (size_t)REPLAY_MALLOC_LIMIT_MB << 20;

/* Exported (the build hides symbols by default), so that the shared
 * libraries' calls bind to these too. */
#define REPLACES_LIBC __attribute__((visibility("default")))

static void check_size(size_t n)
{
    if (n > malloc_limit) {
        static const char msg[] = "fuzz contract broken: single allocation over the limit\n";
        /* No stdio here: it may allocate. */
        if (write(2, msg, sizeof msg - 1) < 0)
            abort();
        abort();
    }
}

REPLACES_LIBC void *malloc(size_t n)
{
    check_size(n);
    return __libc_malloc(n);
}

REPLACES_LIBC void *calloc(size_t k, size_t n)
{
    if (n == 0 || k <= SIZE_MAX / n) /* else glibc fails it (overflow) */
        check_size(k * n);
    return __libc_calloc(k, n);
}

REPLACES_LIBC void *realloc(void *p, size_t n)
{
    check_size(n);
    return __libc_realloc(p, n);
}

REPLACES_LIBC void free(void *p)
{
    __libc_free(p);
}
#endif

static void set_malloc_limit(void)
{
#if defined(HFS_REPLAY_MALLOC_LIMIT) && defined(__GLIBC__)
    const char *mb = getenv("HFS_FUZZ_MALLOC_LIMIT_MB");
    if (mb && atol(mb) > 0)
        malloc_limit = (size_t)atol(mb) << 20;
#endif
}

static int skip_name(const struct dirent *e)
{
    return e->d_name[0] != '.' && strncmp(e->d_name, "README", 6) != 0;
}

/* Whole file in a malloc'ed buffer (at least one byte allocated). */
static unsigned char *read_file(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    unsigned char *buf = NULL;
    size_t cap = 0, n = 0;

    if (!f)
        return NULL;
    for (;;) {
        size_t got;
        if (n == cap) {
            unsigned char *b = realloc(buf, cap ? 2 * cap : 4096);
            if (!b) {
                free(buf);
                fclose(f);
                return NULL;
            }
            buf = b;
            cap = cap ? 2 * cap : 4096;
        }
        got = fread(buf + n, 1, cap - n, f);
        n += got;
        if (got == 0)
            break;
    }
    if (ferror(f)) {
        free(buf);
        buf = NULL;
    }
    fclose(f);
    *size = n;
    return buf;
}

int main(int argc, char **argv)
{
    long inputs = 0;
    int slow = 0;

    set_malloc_limit();
    if (argc < 2) {
        fprintf(stderr, "usage: %s DIR...\n", argv[0]);
        return 1;
    }
    for (int a = 1; a < argc; ++a) {
        struct dirent **names;
        int n = scandir(argv[a], &names, skip_name, alphasort);
        if (n < 0) {
            perror(argv[a]);
            return 1;
        }
        for (int k = 0; k < n; ++k) {
            char path[4096];
            struct stat st;
            snprintf(path, sizeof path, "%s/%s", argv[a], names[k]->d_name);
            free(names[k]);
            if (stat(path, &st) != 0 || !S_ISREG(st.st_mode))
                continue;
            size_t size = 0;
            unsigned char *data = read_file(path, &size);
            if (!data) {
                perror(path);
                while (++k < n)
                    free(names[k]);
                free(names);
                return 1;
            }
            printf("%s (%zu bytes)\n", path, size);
            fflush(stdout); /* the last name printed is the culprit of a crash */
            struct timespec t0, t1;
            clock_gettime(CLOCK_MONOTONIC, &t0);
            LLVMFuzzerTestOneInput(data, size);
            clock_gettime(CLOCK_MONOTONIC, &t1);
            free(data);
            ++inputs;
            const double secs = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
            if (secs > REPLAY_TIMEOUT_S) {
                fprintf(stderr, "fuzz contract broken: %s took %.1f s (limit %.0f s)\n", path,
                        secs, REPLAY_TIMEOUT_S);
                slow = 1;
            }
        }
        free(names);
    }
    printf("%s: %ld inputs replayed\n", argv[0], inputs);
    return inputs > 0 && !slow ? 0 : 1;
}
