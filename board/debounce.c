/*
 * debounce.c — time-based debounce of a button line (debounce.h).
 *
 * One timer: every edge restarts it; when it runs out with the line at a
 * level other than the reported one, that level is reported with the time
 * of the edge that started it.  An edge arriving after the timer ran out
 * confirms the previous level first (the source may feed a burst of edges
 * before it polls), so no real press is lost to a late poll.
 */
#include "debounce.h"

#include "input.h"

static void enqueue(hfs_debounce *d, int level, int64_t t_ns)
{
    if (d->n_queued == HFS_DEBOUNCE_QUEUE) {
        /* Drop the oldest pair so presses and releases keep alternating. */
        for (int i = 2; i < d->n_queued; ++i)
            d->queued[i - 2] = d->queued[i];
        d->n_queued -= 2;
    }
    d->queued[d->n_queued].kind = level ? HFS_INPUT_PRESS : HFS_INPUT_RELEASE;
    d->queued[d->n_queued].t_ns = t_ns;
    d->n_queued++;
}

void hfs_debounce_init(hfs_debounce *d, int64_t settle_ns, int level)
{
    d->settle_ns = settle_ns > 0 ? settle_ns : 0;
    d->stable = d->raw = level != 0;
    d->raw_ns = 0;
    d->pending = 0;
    d->n_queued = 0;
}

void hfs_debounce_edge(hfs_debounce *d, int level, int64_t t_ns)
{
    level = level != 0;
    if (d->pending && t_ns - d->raw_ns >= d->settle_ns) {
        d->stable = d->raw;
        d->pending = 0;
        enqueue(d, d->stable, d->raw_ns);
    }
    /* An edge to the level the line already had means the opposite edge
     * was lost: the line moved, so the timer restarts all the same. */
    d->raw = level;
    d->raw_ns = t_ns;
    d->pending = d->raw != d->stable;
}

int hfs_debounce_poll(hfs_debounce *d, int64_t now_ns, int64_t *event_t_ns)
{
    if (d->pending && now_ns - d->raw_ns >= d->settle_ns) {
        d->stable = d->raw;
        d->pending = 0;
        enqueue(d, d->stable, d->raw_ns);
    }
    if (d->n_queued == 0)
        return 0;
    const int kind = d->queued[0].kind;
    if (event_t_ns)
        *event_t_ns = d->queued[0].t_ns;
    for (int i = 1; i < d->n_queued; ++i)
        d->queued[i - 1] = d->queued[i];
    d->n_queued--;
    return kind;
}

int64_t hfs_debounce_deadline(const hfs_debounce *d)
{
    if (d->n_queued > 0)
        return d->queued[0].t_ns; /* already due */
    if (!d->pending)
        return INT64_MAX;
    if (d->raw_ns > INT64_MAX - d->settle_ns)
        return INT64_MAX;
    return d->raw_ns + d->settle_ns;
}
