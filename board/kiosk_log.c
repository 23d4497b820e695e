/*
 * kiosk_log.c — the kiosk's log: one line per event of note on stderr.
 *
 * Under systemd stderr is usually the journal; a "<N>" prefix (sd-daemon's
 * SD_ERR, SD_WARNING, SD_INFO) then sets each line's priority, so
 * `journalctl -p err` finds errors, without linking libsystemd.  Anywhere
 * else (a terminal, a test harness) lines start with the program's name.
 */
#include "cli_usage.h"
#include "kiosk.h"

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Process-wide on purpose: stderr is. */
static int to_journal;

void kiosk_log_init(void)
{
    to_journal = 0;
    const char *js = getenv("JOURNAL_STREAM");
    unsigned long long dev, ino;
    struct stat st;
    if (!js || sscanf(js, "%llu:%llu", &dev, &ino) != 2 || fstat(STDERR_FILENO, &st) != 0)
        return;
    to_journal = (unsigned long long)st.st_dev == dev && (unsigned long long)st.st_ino == ino;
}

void kiosk_log(kiosk_level level, const char *fmt, ...)
{
    char msg[1024];
    va_list ap;
    va_start(ap, fmt);
    hfs_vformat_line(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (to_journal)
        fprintf(stderr, "<%d>%s\n", (int)level, msg);
    else
        fprintf(stderr, "hfshade-kiosk: %s\n", msg);
    fflush(stderr);
}
