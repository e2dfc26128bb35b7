/*
 * Cortex-M port for the QEMU mps2 boards (see se23_port.h): assert hook and
 * fault report through semihosting stdio and exit status, DWT cycle counter
 * on cores that have one (M3/M4/M7/M33/M55), empty _init/_fini for
 * -nostartfiles. On real hardware replace the two reporting functions with
 * the firmware's logging and reset.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "se23_port.h"

/** Exit status of a failed assertion and of a fault (far above any
 *  failure count the test images report, which they cap at 200). */
#define EXIT_ASSERT 254
#define EXIT_FAULT 255

void se23_port_assert_failed(const char *file, int line, const char *expr)
{
    (void)fprintf(stderr, "%s:%d: assertion failed: %s\n", file, line, expr);
    exit(EXIT_ASSERT);
}

/* Called by the default exception handler in startup.S. */
void se23_port_fault(uint32_t ipsr);
void se23_port_fault(uint32_t ipsr)
{
    (void)fprintf(stderr, "fault: exception %lu\n", (unsigned long)(ipsr & 0x1FFu));
    exit(EXIT_FAULT);
}

#if defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__) ||                   \
    defined(__ARM_ARCH_8M_MAIN__) || defined(__ARM_ARCH_8_1M_MAIN__)
#define REG(addr) (*(volatile uint32_t *)(addr))
#define DEMCR REG(0xE000EDFCu)
#define DEMCR_TRCENA (1u << 24)
#define DWT_CTRL REG(0xE0001000u)
#define DWT_CTRL_CYCCNTENA 1u
#define DWT_CTRL_NOCYCCNT (1u << 25)
#define DWT_CYCCNT REG(0xE0001004u)
#define DWT_LAR REG(0xE0001FB0u) /* CoreSight lock access (M7) */
#define DWT_LAR_KEY 0xC5ACCE55u

int se23_port_cycles_init(void)
{
    DEMCR |= DEMCR_TRCENA;
    DWT_LAR = DWT_LAR_KEY;
    if ((DWT_CTRL & DWT_CTRL_NOCYCCNT) != 0u) {
        return 0;
    }
    DWT_CYCCNT = 0u;
    DWT_CTRL |= DWT_CTRL_CYCCNTENA;
    return 1;
}

uint32_t se23_port_cycles(void) { return DWT_CYCCNT; }
#else
/* ARMv6-M / ARMv8-M baseline: no cycle counter. */
int se23_port_cycles_init(void) { return 0; }
uint32_t se23_port_cycles(void) { return 0u; }
#endif

/* -nostartfiles: newlib's __libc_init_array and exit() call these. */
void _init(void);
void _fini(void);
void _init(void) {}
void _fini(void) {}
