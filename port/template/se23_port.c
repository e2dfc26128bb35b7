/*
 * Template port: copy port/template to port/<name>, replace the bodies, and
 * compile this file into the firmware (the library itself does not need it;
 * SE23_PORT_ASSERT and the cycle counter are for the application, tests and
 * benchmarks). See se23_port.h for the contract.
 */
#include <stdint.h>

#include "se23_port.h"

void se23_port_assert_failed(const char *file, int line, const char *expr)
{
    /* TODO: log file:line and expr, then reset or halt. */
    (void)file;
    (void)line;
    (void)expr;
    for (;;) {
    }
}

int se23_port_cycles_init(void)
{
    /* TODO: start a free-running counter; return 0 if there is none. */
    return 0;
}

uint32_t se23_port_cycles(void)
{
    /* TODO: read the counter. */
    return 0u;
}
