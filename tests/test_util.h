/*
 * test_util.h — the pass/fail tally and the temporary-file helpers shared by
 * the io tests (test_io_*.c) and the ground-truth tests (test_truth_*.c).
 * Everything is a macro or static inline, so each test takes only what it
 * uses; a test is one translation unit, so the state below is its own.
 *
 * Checks
 *   failures               count of failed checks so far.
 *   CHECK(cond)            if cond is false: prints "file:line: CHECK failed:
 *                          cond", counts a failure and goes on.
 *   REQUIRE(cond, fmt, ...) if cond is false: prints "file:line: FAIL cond: "
 *                          and the printf-style message, counts a failure
 *                          and returns from the calling (void) function at
 *                          once (later checks there would only cascade).
 *   finish_checks(name)    for the end of main: prints "name: N check(s)
 *                          failed" (stderr) or "name: all checks passed" and
 *                          returns the exit status, 1 or 0.
 *
 * Temporary files (each test gets a private directory, removed at the end)
 *   tmpdir                 the directory's path.
 *   make_tmpdir(tag)       creates tmpdir as "/dev/shm/TAG_XXXXXX" when
 *                          /dev/shm is writable (tmpfs: the io tests rewrite
 *                          thousands of small files, and truncating files on
 *                          a journaling disk is slow), else "./TAG_XXXXXX";
 *                          returns 0, or -1 after perror.
 *   tpath(name)            "tmpdir/name" in a static buffer; four buffers
 *                          rotate, so up to four results can be live at once.
 *   rm_tmpdir()            removes every entry of tmpdir (files, and empty
 *                          subdirectories), then tmpdir itself.
 *   write_bytes(path, data, n)  writes exactly n bytes to path; a fixture
 *                          that cannot be written is no test result, so on
 *                          failure it prints "cannot write PATH" and exits 1.
 *   read_all(path, &n)     the whole file in a malloc'ed buffer (one spare
 *                          byte, not set) and its size in n; NULL when it
 *                          cannot be opened or read.  The caller frees it.
 */
#ifndef HFS_TEST_UTIL_H
#define HFS_TEST_UTIL_H

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* ---- checks --------------------------------------------------------------------- */

static int failures;

#define CHECK(cond)                                                                     \
    do {                                                                                \
        if (!(cond)) {                                                                  \
            fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond);    \
            ++failures;                                                                 \
        }                                                                               \
    } while (0)

#define REQUIRE(cond, ...)                                                 \
    do {                                                                   \
        if (!(cond)) {                                                     \
            fprintf(stderr, "%s:%d: FAIL %s: ", __FILE__, __LINE__, #cond); \
            fprintf(stderr, __VA_ARGS__);                                  \
            fprintf(stderr, "\n");                                         \
            ++failures;                                                    \
            return;                                                        \
        }                                                                  \
    } while (0)

static inline int finish_checks(const char *name)
{
    if (failures) {
        fprintf(stderr, "%s: %d check(s) failed\n", name, failures);
        return 1;
    }
    printf("%s: all checks passed\n", name);
    return 0;
}

/* ---- temporary files ------------------------------------------------------------ */

static char tmpdir[256];

static inline int make_tmpdir(const char *tag)
{
    snprintf(tmpdir, sizeof tmpdir, "%s/%s_XXXXXX",
             access("/dev/shm", W_OK) == 0 ? "/dev/shm" : ".", tag);
    if (!mkdtemp(tmpdir)) {
        perror("mkdtemp");
        return -1;
    }
    return 0;
}

static inline const char *tpath(const char *name)
{
    static char buf[4][512];
    static int k;
    k = (k + 1) % 4;
    snprintf(buf[k], sizeof buf[k], "%s/%s", tmpdir, name);
    return buf[k];
}

static inline void rm_tmpdir(void)
{
    DIR *d = opendir(tmpdir);
    struct dirent *e;
    if (!d)
        return;
    while ((e = readdir(d))) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, ".."))
            continue;
        if (unlink(tpath(e->d_name)) != 0)
            rmdir(tpath(e->d_name));
    }
    closedir(d);
    rmdir(tmpdir);
}

static inline void write_bytes(const char *path, const void *data, size_t n)
{
    FILE *f = fopen(path, "wb");
    if (!f || (n && fwrite(data, 1, n, f) != n)) {
        fprintf(stderr, "cannot write %s\n", path);
        exit(1);
    }
    fclose(f);
}

static inline unsigned char *read_all(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    unsigned char *b;
    long len;
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    len = ftell(f);
    fseek(f, 0, SEEK_SET);
    b = malloc((size_t)len + 1);
    if (b && fread(b, 1, (size_t)len, f) != (size_t)len) {
        free(b);
        b = NULL;
    }
    fclose(f);
    *n = (size_t)len;
    return b;
}

#endif /* HFS_TEST_UTIL_H */
