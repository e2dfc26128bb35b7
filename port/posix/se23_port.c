/*
 * POSIX port (host builds, tests, tools; see se23_port.h): assert hook on
 * stderr + abort(), cycle counter from CLOCK_MONOTONIC in nanoseconds.
 */
#define _POSIX_C_SOURCE 199309L

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "se23_port.h"

void se23_port_assert_failed(const char *file, int line, const char *expr)
{
    (void)fprintf(stderr, "%s:%d: assertion failed: %s\n", file, line, expr);
    abort();
}

int se23_port_cycles_init(void)
{
    struct timespec ts;
    return clock_gettime(CLOCK_MONOTONIC, &ts) == 0;
}

uint32_t se23_port_cycles(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_MONOTONIC, &ts) != 0) {
        return 0u;
    }
    /* Wraps every 4.3 s; callers only take differences. */
    return (uint32_t)((uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec);
}
