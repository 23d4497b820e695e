/*
 * quadrature.c — Gray-code decoder for rotary encoders (quadrature.h).
 *
 * The four line states form a cycle; an edge moves one step along it.  We
 * keep the steps travelled since the last visit to a rest state (pos).
 * Rest states are spaced steps_per_detent apart on the cycle, so when the
 * lines come back to one, pos is -spd, 0 or +spd: a full cycle one way, a
 * bounce or reversal that came back (nothing), or a full cycle the other
 * way.  That single rule is what rejects bounce and half turns.
 *
 * After an invalid transition the position is unknown: we adopt the
 * reported levels and stop counting until a rest state is reached, so a
 * lost edge can cost at most the detent in progress, never add one.
 */
#include "quadrature.h"

/* Gray index of state (a<<1 | b) along the clockwise cycle 00,10,11,01. */
static const int gray_index[4] = {0, 3, 1, 2};

static int state_of(const hfs_quadrature *q) { return q->a << 1 | q->b; }

static int at_rest(const hfs_quadrature *q)
{
    const int off = (gray_index[state_of(q)] - q->rest + 4) % 4;
    return off % q->steps_per_detent == 0;
}

static void resync(hfs_quadrature *q)
{
    q->invalid++;
    q->pos = 0;
    q->synced = at_rest(q);
}

void hfs_quadrature_init(hfs_quadrature *q, int steps_per_detent, int a, int b)
{
    q->steps_per_detent =
        (steps_per_detent == 1 || steps_per_detent == 2) ? steps_per_detent : 4;
    q->a = a != 0;
    q->b = b != 0;
    q->rest = gray_index[state_of(q)];
    q->pos = 0;
    q->synced = 1;
    q->detents = 0;
    q->invalid = 0;
    q->last_detent_ns = 0;
}

/* The lines moved one valid step to (a, b). */
static int step_to(hfs_quadrature *q, int a, int b, int64_t t_ns)
{
    const int from = gray_index[state_of(q)];
    q->a = a;
    q->b = b;
    const int to = gray_index[state_of(q)];
    q->pos += ((to - from + 4) % 4 == 1) ? 1 : -1;
    if (!at_rest(q))
        return 0;
    if (!q->synced) {
        q->synced = 1;
        q->pos = 0;
        return 0;
    }
    const int detent = q->pos / q->steps_per_detent; /* pos is -spd, 0 or spd */
    q->pos = 0;
    if (detent) {
        q->detents += detent;
        q->last_detent_ns = t_ns;
    }
    return detent;
}

int hfs_quadrature_edge(hfs_quadrature *q, int line, int level, int64_t t_ns)
{
    level = level != 0;
    if (line != 0 && line != 1) {
        q->invalid++; /* a caller bug; count it, change nothing */
        return 0;
    }
    const int current = line == 0 ? q->a : q->b;
    if (level == current) {
        /* The line "changed" to the level it had: its opposite edge was
         * lost, and we cannot tell how far the knob went meanwhile. */
        resync(q);
        return 0;
    }
    return line == 0 ? step_to(q, level, q->b, t_ns) : step_to(q, q->a, level, t_ns);
}

int hfs_quadrature_sample(hfs_quadrature *q, int a, int b, int64_t t_ns)
{
    a = a != 0;
    b = b != 0;
    if (a != q->a && b != q->b) {
        /* Both lines at once: two steps, direction unknown. */
        q->a = a;
        q->b = b;
        resync(q);
        return 0;
    }
    if (a != q->a || b != q->b)
        return step_to(q, a, b, t_ns);
    return 0;
}
