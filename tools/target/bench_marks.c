/*
 * Markers of the benchmark image: tools/target/insn_count.c (a QEMU plugin)
 * counts the guest instructions executed from the first instruction of
 * se23_bench_begin to the first instruction of se23_bench_end. Own
 * translation unit and different bodies, so that neither is inlined nor
 * merged with the other.
 */
#include <stdint.h>

#include "bench.h"

static volatile uint32_t bench_mark;

__attribute__((noinline)) void se23_bench_begin(void) { bench_mark = 1u; }
__attribute__((noinline)) void se23_bench_end(void) { bench_mark = 2u; }
