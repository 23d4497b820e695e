/*
 * test_quadrature.c — the Gray-code decoder (board/quadrature.h) on
 * recorded edge sequences.  Each case is a line of edges, written
 * "A1" (line A rose), "B0" (line B fell), "S10" (both lines sampled: A=1,
 * B=0), applied dt_ns apart; it states exactly what the decoder must
 * report: the net detents, the detents reported in either direction
 * ("moves": a reversal counts twice) and the invalid transitions.
 * Clockwise is A leading B: 00 -> 10 -> 11 -> 01 -> 00.
 */
#include "quadrature.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

typedef struct qcase {
    const char *what;
    int spd, a0, b0;     /* steps per detent, levels at init */
    int64_t dt_ns;
    const char *edges;
    int net, moves, invalid;
} qcase;

#define CW4 "A1 B1 A0 B0 "   /* one clockwise cycle from 00 */
#define CCW4 "B1 A1 B0 A0 "  /* one counter-clockwise cycle from 00 */
#define CW4x5 CW4 CW4 CW4 CW4 CW4
#define CW4x25 CW4x5 CW4x5 CW4x5 CW4x5 CW4x5
#define CCW4x5 CCW4 CCW4 CCW4 CCW4 CCW4

static const qcase cases[] = {
    /* Clean turns, 4 steps per detent (the common EC11 kind). */
    {"cw 1 detent", 4, 0, 0, 2000000, CW4, 1, 1, 0},
    {"ccw 1 detent", 4, 0, 0, 2000000, CCW4, -1, 1, 0},
    {"cw 3 detents", 4, 0, 0, 2000000, CW4 CW4 CW4, 3, 3, 0},
    {"cw from rest 11", 4, 1, 1, 2000000, "A0 B0 A1 B1", 1, 1, 0},
    {"ccw from rest 11", 4, 1, 1, 2000000, "B0 A0 B1 A1", -1, 1, 0},
    /* Contact bounce. */
    {"A bounces 0-1-0 at rest, B steady", 4, 0, 0, 100000, "A1 A0 A1 A0 A1 A0", 0, 0, 0},
    {"B bounces at rest", 4, 0, 0, 100000, "B1 B0 B1 B0", 0, 0, 0},
    {"bounce on every edge of a cw turn", 4, 0, 0, 100000,
     "A1 A0 A1 B1 B0 B1 A0 A1 A0 B0 B1 B0", 1, 1, 0},
    {"bounce at the last step, back at rest twice", 4, 0, 0, 100000,
     "A1 B1 A0 B0 B1 B0 B1 B0", 1, 1, 0},
    /* Reversal mid-detent. */
    {"half a turn and back", 4, 0, 0, 1000000, "A1 B1 B0 A0", 0, 0, 0},
    {"three steps and back", 4, 0, 0, 1000000, "A1 B1 A0 A1 B0 A0", 0, 0, 0},
    {"half cw then a full ccw", 4, 0, 0, 1000000, "A1 B1 B0 A0 " CCW4, -1, 1, 0},
    {"cw, ccw, cw", 4, 0, 0, 1000000, CW4 CCW4 CW4, 1, 3, 0},
    /* Missed edges (invalid): never a spurious detent. */
    {"B1 missed: A1 A0 then B0 at level 0, then a clean cw", 4, 0, 0, 1000000,
     "A1 A0 B0 " CW4, 1, 1, 1},
    {"first A0 of two cw detents missed: both lost", 4, 0, 0, 1000000,
     "A1 B1 B0 A1 B1 A0 B0", 0, 0, 1},
    {"edge to the level the line has, at rest", 4, 0, 0, 1000000, "A0", 0, 0, 1},
    {"both lines at once (sample), resync, then a clean cw", 4, 0, 0, 1000000,
     "S11 A0 B0 " CW4, 1, 1, 1},
    {"half a turn, then both lines at once onto the rest state", 4, 0, 0, 1000000,
     "A1 B1 S00 " CW4, 1, 1, 1},
    {"repeated same-level edges mid-turn", 4, 0, 0, 1000000, "A1 A1 A1 B1 A0 B0 " CW4, 1, 1, 2},
    {"edge on line 2 (caller bug)", 4, 0, 0, 1000000, "C1 " CW4, 1, 1, 1},
    /* 2 steps per detent: rest states 00 and 11. */
    {"spd2 cw 2 detents", 2, 0, 0, 1000000, CW4, 2, 2, 0},
    {"spd2 ccw 2 detents", 2, 0, 0, 1000000, CCW4, -2, 2, 0},
    {"spd2 bounce then a detent", 2, 0, 0, 100000, "A1 A0 A1 B1", 1, 1, 0},
    {"spd2 one detent and back", 2, 0, 0, 1000000, "A1 B1 B0 A0", 0, 2, 0},
    {"spd2 half step and back", 2, 0, 0, 1000000, "B1 B0", 0, 0, 0},
    {"spd2 missed edge", 2, 0, 0, 1000000, "A1 B0 B1 A0 B0", 1, 1, 1},
    /* 1 step per detent: every edge is a detent; a bounce is +1 -1. */
    {"spd1 cw", 1, 0, 0, 1000000, CW4, 4, 4, 0},
    {"spd1 ccw", 1, 0, 0, 1000000, CCW4, -4, 4, 0},
    {"spd1 bounce nets zero", 1, 0, 0, 100000, "A1 A0 A1 A0", 0, 4, 0},
    {"spd1 missed edge", 1, 0, 0, 1000000, "A1 A1 B1", 2, 2, 1},
    /* Very fast turns: edges 1 us apart count exactly. */
    {"fast: 25 cw detents, 1 us edges", 4, 0, 0, 1000, CW4x25, 25, 25, 0},
    {"fast: 10 cw then 5 ccw, 1 us edges", 4, 0, 0, 1000, CW4x5 CW4x5 CCW4x5, 5, 15, 0},
    {"fast: 0 ns apart", 4, 0, 0, 0, CW4x5, 5, 5, 0},
};

static void run_case(const qcase *c)
{
    hfs_quadrature q;
    hfs_quadrature_init(&q, c->spd, c->a0, c->b0);
    int64_t t = 1000000000;
    int net = 0, moves = 0;
    char buf[1024];
    snprintf(buf, sizeof buf, "%s", c->edges);
    char *save = NULL;
    for (char *tok = strtok_r(buf, " ", &save); tok; tok = strtok_r(NULL, " ", &save)) {
        t += c->dt_ns;
        int d;
        if (tok[0] == 'S')
            d = hfs_quadrature_sample(&q, tok[1] == '1', tok[2] == '1', t);
        else
            d = hfs_quadrature_edge(&q, tok[0] - 'A', tok[1] == '1', t);
        CHECK(d >= -1 && d <= 1, "%s: edge %s returned %d", c->what, tok, d);
        net += d;
        moves += d < 0 ? -d : d;
        if (d)
            CHECK(q.last_detent_ns == t, "%s: last detent time", c->what);
    }
    CHECK(net == c->net, "%s: net %d, expected %d", c->what, net, c->net);
    CHECK(moves == c->moves, "%s: moves %d, expected %d", c->what, moves, c->moves);
    CHECK(q.invalid == c->invalid, "%s: invalid %ld, expected %d", c->what, q.invalid,
          c->invalid);
    CHECK(q.detents == net, "%s: running total %ld", c->what, q.detents);
}

/* A long random walk of valid steps: the net detents must equal the
 * position travelled divided by steps per detent, whatever the path. */
static void random_walk(int spd)
{
    static const int cycle[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    hfs_quadrature q;
    hfs_quadrature_init(&q, spd, 0, 0);
    unsigned seed = 12345u + (unsigned)spd;
    int idx = 0, pos = 0, net = 0;
    for (int i = 0; i < 100000; ++i) {
        seed = seed * 1103515245u + 12345u;
        const int dir = (seed >> 16) & 1 ? 1 : -1;
        const int next = (idx + dir + 4) % 4;
        const int line = cycle[next][0] != cycle[idx][0] ? 0 : 1;
        net += hfs_quadrature_edge(&q, line, cycle[next][line], i);
        idx = next;
        pos += dir;
        if (pos % spd == 0)
            CHECK(net == pos / spd, "walk spd %d: net %d at position %d", spd, net, pos);
    }
    CHECK(q.invalid == 0, "walk spd %d: %ld invalid", spd, q.invalid);
}

int main(void)
{
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i)
        run_case(&cases[i]);
    random_walk(1);
    random_walk(2);
    random_walk(4);
    if (failures)
        fprintf(stderr, "test_quadrature: %d failure(s)\n", failures);
    return failures ? 1 : 0;
}
