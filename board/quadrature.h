/*
 * quadrature.h — a rotary encoder's two lines (A, B) decoded into detents.
 *
 * Decoded in user space from edge events (the GPIO source feeds every edge
 * the kernel reports, with its timestamp).  The lines follow a 2-bit Gray
 * code; each valid edge changes exactly one line and moves the position one
 * step (+1 clockwise, -1 counter-clockwise).  A detent is counted only when
 * the position has travelled a full cycle of steps_per_detent steps in one
 * direction and the lines are back at the rest state the encoder sits in
 * between detents.  So:
 *
 *   - contact bounce (A 0-1-0 while B is steady) is +1 then -1: nets zero;
 *   - a reversal mid-detent walks the position back: nothing is counted
 *     unless the turn is completed;
 *   - an invalid transition (an edge reporting a level the line already had,
 *     i.e. a missed edge on the same line, or both lines seen to change at
 *     once) is counted in q->invalid and the decoder resynchronises: it
 *     takes the new levels as the truth and drops the partial detent, so
 *     it can never produce a spurious detent.
 *
 * Clockwise means A leads B: 00 -> 10 -> 11 -> 01 -> 00 (levels written AB).
 * Swap the lines in the configuration to reverse a knob.
 *
 * Timestamps are not needed for decoding (edges arrive in order); they are
 * kept for the caller (the time of the edge that completed the last detent).
 * Not thread-safe; one struct per encoder, no allocation.
 * docs/INPUT.md "Quadrature decoder" draws the state machine.
 */
#ifndef HFS_BOARD_QUADRATURE_H
#define HFS_BOARD_QUADRATURE_H

#include <stdint.h>

typedef struct hfs_quadrature {
    int steps_per_detent;   /* 1, 2 or 4 (anything else is taken as 4)      */
    int a, b;               /* the lines' current levels, 0/1               */
    int pos;                /* steps travelled since the decoder was last
                               at a rest state, -(spd-1)..(spd-1)           */
    int rest;               /* Gray index (0..3) of the rest state taken at
                               init: the encoder is assumed to sit in a
                               detent when its lines are requested          */
    int synced;             /* 0 after an invalid transition until the lines
                               reach a rest state: nothing is counted then  */
    long detents;           /* running total, signed (for diagnostics)      */
    long invalid;           /* invalid transitions seen                     */
    int64_t last_detent_ns; /* time of the edge that completed the last one */
} hfs_quadrature;

/* a, b: the lines' current levels (0/1), read when the lines were
 * requested.  steps_per_detent: 1, 2 or 4. */
void hfs_quadrature_init(hfs_quadrature *q, int steps_per_detent, int a, int b);

/* An edge on line (0 = A, 1 = B), now at level (0/1), at time t_ns
 * (CLOCK_MONOTONIC).  Returns the signed detents this edge completed
 * (+ = clockwise, 0 or +-1). */
int hfs_quadrature_edge(hfs_quadrature *q, int line, int level, int64_t t_ns);

/* Both lines sampled at once (e.g. after an overrun of the edge queue):
 * same rules as an edge; a change of both lines is an invalid transition. */
int hfs_quadrature_sample(hfs_quadrature *q, int a, int b, int64_t t_ns);

#endif /* HFS_BOARD_QUADRATURE_H */
