/*
 * debounce.h — a push button's line, debounced by time.
 *
 * A change of level becomes an event only once the line has stayed at the
 * new level for settle_ns.  Every edge restarts the wait, so a bouncing
 * contact gives one press and one release, and a glitch shorter than
 * settle_ns (down and back up) gives nothing.  The event's time is the time
 * of the edge that started the stable state, not the time it was confirmed,
 * so latency is measured from the finger.
 *
 * The source calls hfs_debounce_edge for each edge, then hfs_debounce_poll
 * whenever it reads (and at hfs_debounce_deadline, which it reports as its
 * own deadline so the kiosk wakes up to confirm a press without a further
 * edge).  Level 1 = pressed; the source handles active-low.
 * Not thread-safe; one struct per button, no allocation.
 */
#ifndef HFS_BOARD_DEBOUNCE_H
#define HFS_BOARD_DEBOUNCE_H

#include <stdint.h>

/* Events kept between two polls; when it overflows the oldest press and
 * release are dropped together, so presses and releases still alternate. */
#define HFS_DEBOUNCE_QUEUE 4

typedef struct hfs_debounce {
    int64_t settle_ns;  /* how long a level must hold (>= 0)              */
    int stable;         /* the last reported (debounced) level, 0/1       */
    int raw;            /* the line's level after the last edge           */
    int64_t raw_ns;     /* time of the last edge that changed raw         */
    int pending;        /* raw != stable: an event may be due at raw_ns +
                           settle_ns                                      */
    /* Changes confirmed by an edge that came after settle_ns (the source
     * fed several edges before polling): oldest first, alternating. */
    int n_queued;
    struct { int kind; int64_t t_ns; } queued[HFS_DEBOUNCE_QUEUE];
} hfs_debounce;

/* level: the line's current level (0/1) when it was requested; it is taken
 * as stable (no event is produced for it). */
void hfs_debounce_init(hfs_debounce *d, int64_t settle_ns, int level);

/* An edge: the line is now at level (0/1) since t_ns.  An edge to the
 * level the line already had (a missed opposite edge) is harmless. */
void hfs_debounce_edge(hfs_debounce *d, int level, int64_t t_ns);

/* HFS_INPUT_PRESS or HFS_INPUT_RELEASE when a change has been stable for
 * settle_ns by now_ns (*event_t_ns = the time of the edge that started the
 * stable state), else 0.  At most one event per call; call again until 0. */
int hfs_debounce_poll(hfs_debounce *d, int64_t now_ns, int64_t *event_t_ns);

/* When poll would next produce an event if no edge came: INT64_MAX when
 * nothing is pending. */
int64_t hfs_debounce_deadline(const hfs_debounce *d);

#endif /* HFS_BOARD_DEBOUNCE_H */
