/*
 * check.h — the message-carrying check of the tests: CHECK(cond, fmt, ...)
 * reports "file:line: FAIL: message" on stderr, counts the failure in
 * `failures` and carries on (one test binary checks many things per run).
 * `checks` counts every CHECK evaluated, for a test's summary line.
 * Define CHECK_MAX_MESSAGES before including to print only the first N
 * failures (a test of millions of random cases would flood the log; every
 * failure is still counted).  Include once per test program.
 */
#ifndef HFS_TEST_CHECK_H
#define HFS_TEST_CHECK_H

#include <stdio.h>

#ifndef CHECK_MAX_MESSAGES
#define CHECK_MAX_MESSAGES 1000000
#endif

static int failures;
static long checks;

#define CHECK(cond, ...)                                                        \
    do {                                                                        \
        ++checks;                                                               \
        if (!(cond)) {                                                          \
            if (failures < CHECK_MAX_MESSAGES) {                                \
                fprintf(stderr, "%s:%d: FAIL: ", __FILE__, __LINE__);           \
                fprintf(stderr, __VA_ARGS__);                                   \
                fputc('\n', stderr);                                            \
            }                                                                   \
            failures++;                                                         \
        }                                                                       \
    } while (0)

#endif /* HFS_TEST_CHECK_H */
