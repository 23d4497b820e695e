/*
 * cli_usage.h — one line on bad input, everywhere (issue 34).  Every
 * program the project builds reports a bad command line (an unknown flag,
 * a missing or bad value, an unknown subcommand, a missing argument) the
 * same way: ONE line on stderr that names the input and what is wrong with
 * it and points at --help, nothing on stdout, exit status 2:
 *
 *     return hfs_usage_error("hfgen", "'%s' is not a kind (%s)", kind, kinds);
 *     hfgen: 'volcano' is not a kind (flat|cones|...) (see hfgen --help)
 *
 * --help (or -h) prints the whole usage on stdout and exits 0.
 */
#ifndef HFS_CLI_USAGE_H
#define HFS_CLI_USAGE_H

#include <stdarg.h>
#include <stddef.h>

#define HFS_EXIT_USAGE 2

/* Prints "PROG: MESSAGE (see PROG --help)" on stderr; returns HFS_EXIT_USAGE. */
int hfs_usage_error(const char *prog, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* FMT's message formatted into buf[n] as one line: newlines become spaces. */
void hfs_vformat_line(char *buf, size_t n, const char *fmt, va_list ap);

/* V, the whole of it, as a number in [lo, hi] (NaN and overflow never are):
 * 0 and *out, else -1 and *out untouched.  The caller words the message
 * (its flag, its range). */
int hfs_cli_real(const char *v, double lo, double hi, double *out);

/* V, the whole of it, as a decimal whole number in [lo, hi]: 0 and *out,
 * else -1 and *out untouched. */
int hfs_cli_long(const char *v, long lo, long hi, long *out);

/* 1 if ARG asks for the usage: --help or -h. */
int hfs_is_help(const char *arg);

#endif
