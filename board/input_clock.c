/*
 * input_clock.c — the input layer's clock: CLOCK_MONOTONIC, the clock the
 * kernel stamps GPIO edge and evdev events with (input.h), so event times
 * and "now" can be subtracted.
 */
#include "input.h"

#include <time.h>

int64_t hfs_input_now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (int64_t)ts.tv_sec * 1000000000 + ts.tv_nsec;
}
