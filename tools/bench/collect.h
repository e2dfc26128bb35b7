/*
 * run_kernel: the only function the instruction counts collect
 * (valgrind --tool=callgrind --toggle-collect=run_kernel). It lives in its
 * own file so that the compiler cannot inline it into its caller.
 */
#ifndef SE23_BENCH_COLLECT_H
#define SE23_BENCH_COLLECT_H

#include "steps.h"

/* n calls of fn over the input ring (i = k % BENCH_RING); returns the
 * calls' results or-ed together. */
int run_kernel(bench_fn_t fn, int n);

#endif /* SE23_BENCH_COLLECT_H */
