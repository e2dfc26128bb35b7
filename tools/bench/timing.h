/*
 * Wall-clock timing of two calls interleaved in one process, so that the
 * machine's noise (other jobs, frequency changes) hits both alike. A batch
 * is one pass over the input ring, timed with clock_gettime(CLOCK_MONOTONIC);
 * each round times one batch of each call, in alternating order, after
 * unrecorded warm-up rounds. Figures are ns per call over the rounds.
 */
#ifndef SE23_BENCH_TIMING_H
#define SE23_BENCH_TIMING_H

#include "steps.h"

#define BENCH_WARMUP_ROUNDS 20

typedef struct {
    double min, p10, median, p90;
} bench_stats_t;

#define BENCH_MAX_ROUNDS 2000

/* Times a and b over `rounds` rounds (1 .. BENCH_MAX_ROUNDS) of one batch
 * of n calls each (i = 0 .. n-1): sa and sb in ns per call, ratio of a's
 * time to b's within each round (the two batches of a round are adjacent,
 * so a slow phase of the machine cancels out of it). Returns nonzero if a
 * call failed or rounds is out of range. */
int bench_time_pair(bench_fn_t a, bench_fn_t b, int n, int rounds, bench_stats_t *sa,
                    bench_stats_t *sb, bench_stats_t *ratio);

#endif /* SE23_BENCH_TIMING_H */
