/*
 * Self-test of the Cortex-M port (startup.S, sections.ld, se23_port.c) on
 * QEMU: .data copied from flash, .bss zeroed, FPU enabled in the build's
 * precision, 8-byte stack alignment at main, semihosting output. Exit
 * status = number of failed checks (checked by tests/check.d/40-target.sh).
 */
#include <stdint.h>
#include <stdio.h>

#include "se23/types.h"
#include "se23_port.h"

static volatile uint32_t data_word = 0x5E23C0DEu;
static volatile uint32_t bss_words[64];
static volatile se23_real_t operand = SE23_R(1.5);

static int failures;

static void expect(int ok, const char *what)
{
    if (!ok) {
        ++failures;
        printf("FAIL %s\n", what);
    }
}

int main(void)
{
    uint32_t zero = 0u;
    unsigned i;
    volatile uint64_t aligned = 0u;

    expect(data_word == 0x5E23C0DEu, ".data copied");
    for (i = 0u; i < 64u; ++i) {
        zero |= bss_words[i];
    }
    expect(zero == 0u, ".bss zeroed");
    expect(operand * operand == SE23_R(2.25), "FPU multiply");
    expect(((uintptr_t)&aligned & 7u) == 0u, "8-byte stack alignment");
    (void)se23_port_cycles_init();
    (void)se23_port_cycles();
    SE23_PORT_ASSERT(failures >= 0);
    printf("port self-test (%s): %d failure(s)\n",
           SE23_CFG_DOUBLE ? "double" : "float", failures);
    return failures;
}
