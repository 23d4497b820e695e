/*
 * check.h — the message-carrying check of the tests: CHECK(cond, fmt, ...)
 * reports "file:line: FAIL: message" on stderr, counts the failure in
 * `failures` and carries on (one test binary checks many things per run).
 * Include once per test program.
 */
#ifndef HFS_TEST_CHECK_H
#define HFS_TEST_CHECK_H

#include <stdio.h>

static int failures;

#define CHECK(cond, ...)                                                        \
    do {                                                                        \
        if (!(cond)) {                                                          \
            fprintf(stderr, "%s:%d: FAIL: ", __FILE__, __LINE__);               \
            fprintf(stderr, __VA_ARGS__);                                       \
            fputc('\n', stderr);                                                \
            failures++;                                                         \
        }                                                                       \
    } while (0)

#endif /* HFS_TEST_CHECK_H */
