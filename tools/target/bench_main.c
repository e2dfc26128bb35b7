/*
 * Benchmark image: for every routine of tests/target/tv_list.h, loads its
 * last reference vector (a random, generic input: no small-angle branch)
 * outside the measured region, then runs
 *     se23_bench_begin(); call(); se23_bench_end();
 * and prints "bench <name> <status>". The instruction count of each region
 * comes from the QEMU plugin tools/target/insn_count.c; tools/target/bench.py
 * pairs regions with names and subtracts the first region, an empty call,
 * so that a count is the routine plus its argument set-up (a few
 * instructions). The composite steps below (a full propagation step with
 * covariance, ...) are timed the same way.
 */
#include <stdio.h>

#include "bench.h"
#include "bench_steps.h"
#include "tv.h"

static int empty_call(void) { return 0; }

static void measure(const char *name, int (*call)(void))
{
    int st;
    se23_bench_begin();
    st = call();
    se23_bench_end();
    printf("bench %s %d\n", name, st);
}

int main(void)
{
    int i;
    measure("(empty call)", empty_call);
    for (i = 0; i < tv_n_routines; ++i) {
        const tv_routine_t *r = &tv_routines[i];
        const tv_data_t *d = r->data;
        r->load(d->in != NULL ? d->in + (size_t)(d->n_vec - 1) * (size_t)d->n_in : NULL);
        measure(r->name, r->call);
    }
    for (i = 0; i < bench_n_steps; ++i) {
        bench_steps[i].prepare();
        measure(bench_steps[i].name, bench_steps[i].call);
    }
    return 0;
}
