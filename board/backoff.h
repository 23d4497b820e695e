/*
 * backoff.h — the device-loss policy shared by the input set (input_set.c)
 * and the capture sources (capture.h): a lost device is reported once,
 * reopened after 100 ms, then after twice the previous wait up to 5 s; a
 * reopen failing for a NEW reason is reported once more ("no such device"
 * -> "permission denied"), the same reason again is not.
 */
#ifndef HFS_BOARD_BACKOFF_H
#define HFS_BOARD_BACKOFF_H

#include <stdint.h>

#define HFS_BACKOFF_MIN_NS (100 * 1000000LL)
#define HFS_BACKOFF_MAX_NS (5000 * 1000000LL)

typedef struct hfs_backoff {
    int lost;                 /* closed, waiting for a reopen             */
    int64_t retry_at_ns;      /* next attempt (CLOCK_MONOTONIC)           */
    int64_t delay_ns;         /* current wait                             */
    int64_t min_ns, max_ns;
    char last_msg[512];       /* last reopen failure ("" after a loss)     */
} hfs_backoff;

/* min_ns/max_ns 0: the defaults above; max below min is raised to min. */
void hfs_backoff_init(hfs_backoff *b, int64_t min_ns, int64_t max_ns);
/* The device was lost at now_ns: the first reopen is due min_ns later. */
void hfs_backoff_lose(hfs_backoff *b, int64_t now_ns);
/* 1 when lost and the next reopen attempt is due. */
int hfs_backoff_due(const hfs_backoff *b, int64_t now_ns);
/* A reopen attempt failed with msg: the wait doubles (up to max_ns).
 * Returns 1 when msg is worth reporting (a new reason, not the first
 * failure right after the loss, which the loss message already said). */
int hfs_backoff_failed(hfs_backoff *b, int64_t now_ns, const char *msg);
/* The reopen worked. */
void hfs_backoff_back(hfs_backoff *b);

#endif /* HFS_BOARD_BACKOFF_H */
