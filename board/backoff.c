/*
 * backoff.c — see backoff.h.
 */
#include "backoff.h"

#include <string.h>

void hfs_backoff_init(hfs_backoff *b, int64_t min_ns, int64_t max_ns)
{
    memset(b, 0, sizeof *b);
    b->min_ns = min_ns > 0 ? min_ns : HFS_BACKOFF_MIN_NS;
    b->max_ns = max_ns > 0 ? max_ns : HFS_BACKOFF_MAX_NS;
    if (b->max_ns < b->min_ns)
        b->max_ns = b->min_ns;
}

void hfs_backoff_lose(hfs_backoff *b, int64_t now_ns)
{
    b->lost = 1;
    b->delay_ns = b->min_ns;
    b->retry_at_ns = now_ns + b->delay_ns;
    b->last_msg[0] = '\0';
}

int hfs_backoff_due(const hfs_backoff *b, int64_t now_ns)
{
    return b->lost && now_ns >= b->retry_at_ns;
}

int hfs_backoff_failed(hfs_backoff *b, int64_t now_ns, const char *msg)
{
    int report = 0;
    if (strcmp(msg, b->last_msg) != 0) {
        report = b->last_msg[0] != '\0';
        strncpy(b->last_msg, msg, sizeof b->last_msg - 1);
        b->last_msg[sizeof b->last_msg - 1] = '\0';
    }
    b->delay_ns = b->delay_ns * 2 < b->max_ns ? b->delay_ns * 2 : b->max_ns;
    b->retry_at_ns = now_ns + b->delay_ns;
    return report;
}

void hfs_backoff_back(hfs_backoff *b)
{
    b->lost = 0;
}
