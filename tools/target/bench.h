/*
 * Benchmark image (tools/target/bench_main.c): instruction counts per call of
 * every routine of tests/target/tv_list.h, plus composite steps, measured by
 * the QEMU plugin tools/target/insn_count.c between the two markers below.
 */
#ifndef SE23_BENCH_H
#define SE23_BENCH_H

/** Start of a measured region (the plugin snapshots its counter here). */
void se23_bench_begin(void);
/** End of a measured region (the plugin prints the instructions since begin). */
void se23_bench_end(void);

#endif /* SE23_BENCH_H */
