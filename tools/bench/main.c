/*
 * se23-bench: the host benchmark's driver, one binary per precision
 * (tools/bench/run.sh runs it; `make bench`).
 *
 *   se23-bench routines        names of the per-routine kernels
 *   se23-bench steps           names of the composite steps
 *   se23-bench count NAME N    N calls of kernel NAME inside run_kernel, the
 *                              only function callgrind collects
 *                              (--toggle-collect=run_kernel); NAME is a
 *                              routine, STEP/se23 or STEP/eigen
 *   se23-bench check           cross-check: the library's and the
 *                              reference's outputs on every ring entry
 *   se23-bench time [ROUNDS]   the cross-check, then every step timed
 *                              (timing.h; 1000 rounds unless given); one
 *                              tab-separated line per step: name, label,
 *                              max relative difference, then min, p10,
 *                              median, p90 in ns per call for se23 and for
 *                              the reference, and p10, median, p90 of the
 *                              ratio se23/reference within a round
 *
 * Exit status 1 if a call fails or the outputs differ by more than
 * rounding (BOUND, relative), 2 on a usage error.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "collect.h"
#include "ring.h"
#include "routines.h"
#include "steps.h"
#include "timing.h"

#if SE23_CFG_DOUBLE
#define BOUND 1e-9
#else
#define BOUND 1e-3
#endif

static bench_fn_t find_kernel(const char *name)
{
    for (int k = 0; k < bench_n_routines; ++k) {
        if (strcmp(name, bench_routines[k].name) == 0) {
            return bench_routines[k].fn;
        }
    }
    const char *slash = strchr(name, '/');
    for (int k = 0; slash != NULL && k < BENCH_N_STEPS; ++k) {
        const bench_step_t *s = &bench_steps[k];
        if (strncmp(name, s->name, (size_t)(slash - name)) == 0 &&
            s->name[slash - name] == '\0') {
            return strcmp(slash + 1, "se23") == 0    ? s->se23
                   : strcmp(slash + 1, "eigen") == 0 ? s->eigen
                                                     : NULL;
        }
    }
    return NULL;
}

/* Runs both sides of every step on every ring entry; diff[k] receives the
 * largest relative difference of step k. Returns nonzero on failure. */
static int cross_check(double *diff)
{
    int bad = 0;
    for (int k = 0; k < BENCH_N_STEPS; ++k) {
        const bench_step_t *s = &bench_steps[k];
        diff[k] = 0;
        for (int i = 0; i < BENCH_RING; ++i) {
            const int st = s->se23(i) | s->eigen(i);
            const double d = st != 0 ? (double)INFINITY : s->diff(i);
            diff[k] = d > diff[k] ? d : diff[k];
        }
        if (!(diff[k] <= BOUND)) {
            fprintf(stderr, "se23-bench: %s: se23 and the reference differ by %.3g (bound %g)\n",
                    s->name, diff[k], BOUND);
            bad = 1;
        }
    }
    return bad;
}

static int count(const char *name, int n)
{
    const bench_fn_t fn = find_kernel(name);
    if (fn == NULL || n < 1) {
        fprintf(stderr, "se23-bench: unknown kernel '%s' or N < 1\n", name);
        return 2;
    }
    int bad = 0;
    for (int i = 0; i < BENCH_RING; ++i) { /* warm: lazy binding, caches */
        bad |= fn(i);
    }
    return (bad | run_kernel(fn, n)) != 0;
}

static int time_steps(int rounds)
{
    double diff[BENCH_N_STEPS];
    if (cross_check(diff) != 0) {
        return 1;
    }
    for (int k = 0; k < BENCH_N_STEPS; ++k) {
        const bench_step_t *s = &bench_steps[k];
        bench_stats_t a, b, r;
        if (bench_time_pair(s->se23, s->eigen, BENCH_RING, rounds, &a, &b, &r) != 0) {
            fprintf(stderr, "se23-bench: %s: a call failed\n", s->name);
            return 1;
        }
        printf("%s\t%s\t%.2g\t%.0f\t%.0f\t%.0f\t%.0f\t%.0f\t%.0f\t%.0f\t%.0f\t%.2f\t%.2f\t%.2f\n",
               s->name, s->label, diff[k], a.min, a.p10, a.median, a.p90, b.min, b.p10,
               b.median, b.p90, r.p10, r.median, r.p90);
    }
    return 0;
}

int main(int argc, char **argv)
{
    const char *cmd = argc >= 2 ? argv[1] : "";
    if (strcmp(cmd, "routines") == 0 || strcmp(cmd, "steps") == 0) {
        const int routines = cmd[0] == 'r';
        for (int k = 0; k < (routines ? bench_n_routines : BENCH_N_STEPS); ++k) {
            puts(routines ? bench_routines[k].name : bench_steps[k].name);
        }
        return 0;
    }
    if (bench_routines_prepare() != 0 || bench_steps_prepare() != 0) {
        fprintf(stderr, "se23-bench: preparing the inputs failed\n");
        return 1;
    }
    if (strcmp(cmd, "count") == 0 && argc == 4) {
        return count(argv[2], atoi(argv[3]));
    }
    if (strcmp(cmd, "check") == 0 && argc == 2) {
        double diff[BENCH_N_STEPS];
        const int bad = cross_check(diff);
        for (int k = 0; k < BENCH_N_STEPS; ++k) {
            printf("%s: max relative difference %.2g (bound %g)\n", bench_steps[k].name, diff[k],
                   BOUND);
        }
        return bad;
    }
    const int rounds = argc == 3 ? atoi(argv[2]) : 1000;
    if (strcmp(cmd, "time") == 0 && argc <= 3 && rounds >= 1 && rounds <= BENCH_MAX_ROUNDS) {
        return time_steps(rounds);
    }
    fprintf(stderr, "usage: se23-bench routines | steps | count NAME N | check | time [ROUNDS]\n"
                    "  (1 <= ROUNDS <= %d)\n", BENCH_MAX_ROUNDS);
    return 2;
}
