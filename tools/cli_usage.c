/* cli_usage.c — the one-line usage error (cli_usage.h). */
#include "cli_usage.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

void hfs_vformat_line(char *buf, size_t n, const char *fmt, va_list ap)
{
    vsnprintf(buf, n, fmt, ap);
    for (char *p = buf; *p; ++p)
        if (*p == '\n' || *p == '\r')
            *p = ' ';
}

int hfs_usage_error(const char *prog, const char *fmt, ...)
{
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    hfs_vformat_line(msg, sizeof msg, fmt, ap);
    va_end(ap);
    fprintf(stderr, "%s: %s (see %s --help)\n", prog, msg, prog);
    return HFS_EXIT_USAGE;
}

int hfs_is_help(const char *arg)
{
    return !strcmp(arg, "--help") || !strcmp(arg, "-h");
}
